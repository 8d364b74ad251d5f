/* render/drive.c - the one loop over the image: passes, per-pixel
 * streams, rows shared by OpenMP threads, cancel, progress and
 * statistics, for every strategy; the row kernels of render/row.h do the
 * rest. The four-lane kernel comes through the one door to render/fast/,
 * render/engine.h. */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "render/engine.h"
#include "render/jitter.h"
#include "render/lighttrace.h"
#include "render/row.h"

typedef rt_row_counts (*row_kernel)(const rt_row *r);

/* What the rows of a render have done so far; read by any thread for the
 * progress report, so written and read atomically. */
typedef struct totals {
    uint64_t paths, segments, dropped;
    int cancelled;
} totals;

/* One render: its job, its kernel and what every row shares. */
typedef struct drive {
    const rt_render_job *job;
    rt_image *img;
    mc_rng *streams;
    rt_jitter jt;
    row_kernel kernel;
    int first, step, threads;
    /* Strategies that splat: the context, the seen term's edges and one
     * set of sums per thread (splats[0] is the caller's). */
    rt_bdpt_ctx ctx;
    bool *edges;
    rt_splats **splats;
    totals tot;
} drive;

static void report(const drive *d, uint64_t total)
{
    const rt_render_job *job = d->job;
    if (!job->progress)
        return;
#pragma omp critical(rt_render_progress)
    {
        rt_progress p = {0, total, 0};
#pragma omp atomic read
        p.paths_done = d->tot.paths;
#pragma omp atomic read
        p.segments_done = d->tot.segments;
        job->progress(job->progress_ctx, &p);
    }
}

/* One pass: samples [k0, k1) of every pixel of the rows first,
 * first + step, ...; the threads take the rows from a shared counter, in
 * order, as they come. Which thread renders a row changes nothing in it:
 * a row's pixels and streams are its own, and its splats go into exact
 * sums (render/splat.h). */
static void pass(drive *d, uint64_t k0, uint64_t k1)
{
    const rt_render_job *job = d->job;
    rt_image *img = d->img;
    rt_cell c0 = rt_jitter_cell(&d->jt, k0);
    int next_row = d->first, step = d->step;
    uint64_t rows = (uint64_t)((img->height - d->first + step - 1) / step);
    uint64_t total = job->spp * (uint64_t)img->width * rows;
    /* BEGIN SNIPPET render_pass_rows */
#pragma omp parallel num_threads(d->threads)
    for (;;) {
        int y;
#pragma omp atomic capture
        { y = next_row; next_row += step; }
        if (y >= img->height)
            break;
        if (job->cancel && atomic_load(job->cancel)) {
#pragma omp atomic write
            d->tot.cancelled = 1;
            break;
        }
        rt_row row = {job, img, d->streams, &d->jt, y, k0, k1, c0, &d->ctx, d->edges,
                      d->splats ? d->splats[omp_get_thread_num()] : NULL};
        rt_row_counts n = d->kernel(&row);
        /* END SNIPPET render_pass_rows */
#pragma omp atomic
        d->tot.segments += n.segments;
#pragma omp atomic
        d->tot.dropped += n.dropped;
#pragma omp atomic
        d->tot.paths += (k1 - k0) * (uint64_t)img->width;
        report(d, total);
    }
}

/* The kernel of job: the splat kernel for the strategies that splat, the
 * four-lane one for the book's integrator (unless the job asks for one
 * path at a time), else the reference. */
static row_kernel kernel_of(const rt_render_job *job)
{
    if (rt_strategy_splats(job->path.strategy))
        return rt_row_splat;
    if (rt_path_steppable(&job->path) && !job->one_path_at_a_time)
        return rt_engine_get()->row4;
    return rt_row_reference;
}

static bool job_ok(const rt_render_job *job, const rt_image *img, int first, int step,
                   const rt_splats *splats)
{
    bool splatting = rt_strategy_splats(job->path.strategy);
    return job->scene && job->spp >= 1 && job->camera.width == img->width &&
           job->camera.height == img->height && job->path.max_depth >= 0 &&
           !(splatting && job->path.max_depth > RT_BDPT_MAX_DEPTH) &&
           !(rt_render_sampler_kind(job) == RT_SAMPLER_SOBOL && job->spp > UINT32_MAX) &&
           step >= 1 && step <= img->height && first >= 0 && first < img->height &&
           (!splatting || (splats && splats->width == img->width && splats->height == img->height));
}

/* The splat sums of every thread but the first, which is the caller's;
 * false when out of memory. */
