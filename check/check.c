/* check/check.c - the public check of a user's sampler: the suite's chart,
 * histogram, per-cell quadrature and Pearson test (mc/gof.h, catalog/) run
 * on callbacks, with the checks a chi-square test alone misses. */
#include "check/check.h"
#include "check/stream.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "mc/chi2.h"
#include "mc/gof.h"
#include "mc/quad.h"
#include "mc/rng.h"
#include "pdf/chart.h"

/* The stream handed to sample_stream: PCG32, the generator of the
 * uniforms. */
struct mcbox_stream {
    mc_rng rng;
};

double mcbox_uniform(mcbox_stream *s)
{
    return mc_rng_uniform(&s->rng);
}

mc_rng *chk_stream_rng(mcbox_stream *s)
{
    return &s->rng;
}

const char *mcbox_version(void)
{
    return "0.1.0";
}

static const char *const domain_names[] = {"interval", "square", "disc",   "triangle",
                                           "sphere",   "hemisphere", "catalog"};
#define N_DOMAINS (sizeof domain_names / sizeof domain_names[0])

const char *mcbox_domain_name(mcbox_domain_kind k)
{
    return (unsigned)k < N_DOMAINS ? domain_names[k] : NULL;
}

bool mcbox_domain_parse(const char *name, mcbox_domain_kind *k)
{
    for (size_t i = 0; name && i < N_DOMAINS; i++)
        if (strcmp(name, domain_names[i]) == 0) {
            *k = (mcbox_domain_kind)i;
            return true;
        }
    return false;
}

int mcbox_domain_dims(const mcbox_domain *d)
{
    switch (d->kind) {
    case MCBOX_INTERVAL: return 1;
    case MCBOX_SQUARE:
    case MCBOX_DISC:
    case MCBOX_TRIANGLE: return 2;
    case MCBOX_SPHERE:
    case MCBOX_HEMISPHERE: return 3;
    case MCBOX_CATALOG: {
        const cat_row *r = d->row ? cat_find(d->row) : NULL;
        return r ? cat_point_dims(r) : 0;
    }
    }
    return 0;
}

mcbox_sampler mcbox_sampler_init(mcbox_domain_kind kind)
{
    mcbox_sampler s;
    memset(&s, 0, sizeof s);
    s.domain.kind = kind;
    s.domain.b = 1.0;
    s.uniforms = kind == MCBOX_INTERVAL ? 1 : 2;
    return s;
}

mcbox_check_options mcbox_check_defaults(void)
{
    mcbox_check_options o;
    memset(&o, 0, sizeof o);
    o.samples = 1000000u;
    o.seed = 1u;
    o.alpha = 0.01;
    o.tests = 1;
    o.norm_tol = 1e-6;
    o.pdf_tol = 1e-6;
    o.weight_tol = 1e-6;
    o.invert_tol = 1e-6;
    o.quad_order = 8;
    return o;
}

void mcbox_check_table_free(mcbox_check_table *t)
{
    if (!t)
        return;
    free(t->observed);
    free(t->expected);
    t->observed = t->expected = NULL;
    t->cells = 0;
}

/* --- the check's state ---------------------------------------------------- */

/* Directions must be unit vectors to within this (relative): a sampler
 * computing in single precision is still on the sphere. */
#define UNIT_TOL 1e-6
/* A sample marked as an atom must be that atom's point to within this. */
#define ATOM_TOL 1e-9
/* A planar point may cross the triangle's hypotenuse by round-off. */
#define PLANAR_SLACK (4.0 * DBL_EPSILON)
/* Points per call of pdf_batch. */
#define BATCH 4096

struct mcbox_check {
    mcbox_sampler s;
    mcbox_check_options o;
    int dims;
    /* The chart: a catalog state, either a row's (MCBOX_CATALOG) or one
     * made here for a basic domain around a copy of a row that only gives
     * its chart kind and interval; the density is always the user's. */
    cat_row row;
    cat_state st;
    mc_gof_spec spec;
    int chart_cells;
    mc_rng rng;
    double *obs; /* chart cells, then atoms */
    uint64_t n;  /* samples added */
    mcbox_check_result r;
    /* Worst cases, for the message. */
    uint64_t first_nonfinite, first_outside, first_bad_atom, first_bad_pdf, worst_pdf_at,
        worst_weight_at, worst_invert_at;
    double bad_pdf_value;
    double example[3];
    double rep_pdf, cb_pdf;
    double sum_weight;
    bool invalid;
    char invalid_msg[200];
};

static void set_message(mcbox_check_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->message, sizeof r->message, fmt, ap);
    va_end(ap);
}

static void fresh_result(mcbox_check_result *r)
{
    memset(r, 0, sizeof *r);
    r->pvalue = (double)NAN;
    r->statistic = (double)NAN;
    r->pdf_integral = (double)NAN;
    r->pdf_integral_error = (double)NAN;
    r->weight_mean = (double)NAN;
    r->weight_mismatch = (double)NAN;
    r->invert_error = (double)NAN;
}

/* The user's density as the catalog's charts call it. */
static double user_density(const double x[3], void *ctx)
{
    const mcbox_check *c = ctx;
    return c->s.pdf(x, c->s.ctx);
}

