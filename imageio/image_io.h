/* imageio/image_io.h - the readers of the image check: a renderer's image,
 * read back as the linear RGB values it stands for, so that mcbox can
 * compare it with exact per-pixel truths: the image door of the
 * Cornell-box renderer of "Ray Tracing: The Rest of Your Life".
 *
 * A float image (PFM, OpenEXR) holds linear values as they are. An 8- or
 * 16-bit image (PNG, PPM) holds codes: a renderer encoded each value with
 * a display curve and quantized it, so a code does not give one value
 * but an interval of them. The reader returns that interval with every
 * pixel, under the curve and quantizer the user names (img_transfer),
 * so that a judge can ask "does the truth lie in the interval the code
 * stands for" instead of guessing a rounding. The file's own gAMA, sRGB
 * or chromaticity claims are not trusted: the user says the curve.
 *
 * Formats are told by their first bytes, never by the file name:
 *   PFM  "PF" colour or "Pf" grey, either byte order, rows bottom to top;
 *   PPM  binary P6 or ascii P3, maxval 255 (8-bit) or 65535 (16-bit);
 *   PNG  8- or 16-bit grey, grey+alpha, RGB, RGBA or palette (libpng);
 *        alpha must be opaque everywhere;
 *   EXR  one scanline or tiled part (level 0 of a mipmap), channels R, G
 *        and B, or Y alone, of type half, float or uint, not subsampled,
 *        the data window equal to the display window (OpenEXRCore);
 *        other channels (A, Z, ...) are ignored.
 * Grey images are replicated to the three channels. Width and height are
 * 1 .. 65536. A float image must be finite and non-negative everywhere.
 */
#ifndef IMG_IMAGE_IO_H
#define IMG_IMAGE_IO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* How the codes of an 8- or 16-bit file were made from linear values x
 * (max = 255 or 65535). Every curve but book rounds: code k stands for
 * the encoded interval [(k - 0.5)/max, (k + 0.5)/max] cut to [0, 1]. */
typedef enum img_transfer {
    IMG_TRANSFER_LINEAR,  /* code = round(max x); PFM and EXR are always linear */
    IMG_TRANSFER_GAMMA2,  /* code = round(max sqrt(x)): mcbox's own PNG and PPM writer */
    IMG_TRANSFER_GAMMA22, /* code = round(max x^(1/2.2)) */
    IMG_TRANSFER_SRGB,    /* the sRGB curve: 12.92 x below 0.0031308, else
                               1.055 x^(1/2.4) - 0.055; code = round(max e) */
    IMG_TRANSFER_BOOK     /* the write_color of Shirley's books: e = sqrt(x) (0 for
                               x <= 0), code = int(256 clamp(e, 0, 0.999)); 8-bit only */
} img_transfer;

/* The names img_transfer_parse accepts, in img_transfer order:
 * "linear", "gamma2", "gamma2.2", "srgb", "book"; NULL-terminated. */
extern const char *const img_transfer_names[];

/* Sets *out to the transfer called name (one of img_transfer_names,
 * exact spelling). Returns 0, or -1 for any other name (then *out is
 * unchanged). */
int img_transfer_parse(const char *name, img_transfer *out);

/* The linear value of an encoded value under the curve of t: the inverse
 * of the curve (e^2 for gamma2 and book, e^2.2, e for linear, the sRGB
 * inverse). encoded is clamped to [0, 1]; NaN gives 0. The result lies
 * in [0, 1] and rises with encoded. */
double img_transfer_decode(img_transfer t, double encoded);

/* An image read back: linear RGB, row-major, the top row first; pixel
 * (x, y) channel c (0 R, 1 G, 2 B) at index 3 (y width + x) + c. */
typedef struct img_picture {
    int width, height; /* 1 .. 65536 */
    /* The value each pixel stands for. Float formats: the stored value.
     * Integer formats: the code k decoded, img_transfer_decode(t, k/max)
     * for the rounding curves, the middle of the code's step,
     * ((k + 0.5)/256)^2, for book. */
    double *value;
    /* Integer formats: every linear value in [lo, hi] would have been
     * written as this code (book's steps are half-open, [lo, hi)). Round
     * curves: the decoded ends of [(k - 0.5)/max, (k + 0.5)/max]; book:
     * [(k/256)^2, ((k + 1)/256)^2). Code 0 has lo = 0 and the top code
     * hi = +INFINITY: values at or below 0, and above the top, clamp to
     * them. NULL for float formats. */
    double *lo, *hi;
    int bits;           /* 0 for float formats (PFM, EXR), else 8 or 16 */
    const char *format; /* "pfm", "exr", "png" or "ppm" (static strings) */
} img_picture;

/* Reads the image file at path into *out (which needs no
 * initialization; free it with img_picture_free), decoding integer
 * formats under the transfer t. A float image takes only
 * IMG_TRANSFER_LINEAR; IMG_TRANSFER_BOOK takes only 8-bit files.
 * Returns 0, or -1 with *out empty (NULL arrays, zero size) and a
 * one-line reason in why (why_len bytes, cut to fit; why may be NULL):
 * the file cannot be read, unknown format, truncated or malformed data,
 * a size outside 1..65536, a non-finite or negative value in a float
 * image or a transparent pixel (with the first such pixel's column and
 * row from the top), a transfer the file cannot have, out of memory. */
int img_picture_read(const char *path, img_transfer t, img_picture *out, char *why,
                       size_t why_len);

/* Frees the arrays of p and empties it. p is NULL (a no-op), zeroed, or
 * filled by img_picture_read, whether it succeeded or not; freeing
 * twice is harmless. */
void img_picture_free(img_picture *p);

/* Writes a colour PFM of width x height (1 .. 65536) pixels: rgb holds
 * width * height * 3 linear values, row-major, the top row first, each
 * stored as a 32-bit float (values beyond the float range become
 * infinite); the file is little-endian (scale -1) and its rows run from
 * the bottom up, as the PFM format says. Returns 0, or -1 with a one-line
 * reason in why (as img_picture_read). */
int img_picture_write_pfm(const char *path, int width, int height, const double *rgb,
                            char *why, size_t why_len);

#ifdef __cplusplus
}
#endif

#endif /* IMG_IMAGE_IO_H */
