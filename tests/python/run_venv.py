#!/usr/bin/env python3
"""make check-python: install the Python package as a user would, then test it.

    /usr/bin/python3 tests/python/run_venv.py /abs/path/to/build/libpoissondisk.so.1

1. copies bindings/python to a scratch directory (pip builds in the source
   directory, which must stay clean);
2. makes a venv there with --system-site-packages, so that Debian's numpy and
   scipy (seen only by /usr/bin/python3) are visible in it;
3. pip-installs the copy offline: --no-index --no-build-isolation (Debian's
   setuptools builds it);
4. runs the test modules of tests/python with the venv's python and
   POISSONDISK_LIBRARY set to the library given: under pytest if the venv
   sees it, else unittest;
5. runs them again with the numpy import blocked, which checks the list
   fallback (the numpy-only tests skip, saying why).
Exits 0 when everything passed. Standard library only.
"""

import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE_SRC = os.path.normpath(os.path.join(HERE, "..", "..", "bindings", "python"))

# Runs the suites in the venv: argv[1] is the tests directory, argv[2] "block" to
# block the numpy import first. Passed with -c so the tests directory, not the
# source tree, is what the venv's python adds to sys.path.
RUNNER = r"""
import sys
tests, mode = sys.argv[1], sys.argv[2]
if mode == "block":
    sys.modules["numpy"] = None  # import numpy now raises ImportError
sys.path.insert(0, tests)
try:
    import pytest
except ImportError:
    pytest = None
if pytest is not None:
    sys.exit(pytest.main(["-q", "-rs", "-p", "no:cacheprovider", tests]))
import unittest
suite = unittest.defaultTestLoader.discover(tests, pattern="test_*.py", top_level_dir=tests)
result = unittest.TextTestRunner(verbosity=1).run(suite)
for case, why in result.skipped:
    print("skipped %s: %s" % (case.id(), why))
bad = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
print("python-%s: %d passed, %d failed, %d skipped"
      % (mode, result.testsRun - bad - len(result.skipped), bad, len(result.skipped)))
sys.exit(0 if result.wasSuccessful() else 1)
"""


def run(cmd, **kw):
    shown = ["<runner>" if "\n" in c else c for c in cmd]
    print("+ " + " ".join(shown), flush=True)
    return subprocess.run(cmd, **kw).returncode


def main():
    if len(sys.argv) != 2 or not os.path.isabs(sys.argv[1]):
        sys.exit("usage: %s /abs/path/to/libpoissondisk.so.1" % sys.argv[0])
    library = sys.argv[1]
    if not os.path.exists(library):
        sys.exit("run_venv: no library at %s (build it first)" % library)
    scratch = tempfile.mkdtemp(prefix="pds-python-")
    try:
        src = os.path.join(scratch, "src")
        shutil.copytree(PACKAGE_SRC, src, ignore=shutil.ignore_patterns(
            "__pycache__", "build", "dist", "*.egg-info"))
        venv = os.path.join(scratch, "venv")
        if run([sys.executable, "-m", "venv", "--system-site-packages", venv]) != 0:
            sys.exit("run_venv: '%s -m venv' failed (Debian: apt-get install python3-venv)"
                     % sys.executable)
        python = os.path.join(venv, "bin", "python")
        pip = [python, "-m", "pip", "install", "--no-index", "--no-build-isolation",
               "--no-deps", "--disable-pip-version-check", "--quiet", src]
        # Only the copy and the system's site packages: no index, no pip configuration.
        pip_env = {k: v for k, v in os.environ.items() if not k.startswith("PIP_")}
        pip_env["PIP_CONFIG_FILE"] = os.devnull
        if run(pip, env=pip_env) != 0:
            sys.exit("run_venv: the offline pip install failed (Debian: apt-get install "
                     "python3-pip python3-setuptools python3-wheel)")
        env = dict(os.environ, POISSONDISK_LIBRARY=library, PYTHONDONTWRITEBYTECODE="1")
        env.pop("PDS_LIBRARY", None)
        env.pop("PYTHONPATH", None)  # the installed package, nothing else
        failed = []
        for mode, extra in (("numpy", {}), ("block", {"POISSONDISK_TEST_NO_NUMPY": "1"})):
            print("== Python package tests (%s)" % ("numpy blocked: the list fallback"
                                                   if extra else "as installed"), flush=True)
            if run([python, "-c", RUNNER, HERE, mode], cwd=scratch, env=dict(env, **extra)):
                failed.append(mode)
        if failed:
            sys.exit("run_venv: Python package tests failed (%s)" % ", ".join(failed))
        print("run_venv: the Python package installs offline and passes its tests")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