/* The triangle's chart is the unit square; the density is 0 beyond the
 * hypotenuse whatever the user's function says there. */
static bool in_triangle(const double x[3])
{
    return x[0] >= 0.0 && x[1] >= 0.0 && x[0] + x[1] <= 1.0 + PLANAR_SLACK;
}

/* Whether the chart point p lies beyond the triangle's hypotenuse. */
static bool masked(const mcbox_check *c, const double p[2])
{
    return c->s.domain.kind == MCBOX_TRIANGLE && !(p[0] + p[1] <= 1.0);
}

static double chart_density(const double p[2], void *ctx)
{
    const mcbox_check *c = ctx;
    if (masked(c, p))
        return 0.0;
    return cat_chart_density_of(&c->st, p, user_density, ctx);
}

/* Sets up the chart of the domain; false with a message otherwise. */
static bool make_chart(mcbox_check *c, char *err, size_t errlen)
{
    const mcbox_domain *d = &c->s.domain;
    memset(&c->row, 0, sizeof c->row);
    if (d->kind == MCBOX_CATALOG) {
        const cat_row *r = d->row ? cat_find(d->row) : NULL;
        if (!r) {
            snprintf(err, errlen, "no row '%s' in the sampler catalog", d->row ? d->row : "(null)");
            return false;
        }
        cat_case cs = {r->name, d->params, {0, 0}, c->o.lobe_width, 0u, 0};
        if (!cat_prepare_case(r, &cs, &c->st, err, errlen))
            return false;
        return true;
    }
    memset(&c->st, 0, sizeof c->st);
    c->row.name = mcbox_domain_name(d->kind);
    c->row.hi = 1.0;
    switch (d->kind) {
    case MCBOX_INTERVAL:
        if (!(isfinite(d->a) && isfinite(d->b) && d->a < d->b)) {
            snprintf(err, errlen, "the interval [%g, %g] is not finite with a < b", d->a, d->b);
            return false;
        }
        c->row.chart = CAT_CHART_LINE, c->row.lo = d->a, c->row.hi = d->b;
        break;
    case MCBOX_SQUARE:
    case MCBOX_TRIANGLE: c->row.chart = CAT_CHART_XY; break;
    case MCBOX_DISC: c->row.chart = CAT_CHART_DISC; break;
    case MCBOX_SPHERE:
    case MCBOX_HEMISPHERE:
        c->row.chart = CAT_CHART_DIRECTION;
        c->row.lo = d->kind == MCBOX_SPHERE ? -1.0 : 0.0;
        break;
    default: snprintf(err, errlen, "unknown domain kind %d", (int)d->kind); return false;
    }
    c->st.row = &c->row;
    c->st.chart = c->row.chart;
    if (c->row.chart == CAT_CHART_DIRECTION) {
        /* The chart the catalog gives its rows about +z. */
        c->st.dir_chart = pdf_chart_spherical((vec3){0.0, 0.0, 1.0}, c->row.lo);
        if (c->o.lobe_width > 0.0) {
            if (d->kind == MCBOX_SPHERE) {
                snprintf(err, errlen, "a lobe chart covers the hemisphere about +z only");
                return false;
            }
            cat_use_lobe_chart(&c->st, c->o.lobe_width);
        }
    }
    return true;
}

static bool options_valid(const mcbox_check_options *o, char *err, size_t errlen)
{
    const char *bad = o->samples < 1                                     ? "samples must be >= 1"
                      : !(o->alpha > 0.0 && o->alpha < 1.0)              ? "alpha must lie in (0, 1)"
                      : o->tests < 1                                     ? "tests must be >= 1"
                      : (o->cells[0] < 0 || o->cells[1] < 0)             ? "cells must be >= 0"
                      : (o->cells[0] > 4096 || o->cells[1] > 4096)       ? "cells must be <= 4096"
                      : !(o->lobe_width >= 0.0 && isfinite(o->lobe_width)) ? "lobe_width must be >= 0"
                      : !(o->norm_tol >= 0.0)                            ? "norm_tol must be >= 0"
                      : !(o->pdf_tol >= 0.0)                             ? "pdf_tol must be >= 0"
                      : !(o->weight_tol >= 0.0)                          ? "weight_tol must be >= 0"
                      : !(o->invert_tol >= 0.0)                          ? "invert_tol must be >= 0"
                      : (o->quad_order < 1 || o->quad_order > 64)        ? "quad_order must be 1..64"
                                                                          : NULL;
    if (bad)
        snprintf(err, errlen, "%s", bad);
    return bad == NULL;
}

