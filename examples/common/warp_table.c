/* examples/common/warp_table.c - the entries of `warp` and their plumbing. */
#include "examples/common/warp_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/lobes.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/spherical.h"
#include "samplers/warp1d.h"

/* How an entry samples and evaluates: plain function pointers where the
 * warp takes only uniforms, a special case otherwise. */
typedef enum kind {
    K_DIR2,     /* vec3 f(u1, u2), pdf(vec3) */
    K_PLANE2,   /* vec2 f(u1, u2), pdf(vec2) */
    K_REAL1,    /* double f(u), pdf(double) */
    K_GAUSSIAN, /* four uniforms */
    K_REJECTION,
    K_PHONG,
    K_GGX,
    K_CONE,
    K_DISCRETE,
    K_ALIAS,
    K_PDF /* a pdf object of pdf/pdf.h: quad-light, sphere-light, mixture */
} kind;

/* How the goodness of fit histograms points: the point itself, a disc
 * point as (r^2, phi) (d area = d(r^2) d phi / 2), or a direction in the
 * chart warp_prepare chose. */
typedef enum gof_chart { G_IDENTITY, G_DISC, G_DIRECTION } gof_chart;

struct warp_entry {
    const char *name, *domain, *measure, *params;
    warp_point point;
    kind k;
    gof_chart chart;
    double lo, hi; /* G_IDENTITY of a real: the interval; G_DIRECTION: cos theta range about +z */
    vec3 (*dir2)(double, double);
    double (*dir_pdf)(vec3);
    vec2 (*plane2)(double, double);
    double (*plane_pdf)(vec2);
    double (*real1)(double);
    double (*real_pdf)(double);
};

/* Table rows by family; the unused function pointers stay NULL. */
#define DIR(name, domain, lo, f, pdf)                                                              \
    {name, domain, "solid-angle", "-", WARP_DIRECTION, K_DIR2, G_DIRECTION, lo, 1.0,             \
     f, pdf, NULL, NULL, NULL, NULL}
#define PLANE(name, domain, chart, f, pdf)                                                         \
    {name, domain, "area", "-", WARP_PLANAR, K_PLANE2, chart, 0.0, 1.0,                          \
     NULL, NULL, f, pdf, NULL, NULL}
#define REAL(name, domain, hi, f, pdf)                                                             \
    {name, domain, "length", "-", WARP_REAL, K_REAL1, G_IDENTITY, 0.0, hi,                       \
     NULL, NULL, NULL, NULL, f, pdf}
#define SPECIAL(name, domain, measure, params, point, k, chart, lo)                                \
    {name, domain, measure, params, point, k, chart, lo, 1.0, NULL, NULL, NULL, NULL, NULL, NULL}

static const char QUAD_PARAMS[] = "corner=-0.5,-0.5,1 u=1,0,0 v=0,1,0";

