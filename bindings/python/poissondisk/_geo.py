"""A polygon domain as pds_set_polygon takes it: flat x,y doubles and ring ends.

Users hold polygons in two shapes, both read here without depending on any
geometry package:
  - rings: a sequence of rings, each a sequence of (x, y) pairs (lists,
    tuples or (n, 2) arrays), or one such ring on its own;
  - GeoJSON-like mappings, directly or through `__geo_interface__` (shapely
    and geopandas objects, and many others): Polygon, MultiPolygon, Feature,
    FeatureCollection and GeometryCollection. Their positions may carry a
    third coordinate (z), which is dropped.
Every ring is passed on as given, holes and outer rings alike: the library
takes the region by the even-odd rule, which for valid GeoJSON polygons is the
region they describe (polygons that overlap each other cancel where they do).
What makes a ring invalid (too few distinct vertices, a NaN) is the library's
to judge, with a message naming the ring and the vertex; `labels` says where
ring k came from, to translate the library's ring numbers back.
"""

from __future__ import annotations

import ctypes
import numbers
import re
from typing import Any, List, Mapping, Optional, Tuple

from ._args import _np

AREAL = ("Polygon", "MultiPolygon", "Feature", "FeatureCollection", "GeometryCollection")


class Rings:
    """A polygon ready for the C call: xy (2*n doubles, a numpy array or a
    ctypes array, never empty), ends (nrings size_t), and labels[k], where ring
    k was found in the caller's object."""

    def __init__(self, xy: Any, n: int, ends: List[int], labels: List[str]) -> None:
        self.xy = xy
        self.n = n
        self.ends = (ctypes.c_size_t * max(len(ends), 1))(*ends)
        self.nrings = len(ends)
        self.labels = labels

    def bounding_box(self) -> Tuple[Tuple[float, float], Tuple[float, float]]:
        xs = self.xy[0:2 * self.n:2]
        ys = self.xy[1:2 * self.n:2]
        if _np is not None and isinstance(xs, _np.ndarray):
            return (float(xs.min()), float(ys.min())), (float(xs.max()), float(ys.max()))
        return (float(min(xs)), float(min(ys))), (float(max(xs)), float(max(ys)))


