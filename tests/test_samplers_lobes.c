/* tests/test_samplers_lobes.c - the Phong lobe, GGX, the uniform cone, the
 * cone that a sphere subtends (Shirley, "Ray Tracing: The Rest of Your Life"
 * (v1.123), chapter 10, including the point inside the sphere, and spheres so
 * small or far, R / d down to 1e-150, that 1 - cos theta_max must be computed
 * without cancellation) and the area-to-solid-angle conversion of (v1.123)
 * chapter 7; this book's #ch-directions and #ch-lights. Every sampler and
 * parameter set passes chi-square, normalization, domain and round trip;
 * negative controls show the checks catching the bugs they are for.
 *
 * Statistics (seeds overridable with MC_TEST_SEED): chi-square with 10^6
 * samples per case at chi2_suite_alpha() = 1.57e-4 (Sidak: 1% over the
 * suite's <= 64 tests). Lobes are histogrammed in x = theta / (theta + s)
 * (s ~ the lobe's width) so that a narrow lobe covers many cells; cones in
 * (cos theta, phi) over [cos_theta_max, 1].
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/quad.h"
#include "mc/stats.h"
#include "samplers/cone.h"
#include "samplers/lobes.h"
#include "samplers/measure.h"
#include "samplers/planar.h"
#include "samplers/spherical.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

enum { N_CHI2 = 1000000 };
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* The rows of the catalog this program tests (chi-square, normalization,
 * domain and round trip of every case: tests built in main). Lobes are
 * histogrammed in the catalog's lobe chart, cones in (cos theta, phi). */
static const char *const families[] = {"lobes", "cone"};

/* The catalog's cone at cos_max, prepared into *s. */
static warp_case cone_case(const char *name, double cos_max, cat_state *s)
{
    char prm[64];
    snprintf(prm, sizeof prm, "cos_max=%.17g", cos_max);
    cat_case tc = {name, prm, {0, 0}, 0.0, 0, 0};
    return warp_case_of(cat_find("cone"), &tc, s);
}

/* --- the sphere as a cone ----------------------------------------------- */

/* A sphere of radius R at a distance of dist_ratio R from the origin, in
 * a direction that is not an axis. */
typedef struct sphere_view {
    double dist_ratio;
    vec3 center;
    double radius;
    double cos_max;
} sphere_view;

static sphere_view make_view(double dist_ratio)
{
    sphere_view v;
    v.dist_ratio = dist_ratio;
    v.radius = 1.3;
    v.center = vec3_scale(vec3_normalize(vec3_make(0.3, -1.1, 0.8)), dist_ratio * v.radius);
    v.cos_max = smp_sphere_cone_cos_theta_max(vec3_length_sq(v.center), v.radius);
    return v;
}

/* Whether the ray from the origin along unit w meets the sphere: the
 * roots of |t w - c|^2 = R^2 are t = w.c +- sqrt((w.c)^2 - |c|^2 + R^2);
 * it hits when they are real and the larger is positive. Written
 * independently of smp_sphere_cone_cos_theta_max. */
static bool ray_hits(vec3 w, const sphere_view *v)
{
    double b = vec3_dot(w, v->center);
    double disc = b * b - (vec3_length_sq(v->center) - v->radius * v->radius);
    return disc >= 0.0 && b + sqrt(disc) > 0.0;
}

/* The hit indicator over (cos theta, phi) about the direction of the
 * centre: the ray-sphere test itself is in world coordinates, the frame
 * only puts the silhouette on a line z = const, where nested adaptive
 * quadrature converges fast (a discontinuity along a curve crossing the
 * rectangle costs it millions of evaluations). */
typedef struct hit_ctx {
    const sphere_view *v;
    onb frame;
} hit_ctx;

static double hit_indicator(double z, double phi, void *params)
{
    const hit_ctx *h = params;
    return ray_hits(onb_to_world(&h->frame, smp_spherical_direction(z, phi)), h->v) ? 1.0 : 0.0;
}