static bool splats_make(drive *d, rt_splats *theirs)
{
    int nt = rt_splat_sets(d->threads);
    size_t npix = (size_t)d->img->width * (size_t)d->img->height;
    d->threads = nt;
    d->splats = calloc((size_t)nt, sizeof *d->splats);
    d->edges = calloc(npix, sizeof *d->edges);
    if (!d->splats || !d->edges)
        return false;
    rt_splats_clear(theirs);
    d->splats[0] = theirs;
    for (int t = 1; t < nt; t++)
        if (!(d->splats[t] = rt_splats_create(d->img->width, d->img->height)))
            return false;
    d->ctx = rt_bdpt_ctx_make(d->job->scene, &d->job->path, &d->job->camera);
    d->ctx.one_ray_at_a_time = d->job->one_path_at_a_time;
    return true;
}

static void splats_free(drive *d)
{
    for (int t = 1; d->splats && t < d->threads; t++)
        rt_splats_destroy(d->splats[t]);
    free(d->splats);
    free(d->edges);
}

int rt_render_part(const rt_render_job *job, rt_image *img, int first, int step, rt_splats *splats,
                   rt_render_stats *stats)
{
    if (!job_ok(job, img, first, step, splats))
        return -1;
    drive d = {.job = job, .img = img, .kernel = kernel_of(job), .first = first, .step = step};
    d.threads = job->threads > 0 ? job->threads : omp_get_max_threads();
    /* BEGIN SNIPPET render_streams */
    size_t npix = (size_t)img->width * (size_t)img->height;
    d.streams = malloc(npix * sizeof *d.streams);
    bool ok = d.streams && (d.kernel != rt_row_splat || splats_make(&d, splats));
    if (!ok) {
        free(d.streams);
        splats_free(&d);
        return -1;
    }
    for (size_t i = 0; i < npix; i++)
        d.streams[i] = mc_rng_derive(job->seed, (uint64_t)i);
    rt_image_clear(img);
    d.jt = rt_render_sampler_kind(job) == RT_SAMPLER_STRATIFIED ? rt_jitter_make(job->spp)
                                                                : rt_jitter_none();
    /* Passes of at most 16 samples per pixel keep a row short enough for
     * the cancel flag to be answered within milliseconds. */
    uint64_t per = job->pass_spp ? job->pass_spp : (job->spp < 16 ? job->spp : 16);
    uint64_t passes = (job->spp + per - 1) / per, base = job->spp / passes, extra = job->spp % passes;
    double t0 = omp_get_wtime();
    /* Pass p takes base samples, one more for the first `extra` passes. */
    for (uint64_t p = 0, k0 = 0; p < passes && !d.tot.cancelled; p++) {
        uint64_t k1 = k0 + base + (p < extra ? 1 : 0);
        pass(&d, k0, k1);
        k0 = k1;
    }
    /* END SNIPPET render_streams */
    for (int t = 1; d.splats && t < d.threads; t++)
        rt_splats_merge(splats, d.splats[t]);
    free(d.streams);
    splats_free(&d);
    if (stats) {
        stats->paths = d.tot.paths;
        stats->segments = d.tot.segments;
        stats->dropped = d.tot.dropped;
        stats->seconds = omp_get_wtime() - t0;
        stats->cancelled = d.tot.cancelled != 0;
    }
    return d.tot.cancelled ? 1 : 0;
}

int rt_render_rows(const rt_render_job *job, rt_image *img, int first, int step, rt_render_stats *stats)
{
    if (!rt_strategy_splats(job->path.strategy))
        return rt_render_part(job, img, first, step, NULL, stats);
    /* A light path splats onto any pixel: the rows alone are no image. */
    if (first != 0 || step != 1)
        return -1;
    rt_splats *splats = rt_splats_create(img->width, img->height);
    rt_render_stats st;
    int rc = splats ? rt_render_part(job, img, 0, 1, splats, &st) : -1;
    /* Every pixel sample traced one light subpath. */
    if (rc >= 0)
        rt_splats_add_to_image(splats, st.paths, img);
    rt_splats_destroy(splats);
    if (rc >= 0 && stats)
        *stats = st;
    return rc;
}

int rt_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats)
{
    if (!job->path.neg.book_spp_divisor)
        return rt_render_rows(job, img, 0, 1, stats);
    /* The negative control: the book's square grid of samples, then its
     * division by the spp asked for. */
    rt_render_job j = *job;
    uint64_t side = (uint64_t)sqrt((double)job->spp);
    j.spp = side * side;
    int rc = rt_render_rows(&j, img, 0, 1, stats);
    double f = (double)j.spp / (double)job->spp;
    for (size_t i = 0; rc >= 0 && i < (size_t)img->width * (size_t)img->height; i++)
        for (int c = 0; c < 3; c++) {
            img->px[i].mean[c] *= f;
            img->px[i].m2[c] *= f * f;
        }
    return rc;
}
