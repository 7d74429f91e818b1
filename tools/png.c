/*
 * png.c - grey-scale PNG: row filters, a fixed-Huffman DEFLATE stream with
 * greedy LZ77, zlib framing and PNG chunks (see png.h).
 */
#include "png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- a growable byte buffer and an LSB-first bit writer (RFC 1951 3.1.1) ---- */

struct out {
    unsigned char *p;
    size_t len, cap;
    int failed;      /* an allocation failed: the rest is dropped */
    uint32_t bits;   /* pending bits, the first ones in the low end */
    int nbits;
};

static void put_byte(struct out *o, unsigned char b)
{
    if (o->len == o->cap && !o->failed) {
        size_t cap = o->cap ? 2 * o->cap : 4096;
        unsigned char *p = realloc(o->p, cap);
        if (p == NULL) {
            o->failed = 1;
            return;
        }
        o->p = p;
        o->cap = cap;
    }
    if (!o->failed)
        o->p[o->len++] = b;
}

static void put_bits(struct out *o, uint32_t value, int n)
{
    o->bits |= value << o->nbits;
    o->nbits += n;
    while (o->nbits >= 8) {
        put_byte(o, (unsigned char)(o->bits & 0xff));
        o->bits >>= 8;
        o->nbits -= 8;
    }
}

/* A Huffman code goes out most significant bit first. */
static void put_code(struct out *o, uint32_t code, int n)
{
    uint32_t rev = 0;
    int i;

    for (i = 0; i < n; i++)
        rev |= ((code >> i) & 1u) << (n - 1 - i);
    put_bits(o, rev, n);
}

static void put_be32(struct out *o, uint32_t v)
{
    put_byte(o, (unsigned char)(v >> 24));
    put_byte(o, (unsigned char)(v >> 16));
    put_byte(o, (unsigned char)(v >> 8));
    put_byte(o, (unsigned char)v);
}

/* ---- DEFLATE with the fixed codes ------------------------------------------------------ */

/* The fixed literal/length code of symbol sym (0..287), RFC 1951 3.2.6. */
static void put_litlen(struct out *o, unsigned sym)
{
    if (sym < 144)
        put_code(o, 0x30 + sym, 8);
    else if (sym < 256)
        put_code(o, 0x190 + (sym - 144), 9);
    else if (sym < 280)
        put_code(o, sym - 256, 7);
    else
        put_code(o, 0xc0 + (sym - 280), 8);
}

static const unsigned short len_base[29] = { 3,  4,  5,  6,  7,  8,  9,  10, 11,  13,
                                             15, 17, 19, 23, 27, 31, 35, 43, 51,  59,
                                             67, 83, 99, 115, 131, 163, 195, 227, 258 };
static const unsigned char len_extra[29] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                             2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0 };
static const unsigned short dist_base[30] = { 1,    2,    3,    4,    5,    7,    9,    13,
                                              17,   25,   33,   49,   65,   97,   129,  193,
                                              257,  385,  513,  769,  1025, 1537, 2049, 3073,
                                              4097, 6145, 8193, 12289, 16385, 24577 };
static const unsigned char dist_extra[30] = { 0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                              6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13 };

static void put_match(struct out *o, unsigned len, unsigned dist)
{
    unsigned i = 28, j = 29;

    while (len_base[i] > len)
        i--;
    put_litlen(o, 257 + i);
    put_bits(o, len - len_base[i], len_extra[i]);
    while (dist_base[j] > dist)
        j--;
    put_code(o, j, 5);
    put_bits(o, dist - dist_base[j], dist_extra[j]);
}

#define WINDOW 32768u
#define MIN_MATCH 3u
#define MAX_MATCH 258u
#define HASH_BITS 15
#define MAX_CHAIN 64 /* candidates tried per position: enough for these images */

static unsigned hash3(const unsigned char *p)
{
    return ((unsigned)p[0] << 10 ^ (unsigned)p[1] << 5 ^ p[2]) & ((1u << HASH_BITS) - 1);
}

/*
 * One final fixed-Huffman block for the n bytes of data. head[h] is the last
 * position with hash h, prev[pos % WINDOW] the one before it with the same
 * hash (-1: none), so a chain visits earlier positions newest first.
 */
static int deflate_fixed(struct out *o, const unsigned char *data, size_t n)
{
    long *head = malloc(sizeof *head << HASH_BITS);
    long *prev = malloc(sizeof *prev * WINDOW);
    size_t i = 0, k;

    if (head == NULL || prev == NULL) {
        free(head);
        free(prev);
        return -1;
    }
    for (k = 0; k < (1u << HASH_BITS); k++)
        head[k] = -1;
    put_bits(o, 1, 1); /* BFINAL */
    put_bits(o, 1, 2); /* BTYPE 01: fixed codes */
    while (i < n) {
        size_t best_len = 0, best_dist = 0, step;
        if (i + MIN_MATCH <= n) {
            unsigned h = hash3(data + i);
            long cand = head[h];
            int chain = MAX_CHAIN;
            size_t limit = n - i < MAX_MATCH ? n - i : MAX_MATCH;
            while (cand >= 0 && i - (size_t)cand <= WINDOW - 1 && chain-- > 0) {
                size_t len = 0;
                while (len < limit && data[(size_t)cand + len] == data[i + len])
                    len++;
                if (len > best_len) {
                    best_len = len;
                    best_dist = i - (size_t)cand;
                    if (len == limit)
                        break;
                }
                cand = prev[(size_t)cand % WINDOW];
            }
        }
        if (best_len >= MIN_MATCH) {
            put_match(o, (unsigned)best_len, (unsigned)best_dist);
            step = best_len;
        } else {
            put_litlen(o, data[i]);
            step = 1;
        }
        /* Every position passed joins its chain, matched or not. */
        for (; step > 0; step--, i++)
            if (i + MIN_MATCH <= n) {
                unsigned h = hash3(data + i);
                prev[i % WINDOW] = head[h];
                head[h] = (long)i;
            }
    }
    put_litlen(o, 256); /* end of block */
    if (o->nbits > 0)
        put_bits(o, 0, 8 - o->nbits);
    free(head);
    free(prev);
    return 0;
}

