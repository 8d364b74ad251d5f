/* tests/test_pdf.c - the pdf objects of pdf/pdf.h: known values, validity,
 * domain, normalization and chi-square goodness of fit of generate()
 * against value(), with negative controls.
 *
 * Directions are histogrammed in a chart of pdf/chart.h chosen per case:
 * (cos theta, phi) about the normal or the cone's axis, where
 * d omega = d(cos theta) d phi makes a density per unit solid angle the
 * density of the rectangle; and the light-plane charts, where every edge
 * of a parallelogram light is a cell edge (see below). The harness then
 * integrates value() times the chart's Jacobian over each cell.
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/quad.h"
#include "pdf/chart.h"
#include "pdf/pdf.h"
#include "samplers/spherical.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"

/* --- the scene: every pdf the tests use, alive for one test ----------- */

typedef struct scene {
    vec3 origin;
    vec3 corner, u, v; /* the tilted quad light */
    pdf uniform, cos_tilted, cos_down, cos_x;
    pdf quad_tilted, quad_below;
    pdf sphere_far, sphere_near, sphere_inside, sphere_side;
    pdf mix50, mix20, list;
    pdf mix_bad_weights;
    const pdf *mix_parts[2];
    double w50[2], w20[2], w_bad[2];
    const pdf *list_items[2];
} scene;

static void scene_init(scene *s)
{
    memset(s, 0, sizeof *s);
    s->origin = vec3_make(0.3, -0.2, 0.1);
    s->corner = vec3_make(-0.4, -0.6, 1.3);
    s->u = vec3_make(1.0, 0.1, 0.35);
    s->v = vec3_make(-0.15, 0.8, 0.45);
    s->uniform = pdf_uniform_sphere();
    s->cos_tilted = pdf_cosine(vec3_make(0.36, -0.48, 0.8));
    s->cos_down = pdf_cosine(vec3_normalize(vec3_make(1e-7, -2e-8, -1.0)));
    s->cos_x = pdf_cosine(vec3_make(1.0, 0.0, 0.0));
    s->quad_tilted = pdf_toward_quad(s->origin, s->corner, s->u, s->v);
    /* A ceiling light seen from below, as in the Cornell box: 0.7 x 0.5 at
     * height 2.3 above the point, facing it. */
    s->quad_below = pdf_toward_quad(vec3_make(0.2, 0.0, -0.3), vec3_make(-0.3, 2.0, -0.4),
                                    vec3_make(0.0, 0.0, 0.5), vec3_make(0.7, 0.0, 0.0));
    s->sphere_far =
        pdf_toward_sphere(s->origin, vec3_add(s->origin, vec3_make(3.0, 4.0, 12.0)), 1.0);
    s->sphere_near =
        pdf_toward_sphere(s->origin, vec3_add(s->origin, vec3_make(0.4, -1.1, 1.5)), 1.5);
    s->sphere_inside = pdf_toward_sphere(s->origin, vec3_make(0.5, 0.1, -0.2), 2.0);
    s->sphere_side =
        pdf_toward_sphere(s->origin, vec3_add(s->origin, vec3_make(3.0, -1.0, -0.5)), 0.8);
    s->mix_parts[0] = &s->cos_tilted;
    s->mix_parts[1] = &s->quad_tilted;
    s->w50[0] = 0.5, s->w50[1] = 0.5;
    s->w20[0] = 0.2, s->w20[1] = 0.8;
    s->w_bad[0] = 0.5, s->w_bad[1] = 0.3;
    s->mix50 = pdf_mixture(s->mix_parts, s->w50, 2);
    s->mix20 = pdf_mixture(s->mix_parts, s->w20, 2);
    s->mix_bad_weights = pdf_mixture(s->mix_parts, s->w_bad, 2);
    s->list_items[0] = &s->quad_tilted;
    s->list_items[1] = &s->sphere_side;
    s->list = pdf_list(s->list_items, 2);
}

/* --- charts ------------------------------------------------------------
 * Each case histograms and integrates in a chart of pdf/chart.h in which
 * its density is smooth on every cell: (cos theta, phi) about an axis for
 * the uniform, cosine and sphere pdfs (a sphere's chart starts exactly at
 * its cone's rim, computed here from the geometry), the light-plane chart
 * for the quad light and the mixtures with it, and the quad-and-cap chart
 * for the list. In (cos theta, phi) the quad light's edges would cut cells
 * along curves, and adaptive quadrature of such a cell to 1e-12 takes
 * about a second.
 */

/* --- a test case: a generator, a claimed density, a chart --------------- */

typedef struct pdf_case pdf_case;
struct pdf_case {
    const char *name;
    const pdf *p;
    /* Overrides for the negative controls; NULL means pdf_value / pdf_generate. */
    double (*value)(const pdf_case *c, vec3 d);
    vec3 (*generate)(const pdf_case *c, mc_rng *rng);
    pdf_chart ch;
};

