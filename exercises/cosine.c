/* exercises/cosine.c - chapters 4 and 5, "Light scattering and importance
 * sampling materials" (#ch-scattering): the cosine-weighted hemisphere.
 *
 * WRITE  sample(u1, u2): a unit direction on the hemisphere z >= 0 whose
 *        density is proportional to cos theta = z, from two uniforms in
 *        [0, 1) (say phi = 2 pi u1 and u2 for the polar angle; the other
 *        way round, 1 - u for u, or another map such as a uniform disc
 *        point lifted to the hemisphere passes too: the judge asks for the
 *        law, not for one map);
 *        pdf(w): its density PER UNIT SOLID ANGLE (0 below the horizon);
 *        invert(w, u): the (u1, u2) that YOUR sample() maps to w: the
 *        inverse pins the map you chose, and must undo it.
 * HINT   The density is c cos theta with c fixed by integrating over the
 *        hemisphere: the integral of cos theta d omega is pi. The CDF of
 *        the polar angle is 1 - cos^2 theta = sin^2 theta, so
 *        cos theta = sqrt(1 - u2) (a uniform point of the disc, lifted).
 *        In the inverse, 1 - z^2 is x^2 + y^2, which stays accurate near
 *        the pole.
 * JUDGED by the public check (check/check.h) on MCBOX_HEMISPHERE, 10^6
 *        samples from seed 3301 in 50 x 100 cells of (cos theta, phi):
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over each cell; the integral of pdf within 1e-6 of
 *           1; the round trip |invert(sample(u)) - u| <= 1e-6; every
 *           sample a unit vector;
 *        2. the same points against the cosine law cos(theta) / pi the
 *           exercise asks for: the chi-square again, and your pdf at every
 *           sample within 1e-6 (relative) of it. The uniform hemisphere
 *           with its own density 1/(2 pi) and its own inverse passes 1 and
 *           fails here;
 *        3. your pdf against cos(theta) / pi at the centres of 64 x 128
 *           cells of (cos theta, phi) over the whole sphere (0 below the
 *           horizon), relative 1e-6 (exact: no statistics).
 *
 * Run:   make exercise NAME=cosine
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A cosine-weighted direction on the hemisphere about +z. */
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
#include "exercises/fixtures/cosine.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* The law the exercise asks for: cos(theta) / pi per steradian above the
 * horizon, 0 below. */
static double cosine_law(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] > 0.0 ? x[2] / MC_PI : 0.0;
}

static void judge(ex_judge *j)
{
    static const ex_direction_fns fns = {sample, pdf, invert};
    static const ex_law law = {"the cosine law", cosine_law, NULL};
    mcbox_sampler s = ex_direction_sampler(MCBOX_HEMISPHERE, &fns);
    ex_check_sampler_law(j, "cosine", &s, &law, 3301, 1000000);
}

const ex_exercise ex_this = {"cosine", "4-5 (#ch-scattering)", EX_VARIANT, judge,
                             EX_KIND,  EX_INTENDED};
