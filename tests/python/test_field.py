"""A variable radius (library 1.3) through Sampler: radius_map, radius_fn with
rmin and rmax, radii(), refine with a field, errors from the field and from
the callable, and the combinations refused. The rule and maximality are
recomputed from the coordinates and radii, not taken from the library."""

import gc
import math
import sys
import unittest
import weakref
from fractions import Fraction

from geometry import as_pairs, inside
from support import TestCase, numpy, poissondisk

Sampler = poissondisk.Sampler

RMIN, RMAX = 0.02, 0.08


def gradient(x, y):
    """Small on the left, large on the right: 0.02 at x = 0 to 0.08 at x = 1."""
    return RMIN + (RMAX - RMIN) * x


def as_floats(radii):
    return [float(r) for r in (radii.tolist() if hasattr(radii, "tolist") else radii)]


def rule_ok(pts, radii):
    """Every later point outside every earlier point's open disk:
    |p_j - p_i| >= r_i for i < j (equality allowed), decided exactly when close."""
    pts = as_pairs(pts)
    radii = as_floats(radii)
    for i, ((xi, yi), ri) in enumerate(zip(pts, radii)):
        near = ri * ri * (1 + 1e-9)
        for j in range(i + 1, len(pts)):
            dx, dy = pts[j][0] - xi, pts[j][1] - yi
            if dx * dx + dy * dy < near:
                ex, ey = Fraction(pts[j][0]) - Fraction(xi), Fraction(pts[j][1]) - Fraction(yi)
                if ex * ex + ey * ey < Fraction(ri) ** 2:
                    print("  point %d is %.17g from point %d, whose radius is %.17g"
                          % (j, math.hypot(dx, dy), i, ri), file=sys.stderr)
                    return False
    return True


def covered_by_disks(pts, radii, x0, y0, x1, y1, step):
    """Every probe of a grid over the rectangle lies in some disk B(p_i, r_i):
    a necessary condition for maximality."""
    pts = as_pairs(pts)
    radii = as_floats(radii)
    cell = max(radii)
    cells = {}
    for (x, y), r in zip(pts, radii):
        cells.setdefault((math.floor(x / cell), math.floor(y / cell)), []).append((x, y, r))
    nx, ny = max(1, round((x1 - x0) / step)), max(1, round((y1 - y0) / step))
    for a in range(nx + 1):
        for b in range(ny + 1):
            qx, qy = x0 + (x1 - x0) * a / nx, y0 + (y1 - y0) * b / ny
            cx, cy = math.floor(qx / cell), math.floor(qy / cell)
            if not any((x - qx) ** 2 + (y - qy) ** 2 <= r * r
                       for i in (-1, 0, 1) for j in (-1, 0, 1)
                       for x, y, r in cells.get((cx + i, cy + j), ())):
                print("  probe (%g, %g) is in no disk" % (qx, qy), file=sys.stderr)
                return False
    return True


def bilinear(rows, x0, y0, x1, y1, x, y):
    """The library's map field: pixel centres, bilinear, clamped (poissondisk.h)."""
    h, w = len(rows), len(rows[0])

    def locate(t, n):
        u = min(max(t * n - 0.5, 0.0), float(n - 1))
        k = int(u)
        if k + 1 >= n:
            k = n - 2 if n >= 2 else 0
        return k, (u - k if n >= 2 else 0.0)

    i, fx = locate((x - x0) / (x1 - x0), w)
    j, fy = locate((y - y0) / (y1 - y0), h)
    i1, j1 = (i + 1 if w >= 2 else i), (j + 1 if h >= 2 else j)
    a, b, c, e = rows[j][i], rows[j][i1], rows[j1][i], rows[j1][i1]
    return (1 - fy) * ((1 - fx) * a + fx * b) + fy * ((1 - fx) * c + fx * e)