mcbox_check *mcbox_check_begin(const mcbox_sampler *s, const mcbox_check_options *o,
                               mcbox_check_result *r)
{
    fresh_result(r);
    char err[200];
    if (!s || !o) {
        set_message(r, "no sampler or no options");
        return NULL;
    }
    if (!options_valid(o, err, sizeof err)) {
        set_message(r, "invalid option: %s", err);
        return NULL;
    }
    if (!s->pdf && !s->pdf_batch) {
        set_message(r, "the sampler has no pdf (pdf or pdf_batch is required)");
        return NULL;
    }
    if (s->uniforms < 0 || s->uniforms > MCBOX_MAX_UNIFORMS) {
        set_message(r, "uniforms must be 0 .. %d", MCBOX_MAX_UNIFORMS);
        return NULL;
    }
    if (s->n_atoms && (!s->atom_x || !s->atom_mass)) {
        set_message(r, "n_atoms > 0 needs atom_x and atom_mass");
        return NULL;
    }
    for (size_t k = 0; k < s->n_atoms; k++)
        if (!(s->atom_mass[k] >= 0.0 && s->atom_mass[k] <= 1.0)) {
            set_message(r, "atom %zu has mass %g, not in [0, 1]", k, s->atom_mass[k]);
            return NULL;
        }
    mcbox_check *c = calloc(1, sizeof *c);
    if (!c) {
        set_message(r, "out of memory");
        return NULL;
    }
    c->s = *s;
    c->o = *o;
    if (!make_chart(c, err, sizeof err)) {
        set_message(r, "%s", err);
        free(c);
        return NULL;
    }
    c->dims = mcbox_domain_dims(&c->s.domain);
    bool given = o->cells[0] > 0;
    if (given && c->st.chart != CAT_CHART_LINE && c->st.chart != CAT_CHART_INDEX &&
        o->cells[1] < 1) {
        set_message(r, "cells: a 2D chart needs both resolutions");
        free(c);
        return NULL;
    }
    c->spec = given ? cat_gof_spec(&c->st, o->cells) : cat_gof_spec_for(&c->st, o->samples);
    c->spec.sample = NULL;
    c->spec.pdf = chart_density;
    c->spec.ctx = c;
    c->chart_cells = mc_gof_cell_count(&c->spec);
    c->obs = calloc((size_t)c->chart_cells + s->n_atoms, sizeof *c->obs);
    if (!c->obs) {
        set_message(r, "out of memory");
        free(c);
        return NULL;
    }
    c->rng = mc_rng_derive(o->seed, 0u);
    c->r = *r;
    c->r.pdf_mismatch = 0.0;
    if (s->eval)
        c->r.weight_mismatch = 0.0;
    if (s->invert)
        c->r.invert_error = 0.0;
    return c;
}

void mcbox_check_uniforms(mcbox_check *c, double *u)
{
    for (int k = 0; k < c->s.uniforms; k++)
        u[k] = mc_rng_uniform(&c->rng);
}

/* Whether a finite point lies in the domain (the chart's rectangle is
 * checked by the histogram). */
static bool in_domain(const mcbox_check *c, const double x[3])
{
    switch (c->s.domain.kind) {
    case MCBOX_TRIANGLE: return in_triangle(x);
    case MCBOX_SPHERE:
    case MCBOX_HEMISPHERE:
        return fabs(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1.0) <= UNIT_TOL;
    case MCBOX_CATALOG: {
        const cat_row *r = c->st.row;
        if (r->point == CAT_DIRECTION &&
            !(fabs(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1.0) <= UNIT_TOL))
            return false;
        return r->in_support ? r->in_support(&c->st, x) : true;
    }
    default: return true;
    }
}

static void remember(mcbox_check *c, uint64_t *first, uint64_t count_before, const double x[3])
{
    if (count_before == 0) {
        *first = c->n;
        memcpy(c->example, x, sizeof c->example);
    }
}

/* The user's density, asked of pdf_batch BATCH points at a time, at the
 * points at(i, src) gives for i < n; where it gives NULL no density is
 * needed and out[i] is left as it is. Returns -1 when out of memory. */
typedef const double *(*point_at)(size_t i, const void *src);

static int batch_densities(const mcbox_check *c, size_t n, point_at at, const void *src,
                           double *out)
{
    double *pts = malloc(BATCH * 3 * sizeof *pts);
    size_t *idx = malloc(BATCH * sizeof *idx);
    int status = pts && idx ? 0 : -1;
    size_t m = 0;
    for (size_t i = 0; status == 0 && i <= n; i++) {
        const double *x = i < n ? at(i, src) : NULL;
        if (x) {
            memcpy(pts + m * (size_t)c->dims, x, (size_t)c->dims * sizeof *pts);
            idx[m++] = i;
        }
        if (m == BATCH || (i == n && m > 0)) {
            double vals[BATCH];
            c->s.pdf_batch(pts, m, vals, c->s.ctx);
            for (size_t k = 0; k < m; k++)
                out[idx[k]] = vals[k];
            m = 0;
        }
    }
    free(pts);
    free(idx);
    return status;
}

/* A sample's point where the check needs the density there: a reported
 * pdf to compare (atoms have none). */
static const double *reported_point(size_t i, const void *src)
{
    const mcbox_sample *q = (const mcbox_sample *)src + i;
    return q->atom < 0 && !isnan(q->pdf) ? q->x : NULL;
}

/* The user's density at the points of samples that need it (a reported
 * pdf or a weight to check), in batches when it comes that way; NaN where
 * it was not asked for (or memory ran out). */
static void densities_at(mcbox_check *c, const mcbox_sample *smp, size_t n, double *out)
{
    if (c->s.pdf) {
        for (size_t i = 0; i < n; i++)
            out[i] = c->s.pdf(smp[i].x, c->s.ctx);
        return;
    }
    for (size_t i = 0; i < n; i++)
        out[i] = (double)NAN;
    (void)batch_densities(c, n, reported_point, smp, out);
}

