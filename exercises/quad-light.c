/* exercises/quad-light.c - chapter 8, "Sampling lights directly"
 * (#ch-lights): the density of directions toward a quad light.
 *
 * The light is the parallelogram corner + s u + t v, (s, t) in [0, 1]^2,
 * of area A = |u x v|, seen from the point `origin`.
 * WRITE  light_sample(u1, u2, origin, q): the unit direction from origin toward
 *        a point uniform in the light's AREA (density 1/A), say the one
 *        with edge coordinates (u1, u2) (1 - u for u, or the edges the
 *        other way round, passes too: the judge asks for the law);
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
 *        the origin (seed 8202), 10^5 samples each:
 *        1. your directions against YOUR light_pdf: Pearson's chi-square
 *           against light_pdf integrated over the chart's cells, the
 *           integral of light_pdf within 1e-6 of 1, every direction a unit
 *           vector that hits the light's chart;
 *        2. the same directions against the law asked for (a point uniform
 *           on the whole light, seen as a direction; the library's
 *           pdf_toward_quad): the chi-square again, and your light_pdf at
 *           every sample within 1e-6 (relative) of it;
 *        3. your light_pdf against that law at the centres of 64 x 128
 *           cells of (cos theta, phi) over the whole sphere (0 where a
 *           direction misses the light), relative 1e-6.
 *
 * Run:   make exercise NAME=quad-light
 */
#include <math.h>

#include "exercises/check_exercise.h"
#include "pdf/pdf.h"

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

/* The law the exercise asks for: a point uniform on the light seen from the
 * origin, per unit solid angle (the library's own, pdf/pdf.h); ctx points
 * to the light. */
static double light_law(const double *x, void *ctx)
{
    const quad_light *q = ctx;
    pdf p = pdf_toward_quad(vec3_make(0.0, 0.0, 0.0), q->corner, q->u, q->v);
    return pdf_value(&p, ex_vec3(x));
}

static void judge(ex_judge *j)
{
    /* Each light twice: as the context and as the row's parameters. */
    static const quad_light tilted = {{-0.7, -0.4, 1.2}, {1.0, 0.1, 0.35}, {-0.15, 0.8, 0.45}};
    static const quad_light away = {{-0.5, 2.0, -0.1}, {0.7, 0.0, 0.0}, {0.0, 0.0, 0.5}};
    static const ex_law tilted_law = {"the light's law", light_law, (void *)&tilted};
    static const ex_law away_law = {"the light's law", light_law, (void *)&away};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = "quad-light";
    s.domain.params = "corner=-0.7,-0.4,1.2 u=1,0.1,0.35 v=-0.15,0.8,0.45";
    s.sample = check_sample, s.pdf = check_pdf, s.ctx = (void *)&tilted;
    ex_check_sampler_law(j, "tilted light", &s, &tilted_law, 8201, 100000);
    s.domain.params = "corner=-0.5,2,-0.1 u=0.7,0,0 v=0,0,0.5";
    s.ctx = (void *)&away;
    ex_check_sampler_law(j, "light facing away", &s, &away_law, 8202, 100000);
}

const ex_exercise ex_this = {"quad-light", "8 (#ch-lights)", EX_VARIANT, judge,
                             EX_KIND,      EX_INTENDED};
