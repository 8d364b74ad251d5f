/* tests/support/warp_check.h - the checks every warp of samplers/ must
 * pass, in one place, so that each sampler test is a table of cases.
 *
 * A warp_case wraps one sampler with one parameter set: how to draw a
 * sample (from two uniforms, or from an RNG), its claimed pdf, its inverse
 * if any, and the parameterization the chi-square harness histograms it in.
 * The checks RETURN their measurements instead of asserting, so that the
 * same check can be required to pass on a correct case and to fail on a
 * negative control. Serves chapter 5 ("Generating Random Directions") and
 * the samplers of chapters 6-8 and 10.
 *
 *  - chi-square goodness of fit (tests/support/chi2_harness.h);
 *  - normalization: the pdf integrated over the parameter rectangle;
 *  - domain: every sample finite, in the support, unit length (directions,
 *    1e-12), pdf(sample) > 0;
 *  - round trip: |invert(sample(u)) - u| on a grid of u;
 *  - agreement of two samplers of the same density (two-sample test).
 */
#ifndef WARP_CHECK_H
#define WARP_CHECK_H

#include <stdbool.h>
#include <stdint.h>

#include "mc/rng.h"
#include "mc/vec2.h"
#include "mc/vec3.h"
#include "tests/support/chi2_harness.h"

/* How samples are mapped to the chi-square rectangle. */
typedef enum warp_param {
    /* Directions: (cos theta, phi) on [z_lo, 1] x [0, 2 pi]. Equal-area:
     * the parameter density is the pdf per unit solid angle itself. */
    WARP_COS_PHI,
    /* Peaked directions: x = theta / (theta + theta_scale) and phi, on
     * [0, x(pi/2)] x [0, 2 pi]. Spreads a lobe of width ~theta_scale over
     * many cells; density pdf * sin theta * d theta / dx. */
    WARP_SCALED_THETA,
    /* Points of the unit disc: (r^2, phi) on [0, 1] x [0, 2 pi]; density
     * pdf / 2 (d area = d(r^2) d phi / 2). */
    WARP_R2_PHI,
    /* Points of the unit square (and the triangle in it): (x, y). */
    WARP_XY,
    /* The case supplies to_param, param_pdf and the rectangle itself. */
    WARP_CUSTOM
} warp_param;

typedef struct warp_case warp_case;
struct warp_case {
    const char *name;
    /* The sample for uniforms (u1, u2); NULL when sample_rng is used. */
    vec3 (*sample)(double u1, double u2, const warp_case *c);
    /* A sampler that needs more than two uniforms or rejection. */
    vec3 (*sample_rng)(mc_rng *rng, const warp_case *c);
    /* The claimed density (per unit solid angle or per unit area). */
    double (*pdf)(vec3 x, const warp_case *c);
    /* The inverse, or NULL. */
    vec2 (*invert)(vec3 x, const warp_case *c);
    /* The support, or NULL for the default of the parameterization
     * (directions: z >= z_lo; disc; square; triangle needs its own). */
    bool (*in_support)(vec3 x, const warp_case *c);
    double param;     /* n, alpha, cos_theta_max, ... */
    bool direction;   /* unit-length check applies */
    bool rim_zero_ok; /* pdf(sample) == 0 allowed exactly on z == 0 (cosine-like) */
    warp_param kind;
    double z_lo;        /* WARP_COS_PHI lower bound of cos theta (-1, 0, cos_max) */
    double theta_scale; /* WARP_SCALED_THETA */
    int cells[2];       /* chi-square resolution; {0, 0}: 50 x 100 */
    /* WARP_CUSTOM: sample -> parameters, parameter density, rectangle. */
    void (*to_param)(vec3 x, const warp_case *c, double out[2]);
    double (*param_pdf)(const double p[2], const warp_case *c);
    double lo[2], hi[2];
    const void *extra; /* case-specific data for the custom functions */
};

/* warp_case adapters of samplers/ functions, defined as static functions
 * in the test file: WARP_WRAP_SAMPLE(name, expr) gives
 * vec3 name(u1, u2, c), WARP_WRAP_PDF and WARP_WRAP_INV give double and
 * vec2 name(w, c); expr may use u1, u2, w and c. WARP_TRIO(tag, stem)
 * wraps smp_<stem>_{sample,pdf,invert} as s_<tag>, p_<tag>, i_<tag>;
 * WARP_TRIO_PARAM passes c->param as their last argument. */
#define WARP_WRAP_SAMPLE(name, expr)                                                               \
    static vec3 name(double u1, double u2, const warp_case *c)                                     \
    {                                                                                              \
        (void)c;                                                                                   \
        return expr;                                                                               \
    }