int mcbox_check_add(mcbox_check *c, const mcbox_sample *smp, const double *u, size_t n)
{
    if (c->invalid)
        return -1;
    double *dens = malloc((n ? n : 1) * sizeof *dens);
    if (!dens) {
        c->invalid = true;
        snprintf(c->invalid_msg, sizeof c->invalid_msg, "out of memory");
        return -1;
    }
    densities_at(c, smp, n, dens);
    mcbox_check_result *r = &c->r;
    int nu = c->s.uniforms;
    for (size_t i = 0; i < n; i++, c->n++) {
        const mcbox_sample *q = &smp[i];
        double x[3] = {q->x[0], c->dims > 1 ? q->x[1] : 0.0, c->dims > 2 ? q->x[2] : 0.0};
        if (q->atom >= 0 || q->atom < -1) {
            size_t k = (size_t)q->atom;
            bool ok = q->atom >= 0 && k < c->s.n_atoms;
            for (int j = 0; ok && j < c->dims; j++)
                ok = fabs(x[j] - c->s.atom_x[k * (size_t)c->dims + (size_t)j]) <= ATOM_TOL;
            if (!ok) {
                remember(c, &c->first_bad_atom, r->bad_atoms, x);
                r->bad_atoms++;
            } else {
                c->obs[c->chart_cells + (int)k] += 1.0;
            }
            continue;
        }
        bool finite = true;
        for (int j = 0; j < c->dims; j++)
            finite = finite && isfinite(x[j]);
        if (!finite) {
            remember(c, &c->first_nonfinite, r->nonfinite, x);
            r->nonfinite++;
            continue;
        }
        double p[2] = {0.0, 0.0};
        cat_chart_point(&c->st, x, p);
        int cell = mc_gof_cell_index(&c->spec, p);
        if (cell < 0 || !in_domain(c, x)) {
            remember(c, &c->first_outside, r->outside, x);
            r->outside++;
        }
        if (cell >= 0)
            c->obs[cell] += 1.0;
        /* The density at the sample, where the sampler reported its own or
         * (with a pointwise pdf) always: a negative or non-finite value is
         * a wrong density whatever the histogram says. */
        double d = dens[i];
        bool evaluated = c->s.pdf || !isnan(q->pdf);
        if (evaluated && !(d >= 0.0 && isfinite(d))) {
            if (r->bad_pdf == 0)
                c->bad_pdf_value = d;
            remember(c, &c->first_bad_pdf, r->bad_pdf, x);
            r->bad_pdf++;
            continue;
        }
        if (!isnan(q->pdf)) {
            r->pdf_reported++;
            double rel = q->pdf == d ? 0.0 : fabs(q->pdf - d) / fmax(fabs(d), DBL_MIN);
            if (!(rel <= r->pdf_mismatch)) {
                r->pdf_mismatch = rel;
                c->worst_pdf_at = c->n, c->rep_pdf = q->pdf, c->cb_pdf = d;
            }
        }
        if (!isnan(q->weight)) {
            r->weight_reported++;
            c->sum_weight += q->weight;
            if (c->s.eval && c->s.pdf && d > 0.0) {
                double want = c->s.eval(x, c->s.ctx) / d;
                double rel = q->weight == want ? 0.0
                                               : fabs(q->weight - want) / fmax(fabs(want), DBL_MIN);
                if (!(rel <= r->weight_mismatch)) {
                    r->weight_mismatch = rel;
                    c->worst_weight_at = c->n;
                }
            }
        }
        if (u && c->s.invert && nu > 0) {
            double back[MCBOX_MAX_UNIFORMS];
            for (int k = 0; k < nu; k++)
                back[k] = (double)NAN;
            c->s.invert(x, back, c->s.ctx);
            const double *ui = u + i * (size_t)nu;
            double e = 0.0;
            for (int k = 0; k < nu; k++)
                e = fmax(e, isnan(back[k]) ? (double)INFINITY : fabs(back[k] - ui[k]));
            if (!(e <= r->invert_error)) {
                r->invert_error = e;
                c->worst_invert_at = c->n;
            }
        }
    }
    free(dens);
    return 0;
}

/* --- expected counts ------------------------------------------------------ */

typedef struct recorder {
    double *at;
    bool called;
} recorder;

static double record_point(const double x[3], void *ctx)
{
    recorder *rec = ctx;
    memcpy(rec->at, x, 3 * sizeof *x);
    rec->called = true;
    return 1.0;
}

/* The quadrature nodes' points, and where the chart maps a node to none
 * (its Jacobian is 0) no density is needed. */
typedef struct nodes {
    const double *pts, *jac;
} nodes;

static const double *node_point(size_t at, const void *src)
{
    const nodes *nd = src;
    return nd->jac[at] != 0.0 ? nd->pts + at * 3 : NULL;
}

/* The tensor Gauss-Legendre rule of n points per axis on the chart box b
 * (x0, x1, y0, y1): its nodes' points into pts and their weights times
 * the chart's Jacobian into jac (0 where the chart maps a node to no
 * point, or beyond the triangle). Returns the nodes written, or 0 when
 * the rule could not be made. */
