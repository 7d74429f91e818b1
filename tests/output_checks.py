"""output_checks.py - judges of the poissondisk program's output files, for
tests/check-cli-output.sh. Standard library only (numpy is used for npy when
it can be imported, and the file is parsed by hand as well).

    python3 tests/output_checks.py CHECK ARGS...

Each check reads the files the program wrote, recomputes what it can from the
plain "x y" output (the reference), and exits 0 when every assertion holds,
1 after printing the first one that does not. The checks:

    formats REF.txt DIR RADIUS X0 Y0 X1 Y1 PERIODIC [RADII]  DIR/p.{csv,json,bin,npy}
    svg FILE REF.txt RADIUS X0 Y0 X1 Y1 DISKS PERIODIC [RADII DOT]
    png FILE REF.txt X0 Y0 X1 Y1 WIDTH HEIGHT
    spectrum-png FILE SIZE BLUE   (BLUE 1: dark centre ring; 0: flat)
    spectrum-csv FILE KIND PATTERNS   (KIND blue or white)
    plot FILE
    stats STATS-LINE-FILE REF.txt RADIUS X0 Y0 X1 Y1 PERIODIC   (RADIUS "map": REF.txt
                                  has the radii as a third column, --radius-map)
    white OUT PATTERNS N SEED     writes uniform random patterns (white noise)
    pgm OUT KIND ENCODING W H     writes a test image for --radius-map (see write_pgm)
    field REF.txt RMIN RMAX X0 Y0 X1 Y1 STEP   a variable-radius pattern ("x y r"
                                  lines): radii in [RMIN, RMAX], the rule, coverage
    gradient REF.txt RMIN RMAX W  "x y r" lines of a map from the image hgrad W x H:
                                  r is linear in x between the first and last pixel
                                  centres, as the map's bilinear interpolation gives

RADII 1: REF.txt holds "x y r" lines and the files the radius as a third value;
the SVG's disks then have radius r/2 each, and its dots radius DOT.
"""
import ast
import csv
import json
import math
import random
import struct
import sys
import xml.etree.ElementTree as ET
import zlib


class Failed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failed(what)


def read_txt(path):
    with open(path) as f:
        return [tuple(float(v) for v in line.split()) for line in f if line.strip()]


# ---- formats ----------------------------------------------------------------------

def parse_npy(data, cols=2):
    """The NumPy 1.0 format by hand: magic, version, header, '<f8' data."""
    check(data[:6] == b"\x93NUMPY", "npy: magic")
    check(data[6:8] == b"\x01\x00", "npy: version 1.0")
    (hlen,) = struct.unpack("<H", data[8:10])
    check((10 + hlen) % 64 == 0, "npy: data aligned on 64 bytes (got %d)" % (10 + hlen))
    header = data[10:10 + hlen].decode("latin1")
    check(header.endswith("\n"), "npy: header ends with a newline")
    meta = ast.literal_eval(header.strip())
    check(meta == {"descr": "<f8", "fortran_order": False, "shape": meta.get("shape")},
          "npy: header keys %r" % meta)
    rows, got = meta["shape"]
    check(got == cols, "npy: shape (N, %d), got (N, %d)" % (cols, got))
    body = data[10 + hlen:]
    check(len(body) == 8 * cols * rows, "npy: %d data bytes for %d rows" % (len(body), rows))
    vals = struct.unpack("<%dd" % (cols * rows), body)
    return list(zip(*[vals[k::cols] for k in range(cols)]))


