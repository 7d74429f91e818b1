/* glue.c - the callbacks of the WebAssembly build, imported from JavaScript.
 *
 * A C function pointer cannot point at a JavaScript function, so the two
 * callback types of the C API are served by two functions imported from the
 * module "poissondisk" (defined in src/wasm.js); `user` carries the sampler's
 * id on the JavaScript side, which looks up the function to call. */
#include <stdint.h>
#include <poissondisk.h>

__attribute__((import_module("poissondisk"), import_name("progress")))
int pdsjs_progress(void *user, size_t count, double done);

__attribute__((import_module("poissondisk"), import_name("radius")))
double pdsjs_radius(void *user, double x, double y);

/* id 0 removes the callback. */
__attribute__((export_name("pdsjs_set_progress")))
int pdsjs_set_progress(pds_sampler *s, uintptr_t id) {
    if (id == 0) return pds_set_progress(s, 0, 0);
    return pds_set_progress(s, pdsjs_progress, (void *)id);
}

__attribute__((export_name("pdsjs_set_radius_fn")))
int pdsjs_set_radius_fn(pds_sampler *s, uintptr_t id, double rmin, double rmax) {
    return pds_set_radius_fn(s, pdsjs_radius, (void *)id, rmin, rmax);
}
