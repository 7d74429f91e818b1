// The WebAssembly build gives the native library's points, byte for byte.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Sampler, poissonDisk } from '../src/index.js';
import { bytesOf, cliPoints, writePgm, writePolygon } from './cli.js';

function sameBytes(actual, expected, what) {
  const a = bytesOf(actual);
  assert.ok(expected.length > 0, `${what}: the CLI wrote no points`);
  assert.equal(a.length, expected.length, `${what}: ${a.length / 16} points, the CLI ${expected.length / 16}`);
  const first = a.findIndex((v, i) => v !== expected[i]);
  assert.equal(first, -1, `${what}: first differing byte at ${first} (point ${Math.floor(first / 16)})`);
}

test('rectangle: the points of the CLI', async () => {
  const pts = await poissonDisk(0.013, { seed: 7, bounds: [-1, -0.5, 1.5, 1] });
  sameBytes(pts, cliPoints(['--radius', '0.013', '--seed', '7', '--domain', '-1', '-0.5', '1.5', '1']), 'rectangle');
});

test('a 64-bit seed beyond 2**53', async () => {
  const seed = 18446744073709551557n;
  const pts = await poissonDisk(0.02, { seed });
  sameBytes(pts, cliPoints(['--radius', '0.02', '--seed', seed.toString()]), 'seed 2**64-59');
});

test('torus: the points of the CLI', async () => {
  const pts = await poissonDisk(0.02, { seed: 11, periodic: true, bounds: [0, 0, 2, 1] });
  sameBytes(pts, cliPoints(['--radius', '0.02', '--seed', '11', '--periodic', '--domain', '0', '0', '2', '1']), 'torus');
});

test('count: the points of the CLI, exactly n', async () => {
  const pts = await poissonDisk(null, { seed: 5, count: 3000 });
  assert.equal(pts.length, 6000);
  sameBytes(pts, cliPoints(['--count', '3000', '--seed', '5']), 'count');
});

test('refine: the points of the CLI', async () => {
  const s = await Sampler.create(0.03, { seed: 9 });
  assert.equal(s.run(), true);
  s.refine(0.015);
  assert.equal(s.run(), true);
  sameBytes(s.points(), cliPoints(['--radius', '0.03', '--refine', '0.015', '--seed', '9']), 'refine');
  s.dispose();
});

test('radius map from grey levels: the points of the CLI --radius-map', async () => {
  const width = 23;
  const height = 17;
  const grey = new Uint8Array(width * height).map((_, i) => ((i % width) * 11 + Math.floor(i / width) * 5) % 256);
  const path = writePgm(width, height, grey);
  const pts = await poissonDisk(null, { seed: 3, radiusMap: { width, height, grey, rmin: 0.006, rmax: 0.03 } });
  sameBytes(pts, cliPoints(['--radius-map', path, '--rmin', '0.006', '--rmax', '0.03', '--seed', '3']), 'radius map');
});

