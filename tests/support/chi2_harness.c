/* tests/support/chi2_harness.c - the suite's names, levels and failure
 * dumps around mc/gof.h, which does the histogram, the per-cell quadrature
 * and the Pearson test. */
#include "tests/support/chi2_harness.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "mc/gof.h"
#include "tests/support/mc_test.h"

double chi2_suite_alpha(void)
{
    return mc_sidak_alpha(CHI2_SUITE_ALPHA, CHI2_SUITE_TESTS);
}

/* The experiment as mc/gof sees it, or false when the resolution has no
 * cells. */
static bool gof_spec(const chi2_spec *s, mc_gof_spec *g)
{
    *g = s->gof;
    return g->cells[0] >= 1 && (g->dims != 2 || g->cells[1] >= 1);
}

/* A table of one double per cell, or NULL. */
static double *cell_table(const mc_gof_spec *g)
{
    return calloc((size_t)mc_gof_cell_count(g), sizeof(double));
}

/* BEGIN SNIPPET harness_normalization */
double chi2_integrate_pdf(const chi2_spec *spec)
{
    mc_gof_spec g;
    double *prob = gof_spec(spec, &g) ? cell_table(&g) : NULL;
    if (!prob)
        return (double)NAN;
    (void)mc_gof_cell_probs(&g, prob); /* a failed workspace leaves NaN cells */
    double sum = 0.0;
    for (int c = 0; c < mc_gof_cell_count(&g); c++)
        sum += prob[c];
    free(prob);
    return sum;
}
/* END SNIPPET harness_normalization */

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
static void write_csv(const char *name, const mc_gof_spec *g, const double *obs,
                      const double *expct)
{
    char dir[1024], file[1300], base[200];
    const char *b = mc_test_build_dir();
    snprintf(dir, sizeof dir, "%s/test-results", b);
    make_dir(b);
    make_dir(dir);
    snprintf(dir, sizeof dir, "%s/test-results/chi2", b);
    safe_name(name ? name : "unnamed", base, sizeof base);
    snprintf(file, sizeof file, "%s/%s.csv", dir, base);
    FILE *f = make_dir(dir) == 0 ? fopen(file, "w") : NULL;
    if (!f) {
        fprintf(stderr, "chi2 %s: cannot write %s\n", base, file);
        return;
    }
    int ny = g->dims == 2 ? g->cells[1] : 1;
    fprintf(f, "i,j,x0,x1,y0,y1,observed,expected\n");
    for (int c = 0; c < mc_gof_cell_count(g); c++) {
        double box[4];
        mc_gof_cell_box(g, c, box);
        fprintf(f, "%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", c / ny, c % ny, box[0], box[1],
                box[2], box[3], obs[c], expct[c]);
    }
    fclose(f);
    fprintf(stderr, "chi2 %s: observed/expected table written to %s\n", base, file);
}

chi2_outcome chi2_run(const chi2_spec *spec, uint64_t n, uint64_t seed, double alpha)
{
    chi2_outcome o;
    memset(&o, 0, sizeof o);
    o.alpha = alpha;
    mc_gof_spec g;
    bool valid = gof_spec(spec, &g);
    double *obs = valid ? cell_table(&g) : NULL, *expct = valid ? cell_table(&g) : NULL;
    if (!obs || !expct) {
        free(obs);
        free(expct);
        o.reject = true;
        o.r.pvalue = 0.0;
        return o;
    }
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_gof_result r = mc_gof_test(&g, n, &rng, alpha, obs, expct);
    o.r = r.r;
    o.reject = r.reject;
    o.outside = r.outside;
    if (o.reject)
        write_csv(spec->name, &g, obs, expct);
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
