/* render/lighttrace.h - rendering with splats: the image loop of the
 * strategies that join light subpaths to the camera (render/bdpt.h).
 *
 * "The noisy caustic", the chapter after the Cornell box chapters of "Ray
 * Tracing: The Rest of Your Life": a path started on the lamp lands where
 * it lands, and the camera sees it in whichever pixel that is; its
 * contribution is added there (a splat), not to the pixel whose sample
 * started it. The driver (render/drive.c) keeps the promises of
 * render/render.h for these strategies too:
 * - Each pixel sample traces its camera subpath and one light subpath from
 *   the pixel's own sampler (render/sampler.h), in passes over the image,
 *   with the row kernel rt_row_splat (render/row.h).
 * - Splats go to the sums of the thread that rendered the row, exact
 *   fixed-point sums (render/splat.h) that do not depend on the order of
 *   their terms; at the end the threads' sums (and, under MPI, the
 *   processes') are added and divided by the number of light paths: the
 *   image is bit-identical for any number of threads and processes.
 * - The cancel flag is read between rows; the N light paths of the rows
 *   finished make an unbiased estimate of every pixel (each light path
 *   estimates the whole image), so a stopped render divides the splats by
 *   that N and keeps a complete picture.
 * A pixel's value is the mean of its own samples (the strategies with
 * t >= 2 camera vertices) plus the splats it received divided by N. Its
 * m2 holds the variance of its own samples only (the splats' is not
 * tracked).
 */
#ifndef RT_LIGHTTRACE_H
#define RT_LIGHTTRACE_H

#include "render/row.h"

/* The most splat sums a render keeps, one per thread (48 bytes per pixel
 * each): also the most threads that render these strategies at once. */
#define RT_SPLAT_BUFFERS 8

/* The sets of splat sums (and threads) of a render that would use
 * `threads` threads (>= 1). */
static inline int rt_splat_sets(int threads)
{
    return threads < RT_SPLAT_BUFFERS ? threads : RT_SPLAT_BUFFERS;
}

/* The splat kernel (render/row.h), for a job whose strategy splats
 * (rt_strategy_splats): each pixel sample's camera subpath goes to its
 * pixel, its light subpath's splats to r->splats. */
rt_row_counts rt_row_splat(const rt_row *r);

#endif /* RT_LIGHTTRACE_H */
