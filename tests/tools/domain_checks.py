"""domain_checks.py - judges of the poissondisk program's shaped domains
(--polygon, --mask, --fixed), for tests/check-cli-domains.sh. Standard
library only; every fact is recomputed from the files, sharing nothing with
the program's readers or the library.

    python3 tests/tools/domain_checks.py CHECK ARGS...

A DOMAIN is "polygon:FILE" (GeoJSON or "x y" text, the rings combined by the
even-odd rule) or "mask:FILE:X0,Y0,X1,Y1" (a PGM image over the box, a pixel
inside when darker than mid-grey, the top row along Y1). The domain is
closed: a point on the outline is inside. FIXED is a "x y [clearance]" file
or "-" for none; a missing clearance is the radius R. The checks, each
exiting 0 when every assertion holds, 1 after the first that does not:

    inside OUT DOMAIN              every "x y" point of OUT lies in the domain
    spacing OUT R FIXED            every pair at least R apart; every point at
                                   least its clearance from every fixed point,
                                   and none of them is a fixed point
    covered OUT R DOMAIN FIXED STEP    every probe of the domain (a STEP grid,
                                   and every STEP along the outline, vertices
                                   included) within R of a point or within a
                                   fixed point's clearance: maximality
    area DOMAIN                    prints the domain's area
    svg FILE DOMAIN FIXED R        the outline path and the fixed points' groups
    clearances FILE                prints the SVG's clearance circles as "x y r" lines
    png FILE DOMAIN OUT            grey outside, white inside, the points dark
"""
import json
import math
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, __file__.rsplit("/", 2)[0])
from output_checks import Failed, check, decode_png, read_txt  # noqa: E402

NS = "{http://www.w3.org/2000/svg}"


# ---- the domain ----------------------------------------------------------------------

def geojson_rings(obj, out):
    kind = obj.get("type")
    if kind == "FeatureCollection":
        for f in obj["features"]:
            geojson_rings(f, out)
    elif kind == "Feature":
        if obj.get("geometry") is not None:
            geojson_rings(obj["geometry"], out)
    elif kind == "GeometryCollection":
        for g in obj["geometries"]:
            geojson_rings(g, out)
    elif kind == "Polygon":
        out.extend([[(p[0], p[1]) for p in ring] for ring in obj["coordinates"]])
    elif kind == "MultiPolygon":
        for poly in obj["coordinates"]:
            out.extend([[(p[0], p[1]) for p in ring] for ring in poly])
    else:
        raise Failed("not a polygon: %r" % kind)


def read_rings(path):
    with open(path, encoding="utf-8-sig") as f:
        text = f.read()
    if text.lstrip().startswith("{"):
        rings = []
        geojson_rings(json.loads(text), rings)
        return rings
    rings, ring = [], []
    for line in text.splitlines():
        body = line.split("#", 1)[0].split()
        if body:
            ring.append((float(body[0]), float(body[1])))
        elif "#" not in line and ring:
            rings.append(ring)
            ring = []
    if ring:
        rings.append(ring)
    return rings


def edges(rings):
    for ring in rings:
        for k in range(len(ring)):
            yield ring[k], ring[(k + 1) % len(ring)]


