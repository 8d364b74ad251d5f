/* pdf/pdf.c - value and generate for every kind of pdf object.
 *
 * The per-kind work is delegated to the warps of samplers/: a pdf object
 * only adds the frame (ONB about a normal or an axis), the measure change
 * from area to solid angle, and the bookkeeping of mixtures.
 */
#include "pdf/pdf.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/measure.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"

/* Nesting depth beyond which pdf_valid declares a composite malformed. */
#define MAX_DEPTH 16

pdf pdf_uniform_sphere(void)
{
    pdf p = {.kind = PDF_UNIFORM_SPHERE};
    return p;
}

pdf pdf_cosine(vec3 normal)
{
    pdf p = {.kind = PDF_COSINE};
    p.as.cosine.frame = onb_from_w(normal);
    return p;
}

pdf pdf_toward_quad(vec3 origin, vec3 corner, vec3 u, vec3 v)
{
    pdf p = {.kind = PDF_TOWARD_QUAD};
    vec3 n = vec3_cross(u, v);
    double len_sq = vec3_length_sq(n);
    p.as.quad.origin = origin;
    p.as.quad.corner = corner;
    p.as.quad.u = u;
    p.as.quad.v = v;
    /* A degenerate parallelogram keeps zero vectors and a zero density
     * rather than dividing by zero; pdf_valid reports it. */
    p.as.quad.normal = len_sq > 0.0 ? vec3_scale(n, 1.0 / sqrt(len_sq)) : n;
    p.as.quad.w = len_sq > 0.0 ? vec3_scale(n, 1.0 / len_sq) : n;
    p.as.quad.inv_area = len_sq > 0.0 ? 1.0 / sqrt(len_sq) : 0.0;
    return p;
}

pdf pdf_toward_sphere(vec3 origin, vec3 center, double radius)
{
    pdf p = {.kind = PDF_TOWARD_SPHERE};
    vec3 axis = vec3_sub(center, origin);
    double dist_sq = vec3_length_sq(axis);
    p.as.sphere.origin = origin;
    p.as.sphere.center = center;
    p.as.sphere.radius = radius;
    /* At the centre any axis will do: the cone is then the whole sphere. */
    p.as.sphere.frame = onb_from_w(dist_sq > 0.0 ? vec3_scale(axis, 1.0 / sqrt(dist_sq))
                                                 : vec3_make(0.0, 0.0, 1.0));
    p.as.sphere.one_minus_cos = smp_sphere_cone_cap(dist_sq, radius, &p.as.sphere.cos_theta_max);
    return p;
}

pdf pdf_mixture(const pdf *const *components, const double *weights, size_t n)
{
    pdf p = {.kind = PDF_MIXTURE};
    p.as.mixture.components = components;
    p.as.mixture.weights = weights;
    p.as.mixture.n = n;
    return p;
}

pdf pdf_list(const pdf *const *items, size_t n)
{
    pdf p = {.kind = PDF_LIST};
    p.as.list.items = items;
    p.as.list.n = n;
    return p;
}

/* BEGIN SNIPPET toward_quad */
/* Where the ray origin + r d (r > 0) meets the parallelogram: the density
 * 1 / A per unit area becomes dist^2 / (|cos| A) per unit solid angle,
 * because a patch dA at distance dist, tilted by the angle whose cosine is
 * cos, subtends d omega = |cos| dA / dist^2 (chapter 7). */
static double quad_value(const pdf *p, vec3 d)
{
    double denom = vec3_dot(p->as.quad.normal, d);
    if (denom == 0.0)
        return 0.0;
    double r = vec3_dot(p->as.quad.normal, vec3_sub(p->as.quad.corner, p->as.quad.origin)) / denom;
    if (!(r > 0.0))
        return 0.0;
    vec3 q = vec3_sub(vec3_madd(p->as.quad.origin, d, r), p->as.quad.corner);
    /* With q = s u + t v and w = (u x v) / |u x v|^2: q x v = s (u x v) and
     * u x q = t (u x v), so dotting with w isolates s and t. */
    double s = vec3_dot(p->as.quad.w, vec3_cross(q, p->as.quad.v));
    double t = vec3_dot(p->as.quad.w, vec3_cross(p->as.quad.u, q));
    if (!(s >= -PDF_QUAD_EDGE_TOL && s <= 1.0 + PDF_QUAD_EDGE_TOL && t >= -PDF_QUAD_EDGE_TOL &&
          t <= 1.0 + PDF_QUAD_EDGE_TOL))
        return 0.0;
    return smp_area_to_solid_angle(p->as.quad.inv_area, r * r, denom);
}

