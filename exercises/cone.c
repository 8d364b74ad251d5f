/* exercises/cone.c - chapter 8, "Sampling lights directly" (#ch-lights):
 * uniform directions in a cone, the building block of sampling a sphere
 * light.
 *
 * WRITE  sample(u1, u2, cos_max): a unit direction distributed uniformly
 *        (in solid angle) over the cone of directions about +z whose
 *        angle to +z is at most theta_max, cos theta_max = cos_max in
 *        [-1, 1) (say phi = 2 pi u1, u2 for the polar angle; the other
 *        way round, or 1 - u for u, passes too: the judge asks for the
 *        law, not for one map);
 *        pdf(w, cos_max): its density PER UNIT SOLID ANGLE, 0 outside.
 * HINT   Solid angle is linear in cos theta (Archimedes again): cos theta
 *        is uniform on [cos_max, 1]. The cone's solid angle is
 *        2 pi (1 - cos_max): a cap of height h = 1 - cos_max on the unit
 *        sphere. cos_max = 0 is the hemisphere, -1 the whole sphere.
 * JUDGED by the public check (check/check.h), twice: on the catalog's
 *        "cone" row with cos_max = 0.385 (its chart starts at the rim, so
 *        a direction outside the cone counts as outside the domain), and on
 *        MCBOX_SPHERE with cos_max = -0.52 (the whole sphere is charted,
 *        so pdf must vanish outside the cone for its integral to be 1).
 *        Each, 10^6 samples (seeds 8101 and 8102) in 50 x 100 cells:
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over each cell, the integral of pdf within 1e-6 of
 *           1, every sample a unit vector;
 *        2. the same points against the law asked for, 1/(2 pi (1 -
 *           cos_max)) inside the cone and 0 outside: the chi-square again,
 *           and your pdf at every sample within 1e-6 (relative) of it;
 *        3. your pdf against that law at the centres of 64 x 128 cells of
 *           (cos theta, phi) over the whole sphere, relative 1e-6.
 *
 * Run:   make exercise NAME=cone
 */
#include <math.h>

#include "exercises/check_exercise.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A uniform direction in the cone about +z with cos theta >= cos_max. */
static vec3 sample(double u1, double u2, double cos_max)
{
    (void)u1, (void)u2, (void)cos_max;
    return vec3_make(0.0, 0.0, 1.0); /* TODO */
}

/* The density of sample() per unit solid angle. */
static double pdf(vec3 w, double cos_max)
{
    (void)w, (void)cos_max;
    return 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/cone.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void check_sample(const double *u, mcbox_sample *out, void *ctx)
{
    ex_put3(out->x, sample(u[0], u[1], *(const double *)ctx));
}

static double check_pdf(const double *x, void *ctx)
{
    return pdf(ex_vec3(x), *(const double *)ctx);
}

/* The law the exercise asks for: 1 / (2 pi (1 - cos_max)) per steradian
 * inside the cone, 0 outside; ctx points to cos_max. */
static double cone_law(const double *x, void *ctx)
{
    double cos_max = *(const double *)ctx;
    return x[2] >= cos_max ? 1.0 / (2.0 * MC_PI * (1.0 - cos_max)) : 0.0;
}

static void judge(ex_judge *j)
{
    /* The catalog row's parameter and the context must agree. */
    static const double narrow = 0.385, wide = -0.52;
    static const ex_law narrow_law = {"the uniform law on the cone", cone_law, (void *)&narrow};
    static const ex_law wide_law = {"the uniform law on the cone", cone_law, (void *)&wide};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = "cone", s.domain.params = "cos_max=0.385";
    s.sample = check_sample, s.pdf = check_pdf, s.ctx = (void *)&narrow;
    ex_check_sampler_law(j, "cos_max 0.385 (catalog row)", &s, &narrow_law, 8101, 1000000);
    /* (cos theta, phi) cells of width 0.04 put the rim -0.52 on a cell
     * edge. */
    mcbox_sampler t = mcbox_sampler_init(MCBOX_SPHERE);
    t.sample = check_sample, t.pdf = check_pdf, t.ctx = (void *)&wide;
    ex_check_sampler_law(j, "cos_max -0.52 (sphere)", &t, &wide_law, 8102, 1000000);
}

const ex_exercise ex_this = {"cone", "8 (#ch-lights)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
