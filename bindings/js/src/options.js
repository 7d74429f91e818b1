// The options that carry arrays, converted to the flat arrays of the C API:
// a radius map (pds_set_radius_map), a polygon as rings or GeoJSON
// (pds_set_polygon), an image mask (pds_set_mask) and fixed points
// (pds_set_fixed). Shapes are checked here (TypeError); values (a NaN, a ring
// of two vertices, a negative clearance) are the library's to judge, with its
// message naming the ring, vertex or point.

// A count for a size_t argument (32-bit in wasm32), or TypeError.
export function toSize(value, name, least) {
  if (!Number.isSafeInteger(value) || value < least || value > 0xffffffff) {
    throw new TypeError(`${name} must be an integer in [${least}, 2**32), got ${value}`);
  }
  return value;
}

// A thread count for pds_set_threads: 0 (one per core) to 1024. Any count gives
// the same points (the parallel process's), and in WebAssembly the same speed:
// the build has one thread.
export function toThreads(value) {
  if (!Number.isSafeInteger(value) || value < 0 || value > 1024) {
    throw new TypeError(`threads must be an integer in [0, 1024] (0: one per core), got ${value}`);
  }
  return value;
}

// The radius map as w*h doubles, row 0 along y0: `radii` as given, or
// `grey` levels of an image (top row first, as images are stored: the top row
// lies along y1) mapped linearly from rmin (0, black) to rmax (maxval), as
// the CLI's --radius-map does.
export function radiusMapValues(map) {
  const { width, height } = map;
  toSize(width, 'radiusMap.width', 0);
  toSize(height, 'radiusMap.height', 0);
  const n = width * height;
  if (map.radii !== undefined) {
    if (map.radii.length !== n) {
      throw new TypeError(`radiusMap.radii must hold width*height = ${n} values, got ${map.radii.length}`);
    }
    return Float64Array.from(map.radii);
  }
  const { grey, rmin, rmax } = map;
  const maxval = map.maxval ?? 255;
  if (grey === undefined || grey.length !== n) {
    throw new TypeError(`radiusMap needs radii or grey, width*height = ${n} values`);
  }
  if (!(rmin > 0 && rmax >= rmin && Number.isFinite(rmax))) {
    throw new TypeError(`radiusMap with grey needs finite 0 < rmin <= rmax, got ${rmin}, ${rmax}`);
  }
  const out = new Float64Array(n);
  for (let row = 0; row < height; ++row) {
    for (let col = 0; col < width; ++col) {
      const g = grey[row * width + col];
      let r = g >= maxval ? rmax : rmin + (rmax - rmin) * (g / maxval);
      if (r > rmax) r = rmax;
      out[(height - 1 - row) * width + col] = r;
    }
  }
  return out;
}

const AREAL = ['Polygon', 'MultiPolygon', 'Feature', 'FeatureCollection', 'GeometryCollection'];

function isArrayLike(v) {
  return Array.isArray(v) || (ArrayBuffer.isView(v) && !(v instanceof DataView));
}

function show(v) {
  let text;
  try { text = JSON.stringify(v); } catch { text = String(v); }
  if (text === undefined) text = String(v);
  return text.length <= 60 ? text : `${text.slice(0, 57)}...`;
}

// A pair [x, y] (or a GeoJSON position [x, y, z...] when `position`).
function isVertex(v, position) {
  return isArrayLike(v) && typeof v[0] === 'number' && (v.length === 2 || (position && v.length > 2));
}

/**
 * A polygon as { xy: Float64Array, ends: Uint32Array, labels }. `polygon`:
 * an array of rings (each an array of [x, y] pairs or a flat ArrayLike
 * [x0, y0, x1, y1, ...]), one ring of pairs alone, or a GeoJSON Polygon,
 * MultiPolygon, Feature, FeatureCollection or GeometryCollection. labels[k]
 * says where ring k came from, for the library's messages.
 */
