"""Integers that cross into C: each is checked for range before ctypes converts
it, since ctypes keeps only the low bits (2**64 + 5 would become a size_t 5 and
an int 2**32 - 1 the code -1). Too large gives OverflowError, negative
ValueError; the largest value that fits is passed on as it is."""

import unittest

from support import TestCase, numpy, poissondisk

Sampler = poissondisk.Sampler
SIZE_MAX = 2 ** 64 - 1  # size_t on the 64-bit platforms the library supports


class SizeArgumentsTest(TestCase):
    def test_run_max_new(self):
        with Sampler(0.05, seed=1) as s:
            for big in (2 ** 64, 2 ** 64 + 5, 2 ** 200):
                with self.assertRaises(OverflowError) as cm:
                    s.run(big)
                self.assertIn("max_new=%d" % big, str(cm.exception))
                self.assertEqual(len(s), 0, "nothing was added")
            with self.assertRaises(ValueError):
                s.run(-(2 ** 64) + 5)  # would wrap to 5 as well
            self.assertIs(s.run(SIZE_MAX), True, "the largest size_t is 'as many as fit'")
            self.assertEqual(len(s), len(poissondisk.sample(0.05, seed=1)))

    def test_count(self):
        for big in (2 ** 64, 2 ** 64 + 3):
            with self.assertRaises(OverflowError) as cm:
                Sampler(None, seed=1, count=big)
            self.assertIn("count=%d" % big, str(cm.exception))
        with self.assertRaises(ValueError):
            Sampler(None, seed=1, count=-(2 ** 64) + 3)
        with Sampler(None, seed=1, count=SIZE_MAX) as s:
            # Passed on unchanged: the library refuses it for its index type.
            self.assertLibraryError(poissondisk.RangeError, poissondisk.ERANGE, s.run)
            self.assertEqual(len(s), 0)

    def test_slices_clip_rather_than_wrap(self):
        with Sampler(0.1, seed=1) as s:
            s.run()
            n = len(s)
            self.assertPoints(s.get_points(2 ** 64 + 1), 0)
            self.assertPoints(s.get_points(1, 2 ** 64 + 1), n - 1)
            self.assertEqual(len(s.radii(0, 2 ** 70)), n)

    def test_error_codes_are_c_ints(self):
        for big in (2 ** 31, 2 ** 32 - 1, -(2 ** 31) - 1):  # 2**32 - 1 would be EINVAL, -1
            with self.assertRaises(OverflowError):
                poissondisk.strerror(big)
        self.assertIsInstance(poissondisk.strerror(-(2 ** 31)), str)
        self.assertIsInstance(poissondisk.strerror(2 ** 31 - 1), str)


@unittest.skipIf(numpy is None, "poissondisk.qmc needs numpy")
class EngineCountTest(TestCase):
    def test_random_n(self):
        from poissondisk.qmc import PoissonDisk
        e = PoissonDisk(radius=0.05, seed=1)
        for big in (2 ** 64, 2 ** 64 + 2):
            with self.assertRaises(OverflowError) as cm:
                e.random(big)
            self.assertIn("n=%d" % big, str(cm.exception))
            with self.assertRaises(OverflowError):
                e.fast_forward(big)
        self.assertEqual(e.num_generated, 0)
        whole = PoissonDisk(radius=0.05, seed=1).fill_space()
        self.assertEqual(e.random(SIZE_MAX).shape, whole.shape, "the largest n: all the rest")


if __name__ == "__main__":
    unittest.main()
