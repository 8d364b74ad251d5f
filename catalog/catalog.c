/* catalog/catalog.c - the rows of the sampler catalog. The plumbing that
 * every row shares (parameters, sampling, charts) is in catalog/rows.c. */
#include "catalog/catalog.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "mc/constants.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/lobes.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/warp1d.h"

static vec3 get3(const double x[3])
{
    return vec3_make(x[0], x[1], x[2]);
}

static void put3(double x[3], vec3 d)
{
    x[0] = d.x, x[1] = d.y, x[2] = d.z;
}

static void put2(double u[2], vec2 v)
{
    u[0] = v.x, u[1] = v.y;
}

/* Adapters from the samplers' own signatures to the catalog's: a row's
 * functions take the state (for its parameters) and points as arrays. */
#define DIR_SAMPLE(tag, expr)                                                                      \
    static void tag##_sample(const cat_state *s, const double *u, double x[3])                     \
    {                                                                                              \
        (void)s;                                                                                   \
        put3(x, expr);                                                                             \
    }
#define DIR_PDF(tag, expr)                                                                         \
    static double tag##_pdf(const cat_state *s, const double x[3])                                 \
    {                                                                                              \
        (void)s;                                                                                   \
        vec3 w = get3(x);                                                                          \
        return expr;                                                                               \
    }
#define DIR_INVERT(tag, expr)                                                                      \
    static void tag##_invert(const cat_state *s, const double x[3], double u[2])                   \
    {                                                                                              \
        (void)s;                                                                                   \
        vec3 w = get3(x);                                                                          \
        put2(u, expr);                                                                             \
    }
/* smp_<stem>_{sample,pdf,invert}; DIR_TRIO_ARG passes the state's
 * parameter `arg` (s->p.n, ...) last. */
