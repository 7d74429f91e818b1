"""poissondisk.qmc.PoissonDisk, the scipy-shaped API: on its own, then the same
calls against scipy.stats.qmc.PoissonDisk when scipy is installed."""

import inspect
import math
import unittest

from geometry import covered, inside, min_dist_ok
from support import TestCase, numpy as np

try:
    from poissondisk import qmc
except ImportError:
    qmc = None
try:
    from scipy.stats import qmc as scipy_qmc
    import scipy
except ImportError:
    scipy_qmc = None

needs_numpy = unittest.skipIf(qmc is None, "numpy is not importable here; poissondisk.qmc "
                                           "needs it (the list fallback is tested instead)")
needs_scipy = unittest.skipIf(scipy_qmc is None,
                              "scipy is not installed: the comparison with "
                              "scipy.stats.qmc.PoissonDisk is skipped (Debian: apt-get "
                              "install python3-scipy)")


def same(a, b):
    return a.shape == b.shape and bool((a == b).all())


@needs_numpy
class PoissonDiskTest(TestCase):
    R = 0.05

    def test_shapes_and_full_space(self):
        e = qmc.PoissonDisk(2, radius=self.R, seed=1)
        a = e.random(5)
        self.assertPoints(a, 5)
        rest = e.fill_space()
        n = 5 + len(rest)
        self.assertPoints(rest, n - 5)
        self.assertEqual(e.num_generated, n)
        self.assertPoints(e.random(3), 0)  # full: nothing more
        self.assertPoints(e.random(0), 0)
        pts = np.vstack([a, rest])
        self.assertTrue(inside(pts, 0, 0, 1, 1))
        self.assertTrue(min_dist_ok(pts, self.R), "every pair at least radius apart")
        self.assertTrue(covered(pts, self.R, 0, 0, 1, 1, 0.01), "maximal: no probe uncovered")
        big = qmc.PoissonDisk(radius=self.R, seed=1).random(10 ** 6)
        self.assertTrue(same(big, pts), "random(n) returns fewer once the space is full")

    def test_splits_reset_fast_forward(self):
        whole = qmc.PoissonDisk(radius=self.R, seed=2).fill_space()
        e = qmc.PoissonDisk(radius=self.R, seed=2)
        parts = [e.random(10), e.random(7), e.random(np.inf)]
        self.assertTrue(same(np.vstack(parts), whole), "split into random() calls")
        self.assertIs(e.reset(), e)
        self.assertEqual(e.num_generated, 0)
        self.assertTrue(same(e.random(math.inf), whole), "reset() starts over")
        e.reset().fast_forward(10)
        self.assertTrue(same(e.fill_space(), whole[10:]))
        self.assertTrue(same(e.random(2.0), np.empty((0, 2))))

    def test_seeds(self):
        def fill(**kw):
            return qmc.PoissonDisk(radius=0.1, **kw).fill_space()
        self.assertTrue(same(fill(seed=7), fill(seed=7)))
        self.assertFalse(same(fill(seed=7), fill(seed=8)))
        self.assertTrue(same(fill(seed=np.int64(7)), fill(seed=7)))
        self.assertTrue(same(fill(rng=7), fill(seed=7)), "rng is seed's newer name")
        g1, g2 = np.random.default_rng(3), np.random.default_rng(3)
        self.assertTrue(same(fill(seed=g1), fill(seed=g2)), "Generators in the same state")
        self.assertNotEqual(g1.integers(1 << 62), np.random.default_rng(3).integers(1 << 62),
                            "drawing the seed advanced the Generator")
        self.assertTrue(same(fill(seed=np.random.RandomState(5)),
                             fill(seed=np.random.RandomState(5))))
        self.assertTrue(same(fill(seed=np.random.SeedSequence(9)),
                             fill(seed=np.random.SeedSequence(9))))
        self.assertEqual(len(fill(seed=2 ** 100)[0]), 2, "ints beyond 64 bits are folded")
        a, b = qmc.PoissonDisk(radius=0.1), qmc.PoissonDisk(radius=0.1)
        self.assertNotEqual(a.seed, b.seed, "seed=None: fresh entropy")
        self.assertTrue(same(a.fill_space(), fill(seed=a.seed)), ".seed repeats it")
        for bad in (-1, "abc", 1.5):
            with self.assertRaises(ValueError):
                qmc.PoissonDisk(seed=bad)
        with self.assertRaises(TypeError):
            qmc.PoissonDisk(seed=1, rng=1)

    def test_arguments(self):
        with self.assertRaisesRegex(ValueError, "d must be 2"):
            qmc.PoissonDisk(3)
        for d in (-1, 2.0, True):
            with self.assertRaisesRegex(ValueError, "d must be a non-negative integer"):
                qmc.PoissonDisk(d)
        self.assertEqual(qmc.PoissonDisk(np.int64(2), radius=0.5).d, 2)
        with self.assertRaises(ValueError):
            qmc.PoissonDisk(2, hypersphere="bogus")
        # scipy checks optimization, then hypersphere, before anything about d
        with self.assertRaisesRegex(ValueError, "'bogus' is not a valid optimization method"):
            qmc.PoissonDisk(3, optimization="bogus", hypersphere="bogus")
        with self.assertRaisesRegex(ValueError, "'bogus' is not a valid hypersphere"):
            qmc.PoissonDisk(1, hypersphere="bogus")
        for r in (0, -0.1, math.nan):
            with self.assertRaises(ValueError):
                qmc.PoissonDisk(2, radius=r)
        ref = qmc.PoissonDisk(2, radius=0.1, seed=4).fill_space()
        other = qmc.PoissonDisk(2, radius=0.1, seed=4, hypersphere="surface", ncandidates=5)
        self.assertTrue(same(other.fill_space(), ref), "hypersphere, ncandidates: no effect")

    def test_bounds(self):
        lo, hi, r = [-1.0, 2.0], [3.0, 3.5], 0.2
        pts = qmc.PoissonDisk(2, radius=r, l_bounds=lo, u_bounds=hi, seed=5).fill_space()
        self.assertTrue(inside(pts, -1, 2, 3, 3.5))
        self.assertTrue(min_dist_ok(pts, r), "radius in the units of the bounds")
        self.assertTrue(covered(pts, r, -1, 2, 3, 3.5, 0.05))
        with self.assertRaises(ValueError):
            qmc.PoissonDisk(2, l_bounds=[0, 1], u_bounds=[1, 1])
        with self.assertRaises(ValueError):
            qmc.PoissonDisk(2, l_bounds=[0, 0, 0])

    def test_integers(self):
        pts = qmc.PoissonDisk(2, radius=0.1, seed=6).random(20)
        e = qmc.PoissonDisk(2, radius=0.1, seed=6)
        ints = e.integers(10, n=20)
        self.assertEqual((ints.shape, ints.dtype), ((20, 2), np.int64))
        self.assertTrue(same(ints, np.floor(pts * 10).astype(np.int64)), "[0, 10), floored")
        self.assertEqual(e.num_generated, 20)
        lo, hi = np.array([-1.0, 2.0]), np.array([3.0, 3.5])
        box = qmc.PoissonDisk(2, radius=0.2, seed=6, l_bounds=lo, u_bounds=hi)
        pts = box.random(15)
        box.reset()
        ints = box.integers([0, 5], u_bounds=[4, 8], n=15, endpoint=True)
        want = np.floor((pts - lo) / (hi - lo) * [5, 4] + [0, 5]).astype(np.int64)
        self.assertTrue(same(ints, want), "relative to the box, [0, 4] x [5, 8]")
        self.assertTrue(bool((ints >= [0, 5]).all() and (ints <= [4, 8]).all()))
        with self.assertRaisesRegex(ValueError, "must be integers"):
            e.integers(1.5)