def check_formats(ref_path, folder, radius, x0, y0, x1, y1, periodic, radii="0"):
    ref = read_txt(ref_path)
    n = len(ref)
    cols = 3 if radii == "1" else 2
    check(all(len(p) == cols for p in ref), "reference: %d values per line" % cols)
    with open(folder + "/p.csv") as f:
        rows = list(csv.reader(f))
    check(rows[0] == ["x", "y", "r"][:cols], "csv: header %s" % ",".join(rows[0]))
    check([tuple(float(v) for v in r) for r in rows[1:]] == ref, "csv: the same points")
    with open(folder + "/p.json") as f:
        doc = json.load(f)
    check(sorted(doc) == ["count", "domain", "periodic", "points", "radius"],
          "json: keys %s" % sorted(doc))
    check(doc["radius"] == float(radius), "json: radius %r" % doc["radius"])
    check(doc["domain"] == [float(v) for v in (x0, y0, x1, y1)], "json: domain")
    check(doc["periodic"] is (periodic == "1"), "json: periodic")
    check(doc["count"] == n, "json: count %r, %d points" % (doc["count"], n))
    check([tuple(p) for p in doc["points"]] == ref, "json: the same points")
    with open(folder + "/p.bin", "rb") as f:
        raw = f.read()
    check(len(raw) == 8 * cols * n, "bin: %d bytes per point" % (8 * cols))
    vals = struct.unpack("<%dd" % (cols * n), raw)
    check(list(zip(*[vals[k::cols] for k in range(cols)])) == ref, "bin: the same points")
    with open(folder + "/p.npy", "rb") as f:
        check(parse_npy(f.read(), cols) == ref, "npy: the same points")
    try:
        import numpy
    except ImportError:
        numpy = None
    if numpy is not None:
        arr = numpy.load(folder + "/p.npy")
        check(arr.dtype == numpy.float64 and arr.shape == (n, cols), "numpy.load: shape")
        check([tuple(r) for r in arr.tolist()] == ref, "numpy.load: the same points")


# ---- SVG ----------------------------------------------------------------------------

NS = "{http://www.w3.org/2000/svg}"


def check_svg(path, ref_path, radius, x0, y0, x1, y1, disks, periodic, radii="0", dot=None):
    ref = read_txt(ref_path)
    r, box = float(radius), [float(v) for v in (x0, y0, x1, y1)]
    root = ET.parse(path).getroot()
    with open(path, "rb") as f:
        check(f.read(5) == b"<?xml", "svg: XML declaration")
    check(root.tag == NS + "svg", "svg: root element <svg> in the SVG namespace")
    vb = [float(v) for v in root.get("viewBox").split()]
    check(vb[0] <= box[0] and vb[1] <= box[1] and vb[0] + vb[2] >= box[2]
          and vb[1] + vb[3] >= box[3], "svg: the viewBox %r holds the domain" % vb)
    groups = {g.get("id"): g for g in root.iter(NS + "g")}
    dom = [e for e in root.iter(NS + "rect") if e.get("id") == "domain"]
    check(len(dom) == 1, "svg: one rect id=domain")
    check([float(dom[0].get(k)) for k in ("x", "y", "width", "height")]
          == [box[0], box[1], box[2] - box[0], box[3] - box[1]], "svg: the domain's box")
    dots = groups["points"].findall(NS + "circle")
    check(len(dots) == len(ref), "svg: %d point circles for %d points" % (len(dots), len(ref)))
    if dot is not None:
        check(all(abs(float(c.get("r")) - float(dot)) <= 1e-9 * float(dot) for c in dots),
              "svg: every dot of radius %s" % dot)
    for (x, y, *_), c in zip(ref, dots):
        # y upwards: the point (x, y) is drawn at (x, y0 + y1 - y).
        check(abs(float(c.get("cx")) - x) <= 1e-9 * (1 + abs(x))
              and abs(float(c.get("cy")) - (box[1] + box[3] - y)) <= 1e-9 * (1 + abs(y)),
              "svg: circle at (%s, %s) for the point (%r, %r)" % (c.get("cx"), c.get("cy"), x, y))
    check(("disks" in groups) == (disks == "1"), "svg: a disks group exactly with --disks")
    check(("disk-copies" in groups) == (disks == "1" and periodic == "1"),
          "svg: a disk-copies group exactly with --disks on a torus")
    if disks == "1" and radii == "1":
        # Each point's own radius r: a disk of radius r/2, in point order.
        circ = groups["disks"].findall(NS + "circle")
        check(len(circ) == len(ref), "svg: %d disks for %d points" % (len(circ), len(ref)))
        for (x, y, rk), c in zip(ref, circ):
            check(abs(float(c.get("r")) - rk / 2) <= 1e-9 * rk
                  and abs(float(c.get("cx")) - x) <= 1e-9 * (1 + abs(x)),
                  "svg: the disk of (%r, %r) has r=%s, not r/2 = %r" % (x, y, c.get("r"), rk / 2))
    elif disks == "1":
        circ = groups["disks"].findall(NS + "circle")
        check(len(circ) == len(ref), "svg: %d disks for %d points" % (len(circ), len(ref)))
        check(all(abs(float(c.get("r")) - r / 2) <= 1e-9 * r for c in circ), "svg: r = R/2")
        # Disks of radius R/2 around points R apart do not overlap (the SVG has 10 digits).
        pts = [(float(c.get("cx")), float(c.get("cy"))) for c in circ]
        check(min_distance(pts, r, box, periodic == "1") >= r * (1 - 1e-8),
              "svg: two disks overlap")