export function polygonArrays(polygon) {
  const rings = [];  // [label, ring, position]
  if (polygon !== null && typeof polygon === 'object' && !isArrayLike(polygon)) {
    walk(polygon, 'polygon', rings);
  } else if (isArrayLike(polygon)) {
    if (polygon.length === 0) throw new TypeError('polygon holds no ring');
    if (typeof polygon[0] === 'number') {
      throw new TypeError(`polygon is an array of rings, got the numbers ${show(polygon)} `
        + '(a ring of flat numbers goes in an array: [ring]; a rectangle is bounds)');
    }
    if (isVertex(polygon[0], false)) rings.push(['polygon', polygon, false]);  // one ring alone
    else Array.from(polygon, (ring, k) => rings.push([`polygon[${k}]`, ring, false]));
  } else {
    throw new TypeError(`polygon must be an array of rings or a GeoJSON object, got ${show(polygon)}`);
  }
  if (rings.length === 0) throw new TypeError('polygon holds no ring (an empty geometry?)');
  const parts = rings.map(([label, ring, position]) => ringXY(ring, label, position));
  const ends = new Uint32Array(parts.length);
  let total = 0;
  parts.forEach((p, k) => { total += p.length / 2; ends[k] = total; });
  const xy = new Float64Array(total * 2);
  let at = 0;
  for (const p of parts) { xy.set(p, at); at += p.length; }
  return { xy, ends, labels: rings.map(([label]) => label) };
}

function walk(geo, where, out) {
  if (geo === null || typeof geo !== 'object' || isArrayLike(geo)) {
    throw new TypeError(`${where} must be a GeoJSON object, got ${show(geo)}`);
  }
  const members = (key) => {
    const v = geo[key];
    if (!isArrayLike(v)) throw new TypeError(`${where} (a ${geo.type}) needs an array ${key}, got ${show(v)}`);
    return v;
  };
  switch (geo.type) {
    case 'Feature':
      if (geo.geometry === null || geo.geometry === undefined) throw new TypeError(`${where} is a Feature without a geometry`);
      walk(geo.geometry, `${where}.geometry`, out);
      break;
    case 'FeatureCollection':
      Array.from(members('features'), (f, i) => walk(f, `${where}.features[${i}]`, out));
      break;
    case 'GeometryCollection':
      Array.from(members('geometries'), (g, i) => walk(g, `${where}.geometries[${i}]`, out));
      break;
    case 'Polygon':
      Array.from(members('coordinates'), (ring, k) => out.push([`${where}.coordinates[${k}]`, ring, true]));
      break;
    case 'MultiPolygon':
      Array.from(members('coordinates'), (poly, i) => {
        if (!isArrayLike(poly)) throw new TypeError(`${where}.coordinates[${i}] must be an array of rings`);
        Array.from(poly, (ring, k) => out.push([`${where}.coordinates[${i}][${k}]`, ring, true]));
      });
      break;
    case 'Point': case 'MultiPoint': case 'LineString': case 'MultiLineString':
      throw new TypeError(`${where} is a ${geo.type}, which encloses no area: give a Polygon or a MultiPolygon`);
    default:
      throw new TypeError(`${where} has type ${show(geo.type)}: the polygon must be one of ${AREAL.join(', ')}`);
  }
}

// One ring as flat doubles x0, y0, x1, y1, ...
function ringXY(ring, label, position) {
  if (!isArrayLike(ring)) throw new TypeError(`${label} must be an array of [x, y] pairs, got ${show(ring)}`);
  if (ring.length > 0 && typeof ring[0] === 'number' && !position) {  // flat
    if (ring.length % 2 !== 0) throw new TypeError(`${label} holds ${ring.length} numbers, not x, y pairs`);
    return Float64Array.from(ring, Number);
  }
  const out = new Float64Array(ring.length * 2);
  for (let j = 0; j < ring.length; ++j) {
    const v = ring[j];
    if (!isVertex(v, position)) throw new TypeError(`${label}[${j}] must be an [x, y] pair, got ${show(v)}`);
    out[2 * j] = Number(v[0]);
    out[2 * j + 1] = Number(v[1]);
  }
  return out;
}

/** The library's message with where its "ring K" came from, for GeoJSON input. */
export function withRingLabel(message, labels) {
  const found = /\bring (\d+)/.exec(message);
  if (found === null) return message;
  const label = labels[Number(found[1])];
  return label !== undefined && label.includes('.') ? `${message} (ring ${found[1]} is ${label})` : message;
}

/** [x0, y0, x1, y1], the bounding box of flat x, y doubles. */
export function boundingBox(xy) {
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < xy.length; i += 2) {
    box[0] = Math.min(box[0], xy[i]);
    box[1] = Math.min(box[1], xy[i + 1]);
    box[2] = Math.max(box[2], xy[i]);
    box[3] = Math.max(box[3], xy[i + 1]);
  }
  return box;
}

