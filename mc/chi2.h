/* mc/chi2.h - Pearson's chi-square goodness-of-fit test [@pearson1900], the pieces.
 *
 * The sampler tests histogram N samples into cells, integrate the claimed
 * pdf over each cell to get expected counts, and ask whether the observed
 * counts could plausibly come from it. This module does the last step:
 * pooling of sparse cells, the statistic, its upper-tail probability (GSL),
 * and the Sidak-corrected level for a suite of many tests. Histogramming
 * and integration live with the callers (tests/support). Serves this
 * book's #ch-directions and #ch-tests, and every sampler after them.
 */
#ifndef MC_CHI2_H
#define MC_CHI2_H

#include <stddef.h>

/* Outcome of one Pearson test. */
typedef struct mc_chi2_result {
    double stat;             /* sum over pooled cells of (obs - exp)^2 / exp */
    int dof;                 /* degrees of freedom: pooled cells - 1 (0 if < 2 cells) */
    double pvalue;           /* P(chi2_dof >= stat); 1 when dof == 0, 0 for NaN stat */
    size_t cells_pooled;     /* cells with expected < min_expected merged into one */
    double obs_in_zero_cells;/* samples observed where the expected count is 0 */
    double obs_total;        /* total observed count */
    double exp_total;        /* total expected count */
} mc_chi2_result;

/* Pearson's test of observed counts obs[0..n) against expected counts
 * exp[0..n) (n >= 1, all finite and >= 0; a NaN is rejected, see below).
 * Cells with exp < min_expected (5 is the textbook rule) are pooled into
 * one cell; if that pool's expected count is still below min_expected it
 * is merged with the smallest remaining cell. Cells whose expected count
 * is exactly 0 are left out of the statistic and their observations
 * reported in obs_in_zero_cells, for the caller to judge (samples where
 * the pdf says none can fall is a failure no p-value should dilute). A NaN
 * among the expected counts makes stat NaN and so the p-value 0. No
 * allocation. */
mc_chi2_result mc_chi2_pearson(const double *obs, const double *exp, size_t n, double min_expected);

/* The upper tail P(X >= stat) for X chi-square with dof degrees of freedom,
 * computed directly by gsl_cdf_chisq_Q (not 1 - P, which loses every digit
 * below 1e-16). GSL's aborting error handler is switched off, once per
 * process (mc/gsl_quiet.h), so this is safe from threads. dof >= 1;
 * returns 1 for stat <= 0 and 0 for a NaN stat: an invalid statistic is
 * rejected. */
double mc_chi2_pvalue(double stat, int dof);

/* The per-test significance level that keeps the probability of one or more
 * false rejections among m independent tests at alpha (Sidak [@sidak1967]):
 * 1 - (1 - alpha)^(1/m). 0 < alpha < 1, m >= 1. */
double mc_sidak_alpha(double alpha, int m);

/* The power of the test above: the probability that a statistic
 * distributed as noncentral chi-square with dof >= 1 degrees of freedom
 * and noncentrality lambda >= 0 exceeds the level-`level` critical value
 * of the central one. The noncentral law is the Poisson(lambda / 2)
 * mixture of central chi-squares with dof + 2j degrees of freedom (the
 * usual series), summed where its weights are not negligible. Pearson's
 * statistic for n samples of a law p tested against q is approximately so
 * distributed with lambda = n sum (p_k - q_k)^2 / q_k. */
double mc_chi2_power(int dof, double level, double lambda);

/* The noncentrality at which mc_chi2_power reaches `power` (in (level,
 * 1)), by bisection to a relative 1e-6. */
double mc_chi2_noncentrality_for_power(int dof, double level, double power);

#endif /* MC_CHI2_H */
