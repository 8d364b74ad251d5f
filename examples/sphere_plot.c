/* examples/sphere_plot.c - chapter 5, "Generating Random Directions":
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
#include <string.h>

#include "examples/common/cli.h"
#include "samplers/sphere.h"

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

    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint64_t i = 0; i < n; i++) {
        vec3 d;
        if (strcmp(method, "inverse") == 0) {
            double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
            d = smp_uniform_sphere_sample(u1, u2);
        } else if (strcmp(method, "gaussian") == 0) {
            double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
            double u3 = mc_rng_uniform(&rng), u4 = mc_rng_uniform(&rng);
            d = smp_uniform_sphere_sample_gaussian(u1, u2, u3, u4);
        } else {
            d = smp_uniform_sphere_sample_rejection(&rng);
        }
        printf("%.17g %.17g %.17g\n", d.x, d.y, d.z);
    }
    return 0;
}
