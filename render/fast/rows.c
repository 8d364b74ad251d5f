/* render/fast/rows.c - the row loop of the book's integrator, four paths
 * at a time. */
#include "render/fast/rows.h"

#include <math.h>

#include "render/fast/hit4.h"
#include "render/fast/lights4.h"

/* One lane of rt_fast_render_row: the pixel it works on, that pixel's sampler and
 * next sample, and the path of the current sample. */
typedef struct lane {
    int x;      /* -1: idle */
    uint64_t k;
    rt_cell c;
    rt_sampler sampler;
    rt_path_state path;
} lane;

/* Gives lane l pixel x of row y from sample k0 on (x == w: none left). */
static void lane_take(lane *l, const rt_render_job *job, const rt_jitter *jt, mc_rng *streams, int y,
                      int x, int w, uint64_t k0, rt_cell c0)
{
    l->x = x < w ? x : -1;
    if (l->x < 0)
        return;
    l->k = k0;
    l->c = c0;
    size_t idx = (size_t)y * (size_t)w + (size_t)x;
    l->sampler = rt_render_sampler(job, streams[idx], idx);
    l->path = rt_path_begin(&job->path,
                            rt_sample_ray(&job->camera, jt, x, y, k0, &l->c, &l->sampler));
}

/* The second half of the step of the lanes in `diffuse` (a bit per lane),
 * each at a diffuse vertex. For the fast mixture the light densities of
 * all four lanes are prepared and evaluated together (render/lights4.h);
 * a lane without a vertex this step goes through with the vertex and
 * direction it had last (or the initial ones), which are finite and whose
 * densities nobody reads: lanes never mix. */
/* BEGIN SNIPPET turn_diffuse */
static void turn_diffuse(const rt_render_job *job, rt_isa isa, lane *lanes,
                         const rt_path_vertex *verts, vec3 *dirs, unsigned diffuse)
{
    const rt_scene *s = job->scene;
    if (!rt_path_batches_lights(s, &job->path)) {
        for (int i = 0; i < RT_LANES; i++)
            if ((diffuse >> i) & 1u)
                rt_path_continue(s, &job->path, &lanes[i].path, &verts[i], &lanes[i].sampler);
        return;
    }
    vec3 at_p[RT_LANES];
    for (int i = 0; i < RT_LANES; i++)
        at_p[i] = verts[i].p;
    rt_lights4 at4;
    rt_lights4_prepare(isa, &at4, rt_scene_lights(s), rt_scene_light_count(s), at_p);
    for (int i = 0; i < RT_LANES; i++)
        if ((diffuse >> i) & 1u)
            dirs[i] = rt_path_draws_light(&job->path, &lanes[i].sampler)
                          ? rt_lights4_generate(&at4, i, &lanes[i].sampler)
                          : rt_path_draw_material(&verts[i], &lanes[i].sampler);
    double values[RT_LANES];
    rt_lights4_value(isa, &at4, dirs, values);
    for (int i = 0; i < RT_LANES; i++)
        if ((diffuse >> i) & 1u)
            rt_path_finish(&job->path, &lanes[i].path, &verts[i], dirs[i], values[i],
                               &lanes[i].sampler);
}
/* END SNIPPET turn_diffuse */

/* rt_row_reference for the book's integrator, RT_LANES paths at a time:
 * each lane takes a pixel and traces its samples one after the other,
 * exactly as rt_row_reference does (the same stream, the same order, so the
 * same numbers), and the lanes' rays are traced together by one
 * rt_scene_hit4 per segment. A lane whose pixel is done takes the next
 * pixel of the row; at the end of the row, a lane with no pixel left
 * traces its last ray again and its results are ignored. */
rt_row_counts rt_fast_render_row(const rt_row *r)
{
    const rt_render_job *job = r->job;
    mc_rng *streams = r->streams;
    const rt_jitter *jt = r->jt;
    uint64_t k0 = r->k0, k1 = r->k1;
    rt_isa isa = rt_isa_best();
    int y = r->y, w = r->img->width, next = 0;
    unsigned live = 0; /* the lanes with a pixel: each has a path under way */
    uint64_t seg = 0, drop = 0;
    lane lanes[RT_LANES];
    rt_path_vertex verts[RT_LANES] = {0};
    vec3 dirs[RT_LANES];
    for (int i = 0; i < RT_LANES; i++) {
        dirs[i] = vec3_make(0.0, 0.0, 1.0);
        lane_take(&lanes[i], job, jt, streams, y, next, w, k0, r->c0);
        next += next < w;
        live |= (unsigned)(lanes[i].x >= 0) << i;
    }
    /* Lanes without a pixel from the start (a row narrower than the
     * lanes) trace lane 0's ray; lane_take leaves an idle lane's path as
     * it was, so lanes that run out later trace their last ray. */
    for (int i = 1; i < RT_LANES; i++)
        if (lanes[i].x < 0)
            lanes[i].path = lanes[0].path;
    /* A lane whose first path is done at once (max depth 0) is settled
     * below before anything is traced. */
    unsigned settle = live;
    while (live) {
        for (int i = 0; i < RT_LANES; i++) {
            lane *l = &lanes[i];
            if (!((settle >> i) & 1u))
                continue;
            /* Finished samples go to the pixel; a sample of depth 0 is
             * finished as soon as it begins. */
            while (l->path.done) {
                size_t idx = (size_t)y * (size_t)w + (size_t)l->x;
                drop += !rt_pixel_add(&r->img->px[idx], l->path.L);
                if (++l->k < k1) {
                    l->path = rt_path_begin(&job->path, rt_sample_ray(&job->camera, jt, l->x, y,
                                                                      l->k, &l->c, &l->sampler));
                    continue;
                }
                streams[idx] = l->sampler.rng;
                lane_take(l, job, jt, streams, y, next, w, k0, r->c0);
                next += next < w;
                if (l->x < 0) {
                    live &= ~(1u << i);
                    break;
                }
            }
        }
        if (!live)
            break;
        rt_ray rays[RT_LANES];
        rt_hit hits[RT_LANES];
        for (int i = 0; i < RT_LANES; i++)
            rays[i] = lanes[i].path.ray;
        unsigned hit = rt_scene_hit4(job->scene, rays, HUGE_VAL, hits);
        unsigned diffuse = 0;
        settle = 0;
        for (int i = 0; i < RT_LANES; i++) {
            if (!((live >> i) & 1u))
                continue;
            lane *l = &lanes[i];
            seg++;
            diffuse |= (unsigned)rt_path_scatter(job->scene, &job->path, &l->path,
                                                 (hit >> i) & 1u ? &hits[i] : NULL, &l->sampler,
                                                 &verts[i])
                       << i;
        }
        if (diffuse)
            turn_diffuse(job, isa, lanes, verts, dirs, diffuse);
        for (int i = 0; i < RT_LANES; i++)
            settle |= (unsigned)lanes[i].path.done << i;
        settle &= live;
    }
    return (rt_row_counts){seg, drop};
}

