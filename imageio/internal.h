/* imageio/internal.h - what the readers of imageio/image_io.c share
 * with the OpenEXR reader of imageio/image_exr.c: the file in memory and the
 * picture being filled, and the steps every decoder takes. */
#ifndef IMG_INTERNAL_H
#define IMG_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>

#include "imageio/image_io.h"

/* Largest width or height. */
#define SIDE_MAX 65536

typedef struct reader {
    const unsigned char *b; /* the whole file, n bytes */
    size_t n;
    img_transfer t;
    img_picture *pic;
    bool grey; /* one channel in the file, replicated to three */
    char *why;
    size_t why_len;
} reader;

/* Writes the reason (printf style) into why, on one line; returns -1. */
int img_say(char *why, size_t len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
#define FAIL(r, ...) img_say((r)->why, (r)->why_len, __VA_ARGS__)

/* Checks the size (w x h) and the transfer against what the file is
 * (bits 0 for floats, 8 or 16), and records them; 0 or -1. */
int img_start(reader *r, long w, long h, int bits);

/* Allocates the picture's arrays once the file is known to hold them. */
int img_alloc(reader *r);

/* Stores channel c of pixel px (row-major); a grey file's one channel
 * goes to all three. */
void img_put(reader *r, size_t px, int c, double v);

/* The OpenEXR reader (imageio/image_exr.c): the file's first part into
 * r->pic as floats; 0 or -1. */
int img_read_exr(reader *r);

#endif /* IMG_INTERNAL_H */
