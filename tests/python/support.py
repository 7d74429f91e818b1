"""The frame shared by the Python test modules (run by run_venv.py).

The package under test is the one installed in the venv; it loads the library
named by POISSONDISK_LIBRARY. In the second pass run_venv.py blocks the numpy
import (POISSONDISK_TEST_NO_NUMPY=1), so the same tests check the list fallback.
"""

import os
import re
import subprocess
import sys
import unittest

try:
    import numpy
except ImportError:
    numpy = None

import poissondisk  # noqa: F401  (re-exported for the test modules)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
NO_NUMPY_PASS = os.environ.get("POISSONDISK_TEST_NO_NUMPY") == "1"


def header_version():
    """MAJOR.MINOR.PATCH from include/poissondisk.h, the version's one home."""
    with open(os.path.join(ROOT, "include", "poissondisk.h")) as f:
        text = f.read()
    return ".".join(re.search(r"#define PDS_VERSION_%s\s+(\d+)" % k, text).group(1)
                    for k in ("MAJOR", "MINOR", "PATCH"))


class TestCase(unittest.TestCase):
    def assertPoints(self, pts, n):
        """pts holds n points in the type of this pass: a C-contiguous (n, 2)
        float64 array with numpy, a list of (x, y) float tuples without."""
        if numpy is not None:
            self.assertIsInstance(pts, numpy.ndarray)
            self.assertEqual(pts.shape, (n, 2))
            self.assertEqual(pts.dtype, numpy.float64)
            self.assertTrue(pts.flags["C_CONTIGUOUS"] and pts.flags["OWNDATA"])
        else:
            self.assertIsInstance(pts, list)
            self.assertEqual(len(pts), n)
            self.assertTrue(all(isinstance(p, tuple) and len(p) == 2 and
                                all(type(v) is float for v in p) for p in pts))

    def assertSamePoints(self, a, b, what=""):
        self.assertEqual(_plain(a), _plain(b), what)

    def assertLibraryError(self, cls, code, fn, *args, **kwargs):
        """fn(*args, **kwargs) raises cls (a PoissonDiskError) with the given code and the
        library's message in its text; returns the exception."""
        with self.assertRaises(cls) as cm:
            fn(*args, **kwargs)
        exc = cm.exception
        self.assertIsInstance(exc, poissondisk.PoissonDiskError)
        self.assertEqual(exc.code, code)
        self.assertTrue(exc.message and exc.strerror, "the error carries both texts")
        self.assertIn(exc.message, str(exc))
        return exc


def child(code, env=None):
    """Runs code in a fresh interpreter of this venv; returns (status, out, err).
    For what could crash the interpreter: a crash fails one test, not the run."""
    full = dict(os.environ)
    full.update(env or {})
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=full, timeout=300)
    return p.returncode, p.stdout, p.stderr


def _plain(pts):
    return pts.tolist() if hasattr(pts, "tolist") else [list(p) for p in pts]
