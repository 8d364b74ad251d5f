/* render/lights.h - the integrators' densities without building pdf
 * objects at every bounce.
 *
 * Chapters 7-10 of "Ray Tracing: The Rest of Your Life" build, at every
 * diffuse hit, a pdf toward each light, a list over them, a cosine pdf and
 * a mixture (pdf/pdf.h). Building those objects costs more than tracing
 * the ray in a small scene (each constructor fills and copies a ~150-byte
 * union), so the renderer precomputes what does not depend on the hit
 * point and evaluates the same densities here. "The same" is meant
 * literally: every function below draws the same uniforms in the same
 * order and performs the same floating-point operations as the pdf object
 * it replaces (pdf_list of pdf_toward_quad / pdf_toward_sphere, and
 * pdf_cosine), through the same samplers; tests/test_render_pdf.c checks
 * the values and directions for bitwise equality and renders images both
 * ways. The pdf objects remain the reference (rt_path_settings.pdf_objects).
 */
#ifndef RT_LIGHTS_H
#define RT_LIGHTS_H

#include <math.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/rng.h"
#include "mc/vec3.h"
#include "pdf/pdf.h"
#include "render/shapes.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/measure.h"
#include "samplers/planar.h"

/* A light of the light list with its hit-point-independent constants. */
typedef struct rt_light {
    rt_prim_kind kind;
    vec3 q, u, v;    /* quad: corner and edges */
    vec3 normal, w;  /* quad: unit (u x v) and (u x v) / |u x v|^2 */
    double inv_area; /* quad: 1 / |u x v| */
    vec3 center;     /* sphere */
    double radius;   /* sphere */
} rt_light;

/* The light for a flattened quad or sphere. */
rt_light rt_light_make(const rt_prim *p);

/* pdf_generate of pdf_list over pdf_toward_quad / pdf_toward_sphere from
 * origin to lights[0..n) (n >= 1): a unit direction. */
vec3 rt_lights_generate(const rt_light *lights, int n, vec3 origin, mc_rng *rng);

/* pdf_value of the same list for the unit direction d: per unit solid
 * angle, the average over the lights. */
double rt_lights_value(const rt_light *lights, int n, vec3 origin, vec3 d);

/* Most lights an rt_lights_at holds. */
#define RT_LIGHTS_AT_MAX 16

/* The light list seen from one origin: the parts of every density that
 * depend on the origin but not on the direction, computed once per hit
 * point (the integrators draw a direction and evaluate the density at the
 * same point) by the very expressions of the functions above, so that the
 * results are the same bits. */
typedef struct rt_lights_at {
    const rt_light *lights;
    int n;
    vec3 origin;
    double num[RT_LIGHTS_AT_MAX];     /* quad: normal . (q - origin) */
    vec3 axis[RT_LIGHTS_AT_MAX];      /* sphere: unit axis of the cone */
    double cos_max[RT_LIGHTS_AT_MAX]; /* sphere: cos theta_max (the rim test) */
    double one_minus_cos[RT_LIGHTS_AT_MAX]; /* sphere: 1 - cos theta_max, accurate */
    double cone[RT_LIGHTS_AT_MAX];          /* sphere: the cone's density inside it */
} rt_lights_at;

/* The functions below are inline: the integrators call them at every
 * diffuse hit, and most of them are a few arithmetic operations. */

/* The cone toward sphere light l from origin: its unit axis,
 * cos theta_max and 1 - cos theta_max (without cancellation), as
 * pdf_toward_sphere computes them. */
static inline vec3 rt_light_cone_axis(const rt_light *l, vec3 origin, double *cos_max,
                                      double *one_minus_cos)
{
    vec3 axis = vec3_sub(l->center, origin);
    double dist_sq = vec3_length_sq(axis);
    *one_minus_cos = smp_sphere_cone_cap(dist_sq, l->radius, cos_max);
    return dist_sq > 0.0 ? vec3_scale(axis, 1.0 / sqrt(dist_sq)) : vec3_make(0.0, 0.0, 1.0);
}