static size_t rule_nodes(const mcbox_check *c, const double b[4], int n, double *pts, double *jac)
{
    int dims = c->spec.dims;
    double gx[64], gw[64], gy[64], gv[64];
    if (mc_quad_gauss_legendre(n, b[0], b[1], gx, gw) != 0 ||
        (dims == 2 && mc_quad_gauss_legendre(n, b[2], b[3], gy, gv) != 0))
        return 0;
    size_t count = dims == 2 ? (size_t)n * (size_t)n : (size_t)n;
    for (size_t k = 0; k < count; k++) {
        size_t i = dims == 2 ? k / (size_t)n : k, j = dims == 2 ? k % (size_t)n : 0;
        double p[2] = {gx[i], dims == 2 ? gy[j] : 0.0};
        double w = gw[i] * (dims == 2 ? gv[j] : 1.0);
        recorder rec = {pts + k * 3, false};
        double jv = 0.0;
        if (!masked(c, p))
            jv = cat_chart_density_of(&c->st, p, record_point, &rec);
        if (!rec.called)
            memset(pts + k * 3, 0, 3 * sizeof *pts);
        jac[k] = rec.called ? w * jv : 0.0;
    }
    return count;
}

/* The rule's sum over nodes [from, from + count): the Jacobian-weighted
 * densities, NaN when a density there is negative or not finite (the test
 * then rejects the cell instead of pooling it away). */
static double rule_sum(const double *jac, const double *vals, size_t from, size_t count)
{
    double sum = 0.0;
    for (size_t a = from; a < from + count; a++) {
        if (jac[a] != 0.0 && !(vals[a] >= 0.0 && isfinite(vals[a])))
            return (double)NAN;
        sum += jac[a] * vals[a];
    }
    return sum;
}

/* Cell probabilities from pdf_batch, by fixed rules in two batches. First
 * every cell gets the Gauss-Legendre rule of quad_order points per axis
 * (the probability) and of quad_order / 2 (a check): on a smooth density
 * both are exact far below the histogram's resolution and agree. Where
 * they disagree, the density jumps inside the cell (a light's edge, the
 * triangle's hypotenuse) or is singular at a corner, and a rule of fixed
 * order converges slowly there; such a cell is integrated again, by the
 * full rule on each of its halves (1D) or quarters (2D). If the error of
 * the rule falls as h^a with the panel's width h, the finer sum's error is
 * the two sums' difference times 2^-a / (1 - 2^-a): 1 for a jump (a = 1),
 * 2.41 for an inverse square root singularity (a = 1/2, the density of
 * uniform theta at the pole). Three times the difference, summed over the
 * cells (with the first pass's difference where a cell was not split), is
 * therefore the error estimate *err. */
static int batch_probs(mcbox_check *c, double *prob, double *err)
{
    int q = c->o.quad_order, dims = c->spec.dims, cells = c->chart_cells;
    int h = q / 2 > 0 ? q / 2 : 1, parts = dims == 2 ? 4 : 2;
    size_t full = dims == 2 ? (size_t)q * (size_t)q : (size_t)q;
    size_t half = dims == 2 ? (size_t)h * (size_t)h : (size_t)h;
    size_t per1 = full + half, per2 = (size_t)parts * full; /* nodes per cell, per pass */
    size_t total = (size_t)cells * (per1 > per2 ? per1 : per2);
    double *pts = malloc(total * 3 * sizeof *pts), *jac = malloc(total * sizeof *jac),
           *vals = calloc(total, sizeof *vals);
    int *split = malloc((size_t)cells * sizeof *split);
    int status = 0;
    if (!pts || !jac || !vals || !split) {
        status = -1;
        goto done;
    }
    /* Pass 1: the two rules on every cell. */
    for (int cell = 0; cell < cells; cell++) {
        double box[4];
        mc_gof_cell_box(&c->spec, cell, box);
        size_t at = (size_t)cell * per1;
        if (rule_nodes(c, box, q, pts + at * 3, jac + at) != full ||
            rule_nodes(c, box, h, pts + (at + full) * 3, jac + at + full) != half) {
            status = -1;
            goto done;
        }
    }
    nodes nd = {pts, jac};
    if (batch_densities(c, (size_t)cells * per1, node_point, &nd, vals) != 0) {
        status = -1;
        goto done;
    }
    int n_split = 0;
    *err = 0.0;
    for (int cell = 0; cell < cells; cell++) {
        size_t at = (size_t)cell * per1;
        double check = rule_sum(jac, vals, at + full, half);
        prob[cell] = rule_sum(jac, vals, at, full);
        double d = fabs(prob[cell] - check);
        /* A bad density (NaN sum) is not split: the cell stays NaN. */
        bool bad = isnan(prob[cell]) || isnan(check);
        if (bad)
            prob[cell] = (double)NAN;
        split[cell] = !bad && !(d <= 1e-13 + 1e-9 * fabs(prob[cell]));
        if (!split[cell])
            *err += 3.0 * d;
        n_split += split[cell];
    }
    if (n_split == 0)
        goto done;
    /* Pass 2: the full rule on the parts of the cells that disagreed. */
    size_t at = 0;
    for (int cell = 0; cell < cells; cell++) {
        if (!split[cell])
            continue;
        double box[4];
        mc_gof_cell_box(&c->spec, cell, box);
        for (int pa = 0; pa < parts; pa++, at += full) {
            /* Part pa: x half pa / 2 (2D) or pa (1D), y half pa % 2. */
            int hx = dims == 2 ? pa / 2 : pa, hy = pa % 2;
            double mx = 0.5 * (box[0] + box[1]), my = 0.5 * (box[2] + box[3]);
            double b[4] = {hx ? mx : box[0], hx ? box[1] : mx, box[2], box[3]};
            if (dims == 2)
                b[2] = hy ? my : box[2], b[3] = hy ? box[3] : my;
            if (rule_nodes(c, b, q, pts + at * 3, jac + at) != full) {
                status = -1;
                goto done;
            }
        }
    }
    for (size_t k = 0; k < at; k++)
        vals[k] = 0.0;
    if (batch_densities(c, at, node_point, &nd, vals) != 0) {
        status = -1;
        goto done;
    }
    at = 0;
    for (int cell = 0; cell < cells; cell++) {
        if (!split[cell])
            continue;
        double fine = rule_sum(jac, vals, at, per2);
        at += per2;
        *err += 3.0 * fabs(fine - prob[cell]);
        prob[cell] = fine;
    }
done:
    free(pts);
    free(jac);
    free(vals);
    free(split);
    return status;
}

