"""The options of the 1.2 library through Sampler: count, progress (reports,
cancel and resume), periodic (the torus)."""

import gc
import unittest

from geometry import as_pairs, covered, inside, min_dist_ok
from support import TestCase, poissondisk

Sampler = poissondisk.Sampler


def reference(r, seed, **kw):
    with Sampler(r, seed=seed, **kw) as s:
        s.run()
        return as_pairs(s.points)


class CountTest(TestCase):
    def test_exactly_n_points(self):
        with Sampler(None, seed=5, count=500) as s:
            self.assertIs(s.run(), True)
            pts = s.points
            r = s.radius
            self.assertPoints(pts, 500)
            self.assertTrue(inside(pts, 0, 0, 1, 1))
            self.assertTrue(min_dist_ok(pts, r), "every pair at least radius=%r apart" % r)
            self.assertTrue(covered(pts, r / 0.99, 0, 0, 1, 1, 0.005),
                            "no probe farther than radius / 0.99 from all points")
            self.assertIn(s.verify(), (True, False))
            exc = self.assertLibraryError(poissondisk.StateError, poissondisk.ESTATE,
                                          s.refine, r / 2)
            self.assertTrue(exc.message.startswith("pds_refine:"))
        ref = as_pairs(pts)
        self.assertEqual(reference(0.3, 5, count=500), ref, "the radius given is ignored")
        with Sampler(1.0, seed=5, count=500) as s:
            while s.run(37) is False:
                pass
            self.assertEqual(as_pairs(s.points), ref, "split into run(37): the same points")
        with Sampler(None, seed=5, count=500, bounds=((-2, 1), (3, 2.5))) as s:
            s.run()
            self.assertEqual(len(s), 500)
            self.assertTrue(inside(s.points, -2, 1, 3, 2.5))

    def test_bad_count(self):
        self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                Sampler, 0.1, count=0)
        with self.assertRaises(ValueError):
            Sampler(0.1, count=-3)


class ProgressTest(TestCase):
    R, SEED = 0.01, 3

    @classmethod
    def setUpClass(cls):
        cls.ref = reference(cls.R, cls.SEED)

    def test_reports(self):
        calls = []
        with Sampler(self.R, seed=self.SEED) as s:
            s.set_progress(lambda count, done: calls.append((count, done, len(s))))
            gc.collect()  # the binding, not the caller, keeps the callback alive
            self.assertIs(s.run(), True)
            self.assertEqual(as_pairs(s.points), self.ref, "a callback changes no point")
        done = [d for _, d, _ in calls]
        self.assertTrue(10 <= len(calls) <= 200, "about a hundred reports (%d)" % len(calls))
        self.assertTrue(all(0.0 <= d <= 1.0 for d in done) and done == sorted(done))
        self.assertTrue(all(c == seen for c, _, seen in calls), "count == len(s) inside")
        self.assertEqual(calls[-1][:2], (len(self.ref), 1.0))

    def test_cancel_then_resume(self):
        n = []
        with Sampler(self.R, seed=self.SEED, progress=lambda c, d: n.append(0) or len(n) > 5) as s:
            exc = self.assertLibraryError(poissondisk.CanceledError, poissondisk.ECANCELED, s.run)
            self.assertTrue(exc.message.startswith("pds_run:"))
            k = len(s)
            self.assertTrue(0 < k < len(self.ref), "a canceled run keeps its %d points" % k)
            self.assertEqual(as_pairs(s.points), self.ref[:k], "they are a prefix")
            s.set_progress(None)
            self.assertIs(s.run(), True)
            self.assertEqual(as_pairs(s.points), self.ref, "resumed: an uninterrupted run")

    def test_cancel_every_third_report(self):
        n = []
        with Sampler(self.R, seed=self.SEED) as s:
            s.set_progress(lambda c, d: n.append(0) or len(n) % 3 == 0)
            cancels = 0
            while True:
                try:
                    s.run()
                    break
                except poissondisk.CanceledError:
                    cancels += 1
                    self.assertLess(cancels, 1000)
            self.assertGreater(cancels, 3)
            self.assertEqual(as_pairs(s.points), self.ref)

    def test_exception_in_callback(self):
        for kind in (ZeroDivisionError, KeyboardInterrupt):
            n = []

            def boom(count, done, kind=kind):
                n.append(0)
                if len(n) == 4:
                    raise kind("from the callback")
            with Sampler(self.R, seed=self.SEED, progress=boom) as s:
                with self.assertRaises(kind):
                    s.run()
                self.assertTrue(0 < len(s) < len(self.ref))
                self.assertIs(s.run(), True)
                self.assertEqual(as_pairs(s.points), self.ref, kind.__name__)

    def test_changes_from_the_callback_are_refused(self):
        codes = []

        def meddle(count, done):
            s.points  # reading is allowed
            for change in (s.step, lambda: s.refine(0.005), lambda: s.set_progress(None)):
                try:
                    change()
                    codes.append(0)
                except poissondisk.StateError as exc:
                    codes.append(exc.code)
        with Sampler(self.R, seed=self.SEED, progress=meddle) as s:
            s.run()
            self.assertEqual(set(codes), {poissondisk.ESTATE})
            self.assertEqual(as_pairs(s.points), self.ref, "refused changes change nothing")

    def test_count_mode_done_is_exact(self):
        seen = []
        with Sampler(None, seed=5, count=500,
                     progress=lambda count, done: seen.append(done == count / 500)) as s:
            s.run()
        self.assertTrue(seen and all(seen))

    def test_not_callable(self):
        with Sampler(0.1) as s, self.assertRaises(TypeError):
            s.set_progress(42)


class PeriodicTest(TestCase):
    def test_torus(self):
        for r, box, seed in ((0.05, ((0, 0), (1, 1)), 2), (0.1, ((-2, 1), (3, 2.5)), 4)):
            (x0, y0), (x1, y1) = box
            with Sampler(r, seed=seed, bounds=box, periodic=True) as s:
                self.assertIs(s.periodic, True)
                self.assertIs(s.run(), True)
                pts = s.points
                self.assertTrue(inside(pts, x0, y0, x1, y1, half_open=True))
                self.assertTrue(min_dist_ok(pts, r, periods=(x1 - x0, y1 - y0)),
                                "every pair at least R apart, wrapped %r" % (box,))
                self.assertTrue(covered(pts, r, x0, y0, x1, y1, r / 4, periodic=True))
                self.assertIs(s.verify(), True)
        self.assertNotEqual(reference(0.05, 2, periodic=True), reference(0.05, 2))

    def test_radius_over_half_the_period(self):
        with Sampler(0.6, periodic=True) as s:
            self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run)

    def test_periods_at_most_1024_to_1(self):
        with Sampler(2 ** -12, bounds=((0, 0), (1, 2 ** -10)), periodic=True) as s:
            self.assertIs(s.run(), True)
        with Sampler(2 ** -12, bounds=((0, 0), (1.001, 2 ** -10)), periodic=True) as s:
            exc = self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run)
            self.assertIn("1024", exc.message)

    def test_with_count(self):
        with Sampler(None, seed=6, count=300, periodic=True) as s:
            s.run()
            self.assertEqual(len(s), 300)
            self.assertTrue(min_dist_ok(s.points, s.radius, periods=(1.0, 1.0)))


if __name__ == "__main__":
    unittest.main()