class FunctionFieldTest(TestCase):
    def test_gradient_is_maximal_and_verified(self):
        with Sampler(None, seed=11, radius_fn=gradient, rmin=RMIN, rmax=RMAX) as s:
            gc.collect()  # the binding, not the caller, keeps the C callback alive
            self.assertEqual(s.radius, RMAX, "radius is the largest in force, rmax")
            self.assertEqual(s.free_area, 1.0)
            self.assertIs(s.run(), True)
            pts, radii = s.points, s.radii()
            n = len(s)
            self.assertPoints(pts, n)
            self.assertTrue(inside(pts, 0, 0, 1, 1))
            self.assertIs(s.verify(), True)
            self.assertEqual(s.free_area, 0.0)
            self.assertIs(s.step(), False)
            self.assertTrue(rule_ok(pts, radii), "|p_j - p_i| >= r_i for i < j")
            self.assertTrue(covered_by_disks(pts, radii, 0, 0, 1, 1, 0.01), "no probe uncovered")
            # Denser where the radius is small: more points in the left third.
            xs = [x for x, _ in as_pairs(pts)]
            self.assertGreater(sum(x < 1 / 3 for x in xs), 2 * sum(x > 2 / 3 for x in xs))
        self.assertSamePoints(poissondisk.sample(None, seed=11, radius_fn=gradient,
                                                 rmin=RMIN, rmax=RMAX), pts)

    def test_radii_are_the_field_values(self):
        def field(x, y):
            return 0.03 + 0.005 * y * x
        with Sampler(None, seed=4, bounds=((-1, 2), (1, 3)), radius_fn=field,
                     rmin=0.01, rmax=0.05) as s:
            s.run()
            radii = s.radii()
            self.assertRadii(radii, len(s))
            self.assertEqual(as_floats(radii), [field(x, y) for x, y in as_pairs(s.points)],
                             "each radius is the value at its point, exactly")
            self.assertEqual(s.radius, 0.05)
            self.assertTrue(rule_ok(s.points, radii))
            self.assertEqual(as_floats(s.radii(3, 4)), as_floats(radii)[3:7])
            self.assertEqual(as_floats(s.radii(len(s) - 2)), as_floats(radii)[-2:])
            self.assertRadii(s.radii(len(s) + 5), 0)
            self.assertRadii(s.radii(0, 0), 0)
            with self.assertRaises(ValueError):
                s.radii(-1)

    def test_runs_in_batches_give_the_same_points(self):
        with Sampler(None, seed=8, radius_fn=gradient, rmin=RMIN, rmax=RMAX) as s:
            s.run()
            ref = as_pairs(s.points)
        with Sampler(None, seed=8, radius_fn=gradient, rmin=RMIN, rmax=RMAX) as s:
            for _ in range(10):
                s.step()
            while s.run(37) is False:
                pass
            self.assertEqual(as_pairs(s.points), ref)

    def test_constant_function_is_the_plain_sampler(self):
        with Sampler(0.05, seed=2) as s:
            s.run()
            ref = as_pairs(s.points)
        with Sampler(None, seed=2, radius_fn=lambda x, y: 0.05, rmin=0.05, rmax=0.05) as s:
            s.run()
            self.assertEqual(as_pairs(s.points), ref)

    def test_with_progress(self):
        done = []
        with Sampler(None, seed=3, radius_fn=gradient, rmin=RMIN, rmax=RMAX,
                     progress=lambda count, d: done.append(d)) as s:
            self.assertIs(s.run(), True)
        self.assertTrue(done and done == sorted(done) and done[-1] == 1.0)

    def assertRadii(self, radii, n):
        """radii holds n radii in the type of this pass: a C-contiguous (n,)
        float64 array with numpy, a list of floats without."""
        if numpy is not None:
            self.assertIsInstance(radii, numpy.ndarray)
            self.assertEqual(radii.shape, (n,))
            self.assertEqual(radii.dtype, numpy.float64)
            self.assertTrue(radii.flags["C_CONTIGUOUS"] and radii.flags["OWNDATA"])
        else:
            self.assertIsInstance(radii, list)
            self.assertEqual(len(radii), n)
            self.assertTrue(all(type(r) is float for r in radii))


class RadiiWithoutFieldTest(TestCase):
    def test_every_radius_is_the_radius(self):
        with Sampler(0.1, seed=1) as s:
            self.assertEqual(as_floats(s.radii()), [])
            s.run()
            self.assertEqual(as_floats(s.radii()), [0.1] * len(s))
            s.refine(0.07)
            self.assertEqual(as_floats(s.radii()), [0.07] * len(s))