def seg_dist(x, y, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = 0.0 if L == 0 else max(0.0, min(1.0, ((x - a[0]) * dx + (y - a[1]) * dy) / L))
    return math.hypot(a[0] + t * dx - x, a[1] + t * dy - y)


class Polygon:
    def __init__(self, path):
        self.rings = read_rings(path)
        xs = [p[0] for r in self.rings for p in r]
        ys = [p[1] for r in self.rings for p in r]
        self.box = (min(xs), min(ys), max(xs), max(ys))
        self.eps = 1e-12 * max(abs(v) for v in self.box + (1.0,))
        self.edges = list(edges(self.rings))

    def contains(self, x, y):
        odd = False
        for a, b in self.edges:
            if (a[1] > y) != (b[1] > y):
                if x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
                    odd = not odd
        # Closed: a point on the outline belongs (within rounding).
        return odd or any(seg_dist(x, y, a, b) <= self.eps for a, b in self.edges)

    def area(self):
        total = 0.0
        for k, ring in enumerate(self.rings):
            a = abs(sum(ring[i][0] * ring[(i + 1) % len(ring)][1]
                        - ring[(i + 1) % len(ring)][0] * ring[i][1] for i in range(len(ring)))) / 2
            # The ring's nesting depth, from the midpoint of its first edge (rings do not cross).
            mx = (ring[0][0] + ring[1][0]) / 2
            my = (ring[0][1] + ring[1][1]) / 2
            depth = 0
            for j, other in enumerate(self.rings):
                if j != k and Polygon.inside_ring(mx, my, other):
                    depth += 1
            total += a if depth % 2 == 0 else -a
        return total

    @staticmethod
    def inside_ring(x, y, ring):
        odd = False
        for a, b in edges([ring]):
            if (a[1] > y) != (b[1] > y) and x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
                odd = not odd
        return odd

    def outline_probes(self, step):
        for a, b in self.edges:
            n = max(1, int(math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / step)))
            for i in range(n):
                yield a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n


def read_pgm(path):
    with open(path, "rb") as f:
        data = f.read()
    tokens, pos = [], 2
    while len(tokens) < 3:
        while data[pos:pos + 1].isspace() or data[pos:pos + 1] == b"#":
            if data[pos:pos + 1] == b"#":
                pos = data.index(b"\n", pos)
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        tokens.append(int(data[pos:end]))
        pos = end
    w, h, maxval = tokens
    if data[:2] == b"P5":
        pix = list(data[pos + 1:pos + 1 + w * h])
    else:
        pix = [int(t) for t in data[pos:].split()][:w * h]
    return w, h, maxval, pix


class Mask:
    def __init__(self, spec):
        path, box = spec.rsplit(":", 1)
        self.box = tuple(float(v) for v in box.split(","))
        self.w, self.h, maxval, pix = read_pgm(path)
        # Row 0 of the image is the top (y1).
        self.inside = [[2 * pix[(self.h - 1 - r) * self.w + c] < maxval for c in range(self.w)]
                       for r in range(self.h)]
        self.cw = (self.box[2] - self.box[0]) / self.w
        self.ch = (self.box[3] - self.box[1]) / self.h

    def pixel(self, c, r):
        return 0 <= c < self.w and 0 <= r < self.h and self.inside[r][c]

    def contains(self, x, y):
        # Closed squares: a point on a pixel's side belongs to both neighbours.
        u, v = (x - self.box[0]) / self.cw, (y - self.box[1]) / self.ch
        eps = 1e-9
        cols = {int(math.floor(u - eps)), int(math.floor(u + eps))}
        rows = {int(math.floor(v - eps)), int(math.floor(v + eps))}
        return any(self.pixel(c, r) for c in cols for r in rows)

    def area(self):
        return sum(map(sum, self.inside)) * self.cw * self.ch

    def outline_probes(self, step):
        for r in range(self.h + 1):
            for c in range(self.w + 1):
                around = [self.pixel(c - a, r - b) for a in (0, 1) for b in (0, 1)]
                if any(around) and not all(around):
                    yield self.box[0] + c * self.cw, self.box[1] + r * self.ch


def domain(spec):
    kind, rest = spec.split(":", 1)
    return Polygon(rest) if kind == "polygon" else Mask(rest)


def read_fixed(path, r):
    out = []
    if path == "-":
        return out
    with open(path, encoding="utf-8-sig") as f:
        for line in f:
            body = line.split("#", 1)[0].split()
            if body:
                c = float(body[2]) if len(body) == 3 else r
                out.append((float(body[0]), float(body[1]), c))
    return out


# ---- the checks ----------------------------------------------------------------------