/* Prepares lights[0..n) (1 <= n <= RT_LIGHTS_AT_MAX) seen from origin. */
static inline void rt_lights_prepare(rt_lights_at *at, const rt_light *lights, int n, vec3 origin)
{
    at->lights = lights;
    at->n = n;
    at->origin = origin;
    for (int i = 0; i < n; i++) {
        const rt_light *l = &lights[i];
        if (l->kind == RT_PRIM_QUAD) {
            at->num[i] = vec3_dot(l->normal, vec3_sub(l->q, origin));
        } else {
            at->axis[i] = rt_light_cone_axis(l, origin, &at->cos_max[i], &at->one_minus_cos[i]);
            at->cone[i] = smp_uniform_cap_pdf(vec3_make(0.0, 0.0, 1.0), at->one_minus_cos[i]);
        }
    }
}

/* The direction toward light l drawn from the uniforms u1, u2: a point of
 * the quad, or a direction of the sphere's cone (axis and 1 - cos
 * theta_max as prepared from origin). */
static inline vec3 rt_light_generate(const rt_light *l, vec3 origin, vec3 axis,
                                     double one_minus_cos, double u1, double u2)
{
    if (l->kind == RT_PRIM_QUAD) {
        vec3 x = smp_parallelogram_sample(u1, u2, l->q, l->u, l->v);
        return vec3_normalize(vec3_sub(x, origin));
    }
    onb frame = onb_from_w(axis);
    return onb_to_world(&frame, smp_uniform_cap_sample(u1, u2, one_minus_cos));
}

/* rt_lights_generate from the prepared origin: the same direction from
 * the same uniforms. */
static inline vec3 rt_lights_at_generate(const rt_lights_at *at, mc_rng *rng)
{
    uint32_t i = mc_rng_bounded(rng, (uint32_t)at->n);
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return rt_light_generate(&at->lights[i], at->origin, at->axis[i], at->one_minus_cos[i], u1, u2);
}

/* pdf_toward_quad's value with its numerator normal . (q - origin) given. */
static inline double rt_light_quad_value(const rt_light *l, vec3 origin, double num, vec3 d)
{
    double denom = vec3_dot(l->normal, d);
    if (denom == 0.0)
        return 0.0;
    double r = num / denom;
    if (!(r > 0.0))
        return 0.0;
    vec3 q = vec3_sub(vec3_madd(origin, d, r), l->q);
    double s = vec3_dot(l->w, vec3_cross(q, l->v));
    double t = vec3_dot(l->w, vec3_cross(l->u, q));
    if (!(s >= -PDF_QUAD_EDGE_TOL && s <= 1.0 + PDF_QUAD_EDGE_TOL &&
          t >= -PDF_QUAD_EDGE_TOL && t <= 1.0 + PDF_QUAD_EDGE_TOL))
        return 0.0;
    return smp_area_to_solid_angle(l->inv_area, r * r, denom);
}

/* rt_lights_value from the prepared origin: the same value. */
static inline double rt_lights_at_value(const rt_lights_at *at, vec3 d)
{
    double sum = 0.0;
    for (int i = 0; i < at->n; i++) {
        const rt_light *l = &at->lights[i];
        /* pdf_toward_sphere's value: 0 outside the rim (d . axis is the
         * direction's cosine in the cone's frame), else the cap's density. */
        sum += l->kind == RT_PRIM_QUAD ? rt_light_quad_value(l, at->origin, at->num[i], d)
               : vec3_dot(d, at->axis[i]) < at->cos_max[i] - PDF_CONE_RIM_TOL ? 0.0
                                                                               : at->cone[i];
    }
    /* For n a power of two 1 / n is exact, and sum * (1 / n) is the
     * correctly rounded sum / n just as the quotient is: the same bits
     * for a multiplication instead of a division (render/lights4.c too). */
    int n = at->n;
    if (n > 0 && (n & (n - 1)) == 0)
        return sum * (1.0 / (double)n);
    return n > 0 ? sum / (double)n : 0.0;
}

/* pdf_generate of pdf_cosine(normal) (unit normal). */
static inline vec3 rt_cosine_generate(vec3 normal, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    onb frame = onb_from_w(normal);
    return onb_to_world(&frame, smp_cosine_hemisphere_sample(u1, u2));
}

/* pdf_value of pdf_cosine(normal): max(0, cos theta) / pi. */
static inline double rt_cosine_value(vec3 normal, vec3 d)
{
    double cos_theta = vec3_dot(d, normal);
    return cos_theta > 0.0 ? cos_theta * MC_INV_PI : 0.0;
}

#endif /* RT_LIGHTS_H */
