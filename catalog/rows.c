/* catalog/rows.c - what every row of the catalog shares: finding rows,
 * parameters with their ranges, sampling, and the charts of the goodness
 * of fit. */
#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/integrate.h"
#include "samplers/spherical.h"

const cat_row *cat_find(const char *name)
{
    for (size_t i = 0; i < cat_count(); i++)
        if (strcmp(cat_at(i)->name, name) == 0)
            return cat_at(i);
    for (size_t i = 0; i < cat_negative_count(); i++)
        if (strcmp(cat_negative_at(i)->name, name) == 0)
            return cat_negative_at(i);
    return NULL;
}

const cat_case *cat_find_case(const char *name, const cat_row **row)
{
    for (size_t i = 0; i < cat_count(); i++)
        for (const cat_case *c = cat_at(i)->cases; c->name; c++)
            if (strcmp(c->name, name) == 0) {
                *row = cat_at(i);
                return c;
            }
    return NULL;
}

int cat_point_dims(const cat_row *r)
{
    return r->point == CAT_DIRECTION || r->point == CAT_POINT ? 3 : (r->point == CAT_PLANAR ? 2 : 1);
}

size_t cat_param_defaults(const cat_row *r, char *buf, size_t size)
{
    if (!r->params->key)
        return (size_t)snprintf(buf, size, "-");
    size_t used = 0;
    for (const cat_param *p = r->params; p->key; p++) {
        /* Past the end of buf, snprintf with no room only counts. */
        size_t room = used < size ? size - used : 0;
        int k = snprintf(room ? buf + used : NULL, room, "%s%s=%s", used ? " " : "", p->key, p->def);
        if (k < 0)
            break;
        used += (size_t)k;
    }
    return used;
}

