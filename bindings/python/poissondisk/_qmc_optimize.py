"""scipy's QMC optimizers ("random-cd", "lloyd") for poissondisk.qmc.PoissonDisk.

scipy.stats.qmc.QMCEngine.random() passes each batch an engine's _random()
makes through the optimizer named by `optimization`, with scipy's own settings
and the engine's random generator; scipy's PoissonDisk inherits that. To apply
it the same way, on every scipy version, a batch of our points goes through a
throwaway QMCEngine whose _random() returns that batch. QMCEngine is public
and documented for subclassing, so no private scipy name is used.

scipy is imported only when an optimization is asked for: poissondisk.qmc
itself needs numpy alone.
"""

from __future__ import annotations

import inspect
from typing import TYPE_CHECKING, Any, Optional

import numpy as np

if TYPE_CHECKING:
    from numpy.typing import NDArray

# scipy's names; it lowercases what it is given ("random-CD" is accepted).
OPTIMIZATIONS = ("random-cd", "lloyd")

# Lloyd's relaxation builds a Voronoi diagram with qhull, which needs at least
# 3 points in the plane; scipy's own engine raises on a batch of 1 or 2.
LLOYD_MIN_POINTS = 3


def check_name(optimization: Any) -> Optional[str]:
    """The optimization's name in scipy's spelling, or None; ValueError as
    scipy words it for an unknown name. Needs no scipy."""
    if optimization is None:
        return None
    name = optimization.lower() if isinstance(optimization, str) else optimization
    if name not in OPTIMIZATIONS:
        raise ValueError("%r is not a valid optimization method. It must be one of %r"
                         % (optimization, set(OPTIMIZATIONS)))
    return str(name)


_BATCH_ENGINE: Any = None


def batch_engine_class(optimization: str) -> Any:
    """A scipy QMCEngine subclass that hands back a given batch (made once).

    ImportError naming scipy when scipy is not installed."""
    global _BATCH_ENGINE
    if _BATCH_ENGINE is not None:
        return _BATCH_ENGINE
    try:
        from scipy.stats import qmc as scipy_qmc
    except ImportError as exc:
        raise ImportError("optimization=%r needs scipy (scipy.stats.qmc applies it), "
                          "which is not installed: install scipy (Debian: python3-scipy) "
                          "or use optimization=None" % (optimization,)) from exc
    # scipy 1.15 renamed QMCEngine's `seed` to `rng`; either takes a Generator
    # and uses that very object, so its stream goes on from call to call.
    params = inspect.signature(scipy_qmc.QMCEngine.__init__).parameters
    rng_name = "rng" if "rng" in params else "seed"

    class BatchEngine(scipy_qmc.QMCEngine):  # type: ignore[misc, valid-type]
        def __init__(self, batch: "NDArray[np.float64]", optimization: str,
                     rng: "np.random.Generator") -> None:
            self._batch = batch
            super().__init__(d=2, optimization=optimization, **{rng_name: rng})

        def _random(self, n: int = 1, *, workers: int = 1) -> "NDArray[np.float64]":
            return self._batch

    _BATCH_ENGINE = BatchEngine
    return BatchEngine


def optimize(batch: "NDArray[np.float64]", optimization: str, rng: "np.random.Generator",
             lo: "NDArray[np.float64]", hi: "NDArray[np.float64]") -> "NDArray[np.float64]":
    """The batch (points in the box [lo, hi]) after scipy's optimizer, in the box.

    scipy's optimizers work in the unit square: another box is mapped to it and
    back (and clipped to the box against rounding). An empty batch, and a batch
    too small for Lloyd's relaxation, is returned as it is.
    """
    if len(batch) == 0 or (optimization == "lloyd" and len(batch) < LLOYD_MIN_POINTS):
        return batch
    unit = bool(np.all(lo == 0.0) and np.all(hi == 1.0))
    scaled = batch if unit else (batch - lo) / (hi - lo)
    engine = batch_engine_class(optimization)(scaled, optimization, rng)
    out = np.asarray(engine.random(len(scaled)), dtype=np.float64)
    if not unit:
        out = np.clip(out * (hi - lo) + lo, lo, hi)
    return np.ascontiguousarray(out)


__all__ = ["OPTIMIZATIONS", "check_name", "batch_engine_class", "optimize"]
