/*
 * spectrum_plot.c - the radially averaged power and the anisotropy of a
 * spectrum as one SVG picture of two panels (see spectrum_out.h), drawn by
 * hand: axes, ticks, a dashed white-noise reference, one polyline each.
 */
#include "spectrum_out.h"

#include <math.h>
#include <stdio.h>

#define PLOT_W 640.0
#define PANEL_H 200.0
#define LEFT 70.0
#define RIGHT 20.0
#define TOP 40.0
#define GAP 70.0

/* One panel: its place on the page and the ranges it shows. */
struct panel {
    double top;              /* page y of the panel's top edge */
    double xmax;             /* f R from 0 to xmax */
    double ylo, yhi, ystep;  /* the value range and its tick step */
};

static double page_x(const struct panel *p, double v)
{
    return LEFT + (PLOT_W - LEFT - RIGHT) * v / p->xmax;
}

static double page_y(const struct panel *p, double v)
{
    if (v < p->ylo)
        v = p->ylo;
    if (v > p->yhi)
        v = p->yhi;
    return p->top + PANEL_H * (p->yhi - v) / (p->yhi - p->ylo);
}

static void axes(FILE *f, const struct panel *p, const char *title, const char *unit)
{
    double v;

    fprintf(f, "<text x=\"%g\" y=\"%g\" font-size=\"15\">%s</text>\n", LEFT, p->top - 12, title);
    fprintf(f, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" "
               "stroke=\"black\"/>\n", LEFT, p->top, PLOT_W - LEFT - RIGHT, PANEL_H);
    for (v = 0; v <= p->xmax + 1e-9; v += 0.25) {
        double x = page_x(p, v);
        int major = fabs(v - floor(v * 2 + 0.5) / 2) < 1e-9;
        fprintf(f, "<line x1=\"%.2f\" y1=\"%g\" x2=\"%.2f\" y2=\"%g\" stroke=\"%s\"/>\n", x,
                p->top, x, p->top + PANEL_H, major ? "#ccc" : "#eee");
        if (major)
            fprintf(f, "<text x=\"%.2f\" y=\"%g\" font-size=\"12\" text-anchor=\"middle\">%g"
                       "</text>\n", x, p->top + PANEL_H + 16, v);
    }
    for (v = p->ylo; v <= p->yhi + 1e-9; v += p->ystep)
        fprintf(f, "<text x=\"%g\" y=\"%.2f\" font-size=\"12\" text-anchor=\"end\">%g</text>\n",
                LEFT - 6, page_y(p, v) + 4, v);
    fprintf(f, "<text x=\"%g\" y=\"%g\" font-size=\"12\" text-anchor=\"middle\">frequency "
               "&#215; R%s</text>\n", LEFT + (PLOT_W - LEFT - RIGHT) / 2, p->top + PANEL_H + 34,
            unit);
}

/* A dashed horizontal line at v, with a label at its right end. */
static void reference(FILE *f, const struct panel *p, double v, const char *label)
{
    fprintf(f, "<line x1=\"%g\" y1=\"%.2f\" x2=\"%g\" y2=\"%.2f\" stroke=\"#c33\" "
               "stroke-dasharray=\"6 4\"/>\n", LEFT, page_y(p, v), PLOT_W - RIGHT, page_y(p, v));
    fprintf(f, "<text x=\"%g\" y=\"%.2f\" font-size=\"11\" fill=\"#c33\" text-anchor=\"end\">"
               "%s</text>\n", PLOT_W - RIGHT - 4, page_y(p, v) - 4, label);
}

/* The curve; a NaN value breaks it. */
static void curve(FILE *f, const struct panel *p, const struct spectrum_ring *r, size_t n,
                  double radius, int anisotropy)
{
    size_t b;
    int open = 0;

    for (b = 0; b < n; b++) {
        double v = anisotropy ? r[b].anisotropy_db : r[b].power;
        if (isnan(v) || isinf(v)) {
            if (open)
                fputs("\"/>\n", f);
            open = 0;
            continue;
        }
        if (!open)
            fputs("<polyline fill=\"none\" stroke=\"#1f4e99\" stroke-width=\"1.5\" points=\"", f);
        fprintf(f, "%s%.2f,%.2f", open ? " " : "", page_x(p, r[b].f * radius), page_y(p, v));
        open = 1;
    }
    if (open)
        fputs("\"/>\n", f);
}

int spectrum_write_plot(const struct spectrum_ring *rings, size_t n, double radius,
                        unsigned patterns, const char *path)
{
    struct panel pw, an;
    double pmax = 2.0, amin = 0.0, amax = 0.0, white_db = -10.0 * log10(patterns ? patterns : 1);
    char label[64];
    size_t b;
    FILE *f;
    int ok;

    for (b = 0; b < n; b++) {
        if (rings[b].power > pmax)
            pmax = rings[b].power;
        if (!isnan(rings[b].anisotropy_db) && !isinf(rings[b].anisotropy_db)) {
            amin = rings[b].anisotropy_db < amin ? rings[b].anisotropy_db : amin;
            amax = rings[b].anisotropy_db > amax ? rings[b].anisotropy_db : amax;
        }
    }
    pw.top = TOP;
    pw.xmax = n > 0 ? ceil(rings[n - 1].f * radius * 2) / 2 : 1;
    pw.ylo = 0;
    pw.yhi = ceil(pmax * 2) / 2;
    pw.ystep = pw.yhi <= 4 ? 0.5 : ceil(pw.yhi / 8);
    an = pw;
    an.top = TOP + PANEL_H + GAP;
    amin = amin < white_db ? amin : white_db;
    an.ylo = floor((amin < -40 ? -40 : amin) / 5) * 5 - 5;
    an.yhi = ceil((amax > 30 ? 30 : amax) / 5) * 5 + 5;
    an.ystep = an.yhi - an.ylo > 40 ? 10 : 5;

    if ((f = fopen(path, "w")) == NULL)
        return -1;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%g\" "
               "height=\"%g\" viewBox=\"0 0 %g %g\" font-family=\"sans-serif\">\n"
               "<title>poissondisk: radially averaged power and anisotropy</title>\n"
               "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            PLOT_W, an.top + PANEL_H + 50, PLOT_W, an.top + PANEL_H + 50);
    snprintf(label, sizeof label, "radially averaged power (%u pattern%s)", patterns,
             patterns == 1 ? "" : "s");
    axes(f, &pw, label, "");
    reference(f, &pw, 1.0, "white noise");
    curve(f, &pw, rings, n, radius, 0);
    axes(f, &an, "anisotropy (dB)", "");
    reference(f, &an, white_db, "white noise");
    curve(f, &an, rings, n, radius, 1);
    ok = fputs("</svg>\n", f) >= 0 && !ferror(f);
    if (fclose(f) != 0)
        ok = 0;
    return ok ? 0 : -1;
}
