"""threads= (library 1.5): None (the default) never calls pds_set_threads and
runs the single-thread process; an int selects the parallel process, whose
points depend on the seed and settings but never on the count, byte for byte.
The one-radius rectangle, polygon and mask (library 1.8 for the last two),
torus and fixed points (library 1.9), with count or refine too, and radius
maps (in the plane since library 1.13, on the torus since 1.14) have a
parallel process; a radius map whose largest radius is over 16 times its
smallest runs on one thread and gives the same points either way."""

import copy
import pickle
import struct
import unittest

from support import TestCase, poissondisk

try:
    import numpy as np
    from poissondisk import qmc
except ImportError:  # no numpy: the drop-in cannot load
    np = qmc = None

Sampler = poissondisk.Sampler
COUNTS = (2, 3, 8)

# The modes, as Sampler arguments: the rectangle, a polygon with a hole, a
# mask with a hole, the torus and fixed points, whose dart stages use the
# threads, with count too, and a radius map in the square and on the torus
# (its darts carried on in the free regions), and one of 1:12 (eight layers
# of dart grids); then a radius map of 1:20, which runs on one thread.
L_SHAPE = [[(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)],
           [(0.3, 0.3), (0.7, 0.3), (0.7, 0.7), (0.3, 0.7)]]
MASK = [[True] * 4 + [False] * 4,  # row 0 along y1: a ring over a bar
        [True, False, False, True] + [False] * 4,
        [True] * 8,
        [True] * 8]
MASK_BOX = ((0, 0), (2, 1))
PARALLEL = {  # the modes with a parallel process of their own
    "rectangle": dict(radius=0.01, bounds=((0, 0), (2, 1))),
    "unit square": dict(radius=0.01),
    "count": dict(radius=None, count=3000),
    "polygon": dict(radius=0.02, domain=L_SHAPE),
    "polygon with count": dict(radius=None, count=3000, domain=L_SHAPE),
    "mask": dict(radius=0.02, mask=MASK, bounds=MASK_BOX),
    "torus": dict(radius=0.01, periodic=True),
    "torus with count": dict(radius=None, count=3000, periodic=True, bounds=((0, 0), (2, 1))),
    "polygon with fixed points": dict(radius=0.02, domain=L_SHAPE,
                                      fixed=[(0.15, 0.15), (1.5, 0.5)]),
    "radius map": dict(radius=None, radius_map=[[0.01, 0.02, 0.03], [0.02, 0.03, 0.02]]),
    "radius map on the torus": dict(radius=None, radius_map=[[0.01, 0.02, 0.03], [0.02, 0.03, 0.02]],
                                    periodic=True),
    "radius map of 1:12": dict(radius=None, radius_map=[[0.0025, 0.01, 0.03], [0.01, 0.03, 0.01]]),
}
ONE_THREAD = {  # the modes that run on one thread whatever was asked
    "radius map of 1:20 on the torus": dict(radius=None, radius_map=[[0.003, 0.01, 0.06], [0.01, 0.06, 0.01]],
                                            periodic=True),
}
MODES = dict(PARALLEL, **ONE_THREAD)


def raw(pts):
    """The points' bytes: x, y doubles in order, as pds_points wrote them."""
    if hasattr(pts, "tobytes"):
        return pts.tobytes()
    return b"".join(struct.pack("=dd", x, y) for x, y in pts)