def min_distance(pts, r, box, periodic):
    """The smallest pair distance, through a grid of cells at least r wide."""
    w, h = box[2] - box[0], box[3] - box[1]
    nx, ny = max(1, int(w / r)), max(1, int(h / r))

    def cell(x, y):
        return (min(int((x - box[0]) / w * nx), nx - 1), min(int((y - box[1]) / h * ny), ny - 1))

    cells = {}
    for i, (x, y) in enumerate(pts):
        cells.setdefault(cell(x, y), []).append(i)
    best = math.inf
    for i, (x, y) in enumerate(pts):
        cx, cy = cell(x, y)
        keys = {((cx + a) % nx, (cy + b) % ny) if periodic else (cx + a, cy + b)
                for a in (-1, 0, 1) for b in (-1, 0, 1)}
        for key in keys:
            for j in cells.get(key, ()):
                if j != i:
                    ex, ey = x - pts[j][0], y - pts[j][1]
                    if periodic:
                        ex -= w * round(ex / w)
                        ey -= h * round(ey / h)
                    best = min(best, math.hypot(ex, ey))
    return best


# ---- PNG ----------------------------------------------------------------------------

def decode_png(path):
    """Checks the signature, every chunk's CRC and the zlib stream; returns the grey rows."""
    with open(path, "rb") as f:
        data = f.read()
    check(data[:8] == b"\x89PNG\r\n\x1a\n", "png: signature")
    pos, idat, types = 8, b"", []
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        ctype, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        check(zlib.crc32(ctype + body) & 0xFFFFFFFF == crc, "png: CRC of %r" % ctype)
        types.append(ctype)
        if ctype == b"IHDR":
            w, h, depth, colour, comp, filt, lace = struct.unpack(">IIBBBBB", body)
            check((depth, colour, comp, filt, lace) == (8, 0, 0, 0, 0), "png: 8-bit grey")
        elif ctype == b"IDAT":
            idat += body
        pos += 12 + length
    check(types[0] == b"IHDR" and types[-1] == b"IEND" and b"IDAT" in types, "png: chunks")
    raw = zlib.decompress(idat)  # checks the Adler-32 too
    check(len(raw) == h * (w + 1), "png: %d bytes decompressed, %d expected" % (len(raw), h * (w + 1)))
    rows, prev = [], bytearray(w)
    for y in range(h):
        kind, line = raw[y * (w + 1)], bytearray(raw[y * (w + 1) + 1:(y + 1) * (w + 1)])
        check(kind in (0, 1, 2, 3, 4), "png: filter type %d" % kind)
        for x in range(w):
            a = line[x - 1] if x else 0
            b, c = prev[x], prev[x - 1] if x else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, rows


