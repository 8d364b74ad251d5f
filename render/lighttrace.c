/* render/lighttrace.c - passes over the image, rows grouped by splat
 * buffer, the buffers reduced in a fixed order. */
#include "render/lighttrace.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "render/bdpt.h"
#include "render/jitter.h"

/* What the rows of one buffer have done so far. */
typedef struct lane_totals {
    uint64_t paths, segments, dropped;
} lane_totals;

/* Samples [k0, k1) of every pixel of row y; the splats go to splat. */
static void splat_row(const rt_render_job *job, const rt_bdpt_ctx *ctx, rt_image *img,
                      mc_rng *streams, bool *edges, const rt_jitter *jt, int y, uint64_t k0,
                      uint64_t k1, rt_cell c0, double *splat, lane_totals *lt)
{
    int w = img->width;
    bool weighted = rt_bdpt_weighted(&job->path);
    for (int x = 0; x < w; x++) {
        size_t idx = (size_t)y * (size_t)w + (size_t)x;
        rt_sampler sampler = rt_render_sampler(job, streams[idx], idx);
        rt_cell c = c0;
        /* The weighted sum leaves out the paths E S* L: the seen term
         * (render/bdpt.h), for which the first pass finds the edges. */
        if (weighted && k0 == 0)
            edges[idx] = rt_bdpt_seen_edge(ctx, x, y, job->seed, &lt->segments);
        for (uint64_t k = k0; k < k1; k++) {
            rt_ray r = rt_sample_ray(&job->camera, jt, x, y, k, &c, &sampler);
            mc_rng aux = rt_bdpt_aux_stream(job->seed, (uint64_t)idx * job->spp + k);
            vec3 L = rt_bdpt_sample(ctx, r, &sampler, &aux, weighted && !edges[idx], splat,
                                    &lt->segments);
            if (weighted && edges[idx])
                L = vec3_add(L, rt_bdpt_seen_sample(ctx, x, y, &aux, &lt->segments));
            if (!rt_pixel_add(&img->px[idx], L))
                lt->dropped++;
        }
        streams[idx] = sampler.rng;
    }
    lt->paths += (k1 - k0) * (uint64_t)w;
}

/* Reports progress after a row (one call at a time). */
static void progress(const rt_render_job *job, const lane_totals *lanes, int nb, uint64_t total)
{
    if (!job->progress)
        return;
#pragma omp critical(rt_splat_progress)
    {
        rt_progress p = {0, total, 0};
        for (int b = 0; b < nb; b++) {
            uint64_t a, s;
#pragma omp atomic read
            a = lanes[b].paths;
#pragma omp atomic read
            s = lanes[b].segments;
            p.paths_done += a;
            p.segments_done += s;
        }
        job->progress(job->progress_ctx, &p);
    }
}

/* One pass: samples [k0, k1) of every pixel. Buffer b's rows are b,
 * b + nb, ..., rendered in that order by one thread at a time; a thread
 * takes the next row of the free buffer with the most rows left, so that
 * the buffers finish together and no thread waits long for another at the
 * end of the pass (with a whole buffer as the unit, two threads sharing
 * eight buffers left one of them idle for part of the pass). Returns
 * whether the cancel flag stopped it. */
static bool splat_pass(const rt_render_job *job, const rt_bdpt_ctx *ctx, rt_image *img,
                       mc_rng *streams, bool *edges, const rt_jitter *jt, uint64_t k0, uint64_t k1,
                       double *splat, lane_totals *lanes, int nb)
{
    rt_cell c0 = rt_jitter_cell(jt, k0);
    int nt = job->threads > 0 ? job->threads : omp_get_max_threads(), cancelled = 0;
    size_t npix = (size_t)img->width * (size_t)img->height;
    uint64_t total = job->spp * (uint64_t)npix;
    int next[RT_SPLAT_BUFFERS];
    bool busy[RT_SPLAT_BUFFERS];
    for (int b = 0; b < nb; b++) {
        next[b] = b;
        busy[b] = false;
    }
    nt = nt < nb ? nt : nb;
#pragma omp parallel num_threads(nt)
    for (int b = -1;;) {
        int y = -1;
        bool stop = job->cancel && atomic_load(job->cancel);
#pragma omp critical(rt_splat_pick)
        {
            if (b >= 0)
                busy[b] = false;
            b = -1;
            for (int i = 0, most = 0; i < nb && !stop; i++) {
                int left = next[i] < img->height ? (img->height - next[i] + nb - 1) / nb : 0;
                if (!busy[i] && left > most) {
                    most = left;
                    b = i;
                }
            }
            if (b >= 0) {
                y = next[b];
                next[b] += nb;
                busy[b] = true;
            }
        }
        if (stop) {
#pragma omp atomic write
            cancelled = 1;
        }
        if (b < 0)
            break;
        lane_totals lt = lanes[b];
        splat_row(job, ctx, img, streams, edges, jt, y, k0, k1, c0, splat + (size_t)b * 3 * npix, &lt);
#pragma omp atomic write
        lanes[b].paths = lt.paths;
#pragma omp atomic write
        lanes[b].segments = lt.segments;
        lanes[b].dropped = lt.dropped;
        progress(job, lanes, nb, total);
    }
    return cancelled != 0;
}

