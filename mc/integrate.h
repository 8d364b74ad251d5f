/* mc/integrate.h - one-dimensional Monte Carlo integration.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 2 "One
 * Dimensional MC Integration" (this book's #ch-integration): the integral
 * of f is the mean of f(X) / p(X) for X drawn with any density p that is
 * positive wherever f is not zero; the closer p follows |f|, the smaller
 * the variance (importance sampling), down to zero when p is proportional
 * to f. This module is that estimator with its error bar, for a sampler
 * given as function pointers (mc/ knows no samplers: samplers/ sits above
 * it), plus the weighted quantile that this book's #ch-integration uses to
 * find the "halfway" point of an integral. Nothing here allocates; the
 * caller owns every array.
 */
#ifndef MC_INTEGRATE_H
#define MC_INTEGRATE_H

#include <stddef.h>
#include <stdint.h>

#include "mc/quad.h"
#include "mc/rng.h"
#include "mc/stats.h"

/* A sampler of one variable given by its warp and its density: x =
 * sample(u) for u uniform, with density pdf(x) per unit length. The
 * samplers/warp1d.h functions plug in directly. */
typedef struct mc_warp1 {
    double (*sample)(double u);
    double (*pdf)(double x);
} mc_warp1;

/* A uniform double in the open interval (0, 1): the midpoint
 * (u32 + 1/2) 2^-32 of one of 2^32 equal cells. The integrators feed this
 * to warps so that integrands singular at an end of the interval (ln sin x
 * at 0) are never evaluated there; its mean is exactly 1/2. */
static inline double mc_uniform_open(mc_rng *rng)
{
    return ((double)mc_rng_u32(rng) + 0.5) * 0x1p-32;
}

/* One weighted sample of an importance-sampled integral: the point x and
 * its weight f(x) / p(x). */
typedef struct mc_weighted {
    double x, w;
} mc_weighted;

/* An importance sampler over any space (the real line, directions, ...),
 * seen through callbacks so that mc/ needs no type of the layers above:
 * draw puts one point drawn with rng into the caller's storage x and
 * returns the density there (per unit of the measure the integral is
 * over); f returns the integrand at the point in x; seen, unless NULL, is
 * told every point and its weight f / density, in drawing order. */
typedef struct mc_is_sampler {
    double (*draw)(mc_rng *rng, void *ctx, void *x);
    double (*f)(const void *x, void *ctx);
    void (*seen)(const void *x, double weight, void *ctx);
    void *ctx;
} mc_is_sampler;

/* The importance-sampled estimate of the integral of s.f from n >= 1
 * points of s.draw, each drawn into x (storage for one point, of the
 * type the callbacks agree on): the mean of the weights f / density,
 * its variance per sample and its standard error (Welford). A point whose
 * density is 0 weighs 0 and f is not called there: the estimate is
 * unbiased only if f vanishes wherever the density does, which is the
 * caller's contract. The one loop behind mc_integrate_is and the
 * directional integrators of pdf/experiments.h. */
mc_estimate mc_integrate_sampler(mc_is_sampler s, void *x, mc_rng *rng, uint64_t n);

/* The estimate of the integral of f from n >= 1 samples x = w.sample(u),
 * u = mc_uniform_open(rng): the mean of f(x) / w.pdf(x), its variance per
 * sample and its standard error (Welford). A sample with pdf(x) == 0
 * contributes 0: the estimate is unbiased only if f vanishes wherever the
 * density does, which is the caller's contract. If record is not NULL,
 * record[0..n) receives every (x, f(x) / pdf(x)) in drawing order. */
mc_estimate mc_integrate_is(mc_fn1 f, mc_warp1 w, mc_rng *rng, uint64_t n, mc_weighted *record);

/* The same with x uniform on [a, b] (density 1 / (b - a)): the mean of
 * (b - a) f(x). a < b. */
mc_estimate mc_integrate_uniform(mc_fn1 f, double a, double b, mc_rng *rng, uint64_t n,
                                 mc_weighted *record);

/* Orders mc_weighted records by x (for qsort). */
int mc_weighted_compare(const void *a, const void *b);

/* The weighted quantile of s[0..n) (n >= 2, sorted by x, weights >= 0 with
 * a positive sum): the smallest x_k at which the running sum of weights
 * reaches q times the total, 0 < q < 1. With s the record of
 * mc_integrate_is for an integrand f >= 0, this estimates the point x_q
 * where the integral of f from the left end reaches q of the whole (q = 1/2:
 * the "halfway" point of this book's #ch-integration).
 *
 * Its error, by the delta method for an estimating equation: x_q solves
 * G(x) = mean of w_i (1{x_i <= x} - q) = 0, and E G has slope f(x_q) at the
 * root (the integral up to x grows at rate f), so
 * var(x_q) ~ var(w (1{x <= x_q} - q)) / (n f(x_q)^2). f is the integrand
 * (evaluated once, at the estimate). The result has value x_q, variance
 * n var(x_q) and its std_error; value is NaN when s is not sorted, a weight
 * is negative, or the total is not positive; std_error is infinite when
 * f(x_q) == 0. */
mc_estimate mc_weighted_quantile(const mc_weighted *s, size_t n, double q, mc_fn1 f);

#endif /* MC_INTEGRATE_H */
