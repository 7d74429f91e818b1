"""A drop-in for scipy.stats.qmc.PoissonDisk in two dimensions.

    from poissondisk.qmc import PoissonDisk     # instead of scipy.stats.qmc
    engine = PoissonDisk(2, radius=0.05, seed=7)
    pts = engine.fill_space()                   # (n, 2) float64, maximal

Same constructor arguments, methods and shapes as scipy's engine, with these
differences:
  - the pattern is exact and maximal: every pair is at least `radius` apart
    (decided with exact arithmetic), and fill_space() stops only when no point
    of the domain is farther than `radius` from every sample (scipy's Bridson
    fill leaves gaps and stops at about 88% of that count); each new point is
    uniform over the free area (dart throwing run to saturation);
  - d must be 2 (ValueError otherwise, after the checks scipy makes first);
  - `hypersphere` ("volume" or "surface") and `ncandidates` are accepted and
    checked as scipy does but change nothing: they shape Bridson's candidates,
    and this sampler has none (each point is drawn exactly uniformly over the
    free area), so the law of the pattern is the same whatever they are;
  - `optimization` ("random-cd" or "lloyd", any case) needs scipy: as in
    scipy, each batch random() returns (fill_space() is one batch) goes
    through scipy's optimizer, with scipy's settings. The optimizers move
    points, so the spacing is no longer guaranteed (scipy documents the same),
    the next batches keep their distance from the points as sampled, not as
    moved, and the points depend on how they are split into random() calls. A
    batch of 1 or 2 points comes back unmoved with "lloyd" (qhull needs 3;
    scipy's engine raises there). Other bounds than the unit square are
    mapped to it for the optimizer and back. Without scipy, "random-cd" and
    "lloyd" raise ImportError naming scipy (None works);
  - `workers` is accepted and ignored, as scipy does for this engine; the
    keyword `threads` (not scipy's): None (default) runs the library's
    single-thread process; an int selects its parallel process on that many
    threads (0: one per core), whose points do not depend on the count but
    differ from the default's;
  - once the space is full, random() returns an empty (0, 2) array;
  - the same seed gives other points than scipy's (another algorithm), and
    without optimization the points are the same however they are split into
    random() calls;
  - `radius` is in the units of the bounds, as in scipy >= 1.15, which
    samples the box [l_bounds, u_bounds] directly;
  - integers() takes the points relative to the box [l_bounds, u_bounds];
  - copy.copy, copy.deepcopy and pickle give an independent engine that goes
    on with exactly the points the original would give next (it regenerates
    the points so far from the seed); unpickling needs the same library
    version.
Needs numpy (the results are arrays); scipy only for `optimization`.
"""

from __future__ import annotations

import copy
import hashlib
import math
import numbers
import operator
from typing import TYPE_CHECKING, Any, Dict, Optional, Sequence, Union, cast

try:
    import numpy as np
except ImportError as exc:  # the Sampler works without numpy, this module cannot
    raise ImportError("poissondisk.qmc needs numpy (its results are numpy arrays); "
                      "poissondisk.Sampler works without it") from exc

from . import _capi, _qmc_optimize
from ._args import _check_threads, _size_arg, random_seed
from ._sampler import Sampler

if TYPE_CHECKING:
    from numpy.typing import NDArray

SeedLike = Union[None, int, "np.random.Generator", "np.random.RandomState",
                 "np.random.SeedSequence"]


