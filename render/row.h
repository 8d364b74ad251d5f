/* render/row.h - what the driver (render/drive.c) hands a row kernel.
 *
 * The driver owns everything about the image loop: the passes, the
 * per-pixel streams, which thread renders which row, cancel, progress and
 * statistics. A kernel renders samples [k0, k1) of every pixel of one
 * row, consuming each pixel's stream in sample order and leaving it where
 * the next pass continues; it never sees the other rows. Three kernels:
 * - rt_row_reference (render/row.c): one path after the other, every
 *   strategy that does not splat;
 * - rt_fast_render_row (render/fast/rows.h): the book's integrator four
 *   paths at a time, the same bits;
 * - rt_row_splat (render/lighttrace.h): light tracing and bidirectional
 *   path tracing, whose light paths splat onto any pixel.
 * Internal to the renderer; programs call render/render.h.
 */
#ifndef RT_ROW_H
#define RT_ROW_H

#include <stdbool.h>
#include <stdint.h>

#include "mc/rng.h"
#include "render/bdpt.h"
#include "render/image.h"
#include "render/jitter.h"
#include "render/render.h"
#include "render/splat.h"

typedef struct rt_row {
    const rt_render_job *job;
    rt_image *img;
    mc_rng *streams;      /* pixel i's stream, row major */
    const rt_jitter *jt;
    int y;                /* the row */
    uint64_t k0, k1;      /* the samples of this pass */
    rt_cell c0;           /* the jitter cell of sample k0 */
    /* The splat kernel only: */
    const rt_bdpt_ctx *ctx;
    bool *edges;          /* per pixel: the seen term's edge (render/bdpt.h) */
    rt_splats *splats;    /* this thread's sums, of the whole image */
} rt_row;

/* What a kernel did: rays traced (shadow rays included) and non-finite
 * samples left out. */
typedef struct rt_row_counts {
    uint64_t segments, dropped;
} rt_row_counts;

/* The reference kernel: samples [k0, k1) of every pixel of row y, one
 * path at a time (rt_radiance). */
rt_row_counts rt_row_reference(const rt_row *r);

#endif /* RT_ROW_H */