def check_png(path, ref_path, x0, y0, x1, y1, width, height):
    ref = read_txt(ref_path)
    x0, y0, x1, y1 = (float(v) for v in (x0, y0, x1, y1))
    w, h, rows = decode_png(path)
    check((w, h) == (int(width), int(height)), "png: %dx%d, expected %sx%s" % (w, h, width, height))
    white = sum(row.count(255) for row in rows)
    check(white > 0.5 * w * h, "png: a white background (%d of %d pixels white)" % (white, w * h))
    for x, y, *_ in ref:
        # Row 0 is the top (y1): y grows upwards.
        px = min(int((x - x0) / (x1 - x0) * w), w - 1)
        py = min(int((y1 - y) / (y1 - y0) * h), h - 1)
        check(rows[py][px] < 128, "png: the pixel (%d, %d) of the point (%r, %r) is %d, not dark"
              % (px, py, x, y, rows[py][px]))


def check_spectrum_png(path, size, blue):
    w, h, rows = decode_png(path)
    size = int(size)
    check((w, h) == (size, size), "spectrum png: %dx%d" % (w, h))
    c = size // 2
    check(rows[c][c] == 255, "spectrum png: the DC term (N) is white in the centre")
    # Mean grey in two annuli, in units of the half-width (which is 2/R, or a little more).
    inner, ring = [], []
    for y in range(h):
        for x in range(w):
            rho = math.hypot(x + 0.5 - size / 2, y + 0.5 - size / 2) / (size / 2)
            if 0.03 < rho < 0.2:
                inner.append(rows[y][x])
            elif 0.42 < rho < 0.52:
                ring.append(rows[y][x])
    mi, mr = sum(inner) / len(inner), sum(ring) / len(ring)
    if blue == "1":
        check(mi + 40 < mr, "spectrum png: the low frequencies (%.0f) darker than the ring (%.0f)"
              % (mi, mr))
    else:
        check(abs(mi - mr) < 15, "spectrum png: white noise is flat (%.0f vs %.0f)" % (mi, mr))


# ---- spectrum CSV and plot ----------------------------------------------------------------

def check_spectrum_csv(path, kind, patterns):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    check(list(rows[0]) == ["frequency", "frequency_r", "power", "anisotropy_db", "samples"],
          "spectrum csv: columns %s" % list(rows[0]))
    fr = [float(r["frequency_r"]) for r in rows]
    power = [float(r["power"]) for r in rows]
    aniso = [float(r["anisotropy_db"]) for r in rows if float(r["frequency_r"]) > 0.5]
    check(fr == sorted(fr) and fr[0] > 0 and fr[-1] >= 1.9, "spectrum csv: rings from 0 to 2/R")
    low = [p for f, p in zip(fr, power) if f < 0.5]
    peak = [(p, f) for f, p in zip(fr, power) if 0.7 <= f <= 1.3]
    mean_low = sum(low) / len(low)
    top, where = max(peak)
    # Averaged over K patterns, white noise's periodogram has variance 1/K over a ring.
    white_db = -10 * math.log10(int(patterns))
    mean_aniso = sum(aniso) / len(aniso)
    check(abs(mean_aniso - white_db) < 1.5, "spectrum csv: mean anisotropy %.2f dB, expected "
          "about %.2f dB" % (mean_aniso, white_db))
    if kind == "blue":
        check(mean_low < 0.25, "blue noise: power below 0.5/R is %.3f, not far below 1" % mean_low)
        check(top > 1.3 and 0.8 <= where <= 1.15,
              "blue noise: the peak %.3f at %.2f/R, expected above 1.3 near 1/R" % (top, where))
    else:
        check(0.85 < mean_low < 1.15, "white noise: power below 0.5/R is %.3f, not about 1"
              % mean_low)
        mean_peak = sum(p for p, _ in peak) / len(peak)
        check(0.85 < mean_peak < 1.15, "white noise: power near 1/R is %.3f, not about 1"
              % mean_peak)


