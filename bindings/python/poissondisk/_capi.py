"""The low-level layer: loading libpoissondisk and declaring its C API.

Every function of include/poissondisk.h gets its exact C signature here, and
nothing else in the package calls ctypes on the library directly. Standard
library only.

Where the library comes from, first match wins:
  1. the path in POISSONDISK_LIBRARY (PDS_LIBRARY, the older name, too), for
     an uninstalled build: POISSONDISK_LIBRARY=/path/to/build/libpoissondisk.so.1;
     if it is set and cannot be loaded, the import fails (no silent fallback);
  2. the soname through the normal loader, as any program linked with
     -lpoissondisk finds it (LD_LIBRARY_PATH, the ld.so cache, the default
     directories), then ctypes.util.find_library("poissondisk");
  3. the libdir that pkg-config reports for poissondisk, then /usr/local/lib:
     `make install` puts the library there, and the loader finds it there
     only once `ldconfig` has refreshed its cache.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import subprocess
import sys
from typing import Callable, List, Optional, Set, Tuple, cast

# Error codes, fixed by the header (never renumbered).
EINVAL = -1
ENOMEM = -2
ESTATE = -3
ERANGE = -4
EINTERNAL = -5
ECANCELED = -6  # the progress callback stopped pds_run (1.2)

# Named results of pds_step, pds_run and pds_verify (1.1.1).
DONE = 0  # the pattern is maximal
MORE = 1  # step: a point was added; run: limit reached, room left; verify: room left

ABI_MAJOR = 1  # the soname major this binding was written for
SONAME = "libpoissondisk.so.%d" % ABI_MAJOR
ENV_VARS = ("POISSONDISK_LIBRARY", "PDS_LIBRARY")

# typedef int (*pds_progress_fn)(void *user, size_t count, double done); (1.2)
PROGRESS_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_size_t,
                               ctypes.c_double)
# typedef double (*pds_radius_fn)(void *user, double x, double y); (1.3)
RADIUS_FN = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.c_void_p, ctypes.c_double,
                             ctypes.c_double)
DOUBLE_P = ctypes.POINTER(ctypes.c_double)

# Functions of later minor versions: a library without them still loads, and
# what needs them raises NotImplementedError when called.
OPTIONAL = {"pds_set_periodic": "1.2", "pds_set_count": "1.2", "pds_set_progress": "1.2",
            "pds_set_radius_map": "1.3", "pds_set_radius_fn": "1.3", "pds_radii": "1.3",
            "pds_set_polygon": "1.4", "pds_set_mask": "1.4", "pds_set_fixed": "1.4",
            "pds_set_threads": "1.5", "pds_threads": "1.5"}


def _installed_libdirs() -> List[str]:
    """Directories `make install` may have used that the loader may not search."""
    dirs = []
    try:
        out = subprocess.run(["pkg-config", "--variable=libdir", "poissondisk"],
                             capture_output=True, text=True, timeout=10)
        if out.returncode == 0 and out.stdout.strip():
            dirs.append(out.stdout.strip())
    except (OSError, subprocess.SubprocessError):
        pass  # no pkg-config: the fixed guess below still applies
    dirs.append("/usr/local/lib")
    return dirs


def _load() -> Tuple[ctypes.CDLL, str]:
    for var in ENV_VARS:
        path = os.environ.get(var)
        if path:
            try:
                return ctypes.CDLL(path), path
            except OSError as exc:
                raise ImportError("poissondisk: cannot load the library named by %s=%r: %s"
                                  % (var, path, exc)) from exc
    tried = []
    candidates = [SONAME]
    found = ctypes.util.find_library("poissondisk")
    if found and found != SONAME:
        candidates.append(found)
    if sys.platform.startswith("linux"):
        candidates += [os.path.join(d, SONAME) for d in _installed_libdirs()]
    for name in candidates:
        try:
            return ctypes.CDLL(name), name
        except OSError as exc:
            tried.append("%s (%s)" % (name, exc))
    raise ImportError(
        "poissondisk: libpoissondisk not found; install it (make install, then ldconfig) "
        "or set POISSONDISK_LIBRARY to the full path of %s. Tried: %s"
        % (SONAME, "; ".join(tried)))


def _declare(lib: ctypes.CDLL) -> Set[str]:
    """Give every function of the header its C signature; returns the names of
    the optional functions this library lacks."""
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
        "pds_points": (sz, [vp, sz, sz, DOUBLE_P]),
        "pds_radius": (dbl, [vp]),
        "pds_free_area": (dbl, [vp]),
        "pds_verify": (i, [vp]),
        "pds_strerror": (ctypes.c_char_p, [i]),
        "pds_errmsg": (ctypes.c_char_p, [vp]),
        "pds_version_number": (ctypes.c_uint, []),
        "pds_version_string": (ctypes.c_char_p, []),
        "pds_set_periodic": (i, [vp, i]),
        "pds_set_count": (i, [vp, sz]),
        "pds_set_progress": (i, [vp, PROGRESS_FN, vp]),
        "pds_set_radius_map": (i, [vp, sz, sz, DOUBLE_P]),
        "pds_set_radius_fn": (i, [vp, RADIUS_FN, vp, dbl, dbl]),
        "pds_radii": (sz, [vp, sz, sz, DOUBLE_P]),
        "pds_set_polygon": (i, [vp, DOUBLE_P, ctypes.POINTER(sz), sz]),
        "pds_set_mask": (i, [vp, sz, sz, ctypes.POINTER(ctypes.c_ubyte)]),
        "pds_set_fixed": (i, [vp, DOUBLE_P, DOUBLE_P, sz]),
        "pds_set_threads": (i, [vp, ctypes.c_uint]),
        "pds_threads": (ctypes.c_uint, [vp]),
    }
    missing = set()
    for name, (restype, argtypes) in table.items():
        try:
            fn = getattr(lib, name)
        except AttributeError as exc:
            if name in OPTIONAL:
                missing.add(name)
                continue
            raise ImportError("poissondisk: the library lacks %s" % name) from exc
        fn.restype = restype
        fn.argtypes = argtypes
    return missing


lib, library_path = _load()
_missing = _declare(lib)

if lib.pds_version_number() // 10000 != ABI_MAJOR:
    raise ImportError("poissondisk: this binding needs library version %d.x, found %s (%s)"
                      % (ABI_MAJOR, lib.pds_version_string().decode(), library_path))


def text(raw: Optional[bytes]) -> str:
    return raw.decode("utf-8", "replace") if raw is not None else ""


INT_MAX = 2 ** (8 * ctypes.sizeof(ctypes.c_int) - 1) - 1
INT_MIN = -INT_MAX - 1


def strerror(code: int) -> str:
    """The library's static text for an error code (unknown codes too);
    OverflowError for an int that is no C int (ctypes would wrap it around
    onto another code)."""
    code = int(code)
    if not INT_MIN <= code <= INT_MAX:
        raise OverflowError("strerror(%d): an error code is a C int, in [%d, %d]"
                            % (code, INT_MIN, INT_MAX))
    return text(lib.pds_strerror(code))


def version() -> str:
    """The loaded library's version as "MAJOR.MINOR.PATCH"."""
    return text(lib.pds_version_string())


def version_number() -> int:
    """The loaded library's version as MAJOR*10000 + MINOR*100 + PATCH."""
    return int(lib.pds_version_number())


def need(name: str) -> Callable[..., int]:
    """The library function `name`, or NotImplementedError if it is too old."""
    if name in _missing:
        raise NotImplementedError("poissondisk: %s needs library %s or later, found %s"
                                  % (name, OPTIONAL[name], version()))
    return cast(Callable[..., int], getattr(lib, name))
