"""Sampler(domain=..., mask=..., fixed=...): polygons (rings and GeoJSON-like
objects), image masks in the image convention, fixed points with clearances,
and the errors. Inside, spacing, clearance and coverage are recomputed from
the coordinates (regions.py, geometry.py), not taken from the library."""

import math
import unittest

from geometry import as_pairs, min_dist_ok
from regions import (clear_of_fixed, covers, grid_probes, in_mask, in_polygon,
                     outline_probes)
from support import TestCase, numpy, poissondisk

Sampler = poissondisk.Sampler

# A non-convex outline (an L) with a square hole, the hole wound the same way.
OUTER = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)]
HOLE = [(0.2, 0.2), (0.6, 0.2), (0.6, 0.6), (0.2, 0.6)]
L_AREA = 3.0 - 0.16
R = 0.06


class Geo:
    """A stand-in for a shapely or geopandas object: only __geo_interface__."""

    def __init__(self, mapping):
        self._mapping = mapping

    @property
    def __geo_interface__(self):
        return self._mapping


def closed(ring):
    return [list(v) for v in ring] + [list(ring[0])]


def check_pattern(case, pts, rings, radius, fixed=()):
    """pts lie in the closed polygon, R apart, and cover it (fixed points' clearances too)."""
    case.assertTrue(len(pts) > 0)
    outside = [p for p in as_pairs(pts) if not in_polygon(p[0], p[1], rings)]
    case.assertEqual(outside, [], "every point in the closed polygon")
    case.assertTrue(min_dist_ok(pts, radius), "every pair at least R apart")
    xs = [x for ring in rings for x, _ in ring]
    ys = [y for ring in rings for _, y in ring]
    box = ((min(xs), min(ys)), (max(xs), max(ys)))
    probes = grid_probes(box, radius / 3, lambda x, y: in_polygon(x, y, rings))
    probes += outline_probes(rings, radius / 3)
    case.assertTrue(covers(pts, radius, probes, fixed), "no probe of the domain uncovered")