/* cos_theta_max against geometry: the solid angle of the set of
 * directions that hit the sphere, by quadrature of the hit indicator over
 * the whole sphere of directions (world coordinates, the sphere off-axis),
 * must be the cone's 2 pi (1 - cos_theta_max), to 1e-6 (the rays are
 * cast in world coordinates; the quadrature's frame is only aligned with
 * the centre for speed). Inside the sphere
 * the cone is everything (4 pi) and the cosine -1, not NaN; on its surface
 * too (a superset of the hit hemisphere, see below). Then
 * the cone sampler carried to the sphere's direction by an ONB: every
 * sample (10^5, seed 5003) hits the sphere, allowing 1e-12 of round-off in
 * the discriminant for directions grazing the silhouette, and the
 * chi-square of the cone at that cos_theta_max passes. */
static void test_sphere_cone_geometry(void **state)
{
    (void)state;
    static const double ratios[] = {1.05, 2.0, 10.0, 1.0, 0.5, 0.0};
    uint64_t seed = mc_test_seed(5003u);
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    for (size_t k = 0; k < sizeof ratios / sizeof ratios[0]; k++) {
        sphere_view v = make_view(ratios[k]);
        if (ratios[k] == 0.0)
            v.center = vec3_make(0.0, 0.0, 0.0);
        if (ratios[k] == 1.0) {
            /* Exactly on the surface only the half-space toward the centre
             * hits (the formula's limit, cos 0, would be exact), but the
             * rounded centre is a few ulps inside or outside, so the ray test
             * is noise there. The agreed contract returns the whole sphere,
             * a superset of the hits, which keeps a cone-sampling estimator
             * unbiased. */
            assert_true(v.cos_max == -1.0);
            continue;
        }
        double solid = 0.0;
        hit_ctx h = {&v, onb_from_w(vec3_length(v.center) > 0.0 ? vec3_normalize(v.center)
                                                                : vec3_make(0.0, 0.0, 1.0))};
        (void)mc_quad_2d(q, (mc_fn2){hit_indicator, &h}, -1.0, 1.0, 0.0, MC_2PI, &solid, NULL);
        double cone = MC_2PI * (1.0 - v.cos_max);
        printf("sphere-cone d/R %.2f: cos_theta_max %.12f, hit solid angle %.10f, cone %.10f\n",
               ratios[k], v.cos_max, solid, cone);
        assert_true(isfinite(v.cos_max));
        assert_near(solid, cone, 1e-6 * cone);
        if (ratios[k] < 1.0)
            assert_true(v.cos_max == -1.0);
        if (vec3_length(v.center) == 0.0)
            continue;
        onb frame = onb_from_w(vec3_normalize(v.center));
        mc_rng rng = mc_rng_derive(seed, k);
        for (int i = 0; i < 100000; i++) {
            vec3 w = onb_to_world(&frame, smp_uniform_cone_sample(mc_rng_uniform(&rng),
                                                                  mc_rng_uniform(&rng), v.cos_max));
            double b = vec3_dot(w, v.center);
            double disc = b * b - (vec3_length_sq(v.center) - v.radius * v.radius);
            if (!(disc >= -1e-12 * vec3_length_sq(v.center)) || !(b > 0.0 || ratios[k] <= 1.0))
                fail_msg("d/R %.2f: sampled direction misses the sphere (disc %.3g, seed %llu)",
                         ratios[k], disc, (unsigned long long)seed);
        }
    }
    mc_quad_destroy(q);
    assert_true(smp_sphere_cone_cos_theta_max(4.0, 0.0) == 1.0);
}

/* The chi-square cases of the sphere-cone: cos_theta_max from
 * smp_sphere_cone_cos_theta_max at four distances (outside, far, on the
 * surface, inside). Seed 5004. */