static double case_value(const pdf_case *c, vec3 d)
{
    return c->value ? c->value(c, d) : pdf_value(c->p, d);
}

static vec3 case_generate(const pdf_case *c, mc_rng *rng)
{
    return c->generate ? c->generate(c, rng) : pdf_generate(c->p, rng);
}

static pdf_case make_case(const char *name, const pdf *p, pdf_chart ch)
{
    pdf_case c = {name, p, NULL, NULL, ch};
    return c;
}

enum { NCASES = 13 };

/* Every positive case: the pdf, its own value and generate. */
static int all_cases(const scene *s, pdf_case *out)
{
    const pdf *b = &s->quad_below;
    pdf_chart tilted = pdf_chart_light_plane(s->origin, s->corner, s->u, s->v);
    int k = 0;
    out[k++] =
        make_case("uniform", &s->uniform, pdf_chart_spherical(vec3_make(1.0, 2.0, 3.0), -1.0));
    out[k++] = make_case("cosine-tilted", &s->cos_tilted,
                         pdf_chart_spherical(s->cos_tilted.as.cosine.frame.n, -1.0));
    out[k++] = make_case("cosine-near-minus-z", &s->cos_down,
                         pdf_chart_spherical(s->cos_down.as.cosine.frame.n, -1.0));
    out[k++] =
        make_case("cosine-x", &s->cos_x, pdf_chart_spherical(vec3_make(1.0, 0.0, 0.0), -1.0));
    out[k++] = make_case("quad-tilted", &s->quad_tilted, tilted);
    out[k++] = make_case(
        "quad-below", b,
        pdf_chart_light_plane(b->as.quad.origin, b->as.quad.corner, b->as.quad.u, b->as.quad.v));
    /* The cone charts start exactly at the rim: cos_lo = sqrt(1 - R^2/d^2)
     * from the geometry (3, 4, 12) / 13 and (0.4, -1.1, 1.5). */
    out[k++] = make_case("sphere-far", &s->sphere_far,
                         pdf_chart_spherical(vec3_make(3.0, 4.0, 12.0), sqrt(1.0 - 1.0 / 169.0)));
    out[k++] = make_case("sphere-near", &s->sphere_near,
                         pdf_chart_spherical(vec3_make(0.4, -1.1, 1.5), sqrt(1.0 - 2.25 / 3.62)));
    out[k++] = make_case("sphere-inside", &s->sphere_inside,
                         pdf_chart_spherical(vec3_make(0.3, 0.1, -0.2), -1.0));
    out[k++] = make_case("mixture-0.5", &s->mix50, tilted);
    out[k++] = make_case("mixture-0.2", &s->mix20, tilted);
    out[k++] = make_case("list-quad-sphere", &s->list,
                         pdf_chart_quad_and_cap(s->origin, s->corner, s->u, s->v,
                                                s->sphere_side.as.sphere.center, 0.8));
    out[k++] = make_case("sphere-side", &s->sphere_side,
                         pdf_chart_spherical(vec3_make(3.0, -1.0, -0.5), sqrt(1.0 - 0.64 / 10.25)));
    return k;
}

/* --- the three checks, as predicates (the negative controls reuse them) */

static void chi2_sample(mc_rng *rng, void *ctx, double out[2])
{
    const pdf_case *c = ctx;
    pdf_chart_point(&c->ch, case_generate(c, rng), out);
}

static double chi2_density(const double x[2], void *ctx)
{
    const pdf_case *c = ctx;
    double jac;
    vec3 d = pdf_chart_direction(&c->ch, x, &jac);
    return jac > 0.0 ? case_value(c, d) * jac : 0.0;
}

/* The chart's rectangle; the cells put an edge on every joint of the
 * chart (multiples of 1/30 in the plane charts). */
static chi2_spec case_spec(const pdf_case *c)
{
    chi2_spec spec = {c->name,  2,           {0.0, 0.0},   {0.0, 0.0},
                      {40, 80}, chi2_sample, chi2_density, (void *)c};
    pdf_chart_rect(&c->ch, spec.lo, spec.hi);
    if (c->ch.kind == PDF_CHART_LIGHT_PLANE)
        spec.cells[0] = 120, spec.cells[1] = 90;
    else if (c->ch.kind == PDF_CHART_QUAD_AND_CAP)
        spec.cells[0] = 60, spec.cells[1] = 30;
    return spec;
}

/* 10^6 samples per case, rejected at the suite's Sidak level
 * chi2_suite_alpha() (about 1.6e-4 per test, 1% over the whole suite of at
 * most 64 chi-square tests). */
enum { CHI2_N = 1000000 };

static chi2_outcome run_chi2(const pdf_case *c, uint64_t seed)
{
    chi2_spec spec = case_spec(c);
    chi2_outcome o = chi2_run(&spec, CHI2_N, seed, chi2_suite_alpha());
    chi2_print(&spec, &o);
    return o;
}

