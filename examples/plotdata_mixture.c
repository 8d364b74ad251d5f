/* examples/plotdata_mixture.c - the experiment of examples/mixture.c, one
 * method at a time, so that `make plots` can time each sampling density
 * alone for the efficiency figure (chapter 8, "Mixture Densities").
 *
 * Same scene and estimators as mixture.c: the parallelogram light (radiance
 * 4) above the origin (normal +z); `light-*` integrates L cos theta (the
 * irradiance), `sky-*` adds a uniform sky of radiance 0.5 and integrates
 * (cos theta / pi) L_in; the directions come from the cosine pdf, the
 * light's pdf or their half-and-half mixture. mixture.c runs all five rows
 * in one process and has no option to pick one; when it gains one, the plots
 * can time it directly and this program can go.
 *
 * Build and run:  make all && build/bin/plotdata_mixture --method sky-mixture --csv
 */
#include <string.h>

#include "examples/common/cli.h"
#include "mc/constants.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"

#define PROG "plotdata_mixture"

static const char *const methods[] = {"light-cosine", "light-light", "light-mixture", "sky-cosine",
                                      "sky-mixture",  "all",         NULL};
static const char *const extra_cols[] = {"variance"};

typedef struct scene {
    pdf light;       /* toward the parallelogram: its value > 0 iff d hits it */
    double radiance; /* of the light */
    double sky;      /* radiance of the sky, 0 for the light-only integrand */
} scene;

/* cos theta times the incoming radiance, over pi (the white Lambertian
 * BRDF) when there is a sky: irradiance without, reflected radiance with. */
static double integrand(vec3 d, void *ctx)
{
    const scene *s = ctx;
    if (d.z <= 0.0)
        return 0.0;
    double in = (pdf_value(&s->light, d) > 0.0 ? s->radiance : 0.0) + s->sky;
    return s->sky > 0.0 ? d.z * MC_INV_PI * in : d.z * in;
}

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    bool csv = false;
    const char *method = "all";
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "directions per method (default 1e6)", NULL, 0, 0},
        {"--seed", APP_SEED, &seed, "random seed (default 1)", NULL, 0, 0},
        {"--method", APP_CHOICE, &method, "integrand-density pair (default all)", methods, 0, 0},
        {"--csv", APP_FLAG, &csv, "print CSV instead of a table", NULL, 0, 0},
    };
    app_parse(PROG, PROG " [--method NAME] [--samples N] [--seed S] [--csv]", argc, argv, opts,
              sizeof opts / sizeof opts[0], NULL, 0);

    vec3 origin = vec3_make(0.0, 0.0, 0.0), up = vec3_make(0.0, 0.0, 1.0);
    vec3 corner = vec3_make(-0.3, 0.2, 1.0), u = vec3_make(0.8, 0.0, 0.2), v = vec3_make(0.0, 0.6, 0.1);
    const vec3 corners[4] = {corner, vec3_add(corner, u), vec3_add(vec3_add(corner, u), v),
                             vec3_add(corner, v)};
    double irradiance = pdf_polygon_irradiance(origin, up, corners, 4, 4.0);

    pdf cosine = pdf_cosine(up), light = pdf_toward_quad(origin, corner, u, v);
    const pdf *parts[2] = {&cosine, &light};
    const double weights[2] = {0.5, 0.5};
    pdf mix = pdf_mixture(parts, weights, 2);
    scene scenes[2] = {{light, 4.0, 0.0}, {light, 4.0, 0.5}};
    /* The sky alone reflects sky * pi / pi; the light adds E / pi. */
    double exact[2] = {irradiance, 0.5 + irradiance * MC_INV_PI};
    const pdf *densities[5] = {&cosine, &light, &mix, &cosine, &mix};

    app_table t = {stdout, csv, extra_cols, 1};
    app_table_begin(&t);
    for (int i = 0; i < 5; i++) {
        if (strcmp(method, "all") != 0 && strcmp(method, methods[i]) != 0)
            continue;
        int s = i < 3 ? 0 : 1;
        /* The stream index of row i in mixture.c: the same estimates. */
        mc_rng rng = mc_rng_derive(seed, (uint64_t)i);
        mc_estimate e = pdf_integrate((pdf_fn){integrand, &scenes[s]}, densities[i], &rng, n);
        app_table_row(&t, methods[i], e, exact[s], &e.variance);
    }
    return 0;
}
