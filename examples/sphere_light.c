/* examples/sphere_light.c - this book's #ch-lights (the sphere light of
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 10) and
 * the closing result of the lecture slides "Solving the Rendering
 * Equation": a
 * Lambertian sphere light of flux Phi and radius r lights a point at
 * distance d exactly like a point light of intensity Phi / (4 pi):
 * E = Phi cos theta / (4 pi d^2), as long as the sphere is wholly above the
 * point's horizon. Its radiance is L = Phi / (4 pi^2 r^2). Two estimates:
 *
 *   area   uniform points on the sphere's whole surface (density
 *          1 / (4 pi r^2) per unit area); the far half faces away and
 *          counts 0, so half the samples are wasted;
 *   cone   uniform directions in the cone the sphere subtends
 *          (pdf_toward_sphere, the book's random_to_sphere): every
 *          direction hits, each weighs L cos theta / p.
 *
 * The point is the origin with normal +z; the sphere's centre lies at
 * distance d at angle theta from the normal, in the x-z plane.
 *
 * Build and run:  make all && build/bin/sphere_light
 *                 build/bin/sphere_light --radius 0.9 --distance 1.5 --theta 20 --csv
 */
#include <math.h>

#include "examples/common/cli.h"
#include "mc/constants.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"

static const char *const methods[] = {"area", "cone", "all", NULL};
static const char *const extra_cols[] = {"variance"};

/* L max(0, cos theta) for a direction from the origin (normal +z). */
static double radiance_cos(vec3 d, void *ctx)
{
    const double *radiance = ctx;
    return d.z > 0.0 ? *radiance * d.z : 0.0;
}

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *method = "all";
    bool csv = false;
    double flux = 10.0, radius = 0.5, dist = 3.0, theta_deg = 30.0;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "samples per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "sampling strategy (default all)", methods, 0, 0},
        /* Squared radiances enter the variance: beyond 1e+-100 they would
         * underflow to 0 or overflow, and the table would print a standard
         * error of 0 or inf. */
        {"--flux", APP_DOUBLE, &flux, "the light's flux Phi, 1e-100 to 1e100 (default 10)", NULL,
         1e-100, 1e100},
        {"--radius", APP_DOUBLE, &radius, "the light's radius r (default 0.5)", NULL, 1e-6, 1e6},
        {"--distance", APP_DOUBLE, &dist, "distance d to its centre (default 3)", NULL, 1e-6, 1e6},
        {"--theta", APP_DOUBLE, &theta_deg, "angle from the normal, degrees (default 30)", NULL,
         0.0, 90.0},
        APP_OPT_CSV(&csv),
    };
    app_parse("sphere_light",
              "sphere_light [--method area|cone|all] [--flux F] [--radius R] [--distance D] "
              "[--theta DEG] [--samples N] [--csv]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("sphere_light", n, 1.3e-07);
    double theta = theta_deg * MC_PI / 180.0;
    /* The formula holds only for a sphere wholly above the horizon. */
    if (!(radius < dist) || theta + asin(radius / dist) >= MC_PI_2)
        app_fail("sphere_light",
                 "the sphere must lie wholly above the horizon: theta + asin(r / d) < 90 degrees");

    /* BEGIN SNIPPET sphere_light_main */
    vec3 origin = vec3_make(0.0, 0.0, 0.0), up = vec3_make(0.0, 0.0, 1.0);
    vec3 center = vec3_make(dist * sin(theta), 0.0, dist * cos(theta));
    double radiance = flux / (MC_4PI * MC_PI * radius * radius);
    double exact = pdf_sphere_light_irradiance(flux, dist, cos(theta));

    app_table t = {stdout, csv, extra_cols, 1, "sphere_light"};
    app_table_begin(&t);
    if (app_selected(method, "area")) {
        mc_rng rng = mc_rng_derive(seed, 0u);
        mc_estimate e = pdf_sphere_light_by_area(origin, up, center, radius, radiance, &rng, n);
        app_table_row(&t, "area", e, exact, &e.variance);
    }
    if (app_selected(method, "cone")) {
        mc_rng rng = mc_rng_derive(seed, 1u);
        pdf cone = pdf_toward_sphere(origin, center, radius);
        mc_estimate e = pdf_integrate((pdf_fn){radiance_cos, &radiance}, &cone, &rng, n);
        app_table_row(&t, "cone", e, exact, &e.variance);
    }
    /* END SNIPPET sphere_light_main */
    return 0;
}