static double value_at(vec3 d, void *ctx)
{
    return case_value(ctx, d);
}

/* What the chart does not cover: value over polar cosines [c0, c1] about
 * `frame`, except inside the two cones (axis, cosine) given. The value
 * there must be 0; a pdf that leaks mass shows up. */
typedef struct rest {
    const pdf_case *c;
    onb frame;
    vec3 skip_axis[2];
    double skip_cos[2];
} rest;

static double rest_integrand(double cos_theta, double phi, void *params)
{
    const rest *r = params;
    vec3 d = onb_to_world(&r->frame, smp_spherical_direction(cos_theta, phi));
    for (int k = 0; k < 2; k++)
        if (vec3_dot(d, r->skip_axis[k]) >= r->skip_cos[k])
            return 0.0;
    return case_value(r->c, d);
}

/* The integral of value over the whole sphere of directions: over the
 * chart (pdf_chart_integrate), plus whatever of the sphere the chart
 * leaves out: below a cone chart's rim, and around the list's light and
 * sphere (cones 0.01 wider than the light's widest corner and than the
 * sphere's rim, so that the mask never cuts the support). */
static double normalization(const pdf_case *c)
{
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    double total = pdf_chart_integrate(&c->ch, value_at, (void *)c, q), v = 0.0;
    const pdf_chart *ch = &c->ch;
    if (ch->kind == PDF_CHART_SPHERICAL && ch->cos_lo > -1.0) {
        rest r = {c, ch->frame, {ch->frame.n, ch->frame.n}, {2.0, 2.0}};
        (void)mc_quad_2d(q, (mc_fn2){rest_integrand, &r}, -1.0, ch->cos_lo, 0.0, MC_2PI, &v, NULL);
        total += v;
    } else if (ch->kind == PDF_CHART_QUAD_AND_CAP) {
        vec3 mid = vec3_madd(vec3_madd(ch->corner, ch->u, 0.5), ch->v, 0.5);
        rest r = {c,
                  ch->frame,
                  {ch->frame.n, vec3_normalize(vec3_sub(mid, ch->origin))},
                  {ch->cos_lo - 0.01, 1.0}};
        for (int k = 0; k < 4; k++) {
            vec3 x =
                vec3_madd(vec3_madd(ch->corner, ch->u, (double)(k & 1)), ch->v, (double)(k >> 1));
            double cs = vec3_dot(vec3_normalize(vec3_sub(x, ch->origin)), r.skip_axis[1]);
            r.skip_cos[1] = fmin(r.skip_cos[1], cs - 0.01);
        }
        (void)mc_quad_2d(q, (mc_fn2){rest_integrand, &r}, -1.0, 1.0, 0.0, MC_2PI, &v, NULL);
        total += v;
    }
    mc_quad_destroy(q);
    return total;
}

/* Every one of n generated directions finite, unit length within 1e-12,
 * with a finite positive density. Prints the first offender. */
static bool domain_ok(const pdf_case *c, uint64_t seed, int n)
{
    mc_rng rng = mc_rng_derive(seed, 1u);
    for (int i = 0; i < n; i++) {
        vec3 d = case_generate(c, &rng);
        double len = vec3_length(d), p = case_value(c, d);
        if (!vec3_is_finite(d) || !(fabs(len - 1.0) <= 1e-12) || !(p > 0.0) || !isfinite(p)) {
            printf("domain %s: sample %d = (%.17g, %.17g, %.17g), |d| - 1 = %.3g, value %.17g\n",
                   c->name, i, d.x, d.y, d.z, len - 1.0, p);
            return false;
        }
    }
    return true;
}

/* --- known values -------------------------------------------------------- */

