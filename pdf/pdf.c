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
    p.as.quad.origin = origin;
    p.as.quad.corner = corner;
    p.as.quad.u = u;
    p.as.quad.v = v;
    /* pdf_valid reports a degenerate parallelogram. */
    pdf_quad_constants(u, v, &p.as.quad.normal, &p.as.quad.w, &p.as.quad.inv_area);
    return p;
}

pdf pdf_toward_sphere(vec3 origin, vec3 center, double radius)
{
    pdf p = {.kind = PDF_TOWARD_SPHERE};
    p.as.sphere.origin = origin;
    p.as.sphere.center = center;
    p.as.sphere.radius = radius;
    p.as.sphere.frame = onb_from_w(pdf_sphere_cone(origin, center, radius, &p.as.sphere.cos_theta_max,
                                                   &p.as.sphere.one_minus_cos));
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

static double quad_value(const pdf *p, vec3 d)
{
    double num = vec3_dot(p->as.quad.normal, vec3_sub(p->as.quad.corner, p->as.quad.origin));
    return pdf_quad_density(p->as.quad.origin, num, p->as.quad.corner, p->as.quad.u, p->as.quad.v,
                            p->as.quad.normal, p->as.quad.w, p->as.quad.inv_area, d);
}

static vec3 quad_generate(const pdf *p, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return pdf_quad_direction(p->as.quad.origin, p->as.quad.corner, p->as.quad.u, p->as.quad.v, u1, u2);
}

/* Uniform in the cone, 0 outside its rim. The rim test uses the rounded
 * cosine with its slack; the density uses 1 - cos theta_max. */
static double sphere_value(const pdf *p, vec3 d)
{
    if (!pdf_cone_contains(p->as.sphere.frame.n, p->as.sphere.cos_theta_max, d))
        return 0.0;
    return pdf_cone_density(p->as.sphere.one_minus_cos);
}

static vec3 sphere_generate(const pdf *p, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return pdf_cone_direction(&p->as.sphere.frame, p->as.sphere.one_minus_cos, u1, u2);
}

double pdf_value(const pdf *p, vec3 d)
{
    switch (p->kind) {
    case PDF_UNIFORM_SPHERE:
        return MC_INV_4PI;
    case PDF_COSINE:
        return pdf_cosine_density(p->as.cosine.frame.n, d);
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
        return pdf_cosine_direction(&p->as.cosine.frame, u1, u2);
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
