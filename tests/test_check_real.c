/* tests/test_check_real.c - the public check (check/check.h) on samplers a
 * renderer really has, written here from their papers
 * (tests/support/real_samplers.h): spherical triangles (Arvo 1995) and
 * rectangles (Urena et al. 2013), a cone about a tilted axis, a narrow von
 * Mises-Fisher lobe (Jakob 2012) and Beckmann normals (Walter et al. 2007).
 *
 * First each sampler's own mathematics, without the check: the solid
 * angles against Van Oosterom-Strackee and a brute-force quadrature, every
 * sample inside its support, the lobes' moments against closed forms. Then
 * through every door (C API, mcbox-check --exec with this program serving
 * the sampler, mcbox-check --samples on a file this program writes, the
 * density then served by --pdf-exec): every correct sampler passes on the
 * charts that fit it (cap, spherical polygon, lobe chart about its axis),
 * every wrong twin is rejected, a narrow lobe on the default chart either
 * gets the right verdict or a warning naming --lobe-width, and the
 * p-values of a density with jumps over 100 seeds are uniform.
 *
 * Statistics: the correct samplers' runs share alpha 0.01 (Sidak over
 * CORRECT_TESTS = 28 runs), 10^5 samples, seed 2000 + 10 x the sampler's
 * index + the chart's, the same at every door; the wrong twins run at the same
 * per-test level, with the counts given at each. The false-alarm test and
 * the moments' z-tests state their own. bench/real_samplers_table.c
 * (make real-table) prints the full table at 10^5 .. 10^6 samples.
 *
 * This program is also the samplers' server: `test_check_real serve NAME`
 * speaks the --exec protocol, `test_check_real sample NAME N SEED [f64]`
 * writes a sample file.
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, realpath */

#include "tests/support/mc_test.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mc/constants.h"
#include "mc/rng.h"
#include "mc/stats.h"
#include "tests/support/negctl.h"
#include "tests/support/real_doors.h"
#include "tests/support/real_samplers.h"

static rs_env env;

/* The correct samplers' runs the family-wise level is shared over: the
 * seven fitted charts of the six samplers (the cone has two), three doors
 * each, plus the two narrow lobes on the default chart, three doors each,
 * and the small triangle there at the C door. */
enum { FITTED_RUNS = 7 * 3, CORRECT_TESTS = FITTED_RUNS + 2 * 3 + 1 };
/* (Without MC_TEST_REAL_ALL two fewer run; the level stays that of the
 * full set, so the verdicts do not depend on the switch.) */

static uint64_t seed_of(size_t sampler, int chart)
{
    return mc_test_seed(2000u + 10u * (uint64_t)sampler + (uint64_t)chart);
}

/* The doors a run of s on chart c goes through: all three, except behind
 * a pipe (--exec, and --samples with --pdf-exec) for a density with a jump
 * on a lobe chart (the cone's rim), whose quadrature there takes 20-25 s a
 * run on two cores: that one runs with MC_TEST_REAL_ALL=1 in the
 * environment, and in make real-table. */
static int doors_for(const rs_sampler *s, rs_chart c)
{
    const char *all = getenv("MC_TEST_REAL_ALL");
    bool slow = c == RS_CHART_LOBE && s->shape->kind == RS_CONE;
    return (all && strcmp(all, "1") == 0) || !slow ? RS_DOORS : 1;
}

/* The position of chart c among s's charts. */
static int chart_index(const rs_sampler *s, rs_chart c)
{
    int k = 0;
    while (k < s->n_charts && s->charts[k] != c)
        k++;
    return k;
}

static size_t index_of(const rs_sampler *s)
{
    size_t i = 0;
    while (rs_at(i) != s)
        i++;
    return i;
}

static void print_outcome(const rs_sampler *s, rs_chart c, rs_door d, uint64_t n,
                          const rs_outcome *r)
{
    printf("  %-22s %-10s %-9s n %-7llu %-12s chi2 %9.2f dof %4d p %.3g integral %.7f "
           "(+- %.2g) power %.3g %.1f s\n",
           s->name, rs_chart_name(c), rs_door_name(d), (unsigned long long)n,
           rs_verdict_name(r->verdict), r->statistic, r->dof, r->pvalue, r->pdf_integral,
           r->pdf_integral_error, r->power_rel_error, r->seconds);
    if (r->message[0])
        printf("      %s\n", r->message);
    if (r->warning[0])
        printf("      warning: %s\n", r->warning);
}