static void test_pdf_known_values(void **state)
{
    (void)state;
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    /* Unit square at height 1 straight above: along +z dist = 1, cos = 1,
     * A = 1, so 1 per steradian; toward (0.25, 0.1, 1) dist^2 = 1.0725 and
     * cos = 1 / sqrt(1.0725), so dist^2 / cos = 1.0725^1.5. */
    pdf q = pdf_toward_quad(o, vec3_make(-0.5, -0.5, 1.0), vec3_make(1.0, 0.0, 0.0),
                            vec3_make(0.0, 1.0, 0.0));
    assert_near(pdf_value(&q, vec3_make(0.0, 0.0, 1.0)), 1.0, 1e-15);
    assert_near(pdf_value(&q, vec3_normalize(vec3_make(0.25, 0.1, 1.0))), pow(1.0725, 1.5), 1e-14);
    assert_true(pdf_value(&q, vec3_make(0.0, 0.0, -1.0)) == 0.0);                /* behind: r < 0 */
    assert_true(pdf_value(&q, vec3_normalize(vec3_make(0.6, 0.0, 1.0))) == 0.0); /* beside */
    assert_true(pdf_value(&q, vec3_make(1.0, 0.0, 0.0)) == 0.0); /* parallel to the plane */
    /* Scaled edges: a 2.385 x 0.5 light at height 3 gives 9 / 1.1925. */
    pdf q2 = pdf_toward_quad(o, vec3_make(-1.0, -0.2, 3.0), vec3_make(2.385, 0.0, 0.0),
                             vec3_make(0.0, 0.5, 0.0));
    assert_near(pdf_value(&q2, vec3_make(0.0, 0.0, 1.0)), 9.0 / 1.1925, 1e-13);

    /* Sphere at distance 2.385 with radius 1: 1 / (2 pi (1 - sqrt(1 - 1/2.385^2))). */
    pdf s = pdf_toward_sphere(o, vec3_make(0.0, 2.385, 0.0), 1.0);
    double cmax = sqrt(1.0 - 1.0 / (2.385 * 2.385));
    assert_near(pdf_value(&s, vec3_make(0.0, 1.0, 0.0)), 1.0 / (MC_2PI * (1.0 - cmax)), 1e-12);
    assert_true(pdf_value(&s, vec3_make(0.0, -1.0, 0.0)) == 0.0);
    pdf in = pdf_toward_sphere(o, vec3_make(0.1, 0.2, 0.3), 1.0);
    assert_near(pdf_value(&in, vec3_make(0.0, -1.0, 0.0)), MC_INV_4PI, 1e-17);
    pdf at = pdf_toward_sphere(o, o, 2.385); /* at the centre */
    assert_near(pdf_value(&at, vec3_make(0.0, 0.0, 1.0)), MC_INV_4PI, 1e-17);

    pdf c = pdf_cosine(vec3_make(0.0, 1.0, 0.0));
    assert_near(pdf_value(&c, vec3_make(0.0, 1.0, 0.0)), MC_INV_PI, 1e-17);
    assert_near(pdf_value(&c, vec3_make(0.6, 0.8, 0.0)), 0.8 * MC_INV_PI, 1e-16);
    assert_true(pdf_value(&c, vec3_make(0.6, -0.8, 0.0)) == 0.0);

    /* Mixture 0.2 cosine + 0.8 quad and the list of both, at +y and +z. */
    const pdf *parts[2] = {&c, &q};
    double w[2] = {0.2, 0.8};
    pdf m = pdf_mixture(parts, w, 2), l = pdf_list(parts, 2);
    assert_near(pdf_value(&m, vec3_make(0.0, 0.0, 1.0)), 0.8, 1e-15);
    assert_near(pdf_value(&m, vec3_make(0.0, 1.0, 0.0)), 0.2 * MC_INV_PI, 1e-16);
    assert_near(pdf_value(&l, vec3_make(0.0, 0.0, 1.0)), 0.5, 1e-15);
    assert_near(pdf_value(&l, vec3_make(0.0, 1.0, 0.0)), 0.5 * MC_INV_PI, 1e-16);
}

/* Each bound the validity checks enforce, from both sides: a weight of
 * exactly 0 is allowed (the header says >= 0) and the smallest negative
 * one is not; a sum off by half the tolerance passes and by twice does
 * not; a cosine lobe's normal must have length 1 within 1e-9, too short
 * as well as too long. */
static void test_pdf_validity_both_sides(void **state)
{
    (void)state;
    double zero_first[2] = {0.0, 1.0}, zero_last[3] = {0.25, 0.75, 0.0};
    assert_true(pdf_mixture_weights_valid(zero_first, 2));
    assert_true(pdf_mixture_weights_valid(zero_last, 3));
    double tiny_negative[2] = {-4.9e-324, 1.0};
    assert_false(pdf_mixture_weights_valid(tiny_negative, 2));
    double near_sum[2] = {0.5, 0.5 + 0.5 * PDF_WEIGHT_SUM_TOL}, far_sum[2] = {0.5, 0.5 + 2.0 * PDF_WEIGHT_SUM_TOL};
    assert_true(pdf_mixture_weights_valid(near_sum, 2));
    assert_false(pdf_mixture_weights_valid(far_sum, 2));
    near_sum[1] = 0.5 - 0.5 * PDF_WEIGHT_SUM_TOL, far_sum[1] = 0.5 - 2.0 * PDF_WEIGHT_SUM_TOL;
    assert_true(pdf_mixture_weights_valid(near_sum, 2));
    assert_false(pdf_mixture_weights_valid(far_sum, 2));
    /* The normal's length: 1 +- 1e-10 passes, 1 +- 1e-8 fails. */
    static const double scale[4] = {1.0 + 1e-10, 1.0 - 1e-10, 1.0 + 1e-8, 1.0 - 1e-8};
    vec3 n = vec3_normalize(vec3_make(0.36, -0.48, 0.8));
    for (int i = 0; i < 4; i++) {
        pdf c = pdf_cosine(n);
        c.as.cosine.frame.n = vec3_scale(n, scale[i]);
        if (pdf_valid(&c) != (i < 2))
            fail_msg("cosine normal of length %.12f: pdf_valid says %d", scale[i], pdf_valid(&c));
    }
}

