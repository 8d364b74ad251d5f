/* tests/test_chapters3.c - the estimators behind the chapter programs of
 * this book's #ch-sphere to #ch-mixture, after Shirley, "Ray Tracing: The
 * Rest of Your Life" (v1.123), chapters 2-10 (sphere_importance, cos_cubed,
 * light_pdf, sphere_light, projected_area, mixture; pdf/experiments.h):
 * z-tests against exact values derived here independently (closed forms,
 * moments, GSL quadrature), each with a wrong estimator the same z-test
 * rejects; then the programs themselves, run from $MC_BUILD/bin: every CSV
 * row they print has |z| < 4.
 *
 * Every z-test: |z| < 4, two-sided false-alarm rate 6.3e-5 per test.
 */
#define _POSIX_C_SOURCE 200809L /* popen */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/quad.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/spherical.h"
#include "tests/support/negctl.h"

#define Z_MAX 4.0
enum { N = 1000000 };

static bool z_rejects(mc_estimate e, double exact)
{
    return !(fabs(mc_z_score(e.value, exact, e.std_error)) < Z_MAX);
}

/* The standard deviation of the sample variance of n draws of a weight
 * with raw moments m[1..4]: sqrt((mu4 - sigma^4) / n). */
static double variance_sd(const double m[5], double n)
{
    double mu = m[1], var = m[2] - mu * mu;
    double mu4 = m[4] - 4.0 * m[3] * mu + 6.0 * m[2] * mu * mu - 3.0 * mu * mu * mu * mu;
    return sqrt((mu4 - var * var) / n);
}

/* Mean and variance per sample of an estimate against moments m[1..4]. */
static void assert_moments(const char *label, mc_estimate e, const double m[5], uint64_t seed)
{
    assert_z_below(label, e.value, m[1], e.std_error, Z_MAX, seed);
    assert_z_below(label, e.variance, m[2] - m[1] * m[1], variance_sd(m, (double)e.n), Z_MAX, seed);
}

/* --- sphere_importance ------------------------------------------------- */

static double cos_sq(vec3 d, void *ctx)
{
    (void)ctx;
    return d.z * d.z;
}
/* The catalog's row `name` with its defaults, prepared into *s, and
 * optionally its density replaced (the copy in *row). */
static const cat_state *row_state(const char *name, cat_row *row,
                                  double (*density)(const cat_state *, const double *),
                                  cat_state *s)
{
    char err[256];
    *row = *cat_find(name);
    if (density)
        row->pdf = density;
    cat_values v;
    cat_defaults(row, &v);
    if (!cat_prepare(row, &v, s, err, sizeof err))
        fail_msg("%s", err);
    return s;
}

static double hemisphere_density(const cat_state *s, const double x[3])
{
    (void)s, (void)x;
    return MC_INV_2PI;
}

/* 10^6 uniform directions (seed 7001): the weight 4 pi c^2 with c = cos
 * theta uniform on [-1, 1] has raw moments (4 pi)^k / (2k + 1): mean
 * 4 pi / 3, variance 64 pi^2 / 45. Negative control: the same directions
 * weighted with the hemisphere's density 1 / (2 pi) estimate half. */
static void test_sphere_importance(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(7001u);
    double m[5];
    for (int k = 0; k <= 4; k++)
        m[k] = pow(MC_4PI, k) / (2.0 * k + 1.0);
    mc_rng rng = mc_rng_derive(seed, 0u);
    cat_row row;
    cat_state s;
    const cat_state *uniform = row_state("sphere-inverse", &row, NULL, &s);
    assert_moments("sphere cos^2", cat_integrate((pdf_fn){cos_sq, NULL}, uniform, &rng, N), m,
                   seed);
    rng = mc_rng_derive(seed, 1u);
    const cat_state *wrong = row_state("sphere-inverse", &row, hemisphere_density, &s);
    mc_estimate e = cat_integrate((pdf_fn){cos_sq, NULL}, wrong, &rng, N);
    assert_seeded(
        negctl_record(t, "sphere weighted with the hemisphere pdf", "z-test", z_rejects(e, m[1])),
        seed);
}