static vec3 quad_generate(const pdf *p, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    vec3 x = smp_parallelogram_sample(u1, u2, p->as.quad.corner, p->as.quad.u, p->as.quad.v);
    return vec3_normalize(vec3_sub(x, p->as.quad.origin));
}
/* END SNIPPET toward_quad */

/* BEGIN SNIPPET toward_sphere */
/* Uniform in the cone: the cap sampler's constant density inside (taken at
 * its axis, which is always inside), 0 outside the rim. The rim test uses
 * the rounded cosine with its slack; the density uses 1 - cos theta_max
 * carried without cancellation, so a far sphere's density is finite and
 * accurate where 1 / (2 pi (1 - cos theta_max)) would be +inf. */
static double sphere_value(const pdf *p, vec3 d)
{
    double cos_max = p->as.sphere.cos_theta_max;
    if (vec3_dot(d, p->as.sphere.frame.n) < cos_max - PDF_CONE_RIM_TOL)
        return 0.0;
    return smp_uniform_cap_pdf(vec3_make(0.0, 0.0, 1.0), p->as.sphere.one_minus_cos);
}

static vec3 sphere_generate(const pdf *p, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    vec3 local = smp_uniform_cap_sample(u1, u2, p->as.sphere.one_minus_cos);
    return onb_to_world(&p->as.sphere.frame, local);
}
/* END SNIPPET toward_sphere */

double pdf_value(const pdf *p, vec3 d)
{
    switch (p->kind) {
    case PDF_UNIFORM_SPHERE:
        return MC_INV_4PI;
    case PDF_COSINE: {
        double cos_theta = vec3_dot(d, p->as.cosine.frame.n);
        return cos_theta > 0.0 ? cos_theta * MC_INV_PI : 0.0;
    }
    case PDF_TOWARD_QUAD:
        return quad_value(p, d);
    case PDF_TOWARD_SPHERE:
        return sphere_value(p, d);
    /* BEGIN SNIPPET mixture_value */
    case PDF_MIXTURE: {
        /* Every component may have produced d, so all of them count. */
        double sum = 0.0;
        for (size_t i = 0; i < p->as.mixture.n; i++)
            if (p->as.mixture.weights[i] > 0.0)
                sum += p->as.mixture.weights[i] * pdf_value(p->as.mixture.components[i], d);
        return sum;
    }
    /* END SNIPPET mixture_value */
    case PDF_LIST: {
        double sum = 0.0;
        for (size_t i = 0; i < p->as.list.n; i++)
            sum += pdf_value(p->as.list.items[i], d);
        return p->as.list.n > 0 ? sum / (double)p->as.list.n : 0.0;
    }
    }
    return 0.0;
}

/* BEGIN SNIPPET choose_component */
/* The component a uniform u in [0, 1) selects: the first i whose running
 * weight sum exceeds u. Zero weights are never selected; if rounding leaves
 * the total a hair below u, the last positive weight takes the remainder. */
static size_t choose_component(const double *weights, size_t n, double u)
{
    double acc = 0.0;
    size_t last = 0;
    for (size_t i = 0; i < n; i++) {
        if (!(weights[i] > 0.0))
            continue;
        last = i;
        acc += weights[i];
        if (u < acc)
            return i;
    }
    return last;
}
/* END SNIPPET choose_component */

