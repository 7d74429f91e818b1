// Domains judged from the coordinates, independently of the library: a
// closed polygon by the even-odd rule, a closed mask in the image convention
// (top row first), fixed points' clearances, spacing and coverage. Doubles
// throughout; "on the outline" within 1e-12 of an edge counts as inside.

function onSegment(px, py, ax, ay, bx, by) {
  const len = Math.hypot(bx - ax, by - ay);
  const cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return Math.abs(cross) <= 1e-12 * len
    && px >= Math.min(ax, bx) - 1e-12 && px <= Math.max(ax, bx) + 1e-12
    && py >= Math.min(ay, by) - 1e-12 && py <= Math.max(ay, by) + 1e-12;
}

/** (x, y) in the closed region of rings (arrays of [x, y]) by the even-odd rule. */
export function inPolygon(x, y, rings) {
  let odd = false;
  for (const ring of rings) {
    for (let k = 0; k < ring.length; ++k) {
      const [ax, ay] = ring[(k + ring.length - 1) % ring.length];
      const [bx, by] = ring[k];
      if (onSegment(x, y, ax, ay, bx, by)) return true;
      if ((ay > y) !== (by > y) && x < ax + ((y - ay) * (bx - ax)) / (by - ay)) odd = !odd;
    }
  }
  return odd;
}

/** (x, y) in the closed union of the true pixels; rows top first, over [x0, y0, x1, y1]. */
export function inMask(x, y, rows, [x0, y0, x1, y1]) {
  const h = rows.length;
  const w = rows[0].length;
  const u = ((x - x0) * w) / (x1 - x0);
  const v = ((y1 - y) * h) / (y1 - y0);
  const cols = [Math.floor(u), Math.ceil(u) - 1].filter((c) => c >= 0 && c < w);
  const rs = [Math.floor(v), Math.ceil(v) - 1].filter((r) => r >= 0 && r < h);
  return rs.some((r) => cols.some((c) => Boolean(rows[r][c])));
}

/** [x, y] pairs of a flat Float64Array. */
export function pairs(xy) {
  const out = [];
  for (let i = 0; i < xy.length; i += 2) out.push([xy[i], xy[i + 1]]);
  return out;
}

/** The closest pair's distance (brute force). */
export function closestPair(pts) {
  let best = Infinity;
  for (let i = 0; i < pts.length; ++i) {
    for (let j = i + 1; j < pts.length; ++j) {
      best = Math.min(best, Math.hypot(pts[i][0] - pts[j][0], pts[i][1] - pts[j][1]));
    }
  }
  return best;
}

/** The first point closer to a fixed point [x, y, clearance?] than its clearance (0: radius), or null. */
export function clearanceBroken(pts, fixed, radius) {
  for (const p of pts) {
    for (const f of fixed) {
      const c = f[2] > 0 ? f[2] : radius;
      if (Math.hypot(p[0] - f[0], p[1] - f[1]) < c) return { point: p, fixed: f };
    }
  }
  return null;
}

/** Grid points over [x0, y0, x1, y1] that keep(x, y) accepts, plus extra. */
export function gridProbes([x0, y0, x1, y1], step, keep) {
  const nx = Math.max(1, Math.round((x1 - x0) / step));
  const ny = Math.max(1, Math.round((y1 - y0) / step));
  const out = [];
  for (let a = 0; a <= nx; ++a) {
    for (let b = 0; b <= ny; ++b) {
      const x = x0 + ((x1 - x0) * a) / nx;
      const y = y0 + ((y1 - y0) * b) / ny;
      if (keep(x, y)) out.push([x, y]);
    }
  }
  return out;
}

/** Points along every edge of the rings, about step apart. */
export function outlineProbes(rings, step) {
  const out = [];
  for (const ring of rings) {
    for (let k = 0; k < ring.length; ++k) {
      const [ax, ay] = ring[(k + ring.length - 1) % ring.length];
      const [bx, by] = ring[k];
      const n = Math.max(1, Math.ceil(Math.hypot(bx - ax, by - ay) / step));
      for (let t = 0; t < n; ++t) out.push([ax + ((bx - ax) * t) / n, ay + ((by - ay) * t) / n]);
    }
  }
  return out;
}

/** The first probe farther than radius from every point and outside every clearance, or null. */
export function uncovered(pts, radius, probes, fixed = []) {
  const cells = new Map();
  const key = (i, j) => `${i},${j}`;
  for (const [x, y] of pts) {
    const k = key(Math.floor(x / radius), Math.floor(y / radius));
    if (!cells.has(k)) cells.set(k, []);
    cells.get(k).push([x, y]);
  }
  for (const [qx, qy] of probes) {
    const ci = Math.floor(qx / radius);
    const cj = Math.floor(qy / radius);
    let hit = false;
    for (let i = -1; i <= 1 && !hit; ++i) {
      for (let j = -1; j <= 1 && !hit; ++j) {
        hit = (cells.get(key(ci + i, cj + j)) ?? []).some(([x, y]) => (x - qx) ** 2 + (y - qy) ** 2 <= radius * radius);
      }
    }
    if (!hit) hit = fixed.some((f) => Math.hypot(f[0] - qx, f[1] - qy) <= (f[2] > 0 ? f[2] : radius));
    if (!hit) return [qx, qy];
  }
  return null;
}
