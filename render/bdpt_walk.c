/* render/bdpt_walk.c - the two subpaths: the walk that both ends share
 * (the materials' own sampling, cosine sampling at Lambertian surfaces,
 * Russian roulette) and the start of a light subpath on an emitter
 * (Veach's thesis, 1997, 10.2 [@veach1997]; this book's #ch-caustic). */
#include <math.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "render/bdpt_internal.h"
#include "render/lights.h"
#include "samplers/sphere.h"

static bool same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* The emitter whose primitive is the world primitive `prim` (the same
 * numbers: both are flattened from the same node), or -1. */
static int emitter_of(const rt_scene *s, int prim)
{
    if (prim < 0)
        return -1;
    const rt_prim *p = &rt_scene_prims(s)[prim];
    const rt_prim *e = rt_scene_emitter_prims(s);
    for (int i = 0; i < rt_scene_emitter_count(s); i++) {
        if (p->kind != e[i].kind || p->material != e[i].material)
            continue;
        if (p->kind == RT_PRIM_QUAD ? same_vec(p->as.quad.q, e[i].as.quad.q) &&
                                          same_vec(p->as.quad.u, e[i].as.quad.u) &&
                                          same_vec(p->as.quad.v, e[i].as.quad.v)
                                    : same_vec(p->as.sphere.center, e[i].as.sphere.center) &&
                                          p->as.sphere.radius == e[i].as.sphere.radius &&
                                          p->as.sphere.orient == e[i].as.sphere.orient)
            return i;
    }
    return -1;
}

/* --- both ends: the materials' sampling, one vertex per hit ---------- */

int rt_bdpt_walk(const rt_bdpt_ctx *c, rt_ray r, vec3 beta, rt_bdpt_vertex *v, int n, int max_n,
                 int segment, double rr_gain, rt_sampler *sampler, uint64_t *segments)
{
    const rt_scene *s = c->scene;
    const rt_path_settings *ps = c->ps;
    vec3 start = beta;
    /* A camera subpath starts at beta 1, where roulette's beta / start is
     * beta itself: the three divisions by 1 give the same bits. */
    bool unit_start = start.x == 1.0 && start.y == 1.0 && start.z == 1.0;
    for (int k = 0; n < max_n; k++) {
        rt_hit h;
        ++*segments;
        if (!rt_scene_hit(s, r, HUGE_VAL, &h))
            break;
        const rt_material *m = rt_scene_material(s, h.material);
        rt_bdpt_vertex *x = &v[n++];
        *x = (rt_bdpt_vertex){RT_BDPT_SURFACE, h.p, h.normal, h.normal, h.front_face, false, m,
                              emitter_of(s, h.prim), beta};
        if (n == max_n)
            break;
        rt_scatter sr;
        rt_sampler_segment(sampler, segment++);
        if (!rt_material_scatter(m, &r, &h, sampler, &sr))
            break;
        if (sr.specular) {
            x->delta = true;
            beta = vec3_mul(beta, sr.attenuation);
            r = sr.ray;
            continue;
        }
        vec3 dir = rt_cosine_generate(sr.normal, sampler);
        double sp = rt_material_scattering_pdf(m, &h, dir), pd = rt_cosine_value(sr.normal, dir);
        if (!(sp > 0.0 && pd > 0.0))
            break;
        /* A Lambertian surface samples its own cosine density: sp and pd
         * are the same product, their ratio exactly 1. */
        beta = vec3_scale(vec3_mul(beta, sr.attenuation), sp == pd ? 1.0 : sp / pd);
        r = rt_ray_make(h.p, dir);
        /* Russian roulette as in render/integrator.c, on the throughput
         * since the subpath's start: it changes how often a subpath goes
         * on, not what it estimates, and the MIS weights (functions of the
         * path alone) still sum to 1. It starts after RT_BDPT_RR_START
         * segments, not the path tracer's rr_start, and survives with
         * rr_gain times the path tracer's probability (at most 0.95;
         * RT_BDPT_RR_GAIN_CAMERA). */
        if (ps->russian_roulette && k + 1 >= RT_BDPT_RR_START) {
            double rel = vec3_max_component(
                unit_start ? beta : vec3_make(beta.x / start.x, beta.y / start.y, beta.z / start.z));
            double q = rr_gain * rel;
            q = q < 0.95 ? q : 0.95;
            if (!(q > 0.0) || rt_sampler_1d(sampler) >= q)
                break;
            double divide_by = ps->neg.bdpt_roulette_ungained ? (rel < 0.95 ? rel : 0.95) : q;
            beta = vec3_scale(beta, 1.0 / divide_by);
        }
    }
    return n;
}

/* --- the light end: a point on an emitter, then the emitted direction */

