/* render/lights.c - light-list and cosine densities, operation for
 * operation as in pdf/pdf.c. */
#include "render/lights.h"

#include <math.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/measure.h"
#include "samplers/planar.h"

/* pdf/pdf.c's slack on the parallelogram's edges and on the cone's rim
 * (see the reasons there); the values must match it. */
#define QUAD_EDGE_TOL 1e-9
#define CONE_RIM_TOL 1e-15

rt_light rt_light_make(const rt_prim *p)
{
    rt_light l = {.kind = p->kind};
    if (p->kind == RT_PRIM_QUAD) {
        l.q = p->as.quad.q;
        l.u = p->as.quad.u;
        l.v = p->as.quad.v;
        vec3 n = vec3_cross(l.u, l.v);
        double len_sq = vec3_length_sq(n);
        l.normal = vec3_scale(n, 1.0 / sqrt(len_sq));
        l.w = vec3_scale(n, 1.0 / len_sq);
        l.inv_area = 1.0 / sqrt(len_sq);
    } else {
        l.center = p->as.sphere.center;
        l.radius = p->as.sphere.radius;
    }
    return l;
}

/* The cone toward a sphere: its unit axis and cos theta_max. */
static vec3 cone_axis(const rt_light *l, vec3 origin, double *cos_max)
{
    vec3 axis = vec3_sub(l->center, origin);
    double dist_sq = vec3_length_sq(axis);
    *cos_max = smp_sphere_cone_cos_theta_max(dist_sq, l->radius);
    return dist_sq > 0.0 ? vec3_scale(axis, 1.0 / sqrt(dist_sq)) : vec3_make(0.0, 0.0, 1.0);
}

static vec3 light_generate(const rt_light *l, vec3 origin, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    if (l->kind == RT_PRIM_QUAD) {
        vec3 x = smp_parallelogram_sample(u1, u2, l->q, l->u, l->v);
        return vec3_normalize(vec3_sub(x, origin));
    }
    double cos_max;
    onb frame = onb_from_w(cone_axis(l, origin, &cos_max));
    return onb_to_world(&frame, smp_uniform_cone_sample(u1, u2, cos_max));
}

static double quad_value(const rt_light *l, vec3 origin, vec3 d)
{
    double denom = vec3_dot(l->normal, d);
    if (denom == 0.0)
        return 0.0;
    double r = vec3_dot(l->normal, vec3_sub(l->q, origin)) / denom;
    if (!(r > 0.0))
        return 0.0;
    vec3 q = vec3_sub(vec3_madd(origin, d, r), l->q);
    double s = vec3_dot(l->w, vec3_cross(q, l->v));
    double t = vec3_dot(l->w, vec3_cross(l->u, q));
    if (!(s >= -QUAD_EDGE_TOL && s <= 1.0 + QUAD_EDGE_TOL && t >= -QUAD_EDGE_TOL &&
          t <= 1.0 + QUAD_EDGE_TOL))
        return 0.0;
    return smp_area_to_solid_angle(l->inv_area, r * r, denom);
}

static double sphere_value(const rt_light *l, vec3 origin, vec3 d)
{
    double cos_max;
    vec3 axis = cone_axis(l, origin, &cos_max);
    if (vec3_dot(d, axis) < cos_max - CONE_RIM_TOL)
        return 0.0;
    return smp_uniform_cone_pdf(vec3_make(0.0, 0.0, 1.0), cos_max);
}

vec3 rt_lights_generate(const rt_light *lights, int n, vec3 origin, mc_rng *rng)
{
    uint32_t i = mc_rng_bounded(rng, (uint32_t)n);
    return light_generate(&lights[i], origin, rng);
}

double rt_lights_value(const rt_light *lights, int n, vec3 origin, vec3 d)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += lights[i].kind == RT_PRIM_QUAD ? quad_value(&lights[i], origin, d)
                                              : sphere_value(&lights[i], origin, d);
    return n > 0 ? sum / (double)n : 0.0;
}

vec3 rt_cosine_generate(vec3 normal, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    onb frame = onb_from_w(normal);
    return onb_to_world(&frame, smp_cosine_hemisphere_sample(u1, u2));
}

double rt_cosine_value(vec3 normal, vec3 d)
{
    double cos_theta = vec3_dot(d, normal);
    return cos_theta > 0.0 ? cos_theta * MC_INV_PI : 0.0;
}