class PolygonTest(TestCase):
    def test_polygon_with_a_hole(self):
        with Sampler(R, seed=3, domain=[OUTER, HOLE]) as s:
            self.assertEqual(s.bounds, ((0.0, 0.0), (2.0, 2.0)), "the polygon's bounding box")
            self.assertAlmostEqual(s.free_area, L_AREA, delta=1e-9)
            self.assertIs(s.run(), True)
            pts = s.points
            self.assertPoints(pts, len(s))
            check_pattern(self, pts, [OUTER, HOLE], R)
            self.assertIs(s.verify(), True)
            self.assertEqual(s.free_area, 0.0)
        self.assertFalse(any(0.2 < x < 0.6 and 0.2 < y < 0.6 for x, y in as_pairs(pts)),
                         "none in the hole")
        self.assertTrue(any(x > 1.5 and y < 0.5 for x, y in as_pairs(pts)), "the arms are filled")

    def test_rings_meeting_at_corners_a_few_ulps_apart(self):
        # A square with a hole in its corner, the hole's corners 5 to 18 ulps
        # off the square's sides: merged, so the area is the square's less
        # the hole's, and the pattern is maximal by the library's verifier.
        square = [(-3.5, -3.5), (-2.5, -3.5), (-2.5, -2.5), (-3.5, -2.5)]
        hole = [(-3.500000000000016, -3.500000000000007), (-3.5000000000000133, -2.9999999999999867),
                (-2.8999999999999946, -3.0000000000000133), (-2.9000000000000106, -3.499999999999983)]
        with Sampler(0.02, seed=1, domain=[square, hole]) as s:
            self.assertAlmostEqual(s.free_area, 0.7, delta=1e-12)
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts = as_pairs(s.points)
        self.assertGreater(len(pts), 1000)
        self.assertFalse(any(-3.5 + 1e-12 < x < -2.9 - 1e-12 and -3.5 + 1e-12 < y < -3.0 - 1e-12 for x, y in pts),
                         "none in the hole")

    def test_islands_far_apart(self):
        # Two unit squares 1000 apart: a grid over their whole box would not
        # fit in memory at this radius; the run holds what the squares need.
        a = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        b = [(x + 1000.0, y + 1000.0) for x, y in a]
        with Sampler(0.01, seed=3, domain=[a, b]) as s:
            self.assertAlmostEqual(s.free_area, 2.0, delta=1e-12)
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts = as_pairs(s.points)
        near = [p for p in pts if p[0] < 500.0]
        self.assertGreater(len(near), 5000)
        self.assertGreater(len(pts) - len(near), 5000)
        self.assertTrue(all(0.0 <= x <= 1.0 and 0.0 <= y <= 1.0 for x, y in near))
        self.assertTrue(all(1000.0 <= x <= 1001.0 and 1000.0 <= y <= 1001.0 for x, y in pts if x >= 500.0))

    def test_strip_far_thinner_than_its_cells(self):
        # A strip 1e-12 high along the diagonal of the unit square.
        strip = [(0.0, 0.0), (1.0, 1.0), (1.0, 1.0 + 1e-12), (0.0, 1e-12)]
        with Sampler(0.01, seed=5, domain=[strip]) as s:
            self.assertAlmostEqual(s.free_area, 1e-12, delta=1e-15)
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts = as_pairs(s.points)
        self.assertTrue(70 < len(pts) <= 143, len(pts))
        self.assertTrue(all(0.0 <= x <= 1.0 and x <= y <= x + 1e-12 + 1e-15 for x, y in pts))

    def test_the_same_points_however_the_run_is_split(self):
        whole = poissondisk.sample(R, seed=8, domain=[OUTER, HOLE])
        with Sampler(R, seed=8, domain=[OUTER, HOLE]) as s:
            while not s.run(37):
                pass
            self.assertSamePoints(s.points, whole)

    def test_one_ring_alone_and_arrays(self):
        ring = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
        one = poissondisk.sample(0.08, seed=2, domain=ring)
        self.assertSamePoints(one, poissondisk.sample(0.08, seed=2, domain=[ring]))
        check_pattern(self, one, [ring], 0.08)
        if numpy is not None:
            self.assertSamePoints(one, poissondisk.sample(0.08, seed=2, domain=numpy.array(ring)))
            self.assertSamePoints(one, poissondisk.sample(0.08, seed=2,
                                                          domain=[numpy.array(ring)]))

    def test_count_in_a_polygon(self):
        with Sampler(None, seed=4, count=300, domain=[OUTER, HOLE]) as s:
            self.assertIs(s.run(), True)
            pts = s.points
            self.assertEqual(len(pts), 300)
            check_pattern(self, pts, [OUTER, HOLE], s.radius)

    def test_radius_function_in_a_polygon(self):
        with Sampler(None, seed=5, domain=[OUTER, HOLE], rmin=0.05, rmax=0.1,
                     radius_fn=lambda x, y: 0.05 + 0.025 * x) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            self.assertFalse([p for p in as_pairs(s.points)
                              if not in_polygon(p[0], p[1], [OUTER, HOLE])])

    def test_radius_map_over_a_thin_ring(self):
        # 64-gons of radius 1 and 0.98: the ring fills 1/25 of its box.
        outer = [(math.cos(k * math.pi / 32), math.sin(k * math.pi / 32)) for k in range(64)]
        inner = [(0.98 * x, 0.98 * y) for x, y in outer]
        with Sampler(None, seed=2, domain=[outer, inner], radius_map=[[0.008, 0.016]]) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts = as_pairs(s.points)
        self.assertTrue(500 < len(pts) < 2000, len(pts))
        self.assertFalse([p for p in pts if not in_polygon(p[0], p[1], [outer, inner])])
        self.assertTrue(min_dist_ok(pts, 0.008), "every pair at least rmin apart")


