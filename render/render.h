/* render/render.h - rendering a whole image with OpenMP threads.
 *
 * The image loop of every chapter of Shirley's "Ray Tracing: The Rest of
 * Your Life" (v1.123),
 * made reproducible and interruptible:
 * - Pixel samples are jittered (this book's #ch-pi) on the grid of
 *   mc/strat.h: for spp samples, the largest sx x sy <= spp grid of cells,
 *   each cell holding one uniform point, then spp - sx sy plain uniform
 *   points. Every point traced is counted, so sample count and divisor
 *   agree for any spp (the book traces floor(sqrt(spp))^2 and divides by
 *   spp). The cells are visited in a scrambled order (a stride coprime to
 *   the cell count), so that any prefix of a pixel's samples is spread over
 *   the pixel.
 * - Each pixel draws from its own stream mc_rng_derive(seed, pixel index),
 *   and each pixel's samples are added in a fixed order: the image is
 *   bit-identical for any number of threads. That is the stratified
 *   sampler; rt_render_job.sampler may instead draw every uniform from
 *   the stream (independent) or from Owen-scrambled Sobol points hashed
 *   from (seed, pixel, dimension) (sobol), which depend on the sample's
 *   index alone and are as reproducible (render/sampler.h); the default
 *   is the strategy's best (rt_render_sampler_kind).
 * - The samples are taken in passes over the whole image, so a render
 *   stopped early (the cancel flag, checked between image rows) still holds
 *   a complete picture in which each pixel's mean is unbiased: the rows
 *   finished in the interrupted pass have one pass more samples than the
 *   others, and the caller reports the total sample count actually taken.
 * - The book's integrator (strategies uniform, cosine, mixture) advances
 *   four paths together, one pixel per lane, tracing their segments with
 *   one four-ray query and evaluating their light densities in vector
 *   lanes (render/fast/rows.h); each pixel still consumes its own stream in the same
 *   order, so the image is the one of one path at a time, bit for bit
 *   (rt_render_job.one_path_at_a_time keeps that reference). So does
 *   every sampler.
 * One driver (render/drive.c) owns the loop for every strategy: the
 * passes, the streams, the rows shared by the threads, cancel, progress
 * and statistics; the row kernels of render/row.h (one path at a time,
 * four at a time, light paths that splat) render the samples.
 * Library code never prints; progress goes to a caller's callback.
 */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#include "render/camera.h"
#include "render/image.h"
#include "render/integrator.h"
#include "render/sampler.h"
#include "render/scene.h"
#include "render/splat.h"

/* How far a render has got. */
typedef struct rt_progress {
    uint64_t paths_done, paths_total;
    uint64_t segments_done;
} rt_progress;

/* Called after every finished image row of every pass, from whichever
 * thread finished it, one call at a time. */
typedef void (*rt_progress_fn)(void *ctx, const rt_progress *p);

typedef struct rt_render_job {
    const rt_scene *scene; /* built */
    rt_camera camera;      /* its width and height must equal the image's */
    rt_path_settings path;
    uint64_t spp;          /* samples per pixel, >= 1 */
    uint64_t seed;
    int threads;           /* 0: OpenMP's default */
    uint64_t pass_spp;     /* samples per pixel per pass; 0: about 16 */
    rt_progress_fn progress;
    void *progress_ctx;
    const atomic_int *cancel; /* may be NULL; nonzero stops the render */
    /* The book's integrator (rt_path_steppable) traces four paths
     * together, one pixel per lane (render/fast/rows.h), and the
     * strategies that splat trace their shadow rays four at a time
     * (render/bdpt_internal.h); true traces one path, one shadow ray, at a
     * time instead: the same image bit for bit, kept as the reference the
     * tests compare against. */
    bool one_path_at_a_time;
    rt_sampler_kind sampler; /* zero: stratified; sobol needs spp < 2^32 */
} rt_render_job;

typedef struct rt_render_stats {
    uint64_t paths;    /* samples taken (finite and dropped) */
    uint64_t segments; /* rays traced, shadow rays included */
    uint64_t dropped;  /* non-finite samples left out */
    double seconds;    /* wall time */
    bool cancelled;    /* stopped by the cancel flag */
} rt_render_stats;

/* A job with the book's defaults for the scene and camera: strategy
 * mixture, max depth 50, 100 spp, seed 1, all threads, the strategy's
 * default sampler (RT_SAMPLER_DEFAULT). */
rt_render_job rt_render_job_default(const rt_scene *scene, rt_camera camera);

/* The sampler the job renders with: job->sampler, or for
 * RT_SAMPLER_DEFAULT the strategy's, the one `make bench` measures best
 * at equal error: sobol for bdpt, mis and lighttrace, stratified for
 * uniform, cosine, light and mixture (and wherever spp >= 2^32). */
rt_sampler_kind rt_render_sampler_kind(const rt_render_job *job);

/* Clears img and renders job into it; *stats (may be NULL) receives the
 * totals. Returns 0 when complete, 1 when cancelled (img then holds
 * stats->paths samples), -1 on bad arguments or out of memory. */
int rt_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats);

/* The sampler of pixel `pixel` of the job, continuing its stream rng
 * (for the row loops). */
rt_sampler rt_render_sampler(const rt_render_job *job, mc_rng rng, uint64_t pixel);

/* rt_render restricted to the rows first, first + step, ... of the image
 * (0 <= first < height, 1 <= step <= height), the others left without samples. A
 * pixel's samples and stream do not depend on which rows are rendered
 * with it, so each of its pixels is the one rt_render makes, bit for bit:
 * P processes taking first = 0 .. P-1 with step P render disjoint rows of
 * the same image. Progress and stats count these rows only. Strategies
 * that splat (rt_strategy_splats: light tracing, bidirectional) need the
 * whole image: -1 unless first = 0 and step = 1 (rt_render_part splits
 * them). */
int rt_render_rows(const rt_render_job *job, rt_image *img, int first, int step, rt_render_stats *stats);

/* rt_render_rows for any strategy, with the splats kept apart: for a
 * strategy that splats, splats (the image's size) is cleared and receives
 * the exact sums of the light paths of these rows (render/splat.h), and
 * img only the pixel samples of these rows; NULL is fine otherwise, and
 * left alone. P processes each render their rows, add their splats
 * (rt_splats_merge, in any order: the sums are exact), and divide by the
 * light paths of all of them together, the sum of their stats->paths
 * (rt_splats_add_to_image): the image of one process, bit for bit. */
int rt_render_part(const rt_render_job *job, rt_image *img, int first, int step, rt_splats *splats,
                   rt_render_stats *stats);

#endif /* RT_RENDER_H */
