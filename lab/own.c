/* lab/own.c - the warp lab's own-warp box: a sampler the reader writes in
 * JavaScript on the page, judged by the public check (check/check.h) as
 * the exercises judge theirs (exercises/check_exercise.c,
 * ex_check_sampler_law), with a catalog row as the law asked for.
 *
 * The page draws nothing at random: it asks for the uniforms here (PCG32,
 * two per sample, the stream mcbox_check_run would hand a sampler), calls
 * the reader's sample(u1, u2) and pdf(x) on them and writes the points and
 * densities back. The check then calls the reader's pdf and invert through
 * the module's two imports (lab/own.js answers them), so the cells'
 * integrals come from the check's own quadrature over the reader's density:
 * the same judge as `mcbox-check`, the exercises and the catalog's tests.
 */
#include "lab/lab.h"

#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "mc/constants.h"
#include "mc/rng.h"

#define EXPORT(name) __attribute__((export_name(#name)))
/* The reader's functions, answered by the page: the density at x (unused
 * coordinates 0), and the uniforms of x into u[0], u[1]. */
#define IMPORT(name) __attribute__((import_module("lab"), import_name(#name)))
IMPORT(pdf) double lab_js_pdf(double x0, double x1, double x2);
IMPORT(invert) void lab_js_invert(double x0, double x1, double x2, double *u);

/* Each run is two statistical tests: the level alpha is shared (Sidak). */
#define OWN_ALPHA 0.01
#define OWN_TESTS 2
#define OWN_BATCH 1024

static double *own_u, *own_x, *own_pdf;
static uint64_t own_n;
static int own_dims;
static cat_state law; /* the law asked for: a catalog row, its defaults */
static char law_name[120];
static double lobe_width; /* of the law's chart: see default_lobe_width */
static mcbox_sample batch[OWN_BATCH];
static double batch_u[OWN_BATCH * 2];

/* Per check: the report line as the page reads it, and the numbers. */
static char report_text[LAB_OWN_CHECKS][1800];
static mcbox_check_result results[2];
static mcbox_check_table tables[2];
static double numbers[LAB_OWN_CHECKS][LAB_OWN_RESULT_COUNT];

EXPORT(lab_own_prepare) int lab_own_prepare(uint32_t seed_hi, uint32_t seed_lo, double n_real)
{
    free(own_u), free(own_x), free(own_pdf);
    own_u = own_x = own_pdf = NULL;
    own_n = 0;
    if (!(n_real >= 1.0 && n_real <= LAB_OWN_MAX_SAMPLES))
        return 0;
    uint64_t n = (uint64_t)n_real;
    own_u = malloc(2 * n * sizeof *own_u);
    own_x = calloc(3 * n, sizeof *own_x);
    own_pdf = malloc(n * sizeof *own_pdf);
    if (!own_u || !own_x || !own_pdf)
        return 0;
    mc_rng rng = mc_rng_derive((uint64_t)seed_hi << 32 | seed_lo, 0u);
    for (uint64_t k = 0; k < 2 * n; k++)
        own_u[k] = mc_rng_uniform(&rng);
    own_n = n;
    return 1;
}

EXPORT(lab_own_uniforms) double *lab_own_uniforms(void)
{
    return own_u;
}

EXPORT(lab_own_points) double *lab_own_points(void)
{
    return own_x;
}

EXPORT(lab_own_pdfs) double *lab_own_pdfs(void)
{
    return own_pdf;
}

/* --- the callbacks of the check ------------------------------------------ */

static double reader_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return lab_js_pdf(x[0], own_dims > 1 ? x[1] : 0.0, own_dims > 2 ? x[2] : 0.0);
}

static void reader_invert(const double *x, double *u, void *ctx)
{
    (void)ctx;
    lab_js_invert(x[0], own_dims > 1 ? x[1] : 0.0, own_dims > 2 ? x[2] : 0.0, u);
}

