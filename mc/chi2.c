/* mc/chi2.c - Pearson statistic with pooling, GSL tail, Sidak level. */
#include "mc/chi2.h"

#include <math.h>

#include <gsl/gsl_cdf.h>

#include "mc/gsl_quiet.h"

/* BEGIN SNIPPET chi2_pool */
mc_chi2_result mc_chi2_pearson(const double *obs, const double *exp, size_t n, double min_expected)
{
    mc_chi2_result r = {0.0, 0, 1.0, 0u, 0.0, 0.0, 0.0};
    double pool_obs = 0.0, pool_exp = 0.0;
    size_t big_cells = 0u;
    size_t smallest = n; /* index of the smallest cell kept apart */

    for (size_t i = 0; i < n; i++) {
        r.obs_total += obs[i];
        r.exp_total += exp[i];
        if (exp[i] <= 0.0) {
            r.obs_in_zero_cells += obs[i];
        } else if (exp[i] < min_expected) {
            pool_obs += obs[i];
            pool_exp += exp[i];
            r.cells_pooled++;
        } else {
            big_cells++;
            if (smallest == n || exp[i] < exp[smallest])
                smallest = i;
        }
    }
    /* A pool that is itself too sparse borrows the smallest regular cell, so
     * that no term of the sum has an expected count below min_expected. */
    int merge_smallest = pool_exp > 0.0 && pool_exp < min_expected && smallest < n;
    if (merge_smallest) {
        pool_obs += obs[smallest];
        pool_exp += exp[smallest];
        big_cells--;
    }
    /* END SNIPPET chi2_pool */
    /* BEGIN SNIPPET chi2_sum */
    for (size_t i = 0; i < n; i++) {
        if (exp[i] < min_expected || (merge_smallest && i == smallest))
            continue;
        double d = obs[i] - exp[i];
        r.stat += d * d / exp[i];
    }
    size_t cells = big_cells;
    if (pool_exp > 0.0) {
        double d = pool_obs - pool_exp;
        r.stat += d * d / pool_exp;
        cells++;
    }
    /* A NaN expected count (a NaN or negative density upstream) could hide
     * in the pool or the merged cell; it must reach the statistic so that
     * the p-value rejects. */
    for (size_t i = 0; i < n; i++)
        if (isnan(exp[i]))
            r.stat = (double)NAN;
    r.dof = cells >= 2u ? (int)cells - 1 : 0;
    r.pvalue = r.dof > 0 || isnan(r.stat) ? mc_chi2_pvalue(r.stat, r.dof) : 1.0;
    return r;
}
/* END SNIPPET chi2_sum */

/* BEGIN SNIPPET chi2_pvalue */
double mc_chi2_pvalue(double stat, int dof)
{
    /* An invalid (NaN) statistic, e.g. from a pdf that returned NaN, is
     * rejected; only a genuine perfect fit gets p = 1. */
    if (isnan(stat))
        return 0.0;
    if (stat <= 0.0)
        return 1.0;
    /* GSL's default handler aborts the process on a domain error; a library
     * must return instead. mc_gsl_quiet switches it off once, safely even
     * here: the sampler suites call this from OpenMP threads. */
    mc_gsl_quiet();
    return gsl_cdf_chisq_Q(stat, (double)dof);
}
/* END SNIPPET chi2_pvalue */

/* BEGIN SNIPPET sidak_alpha */
double mc_sidak_alpha(double alpha, int m)
{
    /* 1 - (1 - alpha)^(1/m) computed as -expm1(log1p(-alpha) / m): the naive
     * form loses most digits when alpha / m is tiny. */
    return -expm1(log1p(-alpha) / (double)m);
}
/* END SNIPPET sidak_alpha */

/* The critical value: Q(crit, dof) = level, by bisection on the tail
 * (the tail alone, so that the module needs no more of GSL than it has). */
static double critical_value(int dof, double level)
{
    double lo = 0.0, hi = (double)dof + 10.0;
    while (gsl_cdf_chisq_Q(hi, (double)dof) > level)
        lo = hi, hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if (gsl_cdf_chisq_Q(mid, (double)dof) > level)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

double mc_chi2_power(int dof, double level, double lambda)
{
    mc_gsl_quiet();
    double crit = critical_value(dof, level), m = 0.5 * lambda;
    if (m <= 0.0)
        return gsl_cdf_chisq_Q(crit, (double)dof);
    /* Poisson(m) weights outside m +- 12 sqrt(m) + 30 sum below 1e-30. */
    double spread = 12.0 * sqrt(m) + 30.0;
    long j0 = (long)fmax(0.0, floor(m - spread)), j1 = (long)ceil(m + spread);
    double sum = 0.0;
    for (long j = j0; j <= j1; j++) {
        double w = exp(-m + (double)j * log(m) - lgamma((double)j + 1.0));
        sum += w * gsl_cdf_chisq_Q(crit, (double)dof + 2.0 * (double)j);
    }
    return fmin(1.0, sum);
}

double mc_chi2_noncentrality_for_power(int dof, double level, double power)
{
    double lo = 0.0, hi = 1.0;
    while (mc_chi2_power(dof, level, hi) < power && hi < 1e12)
        lo = hi, hi *= 2.0;
    while (hi - lo > 1e-6 * hi) {
        double mid = 0.5 * (lo + hi);
        if (mc_chi2_power(dof, level, mid) < power)
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}
