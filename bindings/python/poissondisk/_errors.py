"""The exceptions: one class per PDS_E* code, all under PoissonDiskError.

Each also derives from the built-in exception a Python caller would expect
(an invalid argument is a ValueError, running out of memory a MemoryError),
so code that knows nothing of this package still catches them sensibly.
"""

from __future__ import annotations

from typing import Dict, Type

from . import _capi


class PoissonDiskError(Exception):
    """A call into libpoissondisk failed.

    Attributes:
        code: the negative PDS_E* code (poissondisk.EINVAL, ...).
        message: what failed, in the library's words (pds_errmsg), starting
            with the name of the C function.
        strerror: the code's generic text (pds_strerror).
    """

    def __init__(self, code: int, message: str) -> None:
        super().__init__(code, message)
        self.code = code
        self.message = message
        self.strerror = _capi.strerror(code)

    def __str__(self) -> str:
        if self.strerror in self.message:  # do not say the same thing twice
            return "%s [code %d]" % (self.message, self.code)
        return "%s [%s, code %d]" % (self.message, self.strerror, self.code)


class InvalidArgumentError(PoissonDiskError, ValueError):
    """PDS_EINVAL: an argument is invalid (NaN, infinite, out of its range,
    an empty or inverted rectangle)."""


class OutOfMemoryError(PoissonDiskError, MemoryError):
    """PDS_ENOMEM: memory could not be allocated; the sampler is unchanged and
    retrying gives the same points."""


class StateError(PoissonDiskError, RuntimeError):
    """PDS_ESTATE: not allowed now (changing the sampler from inside its
    progress callback, refine in count mode, any change after an internal
    error)."""


class RangeError(PoissonDiskError, ValueError):
    """PDS_ERANGE: the radius is too small for the domain (double precision
    cannot resolve it, or the points asked for cannot fit the library's
    32-bit indices), or larger than half a period on a torus."""


class InternalError(PoissonDiskError, RuntimeError):
    """PDS_EINTERNAL: an internal check failed (a bug: please report it with
    the message); the points can still be read."""


class CanceledError(PoissonDiskError):
    """PDS_ECANCELED: the progress callback asked run() to stop. The points so
    far stay, and a later run() continues exactly as if never stopped."""


_BY_CODE: Dict[int, Type[PoissonDiskError]] = {
    _capi.EINVAL: InvalidArgumentError,
    _capi.ENOMEM: OutOfMemoryError,
    _capi.ESTATE: StateError,
    _capi.ERANGE: RangeError,
    _capi.EINTERNAL: InternalError,
    _capi.ECANCELED: CanceledError,
}


def error_for(code: int, message: str) -> PoissonDiskError:
    """The exception for a negative code (PoissonDiskError for unknown codes)."""
    return _BY_CODE.get(code, PoissonDiskError)(code, message)
