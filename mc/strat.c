/* mc/strat.c - jittered 1D and 2D sample sets for any count. */
#include "mc/strat.h"

#include <math.h>

/* BEGIN SNIPPET strat_grid */
void mc_strat_grid(size_t n, size_t *sx, size_t *sy)
{
    /* sqrt in double can be off by one near large perfect squares; correct
     * it so that sx is exactly floor(sqrt n). */
    size_t s = (size_t)sqrt((double)n);
    while (s > 0 && s * s > n)
        s--;
    while ((s + 1) * (s + 1) <= n)
        s++;
    if (s == 0)
        s = 1;
    *sx = s;
    *sy = n / s;
}
/* END SNIPPET strat_grid */

/* A cell product (i + u) / n may round up to 1.0: for the last cell once
 * n >= 2^21, where n - 1 + (1 - 2^-32) rounds to n. Keep the documented
 * half-open range. */
static double below_one(double x)
{
    return x >= 1.0 ? nextafter(1.0, 0.0) : x;
}

void mc_jitter_1d(mc_rng *rng, size_t n, double *out)
{
    double inv_n = 1.0 / (double)n;
    for (size_t i = 0; i < n; i++)
        out[i] = below_one(((double)i + mc_rng_uniform(rng)) * inv_n);
}

/* BEGIN SNIPPET jitter_2d */
void mc_jitter_2d(mc_rng *rng, size_t n, double *xy)
{
    size_t sx, sy;
    mc_strat_grid(n, &sx, &sy);
    double inv_x = 1.0 / (double)sx, inv_y = 1.0 / (double)sy;
    size_t k = 0;
    for (size_t j = 0; j < sy; j++) {
        for (size_t i = 0; i < sx; i++, k++) {
            xy[2 * k] = ((double)i + mc_rng_uniform(rng)) * inv_x;
            xy[2 * k + 1] = ((double)j + mc_rng_uniform(rng)) * inv_y;
        }
    }
    /* The n - sx sy points beyond the grid, uniform. */
    for (double *p = xy + 2 * k; p < xy + 2 * n; p += 2) {
        p[0] = mc_rng_uniform(rng);
        p[1] = mc_rng_uniform(rng);
    }
    for (k = 0; k < 2 * n; k++)
        xy[k] = below_one(xy[k]);
}
/* END SNIPPET jitter_2d */
