/* tests/support/warp_check.c - chi-square, normalization, domain, round
 * trip and agreement checks of a warp_case. */
#include "tests/support/warp_check.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/gof.h"
#include "mc/onb.h"
#include "mc/quad.h"
#include "samplers/spherical.h"
#include "tests/support/mc_test.h"

/* --- a case's functions: the catalog row's, or its own ----------------- */

static vec3 get3(const double x[3])
{
    return vec3_make(x[0], x[1], x[2]);
}

warp_case warp_case_of(const cat_row *r, const cat_case *tc, cat_state *s)
{
    char err[256];
    if (!cat_prepare_case(r, tc, s, err, sizeof err))
        fail_msg("%s: %s", tc->name, err);
    warp_case c;
    memset(&c, 0, sizeof c);
    c.name = tc->name;
    c.cat = s;
    c.cells[0] = tc->cells[0], c.cells[1] = tc->cells[1];
    c.direction = r->point == CAT_DIRECTION;
    return c;
}

/* Whether the case maps two uniforms (the edge grid and the round trip
 * need them). */
static bool two_uniforms(const warp_case *c)
{
    return c->cat ? c->cat->row->uniforms == 2 : c->sample != NULL;
}

/* Whether the round trip applies: an inverse of two uniforms. */
static bool has_invert(const warp_case *c)
{
    return two_uniforms(c) && (c->cat ? c->cat->row->invert != NULL : c->invert != NULL);
}

static vec3 sample_u(const warp_case *c, double u1, double u2)
{
    if (!c->cat)
        return c->sample(u1, u2, c);
    double u[2] = {u1, u2}, x[3] = {0.0, 0.0, 0.0};
    c->cat->row->sample_u(c->cat, u, x);
    return get3(x);
}

static vec2 invert(const warp_case *c, vec3 x)
{
    if (!c->cat)
        return c->invert(x, c);
    double y[3] = {x.x, x.y, x.z}, u[2];
    c->cat->row->invert(c->cat, y, u);
    return vec2_make(u[0], u[1]);
}

static double density(const warp_case *c, vec3 x)
{
    double y[3] = {x.x, x.y, x.z};
    return c->cat ? cat_pdf(c->cat, y) : c->pdf(x, c);
}

static vec3 draw(const warp_case *c, mc_rng *rng)
{
    if (c->cat) {
        double x[3];
        cat_sample(c->cat, rng, x);
        return get3(x);
    }
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return c->sample(u1, u2, c);
}

static void to_param(const warp_case *c, vec3 x, double out[2])
{
    double y[3] = {x.x, x.y, x.z};
    if (c->cat)
        cat_chart_point(c->cat, y, out);
    else
        c->to_param(x, c, out);
}

static double param_pdf(const double p[2], void *ctx)
{
    const warp_case *c = ctx;
    return c->cat ? cat_chart_density(c->cat, p) : c->param_pdf(p, c);
}

static void chi2_sample(mc_rng *rng, void *ctx, double out[2])
{
    const warp_case *c = ctx;
    to_param(c, draw(c, rng), out);
}

/* The case's chart as mc/gof.h sees it, at the case's resolution. */
static mc_gof_spec gof_spec(const warp_case *c)
{
    mc_gof_spec g;
    if (c->cat) {
        g = cat_gof_spec(c->cat, c->cells);
    } else {
        g = (mc_gof_spec){2, {c->lo[0], c->lo[1]}, {c->hi[0], c->hi[1]}, {50, 100}, NULL, NULL,
                          NULL};
        if (c->cells[0] > 0)
            g.cells[0] = c->cells[0], g.cells[1] = c->cells[1];
    }
    g.sample = chi2_sample;
    g.pdf = param_pdf;
    g.ctx = (void *)c; /* read only, as mc_gof_spec documents */
    return g;
}

chi2_spec warp_chi2_spec(const warp_case *c)
{
    chi2_spec s = {c->name, gof_spec(c)};
    return s;
}

