/* lab/lab.c - the warp lab's glue: the functions lab/lab.h exports to the
 * book's lab page, over the public functions of catalog/, mc/ and pdf/.
 *
 * Nothing here tests or samples on its own: a chi-square run of an
 * independent source is `warp chi2`'s (cat_gof_spec_for, mc_rng_derive
 * (seed, 0), mc_gof_test), so the page and the command line print the same
 * statistic for the same row, seed and count. The other sources replace
 * only the uniforms fed to the row's warp. Built for wasm32 by mk/lab.mk
 * (one thread: the OpenMP pragmas of the library are ignored there).
 */
#include "lab/lab.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "mc/constants.h"
#include "mc/gof.h"
#include "mc/integrate.h"
#include "mc/qmc.h"
#include "mc/stats.h"
#include "mc/strat.h"

/* Every export is named for the page; nothing else leaves the module. */
#define EXPORT(name) __attribute__((export_name(#name)))

static char input[LAB_INPUT_SIZE];
static char message[512];
static char line[160];
static char catalog_json[65536];
static cat_state state; /* large and self-referencing: never copied */
static bool selected;
static double result[LAB_RESULT_COUNT];
static double *observed, *expected;
static double points[LAB_MAX_POINTS * LAB_POINT_STRIDE];

static uint64_t seed_of(uint32_t hi, uint32_t lo)
{
    return (uint64_t)hi << 32 | lo;
}

EXPORT(lab_input) char *lab_input(void)
{
    return input;
}

EXPORT(lab_error) const char *lab_error(void)
{
    return message;
}

/* --- the catalog as JSON ------------------------------------------------- */

typedef struct text {
    char *p;
    size_t len, cap;
} text;

static void put(text *t, const char *s)
{
    size_t k = strlen(s);
    if (t->len + k < t->cap) {
        memcpy(t->p + t->len, s, k + 1);
        t->len += k;
    }
}

/* A JSON string: quotes, backslashes and control characters escaped. */
static void put_string(text *t, const char *s)
{
    if (!s) {
        put(t, "null");
        return;
    }
    put(t, "\"");
    for (; *s; s++) {
        char c[8] = {*s, '\0'};
        if (*s == '"' || *s == '\\')
            c[0] = '\\', c[1] = *s, c[2] = '\0';
        else if ((unsigned char)*s < 0x20)
            snprintf(c, sizeof c, "\\u%04x", (unsigned)*s);
        put(t, c);
    }
    put(t, "\"");
}

static void put_number(text *t, double x)
{
    char buf[40];
    snprintf(buf, sizeof buf, isfinite(x) ? "%.17g" : "null", x);
    put(t, buf);
}

static int sources_of(const cat_row *r)
{
    int s = 1 << LAB_INDEPENDENT;
    if (r->sample_u && r->uniforms >= 1 && r->uniforms <= 2)
        s |= 1 << LAB_JITTERED;
    if (r->sample_u && r->uniforms >= 1)
        s |= 1 << LAB_SOBOL;
    return s;
}

static void put_row(text *t, const cat_row *r)
{
    static const char *const points_of[] = {"direction", "point", "planar", "real", "index"};
    static const char *const charts[] = {"line", "index", "xy", "disc", "parallelogram",
                                         "surface", "direction", "lobe"};
    static const char *const kinds[] = {"number", "vector", "list"};
    char buf[64];
    put(t, "{\"name\":");
    put_string(t, r->name);
    put(t, ",\"domain\":");
    put_string(t, r->domain);
    put(t, ",\"measure\":");
    put_string(t, r->measure);
    put(t, ",\"point\":");
    put_string(t, points_of[r->point]);
    put(t, ",\"chart\":");
    put_string(t, charts[r->chart]);
    snprintf(buf, sizeof buf, ",\"uniforms\":%d,\"sources\":%d,\"wrong\":", r->uniforms,
             sources_of(r));
    put(t, buf);
    put_string(t, r->wrong);
    put(t, ",\"params\":[");
    for (const cat_param *p = r->params; p->key; p++) {
        put(t, p == r->params ? "{\"key\":" : ",{\"key\":");
        put_string(t, p->key);
        put(t, ",\"kind\":");
        put_string(t, kinds[p->kind]);
        put(t, ",\"def\":");
        put_string(t, p->def);
        put(t, ",\"lo\":");
        put_number(t, p->lo);
        put(t, ",\"hi\":");
        put_number(t, p->hi);
        put(t, p->lo_open ? ",\"lo_open\":true" : ",\"lo_open\":false");
        put(t, p->hi_open ? ",\"hi_open\":true}" : ",\"hi_open\":false}");
    }
    put(t, "]}");
}

