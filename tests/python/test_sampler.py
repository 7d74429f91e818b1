"""poissondisk.Sampler: run, step, refine, points, len, free_area, verify, the
context manager and the exceptions. Geometric facts are recomputed from the
coordinates (geometry.py), not taken from the library's verdict."""

import math
import unittest

from geometry import covered, inside, min_dist_ok
from support import NO_NUMPY_PASS, TestCase, header_version, numpy, poissondisk

Sampler = poissondisk.Sampler


class VersionTest(TestCase):
    def test_library_version_is_the_header_version(self):
        self.assertEqual(poissondisk.version(), header_version())
        major, minor, patch = (int(v) for v in header_version().split("."))
        self.assertEqual(poissondisk.version_number(), major * 10000 + minor * 100 + patch)

    def test_package_version_follows_the_header(self):
        self.assertEqual(poissondisk.__version__, header_version(),
                         "bump version in bindings/python/pyproject.toml and __init__.py")

    def test_numpy_as_this_pass_expects(self):
        self.assertEqual(numpy is None, NO_NUMPY_PASS)


class MaximalPatternTest(TestCase):
    R = 0.05

    def test_maximal_pattern(self):
        with Sampler(self.R, seed=1) as s:
            self.assertEqual(len(s), 0)
            self.assertPoints(s.points, 0)
            self.assertAlmostEqual(s.free_area, 1.0, delta=1e-12)
            self.assertEqual(s.radius, self.R)
            self.assertIs(s.run(), True)
            pts = s.points
            n = len(pts)
            self.assertEqual(n, len(s))
            self.assertPoints(pts, n)
            # Covering and packing bounds for a maximal set (see tests/check-cli.sh).
            self.assertTrue(128 <= n <= 509, "N=%d within [128, 509]" % n)
            self.assertTrue(inside(pts, 0, 0, 1, 1))
            self.assertTrue(min_dist_ok(pts, self.R), "every pair at least R apart")
            self.assertTrue(covered(pts, self.R, 0, 0, 1, 1, 0.01), "no probe uncovered")
            self.assertEqual(s.free_area, 0.0)
            self.assertIs(s.verify(), True)
            self.assertIs(s.step(), False, "step() adds nothing to a maximal pattern")
            self.assertEqual(len(s), n)
            self.assertSamePoints(s.get_points(5, 3), pts[5:8])
            self.assertSamePoints(s.get_points(n - 2), pts[n - 2:])
            self.assertPoints(s.get_points(n + 10), 0)
            self.assertPoints(s.get_points(0, 0), 0)
            self.assertIsNot(s.points, s.points, "each access is a new snapshot")

    def test_same_seed_same_points(self):
        a = poissondisk.sample(self.R, seed=1)
        self.assertSamePoints(a, poissondisk.sample(self.R, seed=1))
        self.assertNotEqual(len(a), 0)
        b = poissondisk.sample(self.R, seed=2)
        self.assertFalse(len(a) == len(b) and (a == b if isinstance(a, list) else (a == b).all()))
        with Sampler(self.R, seed=2 ** 64 - 1) as s:
            self.assertIs(s.run(), True, "the largest seed works")

    def test_seed_none_is_drawn_and_exposed(self):
        with Sampler(self.R) as s, Sampler(self.R) as t:
            self.assertNotEqual(s.seed, t.seed)
            self.assertTrue(0 <= s.seed < 2 ** 64)
            s.run()
            with Sampler(self.R, seed=s.seed) as u:
                u.run()
                self.assertSamePoints(u.points, s.points, "the exposed seed repeats it")

    def test_run_cap_and_step(self):
        with Sampler(self.R, seed=1) as s:
            self.assertIs(s.run(10), False)
            self.assertEqual(len(s), 10)
            self.assertIs(s.step(), True)
            self.assertEqual(len(s), 11)
            self.assertGreater(s.free_area, 0.0)
            self.assertIs(s.verify(), False, "valid, room left")
            while s.run(37) is False:
                pass
            self.assertSamePoints(s.points, poissondisk.sample(self.R, seed=1),
                                  "run(10), step(), run(37)...: the points of one run()")

    def test_refine(self):
        first = poissondisk.sample(self.R, seed=1)
        with Sampler(self.R, seed=1) as s:
            s.run()
            s.refine(0.03)
            self.assertEqual(s.radius, 0.03)
            self.assertIs(s.run(), True)
            pts = s.points
            self.assertGreater(len(pts), len(first))
            self.assertSamePoints(pts[:len(first)], first, "refine keeps the points, in order")
            self.assertTrue(min_dist_ok(pts, 0.03))
            self.assertTrue(covered(pts, 0.03, 0, 0, 1, 1, 0.01))
            self.assertIs(s.verify(), True)
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                          s.refine, 0.04)
            self.assertTrue(exc.message.startswith("pds_refine:"), exc.message)
            self.assertEqual(s.radius, 0.03, "a failed refine changes nothing")

    def test_bounds(self):
        (x0, y0), (x1, y1) = box = ((-2.0, 1.0), (3.0, 2.5))
        with Sampler(0.1, seed=4, bounds=box) as s:
            self.assertEqual(s.bounds, box)
            self.assertIs(s.periodic, False)
            self.assertAlmostEqual(s.free_area, 7.5, delta=1e-9)
            s.run()
            pts = s.points
            self.assertTrue(inside(pts, x0, y0, x1, y1))
            self.assertTrue(min_dist_ok(pts, 0.1))
            self.assertTrue(covered(pts, 0.1, x0, y0, x1, y1, 0.05))
            self.assertIs(s.verify(), True)
        pts = poissondisk.sample(0.1, bounds=[[0, 0], [2, 1]])
        self.assertTrue(inside(pts, 0, 0, 2, 1) and max(p[0] for p in pts) > 1.5)

    def test_sliver_free_area(self):
        # A rectangle 1e-200 wide: every disk spans it, so the free area is the
        # width times the length left outside the points' intervals.
        w, r = 1e-200, 0.01
        with Sampler(r, seed=5, bounds=((0.0, 0.0), (w, 1.0))) as s:
            for n in range(1, 21):
                s.run(1)
                ys = sorted(p[1] for p in s.points)
                covered_length, hi = 0.0, 0.0
                for y in ys:
                    a, b = max(y - r, hi), min(y + r, 1.0)
                    covered_length += max(b - a, 0.0)
                    hi = max(hi, b)
                self.assertAlmostEqual(s.free_area / w, 1.0 - covered_length, delta=1e-9,
                                       msg=f"{n} points")
            s.run()
            self.assertEqual(s.free_area, 0.0)
            self.assertIs(s.verify(), True)


