/* render/fast/rows.h - the book's integrator four paths at a time.
 *
 * The reference row loop (render/render.c) traces one path after the
 * other, and each path's segments are a chain in which every step waits
 * for the last. This loop gives each of RT_LANES lanes a pixel of the row
 * and advances the four paths together: their segments in one four-ray
 * query (render/fast/hit4.h), their light densities in the lanes of one
 * vector (render/fast/lights4.h). Each pixel consumes its own stream in
 * the same order as in the reference, so the image is the same bit for
 * bit (tests/test_render_image.c compares them).
 */
#ifndef RT_FAST_ROWS_H
#define RT_FAST_ROWS_H

#include <stdint.h>

#include "mc/rng.h"
#include "render/image.h"
#include "render/jitter.h"
#include "render/render.h"

/* Samples [k0, k1) of every pixel of row y of img, for a job whose
 * strategy runs the book's integrator (rt_path_steppable); streams[i] is
 * pixel i's stream, c0 the cell of sample k0. Adds the rays traced to
 * *segments and the non-finite samples left out to *dropped. */
void rt_fast_render_row(const rt_render_job *job, rt_image *img, mc_rng *streams,
                        const rt_jitter *jt, int y, uint64_t k0, uint64_t k1, rt_cell c0,
                        uint64_t *segments, uint64_t *dropped);

#endif /* RT_FAST_ROWS_H */
