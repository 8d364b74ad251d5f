/* tests/test_samplers_planar.c - uniform points on the unit square, the
 * unit disc (polar and concentric), the triangle, a parallelogram and a
 * sphere's surface: chi-square, normalization, domain, round trip, and
 * negative controls. Chapters 5 (the disc under the cosine hemisphere), 7
 * (parallelogram lights) and 10 (sphere lights).
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
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* The rows of the catalog this program tests (chi-square, normalization,
 * domain and round trip of every case: tests built in main). */
static const char *const families[] = {"planar"};

/* --- parallelogram and sphere surface, with "high-entropy" shapes -------- */

typedef struct shape3 {
    vec3 corner, eu, ev; /* parallelogram */
    vec3 center;         /* sphere */
    double radius;
    bool wrong_pdf; /* negative controls */
} shape3;

static const shape3 para = {
    {0.3, -1.2, 2.385}, {1.7, 0.2, -0.4}, {-0.3, 0.9, 0.6}, {0, 0, 0}, 0.0, false};
static const shape3 ball = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0.5, -1.0, 2.0}, 1.7, false};

static vec3 s_para(double u1, double u2, const warp_case *c)
{
    const shape3 *s = c->extra;
    return smp_parallelogram_sample(u1, u2, s->corner, s->eu, s->ev);
}

static double p_para(vec3 p, const warp_case *c)
{
    const shape3 *s = c->extra;
    double density = smp_parallelogram_pdf(p, s->corner, s->eu, s->ev);
    /* The classic slip: |u| |v| for the area, right only for a rectangle. */
    if (s->wrong_pdf && density > 0.0)
        return 1.0 / (vec3_length(s->eu) * vec3_length(s->ev));
    return density;
}

static vec2 i_para(vec3 p, const warp_case *c)
{
    const shape3 *s = c->extra;
    return smp_parallelogram_invert(p, s->corner, s->eu, s->ev);
}

/* (a, b) by least squares in the plane (Cramer on the Gram matrix),
 * independent of the sampler's dual-basis inverse. */
static void para_to_param(vec3 p, const warp_case *c, double out[2])
{
    const shape3 *s = c->extra;
    vec3 d = vec3_sub(p, s->corner);
    double uu = vec3_dot(s->eu, s->eu), uv = vec3_dot(s->eu, s->ev), vv = vec3_dot(s->ev, s->ev);
    double du = vec3_dot(d, s->eu), dv = vec3_dot(d, s->ev), det = uu * vv - uv * uv;
    out[0] = (du * vv - dv * uv) / det;
    out[1] = (dv * uu - du * uv) / det;
}

/* d area = |u x v| da db. */
static double para_param_pdf(const double p[2], const warp_case *c)
{
    const shape3 *s = c->extra;
    vec3 x = vec3_add(s->corner, vec3_add(vec3_scale(s->eu, p[0]), vec3_scale(s->ev, p[1])));
    return p_para(x, c) * vec3_length(vec3_cross(s->eu, s->ev));
}

static bool para_support(vec3 p, const warp_case *c)
{
    double ab[2];
    para_to_param(p, c, ab);
    const shape3 *s = c->extra;
    vec3 n = vec3_normalize(vec3_cross(s->eu, s->ev));
    double off = fabs(vec3_dot(vec3_sub(p, s->corner), n));
    /* 1e-12 of the shape's size: round-off of the sample's additions. */
    double tol = 1e-12 * (vec3_length(s->eu) + vec3_length(s->ev));
    return off <= tol && ab[0] >= -1e-12 && ab[0] <= 1.0 + 1e-12 && ab[1] >= -1e-12 &&
           ab[1] <= 1.0 + 1e-12;
}

static vec3 s_ball(double u1, double u2, const warp_case *c)
{
    const shape3 *s = c->extra;
    return smp_sphere_surface_sample(u1, u2, s->center, s->radius);
}

static double p_ball(vec3 p, const warp_case *c)
{
    const shape3 *s = c->extra;
    double density = smp_sphere_surface_pdf(p, s->center, s->radius);
    /* The slip: r instead of r^2 in the area 4 pi r^2. */
    return s->wrong_pdf ? density * s->radius : density;
}

static vec2 i_ball(vec3 p, const warp_case *c)
{
    const shape3 *s = c->extra;
    return smp_sphere_surface_invert(p, s->center, s->radius);
}

