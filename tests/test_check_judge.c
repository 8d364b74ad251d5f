/* tests/test_check_judge.c - the public check judged on what it claims of
 * itself: the power it reports, the quadrature's error on densities that
 * jump inside chart cells, the support it must not miss, the charts of
 * caps and spherical polygons, and the doubts it must report instead of
 * passing (an unresolved lobe, a quadrature it cannot settle).
 *
 * Statistics: every check here runs at the library's default level
 * (alpha = 0.01, one test), so each correct sampler below is a false alarm
 * with probability 0.01 at its fixed seed; the seeds are fixed (PCG32 seed
 * stated at each test) and the outcomes deterministic. The power formula
 * is held against the closed form for one degree of freedom and against a
 * simulation of 20,000 noncentral statistics (seed 29), whose rejection
 * rate must lie within 4 binomial standard errors (false alarm 6e-5).
 */
#include "tests/support/mc_test.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check/check.h"
#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/rng.h"
#include "mc/vec3.h"
#include "samplers/sphere.h"

/* --- the power formula ---------------------------------------------------- */

/* For one degree of freedom the noncentral statistic is (Z + sqrt(lambda))^2:
 * P(reject) = P(Z > sqrt(c) - sqrt(l)) + P(Z < -sqrt(c) - sqrt(l)). */
static void test_power_closed_form(void **state)
{
    (void)state;
    double level = 0.01, c = gsl_cdf_chisq_Qinv(level, 1.0);
    for (double l = 0.0; l <= 30.0; l += 2.5) {
        double want = gsl_cdf_ugaussian_Q(sqrt(c) - sqrt(l)) + gsl_cdf_ugaussian_P(-sqrt(c) - sqrt(l));
        assert_near(mc_chi2_power(1, level, l), want, 1e-9);
    }
    double l9 = mc_chi2_noncentrality_for_power(1, level, 0.9);
    assert_near(mc_chi2_power(1, level, l9), 0.9, 1e-6);
    /* Known value: about 14.88 for 1 dof, level 0.01, power 0.9. */
    assert_true(l9 > 14.0 && l9 < 15.5);
}

/* 20,000 statistics sum_i (Z_i + m_i)^2 over 50 degrees of freedom with
 * sum m_i^2 = lambda at the 0.9 point: the rejection rate is 0.9 within 4
 * standard errors (sqrt(0.09 / 20000) = 0.0021). */
static void test_power_simulated(void **state)
{
    (void)state;
    int dof = 50;
    double level = 0.001, lambda = mc_chi2_noncentrality_for_power(dof, level, 0.9);
    double crit = gsl_cdf_chisq_Qinv(level, (double)dof), m = sqrt(lambda / dof);
    mc_rng rng = mc_rng_derive(mc_test_seed(29), 0);
    int reject = 0, runs = 20000;
    for (int r = 0; r < runs; r++) {
        double x2 = 0.0;
        for (int i = 0; i < dof; i += 2) {
            /* Box-Muller: two standard normals. */
            double u1 = 1.0 - mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
            double rad = sqrt(-2.0 * log(u1));
            double z1 = rad * cos(MC_2PI * u2) + m, z2 = rad * sin(MC_2PI * u2) + m;
            x2 += z1 * z1 + z2 * z2;
        }
        reject += x2 > crit;
    }
    double rate = (double)reject / runs;
    printf("noncentrality %.3f at 50 dof, level 0.001: simulated power %.4f (0.9 stated)\n", lambda,
           rate);
    assert_true(fabs(rate - 0.9) < 4.0 * sqrt(0.09 / runs));
}

/* --- samplers on directions ----------------------------------------------- */

/* A uniform cone about a unit axis: cos theta uniform on [cos_max, 1]. */
typedef struct cone {
    vec3 axis, t, b;
    double cos_max, claim; /* the claimed density is claim / (2 pi (1 - cos_max)) */
    int wrong_theta;       /* theta (not cos theta) uniform: a classic slip */
} cone;

static cone cone_make(vec3 axis, double cos_max)
{
    cone c;
    memset(&c, 0, sizeof c);
    c.axis = vec3_normalize(axis);
    vec3 h = fabs(c.axis.x) > 0.9 ? vec3_make(0.0, 1.0, 0.0) : vec3_make(1.0, 0.0, 0.0);
    c.t = vec3_normalize(vec3_cross(h, c.axis));
    c.b = vec3_cross(c.axis, c.t);
    c.cos_max = cos_max;
    c.claim = 1.0;
    return c;
}