def first_difference(a, b):
    """Where two byte strings of points part, for a short failure message
    (unittest would diff their reprs, which takes minutes at this size)."""
    if a == b:
        return None
    k = next((i for i in range(0, min(len(a), len(b)), 16) if a[i:i + 16] != b[i:i + 16]),
             min(len(a), len(b)))
    return "%d points against %d, apart from point %d" % (len(a) // 16, len(b) // 16, k // 16)


def pattern(seed, threads, refine=(), **kw):
    with Sampler(seed=seed, threads=threads, **kw) as s:
        s.run()
        for r in refine:
            s.refine(r)
            s.run()
        return raw(s.points), s.radius


class ThreadsCase(TestCase):
    def assertSamePattern(self, got, ref, what):
        """got and ref: (bytes of the points, radius) or bytes alone."""
        if isinstance(got, tuple):
            self.assertEqual(got[1], ref[1], "%s: the radius" % what)
            got, ref = got[0], ref[0]
        diff = first_difference(got, ref)
        self.assertIsNone(diff, "%s: %s" % (what, diff))

    def assertOtherPattern(self, got, ref, what):
        """got and ref: bytes of points that must differ (told apart without
        a repr of either: they are long)."""
        self.assertIsNotNone(first_difference(got, ref), "%s: the same points" % what)


class ArgumentsTest(ThreadsCase):
    def test_default_and_read_back(self):
        with Sampler(0.1, seed=1) as s:
            self.assertEqual(s.threads, 1, "the default: the library starts no thread")
            s.threads = 3
            self.assertEqual(s.threads, 3)
            s.threads = 0
            self.assertTrue(1 <= s.threads <= 1024, "0 resolves to the core count")
        with Sampler(0.1, seed=1, threads=None) as s:
            self.assertEqual(s.threads, 1)
        with Sampler(0.1, seed=1, threads=5) as s:
            self.assertEqual(s.threads, 5)
        with Sampler(0.1, seed=1, threads=1024) as s:
            self.assertEqual(s.threads, 1024)

    def test_bad_values_raise_value_error(self):
        for bad in (-1, 1025, 2 ** 32 + 1, -2 ** 64):
            with self.assertRaises(ValueError, msg="threads=%r" % bad):
                Sampler(0.1, seed=1, threads=bad)
            with self.assertRaises(ValueError, msg="sample(threads=%r)" % bad):
                poissondisk.sample(0.1, seed=1, threads=bad)
            with Sampler(0.1, seed=1, threads=2) as s:
                with self.assertRaises(ValueError):
                    s.threads = bad
                self.assertEqual(s.threads, 2, "a refused count changes nothing")
        for bad in (1.5, "2"):
            with self.assertRaises(TypeError, msg="threads=%r" % (bad,)):
                Sampler(0.1, seed=1, threads=bad)
        with Sampler(0.1, seed=1, threads=2) as s:
            with self.assertRaises(TypeError, msg="setting None: not a count"):
                s.threads = None

    def test_refused_after_single_thread_points(self):
        ref = pattern(2, None, radius=0.01)
        with Sampler(0.01, seed=2) as s:
            s.run(10)
            with self.assertRaises(poissondisk.StateError) as caught:
                s.threads = 2
            self.assertEqual(caught.exception.code, poissondisk.ESTATE)
            self.assertTrue(caught.exception.message.startswith("pds_set_threads:"),
                            caught.exception.message)
            self.assertIn("single-thread", caught.exception.message, "the library's words")
            self.assertEqual(s.threads, 1)
            s.run()
            self.assertSamePattern((raw(s.points), s.radius), ref,
                                   "the run goes on in the single-thread process")

    def test_set_before_the_first_point_selects(self):
        ref = pattern(2, 1, radius=0.01)
        with Sampler(0.01, seed=2) as s:
            s.threads = 3  # no point yet: selects the parallel process
            s.run(10)
            s.threads = 1  # selected: may change at any time
            s.run()
            self.assertSamePattern((raw(s.points), s.radius), ref, "selected by the property")

    def test_refused_inside_the_progress_callback(self):
        for threads in (None, 2):
            seen = []

            def report(count, done):
                if not seen:
                    try:
                        s.threads = 3
                    except poissondisk.StateError as exc:
                        seen.append(exc)
                    else:
                        seen.append(None)

            with Sampler(0.02, seed=1, progress=report, threads=threads) as s:
                s.run()
                self.assertIsInstance(seen[0], poissondisk.StateError, "threads=%r" % threads)
                self.assertEqual(s.threads, 1 if threads is None else threads)


class SamePointsTest(ThreadsCase):
    def test_modes(self):
        for name, kw in MODES.items():
            ref = pattern(3, 1, **kw)
            self.assertGreater(len(ref[0]), 16 * 1000, name)
            for t in COUNTS:
                self.assertSamePattern(pattern(3, t, **kw), ref, "%s: %d threads" % (name, t))

    def test_default_is_the_single_thread_process(self):
        for name, kw in PARALLEL.items():
            default, parallel = pattern(3, None, **kw), pattern(3, 1, **kw)
            self.assertOtherPattern(default[0], parallel[0],
                                    "%s: threads=None against threads=1" % name)
        for name, kw in ONE_THREAD.items():
            self.assertSamePattern(pattern(3, None, **kw), pattern(3, 2, **kw),
                                   "%s: threads=None against threads=2" % name)

    def test_refine(self):
        for name, kw in (("rectangle", dict(radius=0.03, refine=(0.02, 0.01))),
                         ("polygon", dict(radius=0.06, domain=L_SHAPE, refine=(0.04, 0.02)))):
            ref = pattern(4, 1, **kw)
            for t in COUNTS:
                self.assertSamePattern(pattern(4, t, **kw), ref,
                                       "%s refined: %d threads" % (name, t))
            self.assertOtherPattern(pattern(4, None, **kw)[0], ref[0],
                                    "%s refined: threads=None against threads=1" % name)

    def test_split_runs_changing_the_count(self):
        ref = pattern(5, 1, radius=0.01, bounds=((0, 0), (2, 1)))
        with Sampler(0.01, seed=5, bounds=((0, 0), (2, 1)), threads=2) as s:
            k = 0
            while not s.run((1, 7, 1000)[k % 3]):
                s.threads = (2, 3, 8, 0, 1)[k % 5]
                k += 1
            self.assertSamePattern((raw(s.points), s.radius), ref, "split runs")

    def test_sample(self):
        ref = raw(poissondisk.sample(0.01, seed=6, threads=1))
        for t in COUNTS:
            self.assertSamePattern(raw(poissondisk.sample(0.01, seed=6, threads=t)), ref,
                                   "sample(threads=%d)" % t)
        self.assertNotEqual(raw(poissondisk.sample(0.01, seed=6)), ref,
                            "sample() without threads: the single-thread process")
        self.assertSamePattern(raw(poissondisk.sample(0.01, seed=6)),
                               pattern(6, None, radius=0.01)[0], "sample() against Sampler()")


@unittest.skipIf(qmc is None, "numpy is not importable here; poissondisk.qmc needs it")
class DropInTest(ThreadsCase):
    def test_threads_keyword(self):
        ref = qmc.PoissonDisk(2, radius=0.02, seed=7, threads=1).fill_space()
        for t in COUNTS:
            engine = qmc.PoissonDisk(2, radius=0.02, seed=7, threads=t)
            self.assertEqual(engine.threads, t)
            self.assertSamePattern(engine.fill_space().tobytes(), ref.tobytes(),
                                   "PoissonDisk(threads=%d)" % t)
        default = qmc.PoissonDisk(2, radius=0.02, seed=7)
        self.assertIsNone(default.threads)
        self.assertNotEqual(default.fill_space().tobytes(), ref.tobytes(),
                            "no threads: the single-thread process")
        with self.assertRaises(ValueError):
            qmc.PoissonDisk(2, radius=0.02, threads=-1)

    def test_copies_keep_the_selection(self):
        for threads in (None, 1, 3):
            for how in ("pickle", "copy", "deepcopy"):
                engine = qmc.PoissonDisk(2, radius=0.02, seed=7, threads=threads)
                engine.random(100)
                if how == "pickle":
                    dup = pickle.loads(pickle.dumps(engine))
                else:
                    dup = getattr(copy, how)(engine)
                what = "%s of threads=%r" % (how, threads)
                self.assertEqual(dup.threads, threads, what)
                self.assertSamePattern(dup.random(50).tobytes(), engine.random(50).tobytes(),
                                       what)

    def test_setting_threads(self):
        ref = qmc.PoissonDisk(2, radius=0.02, seed=8, threads=1).fill_space()
        engine = qmc.PoissonDisk(2, radius=0.02, seed=8)
        engine.threads = 2  # no sampler yet: selects the parallel process
        first = engine.random(100)
        engine.threads = 3  # selected: the count may change
        self.assertSamePattern(np.concatenate([first, engine.fill_space()]).tobytes(),
                               ref.tobytes(), "threads set on the engine")
        with self.assertRaises(ValueError):
            engine.threads = None  # its points come from the parallel process
        self.assertEqual(engine.threads, 3)
        engine.reset()
        engine.threads = None
        default = qmc.PoissonDisk(2, radius=0.02, seed=8).random(100)
        self.assertSamePattern(engine.random(100).tobytes(), default.tobytes(),
                               "reset, then threads=None")
        with self.assertRaises(poissondisk.StateError):
            engine.threads = 2  # single-thread points exist
        self.assertIsNone(engine.threads, "a refused change changes nothing")
        dup = pickle.loads(pickle.dumps(engine))
        self.assertSamePattern(dup.random(50).tobytes(), engine.random(50).tobytes(),
                               "a pickled copy after the refused change")


if __name__ == "__main__":
    unittest.main()