static void test_sphere_cone_all_checks(void **state)
{
    (void)state;
    static cat_state st[4];
    warp_case cases[] = {
        cone_case("sphere-cone-d1.05R", make_view(1.05).cos_max, &st[0]),
        cone_case("sphere-cone-d2R", make_view(2.0).cos_max, &st[1]),
        cone_case("sphere-cone-d10R", make_view(10.0).cos_max, &st[2]),
        cone_case("sphere-cone-inside", make_view(0.5).cos_max, &st[3]),
    };
    warp_run_cases(cases, COUNT(cases), 0, N_CHI2, mc_test_seed(5004u));
}

/* --- thin cones: 1 - cos theta_max without cancellation ------------------ */

/* Spheres of radius R = ratio * d at distance d = 2.385 (squared distance
 * rounded once; both inputs are then taken as exact). */
static const double thin_ratios[] = {1e-6, 1e-8, 1e-10, 1e-150};
enum { N_THIN = (int)(sizeof thin_ratios / sizeof thin_ratios[0]) };
static const double thin_d = 2.385;

/* 1 - cos theta_max of those exact inputs, written independently of
 * samplers/cone.c: s = R^2 / d^2 in long double (64-bit significand),
 * then the series 1 - sqrt(1 - s) = s/2 + s^2/8 + s^3/16 + 5 s^4/128 + ...
 * For s <= 1e-12 the first omitted term, 7 s^5 / 256, is 1e-48 of the
 * sum, and the long double rounding ~1e-19: far below the 1e-12 the check
 * asks for. */
static long double exact_one_minus_cos(double dist_sq, double radius)
{
    long double s = (long double)radius * (long double)radius / (long double)dist_sq;
    return s / 2 + s * s / 8 + s * s * s / 16 + 5 * s * s * s * s / 128;
}

/* |got - exact| / exact in long double; inf when got is not finite. */
static double rel_error(double got, long double exact)
{
    return isfinite(got) ? (double)fabsl(((long double)got - exact) / exact) : (double)INFINITY;
}

/* The cone's density, per unit solid angle, the way a light sampler gets
 * it from (dist_sq, radius). */
typedef double (*cone_density_fn)(double dist_sq, double radius);

static double density_cap(double dist_sq, double radius)
{
    return smp_uniform_cap_pdf(vec3_make(0.0, 0.0, 1.0),
                               smp_sphere_cone_one_minus_cos(dist_sq, radius));
}

/* The negative control: 1 - cos theta_max by subtraction from the rounded
 * cosine, the route before the cap functions existed. */
static double density_subtracted(double dist_sq, double radius)
{
    return smp_uniform_cone_pdf(vec3_make(0.0, 0.0, 1.0),
                                smp_sphere_cone_cos_theta_max(dist_sq, radius));
}

/* The largest relative error of f against 1 / (2 pi (1 - cos theta_max))
 * over the thin ratios (inf when f is not finite), each printed. */
static double thin_density_error(const char *label, cone_density_fn f)
{
    const long double two_pi = 6.283185307179586476925286766559005768L;
    double worst = 0.0;
    for (int k = 0; k < N_THIN; k++) {
        double dist_sq = thin_d * thin_d, radius = thin_ratios[k] * thin_d;
        long double exact = 1 / (two_pi * exact_one_minus_cos(dist_sq, radius));
        double got = f(dist_sq, radius);
        double rel = rel_error(got, exact);
        printf("thin cone %-10s R/d %.0e: density %.17g, exact %.17Lg, relative error %.3g\n",
               label, thin_ratios[k], got, exact, rel);
        worst = rel > worst ? rel : worst;
    }
    return worst;
}

/* The cap's density for spheres at R / d = 1e-6, 1e-8, 1e-10 and 1e-150
 * matches 1 / (2 pi (1 - cos theta_max)) from the series to 1e-12
 * relative, and so does 1 - cos theta_max itself (deterministic: the
 * functions are a few roundings away from exact). The density integrates
 * to 1 over the solid angle in the cap's own coordinates (1 - cos theta,
 * phi), d omega = d(1 - cos theta) d phi, with the directions built here:
 * 1 over [0, h], exactly 0 over [h, 2h] beyond the rim. */
