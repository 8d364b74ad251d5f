/* tests/fuzz/fuzz_image.c - libFuzzer target of the image readers
 * (imageio/image_io.h) that `mcbox-check --image` runs on files written
 * by other people's renderers: PFM, PPM, PNG (libpng) and OpenEXR
 * (OpenEXRCore).
 *
 * The first byte chooses the transfer curve; the rest is the file, which
 * the reader takes by name, so it is written to a temporary file first.
 * The reader must return, without a crash, a leak or a read past its
 * buffers (AddressSanitizer watches), either a one-line reason and an
 * empty picture, or a picture of 1..65536 pixels a side whose values are
 * finite and non-negative and, for a file of codes, inside their
 * intervals. Built and run by `make fuzz`.
 */
#define _XOPEN_SOURCE 700 /* mkstemp */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "imageio/image_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* One scratch file for the whole run, removed at exit. */
static char path[64];

static void remove_scratch(void) { unlink(path); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    if (!path[0]) {
        snprintf(path, sizeof path, "/tmp/mcbox_fuzz_image_XXXXXX");
        int fd = mkstemp(path);
        if (fd < 0)
            abort();
        close(fd);
        atexit(remove_scratch);
    }
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data + 1, 1, size - 1, f) != size - 1 || fclose(f) != 0)
        abort();
    img_transfer t = (img_transfer)(data[0] % 5);
    img_picture p;
    char why[256] = "";
    if (img_picture_read(path, t, &p, why, sizeof why) != 0) {
        if (!why[0] || strchr(why, '\n') || p.value || p.width)
            abort();
        return 0;
    }
    if (p.width < 1 || p.height < 1 || p.width > 65536 || p.height > 65536)
        abort();
    for (size_t i = 0; i < 3 * (size_t)p.width * (size_t)p.height; i++) {
        if (!isfinite(p.value[i]) || p.value[i] < 0.0)
            abort();
        if (p.lo && !(p.lo[i] <= p.value[i] && p.value[i] <= p.hi[i]))
            abort();
    }
    img_picture_free(&p);
    return 0;
}
