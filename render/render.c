/* render/render.c - passes over the image, rows shared by OpenMP threads. */
#include "render/render.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "mc/strat.h"
#include "render/lights4.h"

_Static_assert(RT_BVH_LANES == RT_LIGHTS4_LANES, "one light-density lane per traced path");

rt_render_job rt_render_job_default(const rt_scene *scene, rt_camera camera)
{
    rt_render_job job = {0};
    job.scene = scene;
    job.camera = camera;
    job.path = rt_path_settings_default(RT_MIXTURE);
    job.spp = 100;
    job.seed = 1;
    return job;
}

/* The pixel's stratification: mc_strat_grid's sx x sy cells for spp
 * samples, visited as cell (k stride) mod m for sample k < m; cell c is
 * column c mod sx of row c / sx. */
typedef struct jitter {
    uint64_t sx, sy, m, stride;
    uint64_t stride_i, stride_j; /* the stride's column and row */
} jitter;

/* A cell as its column i and row j, so that moving on by the stride
 * needs no division. */
typedef struct cell {
    uint64_t i, j;
} cell;

static cell cell_of(const jitter *jt, uint64_t c)
{
    cell r = {c % jt->sx, c / jt->sx};
    return r;
}

static uint64_t gcd(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* a b mod m for a, b < m < 2^63, by doubling (no 128-bit product). */
static uint64_t mulmod(uint64_t a, uint64_t b, uint64_t m)
{
    uint64_t r = 0;
    while (b) {
        if (b & 1u)
            r = r + a >= m ? r + a - m : r + a;
        a = a + a >= m ? a + a - m : a + a;
        b >>= 1u;
    }
    return r;
}

/* BEGIN SNIPPET jitter_make */
static jitter jitter_make(uint64_t spp)
{
    size_t sx, sy;
    mc_strat_grid((size_t)spp, &sx, &sy);
    jitter j = {sx, sy, (uint64_t)sx * sy, 1, 0, 0};
    /* A stride near m / golden ratio coprime to m is a permutation of the
     * cells whose prefixes spread over the pixel (the Fibonacci lattice
     * idea); coprimality makes it visit every cell exactly once. */
    uint64_t s = (uint64_t)(0.6180339887498949 * (double)j.m);
    s = s ? s : 1;
    while (gcd(s, j.m) != 1)
        s++;
    /* The loop stops by m - 1 (always coprime to m), so 1 <= s < m; for a
     * single cell s = 1, which also leaves the cell at 0. */
    j.stride = s;
    j.stride_i = s % j.sx;
    j.stride_j = s / j.sx;
    return j;
}
/* END SNIPPET jitter_make */

/* A coordinate in [0, 1) from cell i of n and a uniform u. */
static double in_cell(uint64_t i, uint64_t n, double u)
{
    double x = ((double)i + u) / (double)n;
    return x < 1.0 ? x : nextafter(1.0, 0.0);
}

/* The camera ray of sample k of pixel (x, y): a point of its cell c while
 * k < m (c then moves on by the stride), a uniform point after. The two
 * uniforms come first from the pixel's stream. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline rt_ray sample_ray(const rt_render_job *job, const jitter *jt, int x, int y, uint64_t k,
                                cell *c, mc_rng *rng)
{
    /* BEGIN SNIPPET sample_ray */
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng), jx = u1, jy = u2;
    if (k < jt->m) {
        jx = in_cell(c->i, jt->sx, u1);
        jy = in_cell(c->j, jt->sy, u2);
        /* c + stride, then minus m if that reaches m: the column carries
         * into the row, and the row (below 2 sy, since c and the stride
         * are below m) wraps at most once. */
        uint64_t i = c->i + jt->stride_i, carry = i >= jt->sx;
        uint64_t j = c->j + jt->stride_j + carry;
        c->i = carry ? i - jt->sx : i;
        c->j = j >= jt->sy ? j - jt->sy : j;
    }
    return rt_camera_ray(&job->camera, (double)x + jx, (double)y + jy);
    /* END SNIPPET sample_ray */
}

/* Samples [k0, k1) of every pixel of row y; c0 is the cell of sample k0. */
/* BEGIN SNIPPET render_row */
static void render_row(const rt_render_job *job, rt_image *img, mc_rng *streams, const jitter *jt,
                       int y, uint64_t k0, uint64_t k1, cell c0, uint64_t *segments,
                       uint64_t *dropped)
{
    int w = img->width;
    for (int x = 0; x < w; x++) {
        size_t idx = (size_t)y * (size_t)w + (size_t)x;
        mc_rng rng = streams[idx];
        rt_pixel *px = &img->px[idx];
        cell c = c0;
        for (uint64_t k = k0; k < k1; k++) {
            rt_ray r = sample_ray(job, jt, x, y, k, &c, &rng);
            vec3 L = rt_radiance(job->scene, &job->path, r, &rng, segments);
            if (!rt_pixel_add(px, L))
                ++*dropped;
        }
        streams[idx] = rng;
    }
}
/* END SNIPPET render_row */