typedef struct thin_norm {
    double h, phi;
} thin_norm;

static double thin_norm_integrand(double t, void *params)
{
    const thin_norm *n = params;
    double omz = t * n->h, sin_theta = sqrt(omz * (2.0 - omz));
    vec3 w = vec3_make(sin_theta * cos(n->phi), sin_theta * sin(n->phi), 1.0 - omz);
    return smp_uniform_cap_pdf(w, n->h) * MC_2PI * n->h;
}

static void test_thin_cone_density(void **state)
{
    (void)state;
    assert_true(thin_density_error("cap", density_cap) <= 1e-12);
    mc_quad *q = mc_quad_create(1000);
    assert_non_null(q);
    for (int k = 0; k < N_THIN; k++) {
        double dist_sq = thin_d * thin_d, radius = thin_ratios[k] * thin_d;
        long double exact = exact_one_minus_cos(dist_sq, radius);
        double h = smp_sphere_cone_one_minus_cos(dist_sq, radius);
        double h_subtracted = 1.0 - smp_sphere_cone_cos_theta_max(dist_sq, radius);
        double rel = rel_error(h, exact);
        printf("thin cone R/d %.0e: 1 - cos theta_max %.17g, relative error %.3g "
               "(by subtraction %.3g)\n",
               thin_ratios[k], h, rel, rel_error(h_subtracted, exact));
        assert_true(rel <= 1e-12);
        thin_norm n = {h, 2.385};
        double inside = 0.0, beyond = 1.0;
        (void)mc_quad_1d(q, (mc_fn1){thin_norm_integrand, &n}, 0.0, 1.0, &inside, NULL);
        (void)mc_quad_1d(q, (mc_fn1){thin_norm_integrand, &n}, 1.0, 2.0, &beyond, NULL);
        assert_near(inside, 1.0, 1e-12);
        assert_true(beyond == 0.0);
    }
    mc_quad_destroy(q);
    /* The limits: inside the sphere the whole sphere (h = 2, 1 / (4 pi)),
     * a point has no cone and no density. */
    assert_true(smp_sphere_cone_one_minus_cos(1.0, 1.0) == 2.0);
    assert_near(density_cap(0.25, 1.0), MC_INV_4PI, 1e-17);
    assert_true(smp_sphere_cone_one_minus_cos(4.0, 0.0) == 0.0);
    assert_true(density_cap(4.0, 0.0) == 0.0);
}

/* A direction of the cone toward a sphere, drawn from (u1, u2). */
typedef vec3 (*cone_sample_fn)(double u1, double u2, double dist_sq, double radius);

static vec3 sample_cap(double u1, double u2, double dist_sq, double radius)
{
    return smp_uniform_cap_sample(u1, u2, smp_sphere_cone_one_minus_cos(dist_sq, radius));
}

/* The negative control: the cone sampled from the rounded cosine. */
static vec3 sample_subtracted(double u1, double u2, double dist_sq, double radius)
{
    return smp_uniform_cone_sample(u1, u2, smp_sphere_cone_cos_theta_max(dist_sq, radius));
}

/* Whether n directions of f at every thin ratio (streams seed, k) lie in
 * the cone, sin^2 theta = x^2 + y^2 <= R^2 / d^2 (1 + 1e-12, for the
 * rounding of both sides) with z > 0, have a positive cap density, and
 * fill it: V = sin^2 theta / sin^2 theta_max has mean
 * (1 - h / 3) / (2 - h) = 1/2 to 1e-13 for uniform directions in the
 * cone (1 - cos theta = u h, sin^2 = u h (2 - u h)); |z| < 4 against 1/2
 * (two-sided false alarm 6.3e-5 per ratio). */
