/* tests/test_pdf.c - the pdf objects of pdf/pdf.h: known values, validity,
 * the charts of pdf/chart.h, and, for every case of the catalog's pdf rows
 * (catalog/catalog.h: uniform-pdf, cosine-pdf, quad-light, sphere-light,
 * mixture, light-list), domain, normalization and chi-square goodness of
 * fit of generate() against value() through the shared harness
 * (tests/support/warp_check.h), with negative controls.
 *
 * Directions are histogrammed in the chart of pdf/chart.h the row
 * chooses: (cos theta, phi) about the normal or the cone's axis, where
 * d omega = d(cos theta) d phi makes a density per unit solid angle the
 * density of the rectangle; and the light-plane charts, where every edge
 * of a parallelogram light is a cell edge. The harness integrates value()
 * times the chart's Jacobian over each cell.
 *
 * Statistics (seeds overridable with MC_TEST_SEED): chi-square with 10^6
 * samples per case, 40 x 80 cells in (cos theta, phi), 120 x 90 and
 * 60 x 30 in the plane charts, at chi2_suite_alpha() = 1.57e-4 (Sidak: 1%
 * over the suite's <= 64 tests); domain on 10^5 samples; normalization
 * within 1e-6 (deterministic quadrature).
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
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

enum { N_CHI2 = 1000000 };

/* The rows of the catalog this program tests (chi-square, normalization
 * and domain of every case: tests built in main). */
static const char *const families[] = {"pdf"};

/* The tilted parallelogram light of the catalog's cases and a sphere
 * beside it, seen from a point off every axis. */
static const vec3 eye = {0.3, -0.2, 0.1};
static const vec3 light_corner = {-0.4, -0.6, 1.3}, light_u = {1.0, 0.1, 0.35},
                  light_v = {-0.15, 0.8, 0.45};

