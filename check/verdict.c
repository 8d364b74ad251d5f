/* check/verdict.c - the verdict of a check from its counts and the
 * quadrature's report, in the order a user should fix things, and what a
 * pass proves: the smallest error the run could have seen, and whether
 * the chart resolves the density at all. */
#include "check/internal.h"

#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"

/* The power statement: a region holding this share of the mass, a
 * detection probability of 0.9. */
#define POWER_SHARE 0.1
#define POWER_PROB 0.9
/* A chart resolves a density when 90% of the expected count spreads over
 * more than RESOLVE_MIN rows and columns (of at least RESOLVE_AXIS). */
#define RESOLVE_MASS 0.9
#define RESOLVE_MIN 2
#define RESOLVE_AXIS 8

void chk_set_message(mcbox_check_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->message, sizeof r->message, fmt, ap);
    va_end(ap);
}

static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* The fewest of v[0 .. n) (sorted in place, descending) whose sum reaches
 * `share` of the whole. */
static uint64_t fewest_for(double *v, size_t n, double share)
{
    double total = 0.0;
    for (size_t k = 0; k < n; k++)
        total += v[k];
    qsort(v, n, sizeof *v, cmp_desc);
    double acc = 0.0;
    size_t k = 0;
    while (k < n && acc < share * total)
        acc += v[k++];
    return (uint64_t)k;
}

/* How many chart cells, rows and columns hold RESOLVE_MASS of the
 * expected count; false (and the rows or columns concerned) when the
 * chart does not resolve the density. */
static bool resolves(mcbox_check *c, const double *expct, char *why, size_t size)
{
    int nx = c->spec.cells[0], ny = c->spec.dims == 2 ? c->spec.cells[1] : 1;
    size_t cells = (size_t)c->chart_cells;
    double *v = malloc((cells + (size_t)nx + (size_t)ny) * sizeof *v);
    if (!v)
        return true;
    double *rows = v + cells, *cols = rows + nx;
    memset(rows, 0, ((size_t)nx + (size_t)ny) * sizeof *rows);
    for (size_t k = 0; k < cells; k++) {
        v[k] = expct[k];
        rows[k / (size_t)ny] += expct[k];
        cols[k % (size_t)ny] += expct[k];
    }
    c->r.cells_90 = fewest_for(v, cells, RESOLVE_MASS);
    double total = 0.0;
    for (size_t k = 0; k < cells; k++)
        total += expct[k];
    if (!(total > 0.0)) {
        free(v);
        return true; /* nothing to resolve: the verdict says why */
    }
    uint64_t r90 = fewest_for(rows, (size_t)nx, RESOLVE_MASS);
    uint64_t c90 = c->spec.dims == 2 ? fewest_for(cols, (size_t)ny, RESOLVE_MASS) : (uint64_t)ny;
    free(v);
    char lx[32], ly[32];
    chk_chart_labels(c, lx, ly, sizeof lx);
    if (nx >= RESOLVE_AXIS && r90 <= RESOLVE_MIN) {
        snprintf(why, size, "%d%% of the expected count lies in %llu of %d cells along %s",
                 (int)(100 * RESOLVE_MASS), (unsigned long long)r90, nx, lx);
        return false;
    }
    if (c->spec.dims == 2 && ny >= RESOLVE_AXIS && c90 <= RESOLVE_MIN) {
        snprintf(why, size, "%d%% of the expected count lies in %llu of %d cells along %s",
                 (int)(100 * RESOLVE_MASS), (unsigned long long)c90, ny, ly);
        return false;
    }
    return true;
}

/* The warning for a chart that does not resolve the density, with what to
 * pass: for directions, a lobe chart about the samples' mean direction
 * with their spread as its width (for a lobe of small angular spread
 * theta, 1 - |mean| ~ E[theta^2] / 2). */
