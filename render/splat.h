/* render/splat.h - the light paths' splats, summed so that the order of
 * the terms does not matter.
 *
 * A strategy that splats (light tracing, bidirectional: render/bdpt.h)
 * adds each light path's contribution to whichever pixel sees it. Summed
 * in doubles, a pixel's value would depend on the order in which threads,
 * or processes, add their terms (floating-point addition is not
 * associative), and the image on how the rows were shared out. Each term
 * is therefore rounded once, toward minus infinity, to a multiple of
 * 2^-64, and the sums are kept in 128-bit two's-complement fixed point
 * (64 integer bits, 64 fraction bits): integer addition is exact and
 * associative, so any split of the rows over threads and processes gives
 * the same bits. The rounding moves a term by less than 2^-64, against
 * splats of order 1e-3 to 1e6 in the book's scenes; a term of magnitude
 * 2^62 or more (no finite scene comes near it) or a non-finite one is
 * refused and counted by the caller.
 */
#ifndef RT_SPLAT_H
#define RT_SPLAT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "render/image.h"

/* One channel's sum: the value (hi * 2^64 + lo) * 2^-64, hi read as a
 * signed 64-bit integer. */
typedef struct rt_splat_sum {
    uint64_t lo, hi;
} rt_splat_sum;

/* The splats of an image: three sums (red, green, blue) per pixel, row
 * major. */
typedef struct rt_splats {
    int width, height;
    rt_splat_sum *sum; /* 3 * width * height */
} rt_splats;

/* Zeroed sums for a width x height image (both >= 1), or NULL when out of
 * memory. */
rt_splats *rt_splats_create(int width, int height);

/* Frees them (NULL is fine). */
void rt_splats_destroy(rt_splats *s);

/* Sets every sum to zero. */
void rt_splats_clear(rt_splats *s);

/* Adds v, rounded down to a multiple of 2^-64, to *s; false (and *s left
 * alone) when v is not finite or |v| >= 2^62. */
bool rt_splat_add(rt_splat_sum *s, double v);

/* Adds the three channels of a splat to pixel px (< width * height); false
 * (and nothing added) when any channel is refused by rt_splat_add. */
bool rt_splats_add_rgb(rt_splats *s, size_t px, double r, double g, double b);

/* Asks the processor to start loading pixel px's sums (< width * height),
 * so that a caller with work to do before rt_splats_add_rgb (a shadow ray)
 * overlaps the load with it: at 600 x 600 one set is 17 MB, larger than
 * the caches, and a splat into it otherwise waits for memory. A hint: no
 * effect on any value, and nothing where the compiler has no such
 * builtin. */
static inline void rt_splats_prefetch(const rt_splats *s, size_t px)
{
#if defined(__GNUC__)
    __builtin_prefetch(&s->sum[3 * px], 1, 3);
    __builtin_prefetch(&s->sum[3 * px + 2], 1, 3);
#else
    (void)s;
    (void)px;
#endif
}

/* into += from, term by term, exactly; the two have the same size. */
void rt_splats_merge(rt_splats *into, const rt_splats *from);

/* The sum as a double: its integer and fraction parts each converted,
 * then added (within two units in the last place of the exact value). */
double rt_splat_value(rt_splat_sum s);

/* Adds each pixel's sums divided by n (the number of light paths the
 * splats came from) to its mean; n = 0 adds nothing. img has s's size. */
void rt_splats_add_to_image(const rt_splats *s, uint64_t n, rt_image *img);

#endif /* RT_SPLAT_H */
