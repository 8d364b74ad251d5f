/* mc/testfn.h - integrands over the unit cube [0,1)^D with closed-form
 * integrals: the referees of the quasi-Monte Carlo experiments.
 *
 * Serves this book's #ch-qmc: the `qmc` program, its figures
 * and the tests estimate these integrals with random and low-discrepancy
 * points, and compare the estimates with the exact values computed here.
 * They differ in the one property that decides how fast a point set
 * converges, smoothness:
 *
 *   pi      4 [x1^2 + x2^2 < 1] in D = 2: the quarter-disc indicator, scaled
 *           so that its integral is pi. Discontinuous across the arc.
 *   smooth  exp(x1 + ... + xD): a smooth product, integral (e - 1)^D.
 *   peak    prod_j 1 / (1 + a_j^2 (x_j - u_j)^2): Genz's product-peak family
 *           (his form divided by prod a_j^-2, so that the peak value is 1);
 *           per dimension (atan(a (1 - u)) + atan(a u)) / a.
 *   gauss   exp(-sum_j a_j^2 (x_j - u_j)^2): Genz's Gaussian family; per
 *           dimension sqrt(pi) / (2 a) (erf(a (1 - u)) + erf(a u)).
 *
 * Genz, "Testing multidimensional integration routines" (1984) [@genz1984] defines the
 * families; the per-dimension integrals are the antiderivatives of
 * 1 / (1 + a^2 t^2) (atan(a t) / a) and of exp(-a^2 t^2)
 * (sqrt(pi) erf(a t) / (2 a)) between t = -u and t = 1 - u.
 */
#ifndef MC_TESTFN_H
#define MC_TESTFN_H

#include <stdbool.h>

/* Largest number of dimensions (inclusive): that of the Sobol table. */
#define MC_TESTFN_MAX_DIM 1024

typedef enum mc_testfn_kind {
    MC_TESTFN_PI,     /* 4 [x1^2 + x2^2 < 1], D = 2 only */
    MC_TESTFN_SMOOTH, /* exp(x1 + ... + xD) */
    MC_TESTFN_PEAK,   /* Genz product peak, parameters a, u */
    MC_TESTFN_GAUSS,  /* Genz Gaussian, parameters a, u */
} mc_testfn_kind;

/* An integrand and its parameters. a[j] > 0 is the sharpness and u[j] in
 * [0, 1] the centre of dimension j (peak and gauss only; the others ignore
 * them). Large (16 KiB): pass it by pointer. */
typedef struct mc_testfn {
    mc_testfn_kind kind;
    unsigned dim;
    double a[MC_TESTFN_MAX_DIM];
    double u[MC_TESTFN_MAX_DIM];
} mc_testfn;

/* Sets *f to the integrand `kind` in `dim` dimensions with the default
 * parameters: a_j = 5 (peak) or 4 (gauss) in every dimension, and centres
 * u_j = 0.2 + 0.6 frac((j + 1) g), g the golden ratio's fractional part,
 * spread over [0.2, 0.8] and off the cube's midpoint, where symmetric point
 * sets would be lucky. Returns false (leaving *f unspecified) when dim is
 * outside 1 .. MC_TESTFN_MAX_DIM, or is not 2 for MC_TESTFN_PI. */
bool mc_testfn_init(mc_testfn *f, mc_testfn_kind kind, unsigned dim);

/* The integrand at x[0 .. f->dim), x in [0, 1]^D. */
double mc_testfn_eval(const mc_testfn *f, const double *x);

/* The exact integral of the integrand over [0, 1]^D. */
double mc_testfn_exact(const mc_testfn *f);

/* The one-dimensional factors of the exact integrals: the integral over
 * [0, 1] of 1 / (1 + a^2 (x - u)^2), and of exp(-a^2 (x - u)^2); a > 0. */
double mc_genz_peak_integral_1d(double a, double u);
double mc_genz_gauss_integral_1d(double a, double u);

#endif /* MC_TESTFN_H */