chi2_outcome warp_chi2(const warp_case *c, uint64_t n, uint64_t seed)
{
    chi2_spec s = warp_chi2_spec(c);
    return chi2_run(&s, n, seed, chi2_suite_alpha());
}

static double value_at(vec3 d, void *ctx)
{
    return density(ctx, d);
}

/* The density over the directions about frame.n with cos theta in
 * [-1, cos_hi], except inside the two cones (axis, cosine) given. */
typedef struct rest {
    const warp_case *c;
    onb frame;
    vec3 skip_axis[2];
    double skip_cos[2];
} rest;

static double rest_integrand(double cos_theta, double phi, void *params)
{
    const rest *r = params;
    vec3 d = onb_to_world(&r->frame, smp_spherical_direction(cos_theta, phi));
    for (int k = 0; k < 2; k++)
        if (vec3_dot(d, r->skip_axis[k]) >= r->skip_cos[k])
            return 0.0;
    return density(r->c, d);
}

/* What a direction chart leaves out: below a (cos theta, phi) chart's
 * rim; around a quad-and-cap chart's light and sphere, cones 0.01 wider
 * than the light's widest corner and than the sphere's rim, so that the
 * mask never cuts the support. */
static double rest_of_sphere(const warp_case *c, mc_quad *q)
{
    const pdf_chart *ch = &c->cat->dir_chart;
    double v = 0.0;
    if (ch->kind == PDF_CHART_SPHERICAL && ch->cos_lo > -1.0) {
        rest r = {c, ch->frame, {ch->frame.n, ch->frame.n}, {2.0, 2.0}};
        (void)mc_quad_2d(q, (mc_fn2){rest_integrand, &r}, -1.0, ch->cos_lo, 0.0, MC_2PI, &v, NULL);
    } else if (ch->kind == PDF_CHART_QUAD_AND_CAP) {
        vec3 mid = vec3_madd(vec3_madd(ch->corner, ch->u, 0.5), ch->v, 0.5);
        rest r = {c,
                  ch->frame,
                  {ch->frame.n, vec3_normalize(vec3_sub(mid, ch->origin))},
                  {ch->cos_lo - 0.01, 1.0}};
        for (int k = 0; k < 4; k++) {
            vec3 x =
                vec3_madd(vec3_madd(ch->corner, ch->u, (double)(k & 1)), ch->v, (double)(k >> 1));
            double cs = vec3_dot(vec3_normalize(vec3_sub(x, ch->origin)), r.skip_axis[1]);
            r.skip_cos[1] = fmin(r.skip_cos[1], cs - 0.01);
        }
        (void)mc_quad_2d(q, (mc_fn2){rest_integrand, &r}, -1.0, 1.0, 0.0, MC_2PI, &v, NULL);
    }
    return v;
}

double warp_norm_error(const warp_case *c)
{
    chi2_spec s = warp_chi2_spec(c);
    if (!c->cat || c->cat->chart != CAT_CHART_DIRECTION)
        return chi2_integrate_pdf(&s) - 1.0;
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    const pdf_chart *ch = &c->cat->dir_chart;
    double total = ch->kind == PDF_CHART_SPHERICAL
                       ? chi2_integrate_pdf(&s)
                       : pdf_chart_integrate(ch, value_at, (void *)c, q);
    total += rest_of_sphere(c, q);
    mc_quad_destroy(q);
    return total - 1.0;
}

bool warp_norm_rejects(const warp_case *c)
{
    double e = warp_norm_error(c);
    printf("  %s: normalization error %+.4g\n", c->name, e);
    return !(fabs(e) <= WARP_NORM_TOL);
}

bool warp_chi2_rejects(const warp_case *c, uint64_t n, uint64_t seed)
{
    chi2_outcome o = warp_chi2(c, n, seed);
    chi2_spec s = warp_chi2_spec(c);
    chi2_print(&s, &o);
    return o.reject;
}