class MapFieldTest(TestCase):
    # Row 0 along y0: small radii at the bottom, large at the top; and a
    # left-right difference, so a transposed or flipped map shows.
    ROWS = [[0.02, 0.03, 0.04],
            [0.05, 0.06, 0.08]]
    BOX = ((0.0, 0.0), (2.0, 1.0))

    def run_map(self, radius_map, seed=6, bounds=BOX):
        with Sampler(None, seed=seed, bounds=bounds, radius_map=radius_map) as s:
            self.assertIs(s.run(), True)
            return as_pairs(s.points), as_floats(s.radii()), s.radius

    def test_map_orientation_and_values(self):
        pts, radii, radius = self.run_map(self.ROWS)
        self.assertEqual(radius, 0.08, "radius is the map's largest value")
        (x0, y0), (x1, y1) = self.BOX
        for (x, y), r in zip(pts, radii):
            self.assertAlmostEqual(r, bilinear(self.ROWS, x0, y0, x1, y1, x, y), delta=1e-15)
        self.assertTrue(rule_ok(pts, radii))
        self.assertTrue(covered_by_disks(pts, radii, x0, y0, x1, y1, 0.02))
        low = sum(y < 0.25 for _, y in pts)
        high = sum(y > 0.75 for _, y in pts)
        self.assertGreater(low, 2 * high, "row 0 (small radii) lies along y0")

    def test_lists_and_tuples_give_the_same_points(self):
        ref = self.run_map(self.ROWS)
        self.assertEqual(self.run_map(tuple(tuple(r) for r in self.ROWS)), ref)

    @unittest.skipIf(numpy is None, "this pass has no numpy")
    def test_arrays_give_the_points_of_lists(self):
        ref = self.run_map(self.ROWS)
        arr = numpy.array(self.ROWS)
        self.assertEqual(self.run_map(arr), ref, "a numpy array: the same points as lists")
        self.assertEqual(self.run_map(numpy.asfortranarray(arr)), ref, "any memory order")
        self.assertEqual(self.run_map(arr.astype(numpy.float32).astype(numpy.float64)),
                         self.run_map(arr.astype(numpy.float32)), "converted to float64")
        wide = numpy.zeros((2, 6))
        wide[:, ::2] = arr
        self.assertEqual(self.run_map(wide[:, ::2]), ref, "a strided view")

    def test_one_by_one_map_is_the_plain_sampler(self):
        for r, box, seed in ((0.05, ((0, 0), (1, 1)), 3), (0.1, ((-2, 1), (3, 2.5)), 9)):
            with Sampler(r, seed=seed, bounds=box) as s:
                s.run()
                ref = as_pairs(s.points)
            pts, radii, radius = self.run_map([[r]], seed=seed, bounds=box)
            self.assertEqual(pts, ref, "a 1x1 map: byte for byte the points of radius=%g" % r)
            self.assertEqual(radii, [r] * len(ref))
            self.assertEqual(radius, r)

    def test_bad_maps(self):
        bad = {"empty": [], "no columns": [[], []], "zero": [[0.05, 0.0]],
               "negative": [[0.05], [-0.01]], "NaN": [[float("nan")]], "inf": [[math.inf]]}
        for what, radius_map in bad.items():
            maps = [radius_map]
            if numpy is not None:
                maps.append(numpy.array(radius_map, dtype=float).reshape(len(radius_map), -1)
                            if radius_map else numpy.zeros((0, 3)))
            for m in maps:
                exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                              Sampler, None, radius_map=m)
                self.assertTrue(exc.message.startswith("pds_set_radius_map:"), what)
        exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                      Sampler, None, radius_map=[[0.05, 0.05], [0.05, -2.0]])
        self.assertIn("row 1, column 1", exc.message)
        for radius_map in ([0.05, 0.05], [[0.05], [0.05, 0.05]], [[[0.05]]], [["x"]]):
            with self.assertRaises(ValueError, msg=repr(radius_map)):
                Sampler(None, radius_map=radius_map)
        with self.assertRaises(TypeError):
            Sampler(None, radius_map=0.05)

    def test_refine_scales_every_radius(self):
        with Sampler(None, seed=5, radius_map=self.ROWS, bounds=self.BOX) as s:
            s.run(60)
            before = as_floats(s.radii())
            s.refine(0.04)
            self.assertEqual(s.radius, 0.04)
            after = as_floats(s.radii())
            self.assertEqual(len(after), 60)
            for r0, r1 in zip(before, after):
                self.assertAlmostEqual(r1, r0 / 2, delta=1e-16)
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts, radii = s.points, s.radii()
            self.assertEqual(as_floats(radii)[:60], after, "old points keep the scaled radii")
            self.assertTrue(all(0.01 - 1e-16 <= r <= 0.04 for r in as_floats(radii)))
            self.assertTrue(rule_ok(pts, radii))
            self.assertTrue(covered_by_disks(pts, radii, 0, 0, 2, 1, 0.02))
            with self.assertRaises(poissondisk.InvalidArgumentError):
                s.refine(0.05)  # above the largest radius in force