vec3 pdf_generate(const pdf *p, mc_rng *rng)
{
    switch (p->kind) {
    case PDF_UNIFORM_SPHERE: {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        return smp_uniform_sphere_sample(u1, u2);
    }
    case PDF_COSINE: {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        return onb_to_world(&p->as.cosine.frame, smp_cosine_hemisphere_sample(u1, u2));
    }
    case PDF_TOWARD_QUAD:
        return quad_generate(p, rng);
    case PDF_TOWARD_SPHERE:
        return sphere_generate(p, rng);
    /* BEGIN SNIPPET mixture_generate */
    case PDF_MIXTURE: {
        /* n == 0 is invalid (pdf_valid): no component to index; fall
         * through to the documented +z below. */
        if (p->as.mixture.n == 0)
            break;
        size_t i = choose_component(p->as.mixture.weights, p->as.mixture.n, mc_rng_uniform(rng));
        return pdf_generate(p->as.mixture.components[i], rng);
    }
    /* END SNIPPET mixture_generate */
    case PDF_LIST: {
        if (p->as.list.n == 0) /* invalid; mc_rng_bounded(rng, 0) divides by 0 */
            break;
        uint32_t i = mc_rng_bounded(rng, (uint32_t)p->as.list.n);
        return pdf_generate(p->as.list.items[i], rng);
    }
    }
    return vec3_make(0.0, 0.0, 1.0);
}

bool pdf_mixture_weights_valid(const double *weights, size_t n)
{
    if (n == 0 || !weights)
        return false;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(weights[i]) || weights[i] < 0.0)
            return false;
        sum += weights[i];
    }
    return fabs(sum - 1.0) <= PDF_WEIGHT_SUM_TOL;
}

/* |n| = 1 within 1e-9: onb_from_w assumes a unit normal, and an error of
 * e in the length scales the cosine density by 1 + e. */
static bool unit_length(vec3 n)
{
    return vec3_is_finite(n) && fabs(vec3_length(n) - 1.0) <= 1e-9;
}

static bool valid_at(const pdf *p, int depth)
{
    if (!p || depth > MAX_DEPTH)
        return false;
    switch (p->kind) {
    case PDF_UNIFORM_SPHERE:
        return true;
    case PDF_COSINE:
        return unit_length(p->as.cosine.frame.n);
    case PDF_TOWARD_QUAD: {
        double h = vec3_dot(p->as.quad.normal, vec3_sub(p->as.quad.corner, p->as.quad.origin));
        return p->as.quad.inv_area > 0.0 && isfinite(p->as.quad.inv_area) &&
               vec3_is_finite(p->as.quad.origin) && vec3_is_finite(p->as.quad.corner) && h != 0.0;
    }
    case PDF_TOWARD_SPHERE:
        /* 1 - cos theta_max must stay positive, or the cone (and the
         * density's denominator) vanishes; only an underflowing R^2 / d^2
         * (R / d below ~1e-154) gets there, or a denominator so small that
         * the density overflows. */
        return isfinite(p->as.sphere.radius) && p->as.sphere.radius > 0.0 &&
               vec3_is_finite(p->as.sphere.origin) && vec3_is_finite(p->as.sphere.center) &&
               p->as.sphere.one_minus_cos > 0.0 &&
               isfinite(1.0 / (MC_2PI * p->as.sphere.one_minus_cos));
    case PDF_MIXTURE:
        if (!p->as.mixture.components ||
            !pdf_mixture_weights_valid(p->as.mixture.weights, p->as.mixture.n))
            return false;
        for (size_t i = 0; i < p->as.mixture.n; i++)
            if (!valid_at(p->as.mixture.components[i], depth + 1))
                return false;
        return true;
    case PDF_LIST:
        if (!p->as.list.items || p->as.list.n == 0 || p->as.list.n > UINT32_MAX)
            return false;
        for (size_t i = 0; i < p->as.list.n; i++)
            if (!valid_at(p->as.list.items[i], depth + 1))
                return false;
        return true;
    }
    return false;
}

bool pdf_valid(const pdf *p)
{
    return valid_at(p, 0);
}
