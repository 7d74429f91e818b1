"""scipy's own tests of its PoissonDisk engine, run against poissondisk.qmc.PoissonDisk.

The tests come from the installed scipy, not copied here: the class TestPoisson
of scipy.stats.tests.test_qmc (with the QMCEngineTests it inherits). Each of its
test methods, once per parametrization, becomes a test case below, run on a
subclass of TestPoisson whose engine (`qmce`) is the drop-in, and with the name
`qmc` in scipy's test module bound to a copy of scipy.stats.qmc whose
PoissonDisk is the drop-in (test_raises calls qmc.PoissonDisk directly).

Skipped here because they are not 2-D (the drop-in samples the plane only, and
raises ValueError for another d):
  test_0dim     d = 0
  test_mindist  d = 1, 3 and 4
Skipped by scipy's tests themselves, for scipy's own engine too (the skip says
scipy's reason): test_bounds (d = 100, "too costly in memory"),
test_fast_forward, test_sample, and every Scrambled case (PoissonDisk cannot
scramble), test_distribution (d = 50) among them.
Run against the drop-in (scipy 1.10): test_0sample, test_1sample,
test_continuing, test_reset, test_fill_space, test_raises,
test_raises_optimizer, test_optimizers (random-CD and lloyd).

scipy's tests use pytest; where it is missing (Debian's python3 has scipy
without it) pytest_shim stands in for it while scipy's module is imported.
"""

import importlib
import itertools
import re
import types
import unittest
from unittest import mock

import pytest_shim

try:
    from poissondisk import qmc as dropin
except ImportError:
    dropin = None

# Tests that are not about the plane, with why they cannot run here.
NOT_2D = {
    "test_0dim": "not 2-D: samples d = 0; poissondisk.qmc.PoissonDisk takes d = 2 only",
    "test_mindist": "not 2-D: samples d = 1, 3 and 4; poissondisk.qmc.PoissonDisk takes "
                    "d = 2 only",
}


def load_scipy_tests():
    """scipy's test module, or a reason to skip (a str)."""
    if dropin is None:
        return "numpy is not importable here; poissondisk.qmc needs it"
    try:
        importlib.import_module("scipy.stats.qmc")
    except ImportError:
        return "scipy is not installed (Debian: apt-get install python3-scipy)"
    name = "scipy.stats.tests.test_qmc"
    try:
        try:
            importlib.import_module("pytest")
            return importlib.import_module(name)
        except ImportError as exc:
            if exc.name != "pytest":
                raise
        with pytest_shim.installed():
            return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        if exc.name and name.startswith(exc.name):
            return "this scipy does not ship its tests (%s)" % name
        raise


def parametrizations(fn):
    """(id, kwargs) for each case pytest would make of fn (parametrize marks)."""
    axes = []
    for mark in getattr(fn, "pytestmark", []):
        if mark.name != "parametrize":
            continue
        names, values = mark.args[0], list(mark.args[1])
        if isinstance(names, str):
            names = [n.strip() for n in names.split(",")]
        ids = mark.kwargs.get("ids") or [None] * len(values)
        axis = []
        for index, (value, case_id) in enumerate(zip(values, ids)):
            value = getattr(value, "values", value)  # pytest.param(...)
            value = tuple(value) if len(names) > 1 else (value,)
            # pytest's ids: the value when it is plain, else the name and index
            auto = "-".join(str(v) if isinstance(v, (str, int, float, bool, type(None)))
                            else "%s%d" % (n, index) for n, v in zip(names, value))
            axis.append((case_id or auto, dict(zip(names, value))))
        axes.append(axis)
    for combo in itertools.product(*axes):
        yield "-".join(c[0] for c in combo), {k: v for c in combo for k, v in c[1].items()}


def skip_mark(fn):
    for mark in getattr(fn, "pytestmark", []):
        if mark.name == "skip":
            return mark.kwargs.get("reason", "marked skip")
        if mark.name == "skipif" and mark.args and mark.args[0]:
            return mark.kwargs.get("reason", "marked skipif")
    return None


def make_case(mod, method, kwargs, reason):
    engine_tests = type("DropInPoissonTests", (mod.TestPoisson,), {"qmce": dropin.PoissonDisk})
    qmc_with_dropin = types.ModuleType(mod.qmc.__name__)
    qmc_with_dropin.__dict__.update(vars(mod.qmc))
    qmc_with_dropin.PoissonDisk = dropin.PoissonDisk
    skipped = mod.pytest.skip.Exception

    def test(self):
        if reason:
            self.skipTest(reason)
        tests = engine_tests()
        fn = getattr(tests, method)
        with mock.patch.object(mod, "qmc", qmc_with_dropin):
            if hasattr(tests, "setup_method"):
                tests.setup_method(fn)
            try:
                fn(**kwargs)
            except skipped as exc:
                why = getattr(exc, "msg", "") or (
                    "PoissonDisk cannot scramble (can_scramble is False)"
                    if kwargs.get("scramble") else "(it gives no reason)")
                self.skipTest("scipy's test skips itself: %s" % why)
            finally:
                if hasattr(tests, "teardown_method"):
                    tests.teardown_method(fn)
    return test


def build():
    mod = load_scipy_tests()
    if isinstance(mod, str):
        reason = mod

        @unittest.skip(reason)
        def test_scipy_poisson_tests(self):
            pass
        return {"test_scipy_poisson_tests": test_scipy_poisson_tests}
    assert dropin is not None
    cases = {}
    for method in sorted(n for n in dir(mod.TestPoisson) if n.startswith("test")):
        fn = getattr(mod.TestPoisson, method)
        for case_id, kwargs in parametrizations(fn):
            name = method + ("__" + re.sub(r"\W", "_", case_id) if case_id else "")
            reason = NOT_2D.get(method) or skip_mark(fn)
            cases[name] = make_case(mod, method, kwargs, reason)
    if not cases:
        raise AssertionError("scipy's TestPoisson has no tests: was it renamed?")
    return cases


ScipyPoissonDiskTests = type("ScipyPoissonDiskTests", (unittest.TestCase,), build())
ScipyPoissonDiskTests.__doc__ = "scipy.stats.tests.test_qmc.TestPoisson, on the drop-in"


if __name__ == "__main__":
    unittest.main()
