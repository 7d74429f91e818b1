"""Sampler: one libpoissondisk handle as a Python object.

The points come back as a numpy float64 array of shape (N, 2) when numpy can
be imported, filled by pds_points straight into the array's buffer (the C
layout, interleaved x,y, is the array's), and as a list of (x, y) tuples
otherwise; the radii (pds_radii) likewise, shape (N,) or a list of floats.
"""

from __future__ import annotations

import ctypes
import operator
from typing import Any, Callable, List, Optional, Sequence, Tuple, cast

from . import _capi
from ._args import (UNIT_SQUARE, Bounds, Points, ProgressFn, Radii, RadiusFn, _check_bounds,
                    _check_field, _check_seed, _check_threads, _map_buffer, _np, _size_arg)
from ._callbacks import progress_callback, radius_callback
from ._domain import fixed_buffers, mask_buffer, pointer
from ._errors import error_for
from ._geo import Rings, from_domain, ring_label


class Sampler:
    """Exact maximal Poisson-disk sampling in a rectangle, a polygon, an image
    mask or on a torus, around fixed points if given.

    Every pair of points is at least `radius` apart (decided exactly), each
    new point is uniform over the area where a point may still go, and run()
    returns True once every point of the domain, its outline included, lies
    within `radius` of a sample or within a fixed point's clearance (maximal).

    Args:
        radius: the minimum distance R, finite and > 0. May be None when
            `count` is given (the library then chooses it); must be None
            when `radius_map` or `radius_fn` gives the radius.
        bounds: ((x0, y0), (x1, y1)), the closed rectangle [x0,x1]x[y0,y1];
            the unit square by default. With `mask`, the rectangle the mask
            is spread over.
        domain: a polygon (library 1.4): a sequence of rings, each a sequence
            of (x, y) pairs or an (n, 2) array (one ring alone too), or a
            GeoJSON-like Polygon, MultiPolygon, Feature, FeatureCollection or
            GeometryCollection, as a mapping or through __geo_interface__
            (shapely, geopandas). The region is what the rings enclose by
            the even-odd rule (holes and outer rings alike, either way
            round, rings that cross too), outline included; its bounding
            box is `bounds` then (give no bounds). Copied.
        mask: an image domain (library 1.4): a 2-D array of booleans (or
            0/1), shape (h, w), in the image convention: row 0 is the TOP
            row, along y1, column 0 along x0 (as numpy shows an image; note
            radius_map's row 0 lies along y0). The domain is the union of
            the True pixels' squares over `bounds`. Copied.
        fixed: points already there (library 1.4): an (n, 2) array of
            (x, y), or (n, 3) of (x, y, clearance), inside the domain's
            bounding box. Every new point keeps at least the clearance from
            each (0, or (n, 2): the radius in force there, following
            refine()); they count for coverage but are not returned by
            `points` nor counted by len(). Copied.
        seed: an int in [0, 2**64); the same seed and library version give
            the same points. None draws one from os.urandom; read it back
            from `.seed` to repeat the pattern.
        periodic: True samples the rectangle as a flat torus: distances wrap
            around, points lie in [x0,x1)x[y0,y1), and copies shifted by the
            periods tile the plane seamlessly. The radius must be at most half
            the shorter period, and the longer period at most 1024 times the
            shorter (else RangeError at the first point).
        count: a number of points n >= 1: the library chooses the radius so
            that run() ends with exactly n points (then `radius` is the last
            radius used, and refine() is refused).
        progress: a callable fn(count, done), see set_progress().
        threads: None (default) runs the single-thread process, the faster
            one on one core (around fixed points too from library 1.11); an
            int (library 1.5) selects the parallel process on that many
            threads (0: one per core, at most 1024, else ValueError), whose
            points do not depend on the count but differ from the default's.
            The one-radius rectangle, polygon, mask or torus (with count,
            refine or fixed too) uses threads, and so does a radius map
            (library 1.13, with periodic library 1.14; before, the
            single-thread process's points), except with its largest
            radius over 16 times its smallest (8 before library 1.15),
            where it gives the same points either way. See the `threads`
            property.
        radius_map: a variable radius (library 1.3): a 2-D array-like of
            shape (h, w) of radii, each finite and > 0, spread over the
            domain: row 0 along y0, column 0 along x0, bilinear between
            pixel centres and constant beyond the outer ones. Copied.
        radius_fn, rmin, rmax: a variable radius from a callable
            fn(x, y) -> float, with the bounds of its values, both
            required, finite, 0 < rmin <= rmax. It is called once per
            point as it is placed (with threads, when its dart is
            accepted, up to one epoch of darts before run() returns the
            point; a refine() in between drops such darts) and, with a
            progress callback, 4096 times over a grid at the first run()
            for the progress estimate (not at all when rmin == rmax). A
            value outside [rmin, rmax] or not finite stops run()/step()
            with InvalidArgumentError before the point is added; an
            exception raised by fn stops it too and comes out of
            run()/step(). Either way the points so far stay and the
            sampler can go on (with threads, the darts of that epoch
            accepted before it are not added; the next call meets the same
            value again). fn may read the sampler but not change or close
            it (StateError).

    With a field, point i gets the radius r_i = r(p_i) where it lands, and
    each later point keeps out of its closed disk: |p_j - p_i| >= r_i for
    i < j. `radius` is then the largest radius in force (rmax: the map's
    largest value, or the declared bound), radii() gives each point's, and
    refine(R) scales them all by R / radius. A field works with `periodic`
    (rmax at most half the shorter period) but not with `count`
    (ValueError). A constant field gives exactly the
    points of the plain sampler at that radius.

    Errors of the library raise subclasses of PoissonDiskError carrying its
    message; misuse on the Python side raises ValueError or TypeError, and
    a count beyond what a C size_t holds OverflowError.
    Use it as a context manager, or call close(), to free the C sampler at
    once. One Sampler must be used by one thread at a time. A Sampler owns
    its C sampler alone: copy.copy, copy.deepcopy and pickle raise
    TypeError (a new Sampler with the same arguments and seed repeats the
    points).
    """

    _handle: Optional[ctypes.c_void_p] = None  # close()/__del__ work if __init__ failed
    # (the C callback, self._errors: what the callbacks raised) while a
    # progress function is set: the library holds a pointer into the first,
    # so it must stay alive.
    _progress: Optional[Tuple[Any, List[BaseException]]] = None
    # The C callback of a radius function, kept alive as the library holds it.
    _radius_fn: Any = None
    # What is running in the C sampler now, innermost last ("run()", then
    # "the progress callback", ...): close() is refused while it is not empty,
    # as the library is still using the handle. Shared with the callbacks.
    _calls: Sequence[str] = ()  # the instance's own list from __init__ on

    def __init__(self, radius: Optional[float], *,
                 bounds: Optional[Sequence[Sequence[float]]] = None,
                 seed: Optional[int] = None, periodic: bool = False,
                 count: Optional[int] = None, progress: Optional[ProgressFn] = None,
                 radius_map: Any = None, radius_fn: Optional[RadiusFn] = None,
                 rmin: Optional[float] = None, rmax: Optional[float] = None,
                 domain: Any = None, mask: Any = None, fixed: Any = None,
                 threads: Optional[int] = None) -> None:
        # What the callbacks raised during the current run()/step(), first
        # first. Shared by them; they hold the list, not self (no cycle).
        self._errors: List[BaseException] = []
        self._calls: List[str] = []
        self._seed = _check_seed(seed)
        threads = _check_threads(threads)
        if domain is not None and (mask is not None or bounds is not None):
            raise TypeError("give domain= alone: its bounding box is the domain's rectangle "
                            "(bounds= goes with a rectangle or a mask)")
        self._bounds = _check_bounds(UNIT_SQUARE if bounds is None else bounds)
        # The shapes are checked before the C sampler exists; the values by the library.
        rings = from_domain(domain) if domain is not None else None
        raster = mask_buffer(mask) if mask is not None else None
        points = fixed_buffers(fixed) if fixed is not None else None
        field = _check_field(radius, radius_map, radius_fn, rmin, rmax)
        if field is not None:
            if count is not None:
                raise ValueError("a variable radius (%s) is not supported with count=" % field)
            radius = 1.0  # replaced by the field's largest radius
        elif radius is None:
            if count is None:
                raise TypeError("Sampler() needs a radius unless count, radius_map or "
                                "radius_fn is given")
            radius = 1.0  # ignored by the library in count mode
        handle = ctypes.c_void_p()
        rc = _capi.lib.pds_create(ctypes.byref(handle), float(radius), self._seed)
        if rc < 0:
            # No handle exists, so the code's own text is the explanation.
            raise error_for(rc, "pds_create(radius=%r): %s" % (radius, _capi.strerror(rc)))
        self._handle = handle
        self._periodic = bool(periodic)
        try:
            (x0, y0), (x1, y1) = self._bounds
            self._check(_capi.lib.pds_set_domain(handle, x0, y0, x1, y1), "pds_set_domain")
            if periodic:
                self._check(_capi.need("pds_set_periodic")(handle, 1), "pds_set_periodic")
            if count is not None:
                count = operator.index(count)
                if count < 0:
                    raise ValueError("count must be >= 1, got %d" % count)
                # 0 is the library's to refuse, with its message.
                count = _size_arg(count, "count", 0)
                self._check(_capi.need("pds_set_count")(handle, count), "pds_set_count")
            if rings is not None:
                self._set_polygon(rings)
            elif raster is not None:
                w, h, inside = raster
                inside_p = pointer(inside, ctypes.c_ubyte)
                self._check(_capi.need("pds_set_mask")(handle, w, h, inside_p), "pds_set_mask")
            if points is not None:
                n, xy, clearance = points
                self._check(_capi.need("pds_set_fixed")(
                    handle, pointer(xy, ctypes.c_double),
                    None if clearance is None else pointer(clearance, ctypes.c_double), n),
                    "pds_set_fixed")
            if radius_map is not None:
                self._set_radius_map(radius_map)
            elif radius_fn is not None:
                self._set_radius_fn(radius_fn, cast(float, rmin), cast(float, rmax))
            if progress is not None:
                self.set_progress(progress)
            if threads is not None:  # None: never selected, the single-thread process
                self.threads = threads
        except BaseException:
            self.close()
            raise

    # -- lifetime -----------------------------------------------------------------

    def close(self, _destroy: Callable[[Any], None] = _capi.lib.pds_destroy) -> None:
        """Release the C sampler. Safe to call more than once. Refused with
        StateError from inside a callback of this sampler (run() is still
        using it): close it once run() or step() has returned."""
        # _destroy is bound at definition time so this still works while the
        # interpreter shuts down and module globals are already cleared.
        if self._calls:
            outer, inner = self._calls[0], self._calls[-1]
            where = "from inside %s: %s is" % (inner, outer) if inner != outer else "while %s is" % outer
            raise error_for(_capi.ESTATE, "Sampler.close: not allowed %s still using the sampler; "
                            "close it after %s returns" % (where, outer))
        handle, self._handle = self._handle, None
        if handle is not None:
            _destroy(handle)
        self._progress = None  # the library no longer calls them
        self._radius_fn = None

    @property
    def closed(self) -> bool:
        """True once close() was called (or the with block was left)."""
        return self._handle is None

    def __del__(self) -> None:
        self.close()

    def __enter__(self) -> "Sampler":
        return self

    def __exit__(self, *exc_info: Any) -> None:
        self.close()

    def _refuse_copy(self, *args: Any) -> Any:
        raise TypeError("a poissondisk.Sampler cannot be copied or pickled: it owns its C "
                        "sampler alone; make a new Sampler with the same arguments and seed "
                        "(.seed) to repeat the points")

    __copy__ = __deepcopy__ = __reduce_ex__ = __reduce__ = _refuse_copy

    def _c_call(self, what: str, name: str, *args: Any) -> int:
        """The C function `name` called with args, a call that may run the
        callbacks: marked as running while it does (for close()), then
        checked as _checked_call does."""
        fn = getattr(_capi.lib, name)
        del self._errors[:]
        self._calls.append(what)
        try:
            rc = fn(*args)
        finally:
            self._calls.pop()
        return self._checked_call(rc, name)

    def _h(self) -> ctypes.c_void_p:
        if self._handle is None:
            raise ValueError("operation on a closed Sampler")
        return self._handle

    def _check(self, rc: int, what: str, rings: Optional[Rings] = None) -> int:
        if rc < 0:
            msg = _capi.text(_capi.lib.pds_errmsg(self._h()))
            # Name the failing function once, whether or not the library did.
            if not msg.startswith(what + ":"):
                msg = "%s: %s" % (what, msg)
            raise error_for(rc, ring_label(rings, msg))
        return rc

    def _checked_call(self, rc: int, what: str) -> int:
        """_check for a call that ran the callbacks: what one of them raised
        comes first (it is what stopped the call, with its own traceback)."""
        errors = self._errors
        if errors:
            exc = errors[0]
            del errors[:]
            raise exc
        return self._check(rc, what)

    def _set_polygon(self, rings: Rings) -> None:
        rc = _capi.need("pds_set_polygon")(self._h(), pointer(rings.xy, ctypes.c_double),
                                           rings.ends, rings.nrings)
        self._check(rc, "pds_set_polygon", rings)
        self._bounds = rings.bounding_box()  # the library's rectangle now

    def _set_radius_map(self, radius_map: Any) -> None:
        w, h, buf = _map_buffer(radius_map)
        if _np is not None and isinstance(buf, _np.ndarray):
            ptr = buf.ctypes.data_as(_capi.DOUBLE_P)
        else:
            ptr = ctypes.cast(buf, _capi.DOUBLE_P)
        # The library copies the map: buf may go once this returns.
        self._check(_capi.need("pds_set_radius_map")(self._h(), w, h, ptr), "pds_set_radius_map")

    def _set_radius_fn(self, fn: RadiusFn, rmin: float, rmax: float) -> None:
        callback = radius_callback(fn, self._errors, self._calls)
        rmin, rmax = float(rmin), float(rmax)  # the library judges them
        self._check(_capi.need("pds_set_radius_fn")(self._h(), callback, None, rmin, rmax),
                    "pds_set_radius_fn")
        self._radius_fn = callback  # only once the library holds it

    # -- building the pattern -----------------------------------------------------

    def run(self, max_new: Optional[int] = None) -> bool:
        """Add points until the pattern is maximal, or until max_new were added.

        Returns True when the pattern is maximal (in count mode: when the
        count is reached), False when max_new points were added and room is
        left. The same seed gives the same points however a run is split.
        Raises RangeError when the radius does not suit the domain (judged at
        the first point), CanceledError when the progress callback returned
        a true value, InvalidArgumentError when the radius function gave a
        value outside [rmin, rmax], and whatever a callback (progress or
        radius function) raised if it raised.
        """
        # 0 is the C API's "no limit"
        limit = 0 if max_new is None else _size_arg(max_new, "max_new", 1)
        added = ctypes.c_size_t(0)
        handle = self._h()
        rc = self._c_call("run()", "pds_run", handle, limit, ctypes.byref(added))
        return rc == _capi.DONE

    def step(self) -> bool:
        """Add one point: True if one was added, False if the pattern is maximal.
        With a radius function, raises as run() does when it refuses a point."""
        return self._c_call("step()", "pds_step", self._h()) == _capi.MORE

    def refine(self, radius: float) -> None:
        """Go on at a smaller radius (0 < radius <= self.radius), keeping every
        point; run() then extends the pattern to maximal at the new radius.
        With a variable radius every radius, old points' too, is scaled by
        radius / self.radius."""
        self._check(_capi.lib.pds_refine(self._h(), float(radius)), "pds_refine")

    def set_progress(self, fn: Optional[ProgressFn]) -> None:
        """Have run() call fn(count, done) between points.

        count points exist and done estimates the fraction made (0..1,
        exactly count/n in count mode, 1 when complete). It is called when
        done grew by 1% or a second passed, so about a hundred times per run.
        A true return value stops run() with CanceledError; an exception
        raised by fn stops it too and run() raises that exception (so Ctrl-C
        during a run stops it cleanly). Either way the points stay, and a
        later run() continues to exactly the pattern an uninterrupted run
        gives. fn may read the sampler (len, points) but not change or close
        it (StateError). None removes the callback.
        """
        handle = self._h()
        setter = _capi.need("pds_set_progress")
        if fn is None:
            null = _capi.PROGRESS_FN(0)  # a NULL function pointer
            self._check(setter(handle, null, None), "pds_set_progress")
            self._progress = None
            return
        if not callable(fn):
            raise TypeError("set_progress() needs a callable or None, got %r" % (fn,))
        callback = progress_callback(fn, self._errors, self._calls)
        self._check(setter(handle, callback, None), "pds_set_progress")
        self._progress = (callback, self._errors)  # only once the library holds it

    # -- reading it ---------------------------------------------------------------

    def __len__(self) -> int:
        return int(_capi.lib.pds_count(self._h()))

    @property
    def points(self) -> Points:
        """All points in insertion order: a new float64 array of shape (N, 2)
        (a list of (x, y) tuples without numpy). Every prefix of it is itself
        a Poisson-disk set."""
        return self.get_points()

    @staticmethod
    def _slice(handle: Any, first: int, count: Optional[int]) -> Tuple[int, int]:
        """(first, n): the slice of points first .. first+count-1 that exist."""
        total = int(_capi.lib.pds_count(handle))
        first = operator.index(first)
        if first < 0:
            raise ValueError("first must be >= 0, got %d" % first)
        avail = max(total - first, 0)
        return first, avail if count is None else max(min(operator.index(count), avail), 0)

    def get_points(self, first: int = 0, count: Optional[int] = None) -> Points:
        """Points first .. first+count-1 (to the end by default), clipped to
        the points that exist; same types as `points`."""
        handle = self._h()
        first, n = self._slice(handle, first, count)
        if _np is not None:
            out = _np.empty((n, 2), dtype=_np.float64)
            if n:
                got = _capi.lib.pds_points(handle, first, n, out.ctypes.data_as(_capi.DOUBLE_P))
                if got != n:
                    out = out[:got]
            return out
        buf = (ctypes.c_double * (2 * n))()
        got = int(_capi.lib.pds_points(handle, first, n, buf)) if n else 0
        flat = buf[:2 * got]
        return list(zip(flat[0::2], flat[1::2]))

    def radii(self, first: int = 0, count: Optional[int] = None) -> Radii:
        """The radius in force of each point, in insertion order: a new float64
        array of shape (N,) (a list of floats without numpy); first and count
        select a slice as in get_points(). Without a variable radius each is
        `radius`; with one, point i's radius r_i = r(p_i) (scaled by refine),
        and every later point is at least r_i from it."""
        handle = self._h()
        copy = _capi.need("pds_radii")
        first, n = self._slice(handle, first, count)
        if _np is not None:
            out = _np.empty(n, dtype=_np.float64)
            if n:
                got = copy(handle, first, n, out.ctypes.data_as(_capi.DOUBLE_P))
                if got != n:
                    out = out[:got]
            return out
        buf = (ctypes.c_double * n)()
        got = int(copy(handle, first, n, buf)) if n else 0
        return buf[:got]

    @property
    def radius(self) -> float:
        """The current radius R (in count mode, the last one the library used;
        with a variable radius, the largest in force: rmax until refine())."""
        return float(_capi.lib.pds_radius(self._h()))

    @property
    def free_area(self) -> float:
        """Area where a new point could still go: the domain's area before the
        first point, exactly 0.0 once maximal. O(N) while room is left."""
        return float(_capi.lib.pds_free_area(self._h()))

    @property
    def seed(self) -> int:
        """The seed of this pattern (the one drawn from os.urandom if None was given)."""
        return self._seed

    @property
    def bounds(self) -> Bounds:
        """((x0, y0), (x1, y1)) as given, or the polygon's bounding box."""
        return self._bounds

    @property
    def periodic(self) -> bool:
        """True when the domain is a torus."""
        return self._periodic

    @property
    def threads(self) -> int:
        """The threads a run may use (0 given: resolved to the core count);
        1 until set. Setting it before the first point selects the parallel
        process; once selected it may change at any time, between run()
        calls too, without changing the points. Setting it after points of
        the single-thread process exist raises StateError; ValueError
        outside [0, 1024]."""
        if "pds_threads" in _capi._missing:
            return 1  # a library before 1.5 runs on one thread
        return int(_capi.need("pds_threads")(self._h()))

    @threads.setter
    def threads(self, n: int) -> None:
        n = _check_threads(operator.index(n))  # None is not a count here
        self._check(_capi.need("pds_set_threads")(self._h(), n), "pds_set_threads")

    def verify(self) -> bool:
        """Re-check the pattern from scratch, independently of the sampler's
        bookkeeping: True if valid and maximal, False if valid with room left.
        Raises InternalError if a check fails (a bug in the library)."""
        return self._check(_capi.lib.pds_verify(self._h()), "pds_verify") == _capi.DONE

    def __repr__(self) -> str:
        if self._handle is None:
            return "<poissondisk.Sampler closed>"
        return "<poissondisk.Sampler radius=%g points=%d seed=%d>" % (
            self.radius, len(self), self._seed)