/* Adds the buffers, in order, to the pixels: splat / n_light each. */
/* BEGIN SNIPPET splat_reduce */
static void reduce(rt_image *img, const double *splat, int nb, uint64_t n_light)
{
    size_t npix = (size_t)img->width * (size_t)img->height;
    for (size_t i = 0; i < npix; i++) {
        double sum[3] = {0.0, 0.0, 0.0};
        for (int b = 0; b < nb; b++)
            for (int ch = 0; ch < 3; ch++)
                sum[ch] += splat[(size_t)b * 3 * npix + 3 * i + (size_t)ch];
        rt_pixel *px = &img->px[i];
        for (int ch = 0; ch < 3; ch++)
            px->mean[ch] += n_light ? sum[ch] / (double)n_light : 0.0;
    }
}
/* END SNIPPET splat_reduce */

int rt_splat_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats)
{
    if (!job->scene || job->spp < 1 || job->camera.width != img->width ||
        job->camera.height != img->height || job->path.max_depth < 0 ||
        job->path.max_depth > RT_BDPT_MAX_DEPTH ||
        (job->sampler == RT_SAMPLER_SOBOL && job->spp > UINT32_MAX))
        return -1;
    size_t npix = (size_t)img->width * (size_t)img->height;
    int nb = img->height < RT_SPLAT_BUFFERS ? img->height : RT_SPLAT_BUFFERS;
    mc_rng *streams = malloc(npix * sizeof *streams);
    bool *edges = calloc(npix, sizeof *edges);
    double *splat = calloc((size_t)nb * 3 * npix, sizeof *splat);
    lane_totals *lanes = calloc((size_t)nb, sizeof *lanes);
    if (!streams || !edges || !splat || !lanes) {
        free(streams);
        free(edges);
        free(splat);
        free(lanes);
        return -1;
    }
    for (size_t i = 0; i < npix; i++)
        streams[i] = mc_rng_derive(job->seed, (uint64_t)i);
    rt_image_clear(img);
    rt_jitter jt = job->sampler == RT_SAMPLER_STRATIFIED ? rt_jitter_make(job->spp) : rt_jitter_none();
    rt_bdpt_ctx ctx = rt_bdpt_ctx_make(job->scene, &job->path, &job->camera);
    /* Passes as in render/render.c. */
    uint64_t per = job->pass_spp ? job->pass_spp : (job->spp < 16 ? job->spp : 16);
    uint64_t passes = (job->spp + per - 1) / per, base = job->spp / passes, extra = job->spp % passes;
    bool cancelled = false;
    double t0 = omp_get_wtime();
    for (uint64_t p = 0, k0 = 0; p < passes && !cancelled; p++) {
        uint64_t k1 = k0 + base + (p < extra ? 1 : 0);
        cancelled = splat_pass(job, &ctx, img, streams, edges, &jt, k0, k1, splat, lanes, nb);
        k0 = k1;
    }
    lane_totals tot = {0, 0, 0};
    for (int b = 0; b < nb; b++) {
        tot.paths += lanes[b].paths;
        tot.segments += lanes[b].segments;
        tot.dropped += lanes[b].dropped;
    }
    /* Every pixel sample traced one light subpath. */
    reduce(img, splat, nb, tot.paths);
    free(streams);
    free(edges);
    free(splat);
    free(lanes);
    if (stats) {
        stats->paths = tot.paths;
        stats->segments = tot.segments;
        stats->dropped = tot.dropped;
        stats->seconds = omp_get_wtime() - t0;
        stats->cancelled = cancelled;
    }
    return cancelled ? 1 : 0;
}
