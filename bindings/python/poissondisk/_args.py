"""The arguments of a Sampler, checked and converted on the Python side before
anything crosses into C: the seed, counts (size_t), the bounds, which field
gives the radius, and a radius map as a C array of doubles.
"""

from __future__ import annotations

import ctypes
import operator
import os
from typing import TYPE_CHECKING, Any, Callable, List, Optional, Sequence, Tuple, Union

if TYPE_CHECKING:
    import numpy

try:
    import numpy as _np
except ImportError:  # the list fallback
    _np = None  # type: ignore[assignment]

# The largest value a size_t argument of the C API holds. ctypes converts a
# larger Python int by dropping its high bits (2**64 + 5 becomes 5), so every
# count crosses into C through _size_arg, which refuses what would wrap.
SIZE_MAX = 2 ** (8 * ctypes.sizeof(ctypes.c_size_t)) - 1

Bounds = Tuple[Tuple[float, float], Tuple[float, float]]
# fn(count, done): count points exist, done in [0, 1]; a true result cancels.
ProgressFn = Callable[[int, float], Any]
# fn(x, y): the radius at user point (x, y), within [rmin, rmax].
RadiusFn = Callable[[float, float], float]
Points = Union["numpy.ndarray", List[Tuple[float, float]]]
Radii = Union["numpy.ndarray", List[float]]

UNIT_SQUARE: Bounds = ((0.0, 0.0), (1.0, 1.0))


def random_seed() -> int:
    """A seed in [0, 2**64) from the operating system's entropy."""
    return int.from_bytes(os.urandom(8), "little")


def _check_seed(seed: Optional[int]) -> int:
    if seed is None:
        return random_seed()
    seed = operator.index(seed)
    if not 0 <= seed < 2 ** 64:
        raise ValueError("seed must be in [0, 2**64), got %d" % seed)
    return seed


# The most threads pds_set_threads takes; 0 means one per online core.
MAX_THREADS = 1024


def _check_threads(threads: Optional[int]) -> Optional[int]:
    """threads as None (the single-thread process: pds_set_threads is never
    called) or an int in [0, MAX_THREADS] (ctypes would wrap a negative or
    huge one into the C unsigned)."""
    if threads is None:
        return None
    threads = operator.index(threads)
    if not 0 <= threads <= MAX_THREADS:
        raise ValueError("threads must be None or in [0, %d] (0: one per online core), got %d"
                         % (MAX_THREADS, threads))
    return threads


def _size_arg(value: int, name: str, least: int) -> int:
    """value as an int in [least, SIZE_MAX], for a size_t argument of the C
    API: ValueError below least, OverflowError above SIZE_MAX (rather than
    the silent wrap-around of ctypes)."""
    value = operator.index(value)
    if value < least:
        raise ValueError("%s must be >= %d, got %d" % (name, least, value))
    if value > SIZE_MAX:
        raise OverflowError("%s=%d is more than the library can take (at most 2**%d - 1)"
                            % (name, value, 8 * ctypes.sizeof(ctypes.c_size_t)))
    return value


def _check_bounds(bounds: Sequence[Sequence[float]]) -> Bounds:
    try:
        (x0, y0), (x1, y1) = bounds
    except (TypeError, ValueError):
        raise TypeError("bounds must be ((x0, y0), (x1, y1)), got %r" % (bounds,)) from None
    return (float(x0), float(y0)), (float(x1), float(y1))


def _check_field(radius: Optional[float], radius_map: Any, radius_fn: Optional[RadiusFn],
                 rmin: Optional[float], rmax: Optional[float]) -> Optional[str]:
    """Which of radius_map / radius_fn defines the radius ("radius_map",
    "radius_fn"), or None for a constant radius; TypeError for a combination
    that does not say which."""
    if radius_fn is None:
        if rmin is not None or rmax is not None:
            raise TypeError("rmin and rmax are the bounds of radius_fn; give them with it")
        if radius_map is None:
            return None
        field = "radius_map"
    else:
        if radius_map is not None:
            raise TypeError("give radius_map or radius_fn, not both")
        if not callable(radius_fn):
            raise TypeError("radius_fn must be a callable fn(x, y) -> radius, got %r"
                            % (radius_fn,))
        if rmin is None or rmax is None:
            raise TypeError("radius_fn needs rmin and rmax, the bounds of its values")
        field = "radius_fn"
    if radius is not None:
        raise TypeError("give radius=None with %s: the field defines the radius" % field)
    return field


def _map_buffer(radius_map: Any) -> Tuple[int, int, Any]:
    """(w, h, buffer): an (h, w) radius map as w*h C doubles, row-major, row 0
    first. The buffer is a numpy array or a ctypes array, never empty (an
    empty map keeps its shape, for the library to refuse with its message)."""
    if _np is not None:
        try:
            arr = _np.asarray(radius_map, dtype=_np.float64)
        except (TypeError, ValueError) as exc:
            raise type(exc)("radius_map must be a 2-D array-like of numbers, shape (h, w): %s"
                            % exc) from None
        if arr.ndim == 0:
            raise TypeError("radius_map must be a 2-D array-like (a sequence of rows of "
                            "numbers), got %r" % (type(radius_map).__name__,))
        if arr.ndim == 1 and arr.size == 0:
            arr = arr.reshape(0, 0)  # [] is a map with no rows, as without numpy
        if arr.ndim != 2:
            raise ValueError("radius_map must be 2-D, shape (h, w) (row 0 along y0), got %d-D "
                             "shape %r" % (arr.ndim, arr.shape))
        h, w = arr.shape
        if arr.size == 0:
            arr = _np.zeros(1)  # a valid pointer; w or h 0 is the library's to refuse
        return w, h, _np.ascontiguousarray(arr)  # row-major, copied only if need be
    try:
        outer = list(radius_map)
    except TypeError:
        raise TypeError("radius_map must be a 2-D array-like (a sequence of rows of "
                        "numbers), got %r" % (type(radius_map).__name__,)) from None
    rows = []
    for j, row in enumerate(outer):
        try:
            rows.append(list(row))
        except TypeError:
            raise ValueError("radius_map must be 2-D, shape (h, w) (row 0 along y0): row %d "
                             "is %r, not a sequence of numbers" % (j, row)) from None
    h = len(rows)
    w = len(rows[0]) if rows else 0
    for j, row in enumerate(rows):
        if len(row) != w:
            raise ValueError("radius_map rows must all have the same length: row 0 has %d "
                             "values, row %d has %d" % (w, j, len(row)))
    buf = (ctypes.c_double * max(w * h, 1))()
    k = 0
    for row in rows:
        for v in row:
            try:
                buf[k] = float(v)
            except (TypeError, ValueError):
                raise ValueError("radius_map must hold numbers, got %r at row %d, column %d"
                                 % (v, k // w, k % w)) from None
            k += 1
    return w, h, buf