static void cone_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const cone *c = ctx;
    double ct = 1.0 - u[0] * (1.0 - c->cos_max);
    if (c->wrong_theta)
        ct = cos(u[0] * acos(c->cos_max));
    double st = sqrt(fmax(0.0, 1.0 - ct * ct)), phi = MC_2PI * u[1];
    vec3 d = vec3_add(vec3_scale(c->axis, ct),
                      vec3_add(vec3_scale(c->t, st * cos(phi)), vec3_scale(c->b, st * sin(phi))));
    out->x[0] = d.x, out->x[1] = d.y, out->x[2] = d.z;
}

static double cone_pdf(const double *x, void *ctx)
{
    const cone *c = ctx;
    double d = x[0] * c->axis.x + x[1] * c->axis.y + x[2] * c->axis.z;
    return d >= c->cos_max ? c->claim / (MC_2PI * (1.0 - c->cos_max)) : 0.0;
}

static void cone_pdf_batch(const double *x, size_t n, double *out, void *ctx)
{
    for (size_t i = 0; i < n; i++)
        out[i] = cone_pdf(x + 3 * i, ctx);
}

static mcbox_sampler cone_sampler(cone *c, mcbox_domain_kind kind, bool batch)
{
    mcbox_sampler s = mcbox_sampler_init(kind);
    s.sample = cone_sample;
    if (batch)
        s.pdf_batch = cone_pdf_batch;
    else
        s.pdf = cone_pdf;
    s.ctx = c;
    s.domain.axis[0] = c->axis.x, s.domain.axis[1] = c->axis.y, s.domain.axis[2] = c->axis.z;
    s.domain.cos_max = c->cos_max;
    return s;
}

static mcbox_check_result run(const mcbox_sampler *s, uint64_t n, uint64_t seed,
                              const mcbox_check_options *base)
{
    mcbox_check_options o = base ? *base : mcbox_check_defaults();
    o.samples = n;
    o.seed = mc_test_seed(seed);
    mcbox_check_result r;
    assert_int_equal(mcbox_check_run(s, &o, &r, NULL), 0);
    printf("  %s: stat %.1f dof %d integral %.9f +- %.2g power %.3g %s%s%s\n",
           r.pass ? "pass" : r.undetermined ? "undetermined" : "rejected", r.statistic, r.dof,
           r.pdf_integral, r.pdf_integral_error, r.power_rel_error, r.message, r.warning[0] ? "; warning: " : "", r.warning);
    return r;
}

/* The cone's rim crosses the (cos theta, phi) cells of the sphere's chart
 * on a curve: the quadrature must refine it to an honest error, through
 * both the pointwise and the batch density, and still catch a density
 * 0.5% high. On the cap's own chart the rim is a cell edge. Seeds 31, 32. */
static void test_cone_with_jumps(void **state)
{
    (void)state;
    cone c = cone_make(vec3_make(0.3, -0.5, 0.8), 0.9);
    for (int batch = 0; batch < 2; batch++) {
        for (int k = 0; k < 2; k++) {
            mcbox_domain_kind kind = k ? MCBOX_CAP : MCBOX_SPHERE;
            printf("cone on %s, %s density\n", mcbox_domain_name(kind), batch ? "batch" : "pointwise");
            c.claim = 1.0;
            mcbox_sampler s = cone_sampler(&c, kind, batch);
            mcbox_check_result r = run(&s, 200000, 31, NULL);
            assert_true(r.pass);
            /* The integral is 1 within the error the check states. */
            assert_true(fabs(r.pdf_integral - 1.0) <= r.pdf_integral_error + 1e-6);
            assert_true(r.pdf_integral_error <= 1e-3);
            c.claim = 1.005;
            r = run(&s, 200000, 32, NULL);
            assert_false(r.pass);
            assert_false(r.undetermined);
            assert_non_null(strstr(r.message, "integrates to"));
            printf("negative control density 0.5%% high on the %s: caught by normalization\n",
                   mcbox_domain_name(kind));
        }
    }
    /* Theta uniform instead of cos theta, with the right density: the cap's
     * chart sees it. Seed 33. */
    c.claim = 1.0, c.wrong_theta = 1;
    mcbox_sampler s = cone_sampler(&c, MCBOX_CAP, false);
    mcbox_check_result r = run(&s, 200000, 33, NULL);
    assert_false(r.pass);
    assert_non_null(strstr(r.message, "chi-square"));
    printf("negative control cone uniform in theta: caught by chi-square on the cap\n");
}

