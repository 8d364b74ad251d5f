/* render/integrator.c - the book's mixture path tracer and next-event
 * estimation with multiple importance sampling. */
#include "render/integrator.h"

#include <math.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "render/names.h"
#include "render/roulette.h"
#include "samplers/hemisphere.h"

_Static_assert(RT_MAX_LIGHTS <= RT_LIGHTS_AT_MAX, "rt_lights_at holds every light of a scene");

const char *const rt_strategy_names[] = {"uniform", "cosine",     "light", "mixture",
                                         "mis",     "lighttrace", "bdpt",  NULL};

rt_path_settings rt_path_settings_default(rt_strategy strategy)
{
    /* neg is left out: zero, the correct renderer. */
    return (rt_path_settings){
        .strategy = strategy,
        .max_depth = 50,
        .russian_roulette = false,
        .rr_start = 3,
        .pdf_objects = false,
        .bdpt_s = 0,
        .bdpt_t = 0,
        .emit_aim = RT_EMIT_AIM_DEFAULT,
    };
}

bool rt_strategy_parse(const char *name, rt_strategy *out)
{
    int i = rt_name_index(rt_strategy_names, name);
    if (i < 0)
        return false;
    *out = (rt_strategy)i;
    return true;
}

const char *rt_strategy_name(rt_strategy s)
{
    return (unsigned)s <= (unsigned)RT_BDPT ? rt_strategy_names[s] : "?";
}

