/* examples/sphere_plot.c - this book's #ch-sphere (after Shirley, "Ray
 * Tracing: The Rest of Your Life" (v1.123), chapter 5 "Generating Random
 * Directions"):
 * uniformly distributed points on the unit sphere, one `x y z` per line,
 * the input of the scatter plot (plots/) that shows them without clumps at
 * the poles.
 *
 * Three methods, equal in distribution (tests/test_samplers_* check it):
 *   inverse    z = 1 - 2 u2, phi = 2 pi u1 (Archimedes: z is uniform)
 *   gaussian   three independent normals, normalized (rotation invariance)
 *   rejection  points of the cube kept inside the unit ball, normalized
 *
 * Build and run:  make all && build/bin/sphere_plot --samples 2000 > sphere.dat
 *                 build/bin/sphere_plot --method rejection --seed 7
 */
#include <stdio.h>

#include "examples/common/cli.h"
#include "catalog/catalog.h"

static const char *const methods[] = {"inverse", "gaussian", "rejection", NULL};

int main(int argc, char **argv)
{
    uint64_t n = 1000u, seed = 1u;
    const char *method = "inverse";
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "number of points (default 1000)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "sampler (default inverse)", methods, 0, 0},
    };
    app_parse("sphere_plot",
              "sphere_plot [--method inverse|gaussian|rejection] [--samples N] [--seed S]", argc,
              argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    if (n > 100000000u)
        app_fail("sphere_plot", "--samples: at most 1e8 points (a plot needs far fewer)");

    /* BEGIN SNIPPET sphere_plot_loop */
    /* The three methods are the catalog's rows sphere-<method>: one
     * sampler table for this program, warp and the tests, so the scatter
     * plot shows what they test. */
    char name[32], err[200];
    snprintf(name, sizeof name, "sphere-%s", method);
    const cat_row *r = cat_find(name);
    static cat_state state;
    cat_values params;
    cat_defaults(r, &params);
    if (!cat_prepare(r, &params, &state, err, sizeof err))
        app_fail("sphere_plot", "%s", err);
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint64_t i = 0; i < n; i++) {
        double d[3];
        cat_sample(&state, &rng, d);
        printf("%.17g %.17g %.17g\n", d[0], d[1], d[2]);
    }
    /* END SNIPPET sphere_plot_loop */
    return 0;
}
