"""Who owns the C sampler: a Sampler alone. Copying or pickling one is refused
(a copy sharing the handle would free it twice), close() from inside a
callback is refused (run() is still using the handle), and a qmc.PoissonDisk
engine copies into an independent engine that goes on with the same points.

What could crash the interpreter runs in a child process, so that a crash
fails one test instead of ending the run."""

import copy
import json
import unittest

from support import TestCase, child, numpy, poissondisk

Sampler = poissondisk.Sampler
R, SEED = 0.02, 9  # about 2,000 points: the progress callback is called many times


def as_pairs(pts):
    return [tuple(p) for p in (pts.tolist() if hasattr(pts, "tolist") else pts)]


def reference():
    with Sampler(R, seed=SEED) as s:
        s.run()
        return as_pairs(s.points)


class SamplerCopyTest(TestCase):
    CODE = """import copy, json, pickle, poissondisk
s = poissondisk.Sampler(0.05, seed=1)
s.run(20)
out = []
for f in (copy.copy, copy.deepcopy, pickle.dumps):
    try:
        f(s)  # a copy sharing the handle would free it when dropped here
        out.append("copied")
    except TypeError as exc:
        out.append(str(exc))
done = s.run()
print(json.dumps({"out": out, "done": done, "n": len(s), "verify": s.verify()}))
s.close()
"""

    def test_copies_are_refused_and_the_sampler_goes_on(self):
        status, out, err = child(self.CODE)
        self.assertEqual(status, 0, "the child died: %s" % err)
        got = json.loads(out)
        self.assertEqual(len(got["out"]), 3)
        for text in got["out"]:
            self.assertIn("cannot be copied or pickled", text)
            self.assertIn("same arguments and seed", text, "it says what to do instead")
        self.assertTrue(got["done"] and got["verify"])
        self.assertEqual(got["n"], len(poissondisk.sample(0.05, seed=1)))


class CloseFromCallbackTest(TestCase):
    CODE = """import json, poissondisk
R, SEED = %r, %r
out = {}
s = poissondisk.Sampler(R, seed=SEED)
calls = []
def close_once(count, done):
    calls.append(count)
    if len(calls) == 3:
        s.close()  # run() is still using the handle
s.set_progress(close_once)
try:
    s.run()
    out["progress"] = "no error"
except poissondisk.StateError as exc:
    out["progress"] = [exc.code, exc.message, s.closed, len(s) > 0]
s.set_progress(None)
out["finished"] = [s.run(), len(s)]
s.close()
out["closed_after"] = s.closed

def field(x, y):
    if x > 0.5:
        t.close()
    return 0.03
for call in ("run", "step"):
    t = poissondisk.Sampler(None, seed=SEED, radius_fn=field, rmin=0.02, rmax=0.04)
    try:
        if call == "run":
            t.run()
        else:
            while t.step():
                pass
        out[call] = "no error"
    except poissondisk.StateError as exc:
        out[call] = [exc.code, exc.message, t.closed, len(t) > 0]
    t.close()
print(json.dumps(out))
""" % (R, SEED)

    def test_close_is_refused_and_the_sampler_survives(self):
        status, out, err = child(self.CODE)
        self.assertEqual(status, 0, "the child died: %s" % err)
        got = json.loads(out)
        code, message, closed, some = got["progress"]
        self.assertEqual(code, poissondisk.ESTATE)
        self.assertIn("from inside the progress callback", message)
        self.assertIn("after run() returns", message)
        self.assertFalse(closed, "the refused close() left the sampler open")
        self.assertTrue(some)
        done, n = got["finished"]
        self.assertTrue(done)
        self.assertEqual(n, len(reference()), "it finishes the same pattern")
        self.assertTrue(got["closed_after"])
        for call in ("run", "step"):
            code, message, closed, some = got[call]
            self.assertEqual(code, poissondisk.ESTATE, call)
            self.assertIn("from inside the radius function: %s() is" % call, message)
            self.assertFalse(closed, call)
            self.assertTrue(some, "%s: points were made before x > 0.5" % call)

    CAUGHT = """import json, poissondisk
refused = []
def try_close(count, done):
    try:
        s.close()
    except poissondisk.StateError:
        refused.append(count)
with poissondisk.Sampler(%r, seed=%r, progress=try_close) as s:
    done = s.run()
    state = [done, len(refused), s.closed, s.points.tolist() if hasattr(s.points, "tolist")
             else [list(p) for p in s.points]]
print(json.dumps(state + [s.closed]))
""" % (R, SEED)

    def test_a_caught_refusal_changes_nothing(self):
        status, out, err = child(self.CAUGHT)
        self.assertEqual(status, 0, "the child died: %s" % err)
        done, refused, closed, pts, closed_after = json.loads(out)
        self.assertTrue(done)
        self.assertTrue(refused > 3, "refused at each call")
        self.assertFalse(closed)
        self.assertEqual([tuple(p) for p in pts], reference(), "the same pattern")
        self.assertTrue(closed_after, "and close() works once run() has returned")


@unittest.skipIf(numpy is None, "poissondisk.qmc needs numpy")
class EngineCopyTest(TestCase):
    CODE = """import copy, json, pickle
from poissondisk.qmc import PoissonDisk
e = PoissonDisk(radius=0.05, seed=3)
e.random(30)
copies = [copy.copy(e), copy.deepcopy(e), pickle.loads(pickle.dumps(e))]
ref = PoissonDisk(radius=0.05, seed=3)
ref.random(30)
want = ref.random(25).tolist()
del e  # frees the original's sampler: a copy sharing it would now crash
print(json.dumps([[c.num_generated, c.random(25).tolist() == want] for c in copies]))
"""

    def test_copies_are_independent_and_go_on_alike(self):
        status, out, err = child(self.CODE)
        self.assertEqual(status, 0, "the child died: %s" % err)
        self.assertEqual(json.loads(out), [[30, True]] * 3)

    def test_copy_states(self):
        from poissondisk.qmc import PoissonDisk
        fresh = copy.deepcopy(PoissonDisk(radius=0.1, seed=4))
        whole = PoissonDisk(radius=0.1, seed=4).fill_space()
        self.assertTrue(numpy.array_equal(fresh.fill_space(), whole), "a fresh engine")
        full = PoissonDisk(radius=0.1, seed=4)
        full.fill_space()
        twin = copy.copy(full)
        self.assertEqual(twin.random(5).shape, (0, 2), "a full engine's copy is full")
        self.assertEqual(twin.num_generated, len(whole))
        self.assertTrue(numpy.array_equal(twin.reset().fill_space(), whole))
        state = full.__getstate__()
        state["_library"] = "0.0.0"
        with self.assertRaises(ValueError) as cm:
            PoissonDisk.__new__(PoissonDisk).__setstate__(state)
        self.assertIn("0.0.0", str(cm.exception))


if __name__ == "__main__":
    unittest.main()