int rt_bdpt_light_walk(const rt_bdpt_ctx *c, rt_sampler *sampler, rt_bdpt_vertex *v, int max_n,
                       uint64_t *segments)
{
    const rt_scene *s = c->scene;
    int ne = rt_scene_emitter_count(s);
    if (ne == 0 || max_n < 1)
        return 0;
    rt_sampler_segment(sampler, c->ps->max_depth + 1);
    /* The start's uniforms: the emitter, the point on it (u1, u2), the
     * direction (u[0], u[1]). With Sobol points they are one point of the
     * image's sequence (rt_sampler_image_point): a light subpath's splats
     * land anywhere in the image, and the light subpaths of all the
     * pixels then fill the start's domain as one low-discrepancy set, not
     * as independent sets of spp points each. Its dimensions 0 and 1, the
     * best spread pair, go to the direction, which decides where the
     * light lands. */
    double u[RT_SAMPLER_IMAGE_DIMS], u1, u2;
    int i;
    if (sampler->sobol) {
        /* Dimension 4 picks the emitter, and only where there is a choice. */
        rt_sampler_image_point(sampler, ne > 1 ? 5u : 4u, u);
        i = ne > 1 ? (int)rt_sampler_index_of(u[4], (uint32_t)ne) : 0;
        u1 = u[2];
        u2 = u[3];
    } else {
        i = (int)rt_sampler_index(sampler, (uint32_t)ne);
        rt_sampler_2d(sampler, &u1, &u2);
    }
    const rt_prim *e = &rt_scene_emitter_prims(s)[i];
    vec3 p, n;
    if (e->kind == RT_PRIM_QUAD) {
        const rt_quad *q = &e->as.quad;
        p = vec3_add(q->q, vec3_add(vec3_scale(q->u, u1), vec3_scale(q->v, u2)));
        n = q->normal;
    } else {
        const rt_sphere *sp = &e->as.sphere;
        vec3 d = smp_uniform_sphere_sample(u1, u2);
        p = vec3_madd(sp->center, d, sp->radius);
        n = vec3_scale(d, sp->orient);
    }
    const rt_material *m = rt_scene_material(s, e->material);
    rt_bdpt_vertex y0 = {RT_BDPT_LIGHT, p, n, n, true, false, m, i, vec3_make(0.0, 0.0, 0.0)};
    y0.beta = vec3_scale(m->emission, 1.0 / rt_bdpt_origin_pdf(c, &y0));
    v[0] = y0;
    if (max_n == 1)
        return 1;
    rt_lights_at at;
    rt_bdpt_emit_prepare(c, p, &at);
    vec3 dir = sampler->sobol ? rt_bdpt_emit_direction_uv(c, &at, n, u[0], u[1])
                              : rt_bdpt_emit_direction_at(c, &at, n, sampler);
    double cos_e = vec3_dot(dir, n);
    if (!(cos_e > 0.0))
        return 1;
    /* Radiance Le times cos over the density of the direction. Cosine
     * emission alone (no aim) cancels the cosine: Le pi. */
    double scale = c->aim > 0.0 && !c->ps->neg.emit_aim_cosine_beta
                       ? cos_e / rt_bdpt_emit_pdf_at(c, &at, n, dir)
                       : MC_PI;
    return rt_bdpt_walk(c, rt_ray_make(p, dir), vec3_scale(y0.beta, scale), v, 1, max_n,
                        c->ps->max_depth + 2, 1.0, sampler, segments);
}

/* BEGIN SNIPPET emit_aim */
vec3 rt_bdpt_emit_direction_uv(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n, double u1,
                               double u2)
{
    if (c->aim > 0.0) {
        /* u1 < aim chooses the targets, and u1 rescaled to [0, 1) is
         * uniform again given the choice: it picks the target (uniformly,
         * as rt_lights_at_value averages) and is the first uniform of its
         * direction. */
        if (u1 < c->aim) {
            double v = u1 / c->aim * (double)at->n;
            int i = v < (double)(at->n - 1) ? (int)v : at->n - 1;
            return rt_light_generate(&at->lights[i], at->origin, at->axis[i], at->one_minus_cos[i],
                                     v - (double)i, u2);
        }
        u1 = (u1 - c->aim) / (1.0 - c->aim);
    }
    onb frame = onb_from_w(n);
    return pdf_cosine_direction(&frame, u1, u2);
}
/* END SNIPPET emit_aim */

vec3 rt_bdpt_emit_direction_at(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n,
                               rt_sampler *sampler)
{
    double u1, u2;
    rt_sampler_2d(sampler, &u1, &u2);
    return rt_bdpt_emit_direction_uv(c, at, n, u1, u2);
}

vec3 rt_bdpt_emit_direction(const rt_bdpt_ctx *c, vec3 p, vec3 n, rt_sampler *sampler)
{
    rt_lights_at at;
    rt_bdpt_emit_prepare(c, p, &at);
    return rt_bdpt_emit_direction_at(c, &at, n, sampler);
}
