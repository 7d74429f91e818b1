"""poissondisk: exact maximal Poisson-disk sampling in the plane.

A binding of libpoissondisk (Jones 2006, exact arithmetic) through ctypes;
numpy is used when present but not needed.

    with poissondisk.Sampler(0.02, seed=7) as s:
        s.run()              # True: maximal, no room left for another point
        pts = s.points       # numpy float64 array, shape (N, 2)

`poissondisk.qmc.PoissonDisk` is a drop-in for scipy.stats.qmc.PoissonDisk
(2-D only), and `poissondisk.sample()` is the one-call form.

The shared library is found through the normal loader (libpoissondisk.so.1,
as installed by `make install`); POISSONDISK_LIBRARY=/path/to/libpoissondisk.so.1
names another one, e.g. an uninstalled build.
"""

from __future__ import annotations

from typing import Any, Optional, Sequence

from ._capi import (DONE, ECANCELED, EINTERNAL, EINVAL, ENOMEM, ERANGE, ESTATE, MORE,
                    library_path, strerror, version, version_number)
from ._errors import (CanceledError, InternalError, InvalidArgumentError, OutOfMemoryError,
                      PoissonDiskError, RangeError, StateError)
from ._args import UNIT_SQUARE, Points, ProgressFn, Radii, RadiusFn, random_seed
from ._sampler import Sampler

__version__ = "1.16.0"  # of this package; version() is the loaded library's


def sample(radius: Optional[float], *, bounds: Optional[Sequence[Sequence[float]]] = None,
           seed: Optional[int] = None, periodic: bool = False,
           count: Optional[int] = None, radius_map: Any = None,
           radius_fn: Optional[RadiusFn] = None, rmin: Optional[float] = None,
           rmax: Optional[float] = None, domain: Any = None, mask: Any = None,
           fixed: Any = None, threads: Optional[int] = None) -> Points:
    """A maximal pattern in one call: Sampler(...) run to the end, its points.

    Same arguments as Sampler; returns a float64 array of shape (N, 2) (a
    list of (x, y) tuples without numpy). Fixed points are not among them.
    threads: None (default) runs the single-thread process; an int selects
    the parallel process on that many threads (0: one per core), whose
    points do not depend on the count but differ from the default's.
    """
    with Sampler(radius, bounds=bounds, seed=seed, periodic=periodic, count=count,
                 radius_map=radius_map, radius_fn=radius_fn, rmin=rmin, rmax=rmax,
                 domain=domain, mask=mask, fixed=fixed, threads=threads) as s:
        s.run()
        return s.points


__all__ = [
    "Sampler", "sample", "random_seed", "Points", "ProgressFn", "Radii", "RadiusFn", "version", "version_number", "strerror",
    "library_path", "PoissonDiskError", "InvalidArgumentError", "OutOfMemoryError",
    "StateError", "RangeError", "InternalError", "CanceledError",
    "EINVAL", "ENOMEM", "ESTATE", "ERANGE", "EINTERNAL", "ECANCELED", "DONE", "MORE",
]
