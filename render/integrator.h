/* render/integrator.h - estimators of the radiance arriving along a ray.
 *
 * Two integrators, five strategies, one quantity: every strategy estimates
 * the same sum over paths of at most max_depth ray segments (a segment is
 * one ray from one surface point to the next hit), so that they must agree
 * image for image (Shirley, "Ray Tracing: The Rest of Your Life" (v1.123) [@shirley-rotl],
 * chapter 4: two strategies that should agree but do not reveal a bug).
 *
 * The book's integrator (its chapters 4-10; this book's #ch-cornell): at a diffuse hit one direction is
 * drawn from a density p and the path continues with weight
 * albedo * s(direction) / p(direction), emission being collected where the
 * path lands. Strategies:
 *   RT_UNIFORM   p = 1 / (2 pi) on the hemisphere (v1.123 ch. 4's experiment)
 *   RT_COSINE    p = the material's scattering pdf, cos / pi
 *   RT_MIXTURE   p = 1/2 light list + 1/2 material pdf (v1.123 ch. 8, 10)
 * The second integrator splits direct from indirect light (the lecture
 * slides "Solving the Rendering Equation"; this book's #ch-nee-mis): at each diffuse hit a shadow ray goes toward a point drawn from
 * the light list, and the path continues by the material pdf:
 *   RT_LIGHT     the shadow ray carries all light the light list can
 *                reach; a continued path that lands on such an emitter
 *                adds nothing (it would count that light twice)
 *   RT_MIS       both count, weighted by Veach's power heuristic
 *                w_a = p_a^2 / (p_light^2 + p_material^2); its shadow
 *                rays aim at the emitters of the light list only
 *                (rt_scene_emitters): an entry that emits nothing, such
 *                as the book's glass sphere, would only waste them
 * Specular events (metal, glass) continue with their single ray in all
 * strategies, and emission reached right after them always counts.
 * With no lights, RT_MIXTURE, RT_LIGHT and RT_MIS reduce to RT_COSINE.
 */
#ifndef RT_INTEGRATOR_H
#define RT_INTEGRATOR_H

#include <stdbool.h>
#include <stdint.h>

#include "render/sampler.h"
#include "mc/vec3.h"
#include "render/lights.h"
#include "render/ray.h"
#include "render/scene.h"

/* RT_LIGHTTRACE and RT_BDPT are the strategies of render/bdpt.h, which
 * splat onto the image: they render through rt_render only (rt_radiance
 * does not serve them). */
typedef enum rt_strategy {
    RT_UNIFORM,
    RT_COSINE,
    RT_LIGHT,
    RT_MIXTURE,
    RT_MIS,
    RT_LIGHTTRACE,
    RT_BDPT
} rt_strategy;

/* True for the strategies that splat (render/bdpt.h). */
static inline bool rt_strategy_splats(rt_strategy s) { return s == RT_LIGHTTRACE || s == RT_BDPT; }

/* Negative-control hooks: deliberately wrong behaviour, so that a test
 * can check that a renderer with that bug fails it. Only tests set them.
 * Zero (what an initialiser that leaves them out gives) means the correct
 * renderer, and at zero they change no bit of any image. */