static void test_pdf_validity(void **state)
{
    (void)state;
    scene s;
    scene_init(&s);
    pdf_case cases[NCASES];
    int n = all_cases(&s, cases);
    for (int i = 0; i < n; i++)
        assert_true(pdf_valid(cases[i].p));
    double sum_rounded[10];
    for (int i = 0; i < 10; i++)
        sum_rounded[i] = 0.1; /* sums to 1 - 1.1e-16 */
    assert_true(pdf_mixture_weights_valid(sum_rounded, 10));
    assert_false(pdf_mixture_weights_valid(s.w_bad, 2));
    assert_false(pdf_valid(&s.mix_bad_weights));
    double negative[2] = {1.5, -0.5};
    assert_false(pdf_mixture_weights_valid(negative, 2));
    assert_false(pdf_mixture_weights_valid(s.w50, 0));
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    pdf flat = pdf_toward_quad(o, vec3_make(1.0, 0.0, 0.0), vec3_make(1.0, 0.0, 0.0),
                               vec3_make(2.0, 0.0, 0.0));
    assert_false(pdf_valid(&flat)); /* zero area */
    pdf edge_on = pdf_toward_quad(o, vec3_make(1.0, 0.0, 0.0), vec3_make(1.0, 0.0, 0.0),
                                  vec3_make(0.0, 1.0, 0.0));
    assert_false(pdf_valid(&edge_on)); /* origin in the light's plane */
    pdf no_radius = pdf_toward_sphere(o, vec3_make(0.0, 0.0, 5.0), 0.0);
    assert_false(pdf_valid(&no_radius));
    pdf long_normal = pdf_cosine(vec3_make(0.0, 0.0, 1.001));
    assert_false(pdf_valid(&long_normal));
    /* A mixture that contains itself is cyclic: invalid, not a crash. */
    const pdf *self[1];
    double one[1] = {1.0};
    pdf cyc = pdf_mixture(self, one, 1);
    self[0] = &cyc;
    assert_false(pdf_valid(&cyc));
    /* Empty composites are invalid, yet defined: value 0, generate +z
     * (no division by zero in the uniform choice of a list item). */
    pdf empties[2] = {pdf_list(NULL, 0), pdf_mixture(NULL, NULL, 0)};
    mc_rng rng = mc_rng_derive(1u, 0u);
    for (int k = 0; k < 2; k++) {
        assert_false(pdf_valid(&empties[k]));
        assert_true(pdf_value(&empties[k], vec3_make(0.0, 0.0, 1.0)) == 0.0);
        vec3 d = pdf_generate(&empties[k], &rng);
        assert_true(d.x == 0.0 && d.y == 0.0 && d.z == 1.0);
    }
}

/* A zero weight is never chosen, even when rounding of the other weights
 * leaves their sum a hair below the uniform that picks. */
static void test_pdf_mixture_zero_weight_never_chosen(void **state)
{
    (void)state;
    pdf up = pdf_cosine(vec3_make(0.0, 0.0, 1.0)), down = pdf_cosine(vec3_make(0.0, 0.0, -1.0));
    const pdf *parts[3] = {&up, &up, &down};
    double w[3] = {0.7, 0.3 - 1e-16, 0.0};
    pdf m = pdf_mixture(parts, w, 3);
    uint64_t seed = mc_test_seed(3301u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (int i = 0; i < 100000; i++)
        assert_true(pdf_generate(&m, &rng).z > 0.0);
}

/* --- the charts themselves --------------------------------------------- */

static double one(vec3 d, void *ctx)
{
    (void)d, (void)ctx;
    return 1.0;
}

/* The solid angle of the triangle (a, b, c) seen from the origin, by Van
 * Oosterom and Strackee's formula tan(Omega / 2) = |a . (b x c)| /
 * (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|): independent of the
 * Jacobians the charts use. */
static double triangle_solid_angle(vec3 a, vec3 b, vec3 c)
{
    double la = vec3_length(a), lb = vec3_length(b), lc = vec3_length(c);
    double num = fabs(vec3_dot(a, vec3_cross(b, c)));
    double den = la * lb * lc + vec3_dot(a, b) * lc + vec3_dot(a, c) * lb + vec3_dot(b, c) * la;
    return 2.0 * atan2(num, den);
}

/* The charts' Jacobians: the whole light-plane chart has solid angle
 * 4 pi; the quad-and-cap chart the parallelogram's solid angle (two
 * triangles) plus the cap's 2 pi (1 - cos theta_max). And every chart
 * point maps back to itself. */
static void test_pdf_chart_jacobians(void **state)
{
    (void)state;
    scene s;
    scene_init(&s);
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    pdf_chart plane = pdf_chart_light_plane(s.origin, s.corner, s.u, s.v);
    assert_near(pdf_chart_integrate(&plane, one, NULL, q), MC_4PI, 1e-9);
    vec3 center = vec3_add(s.origin, vec3_make(3.0, -1.0, -0.5));
    pdf_chart both = pdf_chart_quad_and_cap(s.origin, s.corner, s.u, s.v, center, 0.8);
    vec3 a = vec3_sub(s.corner, s.origin), b = vec3_add(a, s.u), d = vec3_add(a, s.v);
    vec3 c = vec3_add(b, s.v);
    double quad = triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d);
    double cap = MC_2PI * (1.0 - sqrt(1.0 - 0.64 / 10.25));
    assert_near(pdf_chart_integrate(&both, one, NULL, q), quad + cap, 1e-9);
    mc_quad_destroy(q);
    const pdf_chart *charts[2] = {&plane, &both};
    for (int k = 0; k < 2; k++) {
        double lo[2], hi[2];
        pdf_chart_rect(charts[k], lo, hi);
        for (int i = 0; i < 40; i++)
            for (int j = 0; j < 30; j++) {
                double x[2] = {lo[0] + (hi[0] - lo[0]) * (i + 0.37) / 40.0,
                               lo[1] + (hi[1] - lo[1]) * (j + 0.61) / 30.0};
                double y[2], jac;
                pdf_chart_point(charts[k], pdf_chart_direction(charts[k], x, &jac), y);
                assert_near(y[0], x[0], 1e-9);
                assert_near(y[1], x[1], 1e-9);
            }
    }
}

