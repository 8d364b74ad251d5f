/* exercises/disc.c - chapter 5, "Generating random directions"
 * (#ch-directions): Shirley and Chiu's concentric map of the square onto
 * the disc.
 *
 * WRITE  sample(u1, u2): a point of the unit disc, uniform in area, by the
 *        CONCENTRIC map: (a, b) = (2 u1 - 1, 2 u2 - 1) in [-1, 1]^2, and
 *        the square ring max(|a|, |b|) = r goes to the circle of radius r;
 *        pdf(p): its density PER UNIT AREA (0 outside the disc);
 *        invert(p, u): the (u1, u2) that sample() maps to p.
 *        The map is pinned to the concentric one (square rings to
 *        circles); where on its circle a point of a ring lands (the angle's
 *        origin and direction, which of a and b is the x side) is yours:
 *        every such variant passes, if your inverse undoes it.
 * HINT   Where |a| > |b| the radius is a and the angle (pi/4)(b/a);
 *        otherwise the radius is b and the angle pi/2 - (pi/4)(a/b) (a
 *        negative radius is the opposite point, which is what you want).
 *        Keep (0, 0) away from the divisions. The disc has area pi. The
 *        inverse finds which case made p (|x| >= |y|?), its radius with
 *        the sign of x (or y), then the angle with atan2.
 * JUDGED by the public check (check/check.h) on MCBOX_DISC, 10^6 samples
 *        from seed 3401 histogrammed in (r^2, phi) cells (equal areas):
 *        1. your points against YOUR pdf: Pearson's chi-square against pdf
 *           integrated over each cell; the integral of pdf within 1e-6 of
 *           1; the round trip |invert(sample(u)) - u| <= 1e-6;
 *        2. the same points against the law asked for, 1/pi on the disc:
 *           the chi-square again, and your pdf at every sample within 1e-6
 *           (relative) of it;
 *        3. your pdf against 1/pi (0 outside the disc) at the centres of
 *           128 x 128 cells of the square [-1, 1]^2, relative 1e-6;
 *        4. exactly, that the map is the concentric one: on a 64 x 64 grid
 *           of u, |sample(u)| equals max(|2 u1 - 1|, |2 u2 - 1|) to 1e-12
 *           (the polar map r = sqrt(u2) is uniform too, and passes 1-3).
 *
 * Run:   make exercise NAME=disc
 */
#include <math.h>

#include "exercises/check_exercise.h"
#include "mc/vec2.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A uniform point of the unit disc by the concentric map. */
static vec2 sample(double u1, double u2)
{
    (void)u1, (void)u2;
    return vec2_make(0.0, 0.0); /* TODO */
}

/* The density of sample() per unit area. */
static double pdf(vec2 p)
{
    (void)p;
    return 0.0; /* TODO */
}

/* The uniforms (u[0], u[1]) that sample() maps to the point p. */
static void invert(vec2 p, double u[2])
{
    (void)p;
    u[0] = u[1] = 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/disc.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void check_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    vec2 p = sample(u[0], u[1]);
    out->x[0] = p.x, out->x[1] = p.y;
}

static double check_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return pdf(vec2_make(x[0], x[1]));
}

static void check_invert(const double *x, double *u, void *ctx)
{
    (void)ctx;
    invert(vec2_make(x[0], x[1]), u);
}

/* The concentric map sends the square ring of half-width r to the circle of
 * radius r: the largest | |p| - max(|a|, |b|) | over a grid. */
static double ring_error(void)
{
    double worst = 0.0;
    for (int i = 0; i < 64; i++)
        for (int k = 0; k < 64; k++) {
            double u1 = i / 64.0, u2 = k / 64.0;
            vec2 p = sample(u1, u2);
            double r = fmax(fabs(2.0 * u1 - 1.0), fabs(2.0 * u2 - 1.0));
            double e = fabs(hypot(p.x, p.y) - r);
            worst = e > worst || isnan(e) ? e : worst;
        }
    return worst;
}

/* The law the exercise asks for: 1 / pi per unit area on the disc. */
static double uniform_law(const double *x, void *ctx)
{
    (void)ctx;
    return x[0] * x[0] + x[1] * x[1] <= 1.0 ? 1.0 / MC_PI : 0.0;
}

static void judge(ex_judge *j)
{
    static const ex_law law = {"the uniform law on the disc", uniform_law, NULL};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_DISC);
    s.sample = check_sample, s.pdf = check_pdf, s.invert = check_invert;
    ex_check_sampler_law(j, "disc", &s, &law, 3401, 1000000);
    double e = ring_error();
    ex_check_exact(j, "rings", "concentric rings", e <= 1e-12,
                   "largest | |p| - max(|2u1-1|, |2u2-1|) | on a 64 x 64 grid: %.3g (<= 1e-12)", e);
}

const ex_exercise ex_this = {"disc", "5 (#ch-directions)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
