/* exercises/sphere.c - chapter 3, "The sphere of directions" (#ch-sphere).
 *
 * WRITE  sample(u1, u2): a unit direction distributed uniformly over the
 *        whole sphere, from two uniforms in [0, 1);
 *        pdf(w): its density at the unit direction w, PER UNIT SOLID ANGLE.
 * HINT   Archimedes' hat-box theorem: the band of the sphere between the
 *        heights z and z + dz has area 2 pi dz whatever z is, so z = cos
 *        theta is uniform on [-1, 1] (not theta!). The azimuth phi is
 *        uniform on [0, 2 pi). The whole sphere has solid angle 4 pi.
 * JUDGED by the public check (check/check.h) on MCBOX_SPHERE: 10^6 samples
 *        from seed 3101 histogrammed in 50 x 100 cells of (cos theta, phi),
 *        Pearson's chi-square against pdf integrated over every cell; the
 *        integral of pdf over the sphere within 1e-6 of 1; every sample a
 *        unit vector.
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

static void judge(ex_judge *j)
{
    static const ex_direction_fns fns = {sample, pdf, NULL};
    mcbox_sampler s = ex_direction_sampler(MCBOX_SPHERE, &fns);
    ex_check_sampler(j, "public check", &s, 3101, 1000000);
}

const ex_exercise ex_this = {"sphere", "3 (#ch-sphere)", EX_VARIANT, judge};
