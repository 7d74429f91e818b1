// The threads option: undefined (the default) never calls pds_set_threads and
// runs the single-thread process; a number selects the parallel process, whose
// points depend on the seed and settings but never on the count (the
// WebAssembly build has one thread, so not the speed either). The one-radius
// rectangle, polygon, mask, torus and fixed points and a radius map (in the
// plane and on the torus) have that process; a radius map whose largest radius
// is over 16 times its smallest runs on one thread either way. The native CLI's
// points at --threads 4 are the same bytes.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { Sampler, StateError, poissonDisk } from '../src/index.js';
import { bytesOf, cliPoints, writePgm, writePolygon } from './cli.js';

function sameBytes(actual, expected, what) {
  const a = bytesOf(actual);
  const b = expected instanceof Uint8Array ? expected : bytesOf(expected);
  assert.ok(b.length > 0, `${what}: no points`);
  assert.equal(a.length, b.length, `${what}: ${a.length / 16} points against ${b.length / 16}`);
  const first = a.findIndex((v, i) => v !== b[i]);
  assert.equal(first, -1, `${what}: first differing byte at ${first} (point ${Math.floor(first / 16)})`);
}

// An L with a square hole, and a mask (row 0 at the top) of a ring over a bar.
const L_SHAPE = [[[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]],
  [[0.3, 0.3], [0.7, 0.3], [0.7, 0.7], [0.3, 0.7]]];
const MASK = [[1, 1, 1, 1, 0, 0, 0, 0], [1, 0, 0, 1, 0, 0, 0, 0], [1, 1, 1, 1, 1, 1, 1, 1], [1, 1, 1, 1, 1, 1, 1, 1]];
const PARALLEL = {  // the modes with a parallel process of their own
  rectangle: [0.01, { bounds: [0, 0, 2, 1] }],
  'unit square': [0.01, {}],
  count: [null, { count: 3000 }],
  polygon: [0.02, { polygon: L_SHAPE }],
  'polygon with count': [null, { polygon: L_SHAPE, count: 3000 }],
  mask: [0.02, { mask: MASK, bounds: [0, 0, 2, 1] }],
  torus: [0.01, { periodic: true }],
  'torus with count': [null, { periodic: true, bounds: [0, 0, 2, 1], count: 3000 }],
  'polygon with fixed points': [0.02, { polygon: L_SHAPE, fixed: [[0.15, 0.15], [1.5, 0.5]] }],
  'radius map': [null, { radiusMap: { width: 3, height: 2, radii: [0.008, 0.01, 0.012, 0.01, 0.012, 0.01] } }],
  'radius map on the torus': [null, {
    radiusMap: { width: 3, height: 2, radii: [0.008, 0.01, 0.012, 0.01, 0.012, 0.01] }, periodic: true,
  }],
  'radius map of 1:12': [null, { radiusMap: { width: 3, height: 2, radii: [0.003, 0.01, 0.036, 0.01, 0.036, 0.01] } }],
};
const ONE_THREAD = {  // the modes that run on one thread whatever was asked
  'radius map of 1:20 on the torus': [null, {
    radiusMap: { width: 3, height: 2, radii: [0.003, 0.01, 0.06, 0.01, 0.06, 0.01] }, periodic: true,
  }],
};

test('threads 1, 2, 4 and 8 give the same points; no threads option gives the single-thread process', async () => {
  for (const [name, [radius, options]] of Object.entries({ ...PARALLEL, ...ONE_THREAD })) {
    const one = await poissonDisk(radius, { ...options, seed: 3, threads: 1 });
    assert.ok(one.length / 2 > 1000, `${name}: ${one.length / 2} points`);
    for (const threads of [2, 4, 8]) {
      const other = await poissonDisk(radius, { ...options, seed: 3, threads });
      sameBytes(other, one, `${name}: threads ${threads} against 1`);
    }
    const single = await poissonDisk(radius, { ...options, seed: 3 });
    if (name in PARALLEL) {
      assert.notDeepEqual(bytesOf(single), bytesOf(one), `${name}: the default against threads 1`);
    } else {
      sameBytes(single, one, `${name}: the default against threads 1 (one thread either way)`);
    }
  }
  sameBytes(await poissonDisk(0.01, { seed: 3, bounds: [0, 0, 2, 1], threads: 4 }),
    cliPoints(['--radius', '0.01', '--seed', '3', '--domain', '0', '0', '2', '1', '--threads', '4']),
    'threads 4 against the native CLI at --threads 4');
  sameBytes(await poissonDisk(0.01, { seed: 3, bounds: [0, 0, 2, 1] }),
    cliPoints(['--radius', '0.01', '--seed', '3', '--domain', '0', '0', '2', '1']),
    'no threads against the native CLI without --threads');
});

