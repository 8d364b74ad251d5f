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
#include "samplers/spherical.h"
#include "tests/support/mc_test.h"

/* --- parameterizations -------------------------------------------------- */

static double scaled_x_max(const warp_case *c)
{
    return MC_PI_2 / (MC_PI_2 + c->theta_scale);
}

static void rectangle(const warp_case *c, double lo[2], double hi[2])
{
    lo[1] = 0.0;
    hi[1] = MC_2PI;
    switch (c->kind) {
    case WARP_COS_PHI:
        lo[0] = c->z_lo;
        hi[0] = 1.0;
        break;
    case WARP_SCALED_THETA:
        lo[0] = 0.0;
        hi[0] = scaled_x_max(c);
        break;
    case WARP_R2_PHI:
        lo[0] = 0.0;
        hi[0] = 1.0;
        break;
    case WARP_XY:
        lo[0] = lo[1] = 0.0;
        hi[0] = hi[1] = 1.0;
        break;
    case WARP_CUSTOM:
        lo[0] = c->lo[0], lo[1] = c->lo[1];
        hi[0] = c->hi[0], hi[1] = c->hi[1];
        break;
    }
}

static void to_param(const warp_case *c, vec3 x, double out[2])
{
    switch (c->kind) {
    case WARP_COS_PHI:
        out[0] = x.z;
        out[1] = smp_spherical_phi(x);
        break;
    case WARP_SCALED_THETA: {
        double theta = smp_spherical_theta(x);
        out[0] = theta / (theta + c->theta_scale);
        out[1] = smp_spherical_phi(x);
        break;
    }
    case WARP_R2_PHI:
        out[0] = x.x * x.x + x.y * x.y;
        out[1] = smp_spherical_phi(vec3_make(x.x, x.y, 0.0));
        break;
    case WARP_XY: out[0] = x.x, out[1] = x.y; break;
    case WARP_CUSTOM: c->to_param(x, c, out); break;
    }
}

static double param_pdf(const double p[2], void *ctx)
{
    const warp_case *c = ctx;
    switch (c->kind) {
    case WARP_COS_PHI: return c->pdf(smp_spherical_direction(p[0], p[1]), c);
    case WARP_SCALED_THETA: {
        /* theta = s x / (1 - x), d theta / dx = s / (1 - x)^2, and the
         * solid angle element is sin theta d theta d phi. */
        double s = c->theta_scale, x = p[0];
        double theta = s * x / (1.0 - x);
        if (theta > MC_PI_2)
            return 0.0;
        vec3 w = smp_spherical_direction(cos(theta), p[1]);
        return c->pdf(w, c) * sin(theta) * s / ((1.0 - x) * (1.0 - x));
    }
    case WARP_R2_PHI: {
        double r = sqrt(p[0]);
        return 0.5 * c->pdf(vec3_make(r * cos(p[1]), r * sin(p[1]), 0.0), c);
    }
    case WARP_XY: return c->pdf(vec3_make(p[0], p[1], 0.0), c);
    case WARP_CUSTOM: return c->param_pdf(p, c);
    }
    return 0.0;
}

static vec3 draw(const warp_case *c, mc_rng *rng)
{
    if (c->sample_rng)
        return c->sample_rng(rng, c);
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return c->sample(u1, u2, c);
}

static void chi2_sample(mc_rng *rng, void *ctx, double out[2])
{
    const warp_case *c = ctx;
    to_param(c, draw(c, rng), out);
}

chi2_spec warp_chi2_spec(const warp_case *c)
{
    chi2_spec s;
    memset(&s, 0, sizeof s);
    s.name = c->name;
    s.dims = 2;
    rectangle(c, s.lo, s.hi);
    s.cells[0] = c->cells[0] > 0 ? c->cells[0] : 50;
    s.cells[1] = c->cells[1] > 0 ? c->cells[1] : 100;
    s.sample = chi2_sample;
    s.pdf = param_pdf;
    s.ctx = (void *)c; /* read only, as chi2_spec documents */
    return s;
}

chi2_outcome warp_chi2(const warp_case *c, uint64_t n, uint64_t seed)
{
    chi2_spec s = warp_chi2_spec(c);
    return chi2_run(&s, n, seed, chi2_suite_alpha());
}