/* --- cos_cubed ------------------------------------------------------------ */

static double cos_cubed(vec3 d, void *ctx)
{
    (void)ctx;
    return d.z > 0.0 ? d.z * d.z * d.z : 0.0;
}
static double cosine_without_pi(const cat_state *s, const double x[3])
{
    (void)s;
    return x[2] > 0.0 ? x[2] : 0.0;
}

/* Seeds 7002, 7003, 10^6 each. Uniform: weight 2 pi c^3, c uniform on
 * [0, 1]: moments (2 pi)^k / (3k + 1), variance 9 pi^2 / 28. Cosine:
 * weight pi c^2 with c^2 uniform: moments pi^k / (k + 1), variance
 * pi^2 / 12. Negative control: the cosine density without its 1 / pi
 * (estimates 1/2). */
static void test_cos_cubed(void **state)
{
    negctl *t = *state;
    double mu[5], mc[5];
    for (int k = 0; k <= 4; k++) {
        mu[k] = pow(MC_2PI, k) / (3.0 * k + 1.0);
        mc[k] = pow(MC_PI, k) / (k + 1.0);
    }
    assert_near(mu[1], MC_PI_2, 1e-15);
    assert_near(mu[2] - mu[1] * mu[1], 9.0 * MC_PI * MC_PI / 28.0, 1e-14);
    assert_near(mc[2] - mc[1] * mc[1], MC_PI * MC_PI / 12.0, 1e-14);
    uint64_t seed = mc_test_seed(7002u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    pdf_fn f = {cos_cubed, NULL};
    cat_row row;
    cat_state s;
    assert_moments("cos^3 uniform", cat_integrate(f, row_state("hemisphere", &row, NULL, &s), &rng, N),
                   mu, seed);
    seed = mc_test_seed(7003u);
    rng = mc_rng_derive(seed, 0u);
    assert_moments("cos^3 cosine", cat_integrate(f, row_state("cosine", &row, NULL, &s), &rng, N), mc,
                   seed);
    rng = mc_rng_derive(seed, 1u);
    mc_estimate e = cat_integrate(f, row_state("cosine", &row, cosine_without_pi, &s), &rng, N);
    assert_seeded(negctl_record(t, "cosine pdf without 1/pi", "z-test", z_rejects(e, MC_PI_2)),
                  seed);
}

/* --- light_pdf ------------------------------------------------------------ */

/* The program's light: L = 4 on corner (-0.3, 0.2, 1), u = (0.8, 0, 0.2),
 * v = (0, 0.6, 0.1), seen from the origin with normal +z. */
typedef struct quad_light {
    vec3 corner, u, v;
    double radiance;
} quad_light;

static const quad_light LIGHT = {{-0.3, 0.2, 1.0}, {0.8, 0.0, 0.2}, {0.0, 0.6, 0.1}, 4.0};

/* The area form of the irradiance, integrated over the light's (s, t):
 * L cos_x cos_l A / r^2 (the measure change of Shirley, "Ray Tracing: The
 * Rest of Your Life" (v1.123), chapter 7, applied the other way round from
 * the pdf). */
static double area_integrand(double s, double t, void *params)
{
    const quad_light *l = params;
    vec3 q = vec3_madd(vec3_madd(l->corner, l->u, s), l->v, t), n = vec3_cross(l->u, l->v);
    double r2 = vec3_length_sq(q), r = sqrt(r2);
    double cos_x = q.z / r, cos_l = fabs(vec3_dot(n, q)) / (vec3_length(n) * r);
    return l->radiance * cos_x * cos_l * vec3_length(n) / r2;
}

static double light_exact(const quad_light *l)
{
    const vec3 c[4] = {l->corner, vec3_add(l->corner, l->u),
                       vec3_add(vec3_add(l->corner, l->u), l->v), vec3_add(l->corner, l->v)};
    return pdf_polygon_irradiance(vec3_make(0.0, 0.0, 0.0), vec3_make(0.0, 0.0, 1.0), c, 4,
                                  l->radiance);
}

/* Lambert's formula against GSL quadrature of the area form, for the
 * program's light and for a unit square at height 1 straight above. */
static void test_light_polygon_formula(void **state)
{
    (void)state;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    const quad_light lights[2] = {LIGHT,
                                  {{-0.5, -0.5, 1.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.385}};
    for (int i = 0; i < 2; i++) {
        double v = 0.0;
        assert_int_equal(mc_quad_2d(q, (mc_fn2){area_integrand, (void *)&lights[i]}, 0.0, 1.0, 0.0,
                                    1.0, &v, NULL),
                         0);
        assert_near(light_exact(&lights[i]), v, 1e-10 * v);
    }
    mc_quad_destroy(q);
}

/* L cos theta where the ray from the origin meets the light, else 0; the
 * hit found by solving origin + r d = corner + s u + t v by Cramer's rule
 * (independent of the pdf's own intersection). */
static double light_integrand(vec3 d, void *ctx)
{
    const quad_light *l = ctx;
    if (d.z <= 0.0)
        return 0.0;
    /* r d - s u - t v = corner: det = d . (u x v). */
    vec3 uv = vec3_cross(l->u, l->v);
    double det = vec3_dot(d, uv);
    if (det == 0.0)
        return 0.0;
    double r = vec3_dot(l->corner, uv) / det;
    double s = -vec3_dot(d, vec3_cross(l->corner, l->v)) / det;
    double t = -vec3_dot(d, vec3_cross(l->u, l->corner)) / det;
    return r > 0.0 && s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0 ? l->radiance * d.z : 0.0;
}

/* light_pdf's two estimators (seed 7004, 10^6 each); negative control:
 * the light's directions weighted with dist^2 / A, the pdf without its
 * cosine. */
static void test_light_pdf(void **state)
{
    negctl *t = *state;
    const quad_light *l = &LIGHT;
    double exact = light_exact(l);
    uint64_t seed = mc_test_seed(7004u);
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    pdf light = pdf_toward_quad(o, l->corner, l->u, l->v),
        cosine = pdf_cosine(vec3_make(0.0, 0.0, 1.0));
    pdf_fn f = {light_integrand, (void *)l};
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate e = pdf_integrate(f, &light, &rng, N);
    assert_z_below("light_pdf light", e.value, exact, e.std_error, Z_MAX, seed);
    rng = mc_rng_derive(seed, 1u);
    e = pdf_integrate(f, &cosine, &rng, N);
    assert_z_below("light_pdf cosine", e.value, exact, e.std_error, Z_MAX, seed);

    rng = mc_rng_derive(seed, 2u);
    mc_welford w = mc_welford_init();
    vec3 n = vec3_normalize(vec3_cross(l->u, l->v));
    for (int i = 0; i < N; i++) {
        vec3 d = pdf_generate(&light, &rng);
        double no_cos = pdf_value(&light, d) * fabs(vec3_dot(n, d));
        mc_welford_add(&w, f.f(d, f.ctx) / no_cos);
    }
    assert_seeded(negctl_record(t, "light pdf without the cosine", "z-test",
                                z_rejects(mc_welford_estimate(&w), exact)),
                  seed);
}

/* --- sphere_light ----------------------------------------------------------- */

typedef struct cone_params {
    onb frame;
    double radiance;
} cone_params;

static double cone_integrand(double cos_a, double phi, void *params)
{
    const cone_params *c = params;
    vec3 d = onb_to_world(&c->frame, smp_spherical_direction(cos_a, phi));
    return d.z > 0.0 ? c->radiance * d.z : 0.0;
}

static double radiance_cos(vec3 d, void *ctx)
{
    return d.z > 0.0 ? *(const double *)ctx * d.z : 0.0;
}

/* The program's default light: flux 10, radius 0.5, distance 3, 30 degrees
 * from the normal; and a near, large one (0.9 at 1.5, 20 degrees). The
 * formula phi cos theta / (4 pi d^2) against quadrature over the cone;
 * both estimators z-tested (seed 7005); negative control: area sampling
 * that counts the far half with |cos| (no visibility). */
static void test_sphere_light(void **state)
{
    negctl *t = *state;
    const double cfg[2][3] = {{0.5, 3.0, 30.0}, {0.9, 1.5, 20.0}}; /* radius, distance, degrees */
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    vec3 o = vec3_make(0.0, 0.0, 0.0), up = vec3_make(0.0, 0.0, 1.0);
    for (int i = 0; i < 2; i++) {
        double r = cfg[i][0], d = cfg[i][1], th = cfg[i][2] * MC_PI / 180.0, flux = 10.0;
        double radiance = flux / (MC_4PI * MC_PI * r * r);
        vec3 center = vec3_make(d * sin(th), 0.0, d * cos(th));
        double exact = pdf_sphere_light_irradiance(flux, d, cos(th)), v = 0.0;
        cone_params c = {onb_from_w(vec3_normalize(center)), radiance};
        (void)mc_quad_2d(q, (mc_fn2){cone_integrand, &c}, sqrt(1.0 - r * r / (d * d)), 1.0, 0.0,
                         MC_2PI, &v, NULL);
        assert_near(exact, v, 1e-10 * v);

        uint64_t seed = mc_test_seed(7005u + (uint64_t)i);
        mc_rng rng = mc_rng_derive(seed, 0u);
        mc_estimate e = pdf_sphere_light_by_area(o, up, center, r, radiance, &rng, N);
        assert_z_below("sphere_light area", e.value, exact, e.std_error, Z_MAX, seed);
        rng = mc_rng_derive(seed, 1u);
        pdf cone = pdf_toward_sphere(o, center, r);
        e = pdf_integrate((pdf_fn){radiance_cos, &radiance}, &cone, &rng, N);
        assert_z_below("sphere_light cone", e.value, exact, e.std_error, Z_MAX, seed);
        if (i == 1) {
            rng = mc_rng_derive(seed, 2u);
            mc_welford w = mc_welford_init();
            for (int k = 0; k < N; k++) {
                double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
                vec3 p = smp_sphere_surface_sample(u1, u2, center, r), dir = vec3_normalize(p);
                double cos_q = fabs(vec3_dot(vec3_normalize(vec3_sub(p, center)), dir));
                mc_welford_add(&w, radiance * fmax(0.0, dir.z) * cos_q / vec3_length_sq(p) *
                                       MC_4PI * r * r);
            }
            assert_seeded(negctl_record(t, "sphere light by area without visibility", "z-test",
                                        z_rejects(mc_welford_estimate(&w), exact)),
                          seed);
        }
    }
    mc_quad_destroy(q);
}

/* --- projected_area ------------------------------------------------------ */

/* The program's box (2.385 x 1 x 0.5) and unit sphere; seed 7007. Known
 * answers first: the box seen along x casts its 1 x 0.5 face, along the
 * diagonal (1,1,1)/sqrt 3 it casts (sum of the face areas)/sqrt 3. */
static void test_projected_area(void **state)
{
    negctl *t = *state;
    pdf_body box = {true, vec3_make(1.1925, 0.5, 0.25), 0.0},
             ball = {false, vec3_make(0.0, 0.0, 0.0), 1.0};
    assert_near(pdf_body_projected_area(box, vec3_make(1.0, 0.0, 0.0)), 0.5, 1e-15);
    assert_near(pdf_body_projected_area(box, vec3_normalize(vec3_make(1.0, 1.0, 1.0))),
                (0.5 + 1.1925 + 2.385) / sqrt(3.0), 1e-14);
    assert_near(pdf_body_area(box), 2.0 * (2.385 + 0.5 + 1.1925), 1e-14);
    uint64_t seed = mc_test_seed(7007u);
    const double box_mean = 2.0 * (2.385 + 0.5 + 1.1925) / 4.0;
    for (int rays = 0; rays < 2; rays++) {
        mc_rng rng = mc_rng_derive(seed, (uint64_t)rays);
        mc_estimate e = pdf_mean_projected_area(box, rays, &rng, N);
        assert_z_below(rays ? "box by rays" : "box exact shadow", e.value, box_mean, e.std_error,
                       Z_MAX, seed);
    }
    mc_rng rng = mc_rng_derive(seed, 2u);
    mc_estimate e = pdf_mean_projected_area(ball, false, &rng, 1000u);
    assert_near(e.value, MC_PI, 1e-15);
    rng = mc_rng_derive(seed, 3u);
    e = pdf_mean_projected_area(ball, true, &rng, N);
    assert_z_below("sphere by rays", e.value, MC_PI, e.std_error, Z_MAX, seed);
    /* Negative control: the shadow as the sum over all six faces of
     * |d . n| A, forgetting that each shadow point is covered twice. */
    rng = mc_rng_derive(seed, 4u);
    mc_welford w = mc_welford_init();
    for (int i = 0; i < N; i++) {
        double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
        mc_welford_add(&w, 2.0 * pdf_body_projected_area(box, smp_uniform_sphere_sample(u1, u2)));
    }
    assert_seeded(negctl_record(t, "box shadow from all six faces", "z-test",
                                z_rejects(mc_welford_estimate(&w), box_mean)),
                  seed);
}

/* --- mixture ---------------------------------------------------------------- */

typedef struct sky_scene {
    quad_light light;
    double sky;
} sky_scene;

/* (cos / pi) (sky + L on the light): reflected radiance of a white
 * Lambertian surface; exact sky + E / pi. */
static double sky_integrand(vec3 d, void *ctx)
{
    const sky_scene *s = ctx;
    return d.z > 0.0 ? MC_INV_PI * (s->sky * d.z + light_integrand(d, (void *)&s->light)) : 0.0;
}

/* Seed 7008, 10^6 per estimate: cosine, light and the 50/50 mixture agree
 * on the irradiance; with a sky of radiance 0.5 the cosine and the
 * mixture agree on the reflected radiance and the mixture's variance is
 * below a fifth of the cosine's (asserted on every run). Negative controls: the mixture's directions weighted by the
 * density of the component that produced them only; the light pdf alone
 * under the sky (it never samples the sky). */
static void test_mixture(void **state)
{
    negctl *t = *state;
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    pdf cosine = pdf_cosine(vec3_make(0.0, 0.0, 1.0)),
        light = pdf_toward_quad(o, LIGHT.corner, LIGHT.u, LIGHT.v);
    const pdf *parts[2] = {&cosine, &light};
    const double weights[2] = {0.5, 0.5};
    pdf mix = pdf_mixture(parts, weights, 2);
    double e_light = light_exact(&LIGHT);
    sky_scene sky = {LIGHT, 0.5};
    double exact_sky = 0.5 + e_light * MC_INV_PI;
    uint64_t seed = mc_test_seed(7008u);
    const pdf *p[3] = {&cosine, &light, &mix};
    for (int i = 0; i < 3; i++) {
        mc_rng rng = mc_rng_derive(seed, (uint64_t)i);
        mc_estimate e = pdf_integrate((pdf_fn){light_integrand, (void *)&LIGHT}, p[i], &rng, N);
        assert_z_below("mixture: light irradiance", e.value, e_light, e.std_error, Z_MAX, seed);
    }
    mc_rng rng = mc_rng_derive(seed, 3u);
    mc_estimate ec = pdf_integrate((pdf_fn){sky_integrand, &sky}, &cosine, &rng, N);
    rng = mc_rng_derive(seed, 4u);
    mc_estimate em = pdf_integrate((pdf_fn){sky_integrand, &sky}, &mix, &rng, N);
    assert_z_below("mixture: sky, cosine", ec.value, exact_sky, ec.std_error, Z_MAX, seed);
    assert_z_below("mixture: sky, mixture", em.value, exact_sky, em.std_error, Z_MAX, seed);
    assert_true(em.variance < 0.2 * ec.variance);

    rng = mc_rng_derive(seed, 5u);
    mc_welford w = mc_welford_init();
    for (int i = 0; i < N; i++) {
        const pdf *chosen = mc_rng_uniform(&rng) < 0.5 ? &cosine : &light;
        vec3 d = pdf_generate(chosen, &rng);
        mc_welford_add(&w, sky_integrand(d, &sky) / pdf_value(chosen, d));
    }
    assert_seeded(negctl_record(t, "mixture weighted by the chosen component only", "z-test",
                                z_rejects(mc_welford_estimate(&w), exact_sky)),
                  seed);
    rng = mc_rng_derive(seed, 6u);
    mc_estimate el = pdf_integrate((pdf_fn){sky_integrand, &sky}, &light, &rng, N);
    assert_seeded(
        negctl_record(t, "light pdf alone under a sky", "z-test", z_rejects(el, exact_sky)), seed);
}

/* --- the programs ------------------------------------------------------------ */

/* Runs `cmd`; checks the CSV header and that every row with a z has
 * |z| < 4; returns the number of rows (-1 if the program could not run). */
static int csv_rows_ok(const char *cmd)
{
    FILE *f = popen(cmd, "r");
    if (!f)
        return -1;
    char line[1024];
    int rows = 0;
    bool header =
        fgets(line, sizeof line, f) && strncmp(line, "method,n,estimate,stderr,exact,z", 32) == 0;
    while (header && fgets(line, sizeof line, f)) {
        char *p = line;
        for (int c = 0; c < 5 && p; c++)
            p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL;
        if (p && *p != ',' && *p != '\n' && !(fabs(strtod(p, NULL)) < Z_MAX)) {
            printf("row with |z| >= 4: %s", line);
            rows = -1000;
        }
        rows++;
    }
    return pclose(f) == 0 && header ? rows : -1;
}

/* Each program with 2 10^5 samples and a seed from mc_test_seed(7009):
 * the rows it prints, all with |z| < 4. sphere_plot: 1000 unit vectors. */
static void test_programs(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int rows;
    } progs[6] = {{"sphere_importance", 3}, {"cos_cubed", 2},      {"light_pdf", 2},
                  {"sphere_light", 2},      {"projected_area", 4}, {"mixture", 5}};
    uint64_t seed = mc_test_seed(7009u);
    char cmd[2048];
    for (int i = 0; i < 6; i++) {
        snprintf(cmd, sizeof cmd, "%s/bin/%s --csv --samples 200000 --seed %llu",
                 mc_test_build_dir(), progs[i].name, (unsigned long long)seed);
        int rows = csv_rows_ok(cmd);
        if (rows != progs[i].rows)
            printf("%s: %d rows (seed %llu)\n", cmd, rows, (unsigned long long)seed);
        assert_int_equal(rows, progs[i].rows);
    }
    snprintf(cmd, sizeof cmd, "%s/bin/sphere_plot --method gaussian --samples 1000 --seed %llu",
             mc_test_build_dir(), (unsigned long long)seed);
    FILE *f = popen(cmd, "r");
    assert_non_null(f);
    int lines = 0;
    double x, y, z;
    while (fscanf(f, "%lf %lf %lf", &x, &y, &z) == 3) {
        assert_near(x * x + y * y + z * z, 1.0, 1e-12);
        lines++;
    }
    assert_int_equal(pclose(f), 0);
    assert_int_equal(lines, 1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_importance),
        cmocka_unit_test(test_cos_cubed),
        cmocka_unit_test(test_light_polygon_formula),
        cmocka_unit_test(test_light_pdf),
        cmocka_unit_test(test_sphere_light),
        cmocka_unit_test(test_projected_area),
        cmocka_unit_test(test_mixture),
        cmocka_unit_test(test_programs),
    };
    return cmocka_run_group_tests_name("test_chapters3", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
