/* examples/sphere_importance.c - this book's #ch-sphere, after Shirley,
 * "Ray Tracing: The Rest of Your Life" (v1.123), the second chapter 2 "MC
 * Integration on the Sphere of Directions": the integral of cos^2 theta over all directions, exactly
 * 4 pi / 3, from uniformly distributed directions (density 1 / (4 pi) per
 * unit solid angle), each weighted by f / p = 4 pi cos^2 theta.
 *
 * What it shows: integrating over directions is integrating over the unit
 * sphere with the solid-angle measure; the uniform density is the simplest
 * choice and already gives a z-score consistent with 0. The three uniform
 * samplers (inverse CDF, normalized Gaussian, rejection from the ball)
 * estimate the same value with the same variance per sample, 64 pi^2 / 45.
 *
 * Build and run:  make all && build/bin/sphere_importance
 *                 build/bin/sphere_importance --samples 1e7 --csv
 */
#include "examples/common/cli.h"
#include "catalog/catalog.h"
#include "mc/constants.h"

static const char *const methods[] = {"inverse", "gaussian", "rejection", "all", NULL};
static const char *const extra_cols[] = {"variance"};

static double cos_squared(vec3 d, void *ctx)
{
    (void)ctx;
    return d.z * d.z;
}

/* The catalog's row of each method (catalog/catalog.h). */
static const char *const rows[] = {"sphere-inverse", "sphere-gaussian", "sphere-rejection"};


int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *method = "all";
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "directions per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "uniform sampler (default all)", methods, 0, 0},
        APP_OPT_CSV(&csv),
    };
    app_parse("sphere_importance",
              "sphere_importance [--method inverse|gaussian|rejection|all] [--samples N] [--seed "
              "S] [--csv]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("sphere_importance", n, 2.1e-07);

    app_table t = {stdout, csv, extra_cols, 1, "sphere_importance"};
    app_table_begin(&t);
    const double exact = MC_4PI / 3.0;
    /* BEGIN SNIPPET sphere_methods */
    for (int m = 0; m < 3; m++) {
        if (!app_selected(method, methods[m]))
            continue;
        cat_state s;
        char err[256];
        if (!cat_prepare_named(rows[m], &s, err, sizeof err))
            app_fail("sphere_importance", "%s", err);
        mc_rng rng = mc_rng_derive(seed, (uint64_t)m);
        mc_estimate e = cat_integrate((pdf_fn){cos_squared, NULL}, &s, &rng, n);
        app_table_row(&t, methods[m], e, exact, &e.variance);
    }
    /* END SNIPPET sphere_methods */
    return 0;
}
