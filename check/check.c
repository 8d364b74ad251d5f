/* check/check.c - the public check of a user's sampler: the suite's chart,
 * histogram, per-cell quadrature and Pearson test (mc/gof.h, catalog/) run
 * on callbacks, with the checks a chi-square test alone misses. This file
 * holds the samples' side; run.c the whole check in one call; chart.c,
 * quadrature.c, rules.c and verdict.c the rest. */
#include "check/check.h"
#include "check/internal.h"
#include "check/stream.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"

double mcbox_uniform(mcbox_stream *s)
{
    return mc_rng_uniform(&s->rng);
}

mc_rng *chk_stream_rng(mcbox_stream *s)
{
    return &s->rng;
}

#define STR2(x) #x
#define STR(x) STR2(x)

const char *mcbox_version(void)
{
    return STR(MCBOX_VERSION_MAJOR) "." STR(MCBOX_VERSION_MINOR) "." STR(MCBOX_VERSION_PATCH);
}

static const char *const domain_names[] = {
    "interval", "square", "disc", "triangle", "sphere", "hemisphere", "catalog", "cap",
    "spherical-triangle", "spherical-quad"};
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
    case MCBOX_HEMISPHERE:
    case MCBOX_CAP:
    case MCBOX_SPHERICAL_TRIANGLE:
    case MCBOX_SPHERICAL_QUAD: return 3;
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
    o.quad_depth = 12;
    o.quad_error_max = 1e-3;
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

/* A sample marked as an atom must be that atom's point to within this. */
#define ATOM_TOL 1e-9

void chk_fresh_result(mcbox_check_result *r)
{
    memset(r, 0, sizeof *r);
    r->pvalue = (double)NAN;
    r->statistic = (double)NAN;
    r->pdf_integral = (double)NAN;
    r->pdf_integral_error = (double)NAN;
    r->weight_mean = (double)NAN;
    r->weight_mismatch = (double)NAN;
    r->invert_error = (double)NAN;
    r->power_rel_error = (double)NAN;
    r->scale_detectable = (double)NAN;
}

bool chk_options_valid(const mcbox_check_options *o, char *err, size_t errlen)
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
                      : (o->quad_depth < 0 || o->quad_depth > 30)        ? "quad_depth must be 0..30"
                      : !(o->quad_error_max > 0.0)                       ? "quad_error_max must be > 0"
                                                                          : NULL;
    if (bad)
        snprintf(err, errlen, "%s", bad);
    return bad == NULL;
}

