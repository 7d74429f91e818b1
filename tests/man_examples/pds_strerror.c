/*
 * Check at run time that the library suits the header the program was
 * compiled with, then show the two ways of reporting an error.
 */
#include <stdio.h>

#include <poissondisk.h>

int
main(void)
{
    pds_sampler *s;
    unsigned v = pds_version_number();
    int rc;

    /*
     * Same major version, and at least the header's minor version,
     * which is where the functions this program uses appeared.
     */
    if (v / 10000 != PDS_VERSION_MAJOR || v < PDS_VERSION_NUMBER) {
        fprintf(stderr, "built for poissondisk %d.%d.%d, running "
            "with %s\n", PDS_VERSION_MAJOR, PDS_VERSION_MINOR,
            PDS_VERSION_PATCH, pds_version_string());
        return 1;
    }
    printf("poissondisk %s\n", pds_version_string());

    /* No sampler was made: pds_strerror() describes the code. */
    rc = pds_create(&s, -1.0, 1);
    if (rc != PDS_EINVAL) {
        fprintf(stderr, "a negative radius was accepted\n");
        pds_destroy(s);    /* s is NULL if pds_create() failed */
        return 1;
    }
    printf("pds_create: %s\n", pds_strerror(rc));

    /* With a sampler, pds_errmsg() says more about the failure. */
    if ((rc = pds_create(&s, 0.1, 1)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }
    rc = pds_refine(s, 0.2);    /* larger than the current radius */
    if (rc != PDS_EINVAL) {
        fprintf(stderr, "a larger radius was accepted\n");
        pds_destroy(s);
        return 1;
    }
    printf("%s\n", pds_errmsg(s));  /* names the function */
    pds_destroy(s);
    return 0;
}