test('polygon with a hole: the points of the CLI', async () => {
  const rings = [[[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], [[0.2, 0.2], [0.6, 0.2], [0.4, 0.6]]];
  const pts = await poissonDisk(0.02, { seed: 4, polygon: rings });
  sameBytes(pts, cliPoints(['--polygon', writePolygon(rings), '--radius', '0.02', '--seed', '4']), 'polygon');
});

// Over the islands' box the dart grid has 1.8e9 cells (300 apart) and 2.0e10
// (1000 apart): more than a 32-bit size_t counts, numbered alike all the same.
for (const apart of [300, 1000]) {
  test(`islands ${apart} apart: the points of the CLI`, async () => {
    const a = [[0, 0], [1, 0], [1, 1], [0, 1]];
    const rings = [a, a.map(([x, y]) => [x + apart, y + apart])];
    const pts = await poissonDisk(0.01, { seed: 3, polygon: rings });
    sameBytes(pts, cliPoints(['--polygon', writePolygon(rings), '--radius', '0.01', '--seed', '3']), `${apart} apart`);
  });
}

test('radius map over a thin ring: the points of the CLI', async () => {
  // 64-gons of radius 1 and 0.98: the field's darts come from the ring's raster.
  const outer = Array.from({ length: 64 }, (_, k) => [Math.cos((k * Math.PI) / 32), Math.sin((k * Math.PI) / 32)]);
  const rings = [outer, outer.map(([x, y]) => [0.98 * x, 0.98 * y])];
  const grey = new Uint8Array([0, 255]);
  const pts = await poissonDisk(null, { seed: 2, polygon: rings, radiusMap: { width: 2, height: 1, grey, rmin: 0.004, rmax: 0.008 } });
  sameBytes(pts, cliPoints(['--polygon', writePolygon(rings), '--radius-map', writePgm(2, 1, grey), '--rmin', '0.004',
    '--rmax', '0.008', '--seed', '2']), 'radius map over a ring');
});

test('mask and fixed points: the points of the CLI --mask --fixed', async () => {
  const width = 40;
  const height = 30;
  // Grey levels, top row first (the PGM's order): a dark disk and a dark bar.
  const grey = new Uint8Array(width * height).map((_, k) => {
    const i = k % width;
    const j = Math.floor(k / width);
    return (i - 14) ** 2 + (j - 12) ** 2 < 100 || (j > 22 && i > 5) ? 20 : 230;
  });
  const inside = grey.map((g) => (g < 128 ? 1 : 0));  // top row first too
  const fixed = [[1.0, 1.0, 0.2], [1.5, 0.3], [2.2, 0.2, 0.05]];
  const dir = mkdtempSync(join(tmpdir(), 'poissondisk-js-'));
  const fixedPath = join(dir, 'fixed.txt');
  writeFileSync(fixedPath, fixed.map((f) => f.join(' ')).join('\n') + '\n');
  const pts = await poissonDisk(0.03, { seed: 6, bounds: [0, 0, 4, 3], mask: { width, height, inside }, fixed });
  sameBytes(pts, cliPoints(['--mask', writePgm(width, height, grey), '--domain', '0', '0', '4', '3', '--fixed', fixedPath,
    '--radius', '0.03', '--seed', '6']), 'mask and fixed points');
});

test('a bounded run in a rectangle 10^6 R wide: the points of the CLI --max-points', async () => {
  const s = await Sampler.create(0.01, { seed: 8, bounds: [0, 0, 1e4, 1e4] });
  assert.equal(s.run(3000), false);
  sameBytes(s.points(), cliPoints(['--domain', '0', '0', '1e4', '1e4', '--radius', '0.01', '--seed', '8',
    '--max-points', '3000', '--partial']), 'bounded run');
  s.dispose();
});

test('the same points however the run is split (steps, batches, runAsync)', async () => {
  const whole = await poissonDisk(0.02, { seed: 21 });
  const a = await Sampler.create(0.02, { seed: 21 });
  while (a.step()) { /* one point at a time */ }
  sameBytes(a.points(), bytesOf(whole), 'steps');
  const b = await Sampler.create(0.02, { seed: 21 });
  while (!b.run(97)) { /* batches */ }
  sameBytes(b.points(), bytesOf(whole), 'batches');
  const c = await Sampler.create(0.02, { seed: 21 });
  assert.equal(await c.runAsync({ sliceMs: 0 }), true);
  sameBytes(c.points(), bytesOf(whole), 'runAsync');
  for (const s of [a, b, c]) s.dispose();
});

test('maximal, and verify() says so; freeArea falls to 0', async () => {
  const s = await Sampler.create(0.01, { seed: 2 });
  assert.equal(s.freeArea, 1);
  s.run(500);
  assert.equal(s.verify(), false, 'room is left after 500 points');
  assert.ok(s.freeArea > 0);
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  assert.equal(s.freeArea, 0);
  const r = s.radii();
  assert.equal(r.length, s.count);
  assert.ok(r.every((v) => v === 0.01));
  s.dispose();
});

test('a rectangle far thinner than R: the free area is the width times the free length', async () => {
  const w = 1e-200, r = 0.01;
  const s = await Sampler.create(r, { seed: 5, bounds: [0, 0, w, 1] });
  for (let n = 1; n <= 20; n++) {
    s.run(1);
    const ys = [];
    const pts = s.points();
    for (let i = 1; i < pts.length; i += 2) ys.push(pts[i]);
    ys.sort((a, b) => a - b);
    let covered = 0, hi = 0;
    for (const y of ys) {
      const a = Math.max(y - r, hi), b = Math.min(y + r, 1);
      covered += Math.max(b - a, 0);
      hi = Math.max(hi, b);
    }
    assert.ok(Math.abs(s.freeArea / w - (1 - covered)) < 1e-9, `${n} points: free area ${s.freeArea}`);
  }
  assert.equal(s.run(), true);
  assert.equal(s.freeArea, 0);
  assert.equal(s.verify(), true);
  s.dispose();
});
