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
  - d must be 2 (ValueError otherwise);
  - `hypersphere` and `ncandidates` are accepted (and checked as scipy does)
    but have no effect: there are no candidates; `optimization` must be None,
    as both of scipy's post-processing schemes would move points closer than
    `radius`; `workers` is accepted and ignored, as scipy does for this engine;
  - once the space is full, random() returns an empty (0, 2) array;
  - the same seed gives other points than scipy's (another algorithm), and the
    points are the same however they are split into random() calls;
  - `radius` is in the units of the bounds, as in scipy >= 1.15, which
    samples the box [l_bounds, u_bounds] directly;
  - integers() is not provided;
  - copy.copy, copy.deepcopy and pickle give an independent engine that goes
    on with exactly the points the original would give next (it regenerates
    the points so far from the seed); unpickling needs the same library
    version.
Needs numpy (the results are arrays).
"""

from __future__ import annotations

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

from . import _capi
from ._args import _size_arg, random_seed
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
        hypersphere: "volume" or "surface"; checked, no effect here.
        ncandidates: checked to be an int, no effect here.
        optimization: must be None.
        l_bounds, u_bounds: the box [l_bounds, u_bounds] to fill; default the
            unit square. Scalars apply to both coordinates.
        seed: None (fresh entropy), an int, or a numpy Generator, RandomState
            or SeedSequence, as scipy accepts; one 64-bit seed is taken from it
            when the engine is made and kept for reset(). Read it from `.seed`.
        rng: the newer scipy name for `seed` (give one of the two).
    """

    def __init__(self, d: int = 2, *, radius: float = 0.05, hypersphere: str = "volume",
                 ncandidates: int = 30, optimization: Optional[str] = None,
                 l_bounds: Optional[Sequence[float]] = None,
                 u_bounds: Optional[Sequence[float]] = None,
                 seed: SeedLike = None, rng: SeedLike = None) -> None:
        if operator.index(d) != 2:
            raise ValueError("poissondisk.qmc.PoissonDisk samples the plane only: d must be "
                             "2, got %r (use scipy.stats.qmc.PoissonDisk for other "
                             "dimensions)" % (d,))
        if hypersphere not in ("volume", "surface"):
            raise ValueError("%r is not a valid hypersphere sampling method. It must be one "
                             "of {'volume', 'surface'}" % (hypersphere,))
        if optimization is not None:
            raise ValueError("optimization=%r is not supported: it would move points closer "
                             "than radius; use None" % (optimization,))
        if seed is not None and rng is not None:
            raise TypeError("give seed or rng, not both")
        radius = float(radius)
        if not (math.isfinite(radius) and radius > 0):
            raise ValueError("radius must be finite and > 0, got %r" % radius)
        self.d = 2
        self.radius = radius
        self.hypersphere = hypersphere
        self.ncandidates = operator.index(ncandidates)
        self.optimization = None
        self.l_bounds = _bounds(l_bounds, 0.0, "l_bounds")
        self.u_bounds = _bounds(u_bounds, 1.0, "u_bounds")
        if not np.all(self.l_bounds < self.u_bounds):
            raise ValueError("Bounds are not consistent 'l_bounds' < 'u_bounds'")
        self.seed = seed_to_int(rng if seed is None else seed)
        self.num_generated = 0
        self._sampler: Optional[Sampler] = None
        self._full = False

    def _engine(self) -> Sampler:
        if self._sampler is None:
            box = (tuple(self.l_bounds.tolist()), tuple(self.u_bounds.tolist()))
            self._sampler = Sampler(self.radius, bounds=box, seed=self.seed)
        return self._sampler

    def random(self, n: Union[int, float] = 1, *, workers: int = 1) -> "NDArray[np.float64]":
        """The next n points, as a float64 array of shape (k, 2), k <= n.

        Each point is at least `radius` from the ones returned before (since
        the last reset()). Fewer than n come back when the space fills up, and
        none (shape (0, 2)) once it is full. n may be math.inf: all the rest.
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
        self.num_generated += len(out)
        return out

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
        state["_library"] = _capi.version()
        return state

    def __setstate__(self, state: Dict[str, Any]) -> None:
        state = dict(state)
        made, library = state.pop("_made"), state.pop("_library")
        if made and library != _capi.version():
            raise ValueError("this PoissonDisk engine was saved with libpoissondisk %s and "
                             "the library here is %s: its points would differ"
                             % (library, _capi.version()))
        self.__dict__.update(state)
        self._sampler = None
        if made:
            self._engine().run(made)

    def __repr__(self) -> str:
        return "<poissondisk.qmc.PoissonDisk radius=%g seed=%d generated=%d>" % (
            self.radius, self.seed, self.num_generated)


__all__ = ["PoissonDisk", "seed_to_int"]