static double law_pdf(const double *x, void *ctx)
{
    (void)ctx;
    double p[3] = {x[0], own_dims > 1 ? x[1] : 0.0, own_dims > 2 ? x[2] : 0.0};
    return cat_pdf(&law, p);
}

/* --- one check over the page's points -------------------------------------- */

/* The lobe width of the row's own test case at its default parameters:
 * the catalog's tests histogram a narrow lobe (Phong's n = 40) in a lobe
 * chart, which the check then uses too; 0 for the row's chart. */
static double default_lobe_width(const cat_row *row)
{
    char defs[200];
    cat_param_defaults(row, defs, sizeof defs);
    for (const cat_case *c = row->cases; c->name; c++)
        if (c->params ? strcmp(c->params, defs) == 0 : strcmp(defs, "-") == 0)
            return c->lobe_width;
    return 0.0;
}

/* The public check of s over the stored points: with the reader's density
 * at each sample reported (`pinned`: the law check) or not, with the
 * uniforms for the round trip when s has an inverse (the first of each
 * pair for an interval, whose inverse gives one). Returns 0 pass, 1 fail,
 * 2 could not run. */
static int run_check(const mcbox_sampler *s, bool pinned, uint64_t seed, mcbox_check_result *r,
                     mcbox_check_table *t)
{
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = own_n, o.seed = seed, o.alpha = OWN_ALPHA, o.tests = OWN_TESTS;
    o.lobe_width = lobe_width;
    mcbox_check *c = mcbox_check_begin(s, &o, r);
    if (!c)
        return 2;
    for (uint64_t done = 0; done < own_n;) {
        size_t m = (size_t)(own_n - done < OWN_BATCH ? own_n - done : OWN_BATCH);
        for (size_t i = 0; i < m; i++) {
            mcbox_sample *q = &batch[i];
            memcpy(q->x, own_x + 3 * (done + i), sizeof q->x);
            q->pdf = pinned ? own_pdf[done + i] : (double)NAN;
            q->weight = (double)NAN;
            q->atom = -1;
            for (int k = 0; k < s->uniforms; k++)
                batch_u[i * (size_t)s->uniforms + (size_t)k] = own_u[2 * (done + i) + (size_t)k];
        }
        mcbox_check_add(c, batch, s->invert ? batch_u : NULL, m);
        done += m;
    }
    if (mcbox_check_finish(c, r, t) != 0)
        return 2;
    return r->pass ? 0 : 1;
}

static void keep(int k, int status, const char *name, const char *key, const char *fig,
                 const char *why, const mcbox_check_result *r, const mcbox_check_table *t)
{
    snprintf(report_text[k], sizeof report_text[k], "%d\t%s\t%s\t%s\t%s\t%s\t%s", status, name, key,
             fig, why ? why : "", t ? t->xlabel : "", t ? t->ylabel : "");
    double *v = numbers[k];
    for (int i = 0; i < LAB_OWN_RESULT_COUNT; i++)
        v[i] = (double)NAN;
    v[0] = status;
    if (!r)
        return;
    double in[] = {r->statistic, r->dof, r->pvalue, r->level, r->pdf_integral,
                   r->pdf_integral_error, r->invert_error, r->pdf_mismatch, (double)r->samples,
                   (double)r->outside, (double)r->cells_pooled, r->power_rel_error};
    memcpy(v + 1, in, sizeof in);
    if (t && t->observed) {
        double tab[] = {t->dims, t->nx, t->ny, t->lo[0], t->hi[0], t->lo[1], t->hi[1]};
        memcpy(v + 13, tab, sizeof tab);
    }
}