/* One lane of render_row4: the pixel it works on, that pixel's stream and
 * next sample, and the path of the current sample. */
typedef struct lane {
    int x;      /* -1: idle */
    uint64_t k;
    cell c;
    mc_rng rng;
    rt_path_state path;
} lane;

/* Gives lane l pixel x of row y from sample k0 on (x == w: none left). */
static void lane_take(lane *l, const rt_render_job *job, const jitter *jt, mc_rng *streams, int y,
                      int x, int w, uint64_t k0, cell c0)
{
    l->x = x < w ? x : -1;
    if (l->x < 0)
        return;
    l->k = k0;
    l->c = c0;
    l->rng = streams[(size_t)y * (size_t)w + (size_t)x];
    l->path = rt_path_begin(&job->path, sample_ray(job, jt, x, y, k0, &l->c, &l->rng));
}

/* The second half of the step of the lanes in `diffuse` (a bit per lane),
 * each at a diffuse vertex. For the fast mixture the light densities of
 * all four lanes are prepared and evaluated together (render/lights4.h);
 * a lane without a vertex this step goes through with the vertex and
 * direction it had last (or the initial ones), which are finite and whose
 * densities nobody reads: lanes never mix. */
/* BEGIN SNIPPET turn_diffuse */
static void turn_diffuse(const rt_render_job *job, lane *lanes, const rt_path_vertex *verts,
                         vec3 *dirs, unsigned diffuse)
{
    const rt_scene *s = job->scene;
    if (!rt_path_batches_lights(s, &job->path)) {
        for (int i = 0; i < RT_BVH_LANES; i++)
            if ((diffuse >> i) & 1u)
                rt_path_continue(s, &job->path, &lanes[i].path, &verts[i], &lanes[i].rng);
        return;
    }
    vec3 at_p[RT_LIGHTS4_LANES];
    for (int i = 0; i < RT_BVH_LANES; i++)
        at_p[i] = verts[i].p;
    rt_lights4 at4;
    rt_lights4_prepare(&at4, rt_scene_lights(s), rt_scene_light_count(s), at_p);
    for (int i = 0; i < RT_BVH_LANES; i++)
        if ((diffuse >> i) & 1u)
            dirs[i] = rt_path_draw(&job->path, &verts[i], &at4, i, &lanes[i].rng);
    double values[RT_LIGHTS4_LANES];
    rt_lights4_value(&at4, dirs, values);
    for (int i = 0; i < RT_BVH_LANES; i++)
        if ((diffuse >> i) & 1u)
            rt_path_finish(&job->path, &lanes[i].path, &verts[i], dirs[i], values[i], &lanes[i].rng);
}
/* END SNIPPET turn_diffuse */

/* render_row for the book's integrator, RT_BVH_LANES paths at a time:
 * each lane takes a pixel and traces its samples one after the other,
 * exactly as render_row does (the same stream, the same order, so the
 * same numbers), and the lanes' rays are traced together by one
 * rt_scene_hit4 per segment. A lane whose pixel is done takes the next
 * pixel of the row; at the end of the row, a lane with no pixel left
 * traces its last ray again and its results are ignored. */
