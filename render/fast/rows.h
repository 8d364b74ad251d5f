/* render/fast/rows.h - the book's integrator four paths at a time.
 *
 * The reference row kernel (render/row.c) traces one path after the
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

#include "render/row.h"

/* The row kernel (render/row.h) for a job whose strategy runs the book's
 * integrator (rt_path_steppable): rt_row_reference's samples, streams and
 * pixels, bit for bit. */
rt_row_counts rt_fast_render_row(const rt_row *r);

#endif /* RT_FAST_ROWS_H */
