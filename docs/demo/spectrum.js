// The periodogram of points in the unit square: P(k) = |sum_j exp(-2 pi i k.p_j)|^2 / N
// for integer k in [-K, K]^2, row-major from (-K, -K). Separable: the
// per-point factors along x and y come from a recurrence, N (2K+1)^2 work.
export function periodogram(xy, K) {
  const n = xy.length / 2;
  const side = 2 * K + 1;
  const re = new Float64Array(side * side);
  const im = new Float64Array(side * side);
  const ex = new Float64Array(2 * side);
  const ey = new Float64Array(2 * side);
  const fill = (e, t) => {
    const c = Math.cos(2 * Math.PI * t);
    const s = -Math.sin(2 * Math.PI * t);
    let r = 1;
    let i = 0;
    e[2 * K] = 1;
    e[2 * K + 1] = 0;
    for (let k = 1; k <= K; ++k) {
      [r, i] = [r * c - i * s, r * s + i * c];
      e[2 * (K + k)] = r;
      e[2 * (K + k) + 1] = i;
      e[2 * (K - k)] = r;
      e[2 * (K - k) + 1] = -i;
    }
  };
  for (let j = 0; j < n; ++j) {
    fill(ex, xy[2 * j]);
    fill(ey, xy[2 * j + 1]);
    for (let b = 0; b < side; ++b) {
      const yr = ey[2 * b];
      const yi = ey[2 * b + 1];
      const row = b * side;
      for (let a = 0; a < side; ++a) {
        const xr = ex[2 * a];
        const xi = ex[2 * a + 1];
        re[row + a] += xr * yr - xi * yi;
        im[row + a] += xr * yi + xi * yr;
      }
    }
  }
  const p = new Float64Array(side * side);
  for (let i = 0; i < p.length; ++i) p[i] = (re[i] * re[i] + im[i] * im[i]) / n;
  p[K * side + K] = 0;  // the DC term is n: not part of the picture
  return p;
}