/* BEGIN SNIPPET warp_entries */
static const warp_entry entries[] = {
    PLANE("square", "unit-square", G_IDENTITY, smp_unit_square_sample, smp_unit_square_pdf),
    PLANE("disc-polar", "unit-disc", G_DISC, smp_disc_polar_sample, smp_disc_polar_pdf),
    PLANE("disc-concentric", "unit-disc", G_DISC, smp_disc_concentric_sample,
          smp_disc_concentric_pdf),
    PLANE("triangle", "triangle(0,0)(1,0)(0,1)", G_IDENTITY, smp_triangle_sample, smp_triangle_pdf),
    DIR("sphere-inverse", "sphere", -1.0, smp_uniform_sphere_sample, smp_uniform_sphere_pdf),
    SPECIAL("sphere-gaussian", "sphere", "solid-angle", "-", WARP_DIRECTION, K_GAUSSIAN,
            G_DIRECTION, -1.0),
    SPECIAL("sphere-rejection", "sphere", "solid-angle", "-", WARP_DIRECTION, K_REJECTION,
            G_DIRECTION, -1.0),
    DIR("hemisphere", "hemisphere(+z)", 0.0, smp_uniform_hemisphere_sample,
        smp_uniform_hemisphere_pdf),
    DIR("hemisphere-flip", "hemisphere(+z)", 0.0, smp_hemisphere_flip_sample,
        smp_uniform_hemisphere_pdf),
    DIR("cosine", "hemisphere(+z)", 0.0, smp_cosine_hemisphere_sample, smp_cosine_hemisphere_pdf),
    DIR("cosine-malley", "hemisphere(+z)", 0.0, smp_cosine_hemisphere_sample_malley,
        smp_cosine_hemisphere_pdf),
    DIR("cosine-acos", "hemisphere(+z)", 0.0, smp_cosine_hemisphere_sample_acos,
        smp_cosine_hemisphere_pdf),
    DIR("theta-phi", "hemisphere(+z)", 0.0, smp_theta_phi_sample, smp_theta_phi_pdf),
    SPECIAL("phong", "hemisphere(+z)", "solid-angle", "n=40", WARP_DIRECTION, K_PHONG, G_DIRECTION,
            0.0),
    SPECIAL("ggx", "hemisphere(+z)", "solid-angle", "alpha=0.5", WARP_DIRECTION, K_GGX, G_DIRECTION,
            0.0),
    SPECIAL("cone", "cone(+z)", "solid-angle", "cos_max=0.8", WARP_DIRECTION, K_CONE, G_DIRECTION,
            0.0),
    REAL("linear", "[0,2]", 2.0, smp_linear_sample, smp_linear_pdf),
    REAL("quadratic", "[0,2]", 2.0, smp_quadratic_sample, smp_quadratic_pdf),
    REAL("sine", "[0,pi]", MC_PI, smp_sine_sample, smp_sine_pdf),
    SPECIAL("discrete", "{0..k-1}", "counting", "weights=1,2,3,4,5,6,7,8", WARP_INDEX, K_DISCRETE,
            G_IDENTITY, 0.0),
    SPECIAL("alias", "{0..k-1}", "counting", "weights=1,2,3,4,5,6,7,8", WARP_INDEX, K_ALIAS,
            G_IDENTITY, 0.0),
    SPECIAL("quad-light", "sphere(from-origin)", "solid-angle", QUAD_PARAMS, WARP_DIRECTION, K_PDF,
            G_DIRECTION, 0.0),
    SPECIAL("sphere-light", "sphere(from-origin)", "solid-angle", "center=0,0,2 radius=1",
            WARP_DIRECTION, K_PDF, G_DIRECTION, 0.0),
    SPECIAL("mixture", "sphere(from-origin)", "solid-angle",
            "w=0.5 corner=-0.5,-0.5,1 u=1,0,0 v=0,1,0", WARP_DIRECTION, K_PDF, G_DIRECTION, 0.0),
};
/* END SNIPPET warp_entries */

size_t warp_count(void)
{
    return sizeof entries / sizeof entries[0];
}

const warp_entry *warp_at(size_t i)
{
    return i < warp_count() ? &entries[i] : NULL;
}

const warp_entry *warp_find(const char *name)
{
    for (size_t i = 0; i < warp_count(); i++)
        if (strcmp(entries[i].name, name) == 0)
            return &entries[i];
    return NULL;
}

const char *warp_name(const warp_entry *e) { return e->name; }
const char *warp_domain(const warp_entry *e) { return e->domain; }
const char *warp_measure(const warp_entry *e) { return e->measure; }
const char *warp_param_defaults(const warp_entry *e) { return e->params; }
warp_point warp_point_kind(const warp_entry *e) { return e->point; }

int warp_point_dims(const warp_entry *e)
{
    return e->point == WARP_DIRECTION ? 3 : (e->point == WARP_PLANAR ? 2 : 1);
}

/* True when `key` is one of the entry's parameters. */
static bool has_key(const warp_entry *e, const char *key, size_t len)
{
    for (const char *p = e->params; *p;) {
        const char *eq = strchr(p, '=');
        if (!eq)
            return false;
        if ((size_t)(eq - p) == len && strncmp(p, key, len) == 0)
            return true;
        const char *sp = strchr(eq, ' ');
        p = sp ? sp + 1 : eq + strlen(eq);
    }
    return false;
}

/* Parses up to max comma-separated finite numbers; returns the count, or
 * 0 when anything is malformed or there are more than max. */
static size_t parse_numbers(const char *s, double *out, size_t max)
{
    size_t n = 0;
    while (*s) {
        char *end = NULL;
        double v = strtod(s, &end);
        if (end == s || !isfinite(v) || n == max || (*end && *end != ','))
            return 0;
        out[n++] = v;
        s = *end ? end + 1 : end;
        if (*end && !*s)
            return 0; /* a trailing comma */
    }
    return n;
}