static void figure(const mcbox_check_result *r, bool pinned, uint64_t seed, char *fig, size_t size)
{
    char tail[120];
    if (pinned)
        snprintf(tail, sizeof tail, "your density at the samples off the law's by %.3g at most",
                 r->pdf_mismatch);
    else if (!isnan(r->invert_error))
        snprintf(tail, sizeof tail, "integral %.9f; round trip %.2g", r->pdf_integral,
                 r->invert_error);
    else
        snprintf(tail, sizeof tail, "integral %.9f; no inverse", r->pdf_integral);
    snprintf(fig, size,
             "seed %" PRIu64 ", %" PRIu64 " samples, chi-square %.6g with %d dof, p = %.4g "
             "(level %.2g); %s; outside %" PRIu64,
             seed, own_n, r->statistic, r->dof, r->pvalue, r->level, tail, r->outside);
}

/* Why the law check failed, in the reader's terms: the check's "pdf
 * function" is the law here, its "reported pdf" the reader's (as
 * ex_check_sampler_law says it). */
static void law_why(const mcbox_check_result *p, int consistent, char *key, char *why,
                    size_t size)
{
    char cause[600];
    bool chi2_failed = !(p->pvalue >= p->level);
    bool mismatch = !(p->pdf_mismatch <= 1e-6);
    if (p->outside || p->nonfinite || p->in_zero_cells)
        snprintf(cause, sizeof cause, "%s", p->message);
    else if (chi2_failed && strncmp(p->message, "chi-square", 10) == 0)
        snprintf(cause, sizeof cause, "against it, %s", p->message);
    else if (chi2_failed)
        snprintf(cause, sizeof cause, "against it, chi-square %.6g with %d dof, p = %.3g",
                 p->statistic, p->dof, p->pvalue);
    else
        snprintf(cause, sizeof cause, "%s", p->message);
    if (chi2_failed)
        snprintf(key, 120, "chi2 %.5g/%d dof against the law, p = %.3g", p->statistic, p->dof,
                 p->pvalue);
    if (!chi2_failed && mismatch && !p->outside && !p->nonfinite)
        snprintf(why, size,
                 "your points follow %s, but your density is not that law's at the samples "
                 "(largest relative difference %.3g)",
                 law_name, p->pdf_mismatch);
    else if (consistent == 0)
        snprintf(why, size,
                 "your sampler and your density agree with each other, but the points do not "
                 "follow %s: %s",
                 law_name, cause);
    else
        snprintf(why, size, "the points do not follow %s: %s", law_name, cause);
}

/* The point at the centre of grid cell k (as the exercises' grid_point):
 * 64 x 128 cells of (cos theta, phi) on the whole sphere, 128 x 128 of
 * [-1, 1]^2, 1024 of the row's interval. */
static int grid_point(const cat_row *row, int k, double x[3])
{
    x[0] = x[1] = x[2] = 0.0;
    if (own_dims == 3) {
        double z = -1.0 + (k / 128 + 0.5) / 32.0, phi = MC_2PI * (k % 128 + 0.5) / 128.0;
        double r = sqrt(1.0 - z * z);
        x[0] = r * cos(phi), x[1] = r * sin(phi), x[2] = z;
        return 64 * 128;
    }
    if (own_dims == 2) {
        x[0] = -1.0 + (k / 128 + 0.5) / 64.0, x[1] = -1.0 + (k % 128 + 0.5) / 64.0;
        return 128 * 128;
    }
    x[0] = row->lo + (row->hi - row->lo) * (k + 0.5) / 1024.0;
    return 1024;
}

/* The reader's density against the law's on the grid: relative 1e-6,
 * exactly 0 where the law's is 0. Not statistical. */
