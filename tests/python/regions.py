"""Domains other than a rectangle, judged from the coordinates for the Python
tests, independently of the library: a closed polygon by the even-odd rule, a
closed mask in the image convention, fixed points' clearances, and coverage
of a domain by the disks of a pattern and of its fixed points.

Exact where it matters: doubles convert to Fractions exactly, so a point on
an outline or at exactly a clearance is decided without rounding. Standard
library only.
"""

import math
import sys
from fractions import Fraction

from geometry import as_pairs


def _on_segment(px, py, ax, ay, bx, by):
    cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
    return (cross == 0 and min(ax, bx) <= px <= max(ax, bx)
            and min(ay, by) <= py <= max(ay, by))


def in_polygon(x, y, rings):
    """(x, y) lies in the closed region the rings enclose by the even-odd rule
    (on an outline counts as inside). rings: lists of (x, y) vertices, closed
    implicitly."""
    px, py = Fraction(x), Fraction(y)
    odd = False
    for ring in rings:
        verts = [(Fraction(a), Fraction(b)) for a, b in ring]
        for k in range(len(verts)):
            (ax, ay), (bx, by) = verts[k - 1], verts[k]
            if _on_segment(px, py, ax, ay, bx, by):
                return True
            if (ay > py) != (by > py):
                cross_x = ax + (py - ay) * (bx - ax) / (by - ay)
                if px < cross_x:
                    odd = not odd
    return odd


def in_mask(x, y, mask, bounds):
    """(x, y) lies in the closed union of the True pixels' squares; mask is a
    list of rows, row 0 at the TOP (along y1), spread over bounds."""
    (x0, y0), (x1, y1) = bounds
    h, w = len(mask), len(mask[0])
    u = (Fraction(x) - Fraction(x0)) * w / (Fraction(x1) - Fraction(x0))  # column units
    v = (Fraction(y1) - Fraction(y)) * h / (Fraction(y1) - Fraction(y0))  # rows from the top
    cols = {c for c in (math.floor(u), math.ceil(u) - 1) if 0 <= c < w}
    rows = {r for r in (math.floor(v), math.ceil(v) - 1) if 0 <= r < h}
    return any(mask[r][c] for r in rows for c in cols)


def clear_of_fixed(pts, fixed, radius):
    """Every point is at least each fixed point's clearance (0: radius) from it;
    fixed rows are (x, y) or (x, y, clearance)."""
    for i, (x, y) in enumerate(as_pairs(pts)):
        for k, f in enumerate(fixed):
            c = f[2] if len(f) > 2 and f[2] > 0 else radius
            d2 = (Fraction(x) - Fraction(f[0])) ** 2 + (Fraction(y) - Fraction(f[1])) ** 2
            if d2 < Fraction(c) ** 2:
                print("  point %d is %.17g from fixed point %d, clearance %g"
                      % (i, math.sqrt(d2), k, c), file=sys.stderr)
                return False
    return True


def outline_probes(rings, step):
    """Points along every edge of the rings, about step apart, vertices too."""
    out = []
    for ring in rings:
        for k in range(len(ring)):
            (ax, ay), (bx, by) = ring[k - 1], ring[k]
            n = max(1, int(math.ceil(math.hypot(bx - ax, by - ay) / step)))
            out.extend((ax + (bx - ax) * t / n, ay + (by - ay) * t / n) for t in range(n))
    return out


def grid_probes(bounds, step, keep):
    """The points of a grid over bounds that keep(x, y) accepts."""
    (x0, y0), (x1, y1) = bounds
    nx, ny = max(1, round((x1 - x0) / step)), max(1, round((y1 - y0) / step))
    return [(x, y) for a in range(nx + 1) for b in range(ny + 1)
            for x, y in [(x0 + (x1 - x0) * a / nx, y0 + (y1 - y0) * b / ny)] if keep(x, y)]


def covers(pts, radius, probes, fixed=()):
    """Every probe lies within radius of a point or within a fixed point's
    clearance (0: radius): a necessary condition for maximality."""
    pts = as_pairs(pts)
    cells = {}
    for x, y in pts:
        cells.setdefault((math.floor(x / radius), math.floor(y / radius)), []).append((x, y))
    discs = [(f[0], f[1], f[2] if len(f) > 2 and f[2] > 0 else radius) for f in fixed]
    for qx, qy in probes:
        cx, cy = math.floor(qx / radius), math.floor(qy / radius)
        if any((x - qx) ** 2 + (y - qy) ** 2 <= radius * radius
               for i in (-1, 0, 1) for j in (-1, 0, 1) for x, y in cells.get((cx + i, cy + j), ())):
            continue
        if any((fx - qx) ** 2 + (fy - qy) ** 2 <= c * c for fx, fy, c in discs):
            continue
        print("  probe (%.17g, %.17g) is farther than %g from every point and clearance"
              % (qx, qy, radius), file=sys.stderr)
        return False
    return True
