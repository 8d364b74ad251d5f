/* render/jitter.h - where in a pixel each of its samples looks.
 *
 * The stratification ("jittering") of this book's #ch-pi applied to the
 * pixels of the Cornell box: for spp samples, the largest sx x sy <= spp grid of cells
 * (mc/strat.h), each cell holding one uniform point, then spp - sx sy
 * plain uniform points. The cells are visited in a scrambled order (a
 * stride coprime to the cell count), so that any prefix of a pixel's
 * samples is spread over the pixel. Shared by the reference row loop
 * (render/row.c), the fast one (render/fast/rows.c) and the splat one
 * (render/lighttrace.c). The samplers
 * other than the default stratified one (render/sampler.h) use no cells:
 * their pixel position is the sampler's first 2D as it is.
 */
#ifndef RT_JITTER_H
#define RT_JITTER_H

#include <math.h>
#include <stdint.h>

#include "render/camera.h"
#include "render/sampler.h"

/* The pixel's stratification: sx x sy cells, m = sx sy of them, visited
 * as cell (k stride) mod m for sample k < m; cell c is column c mod sx of
 * row c / sx. */
typedef struct rt_jitter {
    uint64_t sx, sy, m, stride;
    uint64_t stride_i, stride_j; /* the stride's column and row */
} rt_jitter;

/* A cell as its column i and row j, so that moving on by the stride
 * needs no division. */
typedef struct rt_cell {
    uint64_t i, j;
} rt_cell;

/* The stratification of spp >= 1 samples. */
rt_jitter rt_jitter_make(uint64_t spp);

/* No cells (m = 0): every pixel position is a plain uniform point. */
rt_jitter rt_jitter_none(void);

/* The cell of sample k (the first cell for k >= m). */
rt_cell rt_jitter_cell(const rt_jitter *jt, uint64_t k);

/* A coordinate in [0, 1) from cell i of n and a uniform u. */
static inline double rt_jitter_in_cell(uint64_t i, uint64_t n, double u)
{
    double x = ((double)i + u) / (double)n;
    return x < 1.0 ? x : nextafter(1.0, 0.0);
}

/* The camera ray of sample k of pixel (x, y), which begins the sample in
 * the pixel's sampler: a point of its cell c while k < m (c then moves on
 * by the stride), a uniform point after. The two uniforms are the
 * sampler's first 2D. Inline: it starts every path. */
RT_HOT_INLINE rt_ray rt_sample_ray(const rt_camera *camera, const rt_jitter *jt, int x, int y,
                                   uint64_t k, rt_cell *c, rt_sampler *sampler)
{
    /* BEGIN SNIPPET sample_ray */
    double u1, u2;
    rt_sampler_start(sampler, k);
    rt_sampler_2d(sampler, &u1, &u2);
    double jx = u1, jy = u2;
    if (k < jt->m) {
        jx = rt_jitter_in_cell(c->i, jt->sx, u1);
        jy = rt_jitter_in_cell(c->j, jt->sy, u2);
        /* c + stride, then minus m if that reaches m: the column carries
         * into the row, and the row (below 2 sy, since c and the stride
         * are below m) wraps at most once. */
        uint64_t i = c->i + jt->stride_i, carry = i >= jt->sx;
        uint64_t j = c->j + jt->stride_j + carry;
        c->i = carry ? i - jt->sx : i;
        c->j = j >= jt->sy ? j - jt->sy : j;
    }
    return rt_camera_ray(camera, (double)x + jx, (double)y + jy);
    /* END SNIPPET sample_ray */
}

#endif /* RT_JITTER_H */