static bool is_zero(vec3 v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

/* --- the densities --------------------------------------------------------
 * The light list seen from one hit point: the book's pdf objects (a
 * pdf_list of pdf_toward_quad / pdf_toward_sphere, with ps->pdf_objects:
 * the reference) or the constants render/lights.h keeps, which go through
 * the same formulas of pdf/pdf.h and give the same bits. This is the one
 * place that tells them apart; every density below is written once. */
typedef struct lights_at {
    bool objects;
    rt_lights_at cache;
    pdf list;
    pdf items[RT_MAX_LIGHTS];
    const pdf *ptrs[RT_MAX_LIGHTS];
} lights_at;

/* The light list from p, or its emitters alone when `emitters` is set
 * (the list, or its emitters, is not empty). Prepared once per hit point:
 * the draw and the density there share it. */
static void lights_prepare(lights_at *a, const rt_scene *s, const rt_path_settings *ps, vec3 p,
                           bool emitters)
{
    a->objects = ps->pdf_objects;
    if (a->objects)
        a->list = emitters ? rt_scene_emitters_pdf(s, p, a->items, a->ptrs)
                           : rt_scene_lights_pdf(s, p, a->items, a->ptrs);
    else if (emitters)
        rt_lights_prepare(&a->cache, rt_scene_emitters(s), rt_scene_emitter_count(s), p);
    else
        rt_lights_prepare(&a->cache, rt_scene_lights(s), rt_scene_light_count(s), p);
}

/* The lights that next-event estimation aims at: for mis the emitters
 * alone (rt_scene_emitters), for the light strategy the whole light list
 * (which keeps its images as they were; it aims at the book's glass
 * sphere for nothing). */
/* BEGIN SNIPPET nee_emitters */
static bool nee_emitters_only(const rt_path_settings *ps) { return ps->strategy == RT_MIS; }

static int nee_count(const rt_scene *s, const rt_path_settings *ps)
{
    return nee_emitters_only(ps) ? rt_scene_emitter_count(s) : rt_scene_light_count(s);
}
/* END SNIPPET nee_emitters */

/* A direction toward the lights (pdf_generate of the list). The pdf
 * objects draw from a PCG32 stream, the pixel's, whatever the sampler:
 * they are the reference for the PCG32 samplers, and under sobol their
 * draws are independent of the sequence's, which leaves the estimate
 * unbiased. */
static vec3 lights_generate(const lights_at *a, rt_sampler *sampler)
{
    return a->objects ? pdf_generate(&a->list, &sampler->rng)
                      : rt_lights_at_generate(&a->cache, sampler);
}

/* The list's density at the unit direction d, per unit solid angle. */
static double lights_value(const lights_at *a, vec3 d)
{
    return a->objects ? pdf_value(&a->list, d) : rt_lights_at_value(&a->cache, d);
}

/* The light list's density at dir as the estimator divides by it: the
 * list's, times the negative controls' factors. For a direction toward
 * the quad emitter at distance t, whose normal makes the cosine c with it,
 * the density per unit solid angle is t^2 / (A c) (dA c / t^2 = dw):
 * without the c it is that times c, and the area density 1 / A that times
 * c / t^2. */
static double light_density(const rt_path_settings *ps, const lights_at *a, vec3 dir)
{
    double pl = lights_value(a, dir) * (1.0 + ps->neg.light_pdf_error);
    if (!(ps->neg.light_drop_cos || ps->neg.light_area_density) || a->objects || !(pl > 0.0))
        return pl;
    for (int i = 0; i < a->cache.n; i++) {
        const rt_light *l = &a->cache.lights[i];
        double dn = vec3_dot(l->normal, dir);
        if (l->kind != RT_PRIM_QUAD || dn == 0.0)
            continue;
        double t = a->cache.num[i] / dn;
        vec3 rel = vec3_sub(vec3_madd(a->cache.origin, dir, t), l->q);
        double al = vec3_dot(l->w, vec3_cross(rel, l->v)), be = vec3_dot(l->w, vec3_cross(l->u, rel));
        if (t > 0.0 && al >= 0.0 && al <= 1.0 && be >= 0.0 && be <= 1.0) {
            double c = fabs(dn);
            return ps->neg.light_area_density ? pl * c / (t * t) : pl * c;
        }
    }
    return pl;
}

/* The material's density at a diffuse hit: pdf_cosine about the normal
 * (rt_scatter_pdf), through the formulas pdf_cosine uses. */
RT_HOT_INLINE vec3 material_generate(const rt_scatter *sr, rt_sampler *sampler)
{
    return rt_cosine_generate(sr->normal, sampler);
}

static double material_value(const rt_scatter *sr, vec3 d) { return rt_cosine_value(sr->normal, d); }

/* The mixture weights of Shirley v1.123 chapter 8 (#ch-mixture): 1/2 lights
 * + 1/2 material. */
static const double mixture_weights[2] = {0.5, 0.5};

/* The mixture's density at dir given the light list's density there,
 * summed in pdf_mixture's order (so the same bits as pdf_value of
 * pdf_mixture), with the negative-control error on the light part
 * (1 + 0 is exactly 1, so at zero the product keeps every bit). */
static double mixture_density(const rt_path_settings *ps, const rt_scatter *sr, vec3 dir,
                              double light_value)
{
    double sum = 0.0;
    sum += mixture_weights[0] * (light_value * (1.0 + ps->neg.light_pdf_error));
    sum += mixture_weights[1] * material_value(sr, dir);
    return sum;
}

/* The mixture of Shirley v1.123 chapter 8 (#ch-mixture): one direction and
 * the mixture density there.
 * The draw is pdf_mixture's: component 0 (the lights) when a uniform is
 * below its weight, else the material, then that component's generate. */
/* BEGIN SNIPPET mixture_sample */
static double mixture_sample(const rt_scene *s, const rt_path_settings *ps, const rt_hit *h,
                             const rt_scatter *sr, rt_sampler *sampler, vec3 *dir)
{
    lights_at lights;
    lights_prepare(&lights, s, ps, h->p, false);
    *dir = rt_sampler_1d(sampler) < mixture_weights[0] ? lights_generate(&lights, sampler)
                                                       : material_generate(sr, sampler);
    return mixture_density(ps, sr, *dir, lights_value(&lights, *dir));
}
/* END SNIPPET mixture_sample */

/* --- the book's integrator ---------------------------------------------- */

/* Draws the direction after a diffuse hit and returns the density it was
 * drawn with (per unit solid angle). */
/* BEGIN SNIPPET diffuse_direction */
static double diffuse_direction(const rt_scene *s, const rt_path_settings *ps, const rt_hit *h,
                                const rt_scatter *sr, rt_sampler *sampler, vec3 *dir)
{
    if (ps->strategy == RT_UNIFORM) {
        double u1, u2;
        rt_sampler_2d(sampler, &u1, &u2);
        onb frame = onb_from_w(h->normal);
        *dir = onb_to_world(&frame, smp_uniform_hemisphere_sample(u1, u2));
        return MC_INV_2PI;
    }
    if (ps->strategy != RT_MIXTURE || rt_scene_light_count(s) == 0) {
        *dir = material_generate(sr, sampler);
        return material_value(sr, *dir);
    }
    return mixture_sample(s, ps, h, sr, sampler, dir);
}
/* END SNIPPET diffuse_direction */

bool rt_path_steppable(const rt_path_settings *ps)
{
    return ps->strategy != RT_LIGHT && ps->strategy != RT_MIS && !rt_strategy_splats(ps->strategy);
}

rt_path_state rt_path_begin(const rt_path_settings *ps, rt_ray r)
{
    rt_path_state p = {r, vec3_make(0.0, 0.0, 0.0), vec3_make(1.0, 1.0, 1.0), 0, ps->max_depth <= 0};
    return p;
}

/* rt_roulette, or with the negative control the same draw without the
 * survivor's division by its probability. */
static bool roulette(const rt_path_settings *ps, int depth, vec3 beta_albedo, vec3 *beta,
                     rt_sampler *sampler)
{
    vec3 before = *beta;
    if (!rt_roulette(ps->rr_start, depth, beta_albedo, beta, sampler))
        return false;
    if (ps->neg.roulette_no_divide)
        *beta = before;
    return true;
}

/* The end of every step that goes on: roulette at the vertex, whose
 * throughput times albedo is beta_albedo, then the depth limit. */
static void path_next(const rt_path_settings *ps, rt_path_state *p, vec3 beta_albedo,
                      rt_sampler *sampler)
{
    /* The flag is tested here too so that, off, the call is skipped. */
    if (ps->russian_roulette && !roulette(ps, p->depth, beta_albedo, &p->beta, sampler))
        p->done = true;
    else if (++p->depth >= ps->max_depth)
        p->done = true;
}

/* BEGIN SNIPPET path_scatter */
bool rt_path_scatter(const rt_scene *s, const rt_path_settings *ps, rt_path_state *p,
                     const rt_hit *h, rt_sampler *sampler, rt_path_vertex *v)
{
    if (!h) {
        p->L = vec3_add(p->L, vec3_mul(p->beta, rt_scene_background(s)));
        p->done = true;
        return false;
    }
    const rt_material *m = rt_scene_material(s, h->material);
    p->L = vec3_add(p->L, vec3_mul(p->beta, rt_material_emitted(m, h)));
    rt_sampler_segment(sampler, p->depth);
    if (!rt_material_scatter(m, &p->ray, h, sampler, &v->sr)) {
        p->done = true;
        return false;
    }
    if (v->sr.specular) {
        p->beta = vec3_mul(p->beta, v->sr.attenuation);
        /* Field by field, not as one struct (docs/performance.md). */
        p->ray.origin = v->sr.ray.origin;
        p->ray.dir = v->sr.ray.dir;
        path_next(ps, p, p->beta, sampler);
        return false;
    }
    v->p = h->p;
    v->normal = h->normal;
    v->m = m;
    return true;
}
/* END SNIPPET path_scatter */

/* The rest of a diffuse step, along dir drawn with density pd. */
/* BEGIN SNIPPET path_turn */
RT_HOT_INLINE void path_turn(const rt_path_settings *ps, rt_path_state *p, const rt_path_vertex *v,
                             vec3 dir, double pd, rt_sampler *sampler)
{
    rt_hit h = {.p = v->p, .normal = v->normal};
    double sp = rt_material_scattering_pdf(v->m, &h, dir);
    /* Below the surface the integrand is 0: nothing more to add. */
    if (!(sp > 0.0)) {
        p->done = true;
        return;
    }
    /* Roulette's q comes from beta_albedo, before the direction's s/p. */
    vec3 beta_albedo = vec3_mul(p->beta, v->sr.attenuation);
    p->beta = vec3_scale(beta_albedo, sp / pd);
    p->ray = rt_ray_make(v->p, dir);
    path_next(ps, p, ps->neg.roulette_after_direction ? p->beta : beta_albedo, sampler);
}
/* END SNIPPET path_turn */

void rt_path_continue(const rt_scene *s, const rt_path_settings *ps, rt_path_state *p,
                      const rt_path_vertex *v, rt_sampler *sampler)
{
    vec3 dir;
    rt_hit h = {.p = v->p, .normal = v->normal};
    double pd = diffuse_direction(s, ps, &h, &v->sr, sampler, &dir);
    path_turn(ps, p, v, dir, pd, sampler);
}

bool rt_path_batches_lights(const rt_scene *s, const rt_path_settings *ps)
{
    return ps->strategy == RT_MIXTURE && !ps->pdf_objects && rt_scene_light_count(s) > 0;
}

bool rt_path_draws_light(const rt_path_settings *ps, rt_sampler *sampler)
{
    /* mixture_draw's choice of component, the same uniform. */
    (void)ps;
    return rt_sampler_1d(sampler) < mixture_weights[0];
}

vec3 rt_path_draw_material(const rt_path_vertex *v, rt_sampler *sampler)
{
    return material_generate(&v->sr, sampler);
}

void rt_path_finish(const rt_path_settings *ps, rt_path_state *p, const rt_path_vertex *v,
                    vec3 dir, double light_value, rt_sampler *sampler)
{
    path_turn(ps, p, v, dir, mixture_density(ps, &v->sr, dir, light_value), sampler);
}

static vec3 book_radiance(const rt_scene *s, const rt_path_settings *ps, rt_ray r,
                          rt_sampler *sampler, uint64_t *segments)
{
    rt_path_state p = rt_path_begin(ps, r);
    while (!p.done) {
        rt_hit h;
        rt_path_vertex v;
        ++*segments;
        bool hit = rt_scene_hit(s, p.ray, HUGE_VAL, &h);
        if (rt_path_scatter(s, ps, &p, hit ? &h : NULL, sampler, &v))
            rt_path_continue(s, ps, &p, &v, sampler);
    }
    return p.L;
}

/* --- next-event estimation ---------------------------------------------- */

/* Radiance arriving along r straight from a surface or the background,
 * without scattering: what a shadow ray sees. */
static vec3 arriving(const rt_scene *s, rt_ray r, uint64_t *segments)
{
    rt_hit h;
    ++*segments;
    if (!rt_scene_hit(s, r, HUGE_VAL, &h))
        return rt_scene_background(s);
    return rt_material_emitted(rt_scene_material(s, h.material), &h);
}

/* The power heuristic a^2 / (a^2 + b^2) for the strategy with density a,
 * written as 1 / (1 + (b/a)^2) so that an infinite a (the cone pdf of a
 * sphere light so small that R^2 / d^2 underflows, R / d < ~1e-154) gives
 * 1 instead of inf/inf = NaN, and a huge ratio overflows to weight 0
 * rather than to NaN. a == 0: that strategy could not have drawn the
 * direction, so it gets nothing. */
/* BEGIN SNIPPET power_weight */
static double power_weight(double a, double b)
{
    if (!(a > 0.0))
        return 0.0;
    if (b == 0.0)
        return 1.0;
    double r = b / a;
    return 1.0 / (1.0 + r * r);
}
/* END SNIPPET power_weight */

/* The weight of light found by continuing the path from `from` along dir,
 * drawn by the material with density p_mat, when the light list could also
 * have sent a shadow ray there. */
/* BEGIN SNIPPET continued_weight */
static double continued_weight(const rt_scene *s, const rt_path_settings *ps, vec3 from, vec3 dir,
                               double p_mat)
{
    if (nee_count(s, ps) == 0)
        return 1.0;
    lights_at lights;
    lights_prepare(&lights, s, ps, from, nee_emitters_only(ps));
    double pl = light_density(ps, &lights, dir);
    if (ps->strategy == RT_LIGHT)
        return pl > 0.0 ? 0.0 : 1.0;
    return power_weight(p_mat, pl);
}
/* END SNIPPET continued_weight */

/* The shadow-ray estimate of light arriving at the diffuse hit h directly,
 * already multiplied by the BRDF cosine and the MIS weight. */
/* BEGIN SNIPPET direct_light */
static vec3 direct_light(const rt_scene *s, const rt_path_settings *ps, const rt_material *m,
                         const rt_hit *h, const rt_scatter *sr, rt_sampler *sampler,
                         uint64_t *segments)
{
    vec3 zero = vec3_make(0.0, 0.0, 0.0);
    if (nee_count(s, ps) == 0)
        return zero;
    lights_at lights;
    lights_prepare(&lights, s, ps, h->p, nee_emitters_only(ps));
    vec3 dir = lights_generate(&lights, sampler);
    double pl = light_density(ps, &lights, dir);
    double sp = rt_material_scattering_pdf(m, h, dir);
    if (!(sp > 0.0 && pl > 0.0))
        return zero;
    vec3 le = arriving(s, rt_ray_make(h->p, dir), segments);
    if (is_zero(le))
        return zero;
    double w = 1.0;
    if (ps->strategy == RT_MIS) {
        double pm = material_value(sr, dir);
        w = power_weight(pl, pm);
    }
    return vec3_scale(vec3_mul(sr->attenuation, le), sp * w / pl);
}
/* END SNIPPET direct_light */

static vec3 nee_radiance(const rt_scene *s, const rt_path_settings *ps, rt_ray r,
                         rt_sampler *sampler, uint64_t *segments)
{
    vec3 L = vec3_make(0.0, 0.0, 0.0), beta = vec3_make(1.0, 1.0, 1.0);
    bool after_diffuse = false;
    vec3 prev_p = r.origin;
    double prev_pm = 0.0;
    /* BEGIN SNIPPET nee_loop */
    for (int depth = 0; depth < ps->max_depth; depth++) {
        rt_hit h;
        ++*segments;
        bool hit = rt_scene_hit(s, r, HUGE_VAL, &h);
        const rt_material *m = hit ? rt_scene_material(s, h.material) : NULL;
        vec3 le = hit ? rt_material_emitted(m, &h) : rt_scene_background(s);
        if (!is_zero(le)) {
            double w = after_diffuse ? continued_weight(s, ps, prev_p, r.dir, prev_pm) : 1.0;
            L = vec3_add(L, vec3_scale(vec3_mul(beta, le), w));
        }
        rt_scatter sr;
        rt_sampler_segment(sampler, depth);
        if (!hit || !rt_material_scatter(m, &r, &h, sampler, &sr))
            break;
        /* Roulette's q comes from beta_albedo, before the direction's s/p. */
        vec3 beta_albedo;
        if (sr.specular) {
            beta_albedo = vec3_mul(beta, sr.attenuation);
            beta = beta_albedo;
            r = sr.ray;
            after_diffuse = false;
        } else {
            /* A shadow ray from here makes a path one segment longer than
             * the one that reached here: only within max_depth. */
            if (depth + 1 < ps->max_depth)
                L = vec3_add(L, vec3_mul(beta, direct_light(s, ps, m, &h, &sr, sampler, segments)));
            vec3 dir = material_generate(&sr, sampler);
            double pm = material_value(&sr, dir);
            double sp = rt_material_scattering_pdf(m, &h, dir);
            if (!(sp > 0.0))
                break;
            beta_albedo = vec3_mul(beta, sr.attenuation);
            beta = vec3_scale(beta_albedo, sp / pm);
            prev_p = h.p;
            prev_pm = pm;
            after_diffuse = true;
            r = rt_ray_make(h.p, dir);
        }
        if (ps->neg.roulette_after_direction)
            beta_albedo = beta;
        if (ps->russian_roulette && !roulette(ps, depth, beta_albedo, &beta, sampler))
            break;
    }
    /* END SNIPPET nee_loop */
    return L;
}

vec3 rt_radiance(const rt_scene *scene, const rt_path_settings *ps, rt_ray r,
                 rt_sampler *sampler, uint64_t *segments)
{
    if (ps->strategy == RT_LIGHT || ps->strategy == RT_MIS)
        return nee_radiance(scene, ps, r, sampler, segments);
    return book_radiance(scene, ps, r, sampler, segments);
}