double warp_norm_error(const warp_case *c)
{
    chi2_spec s = warp_chi2_spec(c);
    return chi2_integrate_pdf(&s) - 1.0;
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

static bool default_support(vec3 x, const warp_case *c)
{
    switch (c->kind) {
    case WARP_COS_PHI: return x.z >= c->z_lo - SLACK;
    case WARP_SCALED_THETA: return x.z >= -SLACK;
    case WARP_R2_PHI: return x.x * x.x + x.y * x.y <= 1.0 + SLACK && x.z == 0.0;
    case WARP_XY: return x.x >= 0.0 && x.x <= 1.0 && x.y >= 0.0 && x.y <= 1.0 && x.z == 0.0;
    case WARP_CUSTOM: return true;
    }
    return false;
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
        /* 1e-12: the brief's bound, ~4500 ulps; the warps are far inside. */
        if (c->direction && !(fabs(vec3_length(x) - 1.0) <= 1e-12)) {
            d->not_unit++;
            bad = true;
        }
        bool in = c->in_support ? c->in_support(x, c) : default_support(x, c);
        if (!in) {
            d->outside++;
            bad = true;
        }
        double p = c->pdf(x, c);
        if (!(p > 0.0) && !(c->rim_zero_ok && x.z == 0.0)) {
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
    if (c->sample) {
        /* The extreme uniforms mc_rng_uniform can return, and their
         * neighbours: where a warp meets a pole, a rim or a corner. */
        static const double edge[] = {0.0, 0x1p-32,       0x1p-31, 0.25,          0.5 - 0x1p-32,
                                      0.5, 0.5 + 0x1p-32, 0.75,    1.0 - 0x1p-31, 1.0 - 0x1p-32};
        size_t m = sizeof edge / sizeof edge[0];
        for (size_t i = 0; i < m; i++)
            for (size_t j = 0; j < m; j++)
                check_one(c, c->sample(edge[i], edge[j], c), &d);
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
    vec3 x = c->sample(u1, u2, c);
    vec2 v = c->invert(x, c);
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
    mc_gof_spec s = {2, {0.0, 0.0}, {0.0, 0.0}, {AGREE_NX, AGREE_NY}, framed_sample, NULL, &f};
    rectangle(frame, s.lo, s.hi);
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

void warp_print_summary(const warp_case *c, const chi2_outcome *o, double norm_err, double rt_err)
{
    char rt[32];
    if (c->invert)
        snprintf(rt, sizeof rt, "%.2e", rt_err);
    else
        snprintf(rt, sizeof rt, "-");
    printf("sampler %-26s chi2 %10.2f dof %5d p %.4f norm_err %.2e roundtrip %s %s\n", c->name,
           o->r.stat, o->r.dof, o->r.pvalue, fabs(norm_err), rt, o->reject ? "REJECT" : "ok");
}

/* The seed of case i of a table: hashed, so that neighbouring cases and
 * neighbouring base seeds share no streams. */
static uint64_t case_seed(uint64_t seed, int i)
{
    mc_rng r = mc_rng_derive(seed, (uint64_t)i + 100u);
    return (uint64_t)mc_rng_u32(&r) << 32 | mc_rng_u32(&r);
}

typedef struct case_result {
    chi2_outcome o;
    double norm_err, rt_err;
    warp_domain d;
} case_result;

void warp_run_cases(const warp_case *cases, int m, uint64_t n, uint64_t seed)
{
    case_result *res = calloc((size_t)m, sizeof *res);
    assert_non_null(res);
#pragma omp parallel for schedule(dynamic)
    for (int i = 0; i < m; i++) {
        const warp_case *c = &cases[i];
        uint64_t s = case_seed(seed, i);
        res[i].o = warp_chi2(c, n, s);
        res[i].norm_err = warp_norm_error(c);
        res[i].d = warp_check_domain(c, 100000u, s);
        res[i].rt_err = c->invert ? warp_roundtrip_error(c, 64) : 0.0;
    }
    int failures = 0;
    for (int i = 0; i < m; i++) {
        const warp_case *c = &cases[i];
        case_result *r = &res[i];
        warp_print_summary(c, &r->o, r->norm_err, r->rt_err);
        if (r->o.reject) {
            chi2_spec s = warp_chi2_spec(c);
            chi2_print(&s, &r->o);
            print_error("%s: chi-square rejects (seed %llu)\n", c->name,
                        (unsigned long long)case_seed(seed, i));
            failures++;
        }
        if (!(fabs(r->norm_err) <= WARP_NORM_TOL)) {
            print_error("%s: pdf integrates to 1 %+.3g\n", c->name, r->norm_err);
            failures++;
        }
        if (!warp_domain_ok(&r->d)) {
            print_error("%s: domain: %llu not finite, %llu not unit, %llu outside, %llu zero pdf "
                        "of %llu; first (%.17g, %.17g, %.17g) (seed %llu)\n",
                        c->name, (unsigned long long)r->d.not_finite,
                        (unsigned long long)r->d.not_unit, (unsigned long long)r->d.outside,
                        (unsigned long long)r->d.zero_pdf, (unsigned long long)r->d.n,
                        r->d.example.x, r->d.example.y, r->d.example.z,
                        (unsigned long long)case_seed(seed, i));
            failures++;
        }
        if (c->invert && !(r->rt_err < WARP_RT_TOL)) {
            print_error("%s: round trip error %.3g >= 1e-9\n", c->name, r->rt_err);
            failures++;
        }
    }
    free(res);
    if (failures)
        fail_msg("%d check(s) failed (base seed %llu)", failures, (unsigned long long)seed);
}
