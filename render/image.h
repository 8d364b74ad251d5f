/* render/image.h - the accumulated image and its output files.
 *
 * Every pixel keeps the running mean and squared deviations (Welford [@welford1962]) of
 * its finite samples in double precision, linear radiance, plus how many
 * non-finite samples were dropped. Shirley's "Ray Tracing: The Rest of
 * Your Life" (v1.123, chapter 10; de_nan in main.cc of release v1.123.0)
 * ends by zeroing a NaN sample's colour, which still divides by the full
 * sample count and darkens the pixel; here such a sample is
 * dropped and counted, and the pixel is the mean of the samples that are
 * left. Display encoding (the book's gamma 2 square root, gamma 2.2 or
 * sRGB) happens only on output.
 */
#ifndef RT_IMAGE_H
#define RT_IMAGE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "mc/stats.h"
#include "mc/vec3.h"

typedef struct rt_pixel {
    double mean[3];   /* linear RGB mean of the finite samples */
    double m2[3];     /* sums of squared deviations from the mean */
    uint64_t n;       /* finite samples */
    uint64_t dropped; /* non-finite samples left out */
} rt_pixel;

typedef struct rt_image {
    int width, height;
    rt_pixel *px; /* row-major, row 0 at the top */
} rt_image;

/* A black image with no samples (width, height >= 1); NULL when out of
 * memory. */
rt_image *rt_image_create(int width, int height);

/* Frees the image; NULL is a no-op. */
void rt_image_destroy(rt_image *img);

/* Forgets every sample. */
void rt_image_clear(rt_image *img);

/* Adds one sample to a pixel: into the mean if all three channels are
 * finite, else to the dropped count. Returns whether it was kept. */
bool rt_pixel_add(rt_pixel *p, vec3 radiance);

/* The linear RGB of pixel (x, y): the mean of its finite samples, black if
 * it has none. */
vec3 rt_image_get(const rt_image *img, int x, int y);

/* The mean over the pixels of [x0, x1) x [y0, y1) of each channel's pixel
 * value, with its standard error from the per-pixel sample variances
 * (sum of var_i / n_i over the pixels, over the pixel count squared; pixels
 * with fewer than two samples count as zero variance). n in the estimate
 * is the number of finite samples. */
void rt_image_region_stats(const rt_image *img, int x0, int y0, int x1, int y1, mc_estimate out[3]);

/* Total dropped samples over the image. */
uint64_t rt_image_dropped(const rt_image *img);

/* --- output ---------------------------------------------------------------- */

typedef enum rt_format { RT_FORMAT_UNKNOWN, RT_FORMAT_PFM, RT_FORMAT_PNG, RT_FORMAT_PPM } rt_format;

/* The format named by the file's extension (.pfm, .png, .ppm, any case). */
rt_format rt_format_from_path(const char *path);

typedef enum rt_gamma { RT_GAMMA_2, RT_GAMMA_2_2, RT_GAMMA_SRGB } rt_gamma;

/* "2", "2.2" or "srgb"; false for anything else. */
bool rt_gamma_parse(const char *name, rt_gamma *out);

/* The names rt_gamma_parse accepts, in rt_gamma order, NULL-terminated. */
extern const char *const rt_gamma_names[];

/* The display value of a linear value: x^(1/2) (the book's sqrt),
 * x^(1/2.2), or the sRGB curve (12.92 x below 0.0031308, else
 * 1.055 x^(1/2.4) - 0.055). Negative or NaN input gives 0. */
double rt_gamma_encode(double linear, rt_gamma g);

/* An encoded value in [0, 1] (clamped) as a byte: round(255 v). */
uint8_t rt_encode_byte(double encoded);

/* Writes the image to f: PFM is linear 32-bit float RGB (rows bottom to
 * top, scale -1: little-endian); PNG and PPM are 8-bit RGB after gamma.
 * Returns 0, or -1 on a write error or out of memory. */
int rt_image_write(const rt_image *img, FILE *f, rt_format format, rt_gamma g);

/* Opens path, writes the image in the format of its extension, closes it.
 * Returns 0, or -1 (unknown extension, cannot open or write). */
int rt_image_save(const rt_image *img, const char *path, rt_gamma g);

/* --- input and comparison -------------------------------------------------- */

/* Reads a colour PFM ("PF", either byte order, as rt_image_write writes
 * it; width and height 1..65536) into a new image whose every pixel holds
 * one sample, the file's value. NULL on failure, with *why (may be NULL)
 * set to a short static reason: not a PFM file, a greyscale PFM, a size
 * out of range, truncated data, non-finite values, out of memory. */
rt_image *rt_image_read_pfm(FILE *f, const char **why);

/* The mean squared difference of the pixel values (rt_image_get) of two
 * images of the same size, over all pixels and the three linear RGB
 * channels. */
double rt_image_mse(const rt_image *a, const rt_image *b);

#endif /* RT_IMAGE_H */
