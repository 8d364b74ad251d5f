/* tests/test_samplers_planar.c - uniform points on the unit square, the
 * unit disc (polar and concentric), the triangle, a parallelogram and a
 * sphere's surface: chi-square, normalization, domain, round trip, and
 * negative controls. This book's #ch-directions (the disc under the cosine
 * hemisphere) and #ch-lights (the parallelogram lights of Shirley, "Ray
 * Tracing: The Rest of Your Life" (v1.123), chapter 7, and the sphere
 * lights of its chapter 10).
 *
 * Statistics (seeds overridable with MC_TEST_SEED): chi-square with 10^6
 * samples per case at chi2_suite_alpha() = 1.57e-4 (Sidak: 1% over the
 * suite's <= 64 tests); discs in (r^2, phi), where uniform area is uniform.
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/constants.h"
#include "samplers/planar.h"
#include "samplers/spherical.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

enum { N_CHI2 = 1000000 };

/* The rows of the catalog this program tests (chi-square, normalization,
 * domain and round trip of every case: tests built in main). */
static const char *const families[] = {"planar"};

/* The "high-entropy" shapes of the catalog's parallelogram and
 * sphere-surface cases, for the known answers below. */
static const vec3 para_corner = {0.3, -1.2, 2.385}, para_u = {1.7, 0.2, -0.4},
                  para_v = {-0.3, 0.9, 0.6};
static const vec3 ball_center = {0.5, -1.0, 2.0};
static const double ball_radius = 1.7;

/* Known answers where the warps meet their special points. */
static void test_planar_special_points(void **state)
{
    (void)state;
    vec2 o = smp_disc_concentric_sample(0.5, 0.5);
    assert_true(o.x == 0.0 && o.y == 0.0);
    vec2 u = smp_disc_concentric_invert(vec2_make(0.0, 0.0));
    assert_near(u.x, 0.5, 0.0);
    assert_near(u.y, 0.5, 0.0);
    /* The corners of the square go to the disc's rim at 45 degrees. */
    vec2 c = smp_disc_concentric_sample(1.0, 1.0);
    assert_near(c.x, sqrt(0.5), 1e-15);
    assert_near(c.y, sqrt(0.5), 1e-15);
    vec2 t = smp_triangle_sample(0.0, 0.3);
    assert_true(t.x == 1.0 && t.y == 0.0);
    assert_near(smp_triangle_pdf(vec2_make(0.6, 0.5)), 0.0, 0.0);
    assert_near(smp_disc_polar_pdf(vec2_make(0.8, 0.61)), 0.0, 0.0);
    assert_near(smp_parallelogram_pdf(vec3_make(0.3, -1.2, 2.5), para_corner, para_u, para_v),
                0.0, 0.0);
    assert_near(smp_sphere_surface_pdf(vec3_make(0.5, -1.0, 2.0), ball_center, ball_radius), 0.0,
                0.0);
}

/* --- negative controls -------------------------------------------------- */

/* r = u2 instead of sqrt(u2): the points crowd at the centre. */
static void s_disc_no_sqrt(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    double phi = MC_2PI * u[0];
    x[0] = u[1] * cos(phi), x[1] = u[1] * sin(phi);
}

/* (1 - u1, u2 u1): the triangle without the sqrt. */
static void s_tri_no_sqrt(const cat_state *s, const double *u, double x[3])
{
    (void)s;
    x[0] = 1.0 - u[0], x[1] = u[1] * u[0];
}

/* The classic slip: |u| |v| for the parallelogram's area, right only for
 * a rectangle. */
static double p_para_lengths(const cat_state *s, const double x[3])
{
    double density = cat_find("parallelogram")->pdf(s, x);
    return density > 0.0 ? 1.0 / (vec3_length(s->p.u) * vec3_length(s->p.v)) : 0.0;
}

/* The slip: r instead of r^2 in the sphere's area 4 pi r^2. */
static double p_ball_4_pi_r(const cat_state *s, const double x[3])
{
    return cat_find("sphere-surface")->pdf(s, x) * s->p.radius;
}

/* The catalog case `name` with its sampler or its density replaced (NULL:
 * kept); *row holds the copy. */
static warp_case control(const char *label, const char *name, cat_row *row,
                         void (*sample)(const cat_state *, const double *, double *),
                         double (*density)(const cat_state *, const double *), cat_state *s)
{
    const cat_row *r = NULL;
    const cat_case *tc = cat_find_case(name, &r);
    assert_non_null(tc);
    *row = *r;
    row->sample_u = sample ? sample : r->sample_u;
    row->pdf = density ? density : r->pdf;
    row->invert = NULL;
    warp_case c = warp_case_of(row, tc, s);
    c.name = label;
    return c;
}

/* Seed 6002 for the sampled controls. */
static void test_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(6002u);
    static cat_row rows[4];
    static cat_state st[4];
    warp_case disc =
        control("negctl-disc-no-sqrt", "disc-polar", &rows[0], s_disc_no_sqrt, NULL, &st[0]);
    assert_true(negctl_record(t, "disc radius without the sqrt", "chi-square",
                              warp_chi2_rejects(&disc, N_CHI2, seed)));

    warp_case tri =
        control("negctl-triangle-no-sqrt", "triangle", &rows[1], s_tri_no_sqrt, NULL, &st[1]);
    assert_true(negctl_record(t, "triangle without the sqrt", "chi-square",
                              warp_chi2_rejects(&tri, N_CHI2, seed + 1u)));

    warp_case pc = control("negctl-parallelogram-area-|u||v|", "parallelogram", &rows[2], NULL,
                           p_para_lengths, &st[2]);
    assert_true(
        negctl_record(t, "parallelogram area as |u| |v|", "normalization", warp_norm_rejects(&pc)));

    warp_case bc = control("negctl-sphere-surface-4-pi-r", "sphere-surface", &rows[3], NULL,
                           p_ball_4_pi_r, &st[3]);
    assert_true(negctl_record(t, "sphere area as 4 pi r", "normalization", warp_norm_rejects(&bc)));
}

int main(void)
{
    struct CMUnitTest tests[64];
    size_t n = 0;
    warp_catalog_tests(families, 1, tests, &n, 60);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_planar_special_points);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_negative_controls);
    return _cmocka_run_group_tests("test_samplers_planar", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