/* The chart cell with the largest |obs - exp| / sqrt(exp), for the
 * message of a rejected test. */
static int worst_cell(const mcbox_check *c, const double *expct, size_t cells)
{
    int worst = -1;
    double best = -1.0;
    for (size_t k = 0; k < cells; k++) {
        double e = expct[k], d = fabs(c->obs[k] - e) / sqrt(fmax(e, 1.0));
        if (e > 0.0 && d > best)
            best = d, worst = (int)k;
    }
    return worst;
}

static void describe_cell(const mcbox_check *c, int k, char *buf, size_t size)
{
    if (k >= c->chart_cells) {
        snprintf(buf, size, "atom %d", k - c->chart_cells);
        return;
    }
    double b[4];
    mc_gof_cell_box(&c->spec, k, b);
    if (c->spec.dims == 2)
        snprintf(buf, size, "cell [%.4g, %.4g] x [%.4g, %.4g] of the chart", b[0], b[1], b[2], b[3]);
    else
        snprintf(buf, size, "cell [%.4g, %.4g] of the chart", b[0], b[1]);
}

static const char *const lobe_labels[2] = {"theta / (theta + w)", "phi"};

static void chart_labels(const mcbox_check *c, char *x, char *y, size_t size)
{
    const char *lx = "x", *ly = "y";
    switch (c->st.chart) {
    case CAT_CHART_LINE: lx = "x", ly = ""; break;
    case CAT_CHART_INDEX: lx = "outcome + 1/2", ly = ""; break;
    case CAT_CHART_XY: break;
    case CAT_CHART_DISC: lx = "r^2", ly = "phi"; break;
    case CAT_CHART_PARALLELOGRAM: lx = "a", ly = "b"; break;
    case CAT_CHART_SURFACE: lx = "cos theta", ly = "phi"; break;
    case CAT_CHART_DIRECTION:
        if (c->st.dir_chart.kind == PDF_CHART_SPHERICAL)
            lx = "cos theta", ly = "phi";
        else
            lx = "chart x", ly = "chart y";
        break;
    case CAT_CHART_LOBE: lx = lobe_labels[0], ly = lobe_labels[1]; break;
    }
    snprintf(x, size, "%s", lx);
    snprintf(y, size, "%s", ly);
}

static void coords(const mcbox_check *c, const double x[3], char *buf, size_t size)
{
    if (c->dims == 1)
        snprintf(buf, size, "(%.9g)", x[0]);
    else if (c->dims == 2)
        snprintf(buf, size, "(%.9g, %.9g)", x[0], x[1]);
    else
        snprintf(buf, size, "(%.9g, %.9g, %.9g)", x[0], x[1], x[2]);
}

/* The first failing check's message, in the order a user should fix them:
 * points that are not points, points outside, a density that is not one,
 * then the statistics. */
