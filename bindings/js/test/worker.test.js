// The package works in a worker thread (its own module instance), with the
// same points as on the main thread.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { Worker } from 'node:worker_threads';
import { poissonDisk } from '../src/index.js';

test('a worker thread samples the same points', async () => {
  const worker = new Worker(new URL('./worker-main.js', import.meta.url),
    { workerData: { radius: 0.01, seed: 17 } });
  const fromWorker = await new Promise((resolve, reject) => {
    worker.once('message', resolve);
    worker.once('error', reject);
  });
  await worker.terminate();
  assert.ok(fromWorker instanceof Float64Array && fromWorker.length > 0);
  assert.deepEqual(fromWorker, await poissonDisk(0.01, { seed: 17, periodic: true }));
});
