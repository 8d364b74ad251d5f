/* samplers/warp1d.h - one-dimensional warps by inverting the CDF.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 2 "One
 * Dimensional MC Integration" (this book's #ch-integration): to draw x with
 * density p, push a uniform u through the inverse of the CDF P. Each family
 * here is a trio: _sample(u) = P^-1(u), _pdf(x) = p(x) per unit length (0
 * outside the support, never NaN), _invert(x) = P(x) (so
 * invert(sample(u)) == u). The inputs u are uniform in [0, 1]; the
 * endpoints map to the ends of the support. Used by the integrate_x_sq,
 * inverse_cdf and log_sin programs.
 *
 *   linear     p(x) = x / 2        on [0, 2]   x = sqrt(4 u)     (P = x^2/4)
 *   quadratic  p(x) = 3 x^2 / 8    on [0, 2]   x = 2 cbrt(u)     (P = x^3/8)
 *   sine       p(x) = sin(x) / 2   on [0, pi]  x = acos(1 - 2u)  (P = (1 - cos x)/2)
 *   log_ends   p(x) = -ln(2 d / pi) / pi on [0, pi], d = min(x, pi - x):
 *              infinite, like ln(sin x), at both ends (see below)
 *
 * The quadratic inverse is cbrt(8 u) = 2 cbrt(u). Slipping to 8 cbrt(u)
 * (the book's code does) spreads the samples over [0, 8]
 * yet keeps zero variance, because the formula 3x^2/8 still cancels the
 * integrand x^2 exactly: the estimate stays 8/3 and hides the bug. Only a
 * domain check on the samples finds it (tests/test_integrate.c does).
 */
#ifndef SMP_WARP1D_H
#define SMP_WARP1D_H

/* x = sqrt(4 u) in [0, 2], density x / 2. u in [0, 1]. */
double smp_linear_sample(double u);
/* x / 2 per unit length on [0, 2], 0 elsewhere. */
double smp_linear_pdf(double x);
/* The CDF x^2 / 4 (0 below 0, 1 above 2): the u that sample maps to x. */
double smp_linear_invert(double x);

/* x = 2 cbrt(u) in [0, 2], density 3 x^2 / 8. u in [0, 1]. */
double smp_quadratic_sample(double u);
/* 3 x^2 / 8 per unit length on [0, 2], 0 elsewhere. */
double smp_quadratic_pdf(double x);
/* The CDF x^3 / 8 (clamped to [0, 1] outside [0, 2]). */
double smp_quadratic_invert(double x);

/* x = acos(1 - 2 u) in [0, pi], density sin(x) / 2: the polar angle of a
 * uniformly distributed direction. u in [0, 1]. */
double smp_sine_sample(double u);
/* sin(x) / 2 per unit length on [0, pi], 0 elsewhere. */
double smp_sine_pdf(double x);
/* The CDF (1 - cos x) / 2 (clamped to [0, 1] outside [0, pi]). */
double smp_sine_invert(double x);

/* A density for integrands with logarithmic singularities at both ends of
 * [0, pi], such as ln(sin x): with d = min(x, pi - x) the distance to the
 * nearer end, p(x) = -ln(2 d / pi) / pi. Each half carries probability 1/2;
 * on the left half t = 2 x / pi has density -ln t on (0, 1] (the density
 * of a product of two uniforms) and CDF t (1 - ln t), which sample inverts
 * numerically to about 1e-15. Because -ln(sin x) / p(x) stays between 0
 * and pi, the importance-sampling estimator of the integral of ln(sin x)
 * has a bounded weight, hence finite (and small) variance; a density that
 * vanishes at the ends, such as sin(x) / 2, would make it infinite.
 * u in [0, 1]; u = 0 and u = 1 give the ends 0 and pi, where the density is
 * infinite. */
double smp_log_ends_sample(double u);
/* -ln(2 min(x, pi - x) / pi) / pi per unit length on [0, pi] (+infinity at
 * the two ends, 0 at pi/2), 0 outside. */
double smp_log_ends_pdf(double x);
/* The CDF: (t (1 - ln t)) / 2 on the left half with t = 2 x / pi, and
 * symmetrically 1 - (that of pi - x) on the right half. */
double smp_log_ends_invert(double x);

#endif /* SMP_WARP1D_H */
