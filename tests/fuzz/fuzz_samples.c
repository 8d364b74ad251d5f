/* tests/fuzz/fuzz_samples.c - libFuzzer target of the sample-file reader
 * (examples/common/sample_reader.h), the parser `mcbox-check --samples`
 * runs on files written by other people's programs.
 *
 * The first byte chooses the format (text, float32, float64) and the
 * number of coordinates (1 to 3); the rest is the file. The reader must
 * return, without reading past the buffer (AddressSanitizer watches),
 * either an error message or points that are all finite, with their count
 * consistent with the input's size, and text accepted only without control
 * bytes in its first 4 KiB (the reader's "looks binary" rule). Built and run by `make fuzz`.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/sample_reader.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    app_samples_format fmt = (app_samples_format)(data[0] % 3);
    int dims = 1 + (data[0] / 3) % 3;
    /* A copy of exactly the file's bytes, so that a read past its end is a
     * heap overflow the sanitizer reports. */
    size_t len = size - 1;
    char *buf = malloc(len ? len : 1);
    if (!buf)
        return 0;
    memcpy(buf, data + 1, len);
    double *pts = NULL;
    uint64_t n = 0;
    char err[256];
    err[0] = '\0';
    if (app_samples_parse(buf, len, fmt, dims, &pts, &n, err, sizeof err)) {
        if (n < 1)
            abort();
        size_t width = fmt == APP_SAMPLES_F32 ? 4 : 8;
        if (fmt != APP_SAMPLES_TEXT && n * (uint64_t)dims * width != len)
            abort();
        for (uint64_t i = 0; i < n * (uint64_t)dims; i++)
            if (!isfinite(pts[i]))
                abort();
        /* Text read without complaint has no control byte but blanks and
         * line ends in its first 4 KiB: raw records are called binary. */
        for (size_t i = 0; fmt == APP_SAMPLES_TEXT && i < len && i < 4096; i++) {
            unsigned char b = (unsigned char)buf[i];
            if (b == 0 || (b < 0x20 && !strchr(" \t\r\v\f\n", b)) || b == 0x7f)
                abort();
        }
    } else if (pts != NULL || err[0] == '\0' || memchr(err, '\n', strlen(err))) {
        abort(); /* a failure is one line of message and no points */
    }
    free(pts);
    free(buf);
    return 0;
}
