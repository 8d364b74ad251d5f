/* pdf/experiments.c - estimators and closed forms of the chapter programs. */
#include "pdf/experiments.h"

#include <math.h>

#include "mc/constants.h"
#include "mc/integrate.h"
#include "mc/onb.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"

/* pdf_integrate as an mc_is_sampler over unit directions (vec3):
 * mc_integrate_sampler holds the one weighting loop. */
typedef struct dir_ctx {
    pdf_fn f;
    const pdf *p;
} dir_ctx;

static double dir_f(const void *x, void *ctx)
{
    const dir_ctx *c = ctx;
    return c->f.f(*(const vec3 *)x, c->f.ctx);
}

static double pdf_draw(mc_rng *rng, void *ctx, void *x)
{
    const dir_ctx *c = ctx;
    vec3 *d = x;
    *d = pdf_generate(c->p, rng);
    return pdf_value(c->p, *d);
}

mc_estimate pdf_integrate(pdf_fn f, const pdf *p, mc_rng *rng, uint64_t n)
{
    dir_ctx c = {f, p};
    vec3 d;
    return mc_integrate_sampler((mc_is_sampler){pdf_draw, dir_f, NULL, &c}, &d, rng, n);
}

/* Lambert: the irradiance is L times the projected solid angle, and by
 * Stokes the projected solid angle of a spherical polygon is half the
 * sum over its edges of the edge's arc length times the cosine between n
 * and the edge's plane normal. atan2 of |a x b| and a . b gives the arc
 * length accurately also for nearly parallel a, b (acos does not). */
double pdf_polygon_irradiance(vec3 x, vec3 n, const vec3 *v, size_t k, double radiance)
{
    double sum = 0.0;
    for (size_t i = 0; i < k; i++) {
        vec3 a = vec3_normalize(vec3_sub(v[i], x)), b = vec3_normalize(vec3_sub(v[(i + 1) % k], x));
        vec3 c = vec3_cross(a, b);
        double len = vec3_length(c);
        if (len > 0.0)
            sum += atan2(len, vec3_dot(a, b)) * vec3_dot(n, c) / len;
    }
    return 0.5 * radiance * fabs(sum);
}

double pdf_sphere_light_irradiance(double phi, double d, double cos_theta)
{
    return phi * cos_theta / (MC_4PI * d * d);
}

mc_estimate pdf_sphere_light_by_area(vec3 x, vec3 n, vec3 center, double radius, double radiance,
                                     mc_rng *rng, uint64_t n_samples)
{
    double area = MC_4PI * radius * radius;
    mc_welford w = mc_welford_init();
    for (uint64_t i = 0; i < n_samples; i++) {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        vec3 q = smp_sphere_surface_sample(u1, u2, center, radius);
        vec3 to = vec3_sub(q, x);
        double dist_sq = vec3_length_sq(to);
        vec3 dir = vec3_scale(to, 1.0 / sqrt(dist_sq));
        vec3 m = vec3_scale(vec3_sub(q, center), 1.0 / radius);
        /* dA at q subtends |m . w| dA / dist^2 of solid angle at x. */
        double cos_x = fmax(0.0, vec3_dot(n, dir)), cos_q = fmax(0.0, -vec3_dot(m, dir));
        mc_welford_add(&w, radiance * cos_x * cos_q / dist_sq * area);
    }
    return mc_welford_estimate(&w);
}

/* BEGIN SNIPPET body_projected_area */
double pdf_body_area(pdf_body b)
{
    if (!b.is_box)
        return MC_4PI * b.radius * b.radius;
    return 8.0 * (b.half.x * b.half.y + b.half.y * b.half.z + b.half.z * b.half.x);
}

double pdf_body_projected_area(pdf_body b, vec3 d)
{
    if (!b.is_box)
        return MC_PI * b.radius * b.radius;
    /* Faces x = +-hx have area 4 hy hz; half of the six |d . n| A terms. */
    return 4.0 * (fabs(d.x) * b.half.y * b.half.z + fabs(d.y) * b.half.z * b.half.x +
                  fabs(d.z) * b.half.x * b.half.y);
}
/* END SNIPPET body_projected_area */

/* Whether the line o + t d (all t) meets the body. For the sphere, the
 * line's distance from the centre; for the box, Kay and Kajiya's slabs [@kay-kajiya1986]:
 * the parameter intervals inside each pair of planes must overlap. A
 * direction parallel to a slab meets it iff the origin lies between its
 * planes (avoids 0 * inf = NaN). */
static bool line_hits(pdf_body b, vec3 o, vec3 d)
{
    if (!b.is_box) {
        vec3 closest = vec3_madd(o, d, -vec3_dot(o, d));
        return vec3_length_sq(closest) < b.radius * b.radius;
    }
    double t0 = -(double)INFINITY, t1 = (double)INFINITY;
    for (int i = 0; i < 3; i++) {
        double oi = vec3_at(o, i), di = vec3_at(d, i), h = vec3_at(b.half, i);
        if (di == 0.0) {
            if (fabs(oi) > h)
                return false;
            continue;
        }
        double ta = (-h - oi) / di, tb = (h - oi) / di;
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
    }
    return t0 <= t1;
}

/* BEGIN SNIPPET mean_projected_area */
mc_estimate pdf_mean_projected_area(pdf_body b, bool by_rays, mc_rng *rng, uint64_t n)
{
    double r = b.is_box ? vec3_length(b.half) : b.radius, window = 4.0 * r * r;
    mc_welford w = mc_welford_init();
    for (uint64_t i = 0; i < n; i++) {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        vec3 d = smp_uniform_sphere_sample(u1, u2);
        if (!by_rays) {
            mc_welford_add(&w, pdf_body_projected_area(b, d));
            continue;
        }
        /* A uniform point of the window [-R, R]^2 in the plane through the
         * centre perpendicular to d: the hit fraction times the window's
         * area is an unbiased estimate of the shadow's area. */
        onb frame = onb_from_w(d);
        double s = r * (2.0 * mc_rng_uniform(rng) - 1.0), t = r * (2.0 * mc_rng_uniform(rng) - 1.0);
        vec3 o = vec3_add(vec3_scale(frame.s, s), vec3_scale(frame.t, t));
        mc_welford_add(&w, line_hits(b, o, d) ? window : 0.0);
    }
    return mc_welford_estimate(&w);
}
/* END SNIPPET mean_projected_area */