static void resolution_warning(mcbox_check *c, const char *why)
{
    mcbox_check_result *r = &c->r;
    double n = (double)c->n, m[3] = {c->sum_dir[0] / n, c->sum_dir[1] / n, c->sum_dir[2] / n};
    double len = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    if (chk_directions(c) && len > 0.5) {
        r->lobe_hint_width = sqrt(2.0 * (1.0 - len));
        if (!(r->lobe_hint_width > 1e-6))
            r->lobe_hint_width = 1e-6;
        for (int k = 0; k < 3; k++)
            r->lobe_hint_axis[k] = m[k] / len;
        snprintf(r->warning, sizeof r->warning,
                 "the chart does not resolve the density (%s): pass --lobe-width %.3g "
                 "--lobe-axis %.6g,%.6g,%.6g, or a domain that fits its support (cap, "
                 "spherical-triangle, spherical-quad)",
                 why, r->lobe_hint_width, r->lobe_hint_axis[0], r->lobe_hint_axis[1],
                 r->lobe_hint_axis[2]);
    } else {
        snprintf(r->warning, sizeof r->warning,
                 "the chart does not resolve the density (%s): pass finer --cells", why);
    }
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

/* What the run could have detected. For the claimed law q and a true law
 * p equal to q times 1 + e over a region of mass s (made of whole cells)
 * and rescaled to keep its total outside, Pearson's noncentrality is
 * n [e^2 s + (e s / (1 - s))^2 (1 - s)] = n e^2 s / (1 - s). */
static void power(mcbox_check *c, const chk_quad_report *q)
{
    mcbox_check_result *r = &c->r;
    r->power_share = POWER_SHARE;
    r->scale_detectable = c->o.norm_tol + q->error;
    r->power_rel_error = (double)NAN;
    if (r->dof >= 1 && r->level > 0.0 && r->level < POWER_PROB) {
        double lambda = mc_chi2_noncentrality_for_power(r->dof, r->level, POWER_PROB);
        r->power_rel_error =
            sqrt(lambda * (1.0 - POWER_SHARE) / ((double)c->n * POWER_SHARE));
    }
}

/* The first failing check's message, in the order a user should fix them:
 * points that are not points, points outside, a density that is not one,
 * what the quadrature could not settle, then the statistics. */
static void decide(mcbox_check *c, const double *expct, size_t cells, bool finite_exp,
                   const chk_quad_report *q, bool resolved)
{
    mcbox_check_result *r = &c->r;
    char where[160], pt[120];
    chk_coords(c, c->example, pt, sizeof pt);
    const char *dom = c->s.domain.kind == MCBOX_CATALOG ? c->st.row->domain
                                                        : mcbox_domain_name(c->s.domain.kind);
    double n = (double)c->n;
    bool norm_off = !(fabs(r->pdf_integral - 1.0) <= c->o.norm_tol + q->error);
    r->pass = false;
    r->undetermined = false;
    if (r->nonfinite) {
        chk_set_message(r, "%llu sample(s) with a NaN or infinite coordinate; the first is sample %llu",
                        (unsigned long long)r->nonfinite, (unsigned long long)c->first_nonfinite);
    } else if (r->bad_atoms) {
        chk_set_message(r, "%llu sample(s) marked as an atom that is not one; the first is sample %llu %s",
                        (unsigned long long)r->bad_atoms, (unsigned long long)c->first_bad_atom, pt);
    } else if (r->outside) {
        chk_set_message(r, "%llu sample(s) outside the domain %s; the first is sample %llu %s",
                        (unsigned long long)r->outside, dom, (unsigned long long)c->first_outside, pt);
    } else if (r->bad_pdf) {
        chk_set_message(r, "pdf(x) = %g (negative or not finite) at sample %llu %s", c->bad_pdf_value,
                        (unsigned long long)c->first_bad_pdf, pt);
    } else if (!finite_exp) {
        size_t k = 0;
        while (k < cells && isfinite(expct[k]))
            k++;
        chk_describe_cell(c, (int)k, where, sizeof where);
        chk_set_message(r, "the density integrates to a negative or non-finite value over %s", where);
    } else if (q->missed_cell >= 0) {
        r->undetermined = true;
        chk_describe_cell(c, q->missed_cell, where, sizeof where);
        chk_coords(c, q->missed_x, pt, sizeof pt);
        chk_set_message(r,
                        "undetermined: the quadrature missed part of the density's support: %s "
                        "integrates to 0 after %d halvings, but the density is positive at the "
                        "sample %s in it; pass a domain whose chart follows the support or a "
                        "larger quad_depth",
                        where, c->o.quad_depth, pt);
    } else if (r->in_zero_cells > MC_GOF_ZERO_CELL_FRAC * n) {
        size_t k = 0;
        while (k < cells && !(expct[k] == 0.0 && c->obs[k] > 0.0))
            k++;
        chk_describe_cell(c, (int)k, where, sizeof where);
        chk_set_message(r,
                        "%llu sample(s) fell where the density is 0 (the density is 0 at them "
                        "and integrates to 0 around them), e.g. in %s",
                        (unsigned long long)r->in_zero_cells, where);
    } else if (norm_off) {
        chk_set_message(r,
                        "the density integrates to %.9g over the domain (atoms included), not 1 "
                        "(allowed: %.3g, of which %.3g is the quadrature's error)",
                        r->pdf_integral, c->o.norm_tol + q->error, q->error);
    } else if (!(q->error <= c->o.quad_error_max)) {
        r->undetermined = true;
        chk_set_message(r,
                        "undetermined: the quadrature's error estimate %.3g on the density's "
                        "integral exceeds quad_error_max %.3g (the density jumps, or is infinite, "
                        "inside cells); pass a domain whose chart follows its edges, a lobe chart "
                        "(lobe width and axis) about a point where it is infinite, or a larger "
                        "quad_depth",
                        q->error, c->o.quad_error_max);
    } else if (!(r->pdf_mismatch <= c->o.pdf_tol)) {
        chk_set_message(r,
                        "at sample %llu the sampler reported pdf %.9g but the pdf function gives "
                        "%.9g (relative difference %.3g > %.3g)",
                        (unsigned long long)c->worst_pdf_at, c->rep_pdf, c->cb_pdf, r->pdf_mismatch,
                        c->o.pdf_tol);
    } else if (c->s.eval && !(r->weight_mismatch <= c->o.weight_tol)) {
        chk_set_message(r, "at sample %llu the weight differs from eval(x) / pdf(x) by %.3g (relative)",
                        (unsigned long long)c->worst_weight_at, r->weight_mismatch);
    } else if (c->s.invert && !(r->invert_error <= c->o.invert_tol)) {
        chk_set_message(r, "invert(sample(u)) differs from u by %.3g at sample %llu (tolerance %.3g)",
                        r->invert_error, (unsigned long long)c->worst_invert_at, c->o.invert_tol);
    } else if (!(r->pvalue >= r->level)) {
        int k = worst_cell(c, expct, cells);
        chk_describe_cell(c, k, where, sizeof where);
        chk_set_message(r,
                        "chi-square %.6g with %d degrees of freedom: p = %.3g, below the level %.3g; "
                        "the largest deviation is in %s (observed %.0f, expected %.1f)",
                        r->statistic, r->dof, r->pvalue, r->level, where, k >= 0 ? c->obs[k] : 0.0,
                        k >= 0 ? expct[k] : 0.0);
    } else if (!resolved) {
        r->undetermined = true;
        chk_set_message(r, "undetermined: the test passed, but %s", r->warning);
    } else {
        r->pass = true;
        r->message[0] = '\0';
    }
}

void chk_verdict(mcbox_check *c, const double *expct, size_t cells, bool finite_exp,
                 const chk_quad_report *q)
{
    char why[160] = "";
    bool resolved = !finite_exp || resolves(c, expct, why, sizeof why);
    if (!resolved)
        resolution_warning(c, why);
    power(c, q);
    decide(c, expct, cells, finite_exp, q, resolved);
}

void mcbox_check_figure(const mcbox_check_result *r, char *buf, size_t size)
{
    if (r->nonfinite)
        snprintf(buf, size, "%" PRIu64 " non-finite samples", r->nonfinite);
    else if (r->outside)
        snprintf(buf, size, "%" PRIu64 " samples outside", r->outside);
    else if (r->bad_pdf)
        snprintf(buf, size, "%" PRIu64 " bad pdf values", r->bad_pdf);
    else if (!(fabs(r->pdf_integral - 1.0) <= 1e-6))
        snprintf(buf, size, "pdf integrates to %.6g", r->pdf_integral);
    else if (!(r->pdf_mismatch <= 1e-6))
        snprintf(buf, size, "reported pdf off by %.3g", r->pdf_mismatch);
    else if (!isnan(r->invert_error) && !(r->invert_error <= 1e-6))
        snprintf(buf, size, "round trip off by %.3g", r->invert_error);
    else
        snprintf(buf, size, "chi2 %.5g/%d dof, p = %.3g", r->statistic, r->dof, r->pvalue);
}
