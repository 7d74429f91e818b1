"""poissondisk - Python ctypes binding for libpoissondisk (exact maximal
Poisson-disk sampling after Jones 2006).

A thin wrapper over the C API in include/poissondisk.h; standard library only.

    import poissondisk
    with poissondisk.Sampler(0.05, seed=7) as s:
        s.run()                  # True: the pattern is maximal
        pts = s.points()         # [(x, y), ...] in insertion order

The shared library is looked up in this order:
  1. the path in the environment variable PDS_LIBRARY;
  2. ctypes.util.find_library("poissondisk") (the system's search paths).

Failures of the library raise PoissonDiskError, which carries the negative
PDS_E* code, the library's message (pds_errmsg) and the code's text
(pds_strerror). Misuse on the Python side (a negative seed, a closed sampler)
raises ValueError or TypeError, as the standard library does.

One Sampler must be used by one thread at a time; distinct samplers may run
in distinct threads (ctypes releases the GIL during each call).
"""

import ctypes
import ctypes.util
import operator
import os

__all__ = [
    "PoissonDiskError", "Sampler", "version", "version_number", "strerror",
    "EINVAL", "ENOMEM", "ESTATE", "ERANGE", "EINTERNAL", "DONE", "MORE",
]

# Error codes, fixed by the header (never renumbered).
EINVAL = -1
ENOMEM = -2
ESTATE = -3
ERANGE = -4
EINTERNAL = -5

# Named results of pds_step, pds_run and pds_verify (1.1.1).
DONE = 0  # the pattern is maximal
MORE = 1  # step: a point was added; run: limit reached, room left; verify: room left

# The soname major this binding was written for.
_ABI_MAJOR = 1


def _load_library():
    path = os.environ.get("PDS_LIBRARY")
    if path:
        try:
            return ctypes.CDLL(path)
        except OSError as exc:
            raise ImportError(
                "poissondisk: cannot load the library named by PDS_LIBRARY=%r: %s"
                % (path, exc)) from exc
    name = ctypes.util.find_library("poissondisk")
    if name is None:
        raise ImportError(
            "poissondisk: libpoissondisk not found; install it or set "
            "PDS_LIBRARY to the full path of libpoissondisk.so.%d" % _ABI_MAJOR)
    try:
        return ctypes.CDLL(name)
    except OSError as exc:
        raise ImportError("poissondisk: cannot load %s: %s" % (name, exc)) from exc


def _declare(lib):
    """Give every function of the header its exact C signature."""
    vp, dbl, i, sz = ctypes.c_void_p, ctypes.c_double, ctypes.c_int, ctypes.c_size_t
    table = {
        # name: (restype, argtypes)
        "pds_create": (i, [ctypes.POINTER(vp), dbl, ctypes.c_uint64]),
        "pds_destroy": (None, [vp]),
        "pds_set_domain": (i, [vp, dbl, dbl, dbl, dbl]),
        "pds_step": (i, [vp]),
        "pds_run": (i, [vp, sz, ctypes.POINTER(sz)]),
        "pds_refine": (i, [vp, dbl]),
        "pds_count": (sz, [vp]),
        "pds_points": (sz, [vp, sz, sz, ctypes.POINTER(dbl)]),
        "pds_radius": (dbl, [vp]),
        "pds_free_area": (dbl, [vp]),
        "pds_verify": (i, [vp]),
        "pds_strerror": (ctypes.c_char_p, [i]),
        "pds_errmsg": (ctypes.c_char_p, [vp]),
        "pds_version_number": (ctypes.c_uint, []),
        "pds_version_string": (ctypes.c_char_p, []),
    }
    for name, (restype, argtypes) in table.items():
        try:
            fn = getattr(lib, name)
        except AttributeError as exc:
            raise ImportError("poissondisk: the library lacks %s" % name) from exc
        fn.restype = restype
        fn.argtypes = argtypes


_lib = _load_library()
_declare(_lib)

if _lib.pds_version_number() // 10000 != _ABI_MAJOR:
    raise ImportError("poissondisk: this binding needs library version %d.x, found %s"
                      % (_ABI_MAJOR, _lib.pds_version_string().decode()))


def _text(raw):
    return raw.decode("utf-8", "replace") if raw is not None else ""


def strerror(code):
    """The library's static text for an error code (unknown codes too)."""
    return _text(_lib.pds_strerror(int(code)))


def version():
    """The library's version as "MAJOR.MINOR.PATCH"."""
    return _text(_lib.pds_version_string())


def version_number():
    """The library's version as MAJOR*10000 + MINOR*100 + PATCH."""
    return int(_lib.pds_version_number())


class PoissonDiskError(Exception):
    """A call into libpoissondisk failed.

    code     the negative PDS_E* code (compare with EINVAL, ERANGE, ...)
    message  what failed, with the library's explanation (pds_errmsg)
    strerror the code's generic text (pds_strerror)
    """

    def __init__(self, code, message):
        super().__init__(code, message)
        self.code = code
        self.message = message
        self.strerror = strerror(code)

    def __str__(self):
        if self.strerror in self.message:  # do not say the same thing twice
            return "%s [code %d]" % (self.message, self.code)
        return "%s [%s, code %d]" % (self.message, self.strerror, self.code)