#define DIR_TRIO(tag, stem)                                                                        \
    DIR_SAMPLE(tag, smp_##stem##_sample(u[0], u[1]))                                               \
    DIR_PDF(tag, smp_##stem##_pdf(w))                                                              \
    DIR_INVERT(tag, smp_##stem##_invert(w))
#define DIR_TRIO_ARG(tag, stem, arg)                                                               \
    DIR_SAMPLE(tag, smp_##stem##_sample(u[0], u[1], arg))                                          \
    DIR_PDF(tag, smp_##stem##_pdf(w, arg))                                                         \
    DIR_INVERT(tag, smp_##stem##_invert(w, arg))
#define PLANE_TRIO(tag, stem)                                                                      \
    static void tag##_sample(const cat_state *s, const double *u, double x[3])                     \
    {                                                                                              \
        (void)s;                                                                                   \
        vec2 q = smp_##stem##_sample(u[0], u[1]);                                                  \
        x[0] = q.x, x[1] = q.y;                                                                    \
    }                                                                                              \
    static double tag##_pdf(const cat_state *s, const double x[3])                                 \
    {                                                                                              \
        (void)s;                                                                                   \
        return smp_##stem##_pdf(vec2_make(x[0], x[1]));                                            \
    }                                                                                              \
    static void tag##_invert(const cat_state *s, const double x[3], double u[2])                   \
    {                                                                                              \
        (void)s;                                                                                   \
        put2(u, smp_##stem##_invert(vec2_make(x[0], x[1])));                                       \
    }
#define REAL_TRIO(tag, stem)                                                                       \
    static void tag##_sample(const cat_state *s, const double *u, double x[3])                     \
    {                                                                                              \
        (void)s;                                                                                   \
        x[0] = smp_##stem##_sample(u[0]);                                                          \
    }                                                                                              \
    static double tag##_pdf(const cat_state *s, const double x[3])                                 \
    {                                                                                              \
        (void)s;                                                                                   \
        return smp_##stem##_pdf(x[0]);                                                             \
    }                                                                                              \
    static void tag##_invert(const cat_state *s, const double x[3], double u[2])                   \
    {                                                                                              \
        (void)s;                                                                                   \
        u[0] = smp_##stem##_invert(x[0]), u[1] = 0.0;                                              \
    }

PLANE_TRIO(square, unit_square)
PLANE_TRIO(disc_polar, disc_polar)
PLANE_TRIO(disc_conc, disc_concentric)
PLANE_TRIO(triangle, triangle)

/* The triangle's support, exactly (no slack beyond 4 ulps). */
static bool triangle_support(const cat_state *s, const double x[3])
{
    (void)s;
    return x[0] >= 0.0 && x[1] >= 0.0 && x[0] + x[1] <= 1.0 + 4.0 * 0x1p-52 && x[2] == 0.0;
}

DIR_TRIO(sphere, uniform_sphere)
DIR_SAMPLE(gaussian, smp_uniform_sphere_sample_gaussian(u[0], u[1], u[2], u[3]))
static void rejection_sample(const cat_state *s, mc_rng *rng, double x[3])
{
    (void)s;
    put3(x, smp_uniform_sphere_sample_rejection(rng));
}

DIR_TRIO(hemi, uniform_hemisphere)
DIR_SAMPLE(flip, smp_hemisphere_flip_sample(u[0], u[1]))
DIR_TRIO(cosine, cosine_hemisphere)
DIR_SAMPLE(malley, smp_cosine_hemisphere_sample_malley(u[0], u[1]))
DIR_INVERT(malley, smp_cosine_hemisphere_invert_malley(w))
DIR_SAMPLE(acos, smp_cosine_hemisphere_sample_acos(u[0], u[1]))
DIR_INVERT(acos, smp_cosine_hemisphere_invert_acos(w))
DIR_TRIO(theta_phi, theta_phi)
DIR_TRIO_ARG(phong, phong_lobe, s->p.n)
DIR_TRIO_ARG(ggx, ggx, s->p.alpha)
DIR_TRIO_ARG(cone, uniform_cone, s->p.cos_max)

REAL_TRIO(linear, linear)
REAL_TRIO(quadratic, quadratic)
REAL_TRIO(sine, sine)
REAL_TRIO(log_ends, log_ends)

/* Points of a parallelogram and of a sphere's surface in space. */
static void para_sample(const cat_state *s, const double *u, double x[3])
{
    put3(x, smp_parallelogram_sample(u[0], u[1], s->p.corner, s->p.u, s->p.v));
}

static double para_pdf(const cat_state *s, const double x[3])
{
    return smp_parallelogram_pdf(get3(x), s->p.corner, s->p.u, s->p.v);
}

static void para_invert(const cat_state *s, const double x[3], double u[2])
{
    put2(u, smp_parallelogram_invert(get3(x), s->p.corner, s->p.u, s->p.v));
}

/* In the plane within 1e-12 of the shape's size (the round-off of the
 * sample's additions) and inside the edges within 1e-12. */
static bool para_support(const cat_state *s, const double x[3])
{
    const cat_values *p = &s->p;
    double ab[2];
    cat_chart_point(s, x, ab);
    vec3 n = vec3_normalize(vec3_cross(p->u, p->v));
    double off = fabs(vec3_dot(vec3_sub(get3(x), p->corner), n));
    double tol = 1e-12 * (vec3_length(p->u) + vec3_length(p->v));
    return off <= tol && ab[0] >= -1e-12 && ab[0] <= 1.0 + 1e-12 && ab[1] >= -1e-12 &&
           ab[1] <= 1.0 + 1e-12;
}

static bool para_prepare(cat_state *s, char *err, size_t errlen)
{
    if (!(vec3_length_sq(vec3_cross(s->p.u, s->p.v)) > 0.0)) {
        snprintf(err, errlen, "%s: u and v are parallel", s->row->name);
        return false;
    }
    return true;
}

static void ball_sample(const cat_state *s, const double *u, double x[3])
{
    put3(x, smp_sphere_surface_sample(u[0], u[1], s->p.center, s->p.radius));
}

static double ball_pdf(const cat_state *s, const double x[3])
{
    return smp_sphere_surface_pdf(get3(x), s->p.center, s->p.radius);
}

static void ball_invert(const cat_state *s, const double x[3], double u[2])
{
    put2(u, smp_sphere_surface_invert(get3(x), s->p.center, s->p.radius));
}

/* On the sphere within 1e-12 of its radius (round-off). */
static bool ball_support(const cat_state *s, const double x[3])
{
    double r = s->p.radius;
    return fabs(vec3_length(vec3_sub(get3(x), s->p.center)) - r) <= 1e-12 * r;
}

/* --- rows whose parameters build something --------------------------- */

/* The cone's chart starts at its rim: the rim is a cell edge. */
static bool cone_prepare(cat_state *s, char *err, size_t errlen)
{
    (void)err, (void)errlen;
    s->dir_chart = pdf_chart_spherical(vec3_make(0.0, 0.0, 1.0), s->p.cos_max);
    return true;
}

static bool tables_prepare(cat_state *s, char *err, size_t errlen)
{
    const cat_values *p = &s->p;
    if (!smp_discrete_cdf_init(&s->cdf, p->weights, p->n_weights, s->cdf_storage) ||
        !smp_alias_init(&s->alias, p->weights, p->n_weights, s->alias_storage)) {
        snprintf(err, errlen, "%s: weights must be >= 0 with a positive sum", s->row->name);
        return false;
    }
    return true;
}

/* An outcome index k in [0, count), or SIZE_MAX for anything else (which
 * has probability 0). */
static size_t index_of(const cat_state *s, const double x[3])
{
    return x[0] >= 0.0 && x[0] == floor(x[0]) && x[0] < (double)s->p.n_weights ? (size_t)x[0]
                                                                             : SIZE_MAX;
}

static void discrete_sample(const cat_state *s, const double *u, double x[3])
{
    x[0] = (double)smp_discrete_cdf_sample(&s->cdf, u[0], &x[1]);
}

static double discrete_pdf(const cat_state *s, const double x[3])
{
    size_t k = index_of(s, x);
    return k == SIZE_MAX ? 0.0 : smp_discrete_cdf_pmf(&s->cdf, k);
}

static void alias_sample(const cat_state *s, const double *u, double x[3])
{
    x[0] = (double)smp_alias_sample(&s->alias, u[0], &x[1]);
}

static double alias_pdf(const cat_state *s, const double x[3])
{
    size_t k = index_of(s, x);
    return k == SIZE_MAX ? 0.0 : smp_alias_pmf(&s->alias, k);
}

/* The pdf objects look from the origin. */
static bool uniform_prepare(cat_state *s, char *err, size_t errlen)
{
    (void)err, (void)errlen;
    s->uniform = pdf_uniform_sphere();
    s->object = &s->uniform;
    return true;
}

/* The cosine lobe about the unit vector along `normal`; its chart covers
 * the whole sphere about that axis, so that normalization also weighs the
 * lower half, where the density must vanish. */
static bool cosine_prepare(cat_state *s, char *err, size_t errlen)
{
    vec3 n = s->p.normal;
    if (!(vec3_length_sq(n) > 0.0)) {
        snprintf(err, errlen, "%s: the normal must not be the zero vector", s->row->name);
        return false;
    }
    s->cosine = pdf_cosine(vec3_normalize(n));
    s->dir_chart = pdf_chart_spherical(s->cosine.as.cosine.frame.n, -1.0);
    s->object = &s->cosine;
    return true;
}

static bool quad_prepare(cat_state *s, char *err, size_t errlen)
{
    const cat_values *p = &s->p;
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    s->quad = pdf_toward_quad(o, p->corner, p->u, p->v);
    if (!pdf_valid(&s->quad)) {
        snprintf(err, errlen, "%s: degenerate light (u, v parallel, or the origin in its plane)",
                 s->row->name);
        return false;
    }
    s->dir_chart = pdf_chart_light_plane(o, p->corner, p->u, p->v);
    s->object = &s->quad;
    return true;
}

static bool mixture_prepare(cat_state *s, char *err, size_t errlen)
{
    if (!cosine_prepare(s, err, errlen) || !quad_prepare(s, err, errlen))
        return false;
    s->parts[0] = &s->cosine, s->parts[1] = &s->quad;
    s->mix_weights[0] = s->p.w, s->mix_weights[1] = 1.0 - s->p.w;
    s->mixture = pdf_mixture(s->parts, s->mix_weights, 2);
    s->object = &s->mixture;
    return true;
}

/* The sphere seen from the origin, into s->sphere. */
static bool sphere_prepare(cat_state *s, char *err, size_t errlen)
{
    const cat_values *p = &s->p;
    s->sphere = pdf_toward_sphere(vec3_make(0.0, 0.0, 0.0), p->center, p->radius);
    /* The density itself is accurate for any size (samplers/cone.h), but
     * the histogram's chart is (cos theta, phi): a direction's cosine
     * carries ~1e-16 of rounding, which must stay far below a cell of the
     * chart's width 1 - cos theta_max. */
    if (!pdf_valid(&s->sphere) || !(s->sphere.as.sphere.one_minus_cos >= 1e-9)) {
        snprintf(err, errlen,
                 "%s: the sphere is too small to histogram in (cos theta, phi) "
                 "(needs R/d >= 4.5e-5)",
                 s->row->name);
        return false;
    }
    return true;
}

static bool sphere_light_prepare(cat_state *s, char *err, size_t errlen)
{
    if (!sphere_prepare(s, err, errlen))
        return false;
    /* The cone's chart starts at its rim: its edge is a cell edge. */
    const cat_values *p = &s->p;
    s->dir_chart = pdf_chart_spherical(
        vec3_length_sq(p->center) > 0.0 ? p->center : vec3_make(0.0, 0.0, 1.0),
        s->sphere.as.sphere.cos_theta_max);
    s->object = &s->sphere;
    return true;
}

/* The angle between the unit vectors a and b, accurate near 0 and pi. */
static double angle_between(vec3 a, vec3 b)
{
    return atan2(vec3_length(vec3_cross(a, b)), vec3_dot(a, b));
}

/* The list of the parallelogram and the sphere, in the chart that sets the
 * light's (s, t) beside the sphere's cone. That chart needs the two apart
 * as seen from the origin: the sphere's cone must miss the cone about the
 * light's centre that holds its four corners (a sufficient condition). */
static bool list_prepare(cat_state *s, char *err, size_t errlen)
{
    if (!quad_prepare(s, err, errlen) || !sphere_prepare(s, err, errlen))
        return false;
    const cat_values *p = &s->p;
    vec3 mid = vec3_normalize(vec3_madd(vec3_madd(p->corner, p->u, 0.5), p->v, 0.5));
    double quad_half = 0.0;
    for (int k = 0; k < 4; k++) {
        vec3 x = vec3_madd(vec3_madd(p->corner, p->u, (double)(k & 1)), p->v, (double)(k >> 1));
        quad_half = fmax(quad_half, angle_between(mid, vec3_normalize(x)));
    }
    double cone_half = acos(s->sphere.as.sphere.cos_theta_max);
    if (s->sphere.as.sphere.one_minus_cos >= 2.0 ||
        !(angle_between(mid, s->sphere.as.sphere.frame.n) > quad_half + cone_half)) {
        snprintf(err, errlen, "%s: the light and the sphere overlap as seen from the origin",
                 s->row->name);
        return false;
    }
    s->dir_chart = pdf_chart_quad_and_cap(vec3_make(0.0, 0.0, 0.0), p->corner, p->u, p->v,
                                          p->center, p->radius);
    s->parts[0] = &s->quad, s->parts[1] = &s->sphere;
    s->list = pdf_list(s->parts, 2);
    s->object = &s->list;
    return true;
}

static void object_sample(const cat_state *s, mc_rng *rng, double x[3])
{
    put3(x, pdf_generate(s->object, rng));
}

static double object_pdf(const cat_state *s, const double x[3])
{
    return pdf_value(s->object, get3(x));
}

/* --- the table ----------------------------------------------------------- */

#define INF ((double)INFINITY)
#define NUMBER(key, field, def, lo, hi, lo_open, hi_open)                                          \
    {key, CAT_NUMBER, offsetof(cat_values, field), def, lo, hi, lo_open, hi_open}
#define VECTOR(key, field, def) {key, CAT_VECTOR, offsetof(cat_values, field), def, 0, 0, false, false}
#define WEIGHTS {"weights", CAT_LIST, offsetof(cat_values, weights), "1,2,3,4,5,6,7,8", 0, 0, false, false}
#define QUAD_PARAMS                                                                                \
    VECTOR("corner", corner, "-0.5,-0.5,1"), VECTOR("u", u, "1,0,0"), VECTOR("v", v, "0,1,0")
#define RADIUS NUMBER("radius", radius, "1", 0.0, INF, true, false)
#define NORMAL VECTOR("normal", normal, "0,0,1")

/* Rows with two uniforms and a trio, by the point they give. */
#define PLANE(nm, dom, ch, tag)                                                                    \
    .name = nm, .domain = dom, .measure = "area", .family = "planar", .point = CAT_PLANAR,          \
    .uniforms = 2, .sample_u = tag##_sample, .pdf = tag##_pdf, .invert = tag##_invert,             \
    .chart = ch, .hi = 1.0
#define SURFACE(nm, dom, ch, tag)                                                                  \
    .name = nm, .domain = dom, .measure = "area", .family = "planar", .point = CAT_POINT,           \
    .uniforms = 2, .sample_u = tag##_sample, .pdf = tag##_pdf, .invert = tag##_invert,             \
    .in_support = tag##_support, .chart = ch
#define DIR(nm, dom, fam, lo_cos, n_u, smp, density, inv)                                          \
    .name = nm, .domain = dom, .measure = "solid-angle", .family = fam,                            \
    .point = CAT_DIRECTION, .uniforms = n_u, .sample_u = smp, .pdf = density, .invert = inv,         \
    .chart = CAT_CHART_DIRECTION, .lo = lo_cos, .hi = 1.0
#define REAL(nm, dom, upper, tag)                                                                  \
    .name = nm, .domain = dom, .measure = "length", .family = "warp1d", .point = CAT_REAL,         \
    .uniforms = 1, .sample_u = tag##_sample, .pdf = tag##_pdf, .invert = tag##_invert,             \
    .chart = CAT_CHART_LINE, .hi = upper
#define INDEX(nm, tag)                                                                             \
    .name = nm, .domain = "{0..k-1}", .measure = "counting", .family = "discrete",                 \
    .point = CAT_INDEX, .params = {WEIGHTS}, .prepare = tables_prepare, .uniforms = 1,             \
    .sample_u = tag##_sample, .pdf = tag##_pdf, .chart = CAT_CHART_INDEX
#define OBJECT(nm, prep)                                                                           \
    .name = nm, .domain = "sphere(from-origin)", .measure = "solid-angle", .family = "pdf",        \
    .point = CAT_DIRECTION, .prepare = prep, .sample_rng = object_sample, .pdf = object_pdf,       \
    .chart = CAT_CHART_DIRECTION, .lo = -1.0, .hi = 1.0
/* A test case: name, parameters, cells, seed group and position. */
#define CASE(nm, prm, nx, ny, width, group, pos) {nm, prm, {nx, ny}, width, group, pos}

/* The pdf objects' test geometry: a tilted parallelogram light and
 * spheres far, near, around and beside the origin, in "high-entropy"
 * coordinates so that no missing factor or swapped axis can hide. */
#define TILTED_QUAD "corner=-0.7,-0.4,1.2 u=1,0.1,0.35 v=-0.15,0.8,0.45"
#define TILTED_NORMAL "normal=0.36,-0.48,0.8"
#define SIDE_SPHERE "center=3,-1,-0.5 radius=0.8"
#define WEIGHTS8 "weights=1.5,4,2.385,0.25,6,3.1,0.75,2"

/* BEGIN SNIPPET catalog_rows */
static const cat_row rows[] = {
    {PLANE("square", "unit-square", CAT_CHART_XY, square),
     .cases = {CASE("square", NULL, 50, 50, 0.0, 6001, 0)}},
    {PLANE("disc-polar", "unit-disc", CAT_CHART_DISC, disc_polar),
     .cases = {CASE("disc-polar", NULL, 0, 0, 0.0, 6001, 1)}},
    {PLANE("disc-concentric", "unit-disc", CAT_CHART_DISC, disc_conc),
     .cases = {CASE("disc-concentric", NULL, 0, 0, 0.0, 6001, 2)}},
    /* The square's cells are cut by the hypotenuse only along their
     * diagonal (the same count per axis), which keeps the nested
     * quadrature of the cut cells cheap. */
    {PLANE("triangle", "triangle(0,0)(1,0)(0,1)", CAT_CHART_XY, triangle),
     .in_support = triangle_support, .cases = {CASE("triangle", NULL, 40, 40, 0.0, 6001, 3)}},
    {SURFACE("parallelogram", "parallelogram", CAT_CHART_PARALLELOGRAM, para),
     .params = {VECTOR("corner", corner, "0,0,0"), VECTOR("u", u, "1,0,0"),
                VECTOR("v", v, "0,1,0")},
     .prepare = para_prepare,
     .cases = {CASE("parallelogram", "corner=0.3,-1.2,2.385 u=1.7,0.2,-0.4 v=-0.3,0.9,0.6", 50,
                    50, 0.0, 6001, 4)}},
    {SURFACE("sphere-surface", "sphere-surface", CAT_CHART_SURFACE, ball),
     .params = {VECTOR("center", center, "0,0,0"), RADIUS},
     .cases = {CASE("sphere-surface", "center=0.5,-1,2 radius=1.7", 0, 0, 0.0, 6001, 5)}},
    {DIR("sphere-inverse", "sphere", "sphere", -1.0, 2, sphere_sample, sphere_pdf, sphere_invert),
     .cases = {CASE("sphere-inverse", NULL, 0, 0, 0.0, 4001, 0)}},
    {DIR("sphere-gaussian", "sphere", "sphere", -1.0, 4, gaussian_sample, sphere_pdf, NULL),
     .cases = {CASE("sphere-gaussian", NULL, 0, 0, 0.0, 4001, 1)}},
    {DIR("sphere-rejection", "sphere", "sphere", -1.0, 0, NULL, sphere_pdf, NULL),
     .sample_rng = rejection_sample, .cases = {CASE("sphere-rejection", NULL, 0, 0, 0.0, 4001, 2)}},
    {DIR("hemisphere", "hemisphere(+z)", "hemisphere", 0.0, 2, hemi_sample, hemi_pdf, hemi_invert),
     .cases = {CASE("hemisphere", NULL, 0, 0, 0.0, 4002, 0)}},
    {DIR("hemisphere-flip", "hemisphere(+z)", "hemisphere", 0.0, 2, flip_sample, hemi_pdf, NULL),
     .cases = {CASE("hemisphere-flip", NULL, 0, 0, 0.0, 4002, 1)}},
    {DIR("cosine", "hemisphere(+z)", "hemisphere", 0.0, 2, cosine_sample, cosine_pdf,
         cosine_invert),
     .rim_zero = true, .cases = {CASE("cosine", NULL, 0, 0, 0.0, 4003, 0)}},
    {DIR("cosine-malley", "hemisphere(+z)", "hemisphere", 0.0, 2, malley_sample, cosine_pdf,
         malley_invert),
     .rim_zero = true, .cases = {CASE("cosine-malley", NULL, 0, 0, 0.0, 4003, 1)}},
    {DIR("cosine-acos", "hemisphere(+z)", "hemisphere", 0.0, 2, acos_sample, cosine_pdf,
         acos_invert),
     .rim_zero = true, .cases = {CASE("cosine-acos", NULL, 0, 0, 0.0, 4003, 2)}},
    {DIR("theta-phi", "hemisphere(+z)", "hemisphere", 0.0, 2, theta_phi_sample, theta_phi_pdf,
         theta_phi_invert),
     .pole_infinite = true, .cases = {CASE("theta-phi", NULL, 0, 0, 0.0, 4002, 2)}},
    /* Lobe widths of the tests' charts: cos^n falls to 1/e at
     * theta ~ sqrt(2/n); GGX's D is concentrated within theta ~ alpha. */
    {DIR("phong", "hemisphere(+z)", "lobes", 0.0, 2, phong_sample, phong_pdf, phong_invert),
     .params = {NUMBER("n", n, "40", 0.0, INF, false, false)}, .rim_zero = true,
     .cases = {CASE("phong-n1", "n=1", 0, 0, 0.8, 5001, 0),
               CASE("phong-n40", "n=40", 0, 0, 0.22, 5001, 1)}},
    {DIR("ggx", "hemisphere(+z)", "lobes", 0.0, 2, ggx_sample, ggx_pdf, ggx_invert),
     .params = {NUMBER("alpha", alpha, "0.5", 0.0, 1.0, true, false)}, .rim_zero = true,
     .cases = {CASE("ggx-a0.5", "alpha=0.5", 0, 0, 0.5, 5001, 2),
               CASE("ggx-a0.25", "alpha=0.25", 0, 0, 0.25, 5001, 3),
               CASE("ggx-a0.1", "alpha=0.1", 0, 0, 0.1, 5001, 4)}},
    {DIR("cone", "cone(+z)", "cone", 0.0, 2, cone_sample, cone_pdf, cone_invert),
     .params = {NUMBER("cos_max", cos_max, "0.8", -1.0, 1.0, false, true)},
     .prepare = cone_prepare,
     .cases = {CASE("cone-0.8", "cos_max=0.8", 0, 0, 0.0, 5002, 0),
               CASE("cone-0.2", "cos_max=0.2", 0, 0, 0.0, 5002, 1),
               CASE("cone--0.5", "cos_max=-0.5", 0, 0, 0.0, 5002, 2)}},
    /* 1D: 64 equal cells. */
    {REAL("linear", "[0,2]", 2.0, linear), .cases = {CASE("linear", NULL, 64, 1, 0.0, 4101, 0)}},
    {REAL("quadratic", "[0,2]", 2.0, quadratic),
     .cases = {CASE("quadratic", NULL, 64, 1, 0.0, 4101, 1)}},
    {REAL("sine", "[0,pi]", MC_PI, sine), .cases = {CASE("sine", NULL, 64, 1, 0.0, 4101, 2)}},
    {REAL("log-ends", "[0,pi]", MC_PI, log_ends),
     .cases = {CASE("log-ends", NULL, 64, 1, 0.0, 4101, 3)}},
    {INDEX("discrete", discrete), .cases = {CASE("discrete-8", WEIGHTS8, 0, 0, 0.0, 5101, 0)}},
    {INDEX("alias", alias), .cases = {CASE("alias-8", WEIGHTS8, 0, 0, 0.0, 5101, 1)}},
    /* The pdf objects: (cos theta, phi) charts in 40 x 80 cells, the
     * light-plane chart in its 120 x 90 (30 cells per unit, so that the
     * light's edges are cell edges), the quad-and-cap chart in 60 x 30. */
    {OBJECT("quad-light", quad_prepare), .params = {QUAD_PARAMS},
     .cases = {CASE("quad-tilted", TILTED_QUAD, 0, 0, 0.0, 3303, 4),
               CASE("quad-below", "corner=-0.5,2,-0.1 u=0,0,0.5 v=0.7,0,0", 0, 0, 0.0, 3303, 5)}},
    {OBJECT("sphere-light", sphere_light_prepare),
     .params = {VECTOR("center", center, "0,0,2"), RADIUS},
     .cases = {CASE("sphere-far", "center=3,4,12 radius=1", 40, 80, 0.0, 3303, 6),
               CASE("sphere-near", "center=0.4,-1.1,1.5 radius=1.5", 40, 80, 0.0, 3303, 7),
               CASE("sphere-inside", "center=0.2,0.3,-0.3 radius=2", 40, 80, 0.0, 3303, 8),
               CASE("sphere-side", SIDE_SPHERE, 40, 80, 0.0, 3303, 12)}},
    {OBJECT("mixture", mixture_prepare),
     .params = {NUMBER("w", w, "0.5", 0.0, 1.0, false, false), QUAD_PARAMS, NORMAL},
     .cases = {CASE("mixture-0.5", "w=0.5 " TILTED_NORMAL " " TILTED_QUAD, 0, 0, 0.0, 3303, 9),
               CASE("mixture-0.2", "w=0.2 " TILTED_NORMAL " " TILTED_QUAD, 0, 0, 0.0, 3303, 10)}},
    {OBJECT("uniform-pdf", uniform_prepare),
     .cases = {CASE("uniform", NULL, 40, 80, 0.0, 3303, 0)}},
    {OBJECT("cosine-pdf", cosine_prepare), .params = {NORMAL},
     .cases = {CASE("cosine-tilted", TILTED_NORMAL, 40, 80, 0.0, 3303, 1),
               CASE("cosine-near-minus-z", "normal=1e-7,-2e-8,-1", 40, 80, 0.0, 3303, 2),
               CASE("cosine-x", "normal=1,0,0", 40, 80, 0.0, 3303, 3)}},
    {OBJECT("light-list", list_prepare),
     .params = {QUAD_PARAMS, VECTOR("center", center, "0,3,0.5"), RADIUS},
     .cases = {CASE("list-quad-sphere", TILTED_QUAD " " SIDE_SPHERE, 60, 30, 0.0, 3303, 11)}},
};
/* END SNIPPET catalog_rows */

size_t cat_count(void)
{
    return sizeof rows / sizeof rows[0];
}

const cat_row *cat_at(size_t i)
{
    return i < cat_count() ? &rows[i] : NULL;
}