def check_plot(path):
    root = ET.parse(path).getroot()
    check(root.tag == NS + "svg", "plot: an SVG")
    lines = list(root.iter(NS + "polyline"))
    check(len(lines) >= 2, "plot: two curves")
    for line in lines:
        pts = line.get("points").split()
        check(len(pts) > 10, "plot: a curve of %d points" % len(pts))


# ---- --stats --------------------------------------------------------------------------------

def check_coverage(line, fields):
    """Every field a finite number, the coverage in [0, 1] ("-" where the library's free
    area cannot give it), and 1 when maximal."""
    check("nan" not in line and "inf" not in line, "stats: not finite: %s" % line)
    cov = fields["coverage"]
    if cov != "-":
        check(0.0 <= float(cov) <= 1.0, "stats: coverage %s outside [0, 1]" % cov)
    if " maximal" in line and " not maximal" not in line:
        check(cov == "1.000000000", "stats: maximal, but coverage=%s" % cov)


def field_rule_and_nn(ref):
    """For a large variable-radius pattern, what the pairwise loop of check_field_stats
    gives, through scipy's k-d tree (another method than the program's grids): the least
    d / r_i over the pairs i < j, and each point's nearest-neighbour distance over its
    radius. The rule is looked for within 2 r_i of each point i; a result under 2 is
    then exact."""
    import numpy
    from scipy.spatial import cKDTree
    pts = numpy.array([(p[0], p[1]) for p in ref])
    radii = numpy.array([p[2] for p in ref])
    tree = cKDTree(pts)
    dist, _ = tree.query(pts, k=2)
    nn = list(dist[:, 1] / radii)
    rule = math.inf
    for i, near in enumerate(tree.query_ball_point(pts, 2 * radii)):
        later = numpy.array([j for j in near if j > i], dtype=int)
        if len(later):
            d = numpy.hypot(*(pts[later] - pts[i]).T)
            rule = min(rule, float(d.min()) / radii[i])
    check(rule < 2, "stats: no pair within twice the earlier radius (rule %r)" % rule)
    return rule, nn


def check_field_stats(fields, ref, box):
    """--stats with --radius-map: in units of the points' own radii (suffix r). Areas in
    units of the domain's sides, so that a 1e300 domain's do not overflow."""
    w, h = box[2] - box[0], box[3] - box[1]
    packing = sum(math.pi * (p[2] / w) * (p[2] / h) for p in ref) / 4
    check(abs(float(fields["packing"]) - packing) < 1e-6, "stats: packing %s, expected %.6f"
          % (fields["packing"], packing))
    rule, nn = field_rule_and_nn(ref) if len(ref) > 3000 else (math.inf, [])
    for i, (x, y, ri) in enumerate(ref if len(ref) <= 3000 else []):
        best = math.inf
        for j, (u, v, rj) in enumerate(ref):
            if i != j:
                d = math.hypot(x - u, y - v)
                best = min(best, d)
                rule = min(rule, d / (ri if i < j else rj))
        nn.append(best / ri)
    check(fields["min_dist"].endswith("r") and fields["mean_nn"].endswith("r"),
          "stats: the distances in units of the radii (suffix r)")
    got_min, got_mean = float(fields["min_dist"][:-1]), float(fields["mean_nn"][:-1])
    check(abs(got_min - rule) < 1e-8, "stats: min_dist %r, brute force %.9f" % (got_min, rule))
    want_mean = sum(nn) / len(nn)
    check(abs(got_mean - want_mean) < 1e-5, "stats: mean_nn %r, brute force %.6f"
          % (got_mean, want_mean))
    check(got_min >= 1 - 1e-9, "stats: a later point inside an earlier point's disk")
    lo, hi = (float(v) for v in fields["R"].split(".."))
    check(all(lo - 1e-12 <= p[2] <= hi + 1e-12 for p in ref),
          "stats: R=%s does not hold every radius" % fields["R"])