class ErrorTest(TestCase):
    def test_hierarchy(self):
        E = poissondisk
        for cls, base in ((E.InvalidArgumentError, ValueError), (E.RangeError, ValueError),
                          (E.OutOfMemoryError, MemoryError), (E.StateError, RuntimeError),
                          (E.InternalError, RuntimeError), (E.CanceledError, Exception)):
            self.assertTrue(issubclass(cls, E.PoissonDiskError) and issubclass(cls, base))

    def test_bad_radius(self):
        for r in (-1, 0, math.nan, math.inf):
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError,
                                          poissondisk.EINVAL, Sampler, r)
            self.assertIn("pds_create", str(exc))

    def test_bad_bounds(self):
        for box in (((1, 0), (0, 1)), ((0, 0), (math.nan, 1)), ((0, 0), (0, 1))):
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError,
                                          poissondisk.EINVAL, Sampler, 0.1, bounds=box)
            self.assertTrue(exc.message.startswith("pds_set_domain:"), exc.message)
        with self.assertRaises(TypeError):
            Sampler(0.1, bounds=(0, 0, 1, 1))

    def test_radius_judged_at_the_first_point(self):
        with Sampler(1e-9) as s:
            exc = self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run, 10)
            self.assertIn("double precision", exc.message)
            self.assertEqual(len(s), 0, "a refused run adds nothing")
        with Sampler(1e-6) as s:
            self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run)
            self.assertIs(s.run(1000), False)
            self.assertEqual(len(s), 1000)
            self.assertIs(s.verify(), False)
        with Sampler(1e-5, bounds=((0, 0), (1e-3, 1e-3))) as s:
            self.assertTrue(s.run() and s.verify() and 5000 < len(s) < 9000)

    def test_python_side_misuse(self):
        with self.assertRaises(ValueError):
            Sampler(0.1, seed=-1)
        with self.assertRaises(ValueError):
            Sampler(0.1, seed=2 ** 64)
        with self.assertRaises(TypeError):
            Sampler(None)
        with Sampler(0.1) as s:
            for bad in (-1, 0):
                with self.assertRaises(ValueError):
                    s.run(bad)
            with self.assertRaises(ValueError):
                s.get_points(-1)
            with self.assertRaises(TypeError):
                s.run(2.5)

    def test_strerror(self):
        self.assertNotEqual(poissondisk.strerror(poissondisk.EINVAL),
                            poissondisk.strerror(poissondisk.ENOMEM))
        self.assertIsInstance(poissondisk.strerror(-12345), str)


class LifetimeTest(TestCase):
    def test_close(self):
        s = Sampler(0.2)
        self.assertFalse(s.closed)
        s.close()
        s.close()
        self.assertTrue(s.closed)
        self.assertIn("closed", repr(s))
        for use in (s.run, s.step, lambda: s.points, lambda: len(s), s.verify):
            with self.assertRaises(ValueError):
                use()

    def test_context_manager(self):
        with Sampler(0.2) as t:
            t.run()
            self.assertIn("points=", repr(t))
        self.assertTrue(t.closed, "leaving the with block closes the sampler")
        try:
            with Sampler(0.2) as u:
                raise KeyError("inside")
        except KeyError:
            pass
        self.assertTrue(u.closed, "an exception in the block closes it too")

    def test_del(self):
        u = Sampler(0.2)
        u.run()
        del u  # __del__ frees it; nothing to observe but that it does not crash


if __name__ == "__main__":
    unittest.main()