#define WARP_WRAP_PDF(name, expr)                                                                  \
    static double name(vec3 w, const warp_case *c)                                                 \
    {                                                                                              \
        (void)c;                                                                                   \
        return expr;                                                                               \
    }
#define WARP_WRAP_INV(name, expr)                                                                  \
    static vec2 name(vec3 w, const warp_case *c)                                                   \
    {                                                                                              \
        (void)c;                                                                                   \
        return expr;                                                                               \
    }
#define WARP_TRIO(tag, stem)                                                                       \
    WARP_WRAP_SAMPLE(s_##tag, smp_##stem##_sample(u1, u2))                                         \
    WARP_WRAP_PDF(p_##tag, smp_##stem##_pdf(w))                                                    \
    WARP_WRAP_INV(i_##tag, smp_##stem##_invert(w))
#define WARP_TRIO_PARAM(tag, stem)                                                                 \
    WARP_WRAP_SAMPLE(s_##tag, smp_##stem##_sample(u1, u2, c->param))                               \
    WARP_WRAP_PDF(p_##tag, smp_##stem##_pdf(w, c->param))                                          \
    WARP_WRAP_INV(i_##tag, smp_##stem##_invert(w, c->param))

/* The chi2_spec of a case (its ctx points to c, which must outlive it). */
chi2_spec warp_chi2_spec(const warp_case *c);

/* Runs the chi-square test: n samples, seed, at chi2_suite_alpha(). */
chi2_outcome warp_chi2(const warp_case *c, uint64_t n, uint64_t seed);

/* The integral of the parameter density over the rectangle, minus 1. */
double warp_norm_error(const warp_case *c);

/* For negative controls: true when the normalization check rejects c
 * (|warp_norm_error| > WARP_NORM_TOL); prints the error. */
bool warp_norm_rejects(const warp_case *c);

/* For negative controls: true when the chi-square test of c (n samples,
 * seed, chi2_suite_alpha()) rejects; prints the chi2_print line. */
bool warp_chi2_rejects(const warp_case *c, uint64_t n, uint64_t seed);

/* Result of the domain check. */
typedef struct warp_domain {
    uint64_t n;          /* samples checked */
    uint64_t not_finite; /* a coordinate is NaN or infinite */
    uint64_t not_unit;   /* | |w| - 1 | > 1e-12 (directions) */
    uint64_t outside;    /* outside the support */
    uint64_t zero_pdf;   /* pdf(sample) <= 0 or NaN (rim exception aside) */
    vec3 example;        /* the first failing sample */
} warp_domain;

/* Checks n random samples (seed) and, for two-uniform samplers, a grid of
 * edge uniforms (0, 2^-32, 1/2, 1 - 2^-32 and neighbours). */
warp_domain warp_check_domain(const warp_case *c, uint64_t n, uint64_t seed);
/* True when the domain check found nothing wrong. */
bool warp_domain_ok(const warp_domain *d);

/* max |invert(sample(u)) - u| over the grid u = ((i + 1/2)/g, (j + 1/2)/g)
 * plus points 1e-6 from the edges; u1 is ignored where the sample lies on
 * the polar axis (its azimuth is undefined there). */
double warp_roundtrip_error(const warp_case *c, int g);

/* Two-sample chi-square of a against b: n samples of each histogrammed in
 * a's parameterization on a coarse grid (20 x 40 cells, plus one cell for
 * samples outside a's rectangle), statistic
 * sum (A - B)^2 / (A + B) over non-empty cells, dof = cells - 1; pooled
 * cells with A + B < 10 are merged. */
typedef struct warp_agreement {
    double stat;
    int dof;
    double pvalue;
} warp_agreement;
warp_agreement warp_compare(const warp_case *a, const warp_case *b, uint64_t n, uint64_t seed);

/* Prints one summary line of a case's results (for the report). */
void warp_print_summary(const warp_case *c, const chi2_outcome *o, double norm_err, double rt_err);

/* Runs every check on cases[0..m) (in parallel over cases): chi-square with
 * n samples, normalization within 1e-6, domain on 10^5 samples plus the
 * edge grid, round trip within 1e-9 on a 64 x 64 grid where an inverse
 * exists. Case i uses the seed mc_rng_derive-hashed from (seed, i). Prints
 * one summary line per case, then fails the running cmocka test listing
 * every failed check (printing the seed). */
void warp_run_cases(const warp_case *cases, int m, uint64_t n, uint64_t seed);

/* Tolerances of the brief: normalization and round trip. */
#define WARP_NORM_TOL 1e-6
#define WARP_RT_TOL 1e-9

#endif /* WARP_CHECK_H */
