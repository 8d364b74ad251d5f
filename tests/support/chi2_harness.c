/* tests/support/chi2_harness.c - histogram, per-cell quadrature, Pearson
 * test and the CSV dump of a failed experiment. */
#include "tests/support/chi2_harness.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "mc/quad.h"
#include "tests/support/mc_test.h"

/* A quadrature workspace of 1000 subintervals per level is GSL's usual
 * ample size; the pdfs of the suite converge in far fewer. */
#define QUAD_LIMIT 1000

double chi2_suite_alpha(void)
{
    return mc_sidak_alpha(CHI2_SUITE_ALPHA, CHI2_SUITE_TESTS);
}

/* The spec's pdf as the integrands mc_quad wants. */
static double pdf_1d(double x, void *params)
{
    const chi2_spec *s = params;
    double p[2] = {x, 0.0};
    return s->pdf(p, s->ctx);
}

static double pdf_2d(double x, double y, void *params)
{
    const chi2_spec *s = params;
    double p[2] = {x, y};
    return s->pdf(p, s->ctx);
}

/* The integral of the pdf over [x0, x1] (x [y0, y1] in 2D). */
static double integrate_box(mc_quad *q, const chi2_spec *s, double x0, double x1, double y0,
                            double y1)
{
    double v = 0.0;
    /* A non-zero status means GSL could not certify 1e-11; its best value is
     * still far more accurate than the chi-square test can resolve. */
    if (s->dims == 1)
        (void)mc_quad_1d(q, (mc_fn1){pdf_1d, (void *)s}, x0, x1, &v, NULL);
    else
        (void)mc_quad_2d(q, (mc_fn2){pdf_2d, (void *)s}, x0, x1, y0, y1, &v, NULL);
    return v;
}

/* The cell index of coordinate x in [lo, hi] split into n cells, or -1 when
 * x lies outside by more than round-off (NaN is outside). */