mcbox_check *mcbox_check_begin(const mcbox_sampler *s, const mcbox_check_options *o,
                               mcbox_check_result *r)
{
    chk_fresh_result(r);
    char err[200];
    if (!s || !o) {
        chk_set_message(r, "no sampler or no options");
        return NULL;
    }
    if (!chk_options_valid(o, err, sizeof err)) {
        chk_set_message(r, "invalid option: %s", err);
        return NULL;
    }
    if (!s->pdf && !s->pdf_batch) {
        chk_set_message(r, "the sampler has no pdf (pdf or pdf_batch is required)");
        return NULL;
    }
    if (s->uniforms < 0 || s->uniforms > MCBOX_MAX_UNIFORMS) {
        chk_set_message(r, "uniforms must be 0 .. %d", MCBOX_MAX_UNIFORMS);
        return NULL;
    }
    if (s->n_atoms && (!s->atom_x || !s->atom_mass)) {
        chk_set_message(r, "n_atoms > 0 needs atom_x and atom_mass");
        return NULL;
    }
    for (size_t k = 0; k < s->n_atoms; k++)
        if (!(s->atom_mass[k] >= 0.0 && s->atom_mass[k] <= 1.0)) {
            chk_set_message(r, "atom %zu has mass %g, not in [0, 1]", k, s->atom_mass[k]);
            return NULL;
        }
    mcbox_check *c = calloc(1, sizeof *c);
    if (!c) {
        chk_set_message(r, "out of memory");
        return NULL;
    }
    c->s = *s;
    c->o = *o;
    if (!chk_make_chart(c, err, sizeof err)) {
        chk_set_message(r, "%s", err);
        free(c);
        return NULL;
    }
    c->dims = mcbox_domain_dims(&c->s.domain);
    bool given = o->cells[0] > 0;
    if (given && c->st.chart != CAT_CHART_LINE && c->st.chart != CAT_CHART_INDEX &&
        o->cells[1] < 1) {
        chk_set_message(r, "cells: a 2D chart needs both resolutions");
        free(c);
        return NULL;
    }
    c->spec = given ? cat_gof_spec(&c->st, o->cells) : cat_gof_spec_for(&c->st, o->samples);
    c->spec.sample = NULL;
    c->spec.pdf = chk_chart_density;
    c->spec.ctx = c;
    c->chart_cells = mc_gof_cell_count(&c->spec);
    c->obs = calloc((size_t)c->chart_cells + s->n_atoms, sizeof *c->obs);
    if (c->chart_cells <= CHK_HINT_MAX_CELLS) {
        size_t m = (size_t)c->chart_cells * (size_t)c->dims;
        c->hint_x = malloc(m * sizeof *c->hint_x);
        for (size_t k = 0; c->hint_x && k < m; k++)
            c->hint_x[k] = (double)NAN;
    }
    if (!c->obs || (c->chart_cells <= CHK_HINT_MAX_CELLS && !c->hint_x)) {
        chk_set_message(r, "out of memory");
        free(c->obs);
        free(c->hint_x);
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

static void remember(mcbox_check *c, uint64_t *first, uint64_t count_before, const double x[3])
{
    if (count_before == 0) {
        *first = c->n;
        memcpy(c->example, x, sizeof c->example);
    }
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
    (void)chk_densities(c, n, reported_point, smp, out);
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
        if (cell < 0 || !chk_in_domain(c, x)) {
            remember(c, &c->first_outside, r->outside, x);
            r->outside++;
        }
        if (cell >= 0) {
            c->obs[cell] += 1.0;
            double *h = c->hint_x ? c->hint_x + (size_t)cell * (size_t)c->dims : NULL;
            if (h && isnan(h[0]))
                memcpy(h, x, (size_t)c->dims * sizeof *h);
        }
        if (c->dims == 3)
            for (int j = 0; j < 3; j++)
                c->sum_dir[j] += x[j];
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

int mcbox_check_finish(mcbox_check *c, mcbox_check_result *out, mcbox_check_table *t)
{
    mcbox_check_result *r = &c->r;
    size_t cells = (size_t)c->chart_cells + c->s.n_atoms;
    double *expct = malloc(cells * sizeof *expct);
    int status = 0;
    if (t)
        memset(t, 0, sizeof *t);
    if (c->invalid || !expct || c->n == 0) {
        chk_set_message(r, "%s",
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
    chk_quad_report q;
    if (chk_cell_probs(c, expct, &q) != 0) {
        chk_set_message(r, "out of memory (quadrature workspaces)");
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
    r->pdf_integral_error = q.error;
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
    chk_verdict(c, expct, cells, finite, &q);
    if (t) {
        t->dims = c->spec.dims;
        t->nx = c->spec.cells[0];
        t->ny = c->spec.dims == 2 ? c->spec.cells[1] : 1;
        t->lo[0] = c->spec.lo[0], t->hi[0] = c->spec.hi[0];
        t->lo[1] = c->spec.dims == 2 ? c->spec.lo[1] : 0.0;
        t->hi[1] = c->spec.dims == 2 ? c->spec.hi[1] : 0.0;
        chk_chart_labels(c, t->xlabel, t->ylabel, sizeof t->xlabel);
        t->cells = cells;
        t->observed = c->obs, c->obs = NULL;
        t->expected = expct, expct = NULL;
    }
done:
    *out = *r;
    free(expct);
    free(c->obs);
    free(c->hint_x);
    free(c);
    return status;
}