def check_stats(stats_path, ref_path, radius, x0, y0, x1, y1, periodic):
    ref = read_txt(ref_path)
    box = [float(v) for v in (x0, y0, x1, y1)]
    with open(stats_path) as f:
        line = f.read().strip()
    fields = dict(tok.split("=", 1) for tok in line.split() if "=" in tok)
    check_coverage(line, fields)
    if radius == "map":
        return check_field_stats(fields, ref, box)
    r = float(radius)
    # Lengths in units of R, so that any scale works (a 3.2e308 side is inf in user units).
    ref = [(x / r, y / r) for x, y in ref]
    w, h = box[2] / r - box[0] / r, box[3] / r - box[1] / r
    packing = math.pi * len(ref) / (4 * w * h)
    check(abs(float(fields["packing"]) - packing) < 1e-6, "stats: packing %s, expected %.6f"
          % (fields["packing"], packing))
    nn = []
    for i, (x, y) in enumerate(ref):
        best = math.inf
        for j, (u, v) in enumerate(ref):
            if i != j:
                dx, dy = x - u, y - v
                if periodic == "1":
                    dx -= w * round(dx / w)
                    dy -= h * round(dy / h)
                best = min(best, math.hypot(dx, dy))
        nn.append(best)
    want_min, want_mean = min(nn), sum(nn) / len(nn)
    got_min = float(fields["min_dist"].rstrip("R"))
    got_mean = float(fields["mean_nn"].rstrip("R"))
    check(abs(got_min - want_min) < 1e-8, "stats: min_dist %r, brute force %.9f" % (got_min, want_min))
    check(abs(got_mean - want_mean) < 1e-5, "stats: mean_nn %r, brute force %.6f"
          % (got_mean, want_mean))
    check(got_min >= 1 - 1e-9, "stats: min_dist below R")


def write_white(out, patterns, n, seed):
    """Uniform random points in the unit square: K patterns, blank lines between."""
    rng = random.Random(int(seed))
    with open(out, "w") as f:
        for k in range(int(patterns)):
            if k:
                f.write("\n")
            for _ in range(int(n)):
                f.write("%r %r\n" % (rng.random(), rng.random()))


# ---- --radius-map ------------------------------------------------------------------------

