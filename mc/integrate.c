/* mc/integrate.c - importance-sampled 1D integrals and weighted quantiles. */
#include "mc/integrate.h"

#include <math.h>

/* BEGIN SNIPPET integrate_sampler */
mc_estimate mc_integrate_sampler(mc_is_sampler s, void *x, mc_rng *rng, uint64_t n)
{
    mc_welford acc = mc_welford_init();
    for (uint64_t i = 0; i < n; i++) {
        double p = s.draw(rng, s.ctx, x);
        /* The convention 0/0 = 0: where the density is 0 no sample should
         * fall, and one that does must not turn the mean into NaN. */
        double weight = p > 0.0 ? s.f(x, s.ctx) / p : 0.0;
        mc_welford_add(&acc, weight);
        if (s.seen)
            s.seen(x, weight, s.ctx);
    }
    return mc_welford_estimate(&acc);
}
/* END SNIPPET integrate_sampler */

/* mc_integrate_is as an mc_is_sampler over doubles. */
typedef struct warp1_ctx {
    mc_fn1 f;
    mc_warp1 w;
    mc_weighted *record;
    uint64_t i;
} warp1_ctx;

static double warp1_draw(mc_rng *rng, void *ctx, void *x)
{
    const warp1_ctx *c = ctx;
    double *px = x;
    *px = c->w.sample(mc_uniform_open(rng));
    return c->w.pdf(*px);
}

static double warp1_f(const void *x, void *ctx)
{
    const warp1_ctx *c = ctx;
    return c->f.f(*(const double *)x, c->f.params);
}

static void warp1_seen(const void *x, double weight, void *ctx)
{
    warp1_ctx *c = ctx;
    c->record[c->i].x = *(const double *)x;
    c->record[c->i].w = weight;
    c->i++;
}

mc_estimate mc_integrate_is(mc_fn1 f, mc_warp1 w, mc_rng *rng, uint64_t n, mc_weighted *record)
{
    warp1_ctx c = {f, w, record, 0u};
    mc_is_sampler s = {warp1_draw, warp1_f, record ? warp1_seen : NULL, &c};
    double x;
    return mc_integrate_sampler(s, &x, rng, n);
}

/* BEGIN SNIPPET integrate_uniform */
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
/* END SNIPPET integrate_uniform */

int mc_weighted_compare(const void *a, const void *b)
{
    double xa = ((const mc_weighted *)a)->x, xb = ((const mc_weighted *)b)->x;
    return (xa > xb) - (xa < xb);
}

/* BEGIN SNIPPET weighted_quantile */
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
/* END SNIPPET weighted_quantile */