class Sampler:
    """A Poisson-disk sampler: points at least `radius` apart in a rectangle.

    Sampler(radius, seed=1, domain=None)
      radius  the minimum distance R, finite and > 0
      seed    an integer in [0, 2**64); same seed and version, same points
      domain  (x0, y0, x1, y1), the closed rectangle [x0,x1]x[y0,y1];
              None for the unit square

    Use as a context manager, or call close(), to free the C sampler at once;
    otherwise it is freed when the object is collected.
    """

    _handle = None  # so that close()/__del__ work even if __init__ failed early

    def __init__(self, radius, seed=1, domain=None):
        seed = operator.index(seed)
        if not 0 <= seed < 2 ** 64:
            raise ValueError("seed must be in [0, 2**64), got %d" % seed)
        handle = ctypes.c_void_p()
        rc = _lib.pds_create(ctypes.byref(handle), float(radius), seed)
        if rc < 0:
            # No handle exists, so the code's own text is the explanation.
            raise PoissonDiskError(
                rc, "pds_create(radius=%r): %s" % (radius, strerror(rc)))
        self._handle = handle
        if domain is not None:
            try:
                self.set_domain(*domain)
            except BaseException:
                self.close()
                raise

    # -- lifetime ---------------------------------------------------------------

    def close(self, _destroy=_lib.pds_destroy):
        """Release the C sampler. Safe to call more than once."""
        # _destroy is bound at definition time so this still works while the
        # interpreter shuts down and module globals are already cleared.
        handle, self._handle = self._handle, None
        if handle is not None:
            _destroy(handle)

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        self.close()
        return False

    def _h(self):
        if self._handle is None:
            raise ValueError("operation on a closed Sampler")
        return self._handle

    def _check(self, rc, what):
        if rc < 0:
            msg = _text(_lib.pds_errmsg(self._h()))
            # Name the failing function once, whether or not the library did.
            if not msg.startswith(what + ":"):
                msg = "%s: %s" % (what, msg)
            raise PoissonDiskError(rc, msg)
        return rc

    # -- building the pattern -------------------------------------------------------

    def set_domain(self, x0, y0, x1, y1):
        """Sample [x0,x1]x[y0,y1] instead; only before the first point."""
        self._check(_lib.pds_set_domain(self._h(), float(x0), float(y0), float(x1),
                                        float(y1)), "pds_set_domain")

    def step(self):
        """Add one point. True if one was added, False if the pattern is maximal."""
        return self._check(_lib.pds_step(self._h()), "pds_step") == MORE

    def run(self, max_new=0):
        """Add points until maximal or max_new were added (0: no limit).
        Returns True when the pattern is maximal. The radius is judged with
        the domain at the first point: ERANGE if double precision cannot
        resolve it, or if the points asked for (a whole maximal pattern when
        max_new is 0) cannot fit the library's 32-bit indices."""
        max_new = operator.index(max_new)
        if max_new < 0:
            raise ValueError("max_new must be >= 0, got %d" % max_new)
        added = ctypes.c_size_t(0)
        rc = _lib.pds_run(self._h(), max_new, ctypes.byref(added))
        return self._check(rc, "pds_run") == DONE

    def refine(self, radius):
        """Continue with a smaller radius (0 < radius <= self.radius), keeping
        every point; run() then extends the pattern to maximal at the new radius."""
        self._check(_lib.pds_refine(self._h(), float(radius)), "pds_refine")

    # -- reading it -----------------------------------------------------------------

    @property
    def count(self):
        """Number of points so far."""
        return int(_lib.pds_count(self._h()))

    def __len__(self):
        return self.count

    @property
    def radius(self):
        """The current radius R."""
        return float(_lib.pds_radius(self._h()))

    @property
    def free_area(self):
        """Area where a new point could still go; 0.0 once maximal."""
        return float(_lib.pds_free_area(self._h()))

    def points(self, first=0, count=None):
        """Points first .. first+count-1 (all by default) as a list of (x, y)
        tuples, in insertion order."""
        handle = self._h()
        total = int(_lib.pds_count(handle))
        first = operator.index(first)
        if first < 0:
            raise ValueError("first must be >= 0, got %d" % first)
        if count is None:
            count = max(total - first, 0)
        count = max(min(operator.index(count), total - first), 0)
        buf = (ctypes.c_double * (2 * count))()
        got = int(_lib.pds_points(handle, first, count, buf))
        flat = buf[:2 * got]
        return list(zip(flat[0::2], flat[1::2]))

    def verify(self):
        """Re-check the pattern independently of the sampler's bookkeeping.
        Returns True if valid and maximal, False if valid with room left;
        raises PoissonDiskError if a check fails."""
        return self._check(_lib.pds_verify(self._h()), "pds_verify") == DONE

    def __repr__(self):
        if self._handle is None:
            return "<poissondisk.Sampler closed>"
        return "<poissondisk.Sampler radius=%g count=%d>" % (self.radius, self.count)