def pgm_levels(kind, w, h):
    """The grey levels (0..255) of a test image, rows top first."""
    if kind == "hgrad":      # grey = column * 255 / (w - 1): black on the left
        return [[round(255 * i / (w - 1)) for i in range(w)] for _ in range(h)]
    if kind == "topdark":    # the upper half black, the lower half white
        return [[0 if j < h // 2 else 255 for _ in range(w)] for j in range(h)]
    if kind == "bottomdark":
        return [[255 if j < h // 2 else 0 for _ in range(w)] for j in range(h)]
    if kind == "blob":       # a dark disk off centre on a soft gradient
        return [[min(255, round(255 * (0.3 + 0.7 * i / (w - 1))
                                * min(1.0, math.hypot(i - 0.3 * w, j - 0.6 * h) / (0.25 * w))))
                 for i in range(w)] for j in range(h)]
    if kind.startswith("const"):
        return [[int(kind[5:])] * w for _ in range(h)]
    raise Failed("unknown image kind %s" % kind)


def write_pgm(out, kind, encoding, w, h):
    """A test image for --radius-map: KIND (pgm_levels) as ENCODING: p2, p5, p5-16
    (maxval 65535, two bytes per pixel: level * 257, the same greys), or p2-comments and
    p5-comments (comments in the header, and between the P2 pixels)."""
    w, h = int(w), int(h)
    rows = pgm_levels(kind, w, h)
    with open(out, "wb") as f:
        if encoding == "p2":
            f.write(b"P2\n%d %d\n255\n" % (w, h))
            for row in rows:
                f.write((" ".join(str(v) for v in row) + "\n").encode())
        elif encoding == "p2-comments":
            f.write(b"P2 # plain\n# a comment line\n%d# width\n%d\n# maxval next\n255\n" % (w, h))
            for row in rows:
                f.write((" ".join(str(v) for v in row) + " # end of a row\n").encode())
        elif encoding == "p5":
            f.write(b"P5\n%d %d\n255\n" % (w, h) + bytes(v for row in rows for v in row))
        elif encoding == "p5-comments":
            # A comment right after maxval ends with the line break that delimits
            # the raster (as Netpbm reads it); a blank there would be the delimiter.
            f.write(b"P5\n# made by output_checks.py\n%d #w\n%d\n255# maxval\n" % (w, h)
                    + bytes(v for row in rows for v in row))
        elif encoding == "p5-16":
            f.write(b"P5\n%d %d\n65535\n" % (w, h)
                    + b"".join(struct.pack(">H", 257 * v) for row in rows for v in row))
        else:
            raise Failed("unknown encoding %s" % encoding)


def check_field(ref_path, rmin, rmax, x0, y0, x1, y1, step):
    """Radii within [rmin, rmax]; the rule |p_j - p_i| >= r_i for i < j; every probe of
    a grid within r_i of some point i (the disks cover the domain: maximal)."""
    ref = read_txt(ref_path)
    rmin, rmax, step = float(rmin), float(rmax), float(step)
    x0, y0, x1, y1 = (float(v) for v in (x0, y0, x1, y1))
    check(len(ref) > 1 and all(len(p) == 3 for p in ref), "field: \"x y r\" lines")
    for x, y, r in ref:
        check(rmin <= r <= rmax, "field: radius %r outside [%r, %r]" % (r, rmin, rmax))
        check(x0 <= x <= x1 and y0 <= y <= y1, "field: (%r, %r) outside the domain" % (x, y))
    cells = {}
    for i, (x, y, r) in enumerate(ref):
        cells.setdefault((int((x - x0) // rmax), int((y - y0) // rmax)), []).append(i)

    def near(x, y):
        cx, cy = int((x - x0) // rmax), int((y - y0) // rmax)
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                yield from cells.get((cx + a, cy + b), ())

    for j, (x, y, r) in enumerate(ref):
        for i in near(x, y):
            if i < j:
                d = math.hypot(x - ref[i][0], y - ref[i][1])
                check(d >= ref[i][2], "field: point %d at %r from point %d, inside its "
                      "radius %r" % (j, d, i, ref[i][2]))
    ny, nx = int((y1 - y0) / step) + 1, int((x1 - x0) / step) + 1
    for a in range(nx):
        for b in range(ny):
            px, py = min(x1, x0 + a * step), min(y1, y0 + b * step)
            check(any(math.hypot(px - ref[i][0], py - ref[i][1]) <= ref[i][2] for i in near(px, py)),
                  "field: the probe (%r, %r) is outside every disk: not maximal" % (px, py))


def check_gradient(ref_path, rmin, rmax, w):
    """The radius of an hgrad map (black at the left) on the unit square, w = 256 columns so
    that each column's grey is its index: linear in x from the first pixel centre (rmin) to
    the last (rmax), clamped beyond."""
    ref = read_txt(ref_path)
    rmin, rmax, w = float(rmin), float(rmax), int(w)
    for x, y, r in ref:
        t = min(1.0, max(0.0, (x * w - 0.5) / (w - 1)))
        want = rmin + (rmax - rmin) * t
        check(abs(r - want) <= 1e-9 * rmax, "gradient: radius %r at x = %r, expected %r"
              % (r, x, want))


CHECKS = {
    "formats": check_formats, "svg": check_svg, "png": check_png,
    "spectrum-png": check_spectrum_png, "spectrum-csv": check_spectrum_csv,
    "plot": check_plot, "stats": check_stats, "white": write_white,
    "pgm": write_pgm, "field": check_field, "gradient": check_gradient,
}

if __name__ == "__main__":
    try:
        CHECKS[sys.argv[1]](*sys.argv[2:])
    except Failed as e:
        print("output_checks %s: %s" % (sys.argv[1], e), file=sys.stderr)
        sys.exit(1)