/* (cos theta, phi) of the point seen from the centre. */
static void ball_to_param(vec3 p, const warp_case *c, double out[2])
{
    const shape3 *s = c->extra;
    vec3 w = vec3_scale(vec3_sub(p, s->center), 1.0 / s->radius);
    out[0] = w.z;
    out[1] = smp_spherical_phi(w);
}

/* d area = r^2 d omega = r^2 d(cos theta) d phi. */
static double ball_param_pdf(const double p[2], const warp_case *c)
{
    const shape3 *s = c->extra;
    vec3 x = vec3_madd(s->center, smp_spherical_direction(p[0], p[1]), s->radius);
    return p_ball(x, c) * s->radius * s->radius;
}

static bool ball_support(vec3 p, const warp_case *c)
{
    const shape3 *s = c->extra;
    return fabs(vec3_length(vec3_sub(p, s->center)) - s->radius) <= 1e-12 * s->radius;
}

#define PARA_CASE(nm, shape)                                                                       \
    {                                                                                              \
        .name = nm, .sample = s_para, .pdf = p_para, .invert = i_para, .in_support = para_support, \
        .to_param = para_to_param, .param_pdf = para_param_pdf,               \
        .lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .cells = {50, 50}, .extra = shape                      \
    }
#define BALL_CASE(nm, shape)                                                                       \
    {                                                                                              \
        .name = nm, .sample = s_ball, .pdf = p_ball, .invert = i_ball, .in_support = ball_support, \
        .to_param = ball_to_param, .param_pdf = ball_param_pdf,               \
        .lo = {-1.0, 0.0}, .hi = {1.0, MC_2PI}, .extra = shape                                     \
    }

/* The two shapes the catalog has no row for (they take a whole shape as
 * parameters), at positions 4 and 5 of the planar group after the
 * catalog's square, discs and triangle (seed 6001). */
static const warp_case shape_cases[] = {
    PARA_CASE("parallelogram", &para),
    BALL_CASE("sphere-surface", &ball),
};

/* Seed 6001; per case as in warp_run_cases. */
static void test_shapes_all_checks(void **state)
{
    (void)state;
    warp_run_cases(shape_cases, COUNT(shape_cases), 4, N_CHI2, mc_test_seed(6001u));
}

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
    assert_near(smp_parallelogram_pdf(vec3_make(0.3, -1.2, 2.5), para.corner, para.eu, para.ev),
                0.0, 0.0);
    assert_near(smp_sphere_surface_pdf(vec3_make(0.5, -1.0, 2.0), ball.center, ball.radius), 0.0,
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

/* The catalog case `name` with its sampler replaced; *row holds the copy. */
static warp_case control(const char *label, const char *name, cat_row *row,
                         void (*sample)(const cat_state *, const double *, double *),
                         cat_state *s)
{
    const cat_row *r = NULL;
    const cat_case *tc = cat_find_case(name, &r);
    *row = *r;
    row->sample_u = sample;
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
    static cat_row rows[2];
    static cat_state st[2];
    warp_case disc = control("negctl-disc-no-sqrt", "disc-polar", &rows[0], s_disc_no_sqrt, &st[0]);
    assert_true(negctl_record(t, "disc radius without the sqrt", "chi-square",
                              warp_chi2_rejects(&disc, N_CHI2, seed)));

    warp_case tri = control("negctl-triangle-no-sqrt", "triangle", &rows[1], s_tri_no_sqrt, &st[1]);
    assert_true(negctl_record(t, "triangle without the sqrt", "chi-square",
                              warp_chi2_rejects(&tri, N_CHI2, seed + 1u)));

    shape3 bad_para = para;
    bad_para.wrong_pdf = true;
    warp_case pc = PARA_CASE("negctl-parallelogram-area-|u||v|", &bad_para);
    assert_true(
        negctl_record(t, "parallelogram area as |u| |v|", "normalization", warp_norm_rejects(&pc)));

    shape3 bad_ball = ball;
    bad_ball.wrong_pdf = true;
    warp_case bc = BALL_CASE("negctl-sphere-surface-4-pi-r", &bad_ball);
    assert_true(negctl_record(t, "sphere area as 4 pi r", "normalization", warp_norm_rejects(&bc)));
}

int main(void)
{
    struct CMUnitTest tests[64];
    size_t n = 0;
    warp_catalog_tests(families, 1, tests, &n, 60);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_shapes_all_checks);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_planar_special_points);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_negative_controls);
    return _cmocka_run_group_tests("test_samplers_planar", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