bool warp_set_param(const warp_entry *e, warp_params *p, const char *assignment, char *err,
                    size_t errlen)
{
    const char *eq = strchr(assignment, '=');
    size_t len = eq ? (size_t)(eq - assignment) : strlen(assignment);
    if (!eq || !has_key(e, assignment, len)) {
        snprintf(err, errlen, "%s has no parameter '%.*s'", e->name, (int)len, assignment);
        return false;
    }
    const char *v = eq + 1;
    double x[3];
    bool ok = true;
    if (len == 7 && strncmp(assignment, "weights", 7) == 0) {
        p->n_weights = parse_numbers(v, p->weights, WARP_MAX_WEIGHTS);
        ok = p->n_weights > 0;
    } else if (len == 6 &&
               (strncmp(assignment, "corner", 6) == 0 || strncmp(assignment, "center", 6) == 0)) {
        ok = parse_numbers(v, x, 3) == 3;
        if (ok)
            *(assignment[1] == 'o' ? &p->corner : &p->center) = vec3_make(x[0], x[1], x[2]);
    } else if (len == 1 && (assignment[0] == 'u' || assignment[0] == 'v')) {
        ok = parse_numbers(v, x, 3) == 3;
        if (ok)
            *(assignment[0] == 'u' ? &p->u : &p->v) = vec3_make(x[0], x[1], x[2]);
    } else {
        double *dst = len == 1 && assignment[0] == 'n' ? &p->n
                      : len == 1                       ? &p->w
                      : assignment[0] == 'a'           ? &p->alpha
                      : assignment[0] == 'c'           ? &p->cos_max
                                                       : &p->radius;
        ok = parse_numbers(v, dst, 1) == 1;
    }
    if (!ok)
        snprintf(err, errlen, "%s: malformed value in '%s'", e->name, assignment);
    return ok;
}

void warp_defaults(const warp_entry *e, warp_params *p)
{
    memset(p, 0, sizeof *p);
    char err[200];
    char buf[256];
    snprintf(buf, sizeof buf, "%s", e->params);
    /* The defaults are the entry's own parameter string, parsed. */
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        if (strcmp(tok, "-") != 0)
            (void)warp_set_param(e, p, tok, err, sizeof err);
}

/* The light pdfs look from the origin; the mixture's cosine is about +z. */
static bool prepare_pdf(const warp_entry *e, warp_state *s, char *err, size_t errlen)
{
    const warp_params *p = &s->p;
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    if (strcmp(e->name, "sphere-light") == 0) {
        if (!(p->radius > 0.0)) {
            snprintf(err, errlen, "sphere-light: radius must be > 0");
            return false;
        }
        s->sphere = pdf_toward_sphere(o, p->center, p->radius);
        double c = s->sphere.as.sphere.cos_theta_max;
        /* The density itself is accurate for any size (samplers/cone.h),
         * but the histogram's chart is (cos theta, phi): a direction's
         * cosine carries ~1e-16 of rounding, which must stay far below a
         * cell of the chart's width 1 - cos theta_max. */
        if (!pdf_valid(&s->sphere) || !(s->sphere.as.sphere.one_minus_cos >= 1e-9)) {
            snprintf(err, errlen,
                     "sphere-light: the sphere is too small to histogram in (cos theta, phi) "
                     "(needs R/d >= 4.5e-5)");
            return false;
        }
        /* The cone's chart starts at its rim: its edge is a cell edge. */
        s->chart = pdf_chart_spherical(
            vec3_length_sq(p->center) > 0.0 ? p->center : vec3_make(0.0, 0.0, 1.0), c);
        return true;
    }
    s->quad = pdf_toward_quad(o, p->corner, p->u, p->v);
    if (!pdf_valid(&s->quad)) {
        snprintf(err, errlen, "%s: degenerate light (u, v parallel, or the origin in its plane)",
                 e->name);
        return false;
    }
    s->chart = pdf_chart_light_plane(o, p->corner, p->u, p->v);
    if (strcmp(e->name, "mixture") == 0) {
        if (!(p->w >= 0.0 && p->w <= 1.0)) {
            snprintf(err, errlen, "mixture: w must be in [0, 1]");
            return false;
        }
        s->cosine = pdf_cosine(vec3_make(0.0, 0.0, 1.0));
        s->parts[0] = &s->cosine, s->parts[1] = &s->quad;
        s->mix_weights[0] = p->w, s->mix_weights[1] = 1.0 - p->w;
        s->mixture = pdf_mixture(s->parts, s->mix_weights, 2);
    }
    return true;
}

