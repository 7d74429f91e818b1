// Run in a worker thread by worker.test.js: a periodic pattern, sent back.
import { parentPort, workerData } from 'node:worker_threads';
import { poissonDisk } from '../src/index.js';

const pts = await poissonDisk(workerData.radius, { seed: workerData.seed, periodic: true });
parentPort.postMessage(pts, [pts.buffer]);
