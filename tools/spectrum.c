/*
 * spectrum.c - the averaged periodogram, computed separably, and its rings
 * (see spectrum.h).
 */
#include "spectrum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BLOCK 8 /* points whose tables are applied to one row of sums at a time */

static const double two_pi = 6.283185307179586476925286766559;

static int ceil_half(double v)
{
    double c = ceil(v);
    return c > SPECTRUM_MAX_HALF ? SPECTRUM_MAX_HALF : c < 1 ? 1 : (int)c;
}

int spectrum_init(struct spectrum *sp, const double box[4], double fmax)
{
    size_t cells, table;

    memset(sp, 0, sizeof *sp);
    sp->x0 = box[0];
    sp->y0 = box[1];
    sp->w = box[2] - box[0];
    sp->h = box[3] - box[1];
    sp->kmax = ceil_half(fmax * sp->w);
    sp->lmax = ceil_half(fmax * sp->h);
    cells = (size_t)(2 * sp->kmax + 1) * (size_t)(sp->lmax + 1);
    table = 2 * (size_t)(2 * sp->kmax + 1) + 2 * (size_t)(sp->lmax + 1);
    sp->sre = calloc(cells, sizeof *sp->sre);
    sp->sim = calloc(cells, sizeof *sp->sim);
    sp->power = calloc(cells, sizeof *sp->power);
    sp->tab = malloc(BLOCK * table * sizeof *sp->tab);
    if (sp->sre == NULL || sp->sim == NULL || sp->power == NULL || sp->tab == NULL) {
        spectrum_free(sp);
        return -1;
    }
    return 0;
}

void spectrum_free(struct spectrum *sp)
{
    free(sp->sre);
    free(sp->sim);
    free(sp->power);
    free(sp->tab);
    memset(sp, 0, sizeof *sp);
}

/* re[j] + i im[j] = exp(-2 pi i (first + j) t) for j = 0..n-1. */
static void phasors(double *re, double *im, int first, int n, double t)
{
    int j;

    for (j = 0; j < n; j++) {
        /* Reduce the turns to [0,1) first: cos and sin then stay accurate. */
        double turns = (double)(first + j) * t;
        double a = two_pi * (turns - floor(turns));
        re[j] = cos(a);
        im[j] = -sin(a);
    }
}

/* Adds the points of one block (at most BLOCK) to the sums. */
static void add_block(struct spectrum *sp, const double *xy, int n)
{
    int nk = 2 * sp->kmax + 1, nl = sp->lmax + 1;
    size_t per = 2 * (size_t)nk + 2 * (size_t)nl;
    int p, k, l;

    for (p = 0; p < n; p++) {
        double *t = sp->tab + (size_t)p * per;
        phasors(t, t + nk, -sp->kmax, nk, (xy[2 * p] - sp->x0) / sp->w);
        phasors(t + 2 * nk, t + 2 * nk + nl, 0, nl, (xy[2 * p + 1] - sp->y0) / sp->h);
    }
    /* One row of sums (fixed k) stays in cache while the block's points go by. */
    for (k = 0; k < nk; k++) {
        double *re = sp->sre + (size_t)k * nl, *im = sp->sim + (size_t)k * nl;
        for (p = 0; p < n; p++) {
            const double *t = sp->tab + (size_t)p * per;
            const double xr = t[k], xi = t[nk + k];
            const double *yr = t + 2 * nk, *yi = t + 2 * nk + nl;
            for (l = 0; l < nl; l++) {
                re[l] += xr * yr[l] - xi * yi[l];
                im[l] += xr * yi[l] + xi * yr[l];
            }
        }
    }
}

void spectrum_add(struct spectrum *sp, const double *xy, size_t n)
{
    while (n > 0) {
        int m = n < BLOCK ? (int)n : BLOCK;
        add_block(sp, xy, m);
        xy += 2 * m;
        n -= (size_t)m;
        sp->npoints += (size_t)m;
    }
}

void spectrum_end_pattern(struct spectrum *sp)
{
    size_t cells = (size_t)(2 * sp->kmax + 1) * (size_t)(sp->lmax + 1), c;

    if (sp->npoints == 0)
        return;
    for (c = 0; c < cells; c++) {
        sp->power[c] += (sp->sre[c] * sp->sre[c] + sp->sim[c] * sp->sim[c]) / (double)sp->npoints;
        sp->sre[c] = sp->sim[c] = 0.0;
    }
    sp->npoints = 0;
    sp->patterns++;
}

double spectrum_power(const struct spectrum *sp, int k, int l)
{
    if (sp->patterns == 0)
        return 0.0;
    if (l < 0) { /* P(-f) = P(f): only l >= 0 is stored */
        k = -k;
        l = -l;
    }
    return sp->power[(size_t)(k + sp->kmax) * (size_t)(sp->lmax + 1) + (size_t)l]
           / sp->patterns;
}

double spectrum_fmax(const struct spectrum *sp)
{
    double fx = sp->kmax / sp->w, fy = sp->lmax / sp->h;
    return fx < fy ? fx : fy;
}

size_t spectrum_rings(const struct spectrum *sp, struct spectrum_ring **rings)
{
    double step = 1.0 / (sp->w < sp->h ? sp->w : sp->h);
    /* Rings wholly inside the grid: (b + 1/2) step <= fmax. */
    size_t nb = (size_t)floor(spectrum_fmax(sp) / step - 0.5 + 1e-9), b;
    double *sum, *sumsq;
    struct spectrum_ring *r;
    int k, l;

    *rings = NULL;
    if (nb == 0)
        return 0;
    r = calloc(nb, sizeof *r);
    sum = calloc(2 * nb, sizeof *sum);
    if (r == NULL || sum == NULL) {
        free(r);
        free(sum);
        return 0;
    }
    sumsq = sum + nb;
    for (k = -sp->kmax; k <= sp->kmax; k++)
        for (l = -sp->lmax; l <= sp->lmax; l++) {
            double fx = k / sp->w, fy = l / sp->h;
            double ring = floor(sqrt(fx * fx + fy * fy) / step + 0.5);
            double p;
            if (ring < 1 || ring > (double)nb)
                continue;
            b = (size_t)ring - 1;
            p = spectrum_power(sp, k, l);
            sum[b] += p;
            sumsq[b] += p * p;
            r[b].samples++;
        }
    for (b = 0; b < nb; b++) {
        double n = (double)r[b].samples, mean = sum[b] / n;
        double var = n > 1 ? (sumsq[b] - sum[b] * mean) / (n - 1) : NAN;
        r[b].f = (double)(b + 1) * step;
        r[b].power = mean;
        r[b].anisotropy_db = 10.0 * log10((var > 0 ? var : 0.0) / (mean * mean));
        if (n <= 1)
            r[b].anisotropy_db = NAN;
    }
    free(sum);
    *rings = r;
    return nb;
}
