// Errors carry the library's message; callbacks cannot break the sampler;
// dispose() frees it and later calls are refused.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import {
  CanceledError, InvalidArgumentError, PoissonDiskError, RangeError, Sampler, StateError, poissonDisk,
} from '../src/index.js';

test('invalid arguments: InvalidArgumentError with the library message', async () => {
  await assert.rejects(Sampler.create(-1), (e) => e instanceof InvalidArgumentError
    && e instanceof PoissonDiskError && e instanceof Error && e.code === -1 && /pds_create/.test(e.message));
  await assert.rejects(Sampler.create(0.1, { bounds: [0, 0, 0, 1] }),
    (e) => e instanceof InvalidArgumentError && /pds_set_domain/.test(e.message));
  await assert.rejects(Sampler.create(null, { count: 0 }),
    (e) => e instanceof InvalidArgumentError && /pds_set_count/.test(e.message));
  await assert.rejects(Sampler.create(null, { radiusMap: { width: 1, height: 1, radii: [-1] } }),
    (e) => e instanceof InvalidArgumentError && /pds_set_radius_map/.test(e.message));
  await assert.rejects(Sampler.create(0.1, { seed: -1 }), TypeError);
  await assert.rejects(Sampler.create(0.1, { seed: 2 ** 60 }), TypeError);  // not exact: use a BigInt
});

test('no seed: a random one, read back from .seed, repeats the pattern', async () => {
  const a = await Sampler.create(0.05);
  const b = await Sampler.create(0.05);
  assert.equal(typeof a.seed, 'bigint');
  assert.notEqual(a.seed, b.seed);
  a.run();
  assert.deepEqual(await poissonDisk(0.05, { seed: a.seed }), a.points());
  a.dispose();
  b.dispose();
});

test('a radius too small for the domain: RangeError at the first point, nothing added', async () => {
  const s = await Sampler.create(1e-9, { seed: 1 });
  assert.throws(() => s.run(), (e) => e instanceof RangeError && e.code === -4 && /pds_run/.test(e.message));
  assert.equal(s.count, 0);
  s.dispose();
});

test('the library exceptions stay inside: a refused torus radius, refine in count mode', async () => {
  const t = await Sampler.create(0.6, { periodic: true });
  assert.throws(() => t.run(), RangeError);
  const c = await Sampler.create(null, { count: 10 });
  c.run();
  assert.throws(() => c.refine(0.01), StateError);
  assert.equal(c.count, 10, 'the sampler is still usable');
  t.dispose();
  c.dispose();
});

test('progress: called with counts, a true return cancels, a later run continues exactly', async () => {
  const whole = await poissonDisk(0.01, { seed: 4 });
  const seen = [];
  let stopOnce = true;
  const s = await Sampler.create(0.01, {
    seed: 4,
    progress(count, done) {
      seen.push([count, done]);
      if (stopOnce && done > 0.5) { stopOnce = false; return true; }
      return false;
    },
  });
  assert.throws(() => s.run(), CanceledError);
  assert.ok(s.count > 0 && s.count < whole.length / 2);
  assert.equal(s.run(), true);
  assert.deepEqual(s.points(), whole);
  assert.ok(seen.length > 10);
  assert.equal(seen.at(-1)[1], 1);
  s.dispose();
});

test('signal: an abort from the progress callback stops run() with CanceledError (cause: the reason)', async () => {
  const controller = new AbortController();
  const s = await Sampler.create(0.01, {
    seed: 4,
    signal: controller.signal,
    progress(count) { if (count > 1000) controller.abort(new Error('enough')); },
  });
  assert.throws(() => s.run(), (e) => e instanceof CanceledError && e.cause?.message === 'enough');
  const n = s.count;
  assert.ok(n > 1000);
  assert.throws(() => s.run(), CanceledError, 'an aborted signal refuses to start');
  assert.equal(s.count, n);
  s.dispose();
});

test('signal: aborted by a timer while runAsync yields', async () => {
  const s = await Sampler.create(0.002, { seed: 1, signal: AbortSignal.timeout(1) });
  await assert.rejects(s.runAsync({ sliceMs: 0 }), CanceledError);
  s.dispose();
});

test('a throwing progress callback: its error comes out of run(), the sampler goes on', async () => {
  const s = await Sampler.create(0.01, { seed: 4, progress() { throw new Error('from progress'); } });
  assert.throws(() => s.run(), /from progress/);
  s.setProgress(null);
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  s.dispose();
});

test('radius function: each point gets its value; out of bounds and throws are refused', async () => {
  const s = await Sampler.create((x) => 0.01 + 0.02 * x, { seed: 8, rmin: 0.01, rmax: 0.03 });
  assert.equal(s.run(), true);
  assert.equal(s.verify(), true);
  const p = s.points();
  const r = s.radii();
  for (let i = 0; i < r.length; ++i) assert.equal(r[i], 0.01 + 0.02 * p[2 * i]);
  const bad = await Sampler.create(() => 1, { rmin: 0.01, rmax: 0.03 });
  assert.throws(() => bad.run(), (e) => e instanceof InvalidArgumentError && /1/.test(e.message));
  assert.equal(bad.count, 0);
  const thrower = await Sampler.create(() => { throw new Error('no radius'); }, { rmin: 0.01, rmax: 0.03 });
  assert.throws(() => thrower.step(), /no radius/);
  for (const t of [s, bad, thrower]) t.dispose();
});

test('callbacks may read but not change or dispose the sampler', async () => {
  let s;
  const seen = [];
  s = await Sampler.create(0.01, {
    seed: 4,
    progress(count) {
      seen.push(s.points().length / 2 === count);
      assert.throws(() => s.refine(0.005), StateError);
      assert.throws(() => s.dispose(), StateError);
    },
  });
  assert.equal(s.run(), true);
  assert.ok(seen.length > 0 && seen.every(Boolean));
  s.dispose();
});

test('dispose: idempotent, later calls throw StateError, memory is returned', async () => {
  const s = await Sampler.create(0.01, { seed: 1 });
  s.run();
  s.dispose();
  s.dispose();
  assert.equal(s.disposed, true);
  assert.throws(() => s.points(), StateError);
  assert.throws(() => s.run(), StateError);
  // Many samplers created and disposed in turn: the module's memory stays flat.
  const { init } = await import('../src/wasm.js');
  const api = await init();
  for (let i = 0; i < 5; ++i) await poissonDisk(0.005, { seed: i });
  const after = api.memory.buffer.byteLength;
  for (let i = 0; i < 30; ++i) await poissonDisk(0.005, { seed: i });
  assert.equal(api.memory.buffer.byteLength, after);
});
