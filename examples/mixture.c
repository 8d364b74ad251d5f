/* examples/mixture.c - this book's #ch-mixture, after Shirley, "Ray
 * Tracing: The Rest of Your Life" (v1.123), chapter 8 "Mixture Densities":
 * half cosine, half
 * light. A pdf_mixture picks the cosine pdf or the light's pdf with
 * probability 1/2 each and evaluates 0.5 cos/pi + 0.5 p_light for EVERY
 * direction, because either could have produced it. Two integrands at the
 * origin (normal +z) under the parallelogram light of light_pdf (L = 4):
 *
 *   light-*  the irradiance from the light, integral of L cos theta over
 *            it: cosine, light and mixture sampling give the same value;
 *            the mixture's variance is far below the cosine's, though
 *            above the light's (its density is at least half of either
 *            component's, so its mean square weight is at most twice
 *            that of the better one);
 *   sky-*    the radiance reflected by a white Lambertian surface under
 *            that light and a uniform sky of radiance 0.5, integral of
 *            (cos theta / pi) L_in: the light pdf alone cannot be used
 *            (it never samples the sky: biased), cosine sampling can but
 *            pays for the small bright light, and the mixture has the
 *            lowest variance of all.
 *
 * --method NAME runs one row alone (same stream, same estimate), so that
 * the efficiency figure of `make plots` can time each density by itself.
 *
 * Build and run:  make all && build/bin/mixture
 *                 build/bin/mixture --samples 1e7 --csv
 *                 build/bin/mixture --method sky-mixture --csv
 */
#include "examples/common/cli.h"
#include "mc/constants.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"

static const char *const extra_cols[] = {"variance"};

/* The rows in output order, then "all"; row i draws from stream i. */
static const char *const methods[] = {"light-cosine", "light-light", "light-mixture", "sky-cosine",
                                      "sky-mixture",  "all",         NULL};

typedef struct scene {
    pdf light;       /* toward the parallelogram: its value > 0 iff d hits it */
    double radiance; /* of the light */
    double sky;      /* radiance of the sky, 0 for the light-only integrand */
} scene;

/* BEGIN SNIPPET mixture_integrand */
/* The integrand: cos theta times the incoming radiance (over pi, the white
 * Lambertian BRDF, when there is a sky). */
static double integrand(vec3 d, void *ctx)
{
    const scene *s = ctx;
    if (d.z <= 0.0)
        return 0.0;
    double in = (pdf_value(&s->light, d) > 0.0 ? s->radiance : 0.0) + s->sky;
    return s->sky > 0.0 ? d.z * MC_INV_PI * in : d.z * in;
}
/* END SNIPPET mixture_integrand */

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    bool csv = false;
    const char *method = "all";
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "directions per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        APP_OPT_CSV(&csv),
        {"--method", APP_CHOICE, &method, "integrand-density pair (default all)", methods, 0, 0},
    };
    app_parse("mixture", "mixture [--method NAME] [--samples N] [--seed S] [--csv]", argc, argv,
              opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("mixture", n, 7.4e-07);

    vec3 origin = vec3_make(0.0, 0.0, 0.0), up = vec3_make(0.0, 0.0, 1.0);
    vec3 corner = vec3_make(-0.3, 0.2, 1.0), u = vec3_make(0.8, 0.0, 0.2),
         v = vec3_make(0.0, 0.6, 0.1);
    const vec3 corners[4] = {corner, vec3_add(corner, u), vec3_add(vec3_add(corner, u), v),
                             vec3_add(corner, v)};
    double irradiance = pdf_polygon_irradiance(origin, up, corners, 4, 4.0);

    /* BEGIN SNIPPET mixture_build */
    pdf cosine = pdf_cosine(up), light = pdf_toward_quad(origin, corner, u, v);
    const pdf *parts[2] = {&cosine, &light};
    const double weights[2] = {0.5, 0.5};
    pdf mix = pdf_mixture(parts, weights, 2);

    scene scenes[2] = {{light, 4.0, 0.0}, {light, 4.0, 0.5}};
    /* Exact: E for the light alone; sky + E / pi reflected with the sky
     * (the sky alone gives sky * pi / pi). */
    double exact[2] = {irradiance, 0.5 + irradiance * MC_INV_PI};
    /* Row i is methods[i]. */
    const struct {
        int scene;
        const pdf *p;
    } rows[5] = {{0, &cosine}, {0, &light}, {0, &mix}, {1, &cosine}, {1, &mix}};
    /* END SNIPPET mixture_build */

    app_table t = {stdout, csv, extra_cols, 1, "mixture"};
    app_table_begin(&t);
    for (int i = 0; i < 5; i++) {
        if (!app_selected(method, methods[i]))
            continue;
        mc_rng rng = mc_rng_derive(seed, (uint64_t)i);
        mc_estimate e =
            pdf_integrate((pdf_fn){integrand, &scenes[rows[i].scene]}, rows[i].p, &rng, n);
        app_table_row(&t, methods[i], e, exact[rows[i].scene], &e.variance);
    }
    return 0;
}