static void render_row4(const rt_render_job *job, rt_image *img, mc_rng *streams, const jitter *jt,
                        int y, uint64_t k0, uint64_t k1, cell c0, uint64_t *segments,
                        uint64_t *dropped)
{
    int w = img->width, next = 0;
    unsigned live = 0; /* the lanes with a pixel: each has a path under way */
    uint64_t seg = 0, drop = 0;
    lane lanes[RT_BVH_LANES];
    rt_path_vertex verts[RT_BVH_LANES] = {0};
    vec3 dirs[RT_BVH_LANES];
    for (int i = 0; i < RT_BVH_LANES; i++) {
        dirs[i] = vec3_make(0.0, 0.0, 1.0);
        lane_take(&lanes[i], job, jt, streams, y, next, w, k0, c0);
        next += next < w;
        live |= (unsigned)(lanes[i].x >= 0) << i;
    }
    /* Lanes without a pixel from the start (a row narrower than the
     * lanes) trace lane 0's ray; lane_take leaves an idle lane's path as
     * it was, so lanes that run out later trace their last ray. */
    for (int i = 1; i < RT_BVH_LANES; i++)
        if (lanes[i].x < 0)
            lanes[i].path = lanes[0].path;
    /* A lane whose first path is done at once (max depth 0) is settled
     * below before anything is traced. */
    unsigned settle = live;
    while (live) {
        for (int i = 0; i < RT_BVH_LANES; i++) {
            lane *l = &lanes[i];
            if (!((settle >> i) & 1u))
                continue;
            /* Finished samples go to the pixel; a sample of depth 0 is
             * finished as soon as it begins. */
            while (l->path.done) {
                size_t idx = (size_t)y * (size_t)w + (size_t)l->x;
                drop += !rt_pixel_add(&img->px[idx], l->path.L);
                if (++l->k < k1) {
                    l->path = rt_path_begin(&job->path, sample_ray(job, jt, l->x, y, l->k, &l->c, &l->rng));
                    continue;
                }
                streams[idx] = l->rng;
                lane_take(l, job, jt, streams, y, next, w, k0, c0);
                next += next < w;
                if (l->x < 0) {
                    live &= ~(1u << i);
                    break;
                }
            }
        }
        if (!live)
            break;
        rt_ray rays[RT_BVH_LANES];
        rt_hit hits[RT_BVH_LANES];
        for (int i = 0; i < RT_BVH_LANES; i++)
            rays[i] = lanes[i].path.ray;
        unsigned hit = rt_scene_hit4(job->scene, rays, HUGE_VAL, hits);
        unsigned diffuse = 0;
        settle = 0;
        for (int i = 0; i < RT_BVH_LANES; i++) {
            if (!((live >> i) & 1u))
                continue;
            lane *l = &lanes[i];
            seg++;
            diffuse |= (unsigned)rt_path_scatter(job->scene, &job->path, &l->path,
                                                 (hit >> i) & 1u ? &hits[i] : NULL, &l->rng,
                                                 &verts[i])
                       << i;
        }
        if (diffuse)
            turn_diffuse(job, lanes, verts, dirs, diffuse);
        for (int i = 0; i < RT_BVH_LANES; i++)
            settle |= (unsigned)lanes[i].path.done << i;
        settle &= live;
    }
    *segments += seg;
    *dropped += drop;
}

typedef struct totals {
    uint64_t paths, segments, dropped;
    int cancelled;
} totals;

/* One pass: samples [k0, k1) of every pixel, rows handed out in order. */
static void render_pass(const rt_render_job *job, rt_image *img, mc_rng *streams, const jitter *jt,
                        uint64_t k0, uint64_t k1, totals *tot)
{
    cell c0 = cell_of(jt, k0 < jt->m ? mulmod(k0, jt->stride, jt->m) : 0);
    int next_row = 0, nt = job->threads > 0 ? job->threads : omp_get_max_threads();
    uint64_t total = job->spp * (uint64_t)img->width * (uint64_t)img->height;
    /* BEGIN SNIPPET render_pass_rows */
#pragma omp parallel num_threads(nt)
    for (;;) {
        int y;
#pragma omp atomic capture
        y = next_row++;
        if (y >= img->height)
            break;
        if (job->cancel && atomic_load(job->cancel)) {
#pragma omp atomic write
            tot->cancelled = 1;
            break;
        }
        uint64_t seg = 0, drop = 0, paths = (k1 - k0) * (uint64_t)img->width;
        if (rt_path_steppable(&job->path) && !job->one_path_at_a_time)
            render_row4(job, img, streams, jt, y, k0, k1, c0, &seg, &drop);
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

int rt_render(const rt_render_job *job, rt_image *img, rt_render_stats *stats)
{
    if (!job->scene || job->spp < 1 || job->camera.width != img->width ||
        job->camera.height != img->height || job->path.max_depth < 0)
        return -1;
    /* BEGIN SNIPPET render_streams */
    size_t npix = (size_t)img->width * (size_t)img->height;
    mc_rng *streams = malloc(npix * sizeof *streams);
    if (!streams)
        return -1;
    for (size_t i = 0; i < npix; i++)
        streams[i] = mc_rng_derive(job->seed, (uint64_t)i);
    rt_image_clear(img);
    jitter jt = jitter_make(job->spp);
    /* Passes of at most 16 samples per pixel keep a row short enough for
     * the cancel flag to be answered within milliseconds. */
    uint64_t per = job->pass_spp ? job->pass_spp : (job->spp < 16 ? job->spp : 16);
    uint64_t passes = (job->spp + per - 1) / per, base = job->spp / passes, extra = job->spp % passes;
    totals tot = {0, 0, 0, 0};
    double t0 = omp_get_wtime();
    /* Pass p takes base samples, one more for the first `extra` passes. */
    for (uint64_t p = 0, k0 = 0; p < passes && !tot.cancelled; p++) {
        uint64_t k1 = k0 + base + (p < extra ? 1 : 0);
        render_pass(job, img, streams, &jt, k0, k1, &tot);
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