static bool thin_samples_ok(cone_sample_fn f, int n, uint64_t seed)
{
    bool ok = true;
    for (int k = 0; k < N_THIN; k++) {
        double dist_sq = thin_d * thin_d, radius = thin_ratios[k] * thin_d;
        double sin2_max = thin_ratios[k] * thin_ratios[k];
        double h = smp_sphere_cone_one_minus_cos(dist_sq, radius);
        mc_rng rng = mc_rng_derive(seed, (uint64_t)k);
        mc_welford v = mc_welford_init();
        int outside = 0;
        for (int i = 0; i < n; i++) {
            double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
            vec3 w = f(u1, u2, dist_sq, radius);
            double sin2 = w.x * w.x + w.y * w.y;
            if (!(w.z > 0.0 && sin2 <= sin2_max * (1.0 + 1e-12) && smp_uniform_cap_pdf(w, h) > 0.0))
                outside++;
            mc_welford_add(&v, sin2 / sin2_max);
        }
        double z = mc_z_score(v.mean, 0.5, mc_welford_std_error(&v));
        printf("thin cone samples R/d %.0e: %d outside, spread mean %.5f (z %.2f, seed %llu)\n",
               thin_ratios[k], outside, v.mean, z, (unsigned long long)seed);
        ok = ok && outside == 0 && fabs(z) < 4.0;
    }
    return ok;
}

/* 10^4 cap samples per ratio, seed 5007: all inside, spread as uniform. */
static void test_thin_cone_samples(void **state)
{
    (void)state;
    assert_true(thin_samples_ok(sample_cap, 10000, mc_test_seed(5007u)));
}

/* --- area to solid angle ------------------------------------------------ */

/* A parallelogram light seen from a point, off-axis and tilted. */
typedef struct quad_view {
    vec3 origin, corner, eu, ev, normal;
    bool squared; /* false: the negative control with d instead of d^2 */
} quad_view;

static quad_view make_quad_view(void)
{
    quad_view v;
    v.origin = vec3_make(0.1, 0.2, -0.3);
    v.corner = vec3_make(-0.7, -0.4, 1.3);
    v.eu = vec3_make(1.3, 0.2, 0.1);
    v.ev = vec3_make(0.1, 0.9, 0.35);
    v.normal = vec3_normalize(vec3_cross(v.eu, v.ev));
    v.squared = true;
    return v;
}

static vec3 s_quad_dir(double u1, double u2, const warp_case *c)
{
    const quad_view *v = c->extra;
    vec3 q = smp_parallelogram_sample(u1, u2, v->corner, v->eu, v->ev);
    return vec3_normalize(vec3_sub(q, v->origin));
}

/* Where the ray from the origin along w meets the light's plane (t > 0 in
 * *t, or 0 when it does not). */
static vec3 plane_hit(const quad_view *v, vec3 w, double *t)
{
    double denom = vec3_dot(w, v->normal);
    *t = denom != 0.0 ? vec3_dot(vec3_sub(v->corner, v->origin), v->normal) / denom : 0.0;
    if (!(*t > 0.0))
        *t = 0.0;
    return vec3_madd(v->origin, w, *t);
}

/* The claimed solid-angle density of w: the area density where the ray
 * meets the light, converted by smp_area_to_solid_angle. */
static double p_quad_dir(vec3 w, const warp_case *c)
{
    const quad_view *v = c->extra;
    double t;
    vec3 q = plane_hit(v, w, &t);
    if (t == 0.0)
        return 0.0;
    double pa = smp_parallelogram_pdf(q, v->corner, v->eu, v->ev);
    return smp_area_to_solid_angle(pa, v->squared ? t * t : t, vec3_dot(w, v->normal));
}

/* The light's edge coordinates (a, b) of the point the direction hits,
 * solved here by Cramer's rule in the plane (not by the sampler's
 * inverse). */