static uint32_t adler32(const unsigned char *p, size_t n)
{
    uint32_t a = 1, b = 0;
    size_t k;

    for (k = 0; k < n; k++) {
        a = (a + p[k]) % 65521u;
        b = (b + a) % 65521u;
    }
    return b << 16 | a;
}

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    static uint32_t table[256];
    static int ready;
    size_t k;

    if (!ready) {
        uint32_t c, i;
        int j;
        for (i = 0; i < 256; i++) {
            for (c = i, j = 0; j < 8; j++)
                c = c & 1u ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        ready = 1;
    }
    crc = ~crc;
    for (k = 0; k < n; k++)
        crc = table[(crc ^ p[k]) & 0xff] ^ (crc >> 8);
    return ~crc;
}

/* ---- PNG ------------------------------------------------------------------------------- */

/*
 * The filtered scanlines: each row starts with its filter type, the one of
 * None (0), Sub (1) and Up (2) whose bytes, read as signed, have the smallest
 * sum of magnitudes (the usual heuristic of the PNG specification, 12.8).
 */
static void filter_rows(unsigned char *dst, const unsigned char *pix, unsigned w, unsigned h)
{
    unsigned x, y;
    int f;

    for (y = 0; y < h; y++) {
        const unsigned char *row = pix + (size_t)y * w;
        const unsigned char *up = y > 0 ? row - w : NULL;
        unsigned char *out = dst + (size_t)y * (w + 1);
        unsigned long cost[3] = { 0, 0, 0 };
        int best = 0;
        for (x = 0; x < w; x++) {
            unsigned char v[3];
            v[0] = row[x];
            v[1] = (unsigned char)(row[x] - (x > 0 ? row[x - 1] : 0));
            v[2] = (unsigned char)(row[x] - (up != NULL ? up[x] : 0));
            for (f = 0; f < 3; f++)
                cost[f] += v[f] < 128 ? v[f] : 256u - v[f];
        }
        for (f = 1; f < 3; f++)
            if (cost[f] < cost[best])
                best = f;
        out[0] = (unsigned char)best;
        for (x = 0; x < w; x++) {
            unsigned char prior = best == 1 ? (x > 0 ? row[x - 1] : 0)
                                : best == 2 ? (up != NULL ? up[x] : 0) : 0;
            out[1 + x] = (unsigned char)(row[x] - prior);
        }
    }
}

/* Appends a chunk: length, type, data, CRC over type and data. */
static void put_chunk(struct out *o, const char *type, const unsigned char *data, size_t n)
{
    size_t k, start;

    put_be32(o, (uint32_t)n);
    start = o->len;
    for (k = 0; k < 4; k++)
        put_byte(o, (unsigned char)type[k]);
    for (k = 0; k < n; k++)
        put_byte(o, data[k]);
    put_be32(o, o->failed ? 0 : png_crc32(0, o->p + start, 4 + n));
}

int png_write_gray(const char *path, const unsigned char *pix, unsigned width, unsigned height)
{
    static const unsigned char signature[8] = { 137, 'P', 'N', 'G', '\r', '\n', 26, '\n' };
    size_t raw_len = (size_t)height * (width + 1);
    unsigned char *raw = malloc(raw_len);
    unsigned char ihdr[13];
    struct out z, file;
    FILE *f;
    int ok;

    memset(&z, 0, sizeof z);
    memset(&file, 0, sizeof file);
    if (raw == NULL)
        return -1;
    filter_rows(raw, pix, width, height);
    put_byte(&z, 0x78); /* zlib: DEFLATE, 32 KiB window */
    put_byte(&z, 0x01); /* no dictionary, fastest-level hint; 0x7801 % 31 == 0 */
    if (deflate_fixed(&z, raw, raw_len) != 0)
        z.failed = 1;
    put_be32(&z, adler32(raw, raw_len));
    free(raw);

    ihdr[0] = (unsigned char)(width >> 24);
    ihdr[1] = (unsigned char)(width >> 16);
    ihdr[2] = (unsigned char)(width >> 8);
    ihdr[3] = (unsigned char)width;
    ihdr[4] = (unsigned char)(height >> 24);
    ihdr[5] = (unsigned char)(height >> 16);
    ihdr[6] = (unsigned char)(height >> 8);
    ihdr[7] = (unsigned char)height;
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 0;  /* colour type: grey */
    ihdr[10] = 0; /* compression: zlib */
    ihdr[11] = 0; /* filter method 0 */
    ihdr[12] = 0; /* no interlace */
    for (ok = 0; ok < 8; ok++)
        put_byte(&file, signature[ok]);
    put_chunk(&file, "IHDR", ihdr, sizeof ihdr);
    if (!z.failed)
        put_chunk(&file, "IDAT", z.p, z.len);
    put_chunk(&file, "IEND", NULL, 0);
    ok = !z.failed && !file.failed;
    free(z.p);
    if (!ok) {
        free(file.p);
        errno = ENOMEM;
        return -1;
    }
    f = fopen(path, "wb");
    ok = f != NULL && fwrite(file.p, 1, file.len, f) == file.len;
    if (f != NULL && fclose(f) != 0)
        ok = 0;
    free(file.p);
    return ok ? 0 : -1;
}
