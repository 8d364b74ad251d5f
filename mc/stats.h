/* mc/stats.h - estimators with honest error bars.
 *
 * A Monte Carlo estimate is only useful with its standard error. This module
 * keeps a running mean and variance (Welford), merges partial results from
 * threads (Chan et al.), and turns an estimate and a known value into a
 * z-score with its two-sided p-value. Serves this book's #ch-pi and
 * #ch-integration onwards.
 */
#ifndef MC_STATS_H
#define MC_STATS_H

#include <stdint.h>

/* Running mean and sum of squared deviations of a stream of doubles.
 * Welford's update avoids the catastrophic cancellation of sum(x^2) -
 * n mean^2: it stays accurate for data with mean 1e9 and variance 1 and for
 * 10^10 samples (the count is 64-bit). Zero-initialise or use
 * mc_welford_init. */
typedef struct mc_welford {
    uint64_t n;  /* samples seen */
    double mean; /* running mean */
    double m2;   /* sum of squared deviations from the running mean */
} mc_welford;

/* An empty accumulator. */
mc_welford mc_welford_init(void);

/* Adds the sample x. */
void mc_welford_add(mc_welford *w, double x);

/* The accumulator of the union of the samples of a and b (Chan, Golub and
 * LeVeque's pairwise update). Exact in real arithmetic for any split, so
 * per-thread accumulators merge to the same statistics. */
mc_welford mc_welford_merge(mc_welford a, mc_welford b);

/* The unbiased sample variance m2 / (n - 1); 0 when n < 2. */
double mc_welford_variance(const mc_welford *w);

/* The standard error of the mean, sqrt(variance / n); 0 when n < 2. */
double mc_welford_std_error(const mc_welford *w);

/* The result of an estimator: what every chapter program reports. */
typedef struct mc_estimate {
    uint64_t n;       /* samples used */
    double value;     /* the estimate */
    double variance;  /* variance per sample (of one sample's contribution) */
    double std_error; /* standard error of value */
} mc_estimate;

/* The estimate of the mean held in w (variance per sample and standard
 * error as above). */
mc_estimate mc_welford_estimate(const mc_welford *w);

/* z = (estimate - exact) / std_error. With std_error == 0 the result is 0
 * when estimate == exact and +-INFINITY otherwise (a zero-variance estimator
 * that misses is infinitely significant). */
double mc_z_score(double estimate, double exact, double std_error);

/* The two-sided p-value of a standard normal statistic: P(|Z| >= |z|) =
 * erfc(|z| / sqrt 2). 1 at z = 0, 0 at z = +-INFINITY. */
double mc_z_pvalue(double z);

#endif /* MC_STATS_H */
