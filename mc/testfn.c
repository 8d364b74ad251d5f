/* mc/testfn.c - integrands of the unit cube with closed-form integrals. */
#include "mc/testfn.h"

#include <math.h>

#include "mc/constants.h"

bool mc_testfn_init(mc_testfn *f, mc_testfn_kind kind, unsigned dim)
{
    if (dim < 1 || dim > MC_TESTFN_MAX_DIM || (kind == MC_TESTFN_PI && dim != 2))
        return false;
    f->kind = kind;
    f->dim = dim;
    /* The fractional parts of (j + 1) g never repeat and fill [0, 1)
     * evenly (Weyl), so every dimension gets its own centre. */
    const double g = 0.6180339887498948482;
    for (unsigned j = 0; j < dim; j++) {
        double w = (double)(j + 1) * g;
        f->a[j] = kind == MC_TESTFN_GAUSS ? 4.0 : 5.0;
        f->u[j] = 0.2 + 0.6 * (w - floor(w));
    }
    return true;
}

/* BEGIN SNIPPET testfn_genz */
double mc_genz_peak_integral_1d(double a, double u)
{
    /* d/dt atan(a t) / a = 1 / (1 + a^2 t^2), with t = x - u from -u to 1 - u. */
    return (atan(a * (1.0 - u)) + atan(a * u)) / a;
}

double mc_genz_gauss_integral_1d(double a, double u)
{
    /* d/dt erf(a t) = (2 a / sqrt(pi)) exp(-a^2 t^2), t = x - u as above. */
    return sqrt(MC_PI) / (2.0 * a) * (erf(a * (1.0 - u)) + erf(a * u));
}

double mc_testfn_eval(const mc_testfn *f, const double *x)
{
    double v = 1.0, s = 0.0;
    switch (f->kind) {
    case MC_TESTFN_PI:
        return x[0] * x[0] + x[1] * x[1] < 1.0 ? 4.0 : 0.0;
    case MC_TESTFN_SMOOTH:
        for (unsigned j = 0; j < f->dim; j++)
            s += x[j];
        return exp(s);
    case MC_TESTFN_PEAK:
        for (unsigned j = 0; j < f->dim; j++) {
            double t = f->a[j] * (x[j] - f->u[j]);
            v /= 1.0 + t * t;
        }
        return v;
    case MC_TESTFN_GAUSS:
        for (unsigned j = 0; j < f->dim; j++) {
            double t = f->a[j] * (x[j] - f->u[j]);
            s += t * t;
        }
        return exp(-s);
    }
    return 0.0;
}

double mc_testfn_exact(const mc_testfn *f)
{
    /* Every integrand but pi is a product of one-dimensional factors (the
     * exponential of a sum is one), so its integral is the product of the
     * factors' integrals. */
    double v = 1.0;
    for (unsigned j = 0; j < f->dim; j++) {
        switch (f->kind) {
        case MC_TESTFN_PI:
            return MC_PI;
        case MC_TESTFN_SMOOTH:
            v *= expm1(1.0); /* the integral of e^x over [0, 1] */
            break;
        case MC_TESTFN_PEAK:
            v *= mc_genz_peak_integral_1d(f->a[j], f->u[j]);
            break;
        case MC_TESTFN_GAUSS:
            v *= mc_genz_gauss_integral_1d(f->a[j], f->u[j]);
            break;
        }
    }
    return v;
}
/* END SNIPPET testfn_genz */
