/* samplers/warp1d.c - inverse-CDF warps of one variable.
 *
 * Every sampler follows the same recipe: p normalized over its support,
 * P(x) = integral of p from the left end to x, and x = P^-1(u). The
 * derivations are one line each and sit beside the code. */
#include "samplers/warp1d.h"

#include <math.h>

#include "mc/constants.h"

static double clamp01(double u)
{
    return u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
}

/* BEGIN SNIPPET warp_linear */
/* --- linear: p = x/2 on [0, 2], P = x^2/4, so x = sqrt(4u) ------------- */

double smp_linear_sample(double u)
{
    return sqrt(4.0 * clamp01(u));
}

double smp_linear_pdf(double x)
{
    return x >= 0.0 && x <= 2.0 ? 0.5 * x : 0.0;
}

double smp_linear_invert(double x)
{
    return x <= 0.0 ? 0.0 : (x >= 2.0 ? 1.0 : 0.25 * x * x);
}
/* END SNIPPET warp_linear */

/* BEGIN SNIPPET warp_quadratic */
/* --- quadratic: p = 3x^2/8 on [0, 2], P = x^3/8, so x = cbrt(8u) = 2 cbrt(u) */

double smp_quadratic_sample(double u)
{
    return 2.0 * cbrt(clamp01(u));
}

double smp_quadratic_pdf(double x)
{
    return x >= 0.0 && x <= 2.0 ? 0.375 * x * x : 0.0;
}

double smp_quadratic_invert(double x)
{
    return x <= 0.0 ? 0.0 : (x >= 2.0 ? 1.0 : 0.125 * x * x * x);
}
/* END SNIPPET warp_quadratic */

/* BEGIN SNIPPET warp_sine */
/* --- sine: p = sin(x)/2 on [0, pi], P = (1 - cos x)/2, x = acos(1 - 2u) - */

double smp_sine_sample(double u)
{
    return acos(1.0 - 2.0 * clamp01(u));
}

double smp_sine_pdf(double x)
{
    return x >= 0.0 && x <= MC_PI ? 0.5 * sin(x) : 0.0;
}

double smp_sine_invert(double x)
{
    /* 1 - cos x = 2 sin^2(x/2) avoids the cancellation of 1 - cos x near 0,
     * so small u round-trip to full relative precision. */
    if (x <= 0.0)
        return 0.0;
    if (x >= MC_PI)
        return 1.0;
    double s = sin(0.5 * x);
    return s * s;
}
/* END SNIPPET warp_sine */

/* --- log_ends ----------------------------------------------------------- */

/* The t in [0, 1] with t (1 - ln t) = v, for v in [0, 1]: the inverse of
 * the CDF of the density -ln t. With t = e^-s it is the root of
 * h(s) = s - ln(1 + s) = w, w = -ln v (the survival function of a
 * Gamma(2, 1) variable). h is increasing and convex on s >= 0, so Newton's
 * method started at an s0 with h(s0) >= w falls monotonically onto the
 * root. s0 = 2w + sqrt(2w) qualifies: with r = sqrt(2w),
 * h(s0) - w = r^2/2 + r - ln(1 + r + r^2), which is 0 at r = 0 and has
 * derivative (2r^2 + r^3) / (1 + r + r^2) >= 0. When s is small the
 * difference s - log1p(s) ~ s^2/2 has relative error ~ eps / s, which moves
 * s by ~ eps and t = e^-s by ~ eps: full absolute precision in t. */
static double neglog_quantile(double v)
{
    if (v <= 0.0)
        return 0.0;
    if (v >= 1.0)
        return 1.0;
    double w = -log(v);
    double s = 2.0 * w + sqrt(2.0 * w);
    for (int k = 0; k < 100; k++) {
        double step = (s - log1p(s) - w) * (1.0 + s) / s;
        s -= step;
        /* The residual carries a rounding error of about eps (1 + s), so
         * steps below 1e-15 (1 + s) are noise: s (hence t) is then as good
         * as it gets. The negated test also stops on a NaN. */
        if (!(fabs(step) > 1e-15 * (1.0 + s)))
            break;
    }
    return exp(-s);
}

/* t (1 - ln t): the CDF of the density -ln t on (0, 1]. */
static double neglog_cdf(double t)
{
    return t <= 0.0 ? 0.0 : (t >= 1.0 ? 1.0 : t * (1.0 - log(t)));
}

/* BEGIN SNIPPET log_ends_sample_pdf */
double smp_log_ends_sample(double u)
{
    /* The left half takes u < 1/2 (t = P^-1(2u), x = t pi/2), the right half
     * mirrors it (x = pi - pi/2 P^-1(2 - 2u)), so x increases with u. */
    u = clamp01(u);
    if (u < 0.5)
        return MC_PI_2 * neglog_quantile(2.0 * u);
    return MC_PI - MC_PI_2 * neglog_quantile(2.0 - 2.0 * u);
}

double smp_log_ends_pdf(double x)
{
    if (!(x >= 0.0 && x <= MC_PI))
        return 0.0;
    double d = x < MC_PI_2 ? x : MC_PI - x;
    if (d <= 0.0)
        return HUGE_VAL;
    /* d / (pi/2) can exceed 1 by one rounding at x = pi/2: keep p >= 0. */
    double p = -log(d / MC_PI_2) * MC_INV_PI;
    return p > 0.0 ? p : 0.0;
}
/* END SNIPPET log_ends_sample_pdf */

double smp_log_ends_invert(double x)
{
    if (x <= 0.0)
        return 0.0;
    if (x >= MC_PI)
        return 1.0;
    if (x <= MC_PI_2)
        return 0.5 * neglog_cdf(x / MC_PI_2);
    return 1.0 - 0.5 * neglog_cdf((MC_PI - x) / MC_PI_2);
}
