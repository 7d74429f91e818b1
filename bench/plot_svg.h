/*
 * plot_svg.h - a small line chart with a logarithmic x axis, written as a
 * standalone SVG file (no external tools). Enough for the paper's figure 7:
 * time / (N log N) against N, one line per method.
 */
#ifndef BENCH_PLOT_SVG_H
#define BENCH_PLOT_SVG_H

#include <stddef.h>

struct plot_series {
    const char *name;  /* legend text */
    const char *color; /* any SVG colour, e.g. "#1f77b4" */
    const double *x;   /* > 0; points with x <= 0 or non-finite values are skipped */
    const double *y;
    size_t count;
};

/* Writes the chart to path. Returns 0, or -1 if the file cannot be written. */
int plot_svg_write(const char *path, const char *title, const char *x_label, const char *y_label,
                   const struct plot_series *series, size_t series_count);

#endif /* BENCH_PLOT_SVG_H */