static void verdict(mcbox_check *c, const double *expct, size_t cells, bool finite_exp)
{
    mcbox_check_result *r = &c->r;
    char where[160], pt[120];
    coords(c, c->example, pt, sizeof pt);
    const char *dom = c->s.domain.kind == MCBOX_CATALOG ? c->st.row->domain
                                                        : mcbox_domain_name(c->s.domain.kind);
    double n = (double)c->n;
    r->pass = false;
    if (r->nonfinite) {
        set_message(r, "%llu sample(s) with a NaN or infinite coordinate; the first is sample %llu",
                    (unsigned long long)r->nonfinite, (unsigned long long)c->first_nonfinite);
    } else if (r->bad_atoms) {
        set_message(r, "%llu sample(s) marked as an atom that is not one; the first is sample %llu %s",
                    (unsigned long long)r->bad_atoms, (unsigned long long)c->first_bad_atom, pt);
    } else if (r->outside) {
        set_message(r, "%llu sample(s) outside the domain %s; the first is sample %llu %s",
                    (unsigned long long)r->outside, dom, (unsigned long long)c->first_outside, pt);
    } else if (r->bad_pdf) {
        set_message(r, "pdf(x) = %g (negative or not finite) at sample %llu %s", c->bad_pdf_value,
                    (unsigned long long)c->first_bad_pdf, pt);
    } else if (!finite_exp) {
        size_t k = 0;
        while (k < cells && isfinite(expct[k]))
            k++;
        describe_cell(c, (int)k, where, sizeof where);
        set_message(r, "the density integrates to a negative or non-finite value over %s", where);
    } else if (r->in_zero_cells > MC_GOF_ZERO_CELL_FRAC * n) {
        size_t k = 0;
        while (k < cells && !(expct[k] == 0.0 && c->obs[k] > 0.0))
            k++;
        describe_cell(c, (int)k, where, sizeof where);
        set_message(r, "%llu sample(s) fell where the density integrates to 0, e.g. in %s",
                    (unsigned long long)r->in_zero_cells, where);
    } else if (!(fabs(r->pdf_integral - 1.0) <= c->o.norm_tol + r->pdf_integral_error)) {
        set_message(r, "the density integrates to %.9g over the domain (atoms included), not 1%s",
                    r->pdf_integral, r->pdf_integral_error > 0.0 ? " (beyond the quadrature's error)" : "");
    } else if (!(r->pdf_mismatch <= c->o.pdf_tol)) {
        set_message(r,
                    "at sample %llu the sampler reported pdf %.9g but the pdf function gives %.9g "
                    "(relative difference %.3g > %.3g)",
                    (unsigned long long)c->worst_pdf_at, c->rep_pdf, c->cb_pdf, r->pdf_mismatch,
                    c->o.pdf_tol);
    } else if (c->s.eval && !(r->weight_mismatch <= c->o.weight_tol)) {
        set_message(r, "at sample %llu the weight differs from eval(x) / pdf(x) by %.3g (relative)",
                    (unsigned long long)c->worst_weight_at, r->weight_mismatch);
    } else if (c->s.invert && !(r->invert_error <= c->o.invert_tol)) {
        set_message(r, "invert(sample(u)) differs from u by %.3g at sample %llu (tolerance %.3g)",
                    r->invert_error, (unsigned long long)c->worst_invert_at, c->o.invert_tol);
    } else if (!(r->pvalue >= r->level)) {
        int k = worst_cell(c, expct, cells);
        describe_cell(c, k, where, sizeof where);
        set_message(r,
                    "chi-square %.6g with %d degrees of freedom: p = %.3g, below the level %.3g; "
                    "the largest deviation is in %s (observed %.0f, expected %.1f)",
                    r->statistic, r->dof, r->pvalue, r->level, where, k >= 0 ? c->obs[k] : 0.0,
                    k >= 0 ? expct[k] : 0.0);
    } else {
        r->pass = true;
        r->message[0] = '\0';
    }
}

int mcbox_check_finish(mcbox_check *c, mcbox_check_result *out, mcbox_check_table *t)
{
    mcbox_check_result *r = &c->r;
    size_t cells = (size_t)c->chart_cells + c->s.n_atoms;
    double *expct = malloc(cells * sizeof *expct);
    int status = 0;
    if (t)
        memset(t, 0, sizeof *t);
    if (c->invalid || !expct || c->n == 0) {
        set_message(r, "%s",
                    c->invalid ? c->invalid_msg : !expct ? "out of memory" : "no samples to check");
        r->pass = false;
        status = -1;
        goto done;
    }
    r->samples = c->n;
    r->cells = cells;
    r->level = mc_sidak_alpha(c->o.alpha, c->o.tests);
    if (r->weight_reported)
        r->weight_mean = c->sum_weight / (double)r->weight_reported;
    /* Cell probabilities, their sum (the normalization) and the expected
     * counts exactly as mc_gof_expected makes them from the same numbers. */
    r->pdf_integral_error = 0.0;
    int qs = c->s.pdf ? mc_gof_cell_probs(&c->spec, expct)
                      : batch_probs(c, expct, &r->pdf_integral_error);
    if (qs != 0) {
        set_message(r, "out of memory (quadrature workspaces)");
        r->pass = false;
        status = -1;
        goto done;
    }
    double integral = 0.0;
    for (int k = 0; k < c->chart_cells; k++)
        integral += expct[k];
    for (size_t k = 0; k < c->s.n_atoms; k++) {
        integral += c->s.atom_mass[k];
        expct[(size_t)c->chart_cells + k] = c->s.atom_mass[k];
    }
    r->pdf_integral = integral;
    mc_gof_expected_of_probs(expct, cells, c->n, expct);
    bool finite = true;
    for (size_t k = 0; k < cells; k++)
        finite = finite && isfinite(expct[k]);
    mc_chi2_result pr = mc_chi2_pearson(c->obs, expct, cells, MC_GOF_MIN_EXPECTED);
    r->statistic = pr.stat;
    r->dof = pr.dof;
    r->pvalue = pr.pvalue;
    r->cells_pooled = pr.cells_pooled;
    r->in_zero_cells = (uint64_t)pr.obs_in_zero_cells;
    verdict(c, expct, cells, finite);
    if (t) {
        t->dims = c->spec.dims;
        t->nx = c->spec.cells[0];
        t->ny = c->spec.dims == 2 ? c->spec.cells[1] : 1;
        t->lo[0] = c->spec.lo[0], t->hi[0] = c->spec.hi[0];
        t->lo[1] = c->spec.dims == 2 ? c->spec.lo[1] : 0.0;
        t->hi[1] = c->spec.dims == 2 ? c->spec.hi[1] : 0.0;
        chart_labels(c, t->xlabel, t->ylabel, sizeof t->xlabel);
        t->cells = cells;
        t->observed = c->obs, c->obs = NULL;
        t->expected = expct, expct = NULL;
    }
done:
    *out = *r;
    free(expct);
    free(c->obs);
    free(c);
    return status;
}

