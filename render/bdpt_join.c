/* render/bdpt_join.c - the joins of a light subpath's end to a camera
 * subpath's: a shadow ray between two vertices (t >= 2) and the splat of
 * a light vertex seen by the camera onto its pixel (t = 1, light
 * tracing); Veach's thesis, 1997, 10.2 [@veach1997]; this book's #ch-caustic. */
#include <math.h>
#include <stdint.h>

#include "mc/constants.h"
#include "render/bdpt_internal.h"

static bool is_black(vec3 v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

/* What the end vertex x of a subpath sends toward the point `to`, per
 * unit of the subpath's beta: the emission factor (1 on the emitting
 * side) at the start of a light subpath, the Lambertian BRDF albedo / pi
 * on the side the subpath arrived from. */
static vec3 end_factor(const rt_bdpt_vertex *x, vec3 to)
{
    vec3 zero = vec3_make(0.0, 0.0, 0.0), d = vec3_sub(to, x->p);
    if (x->kind == RT_BDPT_LIGHT)
        return vec3_dot(x->ng, d) > 0.0 ? vec3_make(1.0, 1.0, 1.0) : zero;
    if (x->delta || !x->m || x->m->kind != RT_MAT_LAMBERT || !(vec3_dot(x->ns, d) > 0.0))
        return zero;
    return vec3_scale(x->m->albedo, MC_INV_PI);
}

/* --- the queue of shadow rays ----------------------------------------- */

rt_bdpt_shadows rt_bdpt_shadows_begin(vec3 L, rt_splats *splats, uint64_t *segments)
{
    rt_bdpt_shadows q;
    q.n_rays = q.n = 0;
    q.L = L;
    q.splats = splats;
    q.segments = segments;
    return q;
}

/* Traces the waiting rays (a batch of fewer than four repeats its first)
 * and adds every waiting entry whose ray is clear, in order. */
static void flush(const rt_bdpt_ctx *c, rt_bdpt_shadows *q)
{
    unsigned blocked = 0u;
    if (q->n_rays > 0) {
        for (int k = q->n_rays; k < RT_LANES; k++) {
            q->r[k] = q->r[0];
            q->tmax[k] = q->tmax[0];
        }
        blocked = rt_scene_occluded4(c->scene, q->r, q->tmax);
    }
    for (int i = 0; i < q->n; i++) {
        if (q->ray[i] >= 0 && (blocked >> q->ray[i]) & 1u)
            continue;
        vec3 v = q->v[i];
        if (q->px[i] == SIZE_MAX)
            q->L = vec3_add(q->L, v);
        /* A non-finite splat would spoil a pixel for good:
         * rt_splats_add_rgb leaves it out (the factors are finite for
         * any path that gets here). */
        else
            (void)rt_splats_add_rgb(q->splats, q->px[i], v.x, v.y, v.z);
    }
    q->n_rays = q->n = 0;
}

/* Queues v, to add to L (px = SIZE_MAX) or to pixel px's splat sums, if
 * nothing lies along the segment g from the point a (a NULL: no ray,
 * always). */
static void queue(const rt_bdpt_ctx *c, rt_bdpt_shadows *q, vec3 v, size_t px, const vec3 *a,
                  const rt_bdpt_segment *g)
{
    int ray = -1;
    if (a) {
        ray = q->n_rays++;
        q->r[ray] = rt_ray_make(*a, g->dir);
        q->tmax[ray] = g->dist - rt_scene_t_min(c->scene);
        ++*q->segments;
    }
    q->v[q->n] = v;
    q->px[q->n] = px;
    q->ray[q->n++] = ray;
    if (ray >= 0 && c->one_ray_at_a_time) {
        /* The reference: this ray alone, through rt_scene_hit, now. */
        rt_hit h;
        if (rt_scene_hit(c->scene, q->r[ray], q->tmax[ray], &h))
            q->n--;
        else
            q->ray[q->n - 1] = -1;
        q->n_rays = 0;
        flush(c, q);
    } else if (q->n_rays == RT_LANES || q->n == RT_BDPT_QUEUE) {
        flush(c, q);
    }
}

vec3 rt_bdpt_shadows_end(const rt_bdpt_ctx *c, rt_bdpt_shadows *q)
{
    flush(c, q);
    return q->L;
}

/* Russian roulette on a join whose value, if nothing is in the way,
 * would be v, worth `scale` times v to a pixel sample: when that is below
 * RT_BDPT_JOIN_FLOOR in every channel, the shadow ray is traced with
 * probability (its worth / the floor) and the value divided by it, else
 * always. Returns the factor, 0 for a join left out; its mean is 1, so
 * the estimate is unchanged in expectation. */
static double join_roulette(vec3 v, double scale, mc_rng *aux)
{
    double worth = scale * vec3_max_component(v);
    if (!aux || !(worth < RT_BDPT_JOIN_FLOOR))
        return 1.0;
    double q = worth / RT_BDPT_JOIN_FLOOR;
    return mc_rng_uniform(aux) < q ? 1.0 / q : 0.0;
}

/* --- strategies (s, t >= 2): a shadow ray between the two ends -------- */

/* BEGIN SNIPPET bdpt_join */
void rt_bdpt_join(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp, const rt_bdpt_vertex *light,
                  int s, const rt_bdpt_vertex *cam, int t, mc_rng *aux, rt_bdpt_shadows *q)
{
    const rt_bdpt_vertex *z = &cam[t - 1];
    vec3 v;
    if (s == 0) {
        if (z->kind != RT_BDPT_SURFACE || !z->front_face || is_black(z->m->emission))
            return;
        v = vec3_mul(z->beta, z->m->emission);
        if (sp)
            v = vec3_scale(v, rt_bdpt_join_weight_running(c, sp, light, s, cam, t));
        queue(c, q, v, SIZE_MAX, NULL, NULL);
        return;
    }
    const rt_bdpt_vertex *y = &light[s - 1];
    vec3 fy = end_factor(y, z->p), fz = end_factor(z, y->p);
    if (is_black(fy) || is_black(fz))
        return;
    /* The segment from y to z: the geometry factor, the weight's two
     * densities and the shadow ray all read it. */
    rt_bdpt_segment seg = rt_bdpt_segment_make(y->p, z->p);
    double g = fabs(vec3_dot(y->ng, seg.d)) * fabs(vec3_dot(z->ng, seg.d)) /
               (seg.dist_sq * seg.dist_sq);
    if (!(g > 0.0))
        return;
    v = vec3_scale(vec3_mul(vec3_mul(y->beta, fy), vec3_mul(z->beta, fz)), g);
    if (sp)
        v = vec3_scale(v, rt_bdpt_join_weight_along(c, sp, light, s, cam, t, &seg));
    double f = join_roulette(v, 1.0, aux);
    if (f != 0.0)
        queue(c, q, vec3_scale(v, f), SIZE_MAX, &y->p, &seg);
}
/* END SNIPPET bdpt_join */

/* --- strategies (s, 1): the light subpath's end splatted on the film -- */

/* BEGIN SNIPPET bdpt_splat */
void rt_bdpt_splat_to_camera(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int s,
                             const rt_bdpt_vertex *cam0, const rt_bdpt_subpath_pdfs *sp,
                             mc_rng *aux, rt_bdpt_shadows *q)
{
    const rt_bdpt_vertex *y = &light[s - 1];
    size_t px;
    double we;
    if (!rt_bdpt_camera_importance(c, y->p, &px, &we))
        return;
    rt_splats_prefetch(q->splats, px);
    vec3 fy = end_factor(y, cam0->p);
    if (is_black(fy))
        return;
    rt_bdpt_segment seg = rt_bdpt_segment_make(y->p, cam0->p);
    double g = fabs(vec3_dot(y->ng, seg.d)) / (seg.dist * seg.dist_sq);
    if (!(g > 0.0))
        return;
    vec3 v = vec3_scale(vec3_mul(y->beta, fy), g * we);
    if (sp)
        v = vec3_scale(v, rt_bdpt_join_weight_along(c, sp, light, s, cam0, 1, &seg));
    /* A splat is divided by the number of light subpaths, one per pixel
     * sample: to a pixel sample it is worth v over the pixel count. */
    double npix = (double)c->camera->width * (double)c->camera->height;
    double f = join_roulette(v, 1.0 / npix, aux);
    if (f != 0.0)
        queue(c, q, vec3_scale(v, f), px, &y->p, &seg);
}
/* END SNIPPET bdpt_splat */