def _is_number(value: Any) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _describe(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def from_domain(domain: Any) -> Rings:
    """The rings of `domain` (see the module's docstring); TypeError for an
    object of no known shape, ValueError for one that holds no ring."""
    if isinstance(domain, (str, bytes, bytearray)):
        raise TypeError("domain must be rings of (x, y) pairs or a GeoJSON-like polygon, got "
                        "a %s (read the file first, e.g. json.load)" % type(domain).__name__)
    geo = getattr(domain, "__geo_interface__", None)
    if geo is not None:
        rings: List[Tuple[str, Any]] = []
        _walk(geo, "domain.__geo_interface__", rings)
        return _flatten(rings, positions=True)
    if isinstance(domain, Mapping):
        rings = []
        _walk(domain, "domain", rings)
        return _flatten(rings, positions=True)
    return _flatten(_plain_rings(domain), positions=False)


def _plain_rings(domain: Any) -> List[Tuple[str, Any]]:
    """A sequence of rings, or one ring, as (label, ring) pairs."""
    if _np is not None and isinstance(domain, _np.ndarray):
        if domain.ndim == 2:
            return [("domain", domain)]
        if domain.ndim == 3:
            return [("domain[%d]" % k, ring) for k, ring in enumerate(domain)]
        raise ValueError("domain as an array must be one ring of shape (n, 2) or rings of "
                         "shape (k, n, 2), got shape %r" % (domain.shape,))
    try:
        items = list(domain)
    except TypeError:
        raise TypeError("domain must be a sequence of rings of (x, y) pairs or an object with "
                        "__geo_interface__ (a polygon), got %s" % type(domain).__name__) from None
    if not items:
        raise ValueError("domain holds no ring: give at least one ring of 3 or more (x, y) "
                         "pairs (leave domain out for the rectangle of bounds=)")
    if _is_number(items[0]):
        raise TypeError("domain takes rings of (x, y) pairs, not flat numbers (%s); a rectangle "
                        "is bounds=((x0, y0), (x1, y1))" % _describe(domain))
    try:
        first = next(iter(items[0]))
    except (TypeError, StopIteration):
        first = None
    if _is_number(first):  # items[0] is a vertex: the domain is a single ring
        return [("domain", items)]
    return [("domain[%d]" % k, ring) for k, ring in enumerate(items)]


def _walk(geo: Any, where: str, out: List[Tuple[str, Any]]) -> None:
    """Appends the rings of a GeoJSON-like mapping to out, labelled."""
    if not isinstance(geo, Mapping):
        raise TypeError("%s must be a GeoJSON-like mapping, got %s" % (where, _describe(geo)))
    kind = geo.get("type")
    if kind == "Feature":
        inner = geo.get("geometry")
        if inner is None:
            raise ValueError("%s is a Feature without a geometry" % where)
        _walk(inner, where + "['geometry']", out)
    elif kind == "FeatureCollection":
        for i, feature in enumerate(_members(geo, "features", where)):
            _walk(feature, "%s['features'][%d]" % (where, i), out)
    elif kind == "GeometryCollection":
        for i, inner in enumerate(_members(geo, "geometries", where)):
            _walk(inner, "%s['geometries'][%d]" % (where, i), out)
    elif kind == "Polygon":
        for k, ring in enumerate(_members(geo, "coordinates", where)):
            out.append(("%s['coordinates'][%d]" % (where, k), ring))
    elif kind == "MultiPolygon":
        for i, polygon in enumerate(_members(geo, "coordinates", where)):
            for k, ring in enumerate(_list(polygon, "%s['coordinates'][%d]" % (where, i))):
                out.append(("%s['coordinates'][%d][%d]" % (where, i, k), ring))
    elif kind in ("Point", "MultiPoint", "LineString", "MultiLineString"):
        raise ValueError("%s is a %s, which encloses no area: the domain must be a Polygon or "
                         "a MultiPolygon" % (where, kind))
    else:
        raise TypeError("%s has type %s: the domain must be one of %s"
                        % (where, _describe(kind), ", ".join(AREAL)))


def _members(geo: Mapping, key: str, where: str) -> List[Any]:
    if key not in geo:
        raise ValueError("%s (a %s) has no %r" % (where, geo.get("type"), key))
    return _list(geo[key], "%s[%r]" % (where, key))


def _list(value: Any, where: str) -> List[Any]:
    if isinstance(value, (str, bytes, bytearray, Mapping)):
        raise TypeError("%s must be a sequence, got %s" % (where, _describe(value)))
    try:
        return list(value)
    except TypeError:
        raise TypeError("%s must be a sequence, got %s" % (where, _describe(value))) from None


def _flatten(rings: List[Tuple[str, Any]], positions: bool) -> Rings:
    """Rings as flat x,y doubles. With positions (GeoJSON), each vertex may
    carry more coordinates than x and y; plain rings hold pairs."""
    if not rings:
        raise ValueError("the domain holds no polygon ring (an empty geometry?)")
    labels = [label for label, _ in rings]
    ends: List[int] = []
    if _np is not None:
        parts = [_ring_array(ring, label, positions) for label, ring in rings]
        total = 0
        for part in parts:
            total += len(part)
            ends.append(total)
        xy = _np.ascontiguousarray(_np.concatenate(parts) if total else _np.zeros((1, 2)))
        return Rings(xy.reshape(-1), total, ends, labels)
    flat: List[float] = []
    for label, ring in rings:
        for j, vertex in enumerate(_list(ring, label)):
            flat.extend(_vertex(vertex, "%s[%d]" % (label, j), positions))
        ends.append(len(flat) // 2)
    buf = (ctypes.c_double * max(len(flat), 2))(*flat)
    return Rings(buf, len(flat) // 2, ends, labels)


def _ring_array(ring: Any, label: str, positions: bool) -> Any:
    """One ring as an (n, 2) float64 array."""
    try:
        arr = _np.asarray(ring, dtype=_np.float64)
    except (TypeError, ValueError):
        arr = None  # ragged (some positions with z) or not numbers: vertex by vertex
    if arr is not None and arr.ndim == 2 and (arr.shape[1] == 2
                                              or (positions and arr.shape[1] > 2)):
        return arr[:, :2]
    if arr is not None and arr.size == 0:
        return _np.zeros((0, 2))  # an empty ring: the library names it
    vertices = [_vertex(v, "%s[%d]" % (label, j), positions)
                for j, v in enumerate(_list(ring, label))]
    return _np.array(vertices, dtype=_np.float64).reshape(-1, 2)


def _vertex(vertex: Any, where: str, positions: bool) -> Tuple[float, float]:
    try:
        coords = list(vertex)
    except TypeError:
        coords = None
    if coords is None or len(coords) < 2 or (len(coords) > 2 and not positions):
        raise ValueError("%s must be an (x, y) pair, got %s" % (where, _describe(vertex)))
    try:
        return float(coords[0]), float(coords[1])
    except (TypeError, ValueError):
        raise ValueError("%s must hold numbers, got %s" % (where, _describe(vertex))) from None


def ring_label(rings: Optional[Rings], message: str) -> str:
    """The library's message, with where its ring came from when it names one
    ("ring 3") and the rings came out of a GeoJSON-like object (plain rings
    are numbered as the library numbers them)."""
    if rings is None:
        return message
    found = re.search(r"\bring (\d+)", message)
    if found is None:
        return message
    k = int(found.group(1))
    if not 0 <= k < len(rings.labels) or "['" not in rings.labels[k]:
        return message
    return "%s (ring %d is %s)" % (message, k, rings.labels[k])