static vec2 hit_coords(const quad_view *v, vec3 w)
{
    double t;
    vec3 d = vec3_sub(plane_hit(v, w, &t), v->corner);
    double uu = vec3_dot(v->eu, v->eu), uv = vec3_dot(v->eu, v->ev), vv = vec3_dot(v->ev, v->ev);
    double du = vec3_dot(d, v->eu), dv = vec3_dot(d, v->ev), det = uu * vv - uv * uv;
    return vec2_make((du * vv - dv * uv) / det, (dv * uu - du * uv) / det);
}

static void quad_to_param(vec3 w, const warp_case *c, double out[2])
{
    vec2 ab = hit_coords(c->extra, w);
    out[0] = ab.x;
    out[1] = ab.y;
}

/* The density of (a, b) implied by the claimed solid-angle density: times
 * the solid angle of the patch da db, |dw/da x dw/db| for w = r / |r|,
 * r = q(a, b) - origin, with dw/da = (u - w (w.u)) / |r|. This is the
 * definition of the surface element of the unit sphere, not the
 * cos / d^2 formula under test; the integral over [0,1]^2 is 1 only if the
 * conversion is right. */
static double quad_param_pdf(const double p[2], const warp_case *c)
{
    const quad_view *v = c->extra;
    vec3 r = vec3_sub(smp_parallelogram_sample(p[0], p[1], v->corner, v->eu, v->ev), v->origin);
    double len = vec3_length(r);
    vec3 w = vec3_scale(r, 1.0 / len);
    vec3 dwa = vec3_scale(vec3_sub(v->eu, vec3_scale(w, vec3_dot(w, v->eu))), 1.0 / len);
    vec3 dwb = vec3_scale(vec3_sub(v->ev, vec3_scale(w, vec3_dot(w, v->ev))), 1.0 / len);
    return p_quad_dir(w, c) * vec3_length(vec3_cross(dwa, dwb));
}

static bool quad_support(vec3 w, const warp_case *c)
{
    vec2 ab = hit_coords(c->extra, w);
    return ab.x >= -1e-12 && ab.x <= 1.0 + 1e-12 && ab.y >= -1e-12 && ab.y <= 1.0 + 1e-12;
}

static warp_case quad_case(const quad_view *v, const char *name)
{
    warp_case c = {.name = name,
                   .sample = s_quad_dir,
                   .pdf = p_quad_dir,
                   .in_support = quad_support,
                   .direction = true,
                   .to_param = quad_to_param,
                   .param_pdf = quad_param_pdf,
                   .lo = {0.0, 0.0},
                   .hi = {1.0, 1.0},
                   .cells = {50, 50},
                   .extra = v};
    return c;
}

/* Directions to uniform points of a parallelogram light have the density
 * d^2 / (A |cos theta_light|) per unit solid angle. The test histograms
 * them by where they hit the light, (a, b) in [0,1]^2, so the support is
 * the rectangle (a silhouette crossing the cells would make the per-cell
 * quadrature very slow), and converts the claimed density to (a, b) with
 * the sphere's own surface element: chi-square (50 x 50 cells) and
 * normalization. Edge cases: cos_light = 0 gives 0 and the sign of the
 * cosine does not matter. Seed 5005. */
static void test_area_to_solid_angle(void **state)
{
    (void)state;
    assert_true(smp_area_to_solid_angle(0.5, 4.0, 0.0) == 0.0);
    assert_near(smp_area_to_solid_angle(0.5, 4.0, -0.25), 8.0, 1e-15);
    assert_near(smp_area_to_solid_angle(0.5, 4.0, 0.25), 8.0, 1e-15);
    quad_view v = make_quad_view();
    warp_case c = quad_case(&v, "area-to-solid-angle-quad");
    warp_run_cases(&c, 1, 0, N_CHI2, mc_test_seed(5005u));
}

/* --- negative controls -------------------------------------------------- */

/* The cone's solid angle taken as the flat disc pi theta_max^2 (a pdf from
 * theta instead of cos theta). */
