/* exercises/hemisphere.c - chapter 5, "Generating random directions"
 * (#ch-directions): the uniform hemisphere, with its inverse.
 *
 * WRITE  sample(u1, u2): a unit direction distributed uniformly over the
 *        hemisphere z >= 0, from two uniforms in [0, 1) (say u1 for the
 *        azimuth phi = 2 pi u1, u2 for the height; the other way round,
 *        or 1 - u for u, passes too: the judge asks for the law, not
 *        for one map);
 *        pdf(w): its density PER UNIT SOLID ANGLE (0 below the horizon);
 *        invert(w, u): the (u1, u2) that YOUR sample() maps to w: the
 *        inverse pins the map you chose, and must undo it.
 * HINT   As on the sphere, the height z = cos theta is uniform (hat-box
 *        theorem), now on [0, 1]: z = 1 - u2 keeps z > 0. The hemisphere
 *        has solid angle 2 pi. For the inverse, atan2(y, x) gives phi in
 *        (-pi, pi]: bring it to [0, 2 pi) before dividing by 2 pi.
 * JUDGED by the public check (check/check.h) on MCBOX_HEMISPHERE, 10^6
 *        samples from seed 3201 in 50 x 100 cells of (cos theta, phi):
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over each cell; the integral of pdf within 1e-6 of
 *           1; |invert(sample(u)) - u| <= 1e-6 for every sample (the round
 *           trip); every sample a unit vector with z >= 0;
 *        2. the same points against the law asked for, 1/(2 pi) on z >= 0:
 *           the chi-square again, and your pdf at every sample within 1e-6
 *           (relative) of it;
 *        3. your pdf against that law at the centres of 64 x 128 cells of
 *           (cos theta, phi) over the whole sphere (0 below the horizon),
 *           relative 1e-6 (exact: no statistics).
 *
 * Run:   make exercise NAME=hemisphere
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A uniform direction on the hemisphere about +z. */
static vec3 sample(double u1, double u2)
{
    (void)u1, (void)u2;
    return vec3_make(0.0, 0.0, 1.0); /* TODO */
}

/* The density of sample() per unit solid angle. */
static double pdf(vec3 w)
{
    (void)w;
    return 0.0; /* TODO */
}

/* The uniforms (u[0], u[1]) that sample() maps to the direction w. */
static void invert(vec3 w, double u[2])
{
    (void)w;
    u[0] = u[1] = 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/hemisphere.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* The law the exercise asks for: 1 / (2 pi) per steradian above the
 * horizon, 0 below. */
static double uniform_law(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] >= 0.0 ? 1.0 / (2.0 * MC_PI) : 0.0;
}

static void judge(ex_judge *j)
{
    static const ex_direction_fns fns = {sample, pdf, invert};
    static const ex_law law = {"the uniform law on the hemisphere", uniform_law, NULL};
    mcbox_sampler s = ex_direction_sampler(MCBOX_HEMISPHERE, &fns);
    ex_check_sampler_law(j, "hemisphere", &s, &law, 3201, 1000000);
}

const ex_exercise ex_this = {"hemisphere", "5 (#ch-directions)", EX_VARIANT, judge,
                             EX_KIND,      EX_INTENDED};
