/* render/splat.c - exact sums of the splats in 128-bit fixed point. */
#include "render/splat.h"

#include <math.h>
#include <stdlib.h>

rt_splats *rt_splats_create(int width, int height)
{
    if (width < 1 || height < 1)
        return NULL;
    rt_splats *s = malloc(sizeof *s);
    size_t n = 3 * (size_t)width * (size_t)height;
    if (!s)
        return NULL;
    s->width = width;
    s->height = height;
    s->sum = calloc(n, sizeof *s->sum);
    if (!s->sum) {
        free(s);
        return NULL;
    }
    return s;
}

void rt_splats_destroy(rt_splats *s)
{
    if (s)
        free(s->sum);
    free(s);
}

void rt_splats_clear(rt_splats *s)
{
    size_t n = 3 * (size_t)s->width * (size_t)s->height;
    for (size_t i = 0; i < n; i++)
        s->sum[i] = (rt_splat_sum){0, 0};
}

/* BEGIN SNIPPET splat_add */
/* Adds the 128-bit number (hi, lo) to *s: the low words with a carry into
 * the high ones, all in unsigned arithmetic, which wraps as two's
 * complement does. */
static inline void add128(rt_splat_sum *s, uint64_t hi, uint64_t lo)
{
    uint64_t l = s->lo + lo;
    s->hi += hi + (l < lo);
    s->lo = l;
}

bool rt_splat_add(rt_splat_sum *s, double v)
{
    if (!(fabs(v) < 0x1p62))
        return false;
    /* v = i + f with i = floor(v) an integer and 0 <= f < 1: the
     * conversion truncates toward zero (one instruction, where floor is a
     * library call on the x86-64 baseline), then one less for a negative v
     * with a fraction. Both i and v - i are exact (|v| < 2^62, and a v of
     * 2^52 or more has no fraction), except that v - i rounds up to 1 for
     * a tiny negative v: f is then the largest fraction below 1. f 2^64 is
     * exact (a power of two), and the conversion truncates: v rounded down
     * to a multiple of 2^-64. */
    int64_t i = (int64_t)v;
    i -= (double)i > v;
    double f = (v - (double)i) * 0x1p64;
    uint64_t lo = f < 0x1p64 ? (uint64_t)f : UINT64_MAX;
    add128(s, (uint64_t)i, lo);
    return true;
}
/* END SNIPPET splat_add */

bool rt_splats_add_rgb(rt_splats *s, size_t px, double r, double g, double b)
{
    /* All three checked first, so that a refused splat adds nothing. */
    if (!(fabs(r) < 0x1p62) || !(fabs(g) < 0x1p62) || !(fabs(b) < 0x1p62))
        return false;
    rt_splat_sum *p = &s->sum[3 * px];
    (void)rt_splat_add(&p[0], r);
    (void)rt_splat_add(&p[1], g);
    (void)rt_splat_add(&p[2], b);
    return true;
}

void rt_splats_merge(rt_splats *into, const rt_splats *from)
{
    size_t n = 3 * (size_t)into->width * (size_t)into->height;
    for (size_t i = 0; i < n; i++)
        add128(&into->sum[i], from->sum[i].hi, from->sum[i].lo);
}

double rt_splat_value(rt_splat_sum s)
{
    /* hi read as signed: the conversion of an out-of-range unsigned value
     * to int64_t is implementation-defined, so it is spelled out. */
    double hi = s.hi >> 63 ? -(double)(~s.hi) - 1.0 : (double)s.hi;
    return hi + (double)s.lo * 0x1p-64;
}

void rt_splats_add_to_image(const rt_splats *s, uint64_t n, rt_image *img)
{
    if (n == 0)
        return;
    size_t npix = (size_t)s->width * (size_t)s->height;
    for (size_t i = 0; i < npix; i++)
        for (int ch = 0; ch < 3; ch++)
            img->px[i].mean[ch] += rt_splat_value(s->sum[3 * i + (size_t)ch]) / (double)n;
}