/* With no halving allowed the rim's cells keep an error far above the
 * limit: the verdict is undetermined, never a pass. Seed 34. */
static void test_undetermined_quadrature(void **state)
{
    (void)state;
    cone c = cone_make(vec3_make(0.3, -0.5, 0.8), 0.9);
    mcbox_sampler s = cone_sampler(&c, MCBOX_SPHERE, true);
    mcbox_check_options o = mcbox_check_defaults();
    o.quad_depth = 0;
    o.quad_error_max = 1e-5;
    mcbox_check_result r = run(&s, 100000, 34, &o);
    assert_false(r.pass);
    assert_true(r.undetermined);
    assert_non_null(strstr(r.message, "undetermined"));
}

/* A cone of radius 0.002 rad sits inside one cell of the sphere's chart,
 * between the quadrature's nodes. The samples in it point the refinement
 * at it; with no halving allowed the check says it missed the support
 * (undetermined), with halving it finds it, and then says the chart does
 * not resolve the density, naming the lobe width and axis to pass; with
 * those it passes. Seeds 35-37. */
static void test_tiny_support(void **state)
{
    (void)state;
    cone c = cone_make(vec3_make(0.52, 0.31, 0.61), cos(0.002));
    mcbox_sampler s = cone_sampler(&c, MCBOX_SPHERE, true);
    mcbox_check_options o = mcbox_check_defaults();
    o.quad_depth = 0;
    mcbox_check_result r = run(&s, 100000, 35, &o);
    assert_true(r.undetermined);
    assert_non_null(strstr(r.message, "missed part of the density's support"));
    r = run(&s, 100000, 36, NULL);
    assert_true(r.undetermined);
    assert_non_null(strstr(r.warning, "--lobe-width"));
    vec3 hint = vec3_make(r.lobe_hint_axis[0], r.lobe_hint_axis[1], r.lobe_hint_axis[2]);
    assert_true(vec3_dot(hint, c.axis) > cos(0.0005));
    assert_true(r.lobe_hint_width > 0.0005 && r.lobe_hint_width < 0.005);
    o = mcbox_check_defaults();
    o.lobe_width = r.lobe_hint_width;
    memcpy(o.lobe_axis, r.lobe_hint_axis, sizeof o.lobe_axis);
    r = run(&s, 100000, 37, &o);
    assert_true(r.pass);
}

/* --- spherical polygons --------------------------------------------------- */

/* Uniform on the octant x, y, z > 0 (solid angle pi / 2), from the uniform
 * sphere folded by absolute values; the triangle of the three axes. */
static void octant_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    vec3 d = smp_uniform_sphere_sample(u[0], u[1]);
    out->x[0] = fabs(d.x), out->x[1] = fabs(d.y), out->x[2] = fabs(d.z);
}

static double octant_pdf(const double *x, void *ctx)
{
    const double *claim = ctx;
    return x[0] >= 0.0 && x[1] >= 0.0 && x[2] >= 0.0 ? *claim * 2.0 / MC_PI : 0.0;
}

/* Uniform on the cube's face x = 1 seen from its centre (solid angle
 * 4 pi / 6), by rejection from the uniform sphere. */
static void face_sample(mcbox_stream *st, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    vec3 d;
    do
        d = smp_uniform_sphere_sample(mcbox_uniform(st), mcbox_uniform(st));
    while (!(d.x > 0.0 && fabs(d.y) <= d.x && fabs(d.z) <= d.x));
    out->x[0] = d.x, out->x[1] = d.y, out->x[2] = d.z;
}

static double face_pdf(const double *x, void *ctx)
{
    const double *claim = ctx;
    bool in = x[0] > 0.0 && fabs(x[1]) <= x[0] && fabs(x[2]) <= x[0];
    return in ? *claim * 6.0 / (4.0 * MC_PI) : 0.0;
}