/* --- the samplers' own mathematics ---------------------------------------- */

/* The indicator of the shape integrated by the midpoint rule on a grid of
 * nz x 2 nz cells in (z, phi), whose measure is dz dphi: the error is the
 * boundary's cells, about the perimeter over the cell size times half a
 * cell's area. */
static double brute_solid_angle(const rs_shape *sh, int nz)
{
    int nphi = 2 * nz;
    double dz = 2.0 / nz, dphi = MC_2PI / nphi, sum = 0.0;
    for (int i = 0; i < nz; i++) {
        double z = -1.0 + (i + 0.5) * dz, r = sqrt(1.0 - z * z);
        for (int j = 0; j < nphi; j++) {
            double phi = (j + 0.5) * dphi;
            sum += rs_shape_contains(sh, vec3_make(r * cos(phi), r * sin(phi), z));
        }
    }
    return sum * dz * dphi;
}

static void test_real_solid_angles(void **state)
{
    (void)state;
    for (size_t i = 0; i < rs_count(); i++) {
        const rs_sampler *s = rs_at(i);
        const rs_shape *sh = s->shape;
        if (s->wrong || (sh->kind != RS_TRIANGLE && sh->kind != RS_RECT && sh->kind != RS_CONE))
            continue;
        double omega = rs_shape_solid_angle(sh), brute = brute_solid_angle(sh, 1500);
        /* Van Oosterom-Strackee: the triangle's, or the rectangle as two
         * triangles (corner, corner + u, corner + u + v) and (corner,
         * corner + u + v, corner + v). */
        double vos = (double)NAN;
        if (sh->kind == RS_TRIANGLE) {
            vos = rs_triangle_solid_angle(vec3_normalize(sh->v[0]), vec3_normalize(sh->v[1]),
                                          vec3_normalize(sh->v[2]));
        } else if (sh->kind == RS_RECT) {
            vec3 a = sh->v[0], b = vec3_add(a, sh->v[1]), c = vec3_add(b, sh->v[2]),
                 d = vec3_add(a, sh->v[2]);
            vos = rs_triangle_solid_angle(vec3_normalize(a), vec3_normalize(b), vec3_normalize(c)) +
                  rs_triangle_solid_angle(vec3_normalize(a), vec3_normalize(c), vec3_normalize(d));
        }
        /* The grid's cells are 1/750 wide in z and 2 pi / 3000 in phi; a
         * boundary of length L crosses about L * 1000 of them, each off by
         * at most its area 2.8e-6: 3e-3 L at most, 3e-4 L in practice
         * (the errors of the crossed cells cancel in the mean). */
        printf("  %-15s solid angle %.12f, Van Oosterom-Strackee %.12f, brute force %.6f\n",
               s->name, omega, vos, brute);
        if (!isnan(vos))
            assert_near(omega, vos, 1e-12);
        assert_near(brute, omega, 2e-3 * fmax(omega, 0.01) + 1e-4);
    }
}

/* The first uniform of both polygon samplers is area-preserving: with
 * u2 = 1 the sample lies on the far edge of the part it chose, Arvo's
 * sub-triangle A B C_hat or Urena's sub-rectangle [x0, xu] x [y0, y1],
 * whose solid angle (Van Oosterom-Strackee) is u1 times the whole. */