/* --- the statistical checks ------------------------------------------ */

/* Domain: 10^5 samples per case; deterministic properties, no false alarms. */
static void test_pdf_domain(void **state)
{
    (void)state;
    scene s;
    scene_init(&s);
    pdf_case cases[NCASES];
    int n = all_cases(&s, cases);
    uint64_t seed = mc_test_seed(3302u);
    for (int i = 0; i < n; i++)
        assert_true(domain_ok(&cases[i], seed + (uint64_t)i, 100000));
}

/* Normalization: the integral of value over the sphere is 1 within 1e-6
 * (deterministic quadrature; its own accuracy is about 1e-9 or better). */
static void test_pdf_normalization(void **state)
{
    (void)state;
    scene s;
    scene_init(&s);
    pdf_case cases[NCASES];
    int n = all_cases(&s, cases);
    for (int i = 0; i < n; i++) {
        double total = normalization(&cases[i]);
        printf("normalization %-20s %.15f error %.3g\n", cases[i].name, total, total - 1.0);
        assert_near(total, 1.0, 1e-6);
    }
}

/* Chi-square of generate() against value() for every case; seed 3303 + i,
 * 10^6 samples, 40 x 80 cells (120 x 90 and 60 x 30 in the plane charts),
 * level chi2_suite_alpha(): 13 of the suite's CHI2_SUITE_TESTS = 64. */
static void test_pdf_chi2(void **state)
{
    (void)state;
    scene s;
    scene_init(&s);
    pdf_case cases[NCASES];
    int n = all_cases(&s, cases);
    bool all_ok = true;
    for (int i = 0; i < n; i++) {
        uint64_t seed = mc_test_seed(3303u + (uint64_t)i);
        chi2_outcome o = run_chi2(&cases[i], seed);
        if (o.reject)
            printf("chi2 %s rejected (seed %llu)\n", cases[i].name, (unsigned long long)seed);
        all_ok = all_ok && !o.reject;
    }
    assert_true(all_ok);
}

/* --- a tiny, far sphere light ------------------------------------------- */

/* Spheres seen at R / d = 1e-9, 1e-12 and 1e-150 from the scene's origin,
 * 1.3e7 away along (3, 4, 12) (d = 13e6: the axis is not an axis of the
 * frame). Before 1 - cos theta_max was carried without cancellation their
 * cos theta_max was exactly 1 and the density +inf. */
static const double tiny_ratios[] = {1e-9, 1e-12, 1e-150};
enum { N_TINY = (int)(sizeof tiny_ratios / sizeof tiny_ratios[0]) };

static pdf tiny_sphere(vec3 origin, double ratio)
{
    vec3 center = vec3_add(origin, vec3_make(3e6, 4e6, 12e6));
    return pdf_toward_sphere(origin, center, ratio * 13e6);
}

/* 1 / (2 pi (1 - cos theta_max)) for the sphere of p, written
 * independently of samplers/cone.c: d^2 from the axis center - origin (as
 * the pdf forms it) and s = R^2 / d^2 in long double, then the series
 * 1 - sqrt(1 - s) = s/2 + s^2/8 + s^3/16 (the next term is 1e-53 of the
 * sum at s <= 1e-18). */