/* Seeds 38-41. */
static void test_spherical_polygons(void **state)
{
    (void)state;
    double claim = 1.0;
    mcbox_sampler t = mcbox_sampler_init(MCBOX_SPHERICAL_TRIANGLE);
    t.sample = octant_sample, t.pdf = octant_pdf, t.ctx = &claim;
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memcpy(t.domain.vertex, v, sizeof v);
    printf("octant as a spherical triangle\n");
    mcbox_check_result r = run(&t, 200000, 38, NULL);
    assert_true(r.pass);
    /* On the triangle's own chart the density is smooth in every cell. */
    assert_near(r.pdf_integral, 1.0, 1e-9);
    mcbox_sampler q = mcbox_sampler_init(MCBOX_SPHERICAL_QUAD);
    q.uniforms = 0;
    q.sample_stream = face_sample, q.pdf = face_pdf, q.ctx = &claim;
    double f[3][3] = {{1, -1, -1}, {0, 2, 0}, {0, 0, 2}};
    memcpy(q.domain.vertex, f, sizeof f);
    printf("cube face as a spherical quad\n");
    r = run(&q, 200000, 39, NULL);
    assert_true(r.pass);
    assert_near(r.pdf_integral, 1.0, 1e-9);
    claim = 1.005;
    r = run(&q, 200000, 40, NULL);
    assert_false(r.pass);
    printf("negative control face density 0.5%% high: caught\n");
    /* Points outside the polygon are outside its domain. */
    claim = 1.0;
    mcbox_sampler w = t;
    w.sample = NULL, w.uniforms = 0, w.sample_stream = face_sample;
    r = run(&w, 20000, 41, NULL);
    assert_false(r.pass);
    assert_true(r.outside > 0);
    /* A degenerate polygon is refused. */
    double flat[3][3] = {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    memcpy(t.domain.vertex, flat, sizeof flat);
    mcbox_check_options o = mcbox_check_defaults();
    assert_int_equal(mcbox_check_run(&t, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "degenerate"));
}

/* --- what a pass proves --------------------------------------------------- */

/* The uniform hemisphere against a density off by a relative e over the
 * wedge phi < pi / 5 (a tenth of the mass) and rescaled elsewhere: at
 * e = 1.5 times the power the correct sampler's own pass reported, the
 * test must reject (a pass said it would with probability 0.9; the
 * noncentrality is then 2.25 times that of the 0.9 point). Seeds 42, 43. */
typedef struct wedge {
    double e;
} wedge;

static void hemi_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    double z = u[0], r = sqrt(fmax(0.0, 1.0 - z * z)), phi = MC_2PI * u[1];
    out->x[0] = r * cos(phi), out->x[1] = r * sin(phi), out->x[2] = z;
}

static double wedge_pdf(const double *x, void *ctx)
{
    const wedge *w = ctx;
    double phi = atan2(x[1], x[0]);
    if (phi < 0.0)
        phi += MC_2PI;
    double f = phi < MC_PI / 5.0 ? 1.0 + w->e : 1.0 - w->e * 0.1 / 0.9;
    return x[2] >= 0.0 ? f / MC_2PI : 0.0;
}

static void test_power_stated(void **state)
{
    (void)state;
    wedge w = {0.0};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
    s.sample = hemi_sample, s.pdf = wedge_pdf, s.ctx = &w;
    mcbox_check_result r = run(&s, 100000, 42, NULL);
    assert_true(r.pass);
    assert_near(r.power_share, 0.1, 0.0);
    assert_true(isfinite(r.power_rel_error) && r.power_rel_error > 0.0 && r.power_rel_error < 1.0);
    assert_true(r.scale_detectable > 0.0 && r.scale_detectable < 1e-4);
    w.e = 1.5 * r.power_rel_error;
    printf("density off by %.3g over a tenth of the mass\n", w.e);
    r = run(&s, 100000, 43, NULL);
    assert_false(r.pass);
    assert_non_null(strstr(r.message, "chi-square"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_power_closed_form),
        cmocka_unit_test(test_power_simulated),
        cmocka_unit_test(test_cone_with_jumps),
        cmocka_unit_test(test_undetermined_quadrature),
        cmocka_unit_test(test_tiny_support),
        cmocka_unit_test(test_spherical_polygons),
        cmocka_unit_test(test_power_stated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