bool warp_prepare(const warp_entry *e, const warp_params *p, warp_state *s, char *err,
                  size_t errlen)
{
    memset(s, 0, sizeof *s);
    s->p = *p;
    s->chart = pdf_chart_spherical(vec3_make(0.0, 0.0, 1.0), e->lo);
    switch (e->k) {
    case K_PHONG:
        if (!(p->n >= 0.0)) {
            snprintf(err, errlen, "phong: n must be >= 0");
            return false;
        }
        return true;
    case K_GGX:
        if (!(p->alpha > 0.0 && p->alpha <= 1.0)) {
            snprintf(err, errlen, "ggx: alpha must be in (0, 1]");
            return false;
        }
        return true;
    case K_CONE:
        if (!(p->cos_max >= -1.0 && p->cos_max < 1.0)) {
            snprintf(err, errlen, "cone: cos_max must be in [-1, 1)");
            return false;
        }
        s->chart = pdf_chart_spherical(vec3_make(0.0, 0.0, 1.0), p->cos_max);
        return true;
    case K_DISCRETE:
    case K_ALIAS:
        if (!smp_discrete_cdf_init(&s->cdf, p->weights, p->n_weights, s->cdf_storage) ||
            !smp_alias_init(&s->alias, p->weights, p->n_weights, s->alias_storage)) {
            snprintf(err, errlen, "%s: weights must be >= 0 with a positive sum", e->name);
            return false;
        }
        return true;
    case K_PDF:
        return prepare_pdf(e, s, err, errlen);
    default:
        return true;
    }
}

static const pdf *entry_pdf(const warp_entry *e, const warp_state *s)
{
    if (strcmp(e->name, "quad-light") == 0)
        return &s->quad;
    return strcmp(e->name, "sphere-light") == 0 ? &s->sphere : &s->mixture;
}

static void put3(double out[3], vec3 d)
{
    out[0] = d.x, out[1] = d.y, out[2] = d.z;
}

void warp_sample(const warp_entry *e, const warp_state *s, mc_rng *rng, double out[3])
{
    double u1, u2, u3, u4;
    switch (e->k) {
    case K_DIR2:
        u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        put3(out, e->dir2(u1, u2));
        return;
    case K_PLANE2: {
        u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        vec2 x = e->plane2(u1, u2);
        out[0] = x.x, out[1] = x.y;
        return;
    }
    case K_REAL1:
        out[0] = e->real1(mc_rng_uniform(rng));
        return;
    case K_GAUSSIAN:
        u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        u3 = mc_rng_uniform(rng), u4 = mc_rng_uniform(rng);
        put3(out, smp_uniform_sphere_sample_gaussian(u1, u2, u3, u4));
        return;
    case K_REJECTION:
        put3(out, smp_uniform_sphere_sample_rejection(rng));
        return;
    case K_PHONG:
    case K_GGX:
    case K_CONE:
        u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        put3(out, e->k == K_PHONG ? smp_phong_lobe_sample(u1, u2, s->p.n)
                  : e->k == K_GGX ? smp_ggx_sample(u1, u2, s->p.alpha)
                                  : smp_uniform_cone_sample(u1, u2, s->p.cos_max));
        return;
    case K_DISCRETE:
        out[0] = (double)smp_discrete_cdf_sample(&s->cdf, mc_rng_uniform(rng), NULL);
        return;
    case K_ALIAS:
        out[0] = (double)smp_alias_sample(&s->alias, mc_rng_uniform(rng), NULL);
        return;
    case K_PDF:
        put3(out, pdf_generate(entry_pdf(e, s), rng));
        return;
    }
}

double warp_density(const warp_entry *e, const warp_state *s, const double x[3])
{
    vec3 d = vec3_make(x[0], x[1], x[2]);
    vec2 q = vec2_make(x[0], x[1]);
    /* An index is a whole number in [0, k); anything else has probability 0. */
    size_t k = x[0] >= 0.0 && x[0] == floor(x[0]) && x[0] < (double)s->p.n_weights ? (size_t)x[0]
                                                                                   : SIZE_MAX;
    switch (e->k) {
    case K_DIR2:
        return e->dir_pdf(d);
    case K_PLANE2:
        return e->plane_pdf(q);
    case K_REAL1:
        return e->real_pdf(x[0]);
    case K_GAUSSIAN:
    case K_REJECTION:
        return smp_uniform_sphere_pdf(d);
    case K_PHONG:
        return smp_phong_lobe_pdf(d, s->p.n);
    case K_GGX:
        return smp_ggx_pdf(d, s->p.alpha);
    case K_CONE:
        return smp_uniform_cone_pdf(d, s->p.cos_max);
    case K_DISCRETE:
        return k == SIZE_MAX ? 0.0 : smp_discrete_cdf_pmf(&s->cdf, k);
    case K_ALIAS:
        return k == SIZE_MAX ? 0.0 : smp_alias_pmf(&s->alias, k);
    case K_PDF:
        return pdf_value(entry_pdf(e, s), d);
    }
    return 0.0;
}