static void test_real_area_preserving(void **state)
{
    (void)state;
    const double us[] = {0.0731, 0.385, 0.5, 0.9127};
    const rs_sampler *tri = rs_find("triangle"), *rect = rs_find("rectangle");
    const rs_shape *ts = tri->shape, *rs = rect->shape;
    for (size_t k = 0; k < sizeof us / sizeof us[0]; k++) {
        double u[2] = {us[k], 1.0};
        mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
        tri->sample(u, &o, (void *)tri);
        vec3 c_hat = vec3_make(o.x[0], o.x[1], o.x[2]);
        double part = rs_triangle_solid_angle(vec3_normalize(ts->v[0]), vec3_normalize(ts->v[1]),
                                              c_hat);
        printf("  triangle   u1 = %.4f: sub-triangle %.12f, u1 x area %.12f\n", us[k], part,
               us[k] * rs_shape_solid_angle(ts));
        assert_near(part, us[k] * rs_shape_solid_angle(ts), 1e-12);
        /* The rectangle: where the ray meets the plane, the fraction a of
         * the edge u it reached. */
        rect->sample(u, &o, (void *)rect);
        vec3 w = vec3_make(o.x[0], o.x[1], o.x[2]), n = vec3_cross(rs->v[1], rs->v[2]);
        vec3 p = vec3_sub(vec3_scale(w, vec3_dot(rs->v[0], n) / vec3_dot(w, n)), rs->v[0]);
        double a = vec3_dot(p, rs->v[1]) / vec3_length_sq(rs->v[1]);
        vec3 c0 = rs->v[0], c1 = vec3_madd(c0, rs->v[1], a), c2 = vec3_add(c1, rs->v[2]),
             c3 = vec3_add(c0, rs->v[2]);
        part = rs_triangle_solid_angle(vec3_normalize(c0), vec3_normalize(c1), vec3_normalize(c2)) +
               rs_triangle_solid_angle(vec3_normalize(c0), vec3_normalize(c2), vec3_normalize(c3));
        printf("  rectangle  u1 = %.4f: sub-rectangle %.12f, u1 x area %.12f\n", us[k], part,
               us[k] * rs_shape_solid_angle(rs));
        assert_near(part, us[k] * rs_shape_solid_angle(rs), 1e-9);
    }
}

/* A direction inside the shape, away from its edges. */
static vec3 centre(const rs_shape *sh)
{
    switch (sh->kind) {
    case RS_TRIANGLE:
        return vec3_normalize(vec3_add(vec3_add(vec3_normalize(sh->v[0]), vec3_normalize(sh->v[1])),
                                       vec3_normalize(sh->v[2])));
    case RS_RECT:
        return vec3_normalize(vec3_add(sh->v[0], vec3_scale(vec3_add(sh->v[1], sh->v[2]), 0.5)));
    default: return vec3_normalize(sh->axis);
    }
}

/* 10^4 samples of each sampler (seed 31): unit length, inside the
 * support (or within 1e-9 of its edge, where rounding may put them), and
 * the reported pdf equal to the density function's. */
static void test_real_samples_in_support(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(31), 0u);
    for (size_t i = 0; i < rs_count(); i++) {
        const rs_sampler *s = rs_at(i);
        int outside = 0, off_unit = 0;
        for (int k = 0; k < 10000; k++) {
            double u[2];
            u[0] = mc_rng_uniform(&rng); /* in order: an initializer list's order is unspecified */
            u[1] = mc_rng_uniform(&rng);
            mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
            s->sample(u, &o, (void *)s);
            vec3 w = vec3_make(o.x[0], o.x[1], o.x[2]);
            off_unit += !(fabs(vec3_length(w) - 1.0) < 1e-12);
            /* Rounding may put a point on an edge a few ulps outside: it
             * counts as inside when moving it 1e-9 toward the shape's
             * centre brings it in. */
            bool in = rs_shape_contains(s->shape, w);
            if (!in) {
                vec3 moved = vec3_normalize(vec3_madd(w, centre(s->shape), 1e-9));
                in = rs_shape_contains(s->shape, moved);
            }
            outside += !in;
            assert_true(o.pdf == s->pdf(o.x, (void *)s));
        }
        printf("  %-22s 10^4 samples: %d off the unit sphere, %d outside the support\n", s->name,
               off_unit, outside);
        assert_int_equal(off_unit, 0);
        assert_int_equal(outside, 0);
    }
}

/* The lobes' moments against closed forms, 10^5 samples each (seed 32),
 * z-tests at |z| < 4 (two-sided false alarm 6.3e-5 each):
 * cone: E[cos] = (1 + cos_max) / 2; vMF: E[cos] = coth(kappa) - 1 / kappa;
 * Beckmann: tan^2 theta is exponential with mean alpha^2. A wrong twin
 * drawing with another width must fail the same z-test. */