class Grid:
    """Points by cells of side s, for near-neighbour queries."""

    def __init__(self, pts, s):
        self.s, self.cells = s, {}
        for i, (x, y) in enumerate(pts):
            self.cells.setdefault((math.floor(x / s), math.floor(y / s)), []).append(i)

    def near(self, x, y, reach=1):
        cx, cy = math.floor(x / self.s), math.floor(y / self.s)
        for a in range(-reach, reach + 1):
            for b in range(-reach, reach + 1):
                yield from self.cells.get((cx + a, cy + b), ())


def points(path):
    return [(p[0], p[1]) for p in read_txt(path)]


def check_inside(out, spec):
    d = domain(spec)
    pts = points(out)
    check(len(pts) > 0, "inside: no points")
    for k, (x, y) in enumerate(pts):
        check(d.contains(x, y), "inside: point %d (%r, %r) lies outside the domain" % (k + 1, x, y))


def check_spacing(out, r, fixed):
    r = float(r)
    pts = points(out)
    g = Grid(pts, r)
    for i, (x, y) in enumerate(pts):
        for j in g.near(x, y):
            if j > i:
                d = math.hypot(x - pts[j][0], y - pts[j][1])
                check(d >= r * (1 - 1e-12), "spacing: points %d and %d are %r apart, under R = %r"
                      % (i + 1, j + 1, d, r))
    for k, (fx, fy, c) in enumerate(read_fixed(fixed, r)):
        for i, (x, y) in enumerate(pts):
            check((x, y) != (fx, fy), "spacing: the output holds fixed point %d" % (k + 1))
            d = math.hypot(x - fx, y - fy)
            check(d >= c * (1 - 1e-12), "spacing: point %d is %r from fixed point %d, under its "
                  "clearance %r" % (i + 1, d, k + 1, c))


def check_covered(out, r, spec, fixed, step):
    r, step = float(r), float(step)
    d = domain(spec)
    pts = points(out)
    fix = read_fixed(fixed, r)
    g = Grid(pts, r)
    x0, y0, x1, y1 = d.box
    nx, ny = int(math.ceil((x1 - x0) / step)), int(math.ceil((y1 - y0) / step))
    probes = [(x0 + (x1 - x0) * a / nx, y0 + (y1 - y0) * b / ny)
              for a in range(nx + 1) for b in range(ny + 1)]
    probes = [p for p in probes if d.contains(*p)] + list(d.outline_probes(step))
    check(len(probes) > 10, "covered: only %d probes in the domain" % len(probes))
    for (x, y) in probes:
        hit = any(math.hypot(x - pts[j][0], y - pts[j][1]) <= r * (1 + 1e-9)
                  for j in g.near(x, y))
        hit = hit or any(math.hypot(x - fx, y - fy) <= c * (1 + 1e-9) for fx, fy, c in fix)
        check(hit, "covered: the probe (%r, %r) of the domain is farther than R = %r from every "
              "point and outside every clearance" % (x, y, r))


def print_area(spec):
    print("%.17g" % domain(spec).area())


