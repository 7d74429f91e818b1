"""The installed package: where it was imported from, what it ships, how it
finds the library, and the list fallback without numpy (in a child process
whose numpy import is blocked, whatever this pass has)."""

import ctypes
import json
import os
import sys
import unittest

from support import TestCase, child, numpy, poissondisk


BLOCK_NUMPY = "import sys; sys.modules['numpy'] = None\n"


class InstalledTest(TestCase):
    def test_imported_from_the_venv(self):
        where = os.path.realpath(poissondisk.__file__)
        self.assertTrue(where.startswith(os.path.realpath(sys.prefix)),
                        "%s is inside the venv %s, not the source tree" % (where, sys.prefix))
        self.assertNotEqual(sys.prefix, sys.base_prefix, "running in a venv")

    def test_ships_py_typed_and_qmc(self):
        pkg = os.path.dirname(poissondisk.__file__)
        for name in ("py.typed", "qmc.py", "__init__.py"):
            self.assertTrue(os.path.isfile(os.path.join(pkg, name)), name)

    def test_library_from_the_environment(self):
        self.assertEqual(poissondisk.library_path, os.environ["POISSONDISK_LIBRARY"])

    def test_bad_library_path_is_an_import_error(self):
        status, _, err = child("import poissondisk",
                               {"POISSONDISK_LIBRARY": "/nonexistent/libpoissondisk.so.1"})
        self.assertNotEqual(status, 0)
        self.assertIn("ImportError", err)
        self.assertIn("POISSONDISK_LIBRARY='/nonexistent/libpoissondisk.so.1'", err)

    def test_the_soname_through_the_loader(self):
        """With no override, the normal loader finds it (here via LD_LIBRARY_PATH)."""
        env = {"POISSONDISK_LIBRARY": "", "PDS_LIBRARY": "",
               "LD_LIBRARY_PATH": os.path.dirname(os.environ["POISSONDISK_LIBRARY"])}
        status, out, err = child("import poissondisk; print(poissondisk.library_path, "
                                 "poissondisk.version())", env)
        self.assertEqual(status, 0, err)
        self.assertEqual(out.split(), ["libpoissondisk.so.1", poissondisk.version()])


class ListFallbackTest(TestCase):
    CODE = BLOCK_NUMPY + """import json, poissondisk
with poissondisk.Sampler(0.05, seed=11) as s:
    s.run(20)
    part = s.get_points(3, 4)
    s.run()
    pts = s.points
    n = len(s)
print(json.dumps({"type": type(pts).__name__, "item": type(pts[0]).__name__,
                  "points": pts, "part": part, "n": n,
                  "sample": poissondisk.sample(0.2, seed=1)}))
try:
    import poissondisk.qmc
except ImportError as exc:
    print(json.dumps(str(exc)))
"""

    def test_lists_without_numpy(self):
        status, out, err = child(self.CODE)
        self.assertEqual(status, 0, err)
        got, qmc_error = [json.loads(line) for line in out.splitlines()]
        self.assertEqual((got["type"], got["item"]), ("list", "tuple"))
        self.assertEqual(len(got["points"]), got["n"])
        self.assertEqual(got["part"], got["points"][3:7])
        with poissondisk.Sampler(0.05, seed=11) as s:
            s.run()
            pts = s.points
        self.assertEqual([list(p) for p in pts] if numpy is None else pts.tolist(),
                         got["points"], "the same values as the array (or the lists)")
        self.assertIn("needs numpy", qmc_error)
        self.assertEqual(len(got["sample"]), len(poissondisk.sample(0.2, seed=1)))

    @unittest.skipIf(numpy is None, "this pass has no numpy")
    def test_points_are_filled_in_place(self):
        """pds_points writes straight into the array's buffer: no copy."""
        capi = poissondisk._capi
        real = capi.lib.pds_points
        seen = []

        def spy(handle, first, n, buf):
            seen.append(ctypes.cast(buf, ctypes.c_void_p).value)
            return real(handle, first, n, buf)
        with poissondisk.Sampler(0.1, seed=2) as s:
            s.run()
            capi.lib.pds_points = spy
            try:
                a = s.points
            finally:
                capi.lib.pds_points = real
        self.assertEqual(seen, [a.ctypes.data])
        self.assertTrue(a.flags["OWNDATA"] and a.flags["C_CONTIGUOUS"])
        self.assertEqual(a.strides, (16, 8), "interleaved x,y as the C API writes them")

if __name__ == "__main__":
    unittest.main()