EXPORT(lab_catalog) const char *lab_catalog(void)
{
    text t = {catalog_json, 0, sizeof catalog_json};
    catalog_json[0] = '\0';
    put(&t, "{\"rows\":[");
    for (size_t i = 0; i < cat_count(); i++) {
        if (i)
            put(&t, ",");
        put_row(&t, cat_at(i));
    }
    put(&t, "],\"negatives\":[");
    for (size_t i = 0; i < cat_negative_count(); i++) {
        if (i)
            put(&t, ",");
        put_row(&t, cat_negative_at(i));
    }
    put(&t, "]}");
    return catalog_json;
}

/* --- selecting a row ----------------------------------------------------- */

EXPORT(lab_select) int lab_select(void)
{
    input[LAB_INPUT_SIZE - 1] = '\0';
    /* strtok's hidden state is harmless here: the module has one thread
     * and this is the only caller. */
    char *name = strtok(input, "\n");
    const cat_row *r = name ? cat_find(name) : NULL;
    if (!r) {
        snprintf(message, sizeof message, "no sampler '%s' in the catalog", name ? name : "");
        return 0;
    }
    cat_values p;
    cat_defaults(r, &p);
    for (char *a = strtok(NULL, "\n"); a; a = strtok(NULL, "\n"))
        if (!cat_set_param(r, &p, a, message, sizeof message))
            return 0;
    /* Prepared aside first, so that a bad parameter leaves the selection
     * as it was. */
    static cat_state trial;
    if (!cat_prepare(r, &p, &trial, message, sizeof message))
        return 0;
    if (!cat_prepare(r, &p, &state, message, sizeof message))
        return 0;
    selected = true;
    message[0] = '\0';
    return 1;
}

EXPORT(lab_sources) int lab_sources(void)
{
    return selected ? sources_of(state.row) : 0;
}

/* --- point sources ------------------------------------------------------- */

/* The uniforms of point k of a source: a generator's next draws, point k
 * of a jittered set made in advance, or Sobol point k (scrambled by the
 * seed). */
typedef struct source {
    int kind, uniforms;
    mc_rng rng;
    uint64_t seed;
    double *jitter; /* LAB_JITTERED: the whole set, uniforms per point */
    uint64_t k;
} source;

static bool source_open(source *src, int kind, uint64_t seed, uint64_t n)
{
    const cat_row *r = state.row;
    *src = (source){kind, r->uniforms, mc_rng_derive(seed, 0u), seed, NULL, 0};
    if (!(sources_of(r) >> kind & 1)) {
        snprintf(message, sizeof message, "%s cannot take that point source (%s)", r->name,
                 r->sample_u ? "it takes more than two uniforms" : "it draws from a generator");
        return false;
    }
    if (kind == LAB_JITTERED) {
        src->jitter = malloc((size_t)n * (size_t)r->uniforms * sizeof(double));
        if (!src->jitter) {
            snprintf(message, sizeof message, "out of memory for %llu jittered points",
                     (unsigned long long)n);
            return false;
        }
        if (r->uniforms == 1)
            mc_jitter_1d(&src->rng, (size_t)n, src->jitter);
        else
            mc_jitter_2d(&src->rng, (size_t)n, src->jitter);
    }
    return true;
}

static void source_close(source *src)
{
    free(src->jitter);
    src->jitter = NULL;
}

/* The next point of the selected row; its uniforms in u (NaN when the row
 * draws from a generator). An independent source draws exactly as
 * cat_sample does. */
static void source_next(source *src, double u[4], double x[3])
{
    u[0] = u[1] = u[2] = u[3] = (double)NAN;
    if (src->kind == LAB_INDEPENDENT && !src->uniforms) {
        cat_sample(&state, &src->rng, x);
        src->k++;
        return;
    }
    for (int d = 0; d < src->uniforms; d++)
        u[d] = src->kind == LAB_INDEPENDENT ? mc_rng_uniform(&src->rng)
               : src->kind == LAB_JITTERED  ? src->jitter[src->k * (uint64_t)src->uniforms + (uint64_t)d]
                                            : mc_sobol_owen((uint32_t)src->k, (unsigned)d, src->seed, 0u);
    x[0] = x[1] = x[2] = 0.0;
    state.row->sample_u(&state, u, x);
    src->k++;
}