static void test_real_lobe_moments(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(32);
    const char *names[] = {"cone", "vmf", "beckmann", "vmf-900-as-1000", "cone-theta-uniform"};
    for (int q = 0; q < 5; q++) {
        const rs_sampler *s = rs_find(names[q]);
        const rs_shape *sh = s->shape;
        mc_rng rng = mc_rng_derive(seed, (uint64_t)q);
        mc_welford w = mc_welford_init();
        vec3 axis = vec3_normalize(sh->axis);
        for (int k = 0; k < 100000; k++) {
            double u[2];
            u[0] = mc_rng_uniform(&rng);
            u[1] = mc_rng_uniform(&rng);
            mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
            s->sample(u, &o, (void *)s);
            vec3 x = vec3_make(o.x[0], o.x[1], o.x[2]);
            if (sh->kind == RS_BECKMANN)
                mc_welford_add(&w, (x.x * x.x + x.y * x.y) / (x.z * x.z));
            else /* 1 - cos, which keeps its digits near the axis */
                mc_welford_add(&w, 0.5 * vec3_length_sq(vec3_sub(x, axis)));
        }
        double exact = sh->kind == RS_CONE  ? (1.0 - sh->cos_max) / 2.0
                       : sh->kind == RS_VMF ? 1.0 - (1.0 / tanh(sh->kappa) - 1.0 / sh->kappa)
                                            : sh->alpha * sh->alpha;
        mc_estimate e = mc_welford_estimate(&w);
        double z = (e.value - exact) / e.std_error;
        if (s->wrong) {
            printf("  %-20s E = %.6g, exact for the claimed law %.6g, z = %.1f\n", s->name, e.value,
                   exact, z);
            assert_seeded(negctl_record(t, s->name, "moment z-test", fabs(z) >= 4.0), seed);
        } else {
            assert_z_below(s->name, e.value, exact, e.std_error, 4.0, seed);
        }
    }
}

/* The server answers as the C callbacks do, to the bit: hello, a sample
 * batch (point and pdf) and a pdf batch, read back from a pipe. */
