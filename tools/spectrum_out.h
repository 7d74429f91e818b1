/*
 * spectrum_out.h - what the poissondisk program writes of a spectrum
 * (spectrum.h): the periodogram as a grey-scale PNG (--spectrum), the rings
 * as CSV (--spectrum-csv) and as an SVG plot (--spectrum-plot). Plain C99.
 */
#ifndef POISSONDISK_SPECTRUM_OUT_H
#define POISSONDISK_SPECTRUM_OUT_H

#include <stddef.h>

#include "spectrum.h"

/* The grey levels of the PNG: 10 log10 P from DB_BLACK (black) to DB_WHITE (white). */
#define SPECTRUM_DB_BLACK (-20.0)
#define SPECTRUM_DB_WHITE 10.0

/*
 * The periodogram as a size x size grey-scale PNG: f = 0 in the centre, fx
 * to the right, fy upwards, |fx| and |fy| up to spectrum_fmax(); each pixel
 * shows the nearest frequency of the grid, on a log scale clipped to
 * [SPECTRUM_DB_BLACK, SPECTRUM_DB_WHITE] (the DC term, N, is white).
 * Returns 0, or -1 with errno set.
 */
int spectrum_write_png(const struct spectrum *sp, const char *path, unsigned size);

/*
 * The rings as CSV with the header
 *   frequency,frequency_r,power,anisotropy_db,samples
 * frequency in cycles per unit length, frequency_r the same times the
 * radius (so the blue-noise peak is near 1), %.17g. Returns 0 or -1.
 */
int spectrum_write_csv(const struct spectrum_ring *rings, size_t n, double radius,
                       const char *path);

/*
 * The rings as an SVG plot: the radially averaged power (white noise: 1)
 * above and the anisotropy in dB (white noise: -10 log10 patterns) below,
 * against the frequency times the radius. Returns 0 or -1.
 */
int spectrum_write_plot(const struct spectrum_ring *rings, size_t n, double radius,
                        unsigned patterns, const char *path);

#endif /* POISSONDISK_SPECTRUM_OUT_H */
