"""poissondisk.qmc.PoissonDisk(optimization=...): scipy's optimizers applied to
each batch, as scipy's own engine does; without scipy, a clear ImportError."""

import copy
import pickle
import unittest

from geometry import inside, min_dist_ok
from support import TestCase, child, numpy as np

try:
    from poissondisk import qmc
except ImportError:
    qmc = None
try:
    from scipy.stats import qmc as scipy_qmc
except ImportError:
    scipy_qmc = None

needs_numpy = unittest.skipIf(qmc is None, "numpy is not importable here; poissondisk.qmc "
                                           "needs it (the list fallback is tested instead)")
needs_scipy = unittest.skipIf(scipy_qmc is None, "scipy is not installed: the optimizers "
                                                 "are scipy's (Debian: python3-scipy)")


def same(a, b):
    return a.shape == b.shape and bool((a == b).all())


@needs_numpy
@needs_scipy
class OptimizationTest(TestCase):
    R = 0.05

    def batch(self, n, optimization=None, seed=3, **kw):
        e = qmc.PoissonDisk(2, radius=self.R, seed=seed, optimization=optimization, **kw)
        return e.random(n)

    def test_random_cd_permutes_coordinates(self):
        raw = self.batch(64)
        opt = self.batch(64, "Random-CD")
        self.assertPoints(opt, 64)
        self.assertFalse(same(opt, raw), "the optimizer moved points")
        # random-cd swaps coordinates between points, column by column
        self.assertTrue(same(np.sort(opt, axis=0), np.sort(raw, axis=0)))
        self.assertLess(scipy_qmc.discrepancy(opt), scipy_qmc.discrepancy(raw))
        self.assertFalse(min_dist_ok(opt, self.R), "the spacing is no longer guaranteed")

    def test_lloyd_moves_points_in_the_box(self):
        lo, hi = [-1.0, 2.0], [3.0, 3.5]
        r = 0.2
        raw = qmc.PoissonDisk(2, radius=r, seed=4, l_bounds=lo, u_bounds=hi).random(40)
        opt = qmc.PoissonDisk(2, radius=r, seed=4, l_bounds=lo, u_bounds=hi,
                              optimization="lloyd").random(40)
        self.assertPoints(opt, 40)
        self.assertFalse(same(opt, raw))
        self.assertTrue(inside(opt, -1, 2, 3, 3.5), "mapped to the unit square and back")
        for n in (1, 2):  # qhull needs 3 points: smaller batches come back unmoved
            self.assertTrue(same(self.batch(n, "lloyd"), self.batch(n)))
        self.assertPoints(self.batch(0, "lloyd"), 0)

    def test_each_batch_and_repeatable(self):
        e = qmc.PoissonDisk(2, radius=self.R, seed=5, optimization="random-cd")
        self.assertEqual(e.optimization, "random-cd")
        first = e.random(30)
        snap, twin = copy.copy(e), pickle.loads(pickle.dumps(e))
        second = e.random(30)
        self.assertTrue(same(snap.random(30), second), "copy.copy goes on the same way")
        self.assertTrue(same(twin.random(30), second), "pickle goes on the same way")
        e.reset()
        self.assertTrue(same(e.random(30), first), "reset() repeats the optimized points")
        whole = qmc.PoissonDisk(2, radius=self.R, seed=5, optimization="random-cd").random(60)
        self.assertFalse(same(whole, np.vstack([first, second])),
                         "the optimizer works on each batch on its own")
        rest = e.fill_space()
        self.assertEqual(e.random(5).shape, (0, 2), "full: an empty batch, not optimized")
        self.assertEqual(e.num_generated, 30 + len(rest))


@needs_numpy
class WithoutScipyTest(TestCase):
    def test_import_error_names_scipy(self):
        code = (
            "import sys\n"
            "sys.modules['scipy'] = None\n"
            "from poissondisk import qmc\n"
            "print(len(qmc.PoissonDisk(2, radius=0.2, seed=1).fill_space()) > 0)\n"
            "try:\n"
            "    qmc.PoissonDisk(2, optimization='bogus')\n"
            "except ValueError as e:\n"
            "    print(e)\n"
            "try:\n"
            "    qmc.PoissonDisk(2, optimization='lloyd')\n"
            "except ImportError as e:\n"
            "    print(e)\n")
        status, out, err = child(code)
        self.assertEqual(status, 0, err)
        lines = out.splitlines()
        self.assertEqual(lines[0], "True", "optimization=None needs no scipy")
        self.assertIn("'bogus' is not a valid optimization method", lines[1])
        self.assertIn("optimization='lloyd' needs scipy", lines[2])
        self.assertIn("not installed", lines[2])


if __name__ == "__main__":
    unittest.main()
