/* render/render.c - passes over the image, rows shared by OpenMP threads. */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "render/fast/rows.h"
#include "render/jitter.h"
#include "render/lighttrace.h"

rt_render_job rt_render_job_default(const rt_scene *scene, rt_camera camera)
{
    /* The rest zero: all threads, passes of about 16, no progress, no
     * cancel flag, four paths at a time, the stratified sampler. */
    return (rt_render_job){
        .scene = scene,
        .camera = camera,
        .path = rt_path_settings_default(RT_MIXTURE),
        .spp = 100,
        .seed = 1,
    };
}

/* Samples [k0, k1) of every pixel of row y; c0 is the cell of sample k0. */
/* BEGIN SNIPPET render_row */
static void render_row(const rt_render_job *job, rt_image *img, mc_rng *streams, const rt_jitter *jt,
                       int y, uint64_t k0, uint64_t k1, rt_cell c0, uint64_t *segments,
                       uint64_t *dropped)
{
    int w = img->width;
    for (int x = 0; x < w; x++) {
        size_t idx = (size_t)y * (size_t)w + (size_t)x;
        rt_sampler sampler = rt_render_sampler(job, streams[idx], idx);
        rt_pixel *px = &img->px[idx];
        rt_cell c = c0;
        for (uint64_t k = k0; k < k1; k++) {
            rt_ray r = rt_sample_ray(&job->camera, jt, x, y, k, &c, &sampler);
            vec3 L = rt_radiance(job->scene, &job->path, r, &sampler, segments);
            if (!rt_pixel_add(px, L))
                ++*dropped;
        }
        streams[idx] = sampler.rng;
    }
}
/* END SNIPPET render_row */

typedef struct totals {
    uint64_t paths, segments, dropped;
    int cancelled;
} totals;

/* One pass: samples [k0, k1) of every pixel of rows first, first + step,
 * ..., rows handed out in order. */
static void render_pass(const rt_render_job *job, rt_image *img, mc_rng *streams, const rt_jitter *jt,
                        uint64_t k0, uint64_t k1, int first, int step, totals *tot)
{
    rt_cell c0 = rt_jitter_cell(jt, k0);
    int next_row = first, nt = job->threads > 0 ? job->threads : omp_get_max_threads();
    uint64_t rows = (uint64_t)((img->height - first + step - 1) / step);
    uint64_t total = job->spp * (uint64_t)img->width * rows;
    /* BEGIN SNIPPET render_pass_rows */
#pragma omp parallel num_threads(nt)
    for (;;) {
        int y;
#pragma omp atomic capture
        { y = next_row; next_row += step; }
        if (y >= img->height)
            break;
        if (job->cancel && atomic_load(job->cancel)) {
#pragma omp atomic write
            tot->cancelled = 1;
            break;
        }
        uint64_t seg = 0, drop = 0, paths = (k1 - k0) * (uint64_t)img->width;
        if (rt_path_steppable(&job->path) && !job->one_path_at_a_time)
            rt_fast_render_row(job, img, streams, jt, y, k0, k1, c0, &seg, &drop);
        else
            render_row(job, img, streams, jt, y, k0, k1, c0, &seg, &drop);
        /* END SNIPPET render_pass_rows */
#pragma omp atomic
        tot->segments += seg;
#pragma omp atomic
        tot->dropped += drop;
#pragma omp atomic
        tot->paths += paths;
        if (job->progress) {
#pragma omp critical(rt_render_progress)
            {
                rt_progress p = {0, total, 0};
#pragma omp atomic read
                p.paths_done = tot->paths;
#pragma omp atomic read
                p.segments_done = tot->segments;
                job->progress(job->progress_ctx, &p);
            }
        }
    }
}

rt_sampler rt_render_sampler(const rt_render_job *job, mc_rng rng, uint64_t pixel)
{
    rt_sampler s = rt_sampler_pixel(job->sampler, job->seed, job->spp, rng, pixel);
    s.reuse_dim = job->path.neg.sampler_reuse_dim;
    return s;
}

int rt_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats)
{
    return rt_render_rows(job, img, 0, 1, stats);
}

int rt_render_rows(const rt_render_job *job, rt_image *img, int first, int step, rt_render_stats *stats)
{
    /* A light path splats onto any pixel: its renderer takes the whole image. */
    if (rt_strategy_splats(job->path.strategy))
        return first == 0 && step == 1 ? rt_splat_render(job, img, stats) : -1;
    if (!job->scene || job->spp < 1 || job->camera.width != img->width ||
        job->camera.height != img->height || job->path.max_depth < 0 ||
        (job->sampler == RT_SAMPLER_SOBOL && job->spp > UINT32_MAX) || step < 1 ||
        step > img->height || first < 0 || first >= img->height)
        return -1;
    /* BEGIN SNIPPET render_streams */
    size_t npix = (size_t)img->width * (size_t)img->height;
    mc_rng *streams = malloc(npix * sizeof *streams);
    if (!streams)
        return -1;
    for (size_t i = 0; i < npix; i++)
        streams[i] = mc_rng_derive(job->seed, (uint64_t)i);
    rt_image_clear(img);
    rt_jitter jt = job->sampler == RT_SAMPLER_STRATIFIED ? rt_jitter_make(job->spp) : rt_jitter_none();
    /* Passes of at most 16 samples per pixel keep a row short enough for
     * the cancel flag to be answered within milliseconds. */
    uint64_t per = job->pass_spp ? job->pass_spp : (job->spp < 16 ? job->spp : 16);
    uint64_t passes = (job->spp + per - 1) / per, base = job->spp / passes, extra = job->spp % passes;
    totals tot = {0, 0, 0, 0};
    double t0 = omp_get_wtime();
    /* Pass p takes base samples, one more for the first `extra` passes. */
    for (uint64_t p = 0, k0 = 0; p < passes && !tot.cancelled; p++) {
        uint64_t k1 = k0 + base + (p < extra ? 1 : 0);
        render_pass(job, img, streams, &jt, k0, k1, first, step, &tot);
        k0 = k1;
    }
    /* END SNIPPET render_streams */
    free(streams);
    if (stats) {
        stats->paths = tot.paths;
        stats->segments = tot.segments;
        stats->dropped = tot.dropped;
        stats->seconds = omp_get_wtime() - t0;
        stats->cancelled = tot.cancelled != 0;
    }
    return tot.cancelled ? 1 : 0;
}