class GeoInterfaceTest(TestCase):
    POLYGON = {"type": "Polygon", "coordinates": [closed(OUTER), closed(HOLE)]}

    def test_geo_interface_is_the_rings(self):
        rings = [closed(OUTER), closed(HOLE)]
        plain = poissondisk.sample(R, seed=6, domain=rings)
        self.assertSamePoints(poissondisk.sample(R, seed=6, domain=Geo(self.POLYGON)), plain)
        self.assertSamePoints(poissondisk.sample(R, seed=6, domain=self.POLYGON), plain,
                              "a GeoJSON mapping itself")
        feature = {"type": "Feature", "properties": {"name": "L"}, "geometry": self.POLYGON}
        self.assertSamePoints(poissondisk.sample(R, seed=6, domain=Geo(feature)), plain)
        with_z = {"type": "Polygon",
                  "coordinates": [[v + [9.0] for v in ring] for ring in rings]}
        self.assertSamePoints(poissondisk.sample(R, seed=6, domain=Geo(with_z)), plain,
                              "a z coordinate is dropped")

    def test_multipolygon_and_feature_collection(self):
        a = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        b = [(2.0, 0.5), (3.0, 0.5), (3.0, 1.5), (2.0, 1.5)]
        multi = {"type": "MultiPolygon", "coordinates": [[closed(a)], [closed(b)]]}
        collection = {"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
                                                               "coordinates": [closed(a)]}},
            {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
                                                               "coordinates": [closed(b)]}}]}
        pts = poissondisk.sample(0.1, seed=1, domain=Geo(multi))
        self.assertSamePoints(poissondisk.sample(0.1, seed=1, domain=Geo(collection)), pts)
        pairs = as_pairs(pts)
        self.assertTrue(all(in_polygon(x, y, [a]) or in_polygon(x, y, [b]) for x, y in pairs))
        self.assertTrue(any(x < 1 for x, _ in pairs) and any(x > 2 for x, _ in pairs),
                        "both polygons are filled")
        with Sampler(0.1, domain=Geo(multi)) as s:
            self.assertEqual(s.bounds, ((0.0, 0.0), (3.0, 1.5)))

    def test_not_an_area(self):
        for geo in ({"type": "Point", "coordinates": [0, 0]},
                    {"type": "LineString", "coordinates": [[0, 0], [1, 1]]},
                    {"type": "Feature", "geometry": None},
                    {"type": "FeatureCollection", "features": []},
                    {"type": "Polygon", "coordinates": []}):
            with self.assertRaises(ValueError, msg=geo["type"]):
                Sampler(0.1, domain=Geo(geo))
        with self.assertRaises(TypeError):
            Sampler(0.1, domain=Geo({"type": "Circle"}))


# An L of pixels in the image convention (row 0 at the top): the left column
# and the bottom row. Upside down it would be the left column and the top row.
L_MASK = [[True, False, False, False],
          [True, False, False, False],
          [True, False, False, False],
          [True, True, True, True]]
MASK_BOX = ((0.0, 0.0), (4.0, 4.0))


class MaskTest(TestCase):
    def test_orientation_row_0_at_the_top(self):
        with Sampler(0.15, seed=9, mask=L_MASK, bounds=MASK_BOX) as s:
            self.assertAlmostEqual(s.free_area, 7.0, delta=1e-9)
            self.assertIs(s.run(), True)
            pts = as_pairs(s.points)
            self.assertIs(s.verify(), True)
        self.assertEqual([p for p in pts if not in_mask(p[0], p[1], L_MASK, MASK_BOX)], [],
                         "points only in True pixels, row 0 along y1")
        self.assertTrue(any(x > 3 and y < 1 for x, y in pts), "the bottom row (last) is filled")
        self.assertFalse(any(x > 1 and y > 1 for x, y in pts))
        self.assertTrue(min_dist_ok(pts, 0.15))
        probes = grid_probes(MASK_BOX, 0.05, lambda x, y: in_mask(x, y, L_MASK, MASK_BOX))
        self.assertTrue(covers(pts, 0.15, probes))

    def test_fixed_points_on_pixel_lines(self):
        # The corners of the inside pixels, computed as X1 * i / w: within
        # rounding of the library's box, they count as on it.
        x1, y1, w, h = 0.00493827156, 0.0125663704, 3, 5
        mask = [[False] * 3, [False] * 3, [False, True, True], [False] * 3, [False] * 3]
        fixed = [(x1 * 1 / w, y1 * 2 / h), (x1 * 3 / w, y1 * 2 / h), (x1 * 3 / w, y1 * 3 / h), (x1 * 1 / w, y1 * 3 / h)]
        with Sampler(x1 / w / 10, seed=1, mask=mask, bounds=((0.0, 0.0), (x1, y1)), fixed=fixed) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)

    def test_ints_and_arrays(self):
        ints = [[int(v) for v in row] for row in L_MASK]
        a = poissondisk.sample(0.2, seed=4, mask=L_MASK, bounds=MASK_BOX)
        self.assertSamePoints(poissondisk.sample(0.2, seed=4, mask=ints, bounds=MASK_BOX), a)
        if numpy is not None:
            self.assertSamePoints(poissondisk.sample(0.2, seed=4, mask=numpy.array(L_MASK),
                                                     bounds=MASK_BOX), a)

    def test_bad_masks(self):
        for bad in ([[0, 2]], [[0.5]], [[]], [], [[1, 0], [1]]):
            with self.assertRaises(ValueError, msg=repr(bad)):
                Sampler(0.1, mask=bad)
        exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                      Sampler, 0.1, mask=[[False, False]])
        self.assertTrue(exc.message.startswith("pds_set_mask:"), exc.message)


