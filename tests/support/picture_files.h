/* tests/support/picture_files.h - the scratch files of the image
 * readers' tests (tests/test_image_io.c, tests/test_image_exr.c): a
 * temporary directory per run, files written into it, and the two
 * verdicts every reader test asks for. */
#ifndef PICTURE_FILES_H
#define PICTURE_FILES_H

#include <stddef.h>
#include <stdint.h>

#include "imageio/image_io.h"

/* A path in this run's temporary directory (a static buffer). */
const char *path_of(const char *name);

/* Writes n bytes to the named file; returns its path. */
const char *write_bytes(const char *name, const void *b, size_t n);

/* The first bytes (at most 4096) of a file written before, less cut,
 * under a new name; returns its path. */
const char *cut_copy(const char *from, const char *to, size_t cut);

/* The 4 bytes of the float whose IEEE bits are u, in either order. */
void put_bits(unsigned char *q, uint32_t u, int little);

/* Reads path, which must fail with a reason starting with want and
 * leave the picture empty. */
void refused(const char *path, img_transfer t, const char *want);

/* Reads path, which must succeed. */
void read_ok(const char *path, img_transfer t, img_picture *p);

/* cmocka group setup and teardown: the temporary directory. */
int make_dir(void **state);
int remove_dir(void **state);

/* Channel c of pixel (x, y). */
#define V(p, x, y, c) ((p).value[3 * ((size_t)(y) * (size_t)(p).width + (size_t)(x)) + (c)])

#endif /* PICTURE_FILES_H */