@needs_numpy
@needs_scipy
class AgainstScipyTest(TestCase):
    """The same calls on both engines: shapes, dtypes, bounds; ours exact and maximal."""
    R = 0.05

    def engines(self, seed, **kw):
        return (qmc.PoissonDisk(2, radius=self.R, seed=seed, **kw),
                scipy_qmc.PoissonDisk(2, radius=self.R, seed=seed, **kw))

    def test_same_calls(self):
        counts = {"ours": 0, "scipy": 0}
        for seed in (1, 2, 3):
            ours, theirs = self.engines(seed)
            for name, e in (("ours", ours), ("scipy", theirs)):
                head = e.random(5)
                self.assertEqual((head.shape, head.dtype), ((5, 2), np.float64), name)
                rest = e.fill_space()
                self.assertEqual((rest.ndim, rest.shape[1], rest.dtype), (2, 2, np.float64))
                pts = np.vstack([head, rest])
                self.assertTrue(inside(pts, 0, 0, 1, 1), "%s: inside [0, 1]^2" % name)
                counts[name] += len(pts)
                e.reset()
                self.assertTrue(same(e.random(5), head), "%s: reset() starts over" % name)
                if e is ours:
                    self.assertTrue(min_dist_ok(pts, self.R))
                    self.assertTrue(covered(pts, self.R, 0, 0, 1, 1, 0.01), "ours is maximal")
        self.assertGreater(counts["ours"], counts["scipy"],
                           "a maximal pattern holds more points than Bridson's fill %r" % counts)

    def test_same_argument_errors(self):
        for kw in ({"hypersphere": "bogus"},):
            for cls in (qmc.PoissonDisk, scipy_qmc.PoissonDisk):
                with self.assertRaises(ValueError):
                    cls(2, **kw)
        ours, theirs = self.engines(1)
        self.assertEqual(ours.random(0).shape, theirs.random(0).shape)
        for e in (ours, theirs):
            ints = e.integers(3, u_bounds=7, n=4)
            self.assertEqual((ints.shape, ints.dtype), ((4, 2), np.int64))
            self.assertTrue(bool((ints >= 3).all() and (ints < 7).all()))
            with self.assertRaises(ValueError):
                e.integers(0.5)

    def test_bounds_as_scipy(self):
        if "l_bounds" not in inspect.signature(scipy_qmc.PoissonDisk).parameters:
            self.skipTest("scipy %s has no l_bounds/u_bounds (scipy 1.15 added them): "
                          "the bounds are checked on ours alone" % scipy.__version__)
        lo, hi = [-1.0, 2.0], [3.0, 3.5]
        for e in self.engines(4, l_bounds=lo, u_bounds=hi):
            pts = e.fill_space()
            self.assertEqual(pts.shape[1], 2)
            self.assertTrue(inside(pts, -1, 2, 3, 3.5))


if __name__ == "__main__":
    unittest.main()