FIXED = [(0.5, 0.5, 0.3), (0.1, 0.1, 0.0), (0.9, 0.15, 0.02), (0.95, 0.95, 0.0)]


class FixedTest(TestCase):
    def test_clearance_kept_and_fixed_not_returned(self):
        with Sampler(0.05, seed=7, fixed=FIXED) as s:
            self.assertIs(s.run(), True)
            pts = s.points
            self.assertEqual(len(pts), len(s))
            self.assertIs(s.verify(), True)
        pairs = as_pairs(pts)
        self.assertTrue(clear_of_fixed(pairs, FIXED, 0.05), "every clearance kept")
        self.assertFalse(any((x, y) == (f[0], f[1]) for x, y in pairs for f in FIXED),
                         "the fixed points are not returned")
        self.assertFalse(any(math.hypot(x - 0.5, y - 0.5) < 0.3 for x, y in pairs), "obstacle")
        self.assertTrue(min_dist_ok(pairs, 0.05))
        probes = grid_probes(((0, 0), (1, 1)), 0.02, lambda x, y: True)
        self.assertTrue(covers(pairs, 0.05, probes, FIXED), "fixed points count for coverage")

    def test_pairs_mean_clearance_radius(self):
        xy = [(x, y) for x, y, _ in FIXED]
        zeros = [(x, y, 0.0) for x, y in xy]
        a = poissondisk.sample(0.05, seed=2, fixed=xy)
        self.assertSamePoints(poissondisk.sample(0.05, seed=2, fixed=zeros), a)
        self.assertTrue(clear_of_fixed(a, xy, 0.05))
        self.assertSamePoints(poissondisk.sample(0.05, seed=2, fixed=[]),
                              poissondisk.sample(0.05, seed=2), "no fixed points")
        if numpy is not None:
            self.assertSamePoints(poissondisk.sample(0.05, seed=2, fixed=numpy.array(xy)), a)

    def test_fixed_on_a_line_one_inside_another(self):
        # Weighted, the point at 0.67 is hidden between its neighbours on the line.
        fixed = [(0.67, 0.5, 0.0155), (0.669, 0.5, 0.0418), (0.8, 0.5, 0.0162)]
        with Sampler(0.036, seed=1, fixed=fixed) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            pts = as_pairs(s.points)
        self.assertTrue(all((x - fx) ** 2 + (y - fy) ** 2 >= c * c for x, y in pts for fx, fy, c in fixed))

    def test_count_past_a_clearance_covering_the_square(self):
        # The n-th point ends the run, maximal or not at the last radius (a
        # corner may be left free); verify raises InternalError on a pattern
        # that breaks a rule.
        with Sampler(None, seed=4, count=3, fixed=[(0.5, 0.5, 1.0)]) as s:
            self.assertIs(s.run(), True)
            self.assertEqual(len(s), 3)
            self.assertIn(s.verify(), (True, False))

    def test_count_starts_from_the_room_a_clearance_leaves(self):
        # A clearance of 0.3 takes 28% of the square: the first maximal
        # pattern holds a little fewer than the count, so the radius goes
        # down by a step or a few, not by the 15 or more of a start from the
        # whole square (the library's 1.9).
        for threads in (None, 2):
            with Sampler(None, seed=1, count=2000, fixed=[(0.5, 0.5, 0.3)], threads=threads) as s:
                self.assertIs(s.step(), True)
                start = s.radius
                self.assertIs(s.run(), True)
                self.assertEqual(len(s), 2000)
                self.assertTrue(0.96 * start < s.radius < start, (start, s.radius))

    def test_clearance_covering_the_square_leaves_no_point(self):
        with Sampler(0.05, seed=4, fixed=[(0.5, 0.5, 1.0)]) as s:
            self.assertIs(s.run(), True)
            self.assertEqual(len(s), 0)
            self.assertIs(s.verify(), True)
            self.assertEqual(s.free_area, 0.0)

    def test_fixed_given_twice_counts_once(self):
        # One point, the larger clearance, in its place: the points of that one alone.
        with Sampler(0.03, seed=2, fixed=[(0.3, 0.4, 0.05), (0.6, 0.6, 0.0), (0.3, 0.4, 0.1)]) as s:
            self.assertIs(s.run(), True)
            self.assertIs(s.verify(), True)
            twice = as_pairs(s.points)
        with Sampler(0.03, seed=2, fixed=[(0.6, 0.6, 0.0), (0.3, 0.4, 0.1)]) as s:
            s.run()
            self.assertEqual(twice, as_pairs(s.points))

    def test_fixed_in_a_polygon(self):
        fixed = [(0.1, 1.5, 0.25), (1.5, 0.5, 0.0)]
        with Sampler(R, seed=12, domain=[OUTER, HOLE], fixed=fixed) as s:
            self.assertIs(s.run(), True)
            pts = s.points
            self.assertIs(s.verify(), True)
        self.assertTrue(clear_of_fixed(pts, fixed, R))
        check_pattern(self, pts, [OUTER, HOLE], R, fixed)

    def test_bad_fixed(self):
        for bad in ([(1, 2, 3, 4)], [(1,)], [[0.5, 0.5], [0.5, 0.5, 0.1]]):
            with self.assertRaises(ValueError, msg=repr(bad)):
                Sampler(0.1, fixed=bad)
        nan = float("nan")
        for bad in ([(0.5, 0.5), (0.2, nan)], [(0.5, 0.5, 0.1), (0.2, 0.2, -1.0)]):
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                          Sampler, 0.1, fixed=bad)
            self.assertTrue(exc.message.startswith("pds_set_fixed:"), exc.message)
            self.assertIn("point 1", exc.message)
        with Sampler(0.1, fixed=[(2.0, 2.0)]) as s:  # outside the bounding box
            exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL, s.run)
            self.assertIn("fixed point 0 (2, 2) lies outside the domain's bounding box [0,1]x[0,1]",
                          exc.message)
            self.assertEqual(len(s), 0)


