#!/usr/bin/env python3
"""island.py - draws the made-up island of the README's domain picture.

    python3 docs/island.py geojson > docs/island.geojson
    python3 docs/island.py pgm > docs/island.pgm

The island is a noisy closed curve: around a centre, the radius is 1 plus a
sum of cosines of the angle with random phases and amplitudes falling as
k^-1.2 (k = 2..40), times a jitter of 1.2% per vertex, so the coast is
irregular at every scale but star-shaped, and therefore never crosses itself. A lake (a hole, drawn the same way with
a smaller radius) lies well inside it, and an islet off the coast; both are
checked to keep clear of the coast. Units are kilometres, x stretched by
1.3. The GeoJSON is a FeatureCollection: the island (coast and lake) and
the islet, each closed by repeating its first position, 6 decimals.

The PGM is a radius map over the polygon's bounding box (which is where
poissondisk --radius-map spreads it with --polygon): dark (dense points)
along every shore, lighter inland and out at sea, 80 x 64 pixels.

Seeded (random.Random(2026)): the same bytes every run. Standard library only.
"""
import json
import math
import random
import sys

SCALE = 10.0   # kilometres per unit
STRETCH = 1.3  # x is stretched


def curve(rng, cx, cy, radius, n, terms, amp):
    """n vertices of r(t) = radius max(0.35, 1 + sum a_k cos(k t + p_k)), around (cx, cy):
    positive, so the curve is star-shaped about the centre and simple."""
    waves = [(k, amp * rng.uniform(0.3, 1.0) * k ** -1.2, rng.uniform(0, 2 * math.pi))
             for k in range(2, terms + 1)]
    pts = []
    for i in range(n):
        t = 2 * math.pi * i / n
        r = radius * max(0.35, 1 + sum(a * math.cos(k * t + p) for k, a, p in waves))
        r *= 1 + rng.uniform(-0.012, 0.012)  # a rugged shore at the smallest scale
        pts.append((cx + STRETCH * r * math.cos(t), cy + r * math.sin(t)))
    return pts


def inside(x, y, ring):
    odd = False
    for (ax, ay), (bx, by) in zip(ring, ring[1:] + ring[:1]):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            odd = not odd
    return odd


def seg_dist(x, y, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(a[0] + t * dx - x, a[1] + t * dy - y)


def shore_distance(x, y, rings):
    return min(seg_dist(x, y, a, b) for ring in rings for a, b in zip(ring, ring[1:] + ring[:1]))


def island():
    rng = random.Random(2026)
    coast = curve(rng, 0.0, 0.0, 1.0, 420, 40, 0.5)
    lake = curve(rng, 0.2, 0.1, 0.22, 90, 12, 0.45)
    islet = curve(rng, 1.75, -0.95, 0.16, 70, 10, 0.4)
    # The lake inside the coast and the islet out at sea, each with room to spare.
    assert all(inside(x, y, coast) and shore_distance(x, y, [coast]) > 0.1 for x, y in lake)
    assert all(not inside(x, y, coast) and shore_distance(x, y, [coast]) > 0.1 for x, y in islet)
    return [[(SCALE * x, SCALE * y) for x, y in ring] for ring in (coast, lake, islet)]


def closed(ring):
    return [[round(x, 6), round(y, 6)] for x, y in ring + ring[:1]]


def write_geojson(out):
    coast, lake, islet = island()
    features = [
        {"type": "Feature", "properties": {"name": "island", "made_by": "docs/island.py"},
         "geometry": {"type": "Polygon", "coordinates": [closed(coast), closed(lake)]}},
        {"type": "Feature", "properties": {"name": "islet"},
         "geometry": {"type": "Polygon", "coordinates": [closed(islet)]}},
    ]
    out.write(json.dumps({"type": "FeatureCollection", "features": features}) + "\n")


def write_pgm(out, w=80, h=64):
    rings = island()
    xs = [x for ring in rings for x, _ in ring]
    ys = [y for ring in rings for _, y in ring]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    # Coarse rings for the distances: every 3rd vertex is close enough for a map.
    coarse = [ring[::3] for ring in rings]
    grey = []
    for j in range(h):
        for i in range(w):
            x = x0 + (i + 0.5) / w * (x1 - x0)
            y = y1 - (j + 0.5) / h * (y1 - y0)  # the top row is y1
            d = shore_distance(x, y, coarse) / 2.5  # in units of 2.5 km
            grey.append(int(round(255 * min(1.0, d) ** 0.7)))
    out.buffer.write(b"P5\n# radius map for docs/island.geojson (docs/island.py)\n"
                     b"%d %d\n255\n" % (w, h) + bytes(grey))


if __name__ == "__main__":
    {"geojson": write_geojson, "pgm": write_pgm}[sys.argv[1]](sys.stdout)