typedef struct rt_negative_controls {
    /* The light-list density the estimator divides by is multiplied by
     * 1 + light_pdf_error; the sampling is unchanged, so any value but 0
     * makes the image wrong (render/integrator.c). */
    double light_pdf_error;
    /* render/bdpt.h: splats without the 1 / cos^3 of the camera
     * importance. */
    bool splat_drop_cos3;
    /* render/bdpt.h: strategy mis_double - 1 counted twice in the MIS
     * weights' sum (0: none). */
    int mis_double;
    /* render/bdpt.h: the paths E S* L kept in the weighted sum although
     * rt_bdpt_seen_sample adds them too. */
    bool seen_twice;
    /* render/bdpt.h: the paths E (S+ D)+ S+ L kept although the split rays
     * at D add them too. */
    bool through_twice;
    /* render/sampler.h: with sobol, a 1D request does not move on to the
     * next dimension (read by rt_render_sampler, render/render.h). */
    bool sampler_reuse_dim;
    /* render/roulette.h: the survival probability taken from the
     * throughput after the direction's s/p instead of before it (unbiased
     * still, but the mixture's lamp-aimed directions get a small q just
     * before the lamp: several times the variance). */
    bool roulette_after_direction;
    /* Next-event estimation (RT_LIGHT, RT_MIS) with one quad emitter, as
     * a renderer that converts between area and solid angle wrongly:
     * light_drop_cos divides by d^2 / A, the solid-angle density without
     * the cosine at the light; light_area_density divides by 1 / A, the
     * area density where a solid-angle one belongs (render/integrator.c). */
    bool light_drop_cos, light_area_density;
    /* render/roulette.h: a path that survives roulette keeps its
     * throughput instead of dividing it by the survival probability
     * (RT_LIGHT and RT_MIS, and the book's strategies). */
    bool roulette_no_divide;
    /* rt_render: the loop of the book's release code, floor(sqrt(spp))^2
     * samples divided by spp, which darkens every pixel when spp is not a
     * square. */
    bool book_spp_divisor;
    /* render/bdpt.h: light subpaths aimed at the scene's targets
     * (rt_path_settings.emit_aim) carry the throughput of cosine emission,
     * Le pi, instead of Le cos over the mixture's density. */
    bool emit_aim_cosine_beta;
    /* render/bdpt.h: a camera subpath that survives roulette with the
     * gain's probability min(0.95, gain x its throughput) divided by the
     * probability without the gain, min(0.95, its throughput). */
    bool bdpt_roulette_ungained;
} rt_negative_controls;

/* Initialise with designated initialisers (or start from
 * rt_path_settings_default), so that a new field shifts no other. */
typedef struct rt_path_settings {
    rt_strategy strategy;
    int max_depth;         /* most ray segments per path (shadow rays aside), >= 0 */
    bool russian_roulette; /* terminate low-throughput paths, unbiasedly */
    int rr_start;          /* roulette begins after this many segments */
    /* Build the light list's pdf objects at every bounce, as the book does
     * (pdf/pdf.h), instead of render/lights.h's cached constants. Both give
     * the same numbers; the objects are the reference, the default is
     * faster. */
    bool pdf_objects;
    /* RT_BDPT: 0, 0 for every strategy weighted by MIS; else the one
     * strategy (bdpt_s light vertices, bdpt_t camera vertices),
     * unweighted (render/bdpt.h). */
    int bdpt_s, bdpt_t;
    /* RT_BDPT with one strategy chosen: a path with a segment shorter
     * than this (between two of its vertices, the join's included)
     * contributes nothing; 0, the default, keeps every path. Every
     * strategy then estimates the same integral, with the short segments
     * cut out. For the tests that compare strategies: a join of two
     * diffuse vertices near the corner of a room has a geometry term
     * like 1 / r^2, whose square is not integrable there, so such a
     * strategy alone has no finite variance and its t statistic no
     * Student tail; with a floor on the segments every term is bounded. */
    double bdpt_min_segment;
    /* RT_BDPT in a scene whose light list holds entries that do not emit
     * (rt_scene_targets: the book's glass sphere): the
     * probability, in [0, 1), with which a light subpath's first direction
     * is drawn toward them instead of by cosine (render/bdpt.h). 0 keeps
     * cosine emission; rt_path_settings_default gives RT_EMIT_AIM_DEFAULT. */
    double emit_aim;
    rt_negative_controls neg; /* all zero: the correct renderer */
} rt_path_settings;

/* The emission aim of the defaults: on the book scene, at 300x300 and 16
 * spp over three seeds, 0.1 gave bdpt with roulette the least error of
 * the values tried (MSE -11.5% against cosine emission; 0.2 -7%, and in
 * an earlier trial 0.25 -6%, 0.5 +15%), for 5.5% more instructions per
 * sample. */
#define RT_EMIT_AIM_DEFAULT 0.1

/* Book defaults: the given strategy, max depth 50, no roulette
 * (rr_start 3 if it is switched on), fast densities, every strategy of
 * bdpt, light subpaths aimed at the targets with RT_EMIT_AIM_DEFAULT, no
 * negative control. */