/* --- the chi-square run -------------------------------------------------- */

/* The goodness-of-fit experiment with the source's points in place of the
 * row's generator; the density is the row's, through its own spec. */
typedef struct sourced_spec {
    mc_gof_spec row;
    source *src;
} sourced_spec;

static void sourced_sample(mc_rng *rng, void *ctx, double out[2])
{
    (void)rng;
    const sourced_spec *c = ctx;
    double u[4], x[3];
    source_next(c->src, u, x);
    cat_chart_point(&state, x, out);
}

static double sourced_pdf(const double x[2], void *ctx)
{
    const sourced_spec *c = ctx;
    return c->row.pdf(x, c->row.ctx);
}

EXPORT(lab_chi2) int lab_chi2(uint32_t seed_hi, uint32_t seed_lo, double n_real, double alpha,
                              int source_kind)
{
    if (!selected || !(n_real >= 1.0 && n_real <= 1e8) || !(alpha > 0.0 && alpha < 1.0)) {
        snprintf(message, sizeof message, "no row selected, or n outside 1 .. 1e8, or alpha outside (0, 1)");
        return 0;
    }
    uint64_t n = (uint64_t)n_real, seed = seed_of(seed_hi, seed_lo);
    /* BEGIN SNIPPET lab_chi2 */
    mc_gof_spec spec = cat_gof_spec_for(&state, n);
    int cells = mc_gof_cell_count(&spec);
    free(observed);
    free(expected);
    observed = calloc((size_t)cells, sizeof *observed);
    expected = calloc((size_t)cells, sizeof *expected);
    source src;
    if (!observed || !expected || !source_open(&src, source_kind, seed, n)) {
        if (!observed || !expected)
            snprintf(message, sizeof message, "out of memory for %d cells", cells);
        return 0;
    }
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_gof_result r;
    if (source_kind == LAB_INDEPENDENT) {
        r = mc_gof_test(&spec, n, &rng, alpha, observed, expected);
    } else {
        sourced_spec ctx = {spec, &src};
        mc_gof_spec sourced = spec;
        sourced.sample = sourced_sample, sourced.pdf = sourced_pdf, sourced.ctx = &ctx;
        r = mc_gof_test(&sourced, n, &rng, alpha, observed, expected);
    }
    /* END SNIPPET lab_chi2 */
    source_close(&src);
    if (r.r.dof < 1) {
        snprintf(message, sizeof message,
                 "%llu samples are too few for a chi-square test of '%s' (no degrees of freedom)",
                 (unsigned long long)n, state.row->name);
        return 0;
    }
    double out[LAB_RESULT_COUNT] = {
        r.r.stat, r.r.dof, r.r.pvalue, r.reject, r.outside, (double)r.r.cells_pooled,
        r.r.obs_total, r.r.exp_total, spec.dims, spec.lo[0], spec.hi[0], spec.lo[1], spec.hi[1],
        spec.cells[0], spec.dims == 2 ? spec.cells[1] : 1, r.r.obs_in_zero_cells, 0.0};
    memcpy(result, out, sizeof result);
    /* The format of `warp chi2`'s second line. */
    snprintf(line, sizeof line, "%.6f %d %.6g %s", r.r.stat, r.r.dof, r.r.pvalue,
             r.reject ? "fail" : "pass");
    return 1;
}

EXPORT(lab_result) double *lab_result(void)
{
    return result;
}

EXPORT(lab_observed) double *lab_observed(void)
{
    return observed;
}

EXPORT(lab_expected) double *lab_expected(void)
{
    return expected;
}

EXPORT(lab_line) const char *lab_line(void)
{
    return line;
}

/* --- points for the pictures --------------------------------------------- */

EXPORT(lab_points) double *lab_points(uint32_t seed_hi, uint32_t seed_lo, int n, int source_kind)
{
    source src;
    if (!selected || n < 1 || n > LAB_MAX_POINTS ||
        !source_open(&src, source_kind, seed_of(seed_hi, seed_lo), (uint64_t)n))
        return NULL;
    for (int k = 0; k < n; k++) {
        double *p = points + (size_t)k * LAB_POINT_STRIDE, u[4], x[3];
        source_next(&src, u, x);
        p[0] = u[0], p[1] = u[1];
        p[2] = x[0], p[3] = x[1], p[4] = x[2];
        cat_chart_point(&state, x, p + 5);
    }
    source_close(&src);
    return points;
}

