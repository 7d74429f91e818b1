// Speed at about 10^6 points in the unit square: poissondisk (WebAssembly)
// against the npm packages fast-2d-poisson-disk-sampling and
// poisson-disk-sampling (Bridson with a fixed number of tries), in one Node
// process, each run in turn, best of ROUNDS. Maximality: ours by verify()
// (exact); everyone's by probing random points for room left (a probe farther
// than R from every point proves the pattern is not maximal).
//   npm install && node bench.js [R] [ROUNDS]
import FastPoissonDiskSampling from 'fast-2d-poisson-disk-sampling';
import PoissonDiskSampling from 'poisson-disk-sampling';
import { Sampler } from '../src/index.js';

const R = Number(process.argv[2] ?? 0.000834);  // a maximal pattern then holds about 10^6 points
const ROUNDS = Number(process.argv[3] ?? 3);

// Uniform probes with a point farther than R from every sample (grid of side R).
function uncoveredProbes(xy, r, probes = 1_000_000) {
  const cells = Math.ceil(1 / r);
  const head = new Int32Array(cells * cells).fill(-1);
  const next = new Int32Array(xy.length / 2);
  const cell = (v) => Math.min(cells - 1, Math.max(0, Math.floor(v / r)));
  for (let i = 0; i < xy.length / 2; ++i) {
    const c = cell(xy[2 * i + 1]) * cells + cell(xy[2 * i]);
    next[i] = head[c];
    head[c] = i;
  }
  let state = 12345;
  const rand = () => { state = (Math.imul(state, 1664525) + 1013904223) >>> 0; return state / 2 ** 32; };
  let free = 0;
  for (let p = 0; p < probes; ++p) {
    const x = rand();
    const y = rand();
    let covered = false;
    for (let cy = cell(y) - 1; cy <= cell(y) + 1 && !covered; ++cy) {
      for (let cx = cell(x) - 1; cx <= cell(x) + 1 && !covered; ++cx) {
        if (cx < 0 || cy < 0 || cx >= cells || cy >= cells) continue;
        for (let i = head[cy * cells + cx]; i >= 0; i = next[i]) {
          const dx = xy[2 * i] - x;
          const dy = xy[2 * i + 1] - y;
          if (dx * dx + dy * dy < r * r) { covered = true; break; }
        }
      }
    }
    if (!covered) ++free;
  }
  return free;
}

const flat = (pts) => Float64Array.from(pts.flat());

const contenders = {
  async poissondisk() {
    const s = await Sampler.create(R, { seed: 1 });
    const t0 = performance.now();
    s.run();
    const ms = performance.now() - t0;
    const xy = s.points();
    const maximal = s.verify();
    s.dispose();
    return { ms, xy, maximal };
  },
  async 'fast-2d-poisson-disk-sampling'() {
    const t0 = performance.now();
    const pts = new FastPoissonDiskSampling({ shape: [1, 1], radius: R, tries: 30 }).fill();
    return { ms: performance.now() - t0, xy: flat(pts) };
  },
  async 'poisson-disk-sampling'() {
    const t0 = performance.now();
    const pts = new PoissonDiskSampling({ shape: [1, 1], minDistance: R, maxDistance: R, tries: 30 }).fill();
    return { ms: performance.now() - t0, xy: flat(pts) };
  },
};

console.log(`Node ${process.version}, R = ${R}, best of ${ROUNDS} (interleaved)`);
const best = {};
for (let round = 0; round < ROUNDS; ++round) {
  for (const [name, run] of Object.entries(contenders)) {
    const r = await run();
    if (!best[name] || r.ms < best[name].ms) best[name] = r;
  }
}
for (const [name, r] of Object.entries(best)) {
  const n = r.xy.length / 2;
  const free = uncoveredProbes(r.xy, R);
  console.log(`${name.padEnd(30)} ${String(n).padStart(8)} points ${r.ms.toFixed(0).padStart(6)} ms `
    + `${(n / r.ms / 1000).toFixed(2).padStart(6)} Mpoints/s  room left at ${free} of 10^6 probes`
    + (r.maximal === undefined ? '' : `, verify(): ${r.maximal ? 'maximal' : 'NOT maximal'}`));
}
