/* render/lighttrace.h - rendering with splats: the image loop of the
 * strategies that join light subpaths to the camera (render/bdpt.h).
 *
 * "The noisy caustic", the chapter after the Cornell box chapters of "Ray
 * Tracing: The Rest of Your Life": a path started on the lamp lands where
 * it lands, and the camera sees it in whichever pixel that is; its
 * contribution is added there (a splat), not to the pixel whose sample
 * started it. The loop keeps the promises of render/render.h:
 * - Each pixel sample traces its camera subpath and one light subpath from
 *   the pixel's own sampler (render/sampler.h), in passes over the image.
 * - Splats go to one of RT_SPLAT_BUFFERS buffers, chosen by the image row
 *   whose samples made them (row y: buffer y mod RT_SPLAT_BUFFERS); the
 *   rows of one buffer are rendered in order by one thread at a time, and
 *   the buffers are added to the image in a fixed order at the end: the
 *   image is bit-identical for any number of threads.
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

#include "render/image.h"
#include "render/render.h"

/* How many splat buffers a render keeps (each a double per pixel and
 * channel): also the most threads that render at once. */
#define RT_SPLAT_BUFFERS 8

/* rt_render for a job whose strategy splats (rt_strategy_splats), with
 * the same contract; also -1 when job->path.max_depth exceeds
 * RT_BDPT_MAX_DEPTH. */
int rt_splat_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats);

#endif /* RT_LIGHTTRACE_H */