rt_path_settings rt_path_settings_default(rt_strategy strategy);

/* The strategy named "uniform", "cosine", "light", "mixture", "mis",
 * "lighttrace" or "bdpt"; false for anything else. */
bool rt_strategy_parse(const char *name, rt_strategy *out);

/* The name of a strategy. */
const char *rt_strategy_name(rt_strategy s);

/* The strategy names in rt_strategy order, NULL-terminated (for option
 * tables and help text). */
extern const char *const rt_strategy_names[];

/* One sample of the radiance arriving along r (unit direction) at its
 * origin, drawing its uniforms from the sample's sampler
 * (render/sampler.h). May be non-finite if the scene makes it so (the
 * caller drops such samples). *segments is increased by the number of rays traced,
 * shadow rays included. */
vec3 rt_radiance(const rt_scene *scene, const rt_path_settings *ps, rt_ray r,
                 rt_sampler *sampler, uint64_t *segments);

/* The book's integrator one segment at a time, so that a caller can
 * trace the segments of several paths together (render/fast/rows.h): a path
 * is begun with its camera ray, then, while it is not done, its ray is
 * traced and the result handed to rt_path_scatter and rt_path_continue
 * (below). The result is that of
 * rt_radiance, number for number, for the strategies where
 * rt_path_steppable is true (uniform, cosine, mixture). */
typedef struct rt_path_state {
    rt_ray ray; /* the next segment to trace */
    vec3 L;     /* radiance gathered so far */
    vec3 beta;  /* throughput: the weight of what comes back along ray */
    int depth;  /* segments traced so far */
    bool done;  /* L is final */
} rt_path_state;

/* True when the strategy runs the book's integrator (no shadow rays). */
bool rt_path_steppable(const rt_path_settings *ps);

/* A path starting along r (done at once when max_depth is 0). */
rt_path_state rt_path_begin(const rt_path_settings *ps, rt_ray r);

/* A diffuse vertex between the two halves of a step. */
typedef struct rt_path_vertex {
    vec3 p, normal;       /* the hit point and the normal facing the ray */
    rt_scatter sr;        /* the material's scatter record there */
    const rt_material *m; /* the material */
} rt_path_vertex;

/* A step is two calls, so that a caller with several paths can batch the
 * work between them. rt_path_scatter advances p by the segment p->ray just
 * traced (h is its hit, or NULL if it left the scene) up to the choice of
 * the next direction: it returns true at a diffuse hit, having filled in
 * *v, and rt_path_continue(p, v) must then follow before the next
 * segment; false when the step is complete. Both draw from sampler exactly as
 * rt_radiance does at that point. */
bool rt_path_scatter(const rt_scene *s, const rt_path_settings *ps, rt_path_state *p,
                     const rt_hit *h, rt_sampler *sampler, rt_path_vertex *v);
void rt_path_continue(const rt_scene *s, const rt_path_settings *ps, rt_path_state *p,
                      const rt_path_vertex *v, rt_sampler *sampler);

/* True when rt_path_continue is the chapter-8 mixture with the fast
 * densities of render/lights.h: then it may also be done in parts, with
 * the light list prepared at the vertices of several paths and evaluated
 * by the caller: the direction is drawn from the light list (by the
 * caller, from the same sampler) when rt_path_draws_light(ps, sampler),
 * else dir = rt_path_draw_material(v, sampler); then value = the light
 * list's density at dir, and rt_path_finish(v, dir, value). The same
 * numbers as rt_path_continue. */
bool rt_path_batches_lights(const rt_scene *s, const rt_path_settings *ps);
bool rt_path_draws_light(const rt_path_settings *ps, rt_sampler *sampler);
vec3 rt_path_draw_material(const rt_path_vertex *v, rt_sampler *sampler);
void rt_path_finish(const rt_path_settings *ps, rt_path_state *p, const rt_path_vertex *v,
                    vec3 dir, double light_value, rt_sampler *sampler);

#endif /* RT_INTEGRATOR_H */