/* --- the running estimate ------------------------------------------------ */

#define LAB_MAX_RECORDS 80
static double records[LAB_MAX_RECORDS * 3];
static char estimate_line[160];

/* The library's loop (mc_integrate_sampler) tells `seen` every weight in
 * drawing order; a second accumulator fed the same weights in the same
 * order holds, at every count, the estimate the loop would return if it
 * stopped there. */
typedef struct running {
    mc_welford acc;
    uint64_t next;  /* the count of the next record */
    double ratio;   /* of consecutive record counts */
    int count;
} running;

static void record_seen(const void *x, double weight, void *ctx)
{
    (void)x;
    running *r = ctx;
    mc_welford_add(&r->acc, weight);
    if (r->acc.n < r->next || r->count == LAB_MAX_RECORDS)
        return;
    mc_estimate e = mc_welford_estimate(&r->acc);
    double *row = records + 3 * r->count++;
    row[0] = (double)e.n, row[1] = e.value, row[2] = e.std_error;
    while ((double)r->next <= (double)r->acc.n)
        r->next = (uint64_t)ceil((double)r->next * r->ratio);
}

/* Hit-or-miss pi: a uniform point of the unit square (density 1), weight
 * 4 inside the quarter disc. */
static double square_draw(mc_rng *rng, void *ctx, void *x)
{
    (void)ctx;
    double *p = x;
    p[0] = mc_rng_uniform(rng);
    p[1] = mc_rng_uniform(rng);
    return 1.0;
}

static double quarter_disc(const void *x, void *ctx)
{
    (void)ctx;
    const double *p = x;
    return p[0] * p[0] + p[1] * p[1] < 1.0 ? 4.0 : 0.0;
}

/* cos^3 theta over the hemisphere from the selected row's directions
 * (examples/cos_cubed.c's integral). */
static double row_draw(mc_rng *rng, void *ctx, void *x)
{
    (void)ctx;
    double *d = x;
    cat_sample(&state, rng, d);
    return cat_pdf(&state, d);
}

static double cos_cubed(const void *x, void *ctx)
{
    (void)ctx;
    const double *d = x;
    return d[2] > 0.0 ? d[2] * d[2] * d[2] : 0.0;
}

EXPORT(lab_estimate) int lab_estimate(int kind, uint32_t seed_hi, uint32_t seed_lo, double n_real)
{
    if (!(n_real >= 2.0 && n_real <= 1e8) || (kind != 0 && kind != 1)) {
        snprintf(message, sizeof message, "n outside 2 .. 1e8, or no such estimator");
        return 0;
    }
    if (kind == 1 && (!selected || state.row->point != CAT_DIRECTION)) {
        snprintf(message, sizeof message, "the integral over directions needs a direction row");
        return 0;
    }
    uint64_t n = (uint64_t)n_real;
    running r = {mc_welford_init(), 2, pow(n_real / 2.0, 1.0 / (LAB_MAX_RECORDS - 2)), 0};
    if (r.ratio <= 1.0)
        r.ratio = 2.0;
    mc_is_sampler s = kind == 0 ? (mc_is_sampler){square_draw, quarter_disc, record_seen, &r}
                                : (mc_is_sampler){row_draw, cos_cubed, record_seen, &r};
    mc_rng rng = mc_rng_derive(seed_of(seed_hi, seed_lo), 0u);
    double x[3];
    mc_estimate e = mc_integrate_sampler(s, x, &rng, n);
    /* The last count is recorded whatever the spacing, from the loop's own
     * result. */
    if (r.count == 0 || records[3 * (r.count - 1)] != (double)e.n) {
        int k = r.count < LAB_MAX_RECORDS ? r.count++ : r.count - 1;
        records[3 * k] = (double)e.n, records[3 * k + 1] = e.value, records[3 * k + 2] = e.std_error;
    }
    double exact = kind == 0 ? MC_PI : MC_PI_2;
    snprintf(estimate_line, sizeof estimate_line, "%.6f %.6f %.6f %.2f", e.value, e.std_error,
             exact, mc_z_score(e.value, exact, e.std_error));
    return r.count;
}

EXPORT(lab_estimate_table) double *lab_estimate_table(void)
{
    return records;
}

EXPORT(lab_estimate_line) const char *lab_estimate_line(void)
{
    return estimate_line;
}