class LifetimeTest(TestCase):
    def test_close_releases_the_function(self):
        class Field:
            def __call__(self, x, y):
                return gradient(x, y)
        field = Field()
        ref = weakref.ref(field)
        s = Sampler(None, seed=1, radius_fn=field, rmin=RMIN, rmax=RMAX)
        del field
        gc.collect()
        self.assertIsNotNone(ref(), "the sampler keeps the function while open")
        self.assertIs(s.run(), True)
        s.close()
        gc.collect()
        self.assertIsNone(ref(), "and lets it go once closed")

    def test_no_cycle_through_the_callback(self):
        s = Sampler(None, seed=1, radius_fn=gradient, rmin=RMIN, rmax=RMAX)
        ref = weakref.ref(s)
        del s  # freed by reference counting alone: no cycle through the C callback
        self.assertIsNone(ref())


class FieldErrorsTest(TestCase):
    def test_value_out_of_range_stops_then_resumes(self):
        state = {"bad": False}

        def field(x, y):
            if state["bad"] and x > 0.5:
                return 2 * RMAX
            return gradient(x, y)
        for go_on in ("run", "step"):
            with Sampler(None, seed=7, radius_fn=field, rmin=RMIN, rmax=RMAX) as s:
                state["bad"] = False
                self.assertIs(s.run(20), False)
                state["bad"] = True

                def steps():
                    while s.step():
                        pass
                exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                              s.run if go_on == "run" else steps)
                self.assertTrue(exc.message.startswith("pds_%s:" % go_on), exc.message)
                self.assertIn("radius function returned 0.16", exc.message)
                kept = as_pairs(s.points)
                self.assertGreaterEqual(len(kept), 20, "the points so far are kept")
                self.assertTrue(all(x <= 0.5 for x, _ in kept[20:]), "none where it refused")
                self.assertIs(s.verify(), False, "valid, room left")
                state["bad"] = False
                self.assertIs(s.run(), True, "the sampler goes on once the field is fixed")
                self.assertEqual(as_pairs(s.points)[:len(kept)], kept)
                self.assertIs(s.verify(), True)
                self.assertTrue(rule_ok(s.points, s.radii()))

    def test_not_finite_and_below_rmin(self):
        for value in (float("nan"), math.inf, RMIN / 2, 0.0, -1.0):
            with Sampler(None, seed=1, radius_fn=lambda x, y, v=value: v,
                         rmin=RMIN, rmax=RMAX) as s:
                self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL, s.run)
                self.assertEqual(len(s), 0)

    def test_exception_in_the_function_propagates(self):
        for kind in (ZeroDivisionError, KeyboardInterrupt):
            calls = []

            def field(x, y, kind=kind):
                calls.append(0)
                if len(calls) == 50:  # at the 50th point or so (no progress grid without a callback)
                    raise kind("from the radius function")
                return gradient(x, y)
            with Sampler(None, seed=9, radius_fn=field, rmin=RMIN, rmax=RMAX) as s:
                with self.assertRaises(kind) as cm:
                    s.run()
                self.assertEqual(str(cm.exception), "from the radius function")
                k = len(s)
                self.assertTrue(0 < k < 60, "stopped at once (%d points)" % k)
                self.assertIs(s.run(), True, "the sampler still works")
                self.assertIs(s.verify(), True)
                self.assertTrue(rule_ok(s.points, s.radii()))

    def test_exception_in_step_and_in_the_progress_grid(self):
        def boom(x, y):
            raise ValueError("no radius here")
        with Sampler(None, radius_fn=boom, rmin=RMIN, rmax=RMAX) as s:
            for call in (s.step, s.run):
                with self.assertRaises(ValueError) as cm:
                    call()
                self.assertNotIsInstance(cm.exception, poissondisk.PoissonDiskError)
                self.assertEqual(str(cm.exception), "no radius here")
            self.assertEqual(len(s), 0)

    def test_not_a_number(self):
        with Sampler(None, radius_fn=lambda x, y: "0.05", rmin=RMIN, rmax=RMAX) as s:
            with self.assertRaises(TypeError) as cm:
                s.step()
            self.assertIn("must return a number", str(cm.exception))
        with Sampler(None, seed=1, radius_fn=lambda x, y: Fraction(1, 20),
                     rmin=RMIN, rmax=RMAX) as s:
            self.assertIs(s.step(), True)
            self.assertEqual(as_floats(s.radii()), [0.05])

    def test_changes_from_the_function_are_refused(self):
        codes = []

        def field(x, y):
            len(s)  # reading is allowed
            try:
                s.refine(0.01)
                codes.append(0)
            except poissondisk.StateError as exc:
                codes.append(exc.code)
            return gradient(x, y)
        with Sampler(None, seed=2, radius_fn=field, rmin=RMIN, rmax=RMAX) as s:
            self.assertIs(s.run(30), False)
            self.assertEqual(s.radius, RMAX)
        self.assertTrue(codes and set(codes) == {poissondisk.ESTATE})


