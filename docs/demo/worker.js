// The demo's sampler, in a Web Worker so the page stays responsive: it
// samples with the poissondisk package and computes the periodogram.
import { Sampler } from '../../bindings/js/src/index.js';
import { periodogram } from './spectrum.js';

self.onmessage = async ({ data }) => {
  try {
    const { radius, seed, periodic, count, map } = data;
    const t0 = performance.now();
    const s = await Sampler.create(count || map ? null : radius, {
      seed: BigInt(seed), periodic, count: count || undefined,
      radiusMap: map ?? undefined,
      progress: (n, done) => { self.postMessage({ progress: done, n }); },
    });
    try {
      s.run();
      const ms = performance.now() - t0;
      const points = s.points();
      const radii = s.radii();
      const maximal = count ? null : s.verify();
      // Frequencies out to about 1.3 times the ring of a maximal pattern
      // (near sqrt(N) in the unit square), at most 96 (the cost is N (2K+1)^2).
      const K = Math.max(16, Math.min(96, Math.ceil(1.3 * Math.sqrt(points.length / 2))));
      const spectrum = periodogram(points, K);
      self.postMessage({ points, radii, ms, maximal, radius: s.radius, spectrum, K },
        [points.buffer, radii.buffer, spectrum.buffer]);
    } finally {
      s.dispose();
    }
  } catch (e) {
    self.postMessage({ error: `${e.name}: ${e.message}` });
  }
};