/* --- goodness of fit ------------------------------------------------------ */

static void gof_sample(mc_rng *rng, void *ctx, double out[2])
{
    const warp_gof_ctx *g = ctx;
    double x[3] = {0.0, 0.0, 0.0};
    warp_sample(g->e, g->s, rng, x);
    switch (g->e->chart) {
    case G_IDENTITY:
        /* An index k is histogrammed as k + 1/2, the middle of cell k. */
        out[0] = g->e->point == WARP_INDEX ? x[0] + 0.5 : x[0], out[1] = x[1];
        return;
    case G_DISC:
        out[0] = x[0] * x[0] + x[1] * x[1];
        out[1] = smp_spherical_phi(vec3_make(x[0], x[1], 0.0));
        return;
    case G_DIRECTION:
        pdf_chart_point(&g->s->chart, vec3_make(x[0], x[1], x[2]), out);
        return;
    }
}

static double gof_density(const double x[2], void *ctx)
{
    const warp_gof_ctx *g = ctx;
    switch (g->e->chart) {
    case G_IDENTITY: {
        double y[3] = {g->e->point == WARP_INDEX ? floor(x[0]) : x[0], x[1], 0.0};
        return warp_density(g->e, g->s, y);
    }
    case G_DISC: {
        /* d area = r dr d phi = d(r^2) d phi / 2. */
        double r = sqrt(x[0]), y[3] = {r * cos(x[1]), r * sin(x[1]), 0.0};
        return 0.5 * warp_density(g->e, g->s, y);
    }
    case G_DIRECTION: {
        double jac, y[3];
        vec3 d = pdf_chart_direction(&g->s->chart, x, &jac);
        put3(y, d);
        return jac > 0.0 ? warp_density(g->e, g->s, y) * jac : 0.0;
    }
    }
    return 0.0;
}

/* The smallest divisor k of 30 (so plane-chart cells stay aligned with the
 * light's edges) for which the 30/k x 30/k cells covering the light, where
 * the samples fall, keep `per_cell` samples per cell on average. */
static int plane_divisor(uint64_t n, double per_cell)
{
    static const int divisors[] = {1, 2, 3, 5, 6, 10, 15, 30};
    for (size_t i = 0; i < sizeof divisors / sizeof divisors[0]; i++) {
        int k = divisors[i];
        if ((double)n >= per_cell * (30.0 / k) * (30.0 / k))
            return k;
    }
    return 30;
}

mc_gof_spec warp_gof_spec(warp_gof_ctx *ctx, uint64_t n)
{
    const warp_entry *e = ctx->e;
    /* The full 50 x 100 resolution suits 10^6 samples. With fewer, coarser
     * cells keep about WARP_GOF_PER_CELL samples per cell on average;
     * otherwise Pearson pooling would merge most cells and the test would
     * lose its power. */
    double scale = fmin(1.0, sqrt((double)n / (WARP_GOF_PER_CELL * 5000.0)));
    mc_gof_spec spec = {2, {0.0, 0.0}, {1.0, 1.0},
                        {(int)fmax(2.0, 50.0 * scale), (int)fmax(2.0, 100.0 * scale)},
                        gof_sample, gof_density, ctx};
    if (e->point == WARP_REAL || e->point == WARP_INDEX) {
        bool index = e->point == WARP_INDEX;
        spec.dims = 1;
        spec.hi[0] = index ? (double)ctx->s->p.n_weights : e->hi;
        spec.cells[0] = index ? (int)ctx->s->p.n_weights
                              : (int)fmax(2.0, fmin(100.0, (double)n / WARP_GOF_PER_CELL));
    } else if (e->chart == G_DISC) {
        spec.hi[1] = MC_2PI;
    } else if (e->chart == G_DIRECTION) {
        pdf_chart_rect(&ctx->s->chart, spec.lo, spec.hi);
        if (ctx->s->chart.kind == PDF_CHART_LIGHT_PLANE) {
            /* Plane charts: 30/k cells per unit, so the light's edges are
             * cell edges. */
            int k = plane_divisor(n, WARP_GOF_PER_CELL);
            spec.cells[0] = 120 / k, spec.cells[1] = 90 / k;
        }
    }
    return spec;
}
