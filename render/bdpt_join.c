/* render/bdpt_join.c - the joins of a light subpath's end to a camera
 * subpath's: a shadow ray between two vertices (t >= 2) and the splat of
 * a light vertex seen by the camera onto its pixel (t = 1, light
 * tracing); Veach's thesis, 1997, 10.2; this book's #ch-caustic. */
#include <math.h>

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

/* True when nothing lies between the points a and b. */
static bool visible(const rt_scene *s, vec3 a, vec3 b, uint64_t *segments)
{
    vec3 d = vec3_sub(b, a);
    double dist = vec3_length(d);
    rt_hit h;
    ++*segments;
    return !rt_scene_hit(s, rt_ray_make(a, vec3_scale(d, 1.0 / dist)), dist - rt_scene_t_min(s), &h);
}

/* Russian roulette on a join whose value, if nothing is in the way,
 * would be v, worth `scale` times v to a pixel sample: when that is below
 * RT_BDPT_JOIN_FLOOR in every channel, the shadow ray is traced with
 * probability (its worth / the floor) and the value divided by it, else
 * always. Returns the factor, 0 for a join left out; its mean is 1, so
 * the estimate is unchanged in expectation. */
static double join_roulette(vec3 v, double scale, mc_rng *aux)
{
    double worth = scale * fmax(v.x, fmax(v.y, v.z));
    if (!aux || !(worth < RT_BDPT_JOIN_FLOOR))
        return 1.0;
    double q = worth / RT_BDPT_JOIN_FLOOR;
    return mc_rng_uniform(aux) < q ? 1.0 / q : 0.0;
}

/* --- strategies (s, t >= 2): a shadow ray between the two ends -------- */

/* BEGIN SNIPPET bdpt_join */
vec3 rt_bdpt_join(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp, const rt_bdpt_vertex *light,
                  int s, const rt_bdpt_vertex *cam, int t, mc_rng *aux, uint64_t *segments)
{
    const rt_bdpt_vertex *z = &cam[t - 1];
    vec3 zero = vec3_make(0.0, 0.0, 0.0), v;
    if (s == 0) {
        if (z->kind != RT_BDPT_SURFACE || !z->front_face || is_black(z->m->emission))
            return zero;
        v = vec3_mul(z->beta, z->m->emission);
        return sp ? vec3_scale(v, rt_bdpt_join_weight(c, sp, light, s, cam, t)) : v;
    }
    const rt_bdpt_vertex *y = &light[s - 1];
    vec3 fy = end_factor(y, z->p), fz = end_factor(z, y->p);
    if (is_black(fy) || is_black(fz))
        return zero;
    vec3 d = vec3_sub(z->p, y->p);
    double dist_sq = vec3_length_sq(d);
    double g = fabs(vec3_dot(y->ng, d)) * fabs(vec3_dot(z->ng, d)) / (dist_sq * dist_sq);
    if (!(g > 0.0))
        return zero;
    v = vec3_scale(vec3_mul(vec3_mul(y->beta, fy), vec3_mul(z->beta, fz)), g);
    if (sp)
        v = vec3_scale(v, rt_bdpt_join_weight(c, sp, light, s, cam, t));
    double f = join_roulette(v, 1.0, aux);
    if (f == 0.0 || !visible(c->scene, y->p, z->p, segments))
        return zero;
    return vec3_scale(v, f);
}
/* END SNIPPET bdpt_join */

/* --- strategies (s, 1): the light subpath's end splatted on the film -- */

/* BEGIN SNIPPET bdpt_splat */
void rt_bdpt_splat_to_camera(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int s,
                             const rt_bdpt_vertex *cam0, const rt_bdpt_subpath_pdfs *sp,
                             mc_rng *aux, rt_splats *splats, uint64_t *segments)
{
    const rt_bdpt_vertex *y = &light[s - 1];
    size_t px;
    double we;
    if (!rt_bdpt_camera_importance(c, y->p, &px, &we))
        return;
    rt_splats_prefetch(splats, px);
    vec3 fy = end_factor(y, cam0->p);
    if (is_black(fy))
        return;
    vec3 d = vec3_sub(cam0->p, y->p);
    double dist_sq = vec3_length_sq(d);
    double g = fabs(vec3_dot(y->ng, d)) / (sqrt(dist_sq) * dist_sq);
    if (!(g > 0.0))
        return;
    vec3 v = vec3_scale(vec3_mul(y->beta, fy), g * we);
    if (sp)
        v = vec3_scale(v, rt_bdpt_join_weight(c, sp, light, s, cam0, 1));
    /* A splat is divided by the number of light subpaths, one per pixel
     * sample: to a pixel sample it is worth v over the pixel count. */
    double npix = (double)c->camera->width * (double)c->camera->height;
    double f = join_roulette(v, 1.0 / npix, aux);
    if (f == 0.0 || !visible(c->scene, y->p, cam0->p, segments))
        return;
    v = vec3_scale(v, f);
    /* A non-finite splat would spoil a pixel for good: rt_splats_add_rgb
     * leaves it out (the factors above are finite for any path that gets
     * here). */
    (void)rt_splats_add_rgb(splats, px, v.x, v.y, v.z);
}
/* END SNIPPET bdpt_splat */
