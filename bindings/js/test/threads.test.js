// The threads option: checked, passed to pds_set_threads, read back, and never
// changing the points (the WebAssembly build has one thread, so not the speed
// either). The native CLI's points at --threads 4 are the same bytes too.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { Sampler, StateError, poissonDisk } from '../src/index.js';
import { bytesOf, cliPoints } from './cli.js';

function sameBytes(actual, expected, what) {
  const a = bytesOf(actual);
  const b = expected instanceof Uint8Array ? expected : bytesOf(expected);
  assert.ok(b.length > 0, `${what}: no points`);
  assert.equal(a.length, b.length, `${what}: ${a.length / 16} points against ${b.length / 16}`);
  const first = a.findIndex((v, i) => v !== b[i]);
  assert.equal(first, -1, `${what}: first differing byte at ${first} (point ${Math.floor(first / 16)})`);
}

const MODES = {
  rectangle: [0.01, { bounds: [0, 0, 2, 1] }],
  count: [null, { count: 3000 }],
  torus: [0.01, { periodic: true }],
};

test('threads 1 and 4 give the same points', async () => {
  for (const [name, [radius, options]] of Object.entries(MODES)) {
    const one = await poissonDisk(radius, { ...options, seed: 3, threads: 1 });
    const four = await poissonDisk(radius, { ...options, seed: 3, threads: 4 });
    sameBytes(four, one, `${name}: threads 4 against 1`);
    sameBytes(await poissonDisk(radius, { ...options, seed: 3 }), one, `${name}: the default against 1`);
  }
  sameBytes(await poissonDisk(0.01, { seed: 3, bounds: [0, 0, 2, 1], threads: 4 }),
    cliPoints(['--radius', '0.01', '--seed', '3', '--domain', '0', '0', '2', '1', '--threads', '4']),
    'threads 4 against the native CLI at --threads 4');
});

test('the count reads back and may change between runs', async () => {
  const ref = await poissonDisk(0.01, { seed: 5 });
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