test('polygon, mask and torus: threads 4 against the native CLI at --threads 4, and without threads', async () => {
  const polygon = writePolygon(L_SHAPE);
  sameBytes(await poissonDisk(0.02, { seed: 3, polygon: L_SHAPE, threads: 4 }),
    cliPoints(['--polygon', polygon, '--radius', '0.02', '--seed', '3', '--threads', '4']),
    'polygon: threads 4 against the native CLI at --threads 4');
  sameBytes(await poissonDisk(0.02, { seed: 3, polygon: L_SHAPE }),
    cliPoints(['--polygon', polygon, '--radius', '0.02', '--seed', '3']),
    'polygon: no threads against the native CLI without --threads');
  // The PGM's dark pixels are the mask's, top row first as the rows are.
  const mask = writePgm(MASK[0].length, MASK.length, MASK.flat().map((v) => (v ? 0 : 255)));
  sameBytes(await poissonDisk(0.02, { seed: 3, mask: MASK, bounds: [0, 0, 2, 1], threads: 4 }),
    cliPoints(['--mask', mask, '--domain', '0', '0', '2', '1', '--radius', '0.02', '--seed', '3', '--threads', '4']),
    'mask: threads 4 against the native CLI at --threads 4');
  sameBytes(await poissonDisk(0.02, { seed: 3, mask: MASK, bounds: [0, 0, 2, 1] }),
    cliPoints(['--mask', mask, '--domain', '0', '0', '2', '1', '--radius', '0.02', '--seed', '3']),
    'mask: no threads against the native CLI without --threads');
  sameBytes(await poissonDisk(0.01, { seed: 3, periodic: true, bounds: [0, 0, 2, 1], threads: 4 }),
    cliPoints(['--periodic', '--domain', '0', '0', '2', '1', '--radius', '0.01', '--seed', '3', '--threads', '4']),
    'torus: threads 4 against the native CLI at --threads 4');
  sameBytes(await poissonDisk(0.01, { seed: 3, periodic: true, bounds: [0, 0, 2, 1] }),
    cliPoints(['--periodic', '--domain', '0', '0', '2', '1', '--radius', '0.01', '--seed', '3']),
    'torus: no threads against the native CLI without --threads');
});

test('the count reads back and may change between runs', async () => {
  const ref = await poissonDisk(0.01, { seed: 5, threads: 1 });
  const s = await Sampler.create(0.01, { seed: 5, threads: 4 });
  assert.equal(s.threads, 4);
  const counts = [2, 0, 8, 1];
  for (let k = 0; !s.run([1, 7, 1000][k % 3]); k++) s.threads = counts[k % 4];
  sameBytes(s.points(), ref, 'runs of 1, 7 and 1000 points, the count changing between them');
  s.threads = 0;
  assert.equal(s.threads, 1, 'one per core: the WebAssembly build has one thread');
  s.dispose();
  const d = await Sampler.create(0.1, { seed: 1 });
  assert.equal(d.threads, 1, 'the default');
  d.dispose();
});

test('setting threads: before the first point it selects, after single-thread points StateError', async () => {
  const parallel = await poissonDisk(0.01, { seed: 6, threads: 1 });
  const single = await poissonDisk(0.01, { seed: 6 });
  const s = await Sampler.create(0.01, { seed: 6 });
  s.threads = 3;  // no point yet: selects the parallel process
  s.run();
  sameBytes(s.points(), parallel, 'selected by the property');
  s.dispose();
  const d = await Sampler.create(0.01, { seed: 6 });
  d.run(10);
  assert.throws(() => { d.threads = 2; }, (e) => e instanceof StateError
    && e.message.startsWith('pds_set_threads:') && e.message.includes('single-thread'));
  assert.equal(d.threads, 1);
  d.run();
  sameBytes(d.points(), single, 'the run goes on in the single-thread process');
  d.dispose();
});

test('bad counts: TypeError, nothing changed; refused from inside the progress callback', async () => {
  for (const bad of [-1, 1025, 1.5, '2', NaN, 2 ** 32 + 1]) {
    await assert.rejects(Sampler.create(0.1, { seed: 1, threads: bad }), TypeError, `threads ${bad}`);
  }
  const s = await Sampler.create(0.02, { seed: 1, threads: 3 });
  assert.throws(() => { s.threads = 1025; }, TypeError);
  assert.equal(s.threads, 3);
  let inside = null;
  s.setProgress(() => {
    if (inside === null) {
      try { s.threads = 2; inside = 'accepted'; } catch (e) { inside = e; }
    }
  });
  s.run();
  assert.ok(inside instanceof StateError, `from the callback: ${inside}`);
  assert.equal(s.threads, 3);
  s.dispose();
});