/* --- domain ------------------------------------------------------------- */

/* Support slack: 4 ulps of 1, as in samplers/planar.c. */
#define SLACK (4.0 * DBL_EPSILON)

/* The support of a catalog row without its own: its chart's domain (a
 * (cos theta, phi) chart: cos theta about its axis from the chart's lower
 * end; the other direction charts: wherever the density is positive, which
 * the density check sees), the interval of a line, the outcomes of an
 * index. */
static bool in_support(const warp_case *c, vec3 x)
{
    if (!c->cat)
        return c->in_support ? c->in_support(x, c) : true;
    const cat_state *s = c->cat;
    double y[3] = {x.x, x.y, x.z};
    if (s->row->in_support)
        return s->row->in_support(s, y);
    switch (s->row->chart) {
    case CAT_CHART_DIRECTION:
    case CAT_CHART_LOBE:
        return s->dir_chart.kind != PDF_CHART_SPHERICAL ||
               vec3_dot(x, s->dir_chart.frame.n) >= s->dir_chart.cos_lo - SLACK;
    case CAT_CHART_LINE: return x.x >= s->row->lo && x.x <= s->row->hi;
    case CAT_CHART_INDEX: return x.x >= 0.0 && x.x == floor(x.x) && x.x < (double)s->p.n_weights;
    case CAT_CHART_DISC: return x.x * x.x + x.y * x.y <= 1.0 + SLACK && x.z == 0.0;
    case CAT_CHART_XY: return x.x >= 0.0 && x.x <= 1.0 && x.y >= 0.0 && x.y <= 1.0 && x.z == 0.0;
    default: return true;
    }
}

static bool rim_zero_ok(const warp_case *c)
{
    return c->cat && c->cat->row->rim_zero;
}

/* BEGIN SNIPPET warp_domain_one */
static void check_one(const warp_case *c, vec3 x, warp_domain *d)
{
    bool bad = false;
    d->n++;
    if (!vec3_is_finite(x)) {
        d->not_finite++;
        bad = true;
    } else {
        /* 1e-12, about 4500 ulps: a unit length lost to a missing
         * renormalization is far larger, round-off far smaller. */
        if (c->direction && !(fabs(vec3_length(x) - 1.0) <= 1e-12)) {
            d->not_unit++;
            bad = true;
        }
        if (!in_support(c, x)) {
            d->outside++;
            bad = true;
        }
        double p = density(c, x);
        bool pole = c->cat && c->cat->row->pole_infinite && x.x == 0.0 && x.y == 0.0;
        if ((!(p > 0.0) && !(rim_zero_ok(c) && x.z == 0.0)) || (isinf(p) && !pole)) {
            d->zero_pdf++;
            bad = true;
        }
    }
    if (bad && d->not_finite + d->not_unit + d->outside + d->zero_pdf == 1)
        d->example = x;
}
/* END SNIPPET warp_domain_one */

warp_domain warp_check_domain(const warp_case *c, uint64_t n, uint64_t seed)
{
    warp_domain d;
    memset(&d, 0, sizeof d);
    mc_rng rng = mc_rng_derive(seed, 1u);
    for (uint64_t k = 0; k < n; k++)
        check_one(c, draw(c, &rng), &d);
    if (two_uniforms(c)) {
        /* The extreme uniforms mc_rng_uniform can return, and their
         * neighbours: where a warp meets a pole, a rim or a corner. */
        static const double edge[] = {0.0, 0x1p-32,       0x1p-31, 0.25,          0.5 - 0x1p-32,
                                      0.5, 0.5 + 0x1p-32, 0.75,    1.0 - 0x1p-31, 1.0 - 0x1p-32};
        size_t m = sizeof edge / sizeof edge[0];
        for (size_t i = 0; i < m; i++)
            for (size_t j = 0; j < m; j++)
                check_one(c, sample_u(c, edge[i], edge[j]), &d);
    }
    return d;
}

