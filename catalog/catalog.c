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
    x[0] = (double)smp_discrete_cdf_sample(&s->cdf, u[0], NULL);
}

static double discrete_pdf(const cat_state *s, const double x[3])
{
    size_t k = index_of(s, x);
    return k == SIZE_MAX ? 0.0 : smp_discrete_cdf_pmf(&s->cdf, k);
}

static void alias_sample(const cat_state *s, const double *u, double x[3])
{
    x[0] = (double)smp_alias_sample(&s->alias, u[0], NULL);
}

static double alias_pdf(const cat_state *s, const double x[3])
{
    size_t k = index_of(s, x);
    return k == SIZE_MAX ? 0.0 : smp_alias_pmf(&s->alias, k);
}

/* The light pdfs look from the origin; the mixture's cosine is about +z. */
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
    if (!quad_prepare(s, err, errlen))
        return false;
    s->cosine = pdf_cosine(vec3_make(0.0, 0.0, 1.0));
    s->parts[0] = &s->cosine, s->parts[1] = &s->quad;
    s->mix_weights[0] = s->p.w, s->mix_weights[1] = 1.0 - s->p.w;
    s->mixture = pdf_mixture(s->parts, s->mix_weights, 2);
    s->object = &s->mixture;
    return true;
}

static bool sphere_light_prepare(cat_state *s, char *err, size_t errlen)
{
    const cat_values *p = &s->p;
    s->sphere = pdf_toward_sphere(vec3_make(0.0, 0.0, 0.0), p->center, p->radius);
    /* The density itself is accurate for any size (samplers/cone.h), but
     * the histogram's chart is (cos theta, phi): a direction's cosine
     * carries ~1e-16 of rounding, which must stay far below a cell of the
     * chart's width 1 - cos theta_max. */
    if (!pdf_valid(&s->sphere) || !(s->sphere.as.sphere.one_minus_cos >= 1e-9)) {
        snprintf(err, errlen,
                 "sphere-light: the sphere is too small to histogram in (cos theta, phi) "
                 "(needs R/d >= 4.5e-5)");
        return false;
    }
    /* The cone's chart starts at its rim: its edge is a cell edge. */
    s->dir_chart = pdf_chart_spherical(
        vec3_length_sq(p->center) > 0.0 ? p->center : vec3_make(0.0, 0.0, 1.0),
        s->sphere.as.sphere.cos_theta_max);
    s->object = &s->sphere;
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

/* Rows with two uniforms and a trio, by the point they give. */
#define PLANE(nm, dom, ch, tag)                                                                    \
    .name = nm, .domain = dom, .measure = "area", .family = "planar", .point = CAT_PLANAR,          \
    .uniforms = 2, .sample_u = tag##_sample, .pdf = tag##_pdf, .invert = tag##_invert,             \
    .chart = ch, .hi = 1.0
#define DIR(nm, dom, fam, lo_cos, n_u, smp, density, inv)                                          \
    .name = nm, .domain = dom, .measure = "solid-angle", .family = fam,                            \
    .point = CAT_DIRECTION, .uniforms = n_u, .sample_u = smp, .pdf = density, .invert = inv,         \
    .chart = CAT_CHART_DIRECTION, .lo = lo_cos, .hi = 1.0
#define REAL(nm, dom, upper, tag)                                                                  \
    .name = nm, .domain = dom, .measure = "length", .family = "warp1d", .point = CAT_REAL,         \
    .uniforms = 1, .sample_u = tag##_sample, .pdf = tag##_pdf, .chart = CAT_CHART_LINE,            \
    .hi = upper
#define INDEX(nm, tag)                                                                             \
    .name = nm, .domain = "{0..k-1}", .measure = "counting", .family = "discrete",                 \
    .point = CAT_INDEX, .params = {WEIGHTS}, .prepare = tables_prepare, .uniforms = 1,             \
    .sample_u = tag##_sample, .pdf = tag##_pdf, .chart = CAT_CHART_INDEX
#define OBJECT(nm, prep)                                                                           \
    .name = nm, .domain = "sphere(from-origin)", .measure = "solid-angle", .family = "pdf",        \
    .point = CAT_DIRECTION, .prepare = prep, .sample_rng = object_sample, .pdf = object_pdf,       \
    .chart = CAT_CHART_DIRECTION
/* A test case: name, parameters, cells, seed group and position. */
#define CASE(nm, prm, nx, ny, width, group, pos) {nm, prm, {nx, ny}, width, group, pos}

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
     .cases = {CASE("theta-phi", NULL, 0, 0, 0.0, 4002, 2)}},
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
    {REAL("linear", "[0,2]", 2.0, linear)},
    {REAL("quadratic", "[0,2]", 2.0, quadratic)},
    {REAL("sine", "[0,pi]", MC_PI, sine)},
    {INDEX("discrete", discrete)},
    {INDEX("alias", alias)},
    {OBJECT("quad-light", quad_prepare), .params = {QUAD_PARAMS}},
    {OBJECT("sphere-light", sphere_light_prepare),
     .params = {VECTOR("center", center, "0,0,2"),
                NUMBER("radius", radius, "1", 0.0, INF, true, false)}},
    {OBJECT("mixture", mixture_prepare),
     .params = {NUMBER("w", w, "0.5", 0.0, 1.0, false, false), QUAD_PARAMS}},
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