static void density_grid(const cat_row *row)
{
    int bad = 0, cells = grid_point(row, 0, (double[3]){0});
    double first[3] = {0}, yours_first = 0.0, law_first = 0.0;
    for (int k = 0; k < cells; k++) {
        double x[3];
        grid_point(row, k, x);
        double yours = reader_pdf(x, NULL), ref = cat_pdf(&law, x);
        if (!(fabs(yours - ref) <= 1e-6 * ref) && bad++ == 0) {
            memcpy(first, x, sizeof first);
            yours_first = yours, law_first = ref;
        }
    }
    char key[120], fig[400], at[100], why[400] = "";
    snprintf(key, sizeof key, "%d of %d grid points differ", bad, cells);
    snprintf(fig, sizeof fig,
             "%d of %d grid points where your density differs from %s's by more than 1e-6 "
             "relative",
             bad, cells, law_name);
    if (own_dims == 3)
        snprintf(at, sizeof at, "(%.4g, %.4g, %.4g)", first[0], first[1], first[2]);
    else if (own_dims == 2)
        snprintf(at, sizeof at, "(%.4g, %.4g)", first[0], first[1]);
    else
        snprintf(at, sizeof at, "x = %.6g", first[0]);
    if (bad)
        snprintf(why, sizeof why, "your density is not %s's: at %s yours is %.6g, the law's %.6g",
                 law_name, at, yours_first, law_first);
    keep(2, bad ? 1 : 0, "your density on a grid", key, fig, why, NULL, NULL);
    numbers[2][1] = bad, numbers[2][2] = cells;
}

/* BEGIN SNIPPET lab_own_check */
EXPORT(lab_own_check) int lab_own_check(uint32_t seed_hi, uint32_t seed_lo, int has_invert)
{
    /* The input buffer: the law's row, then its name as the page says it. */
    char *in = lab_input(), *eol = strchr(in, '\n');
    snprintf(law_name, sizeof law_name, "%s", eol ? eol + 1 : in);
    if (eol)
        *eol = '\0';
    const cat_row *row = cat_find(in);
    char err[200];
    if (!own_n || !row || !cat_prepare_named(in, &law, err, sizeof err))
        return 0;
    own_dims = cat_point_dims(row);
    lobe_width = default_lobe_width(row);
    uint64_t seed = (uint64_t)seed_hi << 32 | seed_lo;
    for (int k = 0; k < 2; k++)
        mcbox_check_table_free(&tables[k]);

    /* 1. Your points against your density: the chi-square, the density's
     * integral over the domain, the round trip. */
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = row->name;
    s.uniforms = own_dims == 1 ? 1 : 2;
    s.pdf = reader_pdf;
    s.invert = has_invert ? reader_invert : NULL;
    char key[120], fig[400], why[800];
    int mine = run_check(&s, false, seed, &results[0], &tables[0]);
    mcbox_check_figure(&results[0], key, sizeof key);
    figure(&results[0], false, seed, fig, sizeof fig);
    keep(0, mine, "your points, your density", key, fig, results[0].message, &results[0],
         &tables[0]);

    /* 2. The same points against the law asked for, your density at each
     * sample compared with the law's. */
    s.pdf = law_pdf, s.invert = NULL;
    int pinned = run_check(&s, true, seed, &results[1], &tables[1]);
    mcbox_check_figure(&results[1], key, sizeof key);
    figure(&results[1], true, seed, fig, sizeof fig);
    why[0] = '\0';
    if (pinned == 1)
        law_why(&results[1], mine, key, why, sizeof why);
    else if (pinned == 2)
        snprintf(why, sizeof why, "%s", results[1].message);
    char name[160];
    snprintf(name, sizeof name, "your points against %s", law_name);
    keep(1, pinned, name, key, fig, why, &results[1], &tables[1]);

    /* 3. Your density against the law's on a grid over the domain. */
    density_grid(row);
    return 1;
}
/* END SNIPPET lab_own_check */

EXPORT(lab_own_report) const char *lab_own_report(int k)
{
    return k >= 0 && k < LAB_OWN_CHECKS ? report_text[k] : "";
}

EXPORT(lab_own_result) double *lab_own_result(int k)
{
    return k >= 0 && k < LAB_OWN_CHECKS ? numbers[k] : NULL;
}

EXPORT(lab_own_observed) double *lab_own_observed(int k)
{
    return k >= 0 && k < 2 ? tables[k].observed : NULL;
}

EXPORT(lab_own_expected) double *lab_own_expected(int k)
{
    return k >= 0 && k < 2 ? tables[k].expected : NULL;
}