static void test_real_serve_protocol(void **state)
{
    (void)state;
    char cmd[4096], path[512];
    snprintf(path, sizeof path, "%s/proto.txt", env.tmp);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "hello 1 sphere 3 2 7\nsample 2\n0.25 0.75\n0.5, 0.125\npdf 2\n"
               "0.4 0.38 0.9\n0 0 -2\n");
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' serve triangle <%s", env.self, path);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    char line[512];
    assert_non_null(fgets(line, sizeof line, p));
    assert_string_equal(line, "ok\n");
    const rs_sampler *s = rs_find("triangle");
    const double u[2][2] = {{0.25, 0.75}, {0.5, 0.125}};
    for (int k = 0; k < 2; k++) {
        mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
        s->sample(u[k], &o, (void *)s);
        double v[4];
        assert_non_null(fgets(line, sizeof line, p));
        assert_int_equal(sscanf(line, "%lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]), 4);
        for (int j = 0; j < 3; j++)
            assert_true(v[j] == o.x[j]);
        assert_true(v[3] == o.pdf);
    }
    /* Normalized as the server does, operation for operation. */
    double x[3] = {0.4, 0.38, 0.9}, got;
    double l = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (int j = 0; j < 3; j++)
        x[j] /= l;
    assert_non_null(fgets(line, sizeof line, p));
    assert_int_equal(sscanf(line, "%lf", &got), 1);
    assert_true(got == s->pdf(x, (void *)s) && got > 0.0); /* near the centroid */
    assert_non_null(fgets(line, sizeof line, p));
    assert_true(strtod(line, NULL) == 0.0);
    assert_int_equal(pclose(p), 0);
    /* A command it does not serve: "error ..." and exit status 2. */
    snprintf(cmd, sizeof cmd, "printf 'hello 1 sphere 3 2 7\\ninvert 1\\n0 0 1\\n' | '%s' serve cone "
             ">%s/inv.txt 2>/dev/null", env.self, env.tmp);
    int rc = system(cmd);
    assert_int_equal(WEXITSTATUS(rc), 2);
}

/* --- the doors -------------------------------------------------------------- */

/* The charts that fit a support (spherical polygon, cap, lobe chart about
 * the lobe's axis), as opposed to the sphere's and hemisphere's default
 * chart, which the table program and the false-alarm test cover. */
static bool fitted(rs_chart c)
{
    return c == RS_CHART_POLYGON || c == RS_CHART_CAP || c == RS_CHART_LOBE;
}

/* Every correct sampler passes on every fitted chart through every door
 * (the cone's lobe chart behind a pipe with MC_TEST_REAL_ALL=1) at 10^5
 * samples; --exec and --samples see the same points and the same
 * density program, so they give the same statistic. */
static void test_real_correct_every_door(void **state)
{
    (void)state;
    int failures = 0;
    for (size_t i = 0; i < rs_count(); i++) {
        const rs_sampler *s = rs_at(i);
        for (int ci = 0; ci < s->n_charts && !s->wrong; ci++) {
            rs_chart c = s->charts[ci];
            if (!fitted(c))
                continue;
            double stat[RS_DOORS] = {0.0, 0.0, 0.0};
            for (int d = 0; d < doors_for(s, c); d++) {
                rs_outcome r;
                rs_door_run(&env, s, c, (rs_door)d, 100000, seed_of(i, ci), CORRECT_TESTS, &r);
                print_outcome(s, c, (rs_door)d, 100000, &r);
                stat[d] = r.statistic;
                if (r.verdict != RS_PASS) {
                    failures++;
                    print_error("%s on the %s chart through %s: %s (seed %llu)\n", s->name,
                                rs_chart_name(c), rs_door_name((rs_door)d),
                                rs_verdict_name(r.verdict), (unsigned long long)seed_of(i, ci));
                }
            }
            if (!(fabs(stat[RS_DOOR_EXEC] - stat[RS_DOOR_SAMPLES]) <= 1e-9 * stat[RS_DOOR_EXEC])) {
                failures++;
                print_error("%s on the %s chart: --exec chi-square %.17g, --samples %.17g\n",
                            s->name, rs_chart_name(c), stat[RS_DOOR_EXEC], stat[RS_DOOR_SAMPLES]);
            }
        }
    }
    assert_int_equal(failures, 0);
}

/* A wrong twin is caught when the verdict is fail (never undetermined:
 * that would be a judge that could not decide on a plain error). */
static bool caught_everywhere(negctl *t, const rs_sampler *s, rs_chart c, uint64_t n)
{
    bool all = true;
    for (int d = 0; d < doors_for(s, c); d++) {
        rs_outcome r;
        uint64_t seed = seed_of(index_of(s), chart_index(s, c));
        rs_door_run(&env, s, c, (rs_door)d, n, seed, CORRECT_TESTS, &r);
        print_outcome(s, c, (rs_door)d, n, &r);
        char name[128], check[96];
        snprintf(name, sizeof name, "%s (%s) on the %s chart", s->name, s->wrong, rs_chart_name(c));
        snprintf(check, sizeof check, "%s at %llu samples", rs_door_name((rs_door)d),
                 (unsigned long long)n);
        all &= negctl_record(t, name, check, r.verdict == RS_FAIL);
    }
    return all;
}

/* Every wrong twin is rejected on its natural chart through every door.
 * The densities 0.5% too high fail the normalization at any count (here
 * 10^5); the slips and the lobes of the wrong width fail the chi-square
 * test, here at 10^5 samples (bench/real_samplers_table.c measures 10^5 ..
 * 10^6 on every chart). */
static void test_real_wrong_caught(void **state)
{
    negctl *t = *state;
    static const struct {
        const char *name;
        uint64_t n;
    } cases[] = {
        {"triangle-pdf-high", 100000},      {"cone-pdf-high", 100000},
        {"triangle-arc-slip", 100000},      {"cone-theta-uniform", 100000},
        {"vmf-900-as-1000", 100000},        {"beckmann-0.05-as-0.045", 100000},
    };
    bool all = true;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const rs_sampler *s = rs_find(cases[k].name);
        all &= caught_everywhere(t, s, s->charts[0], cases[k].n);
    }
    assert_true(all);
}

/* The narrow lobes (and the small triangle) on the default chart, where
 * all their samples land in a few cells: each run either gives the right
 * verdict (a correct sampler passes, a wrong one fails) or carries a
 * warning naming --lobe-width; a wrong sampler never passes. 10^5 samples,
 * every door; the small triangle at the C door only (its edges cut the
 * default chart's cells, and the rules behind a pipe take half a minute
 * there: bench/real_samplers_table.c runs it). */