static long double tiny_exact_value(const pdf *p)
{
    vec3 a = vec3_sub(p->as.sphere.center, p->as.sphere.origin);
    long double ax = (long double)a.x, ay = (long double)a.y, az = (long double)a.z;
    long double d2 = ax * ax + ay * ay + az * az;
    long double r = (long double)p->as.sphere.radius, s = r * r / d2;
    const long double two_pi = 6.283185307179586476925286766559005768L;
    return 1 / (two_pi * (s / 2 + s * s / 8 + s * s * s / 16));
}

/* The density of p along its axis (within the cone), as a renderer would
 * evaluate it. */
typedef double (*tiny_value_fn)(const pdf *p, vec3 d);

/* The negative control: 1 - cos theta_max by subtraction from the rounded
 * cosine, the value before the fix. */
static double tiny_value_subtracted(const pdf *p, vec3 d)
{
    return vec3_dot(d, p->as.sphere.frame.n) >= p->as.sphere.cos_theta_max - PDF_CONE_RIM_TOL
               ? 1.0 / (MC_2PI * (1.0 - p->as.sphere.cos_theta_max))
               : 0.0;
}

/* Whether f's value along the axis of every tiny sphere is finite and
 * within 1e-12 relative of the exact density (deterministic). */
static bool tiny_values_ok(const char *label, tiny_value_fn f, vec3 origin)
{
    bool ok = true;
    for (int k = 0; k < N_TINY; k++) {
        pdf p = tiny_sphere(origin, tiny_ratios[k]);
        long double exact = tiny_exact_value(&p);
        double got = f(&p, vec3_normalize(vec3_make(3.0, 4.0, 12.0)));
        double rel = isfinite(got) ? (double)fabsl(((long double)got - exact) / exact)
                                   : (double)INFINITY;
        printf("tiny sphere %-10s R/d %.0e: value %.17g, exact %.17Lg, relative error %.3g\n",
               label, tiny_ratios[k], got, exact, rel);
        ok = ok && rel <= 1e-12;
    }
    return ok;
}

/* pdf_toward_sphere of a tiny far sphere: valid, its value along the axis
 * the exact density to 1e-12 relative, 0 a microradian off the axis (far
 * beyond the rim and its slack) and behind; 10^4 generated directions
 * (seed 3360) are unit, finite, get the same nonzero density and lie
 * within the cone, |d x axis| = sin(angle) <= R / d, up to 1e-15 for the
 * rounding of a unit vector's components. */
static void test_pdf_tiny_sphere(void **state)
{
    (void)state;
    vec3 o = vec3_make(0.3, -0.2, 0.1);
    assert_true(tiny_values_ok("pdf_value", pdf_value, o));
    uint64_t seed = mc_test_seed(3360u);
    for (int k = 0; k < N_TINY; k++) {
        pdf p = tiny_sphere(o, tiny_ratios[k]);
        assert_true(pdf_valid(&p));
        vec3 axis = vec3_normalize(vec3_make(3.0, 4.0, 12.0));
        double inside = pdf_value(&p, axis);
        vec3 off = vec3_normalize(vec3_madd(axis, vec3_make(4.0, -3.0, 0.0), 1e-6 / 5.0));
        assert_true(pdf_value(&p, off) == 0.0);
        assert_true(pdf_value(&p, vec3_neg(axis)) == 0.0);
        mc_rng rng = mc_rng_derive(seed, (uint64_t)k);
        for (int i = 0; i < 10000; i++) {
            vec3 d = pdf_generate(&p, &rng);
            double sin_off = vec3_length(vec3_cross(d, axis));
            if (!(vec3_is_finite(d) && fabs(vec3_length(d) - 1.0) <= 1e-15 &&
                  pdf_value(&p, d) == inside && sin_off <= tiny_ratios[k] + 1e-15))
                fail_msg("R/d %.0e: generated direction off the cone (sin %.3g, seed %llu)",
                         tiny_ratios[k], sin_off, (unsigned long long)seed);
        }
    }
}

/* --- negative controls --------------------------------------------------- */

/* The light pdf without its cosine: dist^2 / A instead of
 * dist^2 / (|cos| A). */
static double value_no_cosine(const pdf_case *c, vec3 d)
{
    return pdf_value(c->p, d) * fabs(vec3_dot(d, c->p->as.quad.normal));
}

/* A mixture whose value is only the density of the component a renderer
 * happened to choose (here the cosine one) instead of the weighted sum. */
static double value_chosen_only(const pdf_case *c, vec3 d)
{
    return pdf_value(c->p->as.mixture.components[0], d);
}

/* The cone's solid angle from theta by the small-angle formula pi theta^2
 * instead of 2 pi (1 - cos theta). */