def check_svg(path, spec, fixed, r):
    d = domain(spec)
    root = ET.parse(path).getroot()
    x0, y0, x1, y1 = d.box
    outline = [e for e in root.iter(NS + "path") if e.get("id") == "outline"]
    check(len(outline) == 1, "svg: one path id=outline")
    data = outline[0].get("d")
    if isinstance(d, Polygon):
        check(outline[0].get("fill-rule") == "evenodd", "svg: the outline is filled even-odd")
        subpaths = [s for s in data.replace("\n", " ").split("Z") if s.strip()]
        check(len(subpaths) == len(d.rings), "svg: %d subpaths for %d rings"
              % (len(subpaths), len(d.rings)))
        for k, (sub, ring) in enumerate(zip(subpaths, d.rings)):
            got = [tuple(float(v) for v in t.lstrip("ML").split(","))
                   for t in sub.split() if t.strip("ML")]
            check(len(got) == len(ring), "svg: ring %d has %d vertices, not %d"
                  % (k + 1, len(got), len(ring)))
            for (gx, gy), (x, y) in zip(got, ring):
                # y upwards: (x, y) is drawn at (x, y0 + y1 - y).
                check(abs(gx - x) <= 1e-9 * (1 + abs(x))
                      and abs(gy - (y0 + y1 - y)) <= 1e-9 * (1 + abs(y)),
                      "svg: ring %d vertex (%r, %r) drawn at (%r, %r)" % (k + 1, x, y, gx, gy))
    else:
        masks = [e for e in root.iter(NS + "path") if e.get("id") == "mask"]
        check(len(masks) == 1, "svg: one path id=mask")
        for t in data.split():
            if t.startswith(("M", "L")):
                x, y = (float(v) for v in t[1:].split(","))
                check(x0 - 1e-9 <= x <= x1 + 1e-9 and y0 - 1e-9 <= y <= y1 + 1e-9,
                      "svg: an outline vertex (%r, %r) outside the box" % (x, y))
    groups = {g.get("id"): g for g in root.iter(NS + "g")}
    fix = read_fixed(fixed, float(r))
    check(("fixed" in groups) == (len(fix) > 0), "svg: a fixed group exactly with fixed points")
    if fix:
        rings = groups["clearances"].findall(NS + "circle")
        dots = groups["fixed"].findall(NS + "circle")
        check(len(rings) == len(fix) and len(dots) == len(fix),
              "svg: %d clearance circles and %d dots for %d fixed points"
              % (len(rings), len(dots), len(fix)))
        for (x, y, c), e in zip(fix, rings):
            check(abs(float(e.get("cx")) - x) <= 1e-9 * (1 + abs(x))
                  and abs(float(e.get("cy")) - (y0 + y1 - y)) <= 1e-9 * (1 + abs(y))
                  and abs(float(e.get("r")) - c) <= 1e-9 * c,
                  "svg: the clearance circle of (%r, %r) is %r, not radius %r"
                  % (x, y, e.attrib, c))


def print_clearances(path):
    """The clearance circles of an SVG as a fixed-point file: "x y r" lines."""
    root = ET.parse(path).getroot()
    box = [e for e in root.iter(NS + "rect") if e.get("id") == "domain"][0]
    ysum = 2 * float(box.get("y")) + float(box.get("height"))
    groups = {g.get("id"): g for g in root.iter(NS + "g")}
    for c in groups["clearances"].findall(NS + "circle"):
        print("%s %.17g %s" % (c.get("cx"), ysum - float(c.get("cy")), c.get("r")))


def check_png(path, spec, out):
    d = domain(spec)
    w, h, rows = decode_png(path)
    x0, y0, x1, y1 = d.box
    grey = white = total = 0
    for py in range(0, h, 3):
        for px in range(0, w, 3):
            x = x0 + (px + 0.5) / w * (x1 - x0)
            y = y1 - (py + 0.5) / h * (y1 - y0)
            # Far from the outline (3 pixels): plainly inside or outside.
            near = max((x1 - x0) / w, (y1 - y0) / h) * 3
            if any(d.contains(x + a * near, y + b * near) != d.contains(x, y)
                   for a in (-1, 1) for b in (-1, 1)):
                continue
            total += 1
            if d.contains(x, y):
                white += rows[py][px] > 224
            else:
                check(rows[py][px] <= 224, "png: the pixel (%d, %d) outside the domain is %d, "
                      "not grey" % (px, py, rows[py][px]))
                grey += 1
    check(grey > 0 and white > 0.5 * (total - grey), "png: %d grey and %d light pixels of %d"
          % (grey, white, total))
    for x, y in points(out):
        px = min(int((x - x0) / (x1 - x0) * w), w - 1)
        py = min(int((y1 - y) / (y1 - y0) * h), h - 1)
        check(rows[py][px] < 128, "png: the point (%r, %r) is not dark" % (x, y))


CHECKS = {
    "inside": check_inside, "spacing": check_spacing, "covered": check_covered,
    "area": print_area, "svg": check_svg, "png": check_png, "clearances": print_clearances,
}

if __name__ == "__main__":
    try:
        CHECKS[sys.argv[1]](*sys.argv[2:])
    except Failed as e:
        print("domain_checks %s: %s" % (sys.argv[1], e), file=sys.stderr)
        sys.exit(1)