/* A catalog case by name, prepared into *s (which must outlive it). */
static warp_case case_named(const char *name, const cat_row *row, cat_state *s)
{
    const cat_row *r = NULL;
    const cat_case *tc = cat_find_case(name, &r);
    assert_non_null(tc);
    warp_case c = warp_case_of(row ? row : r, tc, s);
    return c;
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

/* Every case of the catalog's pdf rows builds a valid pdf; the bounds of
 * the validity checks. */
static void test_pdf_validity(void **state)
{
    (void)state;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        for (const cat_case *tc = r->cases; strcmp(r->family, "pdf") == 0 && tc->name; tc++) {
            static cat_state s;
            (void)warp_case_of(r, tc, &s);
            if (!pdf_valid(s.object))
                fail_msg("%s: pdf_valid is false", tc->name);
        }
    }
    double sum_rounded[10];
    for (int i = 0; i < 10; i++)
        sum_rounded[i] = 0.1; /* sums to 1 - 1.1e-16 */
    assert_true(pdf_mixture_weights_valid(sum_rounded, 10));
    pdf cos_tilted = pdf_cosine(vec3_make(0.36, -0.48, 0.8)),
        quad_tilted = pdf_toward_quad(eye, light_corner, light_u, light_v);
    const pdf *parts[2] = {&cos_tilted, &quad_tilted};
    double w_bad[2] = {0.5, 0.3}, w50[2] = {0.5, 0.5};
    pdf mix_bad_weights = pdf_mixture(parts, w_bad, 2);
    assert_false(pdf_mixture_weights_valid(w_bad, 2));
    assert_false(pdf_valid(&mix_bad_weights));
    double negative[2] = {1.5, -0.5};
    assert_false(pdf_mixture_weights_valid(negative, 2));
    assert_false(pdf_mixture_weights_valid(w50, 0));
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
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    pdf_chart plane = pdf_chart_light_plane(eye, light_corner, light_u, light_v);
    assert_near(pdf_chart_integrate(&plane, one, NULL, q), MC_4PI, 1e-9);
    vec3 center = vec3_add(eye, vec3_make(3.0, -1.0, -0.5));
    pdf_chart both = pdf_chart_quad_and_cap(eye, light_corner, light_u, light_v, center, 0.8);
    vec3 a = vec3_sub(light_corner, eye), b = vec3_add(a, light_u), d = vec3_add(a, light_v);
    vec3 c = vec3_add(b, light_v);
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

/* --- negative controls ---------------------------------------------------
 * Each control is a catalog row with its density (and sampler) replaced. */

/* The light pdf without its cosine: dist^2 / A instead of
 * dist^2 / (|cos| A). */
static double value_no_cosine(const cat_state *s, const double x[3])
{
    vec3 d = vec3_make(x[0], x[1], x[2]);
    return pdf_value(s->object, d) * fabs(vec3_dot(d, s->object->as.quad.normal));
}

/* A mixture whose value is only the density of the component a renderer
 * happened to choose (here the cosine one) instead of the weighted sum. */
static double value_chosen_only(const cat_state *s, const double x[3])
{
    return pdf_value(s->object->as.mixture.components[0], vec3_make(x[0], x[1], x[2]));
}

/* The cone's solid angle from theta by the small-angle formula pi theta^2
 * instead of 2 pi (1 - cos theta). */
static double value_cone_from_theta(const cat_state *s, const double x[3])
{
    const pdf *p = s->object;
    double cos_max = p->as.sphere.cos_theta_max, theta = acos(cos_max);
    return vec3_dot(vec3_make(x[0], x[1], x[2]), p->as.sphere.frame.n) >= cos_max
               ? 1.0 / (MC_PI * theta * theta)
               : 0.0;
}

/* The book's random_to_sphere and its pdf from inside the sphere:
 * sqrt(1 - R^2 / d^2) of a negative number. */
static double book_cos_max(const pdf *p)
{
    vec3 a = vec3_sub(p->as.sphere.center, p->as.sphere.origin);
    double r = p->as.sphere.radius;
    return sqrt(1.0 - r * r / vec3_length_sq(a));
}

static double value_book_sphere(const cat_state *s, const double x[3])
{
    (void)x;
    return 1.0 / (MC_2PI * (1.0 - book_cos_max(s->object)));
}

static void generate_book_sphere(const cat_state *s, mc_rng *rng, double x[3])
{
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    double z = 1.0 + u2 * (book_cos_max(s->object) - 1.0), phi = MC_2PI * u1;
    double r = sqrt(1.0 - z * z);
    vec3 d = onb_to_world(&s->object->as.sphere.frame, vec3_make(cos(phi) * r, sin(phi) * r, z));
    x[0] = d.x, x[1] = d.y, x[2] = d.z;
}

/* A list that sums its items' densities instead of averaging them. */
static double value_list_sum(const cat_state *s, const double x[3])
{
    return 2.0 * pdf_value(s->object, vec3_make(x[0], x[1], x[2]));
}

/* The row of case `name` with its density (and, if not NULL, its
 * generator) replaced, into *row. */
static const cat_row *replaced(const char *name, cat_row *row,
                               double (*density)(const cat_state *, const double *),
                               void (*generate)(const cat_state *, mc_rng *, double *))
{
    const cat_row *r = NULL;
    assert_non_null(cat_find_case(name, &r));
    *row = *r;
    row->pdf = density;
    if (generate)
        row->sample_rng = generate;
    return row;
}

/* Seeds 3350 + i for the sampled controls. */
static void test_pdf_negative_controls(void **state)
{
    negctl *t = *state;
    static cat_row rows[6];
    static cat_state st[6];
    bool all = true;

    warp_case c = case_named("quad-tilted", replaced("quad-tilted", &rows[0], value_no_cosine, NULL),
                             &st[0]);
    c.name = "neg-light-missing-cosine";
    all &= negctl_record(t, c.name, "chi-square", warp_chi2_rejects(&c, N_CHI2, mc_test_seed(3350u)));

    /* Its normalization is exactly 1 (value is a component's density):
     * only the chi-square test can see this one. */
    c = case_named("mixture-0.5", replaced("mixture-0.5", &rows[1], value_chosen_only, NULL),
                   &st[1]);
    c.name = "neg-mixture-chosen-only";
    all &= negctl_record(t, c.name, "chi-square", warp_chi2_rejects(&c, N_CHI2, mc_test_seed(3351u)));

    /* Weights 0.5 and 0.3: the mixture keeps a pointer to the state's. */
    c = case_named("mixture-0.5", NULL, &st[2]);
    st[2].mix_weights[1] = 0.3;
    c.name = "neg-mixture-weights-0.5-0.3";
    all &= negctl_record(t, c.name, "normalization", warp_norm_rejects(&c));

    c = case_named("sphere-near", replaced("sphere-near", &rows[3], value_cone_from_theta, NULL),
                   &st[3]);
    c.name = "neg-cone-from-theta";
    all &= negctl_record(t, c.name, "normalization", warp_norm_rejects(&c));

    c = case_named("sphere-inside",
                   replaced("sphere-inside", &rows[4], value_book_sphere, generate_book_sphere),
                   &st[4]);
    c.name = "neg-book-sphere-inside";
    warp_domain d = warp_check_domain(&c, 100000u, mc_test_seed(3354u));
    all &= negctl_record(t, c.name, "domain", !warp_domain_ok(&d));

    c = case_named("list-quad-sphere", replaced("list-quad-sphere", &rows[5], value_list_sum, NULL),
                   &st[5]);
    c.name = "neg-list-sum";
    all &= negctl_record(t, c.name, "normalization", warp_norm_rejects(&c));

    all &= negctl_record(t, "neg-tiny-sphere-subtracted", "tiny-sphere accuracy (1e-12)",
                         !tiny_values_ok("subtracted", tiny_value_subtracted, eye));
    assert_true(all);
}

int main(void)
{
    struct CMUnitTest tests[64];
    size_t n = 0;
    warp_catalog_tests(families, 1, tests, &n, 56);
    const struct CMUnitTest own[] = {
        cmocka_unit_test(test_pdf_known_values),
        cmocka_unit_test(test_pdf_validity),
        cmocka_unit_test(test_pdf_validity_both_sides),
        cmocka_unit_test(test_pdf_mixture_zero_weight_never_chosen),
        cmocka_unit_test(test_pdf_chart_jacobians),
        cmocka_unit_test(test_pdf_tiny_sphere),
        cmocka_unit_test(test_pdf_negative_controls),
    };
    for (size_t k = 0; k < sizeof own / sizeof own[0]; k++)
        tests[n++] = own[k];
    return _cmocka_run_group_tests("test_pdf", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
