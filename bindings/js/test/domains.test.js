// The polygon, mask and fixed options: points inside, spacing, clearances and
// coverage recomputed from the coordinates (regions.js), GeoJSON input, the
// mask's row order, and the errors with the library's message.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { InvalidArgumentError, Sampler, poissonDisk } from '../src/index.js';
import {
  clearanceBroken, closestPair, gridProbes, inMask, inPolygon, outlineProbes, pairs, uncovered,
} from './regions.js';

// A non-convex outline (an L) with a square hole.
const OUTER = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]];
const HOLE = [[0.2, 0.2], [0.6, 0.2], [0.6, 0.6], [0.2, 0.6]];
const closed = (ring) => [...ring, ring[0]];

function checkPattern(xy, rings, radius, fixed = []) {
  const pts = pairs(xy);
  assert.ok(pts.length > 0);
  const outside = pts.find(([x, y]) => !inPolygon(x, y, rings));
  assert.equal(outside, undefined, `${outside} lies outside the polygon`);
  assert.ok(closestPair(pts) >= radius, 'every pair at least R apart');
  const xs = rings.flat().map((v) => v[0]);
  const ys = rings.flat().map((v) => v[1]);
  const box = [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
  const probes = [...gridProbes(box, radius / 3, (x, y) => inPolygon(x, y, rings)), ...outlineProbes(rings, radius / 3)];
  assert.equal(uncovered(pts, radius, probes, fixed), null, 'every probe of the domain covered');
}

test('polygon with a hole: inside, R apart, maximal; bounds is its bounding box', async () => {
  const s = await Sampler.create(0.06, { seed: 3, polygon: [OUTER, HOLE] });
  assert.deepEqual(s.bounds, [0, 0, 2, 2]);
  assert.ok(Math.abs(s.freeArea - (3 - 0.16)) < 1e-9, `free area ${s.freeArea} is the polygon's`);
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  checkPattern(s.points(), [OUTER, HOLE], 0.06);
  assert.ok(!pairs(s.points()).some(([x, y]) => x > 0.2 && x < 0.6 && y > 0.2 && y < 0.6), 'none in the hole');
  s.dispose();
});

test('rings meeting at corners a few ulps apart: merged, the area is the square less the hole, maximal', async () => {
  // The hole's corners lie 5 to 18 ulps off the square's sides.
  const square = [[-3.5, -3.5], [-2.5, -3.5], [-2.5, -2.5], [-3.5, -2.5]];
  const hole = [[-3.500000000000016, -3.500000000000007], [-3.5000000000000133, -2.9999999999999867],
    [-2.8999999999999946, -3.0000000000000133], [-2.9000000000000106, -3.499999999999983]];
  const s = await Sampler.create(0.02, { seed: 1, polygon: [square, hole] });
  assert.ok(Math.abs(s.freeArea - 0.7) < 1e-12, `free area ${s.freeArea}, 0.7 expected`);
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const pts = pairs(s.points());
  assert.ok(pts.length > 1000);
  assert.ok(!pts.some(([x, y]) => x > -3.5 + 1e-12 && x < -2.9 - 1e-12 && y > -3.5 + 1e-12 && y < -3.0 - 1e-12), 'none in the hole');
  s.dispose();
});

for (const apart of [300, 1000]) {
  test(`islands ${apart} apart: memory and time for the islands, not their box`, async () => {
    // Two unit squares: a grid over their whole box would take 15 GB at this
    // radius (300 apart), and its cells outnumber a 32-bit size_t (1000 apart).
    const a = [[0, 0], [1, 0], [1, 1], [0, 1]];
    const b = a.map(([x, y]) => [x + apart, y + apart]);
    const s = await Sampler.create(0.01, { seed: 3, polygon: [a, b] });
    assert.ok(Math.abs(s.freeArea - 2) < 1e-12, `free area ${s.freeArea}, 2 expected`);
    assert.equal(s.run(), true);
    assert.equal(s.verify(), true);
    const pts = pairs(s.points());
    const near = pts.filter(([x]) => x < apart / 2);
    assert.ok(near.length > 5000 && pts.length - near.length > 5000, `${near.length} and ${pts.length - near.length} points`);
    assert.ok(near.every(([x, y]) => x >= 0 && x <= 1 && y >= 0 && y <= 1));
    assert.ok(pts.every(([x, y]) => x < apart / 2 || (x >= apart && x <= apart + 1 && y >= apart && y <= apart + 1)));
    s.dispose();
  });
}

test('a strip far thinner than the outline grid\'s cells: its first point at once, maximal', async () => {
  // 1e-12 high along the diagonal of the unit square.
  const strip = [[0, 0], [1, 1], [1, 1 + 1e-12], [0, 1e-12]];
  const s = await Sampler.create(0.01, { seed: 5, polygon: [strip] });
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const pts = pairs(s.points());
  assert.ok(pts.length > 70 && pts.length <= 143, `${pts.length} points`);
  assert.ok(pts.every(([x, y]) => x >= 0 && x <= 1 && y >= x && y <= x + 1.001e-12));
  s.dispose();
});

test('rings as pairs, as flat numbers, one ring alone, GeoJSON: the same points', async () => {
  const rings = [closed(OUTER), closed(HOLE)];
  const a = await poissonDisk(0.06, { seed: 6, polygon: rings });
  const flat = rings.map((ring) => Float64Array.from(ring.flat()));
  assert.deepEqual(await poissonDisk(0.06, { seed: 6, polygon: flat }), a);
  const geometry = { type: 'Polygon', coordinates: rings };
  assert.deepEqual(await poissonDisk(0.06, { seed: 6, polygon: geometry }), a);
  const feature = { type: 'Feature', properties: {}, geometry: { type: 'Polygon', coordinates: rings.map((r) => r.map(([x, y]) => [x, y, 7])) } };
  assert.deepEqual(await poissonDisk(0.06, { seed: 6, polygon: feature }), a, 'a z coordinate is dropped');
  const one = await poissonDisk(0.06, { seed: 6, polygon: OUTER });
  assert.deepEqual(one, await poissonDisk(0.06, { seed: 6, polygon: [OUTER] }));
});

test('MultiPolygon and FeatureCollection: both parts filled, nothing between', async () => {
  const a = [[0, 0], [1, 0], [1, 1], [0, 1]];
  const b = [[2, 0.5], [3, 0.5], [3, 1.5], [2, 1.5]];
  const multi = { type: 'MultiPolygon', coordinates: [[closed(a)], [closed(b)]] };
  const fc = {
    type: 'FeatureCollection',
    features: [a, b].map((r) => ({ type: 'Feature', properties: null, geometry: { type: 'Polygon', coordinates: [closed(r)] } })),
  };
  const s = await Sampler.create(0.1, { seed: 1, polygon: multi });
  assert.deepEqual(s.bounds, [0, 0, 3, 1.5]);
  s.run();
  const pts = pairs(s.points());
  assert.deepEqual(s.points(), await poissonDisk(0.1, { seed: 1, polygon: fc }));
  assert.ok(pts.every(([x, y]) => inPolygon(x, y, [a]) || inPolygon(x, y, [b])));
  assert.ok(pts.some(([x]) => x < 1) && pts.some(([x]) => x > 2));
  s.dispose();
});

test('count and split runs in a polygon', async () => {
  const xy = await poissonDisk(null, { seed: 4, count: 300, polygon: [OUTER, HOLE] });
  assert.equal(xy.length, 600);
  assert.ok(pairs(xy).every(([x, y]) => inPolygon(x, y, [OUTER, HOLE])));
  const whole = await poissonDisk(0.06, { seed: 8, polygon: [OUTER, HOLE], fixed: [[0.1, 1.5, 0.25]] });
  const s = await Sampler.create(0.06, { seed: 8, polygon: [OUTER, HOLE], fixed: [[0.1, 1.5, 0.25]] });
  while (!s.run(37)) { /* batches */ }
  assert.deepEqual(s.points(), whole);
  s.dispose();
});

// An L of pixels, top row first: the left column and the BOTTOM row.
const L_MASK = [[1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0], [1, 1, 1, 1]];
const MASK_BOX = [0, 0, 4, 4];

test('mask: rows top first, points only in its pixels, maximal', async () => {
  const s = await Sampler.create(0.15, { seed: 9, mask: L_MASK, bounds: MASK_BOX });
  assert.ok(Math.abs(s.freeArea - 7) < 1e-9);
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const pts = pairs(s.points());
  s.dispose();
  assert.equal(pts.find(([x, y]) => !inMask(x, y, L_MASK, MASK_BOX)), undefined, 'only in inside pixels');
  assert.ok(pts.some(([x, y]) => x > 3 && y < 1), 'the last row lies along y0');
  assert.ok(closestPair(pts) >= 0.15);
  const probes = gridProbes(MASK_BOX, 0.05, (x, y) => inMask(x, y, L_MASK, MASK_BOX));
  assert.equal(uncovered(pts, 0.15, probes), null);
  const flat = { width: 4, height: 4, inside: Uint8Array.from(L_MASK.flat()) };
  const bools = L_MASK.map((row) => row.map(Boolean));
  const a = await poissonDisk(0.2, { seed: 4, mask: L_MASK, bounds: MASK_BOX });
  assert.deepEqual(await poissonDisk(0.2, { seed: 4, mask: flat, bounds: MASK_BOX }), a);
  assert.deepEqual(await poissonDisk(0.2, { seed: 4, mask: bools, bounds: MASK_BOX }), a);
});

const FIXED = [[0.5, 0.5, 0.3], [0.1, 0.1, 0], [0.9, 0.15, 0.02], [0.95, 0.95, 0]];

test('fixed points: clearances kept, not returned, counted for coverage', async () => {
  const s = await Sampler.create(0.05, { seed: 7, fixed: FIXED });
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const xy = s.points();
  assert.equal(xy.length, 2 * s.count);
  s.dispose();
  const pts = pairs(xy);
  assert.equal(clearanceBroken(pts, FIXED, 0.05), null);
  assert.ok(!pts.some(([x, y]) => FIXED.some((f) => f[0] === x && f[1] === y)), 'fixed points are not returned');
  assert.ok(closestPair(pts) >= 0.05);
  assert.equal(uncovered(pts, 0.05, gridProbes([0, 0, 1, 1], 0.02, () => true), FIXED), null);
});

test('fixed points on one line, one inside another\'s clearance: maximal, verified', async () => {
  // Weighted, the point at 0.67 is hidden between its neighbours on the line.
  const fixed = [[0.67, 0.5, 0.0155], [0.669, 0.5, 0.0418], [0.8, 0.5, 0.0162]];
  const s = await Sampler.create(0.036, { seed: 1, fixed });
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const pts = pairs(s.points());
  s.dispose();
  assert.equal(clearanceBroken(pts, fixed, 0.036), null);
});

test('count past a clearance that covers the square at the first radius', async () => {
  // The n-th point ends the run, maximal or not at the last radius (a
  // corner may be left free); verify throws on a pattern that breaks a rule.
  const s = await Sampler.create(null, { seed: 4, count: 3, fixed: [[0.5, 0.5, 1.0]] });
  assert.equal(s.run(), true);
  assert.equal(s.count, 3);
  const maximal = s.verify();
  assert.ok(maximal === true || maximal === false, `verify gave ${maximal}`);
  s.dispose();
});

test('count starts from the room a clearance leaves', async () => {
  // A clearance of 0.3 takes 28% of the square: the radius goes down by a
  // step or a few, not by the 15 or more of a start from the whole square.
  for (const threads of [undefined, 2]) {
    const s = await Sampler.create(null, { seed: 1, count: 2000, fixed: [[0.5, 0.5, 0.3]], threads });
    assert.equal(s.step(), true);
    const start = s.radius;
    assert.equal(s.run(), true);
    assert.equal(s.count, 2000);
    assert.ok(s.radius < start && s.radius > 0.96 * start, `${start} -> ${s.radius}`);
    s.dispose();
  }
});

test('fixed points on a mask\'s pixel lines (within rounding of its box) are inside', async () => {
  const x1 = 0.00493827156, y1 = 0.0125663704, w = 3, h = 5;
  const mask = [[0, 0, 0], [0, 0, 0], [0, 1, 1], [0, 0, 0], [0, 0, 0]];
  const fixed = [[x1 * 1 / w, y1 * 2 / h], [x1 * 3 / w, y1 * 2 / h], [x1 * 3 / w, y1 * 3 / h], [x1 * 1 / w, y1 * 3 / h]];
  const s = await Sampler.create(x1 / w / 10, { seed: 1, mask, bounds: [0, 0, x1, y1], fixed });
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  s.dispose();
});

test('a clearance that covers the square leaves no point, maximal and verified', async () => {
  const s = await Sampler.create(0.05, { seed: 4, fixed: [[0.5, 0.5, 1.0]] });
  assert.equal(s.run(), true);
  assert.equal(s.count, 0);
  assert.equal(s.verify(), true);
  assert.equal(s.freeArea, 0);
  s.dispose();
});

test('a fixed point given twice counts once, with the larger clearance', async () => {
  const twice = await poissonDisk(0.03, { seed: 2, fixed: [[0.3, 0.4, 0.05], [0.6, 0.6, 0], [0.3, 0.4, 0.1]] });
  const once = await poissonDisk(0.03, { seed: 2, fixed: [[0.6, 0.6, 0], [0.3, 0.4, 0.1]] });
  assert.deepEqual(Array.from(twice), Array.from(once));
  assert.ok(twice.length > 100);
});

test('fixed points: every form gives the same points; 0 or none means the radius', async () => {
  const xy = FIXED.map(([x, y]) => [x, y]);
  const a = await poissonDisk(0.05, { seed: 2, fixed: xy });
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: Float64Array.from(xy.flat()) }), a);
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: xy.map(([x, y]) => [x, y, 0]) }), a);
  const mixed = FIXED.map((f) => (f[2] === 0 ? [f[0], f[1]] : f));  // [x, y] rows have clearance 0
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: mixed }), await poissonDisk(0.05, { seed: 2, fixed: FIXED }));
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: { points: xy.flat(), clearances: [0, 0, 0, 0] } }), a);
  const c = await poissonDisk(0.05, { seed: 2, fixed: FIXED });
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: { points: xy, clearances: FIXED.map((f) => f[2]) } }), c);
  assert.deepEqual(await poissonDisk(0.05, { seed: 2, fixed: [] }), await poissonDisk(0.05, { seed: 2 }));
  // An earlier pattern as fixed points: the new points keep R from it.
  const first = await poissonDisk(0.1, { seed: 1 });
  const second = await poissonDisk(0.05, { seed: 1, fixed: first });
  assert.equal(clearanceBroken(pairs(second), pairs(first), 0.05), null);
});

