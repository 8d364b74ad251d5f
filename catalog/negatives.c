/* catalog/negatives.c - the catalog's negative controls: rows that are
 * wrong on purpose, each by one of the slips people make when they write
 * a warp (a missing square root, a density off by pi, the wrong measure, a
 * sampler and a density that disagree by one in an exponent). Every door
 * of the public check (the C API, `mcbox-check --exec`, `--samples`) must
 * reject each of them; a check that passes one proves nothing. They are
 * found by cat_find like any row but are not listed by cat_count/cat_at,
 * so nothing that iterates the real samplers meets them. */
#include "catalog/catalog.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/hemisphere.h"
#include "samplers/lobes.h"
#include "samplers/planar.h"

static void put3(double x[3], vec3 d)
{
    x[0] = d.x, x[1] = d.y, x[2] = d.z;
}

/* cos theta / pi without the 1/pi: integrates to pi. */
static void cosine_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    put3(x, smp_cosine_hemisphere_sample(u[0], u[1]));
}
static double cosine_no_pi_pdf(const cat_state *s, const double x[3])
{
    (void)s;
    return x[2] > 0.0 ? x[2] : 0.0;
}

/* theta uniform in [0, pi/2] claimed to be cosine-distributed: the
 * Jacobian sin theta of the solid angle forgotten. */
static void theta_uniform_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    double theta = MC_PI_2 * u[0], phi = MC_2PI * u[1];
    x[0] = sin(theta) * cos(phi), x[1] = sin(theta) * sin(phi), x[2] = cos(theta);
}
static double cosine_pdf(const cat_state *s, const double x[3])
{
    (void)s;
    return smp_cosine_hemisphere_pdf(vec3_make(x[0], x[1], x[2]));
}

/* A uniform hemisphere direction with the sphere's density 1/(4 pi): the
 * domain's measure halved. */
static void hemisphere_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    put3(x, smp_uniform_hemisphere_sample(u[0], u[1]));
}
static double sphere_pdf_on_hemisphere(const cat_state *s, const double x[3])
{
    (void)s;
    return x[2] >= 0.0 ? MC_INV_4PI : 0.0;
}

/* The polar disc with r = u instead of sqrt(u): points crowd the centre
 * while the density claims uniform. */
static void disc_no_sqrt_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    double r = u[0], phi = MC_2PI * u[1];
    x[0] = r * cos(phi), x[1] = r * sin(phi);
}
static double disc_pdf(const cat_state *s, const double x[3])
{
    (void)s;
    return smp_disc_polar_pdf(vec2_make(x[0], x[1]));
}

/* The triangle without its fold: the whole square, half of it outside. */
static void square_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = u[0], x[1] = u[1];
}
static double triangle_pdf(const cat_state *s, const double x[3])
{
    (void)s;
    return smp_triangle_pdf(vec2_make(x[0], x[1]));
}
static bool triangle_support(const cat_state *s, const double x[3])
{
    (void)s;
    return x[0] >= 0.0 && x[1] >= 0.0 && x[0] + x[1] <= 1.0 + 4.0 * 0x1p-52;
}

/* The density x / 2 on [0, 2] sampled as 2u: inverse CDF without its
 * square root. */
static void linear_no_sqrt_sample(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = 2.0 * u[0];
}
static double linear_pdf(const cat_state *s, const double x[3])
{
    (void)s;
    return x[0] >= 0.0 && x[0] <= 2.0 ? 0.5 * x[0] : 0.0;
}

/* Phong's lobe sampled with exponent n + 1, its density with n. */
static void phong_off_sample(const cat_state *s, const double *u, double x[3])
{
    put3(x, smp_phong_lobe_sample(u[0], u[1], s->p.n + 1.0));
}
static double phong_pdf(const cat_state *s, const double x[3])
{
    return smp_phong_lobe_pdf(vec3_make(x[0], x[1], x[2]), s->p.n);
}

#define HEMI(nm, what, smp, density)                                                               \
    .name = nm, .domain = "hemisphere(+z)", .measure = "solid-angle", .family = "negative",        \
    .point = CAT_DIRECTION, .uniforms = 2, .sample_u = smp, .pdf = density,                        \
    .chart = CAT_CHART_DIRECTION, .lo = 0.0, .hi = 1.0, .wrong = what

static const cat_row negatives[] = {
    {HEMI("wrong-cosine-no-pi", "cosine density without its 1/pi", cosine_sample,
          cosine_no_pi_pdf),
     .rim_zero = true},
    {HEMI("wrong-theta-uniform", "theta uniform claimed cosine (no sin theta Jacobian)",
          theta_uniform_sample, cosine_pdf),
     .rim_zero = true},
    {HEMI("wrong-hemisphere-4pi", "uniform hemisphere with the sphere's density 1/(4 pi)",
          hemisphere_sample, sphere_pdf_on_hemisphere)},
    {HEMI("wrong-phong-exponent", "Phong lobe sampled with n + 1, density with n",
          phong_off_sample, phong_pdf),
     .params = {{"n", CAT_NUMBER, offsetof(cat_values, n), "40", 0.0, (double)INFINITY, false,
                 false}},
     .rim_zero = true},
    {.name = "wrong-disc-no-sqrt", .domain = "unit-disc", .measure = "area", .family = "negative",
     .point = CAT_PLANAR, .uniforms = 2, .sample_u = disc_no_sqrt_sample, .pdf = disc_pdf,
     .chart = CAT_CHART_DISC, .hi = 1.0, .wrong = "polar disc radius u instead of sqrt(u)"},
    {.name = "wrong-triangle-no-fold", .domain = "triangle(0,0)(1,0)(0,1)", .measure = "area",
     .family = "negative", .point = CAT_PLANAR, .uniforms = 2, .sample_u = square_sample,
     .pdf = triangle_pdf, .in_support = triangle_support, .chart = CAT_CHART_XY, .hi = 1.0,
     .wrong = "triangle sampled without folding the square"},
    {.name = "wrong-linear-no-sqrt", .domain = "[0,2]", .measure = "length", .family = "negative",
     .point = CAT_REAL, .uniforms = 1, .sample_u = linear_no_sqrt_sample, .pdf = linear_pdf,
     .chart = CAT_CHART_LINE, .hi = 2.0, .wrong = "density x/2 sampled as 2u (no square root)"},
};

size_t cat_negative_count(void)
{
    return sizeof negatives / sizeof negatives[0];
}

const cat_row *cat_negative_at(size_t i)
{
    return i < cat_negative_count() ? &negatives[i] : NULL;
}