static int cell_of(double x, double lo, double hi, int n)
{
    double w = hi - lo, tol = CHI2_EDGE_TOL * w;
    if (!(x >= lo - tol && x <= hi + tol))
        return -1;
    double t = (x - lo) / w * n;
    int i = (int)floor(t);
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

/* The probability of every cell: the pdf integrated over it. Cells are
 * independent, so threads share the work, each with its own quadrature
 * workspace. */
static void cell_probs(const chi2_spec *s, int nx, int ny, double *prob)
{
    double wx = (s->hi[0] - s->lo[0]) / nx;
    double wy = s->dims == 2 ? (s->hi[1] - s->lo[1]) / ny : 0.0;
#pragma omp parallel
    {
        mc_quad *q = mc_quad_create(QUAD_LIMIT);
#pragma omp for schedule(dynamic, 16)
        for (int c = 0; c < nx * ny; c++) {
            int i = c / ny, j = c % ny;
            /* Cell edges from the index, not by accumulation, so that the
             * last edge is exactly hi. */
            double x0 = s->lo[0] + i * wx, x1 = i == nx - 1 ? s->hi[0] : x0 + wx;
            double y0 = 0.0, y1 = 0.0;
            if (s->dims == 2) {
                y0 = s->lo[1] + j * wy;
                y1 = j == ny - 1 ? s->hi[1] : y0 + wy;
            }
            prob[c] = q ? integrate_box(q, s, x0, x1, y0, y1) : (double)NAN;
        }
        mc_quad_destroy(q);
    }
}

static int cells_x(const chi2_spec *s)
{
    return s->cells[0];
}

static int cells_y(const chi2_spec *s)
{
    return s->dims == 2 ? s->cells[1] : 1;
}

double chi2_integrate_pdf(const chi2_spec *spec)
{
    int nx = cells_x(spec), ny = cells_y(spec);
    double *prob = nx > 0 && ny > 0 ? malloc((size_t)nx * (size_t)ny * sizeof *prob) : NULL;
    if (!prob)
        return (double)NAN;
    cell_probs(spec, nx, ny, prob);
    double sum = 0.0;
    for (int c = 0; c < nx * ny; c++)
        sum += prob[c];
    free(prob);
    return sum;
}

/* Keeps file names to [A-Za-z0-9._-]. */
static void safe_name(const char *name, char *out, size_t size)
{
    size_t k = 0;
    for (; name[k] && k + 1 < size; k++) {
        char c = name[k];
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '.' || c == '-' || c == '_';
        out[k] = ok ? c : '_';
    }
    out[k] = '\0';
}

static int make_dir(const char *path)
{
    return mkdir(path, 0777) == 0 || errno == EEXIST ? 0 : -1;
}

/* Writes cell bounds, observed and expected counts for gnuplot; failures to
 * write are reported on stderr but do not change the verdict. */
static void write_csv(const chi2_spec *s, int nx, int ny, const double *obs, const double *expct)
{
    char dir[1024], file[1300], base[200];
    const char *b = mc_test_build_dir();
    snprintf(dir, sizeof dir, "%s/test-results", b);
    make_dir(b);
    make_dir(dir);
    snprintf(dir, sizeof dir, "%s/test-results/chi2", b);
    safe_name(s->name ? s->name : "unnamed", base, sizeof base);
    snprintf(file, sizeof file, "%s/%s.csv", dir, base);
    FILE *f = make_dir(dir) == 0 ? fopen(file, "w") : NULL;
    if (!f) {
        fprintf(stderr, "chi2 %s: cannot write %s\n", base, file);
        return;
    }
    double wx = (s->hi[0] - s->lo[0]) / nx, wy = s->dims == 2 ? (s->hi[1] - s->lo[1]) / ny : 0.0;
    fprintf(f, "i,j,x0,x1,y0,y1,observed,expected\n");
    for (int c = 0; c < nx * ny; c++) {
        int i = c / ny, j = c % ny;
        double x0 = s->lo[0] + i * wx, y0 = s->dims == 2 ? s->lo[1] + j * wy : 0.0;
        fprintf(f, "%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, j, x0, x0 + wx, y0, y0 + wy,
                obs[c], expct[c]);
    }
    fclose(f);
    fprintf(stderr, "chi2 %s: observed/expected table written to %s\n", base, file);
}

chi2_outcome chi2_run(const chi2_spec *spec, uint64_t n, uint64_t seed, double alpha)
{
    chi2_outcome o;
    memset(&o, 0, sizeof o);
    o.alpha = alpha;
    int nx = cells_x(spec), ny = cells_y(spec);
    double *obs = calloc((size_t)nx * (size_t)ny, sizeof *obs);
    double *expct = calloc((size_t)nx * (size_t)ny, sizeof *expct);
    if (!obs || !expct || nx < 1 || ny < 1) {
        free(obs);
        free(expct);
        o.reject = true;
        o.r.pvalue = 0.0;
        return o;
    }
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint64_t k = 0; k < n; k++) {
        double x[2] = {0.0, 0.0};
        spec->sample(&rng, spec->ctx, x);
        int i = cell_of(x[0], spec->lo[0], spec->hi[0], nx);
        int j = spec->dims == 2 ? cell_of(x[1], spec->lo[1], spec->hi[1], ny) : 0;
        if (i < 0 || j < 0)
            o.outside += 1.0;
        else
            obs[i * ny + j] += 1.0;
    }
    cell_probs(spec, nx, ny, expct);
    for (int c = 0; c < nx * ny; c++) {
        /* The quadrature's own zero (its absolute tolerance is 1e-12) is
         * an exactly-zero cell for the test. */
        expct[c] = expct[c] < CHI2_ZERO_CELL_PROB ? 0.0 : expct[c] * (double)n;
    }
    o.r = mc_chi2_pearson(obs, expct, (size_t)nx * (size_t)ny, 5.0);
    bool nan_cell = false;
    for (int c = 0; c < nx * ny; c++)
        nan_cell = nan_cell || !isfinite(expct[c]);
    o.reject = nan_cell || !(o.r.pvalue >= alpha) || o.outside > 0.0 ||
               o.r.obs_in_zero_cells > CHI2_ZERO_CELL_FRAC * (double)n;
    if (o.reject)
        write_csv(spec, nx, ny, obs, expct);
    free(obs);
    free(expct);
    return o;
}

void chi2_print(const chi2_spec *spec, const chi2_outcome *o)
{
    printf("chi2 %-28s stat %12.2f dof %5d p %.4g alpha %.3g pooled %zu outside %.0f zero-cells "
           "%.0f %s\n",
           spec->name ? spec->name : "unnamed", o->r.stat, o->r.dof, o->r.pvalue, o->alpha,
           o->r.cells_pooled, o->outside, o->r.obs_in_zero_cells, o->reject ? "REJECT" : "ok");
}
