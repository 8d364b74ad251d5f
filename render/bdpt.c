/* render/bdpt.c - bidirectional path tracing: the context, the camera's
 * importance and the strategies run over the two subpaths (Veach's thesis,
 * 1997, its chapter 10 [@veach1997]; this book's #ch-caustic). The other seams of the
 * algorithm have files of their own (render/bdpt_internal.h lists them). */
#include "render/bdpt.h"

#include <stdlib.h>
#include <string.h>

#include "render/bdpt_internal.h"

rt_bdpt_ctx rt_bdpt_ctx_make(const rt_scene *scene, const rt_path_settings *ps,
                             const rt_camera *camera)
{
    rt_bdpt_ctx c = {scene, ps, camera, vec3_make(0.0, 0.0, 1.0), 0.0, 0.0, false, NULL};
    /* Light tracing alone cannot see the glass that the aim sends its
     * paths through, and measured no gain from it: bdpt only. */
    c.aim = ps->strategy == RT_BDPT && rt_scene_target_count(scene) > 0 ? ps->emit_aim : 0.0;
    /* The centre of the image plane at distance 1 is the view axis. */
    vec3 centre = vec3_add(camera->corner,
                           vec3_add(vec3_scale(camera->du, 0.5 * (double)camera->width),
                                    vec3_scale(camera->dv, 0.5 * (double)camera->height)));
    c.forward = vec3_normalize(centre);
    c.pixel_area = vec3_length(camera->du) * vec3_length(camera->dv);
    return c;
}

/* BEGIN SNIPPET camera_importance */
bool rt_bdpt_camera_importance(const rt_bdpt_ctx *c, vec3 p, size_t *px, double *importance)
{
    vec3 dir;
    double cos_theta;
    if (!rt_bdpt_camera_dir(c, p, &dir, &cos_theta))
        return false;
    /* Where the direction meets the plane at distance 1, in pixel units
     * (du and dv are orthogonal). */
    const rt_camera *cam = c->camera;
    vec3 rel = vec3_sub(vec3_scale(dir, 1.0 / cos_theta), cam->corner);
    double x = vec3_dot(rel, cam->du) / vec3_length_sq(cam->du);
    double y = vec3_dot(rel, cam->dv) / vec3_length_sq(cam->dv);
    if (!(x >= 0.0 && x < (double)cam->width && y >= 0.0 && y < (double)cam->height))
        return false;
    *px = (size_t)y * (size_t)cam->width + (size_t)x;
    double cos3 = c->ps->neg.splat_drop_cos3 ? 1.0 : cos_theta * cos_theta * cos_theta;
    *importance = 1.0 / (c->pixel_area * cos3);
    return true;
}
/* END SNIPPET camera_importance */

/* Whether the path light[0..s) then cam[0..t) reversed has a segment
 * shorter than min: between neighbours within either subpath, or the
 * join between light[s - 1] and cam[t - 1] (s > 0). */
static bool has_short_segment(const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam, int t,
                              double min)
{
    double min_sq = min * min;
    for (int i = 0; i + 1 < s; i++)
        if (vec3_length_sq(vec3_sub(light[i + 1].p, light[i].p)) < min_sq)
            return true;
    for (int j = 0; j + 1 < t; j++)
        if (vec3_length_sq(vec3_sub(cam[j + 1].p, cam[j].p)) < min_sq)
            return true;
    return s > 0 && vec3_length_sq(vec3_sub(cam[t - 1].p, light[s - 1].p)) < min_sq;
}

/* Whether a render of the one strategy (ps->bdpt_s, ps->bdpt_t) counts
 * strategy (s, t) of this sample: the chosen one, without a segment
 * shorter than ps->bdpt_min_segment. */
static bool single_keeps(const rt_path_settings *ps, const rt_bdpt_vertex *light, int s,
                         const rt_bdpt_vertex *cam, int t)
{
    if (s != ps->bdpt_s || t != ps->bdpt_t)
        return false;
    return !(ps->bdpt_min_segment > 0.0 &&
             has_short_segment(light, s, cam, t, ps->bdpt_min_segment));
}