static double p_cone_from_theta(const cat_state *s, const double w[3])
{
    double theta_max = acos(s->p.cos_max);
    return w[2] >= s->p.cos_max ? 1.0 / (MC_PI * theta_max * theta_max) : 0.0;
}

static double p_phong_n(const cat_state *s, const double w[3])
{
    return w[2] >= 0.0 ? s->p.n * MC_INV_2PI * pow(w[2], s->p.n) : 0.0;
}

/* D(h) alone, per unit solid angle. */
static double p_ggx_no_cos(const cat_state *s, const double h[3])
{
    return h[2] > 0.0 ? smp_ggx_pdf(vec3_make(h[0], h[1], h[2]), s->p.alpha) / h[2] : 0.0;
}

/* The catalog row `name` with its pdf replaced, at the parameters and
 * lobe width given, prepared into *s; *row holds the copy. */
static warp_case control(const char *label, const char *name, cat_row *row,
                         double (*wrong)(const cat_state *, const double *), const char *params,
                         double lobe_width, cat_state *s)
{
    *row = *cat_find(name);
    row->pdf = wrong;
    row->invert = NULL;
    cat_case tc = {label, params, {0, 0}, lobe_width, 0, 0};
    return warp_case_of(row, &tc, s);
}

/* Seed 5006 for the chi-square control. */
static void test_negative_controls(void **state)
{
    negctl *t = *state;
    static cat_row rows[3];
    static cat_state st[3];
    warp_case cone = control("negctl-cone-from-theta", "cone", &rows[0], p_cone_from_theta,
                             "cos_max=0.8", 0.0, &st[0]);
    assert_true(negctl_record(t, "cone pdf from theta (pi theta_max^2)", "normalization",
                              warp_norm_rejects(&cone)));

    warp_case phong =
        control("negctl-phong-n", "phong", &rows[1], p_phong_n, "n=40", 0.22, &st[1]);
    assert_true(negctl_record(t, "Phong lobe normalized with n, not n + 1", "normalization",
                              warp_norm_rejects(&phong)));

    warp_case ggx =
        control("negctl-ggx-no-cos", "ggx", &rows[2], p_ggx_no_cos, "alpha=0.5", 0.5, &st[2]);
    assert_true(negctl_record(t, "GGX without its cos theta_h", "chi-square",
                              warp_chi2_rejects(&ggx, N_CHI2, mc_test_seed(5006u))));

    assert_true(negctl_record(t, "thin-cone density from 1 - rounded cos theta_max",
                              "thin-cone accuracy (1e-12)",
                              !(thin_density_error("subtracted", density_subtracted) <= 1e-12)));
    assert_true(negctl_record(t, "thin cone sampled from the rounded cos theta_max",
                              "thin-cone spread (z-test)",
                              !thin_samples_ok(sample_subtracted, 10000, mc_test_seed(5008u))));

    quad_view v = make_quad_view();
    v.squared = false;
    warp_case quad = quad_case(&v, "negctl-area-distance-not-squared");
    assert_true(negctl_record(t, "area to solid angle with d instead of d^2", "normalization",
                              warp_norm_rejects(&quad)));
}

int main(void)
{
    struct CMUnitTest tests[64];
    size_t n = 0;
    warp_catalog_tests(families, 2, tests, &n, 56);
    const struct CMUnitTest rest[] = {
        cmocka_unit_test(test_sphere_cone_geometry), cmocka_unit_test(test_sphere_cone_all_checks),
        cmocka_unit_test(test_thin_cone_density),    cmocka_unit_test(test_thin_cone_samples),
        cmocka_unit_test(test_area_to_solid_angle),  cmocka_unit_test(test_negative_controls),
    };
    for (size_t i = 0; i < sizeof rest / sizeof rest[0]; i++)
        tests[n++] = rest[i];
    return _cmocka_run_group_tests("test_samplers_lobes", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
