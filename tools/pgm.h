/*
 * pgm.h - read a grey-scale PGM image (Netpbm), for --radius-map, so that
 * the poissondisk program needs no image library.
 *
 * Both kinds are read: P2 (plain: the grey levels as decimal numbers) and
 * P5 (raw: one byte per pixel when maxval < 256, else two bytes, most
 * significant first). The header is the magic, the width, the height and
 * maxval (1 to 65535), separated by white space, where '#' starts a comment
 * that runs to the end of the line; in P5 a single white-space character
 * follows maxval, then the pixels. In P2 comments are also skipped between
 * the pixels. Only the first image of a file is read: whatever follows it
 * is ignored. Every error is a message, never a crash: a file that is not
 * PGM (or a PBM, PPM or PAM one), a malformed or incomplete header, a width
 * or height of 0, more than PGM_MAX_PIXELS pixels, a grey level above
 * maxval, a truncated raster, a read error. Plain C99.
 */
#ifndef POISSONDISK_PGM_H
#define POISSONDISK_PGM_H

#include <stddef.h>
#include <stdio.h>

/* The most pixels an image may have: 4096 x 4096 (the map it makes is 128 MiB). */
#define PGM_MAX_PIXELS ((size_t)1 << 24)

struct pgm {
    size_t width, height;
    unsigned maxval;       /* the grey level of white; 0 is black */
    unsigned short *pix;   /* width * height grey levels, row-major, top row first */
};

/*
 * Reads one image from f (opened in binary mode). Returns 0 and fills *out
 * (release it with pgm_free), or -1 with a message in msg (size bytes, no
 * trailing newline) and *out empty.
 */
int pgm_read(FILE *f, struct pgm *out, char *msg, size_t size);

void pgm_free(struct pgm *p);

#endif /* POISSONDISK_PGM_H */