test('errors: the library message, naming the ring, vertex or point', async () => {
  const two = [[0.2, 0.2], [0.3, 0.3]];
  await assert.rejects(Sampler.create(0.1, { polygon: [OUTER, two] }),
    (e) => e instanceof InvalidArgumentError && /pds_set_polygon/.test(e.message) && /ring 1/.test(e.message));
  await assert.rejects(Sampler.create(0.1, { polygon: [OUTER, [[0, 0], [1, NaN], [0, 1]]] }),
    (e) => e instanceof InvalidArgumentError && /ring 1/.test(e.message) && /vertex 1/.test(e.message));
  const multi = { type: 'MultiPolygon', coordinates: [[closed(OUTER)], [closed(two)]] };
  await assert.rejects(Sampler.create(0.1, { polygon: multi }),
    (e) => e instanceof InvalidArgumentError && e.message.includes('ring 1 is polygon.coordinates[1][0]'));
  for (const options of [{ polygon: [OUTER] }, { mask: L_MASK }, { fixed: [[0.5, 0.5]] }]) {
    await assert.rejects(Sampler.create(0.1, { ...options, periodic: true }), InvalidArgumentError);
  }
  await assert.rejects(Sampler.create(0.1, { mask: [[0, 0]] }),
    (e) => e instanceof InvalidArgumentError && /pds_set_mask/.test(e.message));
  await assert.rejects(Sampler.create(0.1, { fixed: [[0.5, 0.5], [0.2, NaN]] }),
    (e) => e instanceof InvalidArgumentError && /pds_set_fixed/.test(e.message) && /point 1/.test(e.libraryMessage));
  await assert.rejects(Sampler.create(0.1, { fixed: [[0.5, 0.5, -1]] }), InvalidArgumentError);
  const s = await Sampler.create(0.1, { fixed: [[2, 2]] });  // outside the bounding box
  assert.throws(() => s.run(), (e) => e instanceof InvalidArgumentError &&
    e.message.includes("fixed point 0 (2, 2) lies outside the domain's bounding box [0,1]x[0,1]"));
  assert.equal(s.count, 0);
  s.dispose();
});

test('misuse: TypeError before the library is called', async () => {
  for (const options of [
    { polygon: [OUTER], bounds: [0, 0, 2, 2] },
    { polygon: [OUTER], mask: L_MASK },
    { polygon: [0, 0, 1, 1] },
    { polygon: [] },
    { polygon: { type: 'Point', coordinates: [0, 0] } },
    { polygon: { type: 'Feature', geometry: null } },
    { polygon: [[0, 0, 1, 0, 1]] },
    { mask: [[0, 2]] },
    { mask: [[1, 0], [1]] },
    { mask: { width: 2, height: 2, inside: [1, 1, 1] } },
    { mask: [] },
    { fixed: [[1, 2, 3, 4]] },
    { fixed: [0.5] },
    { fixed: [[0.5, 0.5], [0.5]] },
    { fixed: { points: [[0.5, 0.5, 0.1]], clearances: [0.1] } },
    { fixed: { points: [0.5, 0.5], clearances: [1, 2] } },
  ]) {
    await assert.rejects(Sampler.create(0.1, options), TypeError, JSON.stringify(options));
  }
});