static double value_cone_from_theta(const pdf_case *c, vec3 d)
{
    double cos_max = c->p->as.sphere.cos_theta_max, theta = acos(cos_max);
    return vec3_dot(d, c->p->as.sphere.frame.n) >= cos_max ? 1.0 / (MC_PI * theta * theta) : 0.0;
}

/* The book's random_to_sphere and its pdf from inside the sphere:
 * sqrt(1 - R^2 / d^2) of a negative number. */
static double book_cos_max(const pdf *p)
{
    vec3 a = vec3_sub(p->as.sphere.center, p->as.sphere.origin);
    double r = p->as.sphere.radius;
    return sqrt(1.0 - r * r / vec3_length_sq(a));
}

static double value_book_sphere(const pdf_case *c, vec3 d)
{
    (void)d;
    return 1.0 / (MC_2PI * (1.0 - book_cos_max(c->p)));
}

static vec3 generate_book_sphere(const pdf_case *c, mc_rng *rng)
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    double z = 1.0 + u2 * (book_cos_max(c->p) - 1.0), phi = MC_2PI * u1;
    double r = sqrt(1.0 - z * z);
    return onb_to_world(&c->p->as.sphere.frame, vec3_make(cos(phi) * r, sin(phi) * r, z));
}

/* A list that sums its items' densities instead of averaging them. */
static double value_list_sum(const pdf_case *c, vec3 d)
{
    return 2.0 * pdf_value(c->p, d);
}

typedef enum check { BY_CHI2, BY_NORMALIZATION, BY_DOMAIN } check;

/* Runs the check that must catch the control; true when it does. */
static bool caught(const pdf_case *c, check by, uint64_t seed)
{
    switch (by) {
    case BY_CHI2:
        return run_chi2(c, seed).reject;
    case BY_NORMALIZATION: {
        double total = normalization(c);
        printf("normalization %-20s %.15f error %.3g\n", c->name, total, total - 1.0);
        return !(fabs(total - 1.0) <= 1e-6);
    }
    case BY_DOMAIN:
        return !domain_ok(c, seed, 100000);
    }
    return false;
}

static void test_pdf_negative_controls(void **state)
{
    negctl *t = *state;
    scene s;
    scene_init(&s);
    pdf_case cases[NCASES];
    all_cases(&s, cases);
    const pdf_case *quad = &cases[4], *near = &cases[7], *inside = &cases[8], *mix = &cases[9],
                   *list = &cases[11];
    assert_string_equal(quad->name, "quad-tilted");
    assert_string_equal(near->name, "sphere-near");
    assert_string_equal(inside->name, "sphere-inside");
    assert_string_equal(mix->name, "mixture-0.5");
    assert_string_equal(list->name, "list-quad-sphere");
    enum { M = 6 };
    pdf_case bad[M] = {*quad, *mix, *mix, *near, *inside, *list};
    check by[M] = {BY_CHI2,          BY_CHI2,   BY_NORMALIZATION,
                   BY_NORMALIZATION, BY_DOMAIN, BY_NORMALIZATION};
    bad[0].name = "neg-light-missing-cosine", bad[0].value = value_no_cosine;
    /* Its normalization is exactly 1 (value is a component's density):
     * only the chi-square test can see this one. */
    bad[1].name = "neg-mixture-chosen-only", bad[1].value = value_chosen_only;
    bad[2].name = "neg-mixture-weights-0.5-0.3", bad[2].p = &s.mix_bad_weights;
    bad[3].name = "neg-cone-from-theta", bad[3].value = value_cone_from_theta;
    bad[4].name = "neg-book-sphere-inside", bad[4].value = value_book_sphere;
    bad[4].generate = generate_book_sphere;
    bad[5].name = "neg-list-sum", bad[5].value = value_list_sum;
    static const char *const check_name[3] = {"chi-square", "normalization", "domain"};
    bool all = true;
    for (int i = 0; i < M; i++)
        all &= negctl_record(t, bad[i].name, check_name[by[i]],
                             caught(&bad[i], by[i], mc_test_seed(3350u + (uint64_t)i)));
    all &= negctl_record(t, "neg-tiny-sphere-subtracted", "tiny-sphere accuracy (1e-12)",
                         !tiny_values_ok("subtracted", tiny_value_subtracted, s.origin));
    assert_true(all);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pdf_known_values),
        cmocka_unit_test(test_pdf_validity),
        cmocka_unit_test(test_pdf_validity_both_sides),
        cmocka_unit_test(test_pdf_mixture_zero_weight_never_chosen),
        cmocka_unit_test(test_pdf_chart_jacobians),
        cmocka_unit_test(test_pdf_domain),
        cmocka_unit_test(test_pdf_normalization),
        cmocka_unit_test(test_pdf_chi2),
        cmocka_unit_test(test_pdf_tiny_sphere),
        cmocka_unit_test(test_pdf_negative_controls),
    };
    return cmocka_run_group_tests_name("test_pdf", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