static const cat_param *param_of(const cat_row *r, const char *key, size_t len)
{
    for (const cat_param *p = r->params; p->key; p++)
        if (strlen(p->key) == len && strncmp(p->key, key, len) == 0)
            return p;
    return NULL;
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

bool cat_set_param(const cat_row *r, cat_values *v, const char *assignment, char *err,
                   size_t errlen)
{
    const char *eq = strchr(assignment, '=');
    size_t len = eq ? (size_t)(eq - assignment) : strlen(assignment);
    const cat_param *p = eq ? param_of(r, assignment, len) : NULL;
    if (!p) {
        snprintf(err, errlen, "%s has no parameter '%.*s'", r->name, (int)len, assignment);
        return false;
    }
    char *field = (char *)v + p->offset;
    double x[3];
    bool ok;
    switch (p->kind) {
    case CAT_LIST:
        v->n_weights = parse_numbers(eq + 1, v->weights, CAT_MAX_WEIGHTS);
        ok = v->n_weights > 0;
        break;
    case CAT_VECTOR:
        ok = parse_numbers(eq + 1, x, 3) == 3;
        if (ok)
            *(vec3 *)(void *)field = vec3_make(x[0], x[1], x[2]);
        break;
    default:
        ok = parse_numbers(eq + 1, (double *)(void *)field, 1) == 1;
        break;
    }
    if (!ok)
        snprintf(err, errlen, "%s: malformed value in '%s'", r->name, assignment);
    return ok;
}

void cat_defaults(const cat_row *r, cat_values *v)
{
    memset(v, 0, sizeof *v);
    char err[200], buf[256];
    for (const cat_param *p = r->params; p->key; p++) {
        snprintf(buf, sizeof buf, "%s=%s", p->key, p->def);
        (void)cat_set_param(r, v, buf, err, sizeof err);
    }
}

/* Whether the number lies in the parameter's range; the message says the
 * range as an interval, or as a bound when it has one end. */
static bool in_range(const cat_row *r, const cat_param *p, double x, char *err, size_t errlen)
{
    bool ok = (p->lo_open ? x > p->lo : x >= p->lo) && (p->hi_open ? x < p->hi : x <= p->hi);
    if (ok)
        return true;
    if (isinf(p->hi))
        snprintf(err, errlen, "%s: %s must be %s %g", r->name, p->key, p->lo_open ? ">" : ">=",
                 p->lo);
    else
        snprintf(err, errlen, "%s: %s must be in %c%g, %g%c", r->name, p->key,
                 p->lo_open ? '(' : '[', p->lo, p->hi, p->hi_open ? ')' : ']');
    return false;
}

bool cat_prepare(const cat_row *r, const cat_values *v, cat_state *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    s->row = r;
    s->p = *v;
    for (const cat_param *p = r->params; p->key; p++)
        if (p->kind == CAT_NUMBER &&
            !in_range(r, p, *(const double *)(const void *)((const char *)v + p->offset), err,
                      errlen))
            return false;
    s->chart = r->chart;
    if (r->chart == CAT_CHART_DIRECTION)
        s->dir_chart = pdf_chart_spherical(vec3_make(0.0, 0.0, 1.0), r->lo);
    return r->prepare ? r->prepare(s, err, errlen) : true;
}

bool cat_prepare_named(const char *name, cat_state *s, char *err, size_t errlen)
{
    const cat_row *r = cat_find(name);
    if (!r) {
        snprintf(err, errlen, "no sampler '%s' in the catalog", name);
        return false;
    }
    cat_values v;
    cat_defaults(r, &v);
    return cat_prepare(r, &v, s, err, errlen);
}

bool cat_prepare_case(const cat_row *r, const cat_case *c, cat_state *s, char *err,
                      size_t errlen)
{
    cat_values v;
    cat_defaults(r, &v);
    char buf[256];
    snprintf(buf, sizeof buf, "%s", c->params ? c->params : "");
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        if (!cat_set_param(r, &v, tok, err, errlen))
            return false;
    if (!cat_prepare(r, &v, s, err, errlen))
        return false;
    if (c->lobe_width > 0.0)
        cat_use_lobe_chart(s, c->lobe_width);
    return true;
}

void cat_sample(const cat_state *s, mc_rng *rng, double x[3])
{
    const cat_row *r = s->row;
    x[0] = x[1] = x[2] = 0.0;
    if (!r->uniforms) {
        r->sample_rng(s, rng, x);
        return;
    }
    double u[4];
    for (int k = 0; k < r->uniforms; k++)
        u[k] = mc_rng_uniform(rng);
    r->sample_u(s, u, x);
}

double cat_pdf(const cat_state *s, const double x[3])
{
    return s->row->pdf(s, x);
}

/* --- the estimator over directions -------------------------------------- */

/* cat_integrate as an mc_is_sampler over a direction row's points:
 * mc_integrate_sampler holds the one weighting loop. */
typedef struct row_integrand {
    pdf_fn f;
    const cat_state *s;
} row_integrand;

/* BEGIN SNIPPET catalog_estimator */
static double row_draw(mc_rng *rng, void *ctx, void *x)
{
    const row_integrand *c = ctx;
    double *d = x;
    cat_sample(c->s, rng, d);
    return cat_pdf(c->s, d);
}

static double row_f(const void *x, void *ctx)
{
    const row_integrand *c = ctx;
    const double *d = x;
    return c->f.f(vec3_make(d[0], d[1], d[2]), c->f.ctx);
}

mc_estimate cat_integrate(pdf_fn f, const cat_state *s, mc_rng *rng, uint64_t n)
{
    row_integrand c = {f, s};
    double d[3];
    return mc_integrate_sampler((mc_is_sampler){row_draw, row_f, NULL, &c}, d, rng, n);
}
/* END SNIPPET catalog_estimator */

/* --- charts -------------------------------------------------------------- */

void cat_use_lobe_chart(cat_state *s, double width)
{
    s->chart = CAT_CHART_LOBE;
    s->lobe_width = width;
    s->lobe_theta_max = MC_PI_2;
    s->lobe_rotated = false;
}

void cat_use_lobe_chart_about(cat_state *s, double width, vec3 axis, double theta_max)
{
    cat_use_lobe_chart(s, width);
    s->lobe_theta_max = theta_max;
    s->lobe_rotated = !(axis.x == 0.0 && axis.y == 0.0 && axis.z > 0.0);
    s->lobe_frame = onb_from_w(vec3_normalize(axis));
}

void cat_use_polygon_chart(cat_state *s, bool triangle, vec3 a, vec3 e1, vec3 e2)
{
    s->chart = CAT_CHART_POLYGON;
    s->poly_triangle = triangle;
    s->poly_corner = a, s->poly_e1 = e1, s->poly_e2 = e2;
}

/* The edge coordinates (a, b) of the point x of the plane corner + a u +
 * b v, by least squares in the plane (Cramer's rule on the Gram matrix of
 * u and v). */
static void plane_coords(vec3 corner, vec3 u, vec3 v, vec3 x, double out[2])
{
    vec3 d = vec3_sub(x, corner);
    double uu = vec3_dot(u, u), uv = vec3_dot(u, v), vv = vec3_dot(v, v);
    double du = vec3_dot(d, u), dv = vec3_dot(d, v), det = uu * vv - uv * uv;
    out[0] = (du * vv - dv * uv) / det;
    out[1] = (dv * uu - du * uv) / det;
}

/* The chart point of direction d toward the polygon: where the ray from
 * the origin along d meets the polygon's plane, in the polygon's
 * coordinates; NaN (outside every rectangle) for a ray that misses the
 * plane. For the triangle, a + s e1 + t e2 with s = x, t = x y gives
 * x = s and y = t / s. */
static void polygon_point(const cat_state *s, vec3 d, double out[2])
{
    vec3 n = vec3_cross(s->poly_e1, s->poly_e2);
    double dn = vec3_dot(d, n), t = vec3_dot(s->poly_corner, n) / dn;
    out[0] = out[1] = (double)NAN;
    if (!(t > 0.0) || !isfinite(t))
        return;
    double ab[2];
    plane_coords(s->poly_corner, s->poly_e1, s->poly_e2, vec3_scale(d, t), ab);
    double a = ab[0], b = ab[1];
    if (s->poly_triangle) {
        out[0] = a;
        /* At the corner a = 0 every y is the same point. */
        out[1] = a > 0.0 ? b / a : 0.0;
    } else {
        out[0] = a, out[1] = b;
    }
}

/* The direction toward the polygon's point at chart point c, and the
 * chart's Jacobian d omega / (dx dy): d area / (dx dy) times |cos| / r^2,
 * with |cos| / r^2 = |n . p| / (|n| |p|^3) at the point p. */
static vec3 polygon_direction(const cat_state *s, const double c[2], double *jac)
{
    vec3 e2 = s->poly_triangle ? vec3_scale(s->poly_e2, c[0]) : s->poly_e2;
    vec3 p = vec3_madd(vec3_madd(s->poly_corner, s->poly_e1, c[0]), e2, c[1]);
    vec3 n = vec3_cross(s->poly_e1, s->poly_e2);
    double r = vec3_length(p), area = vec3_length(n) * (s->poly_triangle ? c[0] : 1.0);
    *jac = r > 0.0 ? area * fabs(vec3_dot(n, p)) / (vec3_length(n) * r * r * r) : 0.0;
    return r > 0.0 ? vec3_scale(p, 1.0 / r) : p;
}

/* The lobe chart's upper end: x(theta_max). */
static double lobe_x_max(const cat_state *s)
{
    return s->lobe_theta_max / (s->lobe_theta_max + s->lobe_width);
}

void cat_chart_point(const cat_state *s, const double x[3], double out[2])
{
    vec3 d = vec3_make(x[0], x[1], x[2]);
    switch (s->chart) {
    case CAT_CHART_LINE:
    case CAT_CHART_XY:
        out[0] = x[0], out[1] = x[1];
        return;
    case CAT_CHART_INDEX:
        /* An index k is histogrammed as k + 1/2, the middle of cell k. */
        out[0] = x[0] + 0.5, out[1] = 0.0;
        return;
    case CAT_CHART_DISC:
        out[0] = x[0] * x[0] + x[1] * x[1];
        out[1] = smp_spherical_phi(vec3_make(x[0], x[1], 0.0));
        return;
    case CAT_CHART_PARALLELOGRAM:
        plane_coords(s->p.corner, s->p.u, s->p.v, d, out);
        return;
    case CAT_CHART_SURFACE: {
        vec3 w = vec3_scale(vec3_sub(d, s->p.center), 1.0 / s->p.radius);
        out[0] = w.z, out[1] = smp_spherical_phi(w);
        return;
    }
    case CAT_CHART_DIRECTION:
        pdf_chart_point(&s->dir_chart, d, out);
        return;
    case CAT_CHART_LOBE: {
        if (s->lobe_rotated)
            d = onb_to_local(&s->lobe_frame, d);
        double theta = smp_spherical_theta(d);
        out[0] = theta / (theta + s->lobe_width);
        out[1] = smp_spherical_phi(d);
        return;
    }
    case CAT_CHART_POLYGON:
        polygon_point(s, d, out);
        return;
    }
}

double cat_chart_density_of(const cat_state *s, const double c[2], cat_density_fn f, void *ctx)
{
    switch (s->chart) {
    case CAT_CHART_LINE:
    case CAT_CHART_XY: {
        double y[3] = {c[0], c[1], 0.0};
        return f(y, ctx);
    }
    case CAT_CHART_INDEX: {
        double y[3] = {floor(c[0]), 0.0, 0.0};
        return f(y, ctx);
    }
    case CAT_CHART_DISC: {
        /* d area = r dr d phi = d(r^2) d phi / 2. */
        double r = sqrt(c[0]), y[3] = {r * cos(c[1]), r * sin(c[1]), 0.0};
        return 0.5 * f(y, ctx);
    }
    case CAT_CHART_PARALLELOGRAM: {
        /* d area = |u x v| da db. */
        const cat_values *p = &s->p;
        vec3 x = vec3_madd(vec3_madd(p->corner, p->u, c[0]), p->v, c[1]);
        double y[3] = {x.x, x.y, x.z};
        return f(y, ctx) * vec3_length(vec3_cross(p->u, p->v));
    }
    case CAT_CHART_SURFACE: {
        /* d area = r^2 d omega = r^2 d(cos theta) d phi. */
        const cat_values *p = &s->p;
        vec3 x = vec3_madd(p->center, smp_spherical_direction(c[0], c[1]), p->radius);
        double y[3] = {x.x, x.y, x.z};
        return f(y, ctx) * p->radius * p->radius;
    }
    case CAT_CHART_DIRECTION: {
        double jac;
        vec3 d = pdf_chart_direction(&s->dir_chart, c, &jac);
        double y[3] = {d.x, d.y, d.z};
        return jac > 0.0 ? f(y, ctx) * jac : 0.0;
    }
    case CAT_CHART_LOBE: {
        /* theta = s x / (1 - x), d theta / dx = s / (1 - x)^2, and the
         * solid angle element is sin theta d theta d phi. */
        double w = s->lobe_width, x = c[0];
        double theta = w * x / (1.0 - x);
        if (theta > s->lobe_theta_max)
            return 0.0;
        vec3 d = smp_spherical_direction(cos(theta), c[1]);
        if (s->lobe_rotated)
            d = onb_to_world(&s->lobe_frame, d);
        double y[3] = {d.x, d.y, d.z};
        return f(y, ctx) * sin(theta) * w / ((1.0 - x) * (1.0 - x));
    }
    case CAT_CHART_POLYGON: {
        double jac;
        vec3 d = polygon_direction(s, c, &jac);
        double y[3] = {d.x, d.y, d.z};
        return jac > 0.0 ? f(y, ctx) * jac : 0.0;
    }
    }
    return 0.0;
}

static double row_density(const double x[3], void *ctx)
{
    return cat_pdf(ctx, x);
}

double cat_chart_density(const cat_state *s, const double c[2])
{
    return cat_chart_density_of(s, c, row_density, (void *)s);
}

static void gof_sample(mc_rng *rng, void *ctx, double out[2])
{
    const cat_state *s = ctx;
    double x[3];
    cat_sample(s, rng, x);
    cat_chart_point(s, x, out);
}

static double gof_density(const double x[2], void *ctx)
{
    return cat_chart_density(ctx, x);
}

mc_gof_spec cat_gof_spec(const cat_state *s, const int cells[2])
{
    bool given = cells && cells[0] > 0;
    mc_gof_spec spec = {2, {0.0, 0.0}, {1.0, 1.0}, {50, 100}, gof_sample, gof_density, NULL};
    spec.ctx = (void *)s; /* read only, as mc_gof_spec documents */
    switch (s->chart) {
    case CAT_CHART_LINE:
        spec.dims = 1, spec.lo[0] = s->row->lo, spec.hi[0] = s->row->hi, spec.cells[0] = 100;
        break;
    case CAT_CHART_INDEX:
        spec.dims = 1, spec.hi[0] = (double)s->p.n_weights, spec.cells[0] = (int)s->p.n_weights;
        break;
    case CAT_CHART_XY:
    case CAT_CHART_PARALLELOGRAM:
    case CAT_CHART_POLYGON:
        break;
    case CAT_CHART_DISC:
        spec.hi[1] = MC_2PI;
        break;
    case CAT_CHART_SURFACE:
        spec.lo[0] = -1.0, spec.hi[1] = MC_2PI;
        break;
    case CAT_CHART_DIRECTION:
        pdf_chart_rect(&s->dir_chart, spec.lo, spec.hi);
        /* Plane charts: 30 cells per unit, so the light's edges are cell
         * edges. */
        if (s->dir_chart.kind == PDF_CHART_LIGHT_PLANE)
            spec.cells[0] = 120, spec.cells[1] = 90;
        break;
    case CAT_CHART_LOBE:
        spec.hi[0] = lobe_x_max(s), spec.hi[1] = MC_2PI;
        break;
    }
    if (given)
        spec.cells[0] = cells[0], spec.cells[1] = cells[1];
    return spec;
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

mc_gof_spec cat_gof_spec_for(const cat_state *s, uint64_t n)
{
    mc_gof_spec spec = cat_gof_spec(s, NULL);
    if (s->chart == CAT_CHART_INDEX)
        return spec;
    if (s->chart == CAT_CHART_LINE) {
        spec.cells[0] = (int)fmax(2.0, fmin(100.0, (double)n / CAT_GOF_PER_CELL));
        return spec;
    }
    if (s->chart == CAT_CHART_DIRECTION && s->dir_chart.kind == PDF_CHART_LIGHT_PLANE) {
        int k = plane_divisor(n, CAT_GOF_PER_CELL);
        spec.cells[0] = 120 / k, spec.cells[1] = 90 / k;
        return spec;
    }
    /* The full 50 x 100 resolution suits 10^6 samples. With fewer, coarser
     * cells keep about CAT_GOF_PER_CELL samples per cell on average;
     * otherwise Pearson pooling would merge most cells and the test would
     * lose its power. */
    double scale = fmin(1.0, sqrt((double)n / (CAT_GOF_PER_CELL * 5000.0)));
    spec.cells[0] = (int)fmax(2.0, 50.0 * scale), spec.cells[1] = (int)fmax(2.0, 100.0 * scale);
    return spec;
}