/* BEGIN SNIPPET bdpt_strategies */
vec3 rt_bdpt_sample(const rt_bdpt_ctx *c, rt_ray camera_ray, rt_sampler *sampler, mc_rng *aux,
                    bool seen_here, rt_splats *splats, uint64_t *segments)
{
    const rt_path_settings *ps = c->ps;
    int depth = ps->max_depth < RT_BDPT_MAX_DEPTH ? ps->max_depth : RT_BDPT_MAX_DEPTH;
    rt_bdpt_vertex cam[RT_BDPT_MAX_DEPTH + 1], light[RT_BDPT_MAX_DEPTH];
    bool lighttrace = ps->strategy == RT_LIGHTTRACE;
    bool all = rt_bdpt_weighted(ps);
    cam[0] = (rt_bdpt_vertex){RT_BDPT_CAMERA, c->camera->origin, c->forward, c->forward, true,
                              false, NULL, -1, vec3_make(1.0, 1.0, 1.0)};
    vec3 L = vec3_make(0.0, 0.0, 0.0);
    if (depth < 1)
        return L;
    /* The camera ray has density W_j over its pixel: beta 1. */
    int nc = lighttrace ? 1
                        : rt_bdpt_walk(c, camera_ray, cam[0].beta, cam, 1, depth + 1, 0,
                                       RT_BDPT_RR_GAIN_CAMERA, sampler, segments);
    int nl = rt_bdpt_light_walk(c, sampler, light, depth, segments);
    rt_bdpt_subpath_pdfs sp;
    int jd[RT_BDPT_MAX_DEPTH + 1], njd = 0;
    if (all) {
        rt_bdpt_cache_pdfs(c, light, nl, cam, nc, &sp);
        njd = rt_bdpt_through_vertices(cam, nc, jd);
    }
    for (int i = 0; i < njd; i++)
        L = vec3_add(L, rt_bdpt_through_estimate(c, &cam[jd[i]], jd[i], aux, segments));
    if (all && seen_here)
        L = vec3_add(L, rt_bdpt_seen_first(c, camera_ray, cam, nc, depth, aux, segments));
    /* The joins and splats queue their shadow rays; each adds its value
     * to L or to its pixel when its ray is found clear, in the order made. */
    rt_bdpt_shadows q = rt_bdpt_shadows_begin(L, splats, segments);
    for (int t = 1; t <= nc; t++)
        for (int s = 0; s <= nl; s++) {
            if (s + t < 2 || s + t - 1 > depth || (t == 1 && s == 0))
                continue;
            /* (1, 1), a lamp seen directly, has weight 0 (weight_from in
             * bdpt_mis.c). */
            if (all && s == 1 && t == 1)
                continue;
            if (!all && !lighttrace && !single_keeps(ps, light, s, cam, t))
                continue;
            if (t == 1) {
                rt_bdpt_splat_to_camera(c, light, s, &cam[0], all ? &sp : NULL, all ? aux : NULL,
                                        &q);
                continue;
            }
            if (all && s == 0 && rt_bdpt_estimated_apart(ps, cam, t, jd, njd))
                continue; /* rt_bdpt_seen_sample's or rt_bdpt_through_estimate's */
            rt_bdpt_join(c, all ? &sp : NULL, light, s, cam, t, all ? aux : NULL, &q);
        }
    return rt_bdpt_shadows_end(c, &q);
}
/* END SNIPPET bdpt_strategies */

bool rt_bdpt_strategy_parse(const char *name, rt_path_settings *ps)
{
    ps->bdpt_s = ps->bdpt_t = 0;
    if (strncmp(name, "bdpt:", 5) == 0) {
        /* Digits only: strtol would also take blanks and signs. */
        size_t digits = strspn(name + 5, "0123456789");
        if (digits == 0 || name[5 + digits] != ',' || strspn(name + 6 + digits, "0123456789") == 0)
            return false;
        char *end;
        long s = strtol(name + 5, &end, 10);
        if (end == name + 5 || *end != ',' || s < 0 || s > RT_BDPT_MAX_DEPTH)
            return false;
        const char *tp = end + 1;
        long t = strtol(tp, &end, 10);
        if (end == tp || *end != '\0' || t < 1 || t > RT_BDPT_MAX_DEPTH + 1 || s + t < 2)
            return false;
        ps->strategy = RT_BDPT;
        ps->bdpt_s = (int)s;
        ps->bdpt_t = (int)t;
        return true;
    }
    return rt_strategy_parse(name, &ps->strategy);
}