def seed_to_int(seed: Any) -> int:
    """The library's 64-bit seed for a scipy-style seed.

    None: fresh entropy from the operating system. An int (numpy ints too):
    used as it is when below 2**64, hashed down when larger (numpy accepts any
    non-negative int). A numpy Generator or RandomState: one 64-bit value is
    drawn from it (which advances it, as scipy's engines do when they use
    it). A SeedSequence: its first 64-bit state word.
    """
    if seed is None:
        return random_seed()
    if isinstance(seed, numbers.Integral):
        value = operator.index(seed)
        if value < 0:
            raise ValueError("seed must be non-negative, got %d" % value)
        if value < 2 ** 64:
            return value
        raw = value.to_bytes((value.bit_length() + 7) // 8, "little")
        return int.from_bytes(hashlib.blake2b(raw, digest_size=8).digest(), "little")
    if isinstance(seed, np.random.Generator):
        return int(seed.integers(0, 2 ** 64, dtype=np.uint64))
    if isinstance(seed, np.random.RandomState):
        hi, lo = (int(v) for v in seed.randint(0, 2 ** 32, size=2, dtype=np.uint64))
        return (hi << 32) | lo
    if isinstance(seed, np.random.SeedSequence):
        return int(seed.generate_state(1, dtype=np.uint64)[0])
    raise ValueError("%r cannot be used to seed poissondisk.qmc.PoissonDisk" % (seed,))


def _bounds(value: Optional[Sequence[float]], default: float, name: str) -> "NDArray[np.float64]":
    if value is None:
        return np.full(2, default, dtype=np.float64)
    arr = np.array(value, dtype=np.float64)
    if arr.shape == ():
        arr = np.full(2, float(arr))
    if arr.shape != (2,):
        raise ValueError("%s must have 2 values (d = 2), got shape %r" % (name, arr.shape))
    return arr


class PoissonDisk:
    """Poisson disk sampling, exact and maximal, in the style of
    scipy.stats.qmc.PoissonDisk (2-D only).

    Args:
        d: the dimension; must be 2.
        radius: the minimum distance between points, in the units of the bounds.
        hypersphere: "volume" or "surface", checked as scipy does; it picks
            where Bridson's candidates are drawn, and this exact sampler has
            no candidates, so it does not change the law of the pattern.
        ncandidates: an int, as in scipy; no effect, for the same reason.
        optimization: None, or "random-cd" or "lloyd" (any case), which need
            scipy: each batch random() returns then goes through scipy's
            optimizer, as in scipy's own engine, and the points are no longer
            guaranteed to be `radius` apart.
        l_bounds, u_bounds: the box [l_bounds, u_bounds] to fill; default the
            unit square. Scalars apply to both coordinates.
        seed: None (fresh entropy), an int, or a numpy Generator, RandomState
            or SeedSequence, as scipy accepts; one 64-bit seed is taken from it
            when the engine is made and kept for reset(). Read it from `.seed`.
        rng: the newer scipy name for `seed` (give one of the two).
        threads: not in scipy. None (default) runs the single-thread
            process; an int selects the parallel process on that many
            threads (0: one per core, at most 1024), whose points do not
            depend on the count but differ from the default's. Settable;
            copies and pickles keep it.
    """

    _threads: Optional[int] = None  # engines pickled before the keyword existed

    def __init__(self, d: int = 2, *, radius: float = 0.05, hypersphere: str = "volume",
                 ncandidates: int = 30, optimization: Optional[str] = None,
                 l_bounds: Optional[Sequence[float]] = None,
                 u_bounds: Optional[Sequence[float]] = None,
                 seed: SeedLike = None, rng: SeedLike = None,
                 threads: Optional[int] = None) -> None:
        # scipy's checks first, in scipy's order and words (d, optimization,
        # hypersphere), so that a bad argument is reported as scipy reports it
        # whatever d is; then this engine's own limit, d = 2.
        if not np.issubdtype(type(d), np.integer) or d < 0:
            raise ValueError("d must be a non-negative integer value")
        name = _qmc_optimize.check_name(optimization)
        if hypersphere not in ("volume", "surface"):
            raise ValueError("%r is not a valid hypersphere sampling method. It must be one "
                             "of {'volume', 'surface'}" % (hypersphere,))
        if d != 2:
            raise ValueError("poissondisk.qmc.PoissonDisk samples the plane only: d must be "
                             "2, got %r (use scipy.stats.qmc.PoissonDisk for other "
                             "dimensions)" % (d,))
        if name is not None:
            _qmc_optimize.batch_engine_class(name)  # ImportError now if scipy is missing
        if seed is not None and rng is not None:
            raise TypeError("give seed or rng, not both")
        radius = float(radius)
        if not (math.isfinite(radius) and radius > 0):
            raise ValueError("radius must be finite and > 0, got %r" % radius)
        self.d = 2
        self.radius = radius
        self.hypersphere = hypersphere
        self.ncandidates = operator.index(ncandidates)
        self.optimization = name
        self.l_bounds = _bounds(l_bounds, 0.0, "l_bounds")
        self.u_bounds = _bounds(u_bounds, 1.0, "u_bounds")
        if not np.all(self.l_bounds < self.u_bounds):
            raise ValueError("Bounds are not consistent 'l_bounds' < 'u_bounds'")
        self.seed = seed_to_int(rng if seed is None else seed)
        self._sampler: Optional[Sampler] = None
        self._threads = _check_threads(threads)
        self.num_generated = 0
        self._full = False
        self._optimizer_rng = self._new_optimizer_rng()

    def _new_optimizer_rng(self) -> Optional["np.random.Generator"]:
        # The optimizer's random stream (random-cd draws from it) comes from
        # the same seed, so reset() and the seed repeat the optimized points.
        return None if self.optimization is None else np.random.default_rng(self.seed)

    def _engine(self) -> Sampler:
        if self._sampler is None:
            box = (tuple(self.l_bounds.tolist()), tuple(self.u_bounds.tolist()))
            self._sampler = Sampler(self.radius, bounds=box, seed=self.seed,
                                    threads=self._threads)
        return self._sampler

    @property
    def threads(self) -> Optional[int]:
        """None: the single-thread process; an int: the parallel process on
        that many threads (0: one per core), as given."""
        return self._threads

    @threads.setter
    def threads(self, n: Optional[int]) -> None:
        # The engine's sampler must stay the one its copies rebuild from the
        # seed and `threads`: a change it cannot take raises and changes nothing.
        n = _check_threads(n)
        if self._sampler is not None:
            if n is None and self._threads is not None:
                raise ValueError("threads=None cannot be set while the engine's pattern "
                                 "comes from the parallel process; call reset() first")
            if n is not None:
                self._sampler.threads = n  # StateError after single-thread points
        self._threads = n

    def random(self, n: Union[int, float] = 1, *, workers: int = 1) -> "NDArray[np.float64]":
        """The next n points, as a float64 array of shape (k, 2), k <= n.

        Each point is at least `radius` from the ones returned before (since
        the last reset()). Fewer than n come back when the space fills up, and
        none (shape (0, 2)) once it is full. n may be math.inf: all the rest.
        With `optimization`, the batch is then moved by scipy's optimizer, and
        that spacing is no longer guaranteed.
        """
        limit: Optional[int]
        if isinstance(n, float):
            if n == math.inf:
                limit = None
            elif n.is_integer():
                limit = int(n)
            else:
                raise TypeError("n must be an int or math.inf, got %r" % n)
        else:
            limit = operator.index(n)
        if limit is not None:
            limit = _size_arg(limit, "n", 0)  # not wrapped around by ctypes; math.inf: all
            if limit == 0:
                return np.empty((0, 2), dtype=np.float64)
        s = self._engine()
        start = len(s)
        if not self._full and s.run(limit):
            self._full = True
        out = cast("NDArray[np.float64]", s.get_points(start))
        if self.optimization is not None:
            assert self._optimizer_rng is not None
            out = _qmc_optimize.optimize(out, self.optimization, self._optimizer_rng,
                                         self.l_bounds, self.u_bounds)
        self.num_generated += len(out)
        return out

    def integers(self, l_bounds: Any, *, u_bounds: Any = None, n: Union[int, float] = 1,
                 endpoint: bool = False, workers: int = 1) -> "NDArray[np.int64]":
        """The next n points as integers, shape (k, 2), as scipy's engines give them.

        As in scipy: with u_bounds None the range is [0, l_bounds); endpoint=True
        includes the upper bound; the bounds must be integers (ValueError). The
        points of random(n), taken relative to the engine's box (the unit square
        by default), are scaled to the range and rounded down; a point on the
        box's upper edge gives the largest value in range (scipy's would fall
        one past it).
        """
        if u_bounds is None:
            u_bounds, l_bounds = l_bounds, 0
        lo, hi = np.atleast_1d(l_bounds), np.atleast_1d(u_bounds)
        if endpoint:
            hi = hi + 1
        if not (np.issubdtype(lo.dtype, np.integer) and np.issubdtype(hi.dtype, np.integer)):
            raise ValueError("'u_bounds' and 'l_bounds' must be integers or array-like of "
                             "integers")
        unit = (self.random(n) - self.l_bounds) / (self.u_bounds - self.l_bounds)
        values = np.floor(unit * (hi - lo) + lo).astype(np.int64)
        return cast("NDArray[np.int64]", np.minimum(values, np.maximum(hi - 1, lo)))

    def fill_space(self) -> "NDArray[np.float64]":
        """Add points until the space is full; returns those added, shape (n, 2).

        After a fresh start or reset(), that is the whole maximal pattern:
        every point of the box is within `radius` of a sample.
        """
        return self.random(math.inf)

    def reset(self) -> "PoissonDisk":
        """Back to the start: the same seed gives the same points again."""
        if self._sampler is not None:
            self._sampler.close()
        self._sampler = None
        self._full = False
        self.num_generated = 0
        self._optimizer_rng = self._new_optimizer_rng()
        return self

    def fast_forward(self, n: int) -> "PoissonDisk":
        """Skip the next n points (generating them)."""
        self.random(n)
        return self

    # copy.copy, copy.deepcopy and pickle: the state is the arguments, the seed
    # and how many points were made since the start or reset(); the C sampler is
    # not shared but made again, as the same seed gives the same points however
    # a run is split (one run of that many points, then the same continuation).
    def __getstate__(self) -> Dict[str, Any]:
        state = {k: v for k, v in self.__dict__.items() if k != "_sampler"}
        state["_made"] = len(self._sampler) if self._sampler is not None else 0
        # copy.copy shares what the state holds: the generator must not be shared
        state["_optimizer_rng"] = copy.deepcopy(self._optimizer_rng)
        state["_library"] = _capi.version()
        return state

    def __setstate__(self, state: Dict[str, Any]) -> None:
        state = dict(state)
        made, library = state.pop("_made"), state.pop("_library")
        if made and library != _capi.version():
            raise ValueError("this PoissonDisk engine was saved with libpoissondisk %s and "
                             "the library here is %s: its points would differ"
                             % (library, _capi.version()))
        if "threads" in state:  # saved when it was a plain attribute
            state["_threads"] = state.pop("threads")
        self.__dict__.update(state)
        self._sampler = None
        if made:
            self._engine().run(made)

    def __repr__(self) -> str:
        return "<poissondisk.qmc.PoissonDisk radius=%g seed=%d generated=%d>" % (
            self.radius, self.seed, self.num_generated)


__all__ = ["PoissonDisk", "seed_to_int"]