/**
 * A mask as { width, height, inside: Uint8Array }, row 0 along y0 as the C
 * API takes it. `mask`: an array of rows, or { width, height, inside } with
 * inside row-major; either way the TOP row first (along y1), as images are
 * stored, and each value a boolean or 0/1.
 */
export function maskBytes(mask) {
  let width;
  let height;
  let at;
  if (isArrayLike(mask)) {
    height = mask.length;
    width = height > 0 && isArrayLike(mask[0]) ? mask[0].length : 0;
    mask.forEach((row, j) => {
      if (!isArrayLike(row) || row.length !== width) {
        throw new TypeError(`mask rows must be arrays of the same length: row 0 has ${width} values, row ${j} is ${show(row)}`);
      }
    });
    at = (j, i) => mask[j][i];
  } else if (mask !== null && typeof mask === 'object') {
    ({ width, height } = mask);
    const { inside } = mask;
    if (!Number.isSafeInteger(width) || !Number.isSafeInteger(height) || width < 0 || height < 0) {
      throw new TypeError(`mask.width and mask.height must be integers >= 0, got ${width}, ${height}`);
    }
    if (!isArrayLike(inside) || inside.length !== width * height) {
      throw new TypeError(`mask.inside must hold width*height = ${width * height} values, got ${show(inside?.length)}`);
    }
    at = (j, i) => inside[j * width + i];
  } else {
    throw new TypeError(`mask must be an array of rows or { width, height, inside }, got ${show(mask)}`);
  }
  if (width === 0 || height === 0) throw new TypeError(`mask is empty (${width} x ${height}): it needs a pixel inside`);
  const out = new Uint8Array(width * height);
  for (let j = 0; j < height; ++j) {
    const base = (height - 1 - j) * width;  // the caller's row j lies at C row height-1-j
    for (let i = 0; i < width; ++i) {
      const v = at(j, i);
      if (v === true || v === 1) out[base + i] = 1;
      else if (v !== false && v !== 0) {
        throw new TypeError(`mask values must be booleans or 0/1 (threshold the image first), got ${show(v)} at row ${j}, column ${i}`);
      }
    }
  }
  return { width, height, inside: out };
}

/**
 * Fixed points as { n, xy: Float64Array, clearances: Float64Array | null }.
 * `fixed`: flat x, y numbers (a Float64Array such as points() returns), an
 * array of [x, y] or [x, y, clearance] rows (mixed: [x, y] has clearance 0,
 * the radius), or { points, clearances } with points in either of the first
 * two forms.
 */
export function fixedArrays(fixed) {
  let points = fixed;
  let clearances = null;
  if (fixed !== null && typeof fixed === 'object' && !isArrayLike(fixed)) {
    ({ points } = fixed);
    clearances = fixed.clearances ?? null;
    if (!isArrayLike(points)) throw new TypeError(`fixed.points must be an array, got ${show(points)}`);
  } else if (!isArrayLike(fixed)) {
    throw new TypeError(`fixed must be an array of points or { points, clearances }, got ${show(fixed)}`);
  }
  let xy;
  if (points.length === 0 || typeof points[0] === 'number') {
    if (points.length % 2 !== 0) throw new TypeError(`fixed points hold ${points.length} numbers, not x, y pairs`);
    xy = Float64Array.from(points, Number);
  } else {
    const rows = Array.from(points);
    rows.forEach((row, k) => {
      if (!isArrayLike(row) || (row.length !== 2 && row.length !== 3)) {
        throw new TypeError(`fixed rows must be [x, y] or [x, y, clearance]: row ${k} is ${show(row)}`);
      }
    });
    // A row without a clearance has 0: the radius in force there.
    const withClearance = rows.some((row) => row.length === 3);
    if (withClearance && clearances !== null) throw new TypeError('give clearances once: in the rows or in fixed.clearances');
    xy = new Float64Array(rows.length * 2);
    if (withClearance) clearances = new Float64Array(rows.length);
    rows.forEach((row, k) => {
      xy[2 * k] = Number(row[0]);
      xy[2 * k + 1] = Number(row[1]);
      if (withClearance) clearances[k] = row.length === 3 ? Number(row[2]) : 0;
    });
  }
  const n = xy.length / 2;
  if (clearances !== null) {
    if (!isArrayLike(clearances) || clearances.length !== n) {
      throw new TypeError(`fixed.clearances must hold one value per point (${n}), got ${show(clearances?.length)}`);
    }
    clearances = Float64Array.from(clearances, Number);
  }
  return { n, xy, clearances };
}
