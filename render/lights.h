/* render/lights.h - the integrators' densities without building pdf
 * objects at every bounce.
 *
 * Chapters 7-10 of "Ray Tracing: The Rest of Your Life" build, at every
 * diffuse hit, a pdf toward each light, a list over them, a cosine pdf and
 * a mixture (pdf/pdf.h). Building those objects costs more than tracing
 * the ray in a small scene (each constructor fills and copies a ~150-byte
 * union), so the renderer precomputes what does not depend on the hit
 * point and evaluates the same densities here, through the formulas of
 * pdf/pdf.h (pdf_quad_density, pdf_sphere_cone, ...), which the pdf
 * objects use too: every function below draws the same uniforms in the
 * same order as the pdf object it replaces (from a sampler that draws
 * from a PCG32 stream, the same numbers as pdf_generate from that stream) (pdf_list of pdf_toward_quad /
 * pdf_toward_sphere, and pdf_cosine) and computes the same bits;
 * tests/test_render_pdf.c checks the values and directions for bitwise
 * equality and renders images both ways. The pdf objects remain the
 * reference (rt_path_settings.pdf_objects).
 */
#ifndef RT_LIGHTS_H
#define RT_LIGHTS_H

#include <math.h>

#include "mc/onb.h"
#include "render/sampler.h"
#include "mc/vec3.h"
#include "pdf/pdf.h"
#include "render/shapes.h"

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
vec3 rt_lights_generate(const rt_light *lights, int n, vec3 origin, rt_sampler *sampler);

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
            at->axis[i] = pdf_sphere_cone(origin, l->center, l->radius, &at->cos_max[i],
                                          &at->one_minus_cos[i]);
            at->cone[i] = pdf_cone_density(at->one_minus_cos[i]);
        }
    }
}

/* The direction toward light l drawn from the uniforms u1, u2: a point of
 * the quad, or a direction of the sphere's cone (axis and 1 - cos
 * theta_max as prepared from origin). */
static inline vec3 rt_light_generate(const rt_light *l, vec3 origin, vec3 axis,
                                     double one_minus_cos, double u1, double u2)
{
    if (l->kind == RT_PRIM_QUAD)
        return pdf_quad_direction(origin, l->q, l->u, l->v, u1, u2);
    onb frame = onb_from_w(axis);
    return pdf_cone_direction(&frame, one_minus_cos, u1, u2);
}

/* rt_lights_generate from the prepared origin: the same direction from
 * the same uniforms. */
RT_HOT_INLINE vec3 rt_lights_at_generate(const rt_lights_at *at, rt_sampler *sampler)
{
    uint32_t i = rt_sampler_index(sampler, (uint32_t)at->n);
    double u1, u2;
    rt_sampler_2d(sampler, &u1, &u2);
    return rt_light_generate(&at->lights[i], at->origin, at->axis[i], at->one_minus_cos[i], u1, u2);
}

/* rt_lights_value from the prepared origin: the same value. */
static inline double rt_lights_at_value(const rt_lights_at *at, vec3 d)
{
    double sum = 0.0;
    for (int i = 0; i < at->n; i++) {
        const rt_light *l = &at->lights[i];
        if (l->kind == RT_PRIM_QUAD)
            sum += pdf_quad_density(at->origin, at->num[i], l->q, l->u, l->v, l->normal, l->w,
                                    l->inv_area, d);
        else
            sum += pdf_cone_contains(at->axis[i], at->cos_max[i], d) ? at->cone[i] : 0.0;
    }
    /* For n a power of two 1 / n is exact, and sum * (1 / n) is the
     * correctly rounded sum / n just as the quotient is: the same bits
     * for a multiplication instead of a division (render/fast/lights4.c
     * too). */
    int n = at->n;
    if (n > 0 && (n & (n - 1)) == 0)
        return sum * (1.0 / (double)n);
    return n > 0 ? sum / (double)n : 0.0;
}

/* pdf_generate of pdf_cosine(normal) (unit normal). */
RT_HOT_INLINE vec3 rt_cosine_generate(vec3 normal, rt_sampler *sampler)
{
    double u1, u2;
    rt_sampler_2d(sampler, &u1, &u2);
    onb frame = onb_from_w(normal);
    return pdf_cosine_direction(&frame, u1, u2);
}

/* pdf_value of pdf_cosine(normal): max(0, cos theta) / pi. */
static inline double rt_cosine_value(vec3 normal, vec3 d) { return pdf_cosine_density(normal, d); }

#endif /* RT_LIGHTS_H */
