"""Facts about a pattern, recomputed from its coordinates for the Python tests.

Brute force, exact where it matters (a pair that looks close in floating point
is decided with Fractions, to which doubles convert exactly), and independent
of the library's own verdict (Sampler.verify). Standard library only; a
pattern is any sequence of (x, y) pairs: a list of tuples or an (N, 2) array.
"""

import math
import sys
from fractions import Fraction


def as_pairs(pts):
    """A list of (x, y) float tuples, from a list or a numpy array."""
    if hasattr(pts, "tolist"):
        pts = pts.tolist()
    return [(float(x), float(y)) for x, y in pts]


def wrapped(d, period):
    """A coordinate difference to the nearest copy (period None: plain)."""
    if period is None:
        return d
    if d > period / 2:
        return d - period
    if d < -period / 2:
        return d + period
    return d


def min_dist_ok(pts, r, periods=(None, None)):
    """Every pair at least r apart; with periods (px, py), on the torus."""
    pts = as_pairs(pts)
    px, py = periods
    near = r * r * (1 + 1e-9)
    for i in range(len(pts)):
        xi, yi = pts[i]
        for j in range(i + 1, len(pts)):
            dx = wrapped(xi - pts[j][0], px)
            dy = wrapped(yi - pts[j][1], py)
            if dx * dx + dy * dy < near:
                fp = [None if p is None else Fraction(p) for p in periods]
                ex = wrapped(Fraction(xi) - Fraction(pts[j][0]), fp[0])
                ey = wrapped(Fraction(yi) - Fraction(pts[j][1]), fp[1])
                if ex * ex + ey * ey < Fraction(r) ** 2:
                    print("  points %d and %d are %.17g apart" % (i, j, math.hypot(dx, dy)),
                          file=sys.stderr)
                    return False
    return True


def inside(pts, x0, y0, x1, y1, half_open=False):
    pts = as_pairs(pts)
    if half_open:
        return all(x0 <= x < x1 and y0 <= y < y1 for x, y in pts)
    return all(x0 <= x <= x1 and y0 <= y <= y1 for x, y in pts)


def covered(pts, r, x0, y0, x1, y1, step, periodic=False):
    """Every probe of a grid over the rectangle is within r of some point (on
    the torus: of some copy shifted by whole periods): a necessary condition
    for maximality."""
    pts = as_pairs(pts)
    px, py = x1 - x0, y1 - y0
    if periodic:
        pts = [(x + i * px, y + j * py) for x, y in pts for i in (-1, 0, 1) for j in (-1, 0, 1)]
    cells = {}
    for x, y in pts:
        cells.setdefault((math.floor(x / r), math.floor(y / r)), []).append((x, y))
    nx = max(1, round(px / step))
    ny = max(1, round(py / step))
    for a in range(nx if periodic else nx + 1):
        for b in range(ny if periodic else ny + 1):
            qx = x0 + px * a / nx
            qy = y0 + py * b / ny
            cx, cy = math.floor(qx / r), math.floor(qy / r)
            if not any((x - qx) ** 2 + (y - qy) ** 2 <= r * r
                       for i in (-1, 0, 1) for j in (-1, 0, 1)
                       for x, y in cells.get((cx + i, cy + j), ())):
                print("  probe (%g, %g) is farther than %g from every point" % (qx, qy, r),
                      file=sys.stderr)
                return False
    return True
