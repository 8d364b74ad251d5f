/* tests/support/warp_check.h - the checks every warp of samplers/ must
 * pass, in one place, so that each sampler test is a table of cases.
 *
 * A warp_case is one sampler with one parameter set: a row of the sampler
 * catalog (catalog/catalog.h) with its parameters, or, for a formula under
 * test that is no sampler of the library, its own functions.
 * The checks RETURN their measurements instead of asserting, so that the
 * same check can be required to pass on a correct case and to fail on a
 * negative control. Serves this book's #ch-tests and the samplers of its
 * #ch-directions to #ch-mixture.
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

#include "catalog/catalog.h"
#include "mc/rng.h"
#include "mc/vec2.h"
#include "mc/vec3.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/mc_test.h"

typedef struct warp_case warp_case;
struct warp_case {
    const char *name;
    /* A row of the catalog with its parameters (catalog/catalog.h): its
     * sampler, density, inverse, support and chart. NULL for a case that
     * brings its own functions below (a formula under test). */
    const cat_state *cat;
    int cells[2]; /* chi-square resolution; {0, 0}: the chart's (50 x 100) */
    /* Own functions, when cat is NULL. */
    vec3 (*sample)(double u1, double u2, const warp_case *c);
    double (*pdf)(vec3 x, const warp_case *c);
    vec2 (*invert)(vec3 x, const warp_case *c); /* or NULL */
    bool (*in_support)(vec3 x, const warp_case *c);
    bool direction; /* unit-length check applies */
    /* The chart: sample -> rectangle, the density of the rectangle. */
    void (*to_param)(vec3 x, const warp_case *c, double out[2]);
    double (*param_pdf)(const double p[2], const warp_case *c);
    double lo[2], hi[2];
    const void *extra; /* case-specific data for the functions */
};

/* A case of the catalog row r with the parameters of its test case tc
 * (tc->cells, tc->lobe_width), prepared into *s, which must outlive the
 * case. Fails the running test when the parameters do not prepare. */
warp_case warp_case_of(const cat_row *r, const cat_case *tc, cat_state *s);

/* The chi2_spec of a case (its ctx points to c, which must outlive it). */
chi2_spec warp_chi2_spec(const warp_case *c);

/* Runs the chi-square test: n samples, seed, at chi2_suite_alpha(). */
chi2_outcome warp_chi2(const warp_case *c, uint64_t n, uint64_t seed);

/* The integral of the density over its whole domain, minus 1: the chart's
 * rectangle, cell by cell (a direction chart of pdf/chart.h other than
 * (cos theta, phi): by pdf_chart_integrate, which refines toward the
 * chart's singular corners), plus, for a direction row, the directions the
 * chart leaves out (below a (cos theta, phi) chart's lower end; around the
 * light and the cap of a quad-and-cap chart), where a density that leaks
 * mass shows up. */
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
    uint64_t zero_pdf;   /* pdf(sample) <= 0, NaN, or infinite (rim and pole exceptions aside) */
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

/* The checks of one case, each a cmocka test of its own. */
typedef enum warp_check_kind {
    WARP_CHECK_CHI2,
    WARP_CHECK_NORM,
    WARP_CHECK_DOMAIN,
    WARP_CHECK_ROUNDTRIP
} warp_check_kind;

/* Runs one check of c and fails the running cmocka test, naming the case
 * and the seed, when it does not pass: chi-square with n samples,
 * normalization within WARP_NORM_TOL, domain on 10^5 samples plus the edge
 * grid, round trip within WARP_RT_TOL on a 64 x 64 grid. seed is the
 * case's own (warp_case_seed). Prints one line "sampler NAME ...". */
void warp_check(const warp_case *c, warp_check_kind k, uint64_t n, uint64_t seed);

/* The seed of the case at position seq of a test group of base seed
 * `seed`: hashed, so that neighbouring cases and base seeds share no
 * streams. Base seeds pass through mc_test_seed (MC_TEST_SEED). */
uint64_t warp_case_seed(uint64_t seed, int seq);

/* Appends to tests[*count ..] (at most max in all, at most 100 per
 * program) one cmocka test per case and check of every row of the catalog
 * whose family is one of families[0 .. n_families): chi-square (10^6
 * samples), normalization, domain, and round trip where the row has an
 * inverse of two uniforms, named "CASE: check". Each test prepares its
 * case itself and shares nothing with the others: it passes or fails
 * alone, in any order. */
void warp_catalog_tests(const char *const *families, int n_families, struct CMUnitTest *tests,
                        size_t *count, size_t max);

/* Runs every check on cases[0..m), case i with warp_case_seed(seed,
 * first + i), failing the running test listing every failed check. */
void warp_run_cases(const warp_case *cases, int m, int first, uint64_t n, uint64_t seed);

/* Tolerances of the normalization and round-trip checks (README, "How the
 * tests decide"). */
#define WARP_NORM_TOL 1e-6
#define WARP_RT_TOL 1e-9

#endif /* WARP_CHECK_H */
