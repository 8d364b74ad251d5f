/* tests/support/chi2_harness.h - the chi-square goodness-of-fit harness
 * every sampler test shares.
 *
 * A sampler claims a density; the harness checks the claim. It histograms
 * samples over a rectangle of an (ideally equal-measure) parameterization,
 * integrates the claimed density over every cell by adaptive quadrature
 * (never the value at the cell centre, which is biased wherever the pdf
 * curves), pools sparse cells and runs Pearson's test. Samples outside the
 * rectangle, or in cells where the pdf integrates to zero, are failures no
 * p-value may dilute. A chi-square test barely sees a pdf that is wrong by
 * a constant factor, so the harness also integrates the density over the
 * whole rectangle: the normalization check. Serves this book's #ch-tests
 * and every sampler it checks (#ch-directions to #ch-mixture).
 *
 * The work is mc/gof.h's (the same code behind `warp chi2` and the plots);
 * this layer adds what a test suite needs: a name per experiment, the
 * suite-wide Sidak level, a derived RNG stream per seed, the CSV dump of a
 * failure and the log line.
 *
 * Parameterizations used by the suite: (cos theta, phi) for directions on
 * the sphere, hemisphere and cone (d omega = d cos_theta d phi, so the
 * density per unit solid angle IS the parameter density); (r^2, phi) for
 * discs (d area = d(r^2) d phi / 2); (x, y) for the square and triangle;
 * x for 1D densities.
 */
#ifndef CHI2_HARNESS_H
#define CHI2_HARNESS_H

#include <stdbool.h>
#include <stdint.h>

#include "mc/chi2.h"
#include "mc/gof.h"
#include "mc/rng.h"

/* One goodness-of-fit experiment of the suite: mc/gof.h's experiment (the
 * rectangle of an, ideally equal-measure, parameterization, its cells, the
 * sampler and the claimed density) with a name. */
typedef struct chi2_spec {
    const char *name; /* used in messages and in the CSV file names written on failure */
    mc_gof_spec gof;
} chi2_spec;

typedef struct chi2_outcome {
    mc_chi2_result r; /* statistic, dof, p-value, pooling info */
    double alpha;     /* the per-test level used */
    bool reject;      /* p < alpha, or samples in zero-expected cells beyond round-off,
                               or samples outside [lo, hi] */
    double outside;   /* samples that fell outside [lo, hi] */
} chi2_outcome;

/* Histograms n samples from rng = mc_rng_derive(seed, 0), integrates
 * spec->gof.pdf over every cell with mc_quad (1D or nested 2D), pools cells with
 * expected < 5, Pearson chi-square, GSL p-value; rejects at `alpha` (the
 * caller passes the Sidak-corrected level). On rejection writes observed and
 * expected tables as CSV under $MC_BUILD/test-results/chi2/<name>.csv.
 *
 * Round-off rules, so that a correct sampler is never failed by the last
 * bit: a sample within CHI2_EDGE_TOL of the rectangle's width outside it is
 * put in the edge cell (a cos_theta of 1 + 1 ulp is round-off, not a bug);
 * a cell whose probability integrates below CHI2_ZERO_CELL_PROB counts as
 * an expected-zero cell, and up to CHI2_ZERO_CELL_FRAC * n samples may fall
 * in such cells (a sample exactly on a support boundary that coincides
 * with a cell edge). Any real leak of mass is far larger; the domain
 * checks of the tests catch single samples. n >= 1, 0 < alpha < 1. */
chi2_outcome chi2_run(const chi2_spec *spec, uint64_t n, uint64_t seed, double alpha);

/* The rules are mc/gof.h's, under the names the suite documents. */
#define CHI2_EDGE_TOL MC_GOF_EDGE_TOL             /* 1e-12, relative to hi - lo */
#define CHI2_ZERO_CELL_PROB MC_GOF_ZERO_CELL_PROB /* 1e-13, below MC_QUAD_EPSABS */
#define CHI2_ZERO_CELL_FRAC MC_GOF_ZERO_CELL_FRAC /* 1e-6, of n */

/* The suite-wide level: alpha = 0.01 Sidak-corrected over CHI2_SUITE_TESTS tests. */
#define CHI2_SUITE_ALPHA 0.01
#define CHI2_SUITE_TESTS 64 /* an upper bound on the number of chi-square tests in the suite */

/* mc_sidak_alpha(CHI2_SUITE_ALPHA, CHI2_SUITE_TESTS), about 1.57e-4: with
 * every test of the suite at this level, a correct suite fails somewhere
 * with probability at most 1%. */
double chi2_suite_alpha(void);

/* Normalization: the integral of a 1D/2D parameter-space density over
 * [lo, hi] by mc_quad, as the sum of its integrals over the spec's cells
 * (one adaptive rule over the whole rectangle can stall on a support edge
 * that crosses it, such as the triangle's hypotenuse). A correct pdf gives
 * 1 to the quadrature's accuracy (about 1e-11 relative) when its support
 * lies inside the rectangle.
 *
 * Cost: nested adaptive quadrature of a cell is cheap where the pdf is
 * smooth, and where a discontinuity runs along a cell edge, but a jump
 * along a curve THROUGH a cell makes every inner integral bisect down to
 * 1e-12 and can cost millions of pdf calls per cell (a parallelogram
 * light's silhouette in (cos theta, phi): about 100 s for 5000 cells).
 * Choose parameterizations whose rectangle is the support (a light's own
 * (a, b) coordinates, (cos theta, phi) on [cos_theta_max, 1] for a cone). */
double chi2_integrate_pdf(const chi2_spec *spec);

/* The outcome as one line for the test logs: name, statistic, dof, p-value,
 * level, pooled cells, samples outside and in zero cells, verdict. Writes
 * to stdout (tests only; no library code prints). */
void chi2_print(const chi2_spec *spec, const chi2_outcome *o);

#endif /* CHI2_HARNESS_H */
