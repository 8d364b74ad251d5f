/* examples/plotdata_chi2.c - the data of the chi-square figures of `make plots`.
 *
 * Shows how the chi-square test of a sampler works and that it is both
 * calibrated and powerful (this book's #ch-tests):
 *   cells    one test of the cosine-weighted hemisphere sampler (the book's
 *            mapping) in the (cos theta, phi) rectangle, where a density per
 *            unit solid angle is a plain density: per cell the observed count,
 *            the expected count (the pdf integrated over the cell by adaptive
 *            quadrature, times N) and their difference in standard deviations
 *            (obs - exp) / sqrt(exp).
 *   pvalues  the p-value of the same test over many seeds, for that correct
 *            pair and for a wrong one: directions uniform in (theta, phi)
 *            claimed to be uniform in solid angle (the missing sin theta).
 *            Correct: p-values uniform on [0, 1]. Wrong: piled up at 0.
 * The samplers and densities are rows of the catalog (catalog/catalog.h),
 * histogrammed in their chart; histogram, quadrature and pooling are
 * mc/gof.h's, the same as in `warp chi2` and in the test suite's harness.
 * Build and run:  make all && build/bin/plotdata_chi2 pvalues --seeds 200
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "catalog/catalog.h"
#include "examples/common/cli.h"
#include "mc/gof.h"

#define PROG "plotdata_chi2"

/* BEGIN SNIPPET chi2_pairs */
/* A sampler of the catalog and the density it claims: its own, or, for
 * the wrong pair, another row's (per unit solid angle). */
typedef struct pair {
    const char *name;
    const char *sampler, *density; /* rows of the catalog */
} pair;

static const pair pairs[2] = {
    {"correct", "cosine", "cosine"},
    {"wrong", "theta-phi", "hemisphere"},
};
/* END SNIPPET chi2_pairs */

/* The pair's experiment in its rows' (cos theta, phi) chart on
 * [0, 1] x [0, 2 pi], where a density per unit solid angle is a plain
 * density (d omega = d cos_theta d phi), cut into nc x np cells. *row and
 * *s hold the sampler's row with the claimed density and its state. */
static mc_gof_spec pair_spec(const pair *p, int nc, int np, cat_row *row, cat_state *s)
{
    *row = *cat_find(p->sampler);
    row->pdf = cat_find(p->density)->pdf;
    cat_values v;
    cat_defaults(row, &v);
    char err[256];
    if (!cat_prepare(row, &v, s, err, sizeof err))
        app_fail(PROG, "%s", err);
    return cat_gof_spec(s, (const int[2]){nc, np});
}

/* The observed counts of n samples from the stream of `seed`; returns the
 * samples outside the rectangle. */
static double observe(const mc_gof_spec *s, uint64_t n, uint64_t seed, double *obs)
{
    memset(obs, 0, (size_t)mc_gof_cell_count(s) * sizeof *obs);
    mc_rng rng = mc_rng_derive(seed, 0);
    return mc_gof_histogram(s, &rng, n, obs);
}

static void print_cells(const mc_gof_spec *s, const double *obs, const double *expct)
{
    printf("i,j,cos_lo,cos_hi,phi_lo,phi_hi,observed,expected,diff_sd\n");
    for (int c = 0; c < mc_gof_cell_count(s); c++) {
        double b[4], o = obs[c], e = expct[c];
        mc_gof_cell_box(s, c, b);
        printf("%d,%d,%.6f,%.6f,%.6f,%.6f,%.0f,%.6f,%.6f\n", c / s->cells[1], c % s->cells[1],
               b[0], b[1], b[2], b[3], o, e, e > 0.0 ? (o - e) / sqrt(e) : 0.0);
    }
}

int main(int argc, char **argv)
{
    uint64_t n = 100000, seed = 1;
    int seeds = 0, nc = 16, np = 32; /* seeds 0: not given */
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "samples per test (default 1e5)", NULL, 0, 0},
        {"--seed", APP_SEED, &seed, "seed of the test (cells) or of the first test (pvalues)", NULL, 0, 0},
        {"--seeds", APP_INT, &seeds, "pvalues: number of tests, seeds S, S+1, ... (default 200)", NULL, 1, 1e6},
        {"--cos-cells", APP_INT, &nc, "cells along cos theta in [0, 1] (default 16)", NULL, 1, 64},
        {"--phi-cells", APP_INT, &np, "cells along phi in [0, 2 pi) (default 32)", NULL, 1, 64},
    };
    const char *cmd[1] = {NULL};
    int npos = app_parse(PROG, PROG " cells|pvalues [options]", argc, argv, opts, 5, cmd, 1);
    if (npos != 1 || (strcmp(cmd[0], "cells") != 0 && strcmp(cmd[0], "pvalues") != 0))
        app_fail(PROG, "expected the command 'cells' or 'pvalues' (see --help)");
    if (seeds && strcmp(cmd[0], "cells") == 0)
        app_fail(PROG, "--seeds is an option of pvalues, not of cells");
    seeds = seeds ? seeds : 200;

    static double obs[64 * 64], expct[64 * 64];
    static cat_row rows[2];
    static cat_state states[2]; /* large; the specs point into them */
    if (strcmp(cmd[0], "cells") == 0) {
        mc_gof_spec s = pair_spec(&pairs[0], nc, np, &rows[0], &states[0]);
        if (mc_gof_expected(&s, n, expct) != 0)
            app_fail(PROG, "out of memory");
        (void)observe(&s, n, seed, obs);
        print_cells(&s, obs, expct);
    } else {
        /* The expected counts do not depend on the seed: once per pair.
         * Both pairs are checked before the header, so that a test that
         * cannot decide (every cell pooled into one: no degrees of freedom,
         * chi2 0 and p 1, a perfect pass) is refused, as `warp chi2` does,
         * before any output. */
        static double expected[2][64 * 64];
        for (int c = 0; c < 2; c++) {
            mc_gof_spec s = pair_spec(&pairs[c], nc, np, &rows[c], &states[c]);
            if (mc_gof_expected(&s, n, expected[c]) != 0)
                app_fail(PROG, "out of memory");
            mc_chi2_result r0 =
                mc_chi2_pearson(expected[c], expected[c], (size_t)(nc * np), MC_GOF_MIN_EXPECTED);
            if (r0.dof < 1)
                app_fail(PROG, "--samples %llu is too few for a chi-square test of %s (no degrees of freedom)",
                         (unsigned long long)n, pairs[c].name);
        }
        printf("case,seed,n,chi2,dof,p\n");
        for (int c = 0; c < 2; c++) {
            mc_gof_spec s = pair_spec(&pairs[c], nc, np, &rows[c], &states[c]);
            for (int k = 0; k < seeds; k++) {
                uint64_t sd = seed + (uint64_t)k;
                if (observe(&s, n, sd, obs) > 0.0)
                    app_fail(PROG, "%s: a sample outside the rectangle (seed %llu)",
                             pairs[c].name, (unsigned long long)sd);
                mc_chi2_result r =
                    mc_chi2_pearson(obs, expected[c], (size_t)(nc * np), MC_GOF_MIN_EXPECTED);
                printf("%s,%llu,%llu,%.6f,%d,%.6e\n", pairs[c].name, (unsigned long long)sd,
                       (unsigned long long)n, r.stat, r.dof, r.pvalue);
            }
        }
    }
    return 0;
}