bool warp_domain_ok(const warp_domain *d)
{
    return d->n > 0 && d->not_finite == 0 && d->not_unit == 0 && d->outside == 0 &&
           d->zero_pdf == 0;
}

/* --- round trip --------------------------------------------------------- */

/* BEGIN SNIPPET warp_roundtrip */
static double rt_one(const warp_case *c, double u1, double u2)
{
    vec3 x = sample_u(c, u1, u2);
    vec2 v = invert(c, x);
    double e2 = fabs(v.y - u2);
    /* On the polar axis (or the disc centre) the azimuth, hence u1, is not
     * recoverable: only u2 is compared there. */
    if (x.x == 0.0 && x.y == 0.0)
        return e2;
    return fmax(fabs(v.x - u1), e2);
}

double warp_roundtrip_error(const warp_case *c, int g)
{
    double worst = 0.0;
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++)
            worst = fmax(worst, rt_one(c, (i + 0.5) / g, (j + 0.5) / g));
    static const double near_edge[] = {1e-6, 0.5, 1.0 - 1e-6};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            worst = fmax(worst, rt_one(c, near_edge[i], near_edge[j]));
    return worst;
}
/* END SNIPPET warp_roundtrip */

/* --- agreement ---------------------------------------------------------- */

enum { AGREE_NX = 20, AGREE_NY = 40 };

/* Samples of one case mapped into another's parameterization. */
typedef struct framed {
    const warp_case *c, *frame;
} framed;

static void framed_sample(mc_rng *rng, void *ctx, double out[2])
{
    const framed *f = ctx;
    to_param(f->frame, draw(f->c, rng), out);
}

/* n samples of c histogrammed on a coarse grid of frame's rectangle into
 * h[0 .. AGREE_NX * AGREE_NY), the samples outside it into h[AGREE_NX *
 * AGREE_NY]: one more cell of the comparison (the domain check, not this
 * one, judges the support). */
static void histogram(const warp_case *c, const warp_case *frame, uint64_t n, mc_rng *rng,
                      double *h)
{
    framed f = {c, frame};
    mc_gof_spec s = gof_spec(frame);
    s.cells[0] = AGREE_NX, s.cells[1] = AGREE_NY;
    s.sample = framed_sample, s.pdf = NULL, s.ctx = &f;
    h[AGREE_NX * AGREE_NY] = mc_gof_histogram(&s, rng, n, h);
}

warp_agreement warp_compare(const warp_case *a, const warp_case *b, uint64_t n, uint64_t seed)
{
    static const int cells = AGREE_NX * AGREE_NY + 1;
    double *ha = calloc((size_t)cells, sizeof *ha), *hb = calloc((size_t)cells, sizeof *hb);
    warp_agreement r = {0.0, 0, 0.0};
    if (!ha || !hb) {
        free(ha);
        free(hb);
        return r;
    }
    mc_rng ra = mc_rng_derive(seed, 2u), rb = mc_rng_derive(seed, 3u);
    histogram(a, a, n, &ra, ha);
    histogram(b, a, n, &rb, hb);
    /* With equal sample sizes, sum (A - B)^2 / (A + B) over K cells is
     * chi-square with K - 1 dof under the hypothesis of one common law.
     * Sparse cells (A + B < 10) are pooled so the approximation holds. */
    double pa = 0.0, pb = 0.0;
    int k = 0;
    for (int c = 0; c < cells; c++) {
        double s = ha[c] + hb[c];
        if (s < 10.0) {
            pa += ha[c];
            pb += hb[c];
        } else {
            r.stat += (ha[c] - hb[c]) * (ha[c] - hb[c]) / s;
            k++;
        }
    }
    if (pa + pb > 0.0) {
        r.stat += (pa - pb) * (pa - pb) / (pa + pb);
        k++;
    }
    r.dof = k - 1;
    r.pvalue = r.dof > 0 ? mc_chi2_pvalue(r.stat, r.dof) : 1.0;
    free(ha);
    free(hb);
    return r;
}

