"""The domain arguments of a Sampler besides the polygon (_geo.py): an image
mask and fixed points, checked for shape on the Python side and converted to
the C arrays of pds_set_mask and pds_set_fixed. Values are the library's to
judge (a NaN coordinate, a negative clearance, a mask with no pixel inside),
so its message, naming the point, reaches the caller.
"""

from __future__ import annotations

import ctypes
from typing import Any, List, Optional, Tuple

from ._args import _np

# Masks are given in the image convention (row 0 at the top, along y1, as
# numpy shows an image and as PIL, imageio and OpenCV load one); the C
# function's row 0 lies along y0, so the rows are reversed on the way.


def mask_buffer(mask: Any) -> Tuple[int, int, Any]:
    """(w, h, buffer): an (h, w) mask of booleans (or 0/1) as w*h bytes,
    nonzero inside, row 0 along y0 (the caller's last row). TypeError or
    ValueError for what is not such an array, or is empty."""
    if _np is not None:
        try:
            arr = _np.asarray(mask)
        except (TypeError, ValueError) as exc:
            raise ValueError("mask must be a 2-D array of booleans, shape (h, w): %s"
                             % exc) from None
        if arr.ndim != 2:
            raise ValueError("mask must be 2-D, shape (h, w) (row 0 at the top, along y1), got "
                             "%d-D shape %r" % (arr.ndim, arr.shape))
        if arr.size == 0:
            raise ValueError("mask is empty (shape %r): it needs at least one pixel inside"
                             % (arr.shape,))
        if arr.dtype != _np.bool_:
            try:
                values = arr.astype(_np.float64)
            except (TypeError, ValueError):
                raise TypeError("mask must hold booleans or 0/1, got dtype %s"
                                % arr.dtype) from None
            bad = _np.argwhere((values != 0) & (values != 1))
            if len(bad):
                j, i = (int(v) for v in bad[0])
                raise ValueError("mask must hold booleans or 0/1 (threshold an image first, e.g. "
                                 "mask=img < 128), got %r at row %d, column %d"
                                 % (arr[j, i].item(), j, i))
            arr = values != 0
        h, w = arr.shape
        return w, h, _np.ascontiguousarray(arr[::-1], dtype=_np.uint8)
    rows = _rows(mask, "mask", "booleans or 0/1")
    h, w = len(rows), len(rows[0]) if rows else 0
    if h == 0 or w == 0:
        raise ValueError("mask is empty (%d rows of %d): it needs at least one pixel inside"
                         % (h, w))
    buf = (ctypes.c_ubyte * (w * h))()
    for j, row in enumerate(rows):
        if len(row) != w:
            raise ValueError("mask rows must all have the same length: row 0 has %d values, row "
                             "%d has %d" % (w, j, len(row)))
        base = (h - 1 - j) * w  # the caller's row j lies at C row h-1-j
        for i, v in enumerate(row):
            if v is True or v is False or (isinstance(v, (int, float)) and v in (0, 1)):
                buf[base + i] = 1 if v else 0
            else:
                raise ValueError("mask must hold booleans or 0/1 (threshold an image first), got "
                                 "%r at row %d, column %d" % (v, j, i))
    return w, h, buf


def fixed_buffers(fixed: Any) -> Tuple[int, Any, Optional[Any]]:
    """(n, xy, clearance): n fixed points as 2n doubles x,y and n clearances
    (None when the rows are (x, y) pairs: each point's clearance is then the
    radius). Buffers are never empty, for a valid pointer when n is 0."""
    if _np is not None:
        try:
            arr = _np.asarray(fixed, dtype=_np.float64)
        except (TypeError, ValueError) as exc:
            raise ValueError("fixed must be an array of (x, y) or (x, y, clearance) rows, "
                             "shape (n, 2) or (n, 3): %s" % exc) from None
        if arr.size == 0:
            return 0, _np.zeros(2), None
        if arr.ndim != 2 or arr.shape[1] not in (2, 3):
            raise ValueError("fixed must have shape (n, 2) (x, y) or (n, 3) (x, y, clearance), "
                             "got shape %r" % (arr.shape,))
        xy = _np.ascontiguousarray(arr[:, :2])
        clearance = _np.ascontiguousarray(arr[:, 2]) if arr.shape[1] == 3 else None
        return len(arr), xy, clearance
    rows = _rows(fixed, "fixed", "numbers")
    n = len(rows)
    cols = len(rows[0]) if rows else 2
    if cols not in (2, 3):
        raise ValueError("fixed rows must be (x, y) or (x, y, clearance), got %d values in row 0"
                         % cols)
    xy = (ctypes.c_double * max(2 * n, 2))()
    clearance = (ctypes.c_double * n)() if cols == 3 else None
    for k, row in enumerate(rows):
        if len(row) != cols:
            raise ValueError("fixed rows must all have the same length: row 0 has %d values, "
                             "row %d has %d" % (cols, k, len(row)))
        try:
            values = [float(v) for v in row]
        except (TypeError, ValueError):
            raise ValueError("fixed must hold numbers, got %r in row %d" % (row, k)) from None
        xy[2 * k], xy[2 * k + 1] = values[0], values[1]
        if clearance is not None:
            clearance[k] = values[2]
    return n, xy, clearance


def _rows(value: Any, name: str, what: str) -> List[List[Any]]:
    """A 2-D array-like as a list of lists, without numpy."""
    if isinstance(value, (str, bytes, bytearray)):
        raise TypeError("%s must be a 2-D array-like of %s, got a %s"
                        % (name, what, type(value).__name__))
    try:
        outer = list(value)
    except TypeError:
        raise TypeError("%s must be a 2-D array-like (a sequence of rows) of %s, got %s"
                        % (name, what, type(value).__name__)) from None
    rows = []
    for j, row in enumerate(outer):
        try:
            rows.append(list(row))
        except TypeError:
            raise ValueError("%s must be 2-D: row %d is %r, not a sequence of %s"
                             % (name, j, row, what)) from None
    return rows


def pointer(buf: Any, ctype: Any) -> Any:
    """A ctypes pointer to the first element of a numpy or ctypes array."""
    if _np is not None and isinstance(buf, _np.ndarray):
        return buf.ctypes.data_as(ctypes.POINTER(ctype))
    return ctypes.cast(buf, ctypes.POINTER(ctype))
