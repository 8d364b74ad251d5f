/* exercises/sphere.c - chapter 3, "The sphere of directions" (#ch-sphere).
 *
 * WRITE  sample(u1, u2): a unit direction distributed uniformly over the
 *        whole sphere, from two uniforms in [0, 1); which uniform drives
 *        which angle, and u or 1 - u, is yours to choose: every map whose
 *        points are uniform passes;
 *        pdf(w): its density at the unit direction w, PER UNIT SOLID ANGLE.
 * HINT   Archimedes' hat-box theorem: the band of the sphere between the
 *        heights z and z + dz has area 2 pi dz whatever z is, so z = cos
 *        theta is uniform on [-1, 1] (not theta!). The azimuth phi is
 *        uniform on [0, 2 pi). The whole sphere has solid angle 4 pi.
 * JUDGED by the public check (check/check.h) on MCBOX_SPHERE, 10^6 samples
 *        from seed 3101 histogrammed in 50 x 100 cells of (cos theta, phi):
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over every cell; the integral of pdf over the
 *           sphere within 1e-6 of 1; every sample a unit vector;
 *        2. the same points against the law asked for, 1/(4 pi): the
 *           chi-square again, and your pdf at every sample within 1e-6
 *           (relative) of 1/(4 pi); a sampler true to a wrong density of
 *           its own passes 1 and fails here;
 *        3. your pdf against 1/(4 pi) at the centres of 64 x 128 cells of
 *           (cos theta, phi), relative 1e-6 (exact: no statistics).
 *
 * Run:   make exercise NAME=sphere   (figures, verdict and a picture)
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A uniform direction on the unit sphere. */
static vec3 sample(double u1, double u2)
{
    (void)u1, (void)u2;
    return vec3_make(0.0, 0.0, 1.0); /* TODO: always the north pole */
}

/* The density of sample() per unit solid angle. */
static double pdf(vec3 w)
{
    (void)w;
    return 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/sphere.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* The law the exercise asks for: 1 / (4 pi) per steradian everywhere. */
static double uniform_law(const double *x, void *ctx)
{
    (void)x, (void)ctx;
    return 1.0 / (4.0 * MC_PI);
}

static void judge(ex_judge *j)
{
    static const ex_direction_fns fns = {sample, pdf, NULL};
    static const ex_law law = {"the uniform law on the sphere", uniform_law, NULL};
    mcbox_sampler s = ex_direction_sampler(MCBOX_SPHERE, &fns);
    ex_check_sampler_law(j, "sphere", &s, &law, 3101, 1000000);
}

const ex_exercise ex_this = {"sphere", "3 (#ch-sphere)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
