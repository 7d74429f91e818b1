/*
 * png.h - a minimal PNG writer for 8-bit grey-scale images, so that the
 * poissondisk program needs no image library.
 *
 * The file has the three chunks every decoder needs (IHDR, one IDAT, IEND),
 * each with its CRC-32. The pixel rows are filtered (None, Sub or Up, the
 * smallest per row) and compressed into one zlib stream (RFC 1950, Adler-32)
 * holding a single DEFLATE block with the fixed Huffman codes (RFC 1951
 * 3.2.6) and greedy LZ77 matches: no dynamic tables, small and easy to check.
 * Plain C99.
 */
#ifndef POISSONDISK_PNG_H
#define POISSONDISK_PNG_H

#include <stddef.h>
#include <stdint.h>

/*
 * Writes the width x height grey-scale image pix (row-major, top row first,
 * 0 black, 255 white) to the file path. Returns 0, or -1 with errno set
 * (out of memory, or the file could not be written).
 */
int png_write_gray(const char *path, const unsigned char *pix, unsigned width, unsigned height);

/* CRC-32 (ISO 3309, as PNG and zlib use it) of n bytes, continuing from crc (0 to start). */
uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n);

#endif /* POISSONDISK_PNG_H */
