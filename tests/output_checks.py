"""output_checks.py - judges of the poissondisk program's output files, for
tests/check-cli-output.sh. Standard library only (numpy is used for npy when
it can be imported, and the file is parsed by hand as well).

    python3 tests/output_checks.py CHECK ARGS...

Each check reads the files the program wrote, recomputes what it can from the
plain "x y" output (the reference), and exits 0 when every assertion holds,
1 after printing the first one that does not. The checks:

    formats REF.txt DIR RADIUS X0 Y0 X1 Y1 PERIODIC  DIR/p.{csv,json,bin,npy}
    svg FILE REF.txt RADIUS X0 Y0 X1 Y1 DISKS PERIODIC
    png FILE REF.txt X0 Y0 X1 Y1 WIDTH HEIGHT
    spectrum-png FILE SIZE BLUE   (BLUE 1: dark centre ring; 0: flat)
    spectrum-csv FILE KIND PATTERNS   (KIND blue or white)
    plot FILE
    stats STATS-LINE-FILE REF.txt RADIUS X0 Y0 X1 Y1 PERIODIC
    white OUT PATTERNS N SEED     writes uniform random patterns (white noise)
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

def parse_npy(data):
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
    rows, cols = meta["shape"]
    check(cols == 2, "npy: shape (N, 2)")
    body = data[10 + hlen:]
    check(len(body) == 16 * rows, "npy: %d data bytes for %d rows" % (len(body), rows))
    vals = struct.unpack("<%dd" % (2 * rows), body)
    return list(zip(vals[0::2], vals[1::2]))


def check_formats(ref_path, folder, radius, x0, y0, x1, y1, periodic):
    ref = read_txt(ref_path)
    n = len(ref)
    with open(folder + "/p.csv") as f:
        rows = list(csv.reader(f))
    check(rows[0] == ["x", "y"], "csv: header x,y")
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
    check(len(raw) == 16 * n, "bin: 16 bytes per point")
    vals = struct.unpack("<%dd" % (2 * n), raw)
    check(list(zip(vals[0::2], vals[1::2])) == ref, "bin: the same points")
    with open(folder + "/p.npy", "rb") as f:
        check(parse_npy(f.read()) == ref, "npy: the same points")
    try:
        import numpy
    except ImportError:
        numpy = None
    if numpy is not None:
        arr = numpy.load(folder + "/p.npy")
        check(arr.dtype == numpy.float64 and arr.shape == (n, 2), "numpy.load: shape")
        check([tuple(r) for r in arr.tolist()] == ref, "numpy.load: the same points")


# ---- SVG ----------------------------------------------------------------------------

NS = "{http://www.w3.org/2000/svg}"


def check_svg(path, ref_path, radius, x0, y0, x1, y1, disks, periodic):
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
    for (x, y), c in zip(ref, dots):
        # y upwards: the point (x, y) is drawn at (x, y0 + y1 - y).
        check(abs(float(c.get("cx")) - x) <= 1e-9 * (1 + abs(x))
              and abs(float(c.get("cy")) - (box[1] + box[3] - y)) <= 1e-9 * (1 + abs(y)),
              "svg: circle at (%s, %s) for the point (%r, %r)" % (c.get("cx"), c.get("cy"), x, y))
    check(("disks" in groups) == (disks == "1"), "svg: a disks group exactly with --disks")
    check(("disk-copies" in groups) == (disks == "1" and periodic == "1"),
          "svg: a disk-copies group exactly with --disks on a torus")
    if disks == "1":
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
    for x, y in ref:
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

def check_stats(stats_path, ref_path, radius, x0, y0, x1, y1, periodic):
    ref = read_txt(ref_path)
    r, box = float(radius), [float(v) for v in (x0, y0, x1, y1)]
    with open(stats_path) as f:
        line = f.read().strip()
    fields = dict(tok.split("=", 1) for tok in line.split() if "=" in tok)
    area = (box[2] - box[0]) * (box[3] - box[1])
    packing = math.pi * r * r * len(ref) / (4 * area)
    check(abs(float(fields["packing"]) - packing) < 1e-6, "stats: packing %s, expected %.6f"
          % (fields["packing"], packing))
    nn = []
    w, h = box[2] - box[0], box[3] - box[1]
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
    want_min, want_mean = min(nn) / r, sum(nn) / len(nn) / r
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


CHECKS = {
    "formats": check_formats, "svg": check_svg, "png": check_png,
    "spectrum-png": check_spectrum_png, "spectrum-csv": check_spectrum_csv,
    "plot": check_plot, "stats": check_stats, "white": write_white,
}

if __name__ == "__main__":
    try:
        CHECKS[sys.argv[1]](*sys.argv[2:])
    except Failed as e:
        print("output_checks %s: %s" % (sys.argv[1], e), file=sys.stderr)
        sys.exit(1)
