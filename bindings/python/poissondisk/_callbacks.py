"""The C callbacks of a Sampler: Python functions wrapped so that nothing
unwinds through the library.

Each wrapper holds the sampler's `errors` list (what the callbacks raised
during the current call, first first) and its `calls` list (what is running
now, for close()), never the sampler itself: no reference cycle through C.
An exception is recorded and turned into the value that stops the library
(a true progress result, a NaN radius); the Sampler raises it once the C call
returns.
"""

from __future__ import annotations

import math
from typing import Any, List

from . import _capi
from ._args import ProgressFn, RadiusFn


def radius_callback(call: RadiusFn, errors: List[BaseException], calls: List[str]) -> Any:
    """A pds_radius_fn calling call(x, y); a non-number or an exception
    gives NaN, which the library refuses before adding the point."""
    nan = math.nan

    def radius_at(user: Any, x: float, y: float) -> float:
        if errors:
            return nan  # fn raised: refuse every point until the call returns
        calls.append("the radius function")
        try:
            value = call(x, y)
            try:
                if isinstance(value, (str, bytes, bytearray)):
                    raise TypeError(value)
                return float(value)
            except (TypeError, ValueError):
                raise TypeError("radius_fn(%r, %r) must return a number, got %r"
                                % (x, y, value)) from None
        except BaseException as exc:  # never let it unwind through C
            errors.append(exc)
            return nan  # not finite: the library stops before the point
        finally:
            calls.pop()

    return _capi.RADIUS_FN(radius_at)


def progress_callback(call: ProgressFn, errors: List[BaseException], calls: List[str]) -> Any:
    """A pds_progress_fn calling call(count, done); a true result or an
    exception stops the run."""

    def report(user: Any, count: int, done: float) -> int:
        calls.append("the progress callback")
        try:
            return 1 if call(int(count), float(done)) else 0
        except BaseException as exc:  # never let it unwind through C
            errors.append(exc)
            return 1
        finally:
            calls.pop()

    return _capi.PROGRESS_FN(report)
