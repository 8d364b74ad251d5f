/* mc/trig.h - sine and cosine of a whole turn fraction, sin(2 pi u) and
 * cos(2 pi u), for the azimuth of every direction sampler.
 *
 * Every directional warp of this book's #ch-sphere, #ch-directions and
 * #ch-onb (after Shirley, "Ray Tracing: The Rest of Your Life" (v1.123),
 * the second chapter 2 and chapters 5 and 6) draws its azimuth as
 * phi = 2 pi u with u uniform in [0, 1), and then needs cos phi and sin phi.
 * The libm route (sin and cos of the product 2 pi u) costs two general
 * argument reductions per direction and was the largest single item of the
 * renderer's profile after the geometry. Taking u itself is both cheaper and
 * more accurate: 4 u splits exactly into a quadrant and a remainder, so the
 * reduction is exact and only the final polynomial rounds, whereas
 * sin(2 pi * u) first rounds 2 pi u (up to 4.4e-16 absolute near 2 pi).
 */
#ifndef MC_TRIG_H
#define MC_TRIG_H

#include <math.h>

#include "mc/constants.h"

/* *s = sin(2 pi u) and *c = cos(2 pi u) for finite u with |u| < 2^50 (the
 * samplers pass u in [0, 1)). Absolute error below 2.5e-16 against the exact
 * values for the exact u (tests/test_trig.c checks 4e-16 on a dense grid and
 * random u); quarter turns are exact (u = 0, 1/4, 1/2, 3/4 give 0 and +-1). */
static inline void mc_sincos_turn(double u, double *s, double *c)
{
    /* 2 pi u = (pi / 2)(k + f) with k the nearest integer to 4 u and
     * f = 4 u - k in [-1/2, 1/2]. Multiplying by 4 and subtracting an
     * integer this close are both exact in binary floating point, so the
     * only rounding before the polynomials is x = f pi / 2 (half an ulp of
     * x <= pi / 4, plus pi / 2's own 6e-17 relative error). */
    double t = 4.0 * u;
    long long k = (long long)(t + copysign(0.5, t));
    double x = (t - (double)k) * MC_PI_2;
    double z = x * x;
    /* Taylor series on |x| <= pi / 4 (a hair more when t + 1/2 rounds up):
     * the first omitted terms, x^19 / 19! for sin and x^18 / 18! for cos,
     * are below 3e-18 there, far under the final rounding. Horner in
     * z = x^2; the leading terms x and 1 are added last so that only the
     * small corrections carry the polynomial's rounding. */
    double ps = 1.0 / 355687428096000.0; /* 1/17! */
    ps = ps * z - 1.0 / 1307674368000.0; /* 1/15! */
    ps = ps * z + 1.0 / 6227020800.0;    /* 1/13! */
    ps = ps * z - 1.0 / 39916800.0;      /* 1/11! */
    ps = ps * z + 1.0 / 362880.0;        /* 1/9! */
    ps = ps * z - 1.0 / 5040.0;          /* 1/7! */
    ps = ps * z + 1.0 / 120.0;           /* 1/5! */
    ps = ps * z - 1.0 / 6.0;             /* 1/3! */
    double pc = 1.0 / 20922789888000.0;  /* 1/16! */
    pc = pc * z - 1.0 / 87178291200.0;   /* 1/14! */
    pc = pc * z + 1.0 / 479001600.0;     /* 1/12! */
    pc = pc * z - 1.0 / 3628800.0;       /* 1/10! */
    pc = pc * z + 1.0 / 40320.0;         /* 1/8! */
    pc = pc * z - 1.0 / 720.0;           /* 1/6! */
    pc = pc * z + 1.0 / 24.0;            /* 1/4! */
    pc = pc * z - 0.5;                   /* 1/2! */
    double sx = x + x * z * ps, cx = 1.0 + z * pc;
    /* Turning by k quarter turns maps (cos, sin) to (-sin, cos) per quarter:
     * odd quadrants swap the two, quadrants 2 and 3 negate the sine,
     * quadrants 1 and 2 the cosine. k & 3 is k mod 4 for negative k too in
     * two's complement. The quadrant is random in the samplers, so it picks
     * by indexing and multiplies by +-1 (exact) rather than branching: a
     * mispredicted branch would cost more than the polynomials. */
    unsigned q = (unsigned)k & 3u, odd = q & 1u;
    const double v[2] = {sx, cx};
    *s = v[odd] * (1.0 - (double)(q & 2u));
    *c = v[odd ^ 1u] * (1.0 - (double)((q + 1u) & 2u));
}

#endif /* MC_TRIG_H */