class DomainErrorTest(TestCase):
    def test_library_errors_carry_the_message(self):
        nan = float("nan")
        two = [(0.2, 0.2), (0.3, 0.3)]
        exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                      Sampler, 0.1, domain=[OUTER, two])
        self.assertTrue(exc.message.startswith("pds_set_polygon:"), exc.message)
        self.assertIn("ring 1", exc.message)
        bad = [(0.0, 0.0), (1.0, nan), (0.0, 1.0)]
        exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                      Sampler, 0.1, domain=[OUTER, bad])
        self.assertIn("ring 1", exc.message)
        self.assertIn("vertex 1", exc.message)
        geo = {"type": "MultiPolygon", "coordinates": [[closed(OUTER)], [closed(two)]]}
        exc = self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                      Sampler, 0.1, domain=Geo(geo))
        self.assertIn("ring 1 is domain.__geo_interface__['coordinates'][1][0]", exc.message,
                      "the library's ring number traced back into the caller's object")
        for kw in (dict(domain=[OUTER]), dict(mask=L_MASK), dict(fixed=[(0.5, 0.5)])):
            self.assertLibraryError(poissondisk.InvalidArgumentError, poissondisk.EINVAL,
                                    Sampler, 0.1, periodic=True, **kw)

    def test_python_side_misuse(self):
        with self.assertRaises(TypeError):
            Sampler(0.1, domain=(0, 0, 1, 1))  # a rectangle is bounds=
        with self.assertRaises(TypeError):
            Sampler(0.1, domain=[OUTER], bounds=((0, 0), (2, 2)))
        with self.assertRaises(TypeError):
            Sampler(0.1, domain=[OUTER], mask=L_MASK)
        with self.assertRaises(TypeError):
            Sampler(0.1, domain="polygon.json")
        with self.assertRaises(ValueError):
            Sampler(0.1, domain=[])
        with self.assertRaises(ValueError):
            Sampler(0.1, domain=[[(0, 0), (1, 0, 5), (0, 1)]])  # a plain ring holds pairs


if __name__ == "__main__":
    unittest.main()