/* The seed of case i of a table: hashed, so that neighbouring cases and
 * neighbouring base seeds share no streams. */
uint64_t warp_case_seed(uint64_t seed, int seq)
{
    mc_rng r = mc_rng_derive(seed, (uint64_t)seq + 100u);
    return (uint64_t)mc_rng_u32(&r) << 32 | mc_rng_u32(&r);
}

/* Runs check k of c; true when it passes. Writes what went wrong to msg. */
static bool run_check(const warp_case *c, warp_check_kind k, uint64_t n, uint64_t seed,
                      char *msg, size_t size)
{
    switch (k) {
    case WARP_CHECK_CHI2: {
        chi2_outcome o = warp_chi2(c, n, seed);
        printf("sampler %-26s chi2 %10.2f dof %5d p %.4f %s\n", c->name, o.r.stat, o.r.dof,
               o.r.pvalue, o.reject ? "REJECT" : "ok");
        if (o.reject) {
            chi2_spec s = warp_chi2_spec(c);
            chi2_print(&s, &o);
        }
        snprintf(msg, size, "%s: chi-square rejects (seed %llu)", c->name,
                 (unsigned long long)seed);
        return !o.reject;
    }
    case WARP_CHECK_NORM: {
        double e = warp_norm_error(c);
        printf("sampler %-26s norm_err %.2e\n", c->name, fabs(e));
        snprintf(msg, size, "%s: pdf integrates to 1 %+.3g", c->name, e);
        return fabs(e) <= WARP_NORM_TOL;
    }
    case WARP_CHECK_DOMAIN: {
        warp_domain d = warp_check_domain(c, 100000u, seed);
        printf("sampler %-26s domain %llu samples\n", c->name, (unsigned long long)d.n);
        snprintf(msg, size,
                 "%s: domain: %llu not finite, %llu not unit, %llu outside, %llu zero pdf of "
                 "%llu; first (%.17g, %.17g, %.17g) (seed %llu)",
                 c->name, (unsigned long long)d.not_finite, (unsigned long long)d.not_unit,
                 (unsigned long long)d.outside, (unsigned long long)d.zero_pdf,
                 (unsigned long long)d.n, d.example.x, d.example.y, d.example.z,
                 (unsigned long long)seed);
        return warp_domain_ok(&d);
    }
    case WARP_CHECK_ROUNDTRIP: {
        double e = warp_roundtrip_error(c, 64);
        printf("sampler %-26s roundtrip %.2e\n", c->name, e);
        snprintf(msg, size, "%s: round trip error %.3g >= 1e-9", c->name, e);
        return e < WARP_RT_TOL;
    }
    }
    return false;
}

void warp_check(const warp_case *c, warp_check_kind k, uint64_t n, uint64_t seed)
{
    char msg[512];
    if (!run_check(c, k, n, seed, msg, sizeof msg))
        fail_msg("%s", msg);
}

/* One test of the catalog: its row and case, and the check to run. */
typedef struct catalog_test {
    const cat_row *row;
    const cat_case *tc;
    warp_check_kind k;
    char name[96];
} catalog_test;

/* The registered tests. cmocka hands a test its initial_state only when
 * the group has no state of its own, and these groups keep their
 * negative-control tally there; so each test is its own function, the
 * k-th of the trampolines below, which runs registered test k: whatever
 * order cmocka runs them in, and however many of them it runs. */
enum { MAX_CATALOG_TESTS = 100 };
static catalog_test registered[MAX_CATALOG_TESTS];
static size_t n_registered;

/* Prepares the case afresh (nothing is shared between tests) and runs
 * the check; a failure names the case and the check. */
static void catalog_test_run(size_t i)
{
    assert_true(i < n_registered);
    const catalog_test *t = &registered[i];
    static cat_state s; /* large (tables' storage); one test at a time */
    warp_case c = warp_case_of(t->row, t->tc, &s);
    warp_check(&c, t->k, 1000000u, warp_case_seed(mc_test_seed(t->tc->seed), t->tc->seq));
}