class TorusTest(TestCase):
    def test_a_field_on_the_torus(self):
        with Sampler(None, seed=4, periodic=True, radius_fn=gradient, rmin=RMIN, rmax=RMAX) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts, radii = as_pairs(s.points), as_floats(s.radii())
            for i in range(len(pts)):
                for j in range(i + 1, len(pts)):
                    dx = abs(pts[i][0] - pts[j][0])
                    dy = abs(pts[i][1] - pts[j][1])
                    dx, dy = min(dx, 1 - dx), min(dy, 1 - dy)
                    self.assertGreaterEqual(dx * dx + dy * dy, radii[i] ** 2 * (1 - 1e-12))


class ArgumentsTest(TestCase):
    def test_combinations_refused(self):
        for field in ({"radius_map": [[0.05]]},
                      {"radius_fn": gradient, "rmin": RMIN, "rmax": RMAX}):
            with self.assertRaises(ValueError) as cm:
                Sampler(None, count=100, **field)
            self.assertIn("count", str(cm.exception))
            with self.assertRaises(TypeError) as cm:
                Sampler(0.05, **field)
            self.assertIn("radius=None", str(cm.exception))
        with self.assertRaises(TypeError):
            Sampler(None, radius_map=[[0.05]], radius_fn=gradient, rmin=RMIN, rmax=RMAX)
        with self.assertRaises(TypeError):
            Sampler(None, radius_fn=gradient, rmin=RMIN)
        with self.assertRaises(TypeError):
            Sampler(None, radius_fn=gradient, rmax=RMAX)
        with self.assertRaises(TypeError):
            Sampler(0.05, rmin=RMIN, rmax=RMAX)
        with self.assertRaises(TypeError):
            Sampler(None, radius_fn=0.05, rmin=RMIN, rmax=RMAX)
        with self.assertRaises(TypeError):
            Sampler(None)

    def test_bad_bounds(self):
        for rmin, rmax in ((0.08, 0.02), (0.0, 0.05), (-0.01, 0.05), (0.01, math.inf),
                           (float("nan"), 0.05)):
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                          Sampler, None, radius_fn=gradient, rmin=rmin, rmax=rmax)
            self.assertTrue(exc.message.startswith("pds_set_radius_fn:"))

    def test_rmin_too_small_for_the_domain(self):
        with Sampler(None, radius_fn=gradient, rmin=1e-12, rmax=RMAX) as s:
            self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run)
            self.assertEqual(len(s), 0)


if __name__ == "__main__":
    unittest.main()
