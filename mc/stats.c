/* mc/stats.c - Welford accumulation, pairwise merge, z-scores. */
#include "mc/stats.h"

#include <math.h>

#include "mc/constants.h"

mc_welford mc_welford_init(void)
{
    mc_welford w = {0u, 0.0, 0.0};
    return w;
}

/* BEGIN SNIPPET welford_add */
void mc_welford_add(mc_welford *w, double x)
{
    /* Welford (1962) [@welford1962]: update the mean by delta / n, then accumulate
     * delta * (x - new mean), which equals (n-1)/n delta^2 without forming
     * a difference of large squares. */
    w->n += 1u;
    double delta = x - w->mean;
    w->mean += delta / (double)w->n;
    w->m2 += delta * (x - w->mean);
}
/* END SNIPPET welford_add */

mc_welford mc_welford_merge(mc_welford a, mc_welford b)
{
    if (a.n == 0u)
        return b;
    if (b.n == 0u)
        return a;
    /* Chan, Golub and LeVeque (1979) [@chan1979]: the combined M2 is the sum of the
     * parts plus the between-group term delta^2 na nb / n. */
    mc_welford r;
    double na = (double)a.n, nb = (double)b.n;
    r.n = a.n + b.n;
    double n = (double)r.n;
    double delta = b.mean - a.mean;
    r.mean = a.mean + delta * (nb / n);
    r.m2 = a.m2 + b.m2 + delta * delta * (na / n) * nb;
    return r;
}

double mc_welford_variance(const mc_welford *w)
{
    return w->n < 2u ? 0.0 : w->m2 / (double)(w->n - 1u);
}

double mc_welford_std_error(const mc_welford *w)
{
    return w->n < 2u ? 0.0 : sqrt(mc_welford_variance(w) / (double)w->n);
}

mc_estimate mc_welford_estimate(const mc_welford *w)
{
    mc_estimate e = {w->n, w->mean, mc_welford_variance(w), mc_welford_std_error(w)};
    return e;
}

/* BEGIN SNIPPET z_score_pvalue */
double mc_z_score(double estimate, double exact, double std_error)
{
    double diff = estimate - exact;
    if (std_error > 0.0)
        return diff / std_error;
    if (diff == 0.0)
        return 0.0;
    return diff > 0.0 ? HUGE_VAL : -HUGE_VAL;
}

double mc_z_pvalue(double z)
{
    return erfc(fabs(z) / MC_SQRT2);
}
/* END SNIPPET z_score_pvalue */
