"""Just enough of pytest to import and run scipy's QMC engine tests without it.

scipy's test modules import pytest and use pytest.mark.* as decorators,
pytest.skip() and pytest.raises(); Debian's python3 has scipy but not pytest.
installed() puts this stand-in in sys.modules["pytest"] only while scipy's
module is imported (the module keeps its reference; nothing else sees it).
The marks are kept as pytest keeps them, in fn.pytestmark, with .name, .args
and .kwargs, so test_scipy_suite.py reads them the same way under both.
"""

import contextlib
import re
import sys
import types


class Skipped(Exception):
    """What skip() raises; skip.Exception, as in pytest."""

    def __init__(self, msg=""):
        super().__init__(msg)
        self.msg = msg


def skip(reason="", *, msg=None, allow_module_level=False):
    raise Skipped(msg if msg is not None else reason)


skip.Exception = Skipped


class Mark:
    def __init__(self, name, args, kwargs):
        self.name, self.args, self.kwargs = name, args, kwargs

    def __call__(self, fn):
        fn.pytestmark = list(getattr(fn, "pytestmark", [])) + [self]
        return fn


class _MarkGenerator:
    """pytest.mark.NAME(...) gives a decorator; bare @pytest.mark.NAME marks too."""

    def __getattr__(self, name):
        def make(*args, **kwargs):
            if len(args) == 1 and callable(args[0]) and not kwargs:
                return Mark(name, (), {})(args[0])
            return Mark(name, args, kwargs)
        return make


class _Raised:
    value = None
    type = None


@contextlib.contextmanager
def raises(expected, *, match=None):
    info = _Raised()
    try:
        yield info
    except expected as exc:
        info.value, info.type = exc, type(exc)
        if match is not None and not re.search(match, str(exc)):
            raise AssertionError("Regex pattern %r does not match %r" % (match, str(exc)))
    else:
        raise AssertionError("DID NOT RAISE %r" % (expected,))


def module():
    m = types.ModuleType("pytest")
    m.__doc__ = "a stand-in for pytest (tests/python/pytest_shim.py)"
    m.skip, m.raises, m.mark = skip, raises, _MarkGenerator()
    return m


@contextlib.contextmanager
def installed():
    """sys.modules["pytest"] is the stand-in for the duration."""
    saved = sys.modules.get("pytest")
    sys.modules["pytest"] = module()
    try:
        yield
    finally:
        if saved is None:
            del sys.modules["pytest"]
        else:
            sys.modules["pytest"] = saved