/* --- the whole check in one call ----------------------------------------- */

int mcbox_check_run(const mcbox_sampler *s, const mcbox_check_options *o,
                    mcbox_check_result *r, mcbox_check_table *t)
{
    if (t)
        memset(t, 0, sizeof *t);
    mcbox_check *c = mcbox_check_begin(s, o, r);
    if (!c)
        return -1;
    if (!s->sample && !(s->uniforms == 0 && s->sample_stream)) {
        free(c->obs);
        free(c);
        set_message(r, s->uniforms == 0 ? "uniforms = 0 needs sample_stream"
                                        : "the sampler has no sample function");
        return -1;
    }
    enum { CHUNK = 1024 };
    mcbox_sample batch[CHUNK];
    double u[CHUNK * MCBOX_MAX_UNIFORMS];
    int nu = s->uniforms;
    struct mcbox_stream stream;
    for (uint64_t done = 0; done < o->samples;) {
        size_t m = (size_t)(o->samples - done < CHUNK ? o->samples - done : CHUNK);
        for (size_t i = 0; i < m; i++) {
            mcbox_sample *q = &batch[i];
            q->x[0] = q->x[1] = q->x[2] = 0.0;
            q->pdf = q->weight = (double)NAN;
            q->atom = -1;
            if (nu == 0) {
                stream.rng = c->rng;
                s->sample_stream(&stream, q, s->ctx);
                c->rng = stream.rng;
            } else {
                mcbox_check_uniforms(c, u + i * (size_t)nu);
                s->sample(u + i * (size_t)nu, q, s->ctx);
            }
        }
        mcbox_check_add(c, batch, nu ? u : NULL, m);
        done += m;
    }
    return mcbox_check_finish(c, r, t);
}

int mcbox_check_points(const mcbox_sampler *s, const mcbox_sample *samples, uint64_t n,
                       const mcbox_check_options *o, mcbox_check_result *r,
                       mcbox_check_table *t)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (o && n == 0) {
        fresh_result(r);
        set_message(r, "no samples to check");
        return -1;
    }
    mcbox_check_options oo;
    if (o) {
        oo = *o;
        oo.samples = n; /* the resolution follows the points there are */
    }
    mcbox_check *c = mcbox_check_begin(s, o ? &oo : NULL, r);
    if (!c)
        return -1;
    for (uint64_t done = 0; done < n;) {
        size_t m = (size_t)(n - done < 65536 ? n - done : 65536);
        mcbox_check_add(c, samples + done, NULL, m);
        done += m;
    }
    return mcbox_check_finish(c, r, t);
}

/* --- tables made elsewhere ------------------------------------------------- */

int mcbox_check_counts(const double *observed, const double *expected, size_t cells,
                       const mcbox_check_options *o, mcbox_check_result *r)
{
    fresh_result(r);
    char err[200];
    if (!observed || !expected || cells == 0 || !o) {
        set_message(r, "no tables (observed, expected, cells >= 1) or no options");
        return -1;
    }
    if (!options_valid(o, err, sizeof err)) {
        set_message(r, "invalid option: %s", err);
        return -1;
    }
    double n = 0.0;
    for (size_t k = 0; k < cells; k++) {
        if (!(observed[k] >= 0.0 && isfinite(observed[k]))) {
            set_message(r, "observed[%zu] = %g is not a finite count >= 0", k, observed[k]);
            return -1;
        }
        if (!(expected[k] >= 0.0 && isfinite(expected[k]))) {
            set_message(r, "expected[%zu] = %g is not a finite count >= 0", k, expected[k]);
            return -1;
        }
        n += observed[k];
    }
    mc_chi2_result pr = mc_chi2_pearson(observed, expected, cells, MC_GOF_MIN_EXPECTED);
    r->samples = (uint64_t)n;
    r->cells = cells;
    r->statistic = pr.stat;
    r->dof = pr.dof;
    r->pvalue = pr.pvalue;
    r->cells_pooled = pr.cells_pooled;
    r->in_zero_cells = (uint64_t)pr.obs_in_zero_cells;
    r->level = mc_sidak_alpha(o->alpha, o->tests);
    r->pdf_mismatch = 0.0;
    if (r->in_zero_cells > MC_GOF_ZERO_CELL_FRAC * n) {
        set_message(r, "%llu observation(s) in cells whose expected count is 0",
                    (unsigned long long)r->in_zero_cells);
    } else if (pr.dof < 1) {
        set_message(r, "no degrees of freedom: fewer than 2 cells after pooling");
    } else if (!(r->pvalue >= r->level)) {
        set_message(r, "chi-square %.6g with %d degrees of freedom: p = %.3g, below the level %.3g",
                    r->statistic, r->dof, r->pvalue, r->level);
    } else {
        r->pass = true;
    }
    return 0;
}
