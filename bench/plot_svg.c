/*
 * plot_svg.c - the SVG line chart: log10 x axis with a labelled tick per decade, linear
 * y axis from 0 with 1-2-5 steps, legend on the right.
 */
#include "plot_svg.h"

#include <math.h>
#include <stdio.h>

enum { WIDTH = 760, HEIGHT = 460, LEFT = 80, RIGHT = 180, TOP = 50, BOTTOM = 60 };

struct axes {
    double decade_lo, decade_hi; /* x range in log10 */
    double y_max, y_step;
};

static int usable(double x, double y) { return isfinite(x) && isfinite(y) && x > 0.0; }

static double px_x(const struct axes *a, double x) {
    return LEFT + (WIDTH - LEFT - RIGHT) * (log10(x) - a->decade_lo) / (a->decade_hi - a->decade_lo);
}

static double px_y(const struct axes *a, double y) {
    return HEIGHT - BOTTOM - (HEIGHT - TOP - BOTTOM) * y / a->y_max;
}

/* Text goes in as character data: escape what XML reserves. */
static void put_text(FILE *f, const char *s) {
    for (; s != NULL && *s != '\0'; ++s) {
        if (*s == '<') fputs("&lt;", f);
        else if (*s == '>') fputs("&gt;", f);
        else if (*s == '&') fputs("&amp;", f);
        else fputc(*s, f);
    }
}

/* A 1, 2 or 5 times a power of ten step giving about five divisions of top. */
static double nice_step(double top) {
    double raw = top / 5.0, power = pow(10.0, floor(log10(raw))), m = raw / power;
    return power * (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0);
}

static void find_axes(struct axes *a, const struct plot_series *series, size_t series_count) {
    double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_hi = 0.0;
    size_t s, i;
    for (s = 0; s < series_count; ++s)
        for (i = 0; i < series[s].count; ++i) {
            double x = series[s].x[i], y = series[s].y[i];
            if (!usable(x, y)) continue;
            if (x < x_lo) x_lo = x;
            if (x > x_hi) x_hi = x;
            if (y > y_hi) y_hi = y;
        }
    if (x_lo > x_hi) x_lo = x_hi = 1.0; /* nothing to draw: still a valid empty chart */
    /* A fifth of a decade of margin: the end points do not sit on the frame. */
    a->decade_lo = log10(x_lo) - 0.2;
    a->decade_hi = log10(x_hi) + 0.2;
    /* At least one labelled decade. */
    if (ceil(a->decade_lo) > a->decade_hi) a->decade_lo = floor(a->decade_lo);
    if (!(y_hi > 0.0)) y_hi = 1.0;
    a->y_step = nice_step(y_hi * 1.05);
    a->y_max = a->y_step * ceil(y_hi * 1.05 / a->y_step);
}

static int y_ticks(const struct axes *a) { return (int)floor(a->y_max / a->y_step + 0.5); }

static void draw_axes(FILE *f, const struct axes *a, const char *x_label, const char *y_label) {
    double d, m;
    int k, bottom = HEIGHT - BOTTOM, right = WIDTH - RIGHT;
    fprintf(f, "<g stroke=\"#ddd\" stroke-width=\"1\">\n");
    for (d = ceil(a->decade_lo); d <= a->decade_hi; d += 1.0) {
        double x = px_x(a, pow(10.0, d));
        fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\"/>\n", x, TOP, x, bottom);
    }
    /* Tick k at k * step, not a running sum: no drift, no missing last tick. */
    for (k = 1; k <= y_ticks(a); ++k)
        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\"/>\n", LEFT,
                px_y(a, k * a->y_step), right, px_y(a, k * a->y_step));
    fprintf(f, "</g>\n<g stroke=\"#000\" stroke-width=\"1\" fill=\"none\">\n");
    fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\"/>\n", LEFT, TOP, right - LEFT,
            bottom - TOP);
    /* Minor ticks at 2..9 times each decade, as on log paper. */
    for (d = floor(a->decade_lo); d <= a->decade_hi; d += 1.0)
        for (m = 2.0; m <= 9.0; m += 1.0) {
            double x;
            if (log10(m) + d < a->decade_lo || log10(m) + d > a->decade_hi) continue;
            x = px_x(a, m * pow(10.0, d));
            fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\"/>\n", x, bottom, x, bottom - 4);
        }
    fprintf(f, "</g>\n<g font-family=\"sans-serif\" font-size=\"13\" fill=\"#000\">\n");
    for (d = ceil(a->decade_lo); d <= a->decade_hi; d += 1.0)
        fprintf(f,
                "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">10<tspan dy=\"-6\" "
                "font-size=\"10\">%.0f</tspan></text>\n",
                px_x(a, pow(10.0, d)), bottom + 20, d);
    for (k = 0; k <= y_ticks(a); ++k)
        fprintf(f, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n", LEFT - 6,
                px_y(a, k * a->y_step) + 4.0, k * a->y_step);
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">", (LEFT + right) / 2, HEIGHT - 15);
    put_text(f, x_label);
    fprintf(f, "</text>\n<text transform=\"translate(20 %d) rotate(-90)\" text-anchor=\"middle\">",
            (TOP + bottom) / 2);
    put_text(f, y_label);
    fprintf(f, "</text>\n</g>\n");
}

static void draw_series(FILE *f, const struct axes *a, const struct plot_series *series,
                        size_t series_count) {
    size_t s, i;
    for (s = 0; s < series_count; ++s) {
        const struct plot_series *p = &series[s];
        double legend_y = TOP + 10 + 22.0 * (double)s;
        fprintf(f, "<g stroke=\"%s\" fill=\"%s\">\n<polyline fill=\"none\" stroke-width=\"2\" points=\"",
                p->color, p->color);
        for (i = 0; i < p->count; ++i)
            if (usable(p->x[i], p->y[i]))
                fprintf(f, "%.1f,%.1f ", px_x(a, p->x[i]), px_y(a, p->y[i]));
        fprintf(f, "\"/>\n");
        for (i = 0; i < p->count; ++i)
            if (usable(p->x[i], p->y[i]))
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\"/>\n", px_x(a, p->x[i]),
                        px_y(a, p->y[i]));
        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke-width=\"2\"/>\n",
                WIDTH - RIGHT + 15, legend_y, WIDTH - RIGHT + 40, legend_y);
        fprintf(f, "<text x=\"%d\" y=\"%.1f\" stroke=\"none\" fill=\"#000\" font-family=\"sans-serif\" "
                   "font-size=\"13\">",
                WIDTH - RIGHT + 46, legend_y + 4.0);
        put_text(f, p->name);
        fprintf(f, "</text>\n</g>\n");
    }
}

int plot_svg_write(const char *path, const char *title, const char *x_label, const char *y_label,
                   const struct plot_series *series, size_t series_count) {
    struct axes a;
    FILE *f = fopen(path, "w");
    int failed;
    if (f == NULL) return -1;
    find_axes(&a, series, series_count);
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
            WIDTH, HEIGHT, WIDTH, HEIGHT);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n");
    fprintf(f, "<text x=\"%d\" y=\"28\" text-anchor=\"middle\" font-family=\"sans-serif\" "
               "font-size=\"15\">",
            (LEFT + WIDTH - RIGHT) / 2);
    put_text(f, title);
    fprintf(f, "</text>\n");
    draw_axes(f, &a, x_label, y_label);
    draw_series(f, &a, series, series_count);
    fprintf(f, "</svg>\n");
    failed = ferror(f);
    return (fclose(f) != 0 || failed) ? -1 : 0;
}
