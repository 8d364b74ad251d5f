/* examples/plotdata_chi2.c - the data of the chi-square figures of `make plots`.
 *
 * Shows how the chi-square test of a sampler works and that it is both
 * calibrated and powerful (chapter 5, "Generating Random Directions"):
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
 * Build and run:  make all && build/bin/plotdata_chi2 pvalues --seeds 200
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "mc/chi2.h"
#include "mc/quad.h"
#include "mc/rng.h"
#include "samplers/hemisphere.h"
#include "samplers/spherical.h"

#define PROG "plotdata_chi2"
#define MAX_CELLS 4096

typedef struct pair {
    const char *name;
    vec3 (*sample)(double u1, double u2);
    double (*pdf)(vec3 w); /* the density the pair claims, per unit solid angle */
} pair;

static const pair pairs[2] = {
    {"correct", smp_cosine_hemisphere_sample, smp_cosine_hemisphere_pdf},
    {"wrong", smp_theta_phi_sample, smp_uniform_hemisphere_pdf},
};

typedef struct grid {
    int nc, np;            /* cells along cos theta in [0, 1] and phi in [0, 2 pi) */
    double obs[MAX_CELLS]; /* row-major: cell (i, j) at i * np + j */
    double exp[MAX_CELLS];
} grid;

/* d omega = d cos_theta d phi: the density per unit solid angle is already
 * the density of the (cos theta, phi) rectangle. */
static double param_pdf(double cos_theta, double phi, void *params)
{
    const pair *p = params;
    return p->pdf(smp_spherical_direction(cos_theta, phi));
}

static void expected_counts(mc_quad *q, const pair *p, double n, grid *g)
{
    mc_fn2 fn = {param_pdf, (void *)p};
    for (int i = 0; i < g->nc; i++)
        for (int j = 0; j < g->np; j++) {
            double mass = 0.0;
            /* A status other than 0 only means GSL's target was not met;
             * the value is still far below the counts' Poisson noise. */
            (void)mc_quad_2d(q, fn, (double)i / g->nc, (double)(i + 1) / g->nc, MC_2PI * j / g->np,
                             MC_2PI * (j + 1) / g->np, &mass, NULL);
            g->exp[i * g->np + j] = n * mass;
        }
}

static void observed_counts(const pair *p, uint64_t n, uint64_t seed, grid *g)
{
    memset(g->obs, 0, sizeof g->obs);
    mc_rng rng = mc_rng_derive(seed, 0);
    for (uint64_t k = 0; k < n; k++) {
        double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
        vec3 w = p->sample(u1, u2);
        int i = (int)(w.z * g->nc), j = (int)(smp_spherical_phi(w) / MC_2PI * g->np);
        /* cos theta = 1 exactly belongs to the top row. */
        i = i < 0 ? 0 : (i >= g->nc ? g->nc - 1 : i);
        j = j >= g->np ? g->np - 1 : j;
        g->obs[i * g->np + j] += 1.0;
    }
}

static void print_cells(const grid *g)
{
    printf("i,j,cos_lo,cos_hi,phi_lo,phi_hi,observed,expected,diff_sd\n");
    for (int i = 0; i < g->nc; i++)
        for (int j = 0; j < g->np; j++) {
            double o = g->obs[i * g->np + j], e = g->exp[i * g->np + j];
            printf("%d,%d,%.6f,%.6f,%.6f,%.6f,%.0f,%.6f,%.6f\n", i, j, (double)i / g->nc,
                   (double)(i + 1) / g->nc, MC_2PI * j / g->np, MC_2PI * (j + 1) / g->np, o, e,
                   e > 0.0 ? (o - e) / sqrt(e) : 0.0);
        }
}

int main(int argc, char **argv)
{
    uint64_t n = 100000, seed = 1;
    int seeds = 200, nc = 16, np = 32;
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

    static grid g;
    g.nc = nc, g.np = np;
    mc_quad *q = mc_quad_create(1000);
    if (!q)
        app_fail(PROG, "out of memory");
    if (strcmp(cmd[0], "cells") == 0) {
        expected_counts(q, &pairs[0], (double)n, &g);
        observed_counts(&pairs[0], n, seed, &g);
        print_cells(&g);
    } else {
        printf("case,seed,n,chi2,dof,p\n");
        for (int c = 0; c < 2; c++) {
            expected_counts(q, &pairs[c], (double)n, &g);
            for (int s = 0; s < seeds; s++) {
                observed_counts(&pairs[c], n, seed + (uint64_t)s, &g);
                mc_chi2_result r = mc_chi2_pearson(g.obs, g.exp, (size_t)(nc * np), 5.0);
                printf("%s,%llu,%llu,%.6f,%d,%.6e\n", pairs[c].name,
                       (unsigned long long)(seed + (uint64_t)s), (unsigned long long)n, r.stat, r.dof,
                       r.pvalue);
            }
        }
    }
    mc_quad_destroy(q);
    return 0;
}