static void test_real_narrow_lobes_default_chart(void **state)
{
    negctl *t = *state;
    const char *names[] = {"vmf", "beckmann", "triangle-small", "vmf-900-as-1000",
                           "beckmann-0.05-as-0.045"};
    int failures = 0;
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        const rs_sampler *s = rs_find(names[k]);
        rs_chart c = s->charts[1];
        int doors = s->shape->kind == RS_TRIANGLE ? 1 : RS_DOORS;
        for (int d = 0; d < doors; d++) {
            rs_outcome r;
            rs_door_run(&env, s, c, (rs_door)d, 100000, seed_of(index_of(s), 1), CORRECT_TESTS,
                        &r);
            print_outcome(s, c, (rs_door)d, 100000, &r);
            bool warned = strstr(r.warning, "--lobe-width") != NULL;
            bool right = s->wrong ? r.verdict == RS_FAIL : r.verdict == RS_PASS;
            if (s->wrong) {
                char check[96];
                snprintf(check, sizeof check, "%s on the default chart (fail, or warned, no pass)",
                         rs_door_name((rs_door)d));
                negctl_record(t, s->name, check, right || (warned && r.verdict != RS_PASS));
            }
            if (!(right || warned) || (s->wrong && r.verdict == RS_PASS)) {
                failures++;
                print_error("%s on the %s chart through %s: %s without a warning naming "
                            "--lobe-width\n",
                            s->name, rs_chart_name(c), rs_door_name((rs_door)d),
                            rs_verdict_name(r.verdict));
            }
        }
    }
    assert_int_equal(failures, 0);
}

/* The false-alarm rate of a density with jumps: the cone about a tilted
 * axis on the whole sphere's default chart, whose rim cuts its cells
 * (where a quadrature that misjudged the jump would bias the expected
 * counts); C door, 10^5 samples, SEEDS seeds (4000 + k, or derived from
 * $MC_TEST_SEED), the expected counts computed once (rs_sphere_pvalues; the
 * first seed's statistic must be mcbox_check_run's to the bit). Under a
 * correct judge the p-values are uniform: the Kolmogorov-Smirnov test
 * against the uniform law must not reject at 0.001, and the count of
 * p-values below 0.05 must not reach what a binomial(SEEDS, 0.05) reaches
 * with probability below 0.001. Each has a false alarm of at most 0.001. */
static void test_real_false_alarm_rate(void **state)
{
    (void)state;
    enum { SEEDS = 100 };
    const rs_sampler *s = rs_find("cone");
    double p[SEEDS];
    int mismatches = 0, rej = 0;
    uint64_t seed = mc_test_seed(4000);
    assert_int_equal(rs_sphere_pvalues(s, 100000, seed, SEEDS, 1, p, &mismatches), 0);
    assert_int_equal(mismatches, 0);
    for (int k = 0; k < SEEDS; k++)
        rej += p[k] < 0.05;
    double d, ks = rs_ks_uniform(p, SEEDS, &d);
    double tail = rs_binomial_tail(SEEDS, 0.05, rej);
    printf("  cone on the sphere, %d seeds of 10^5: %d p-values below 0.05 (P(>= %d) = %.3g), "
           "KS D = %.4f, p = %.3g; deciles",
           SEEDS, rej, rej, tail, d, ks);
    for (int q = 1; q < 10; q++)
        printf(" %.2f", p[q * SEEDS / 10]);
    printf("\n");
    assert_seeded(ks >= 0.001, seed);
    assert_seeded(tail >= 0.001, seed);
}

static int setup(void **state)
{
    char real[PATH_MAX];
    const char *build = mc_test_build_dir();
    snprintf(env.check, sizeof env.check, "%s/bin/mcbox-check", build);
    if (!realpath(env.check, real))
        return -1;
    if (strlen(real) >= sizeof env.check)
        return -1;
    memcpy(env.check, real, strlen(real) + 1);
    if (!realpath("/proc/self/exe", real))
        return -1;
    if (strlen(real) >= sizeof env.self)
        return -1;
    memcpy(env.self, real, strlen(real) + 1);
    snprintf(env.tmp, sizeof env.tmp, "/tmp/mcbox-check-real-XXXXXX");
    if (!mkdtemp(env.tmp))
        return -1;
    return negctl_group_setup(state);
}

static int teardown(void **state)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf %s", env.tmp);
    (void)!system(cmd);
    return negctl_group_teardown(state);
}

int main(int argc, char **argv)
{
    int rc = rs_main(argc, argv);
    if (rc >= 0)
        return rc;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_real_solid_angles),
        cmocka_unit_test(test_real_area_preserving),
        cmocka_unit_test(test_real_samples_in_support),
        cmocka_unit_test(test_real_lobe_moments),
        cmocka_unit_test(test_real_serve_protocol),
        cmocka_unit_test(test_real_correct_every_door),
        cmocka_unit_test(test_real_wrong_caught),
        cmocka_unit_test(test_real_narrow_lobes_default_chart),
        cmocka_unit_test(test_real_false_alarm_rate),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_check_real", tests, setup, teardown);
}
