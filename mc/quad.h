/* mc/quad.h - deterministic quadrature, the referee of the Monte Carlo
 * estimates.
 *
 * Two uses: exact reference values for integrals with no closed form, and
 * the expected counts of the chi-square tests (a sampler's pdf integrated
 * over each histogram cell, never just evaluated at the cell centre). The
 * work is GSL's adaptive Gauss-Kronrod with extrapolation (QAGS), which also
 * copes with integrable endpoint singularities such as log(sin x) at 0.
 * Serves this book's #ch-integration and every sampler.
 *
 * Allocation: GSL's adaptive rules need a workspace. It is created once by
 * mc_quad_create and reused; nothing else in mc/ allocates.
 */
#ifndef MC_QUAD_H
#define MC_QUAD_H

#include <stddef.h>

/* A real function of one variable with its parameters, GSL style. */
typedef struct mc_fn1 {
    double (*f)(double x, void *params);
    void *params;
} mc_fn1;

/* A real function of two variables with its parameters. */
typedef struct mc_fn2 {
    double (*f)(double x, double y, void *params);
    void *params;
} mc_fn2;

/* Workspaces for one 1D or one nested 2D integration at a time (not to be
 * shared between threads). */
typedef struct mc_quad mc_quad;

/* Accuracy targets of every integration: |error| <= max(abs, rel |I|). */
#define MC_QUAD_EPSABS 1e-12
#define MC_QUAD_EPSREL 1e-11

/* Workspaces for up to `limit` subintervals per level (1000 is ample).
 * Returns NULL when out of memory. Switches GSL's aborting error handler
 * off, once per process (mc/gsl_quiet.h), so failures come back as status
 * codes; safe to call from OpenMP threads. */
mc_quad *mc_quad_create(size_t limit);

/* Frees what mc_quad_create made; NULL is a no-op. */
void mc_quad_destroy(mc_quad *q);

/* The integral of fn over [a, b] (a < b, finite). *abserr, if not NULL,
 * receives GSL's error estimate. Returns 0 on success and a GSL status code
 * when the requested accuracy was not reached (the best value is still
 * stored in *result). */
int mc_quad_1d(mc_quad *q, mc_fn1 fn, double a, double b, double *result, double *abserr);

/* The integral of fn over the rectangle [x0, x1] x [y0, y1] as an outer
 * integral over x of inner integrals over y, both adaptive. Same return
 * convention as mc_quad_1d; the error estimate is the outer one plus the
 * largest inner one times the width in x. */
int mc_quad_2d(mc_quad *q, mc_fn2 fn, double x0, double x1, double y0, double y1, double *result,
               double *abserr);

/* The n-point Gauss-Legendre rule on [a, b] (n >= 1): nodes x[0 .. n) and
 * weights w[0 .. n), exact for polynomials of degree 2n - 1. For densities
 * that can only be evaluated in batches (behind a pipe), where an adaptive
 * rule's one-at-a-time requests would cost a round trip each. Returns 0, or
 * -1 when out of memory. */
int mc_quad_gauss_legendre(int n, double a, double b, double *x, double *w);

#endif /* MC_QUAD_H */
