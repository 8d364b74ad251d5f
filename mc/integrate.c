/* mc/integrate.c - importance-sampled 1D integrals and weighted quantiles. */
#include "mc/integrate.h"

#include <math.h>

mc_estimate mc_integrate_is(mc_fn1 f, mc_warp1 w, mc_rng *rng, uint64_t n, mc_weighted *record)
{
    mc_welford acc = mc_welford_init();
    for (uint64_t i = 0; i < n; i++) {
        double x = w.sample(mc_uniform_open(rng));
        double p = w.pdf(x);
        /* The convention 0/0 = 0: where the density is 0 no sample should
         * fall, and one that does must not turn the mean into NaN. */
        double weight = p > 0.0 ? f.f(x, f.params) / p : 0.0;
        mc_welford_add(&acc, weight);
        if (record) {
            record[i].x = x;
            record[i].w = weight;
        }
    }
    return mc_welford_estimate(&acc);
}

mc_estimate mc_integrate_uniform(mc_fn1 f, double a, double b, mc_rng *rng, uint64_t n,
                                 mc_weighted *record)
{
    mc_welford acc = mc_welford_init();
    double width = b - a;
    for (uint64_t i = 0; i < n; i++) {
        double x = a + width * mc_uniform_open(rng);
        double weight = width * f.f(x, f.params);
        mc_welford_add(&acc, weight);
        if (record) {
            record[i].x = x;
            record[i].w = weight;
        }
    }
    return mc_welford_estimate(&acc);
}

int mc_weighted_compare(const void *a, const void *b)
{
    double xa = ((const mc_weighted *)a)->x, xb = ((const mc_weighted *)b)->x;
    return (xa > xb) - (xa < xb);
}

mc_estimate mc_weighted_quantile(const mc_weighted *s, size_t n, double q, mc_fn1 f)
{
    mc_estimate bad = {n, nan(""), nan(""), nan("")};
    double total = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (!(s[i].w >= 0.0) || (i > 0 && s[i].x < s[i - 1].x))
            return bad;
        total += s[i].w;
    }
    if (n < 2 || !(total > 0.0) || !(q > 0.0 && q < 1.0))
        return bad;
    /* The first k whose running sum reaches q total. */
    double target = q * total, run = 0.0;
    size_t k = 0;
    for (; k < n - 1; k++) {
        run += s[k].w;
        if (run >= target)
            break;
    }
    double xq = s[k].x;
    /* Sample variance of g_i = w_i (1{x_i <= xq} - q), by Welford. */
    mc_welford g = mc_welford_init();
    for (size_t i = 0; i < n; i++)
        mc_welford_add(&g, s[i].w * ((s[i].x <= xq ? 1.0 : 0.0) - q));
    double slope = f.f(xq, f.params);
    double var = slope != 0.0 ? mc_welford_variance(&g) / (slope * slope) : HUGE_VAL;
    mc_estimate e = {n, xq, var, sqrt(var / (double)n)};
    return e;
}