#define TRAMPOLINE(d, k)                                                                           \
    static void catalog_test_##d##k(void **state)                                                  \
    {                                                                                              \
        (void)state;                                                                               \
        catalog_test_run(d * 10 + k);                                                              \
    }
#define TRAMPOLINES10(d)                                                                           \
    TRAMPOLINE(d, 0) TRAMPOLINE(d, 1) TRAMPOLINE(d, 2) TRAMPOLINE(d, 3) TRAMPOLINE(d, 4)           \
        TRAMPOLINE(d, 5) TRAMPOLINE(d, 6) TRAMPOLINE(d, 7) TRAMPOLINE(d, 8) TRAMPOLINE(d, 9)
/* catalog_test_00 .. catalog_test_99 run tests 0 .. 99. */
TRAMPOLINES10(0) TRAMPOLINES10(1) TRAMPOLINES10(2) TRAMPOLINES10(3) TRAMPOLINES10(4)
    TRAMPOLINES10(5) TRAMPOLINES10(6) TRAMPOLINES10(7) TRAMPOLINES10(8) TRAMPOLINES10(9)
#define REF10(d)                                                                                   \
    catalog_test_##d##0, catalog_test_##d##1, catalog_test_##d##2, catalog_test_##d##3,            \
        catalog_test_##d##4, catalog_test_##d##5, catalog_test_##d##6, catalog_test_##d##7,        \
        catalog_test_##d##8, catalog_test_##d##9
static void (*const trampolines[MAX_CATALOG_TESTS])(void **) = {
    REF10(0), REF10(1), REF10(2), REF10(3), REF10(4),
    REF10(5), REF10(6), REF10(7), REF10(8), REF10(9)};

void warp_catalog_tests(const char *const *families, int n_families, struct CMUnitTest *tests,
                        size_t *count, size_t max)
{
    static const char *const check_name[] = {"chi-square", "normalization", "domain",
                                             "round trip"};
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        bool mine = false;
        for (int f = 0; f < n_families; f++)
            mine = mine || strcmp(r->family, families[f]) == 0;
        for (const cat_case *tc = r->cases; mine && tc->name; tc++)
            for (int k = WARP_CHECK_CHI2; k <= WARP_CHECK_ROUNDTRIP; k++) {
                /* The round trip needs the two uniforms of a 2D warp. */
                if (k == WARP_CHECK_ROUNDTRIP && !(r->invert && r->uniforms == 2))
                    continue;
                if (*count == max || n_registered == MAX_CATALOG_TESTS) {
                    fprintf(stderr, "warp_catalog_tests: more than %zu tests\n", *count);
                    exit(2);
                }
                catalog_test *t = &registered[n_registered];
                *t = (catalog_test){r, tc, (warp_check_kind)k, ""};
                snprintf(t->name, sizeof t->name, "%s: %s", tc->name, check_name[k]);
                tests[(*count)++] =
                    (struct CMUnitTest){t->name, trampolines[n_registered], NULL, NULL, NULL};
                n_registered++;
            }
    }
}

void warp_run_cases(const warp_case *cases, int m, int first, uint64_t n, uint64_t seed)
{
    int failures = 0;
    for (int i = 0; i < m; i++) {
        uint64_t s = warp_case_seed(seed, first + i);
        for (int k = WARP_CHECK_CHI2; k <= WARP_CHECK_ROUNDTRIP; k++) {
            char msg[512];
            if (k == WARP_CHECK_ROUNDTRIP && !has_invert(&cases[i]))
                continue;
            if (!run_check(&cases[i], (warp_check_kind)k, n, s, msg, sizeof msg)) {
                print_error("%s\n", msg);
                failures++;
            }
        }
    }
    if (failures)
        fail_msg("%d check(s) failed (base seed %llu)", failures, (unsigned long long)seed);
}
