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

#include "mc/rng.h"
#include "mc/vec3.h"
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
vec3 rt_lights_generate(const rt_light *lights, int n, vec3 origin, mc_rng *rng);

/* pdf_value of the same list for the unit direction d: per unit solid
 * angle, the average over the lights. */
double rt_lights_value(const rt_light *lights, int n, vec3 origin, vec3 d);

/* pdf_generate of pdf_cosine(normal) (unit normal). */
vec3 rt_cosine_generate(vec3 normal, mc_rng *rng);

/* pdf_value of pdf_cosine(normal): max(0, cos theta) / pi. */
double rt_cosine_value(vec3 normal, vec3 d);

#endif /* RT_LIGHTS_H */
