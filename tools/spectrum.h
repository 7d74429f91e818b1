/*
 * spectrum.h - the periodogram of point patterns, averaged over patterns,
 * and its radial average and anisotropy (Ulichney, Digital Halftoning, 1987;
 * the spectra of Jones 2006, figure 6).
 *
 * For a pattern of N points x_j in the domain [x0,x0+W]x[y0,y0+H] and a
 * frequency f = (k/W, l/H), k and l integers (the harmonics of the domain:
 * for the unit square the integer grid),
 *
 *     P(f) = |sum_j exp(-2 pi i f.(x_j - x0))|^2 / N,
 *
 * so that P is about 1 everywhere but at f = 0 (where it is N) for white
 * noise, whatever N. A blue-noise pattern has P far below 1 at low
 * frequencies and a ring above 1 near |f| = 1/R. On the torus these are the
 * torus's own frequencies, which is why periodic patterns give clean
 * spectra; a pattern in a plain rectangle adds a little of its boundary.
 *
 * The sum is separable: exp(-2 pi i f.x) = exp(-2 pi i k u) exp(-2 pi i l v)
 * with u = (x - x0)/W, v = (y - y0)/H. Each point gets two 1-D tables of
 * phasors (cos and sin once per table entry), and the grid of sums is
 * their outer product added up over the points: N (2K+1)(L+1) complex
 * multiply-adds for |k| <= K, 0 <= l <= L, the other half being the
 * complex conjugate (P(-f) = P(f)). The cost grows as N^2: see the
 * poissondisk(1) manual. Plain C99 with <math.h>.
 */
#ifndef POISSONDISK_SPECTRUM_H
#define POISSONDISK_SPECTRUM_H

#include <stddef.h>

#define SPECTRUM_MAX_HALF 512 /* the most frequency steps on each side of 0, per axis */

struct spectrum {
    double x0, y0, w, h;  /* the domain */
    int kmax, lmax;       /* the grid: -kmax <= k <= kmax, 0 <= l <= lmax */
    double *sre, *sim;    /* the current pattern's sums, (2 kmax + 1) x (lmax + 1) */
    double *power;        /* the sum of P over the finished patterns, same layout */
    double *tab;          /* per-point phasor tables (a block of points) */
    size_t npoints;       /* points added to the current pattern */
    unsigned patterns;    /* finished patterns with at least one point */
};

/*
 * Prepares a spectrum of the domain box (x0 y0 x1 y1) up to the frequency
 * fmax (cycles per unit length) along each axis: kmax = ceil(fmax W) and
 * lmax = ceil(fmax H), each at most SPECTRUM_MAX_HALF. Returns 0, or -1
 * when out of memory.
 */
int spectrum_init(struct spectrum *sp, const double box[4], double fmax);
void spectrum_free(struct spectrum *sp);

/* Adds n points (x,y interleaved) to the current pattern; call as often as needed. */
void spectrum_add(struct spectrum *sp, const double *xy, size_t n);

/* Ends the current pattern: adds its P to the average (an empty one is skipped). */
void spectrum_end_pattern(struct spectrum *sp);

/* The averaged P at f = (k/W, l/H), |k| <= kmax, |l| <= lmax; 0 before any pattern. */
double spectrum_power(const struct spectrum *sp, int k, int l);

/* The largest |f| whose whole circle lies in the grid: min(kmax/W, lmax/H). */
double spectrum_fmax(const struct spectrum *sp);

/*
 * One ring of the radial average: the frequencies with |f| within half a
 * step of f, the step being max(1/W, 1/H) (1 for the unit square).
 * anisotropy_db is 10 log10(variance / mean^2) of P over the ring (unbiased
 * variance; NaN for a ring of one sample): about -10 log10(K) dB for white
 * noise averaged over K patterns.
 */
struct spectrum_ring {
    double f;
    double power;
    double anisotropy_db;
    size_t samples;
};

/*
 * The rings from one step up to spectrum_fmax() (the DC term is left out):
 * returns their number, and in *rings an array the caller frees (NULL and 0
 * when out of memory or with no ring).
 */
size_t spectrum_rings(const struct spectrum *sp, struct spectrum_ring **rings);

#endif /* POISSONDISK_SPECTRUM_H */
