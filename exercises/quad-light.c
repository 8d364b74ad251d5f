/* exercises/quad-light.c - chapter 8, "Sampling lights directly"
 * (#ch-lights): the density of directions toward a quad light.
 *
 * The light is the parallelogram corner + s u + t v, (s, t) in [0, 1]^2,
 * of area A = |u x v|, seen from the point `origin`.
 * WRITE  light_sample(u1, u2, origin, q): the unit direction from origin toward
 *        the point of the light with edge coordinates (u1, u2) (a point
 *        uniform in AREA, density 1/A);
 *        light_pdf(d, origin, q): the density of light_sample() at the unit direction
 *        d PER UNIT SOLID ANGLE: where the ray origin + r d (r > 0) meets
 *        the light, 1/A converted to solid angle; 0 where it misses.
 * HINT   A patch dA at distance r, tilted by the angle whose cosine is
 *        cos = |n . d| (n the unit normal u x v / |u x v|), subtends
 *        d omega = cos dA / r^2, so p_omega = r^2 / (cos A). To find the
 *        hit: r = n . (corner - origin) / (n . d); then with
 *        q = origin + r d - corner and w = (u x v) / |u x v|^2, the edge
 *        coordinates are s = w . (q x v) and t = w . (u x q). The light
 *        shines both ways: use |cos|.
 * JUDGED by the public check (check/check.h) on the catalog's "quad-light"
 *        row, which looks from the origin and charts the light's plane, for
 *        a tilted light (seed 8201) and one whose normal points away from
 *        the origin (seed 8202): 10^5 samples each, Pearson's chi-square
 *        against pdf integrated over the chart's cells, the integral of
 *        pdf within 1e-6 of 1, every direction a unit vector that hits the
 *        light's chart.
 *
 * Run:   make exercise NAME=quad-light
 */
#include <math.h>

#include "exercises/check_exercise.h"

typedef struct quad_light {
    vec3 corner, u, v;
} quad_light;

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* The direction from origin toward the point corner + u1 u + u2 v. */
static vec3 light_sample(double u1, double u2, vec3 origin, const quad_light *q)
{
    (void)u1, (void)u2, (void)origin, (void)q;
    return vec3_make(0.0, 0.0, 1.0); /* TODO */
}

/* The density of light_sample() per unit solid angle at the unit direction d. */
static double light_pdf(vec3 d, vec3 origin, const quad_light *q)
{
    (void)d, (void)origin, (void)q;
    return 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/quad-light.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* The catalog's quad-light row looks from the origin. */
static void check_sample(const double *u, mcbox_sample *out, void *ctx)
{
    ex_put3(out->x, light_sample(u[0], u[1], vec3_make(0.0, 0.0, 0.0), ctx));
}

static double check_pdf(const double *x, void *ctx)
{
    return light_pdf(ex_vec3(x), vec3_make(0.0, 0.0, 0.0), ctx);
}

static void judge(ex_judge *j)
{
    /* Each light twice: as the context and as the row's parameters. */
    static const quad_light tilted = {{-0.7, -0.4, 1.2}, {1.0, 0.1, 0.35}, {-0.15, 0.8, 0.45}};
    static const quad_light away = {{-0.5, 2.0, -0.1}, {0.7, 0.0, 0.0}, {0.0, 0.0, 0.5}};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = "quad-light";
    s.domain.params = "corner=-0.7,-0.4,1.2 u=1,0.1,0.35 v=-0.15,0.8,0.45";
    s.sample = check_sample, s.pdf = check_pdf, s.ctx = (void *)&tilted;
    ex_check_sampler(j, "tilted light", &s, 8201, 100000);
    s.domain.params = "corner=-0.5,2,-0.1 u=0.7,0,0 v=0,0,0.5";
    s.ctx = (void *)&away;
    ex_check_sampler(j, "light facing away", &s, 8202, 100000);
}

const ex_exercise ex_this = {"quad-light", "8 (#ch-lights)", EX_VARIANT, judge};
