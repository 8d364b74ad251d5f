/* examples/light_pdf.c - this book's #ch-lights, after Shirley, "Ray
 * Tracing: The Rest of Your Life" (v1.123), chapter 7 "Sampling Lights
 * Directly": the
 * irradiance at a point from a parallelogram light, E = integral of
 * L cos theta over the directions that hit the light, estimated two ways:
 *
 *   light   directions toward uniform points of the light's area; the
 *           area density 1 / A becomes dist^2 / (|cos_light| A) per unit
 *           solid angle (pdf_toward_quad), so each sample weighs
 *           L cos theta |cos_light| A / dist^2, nearly constant;
 *   cosine  cosine-weighted directions about the normal (density
 *           cos theta / pi): each sample weighs pi L if it hits the light
 *           and 0 if not, a coin flip with a large variance.
 *
 * Both match the exact value from Lambert's polygon formula
 * (pdf_polygon_irradiance; tests/test_chapters3.c checks it by quadrature).
 * The point is the origin with normal +z, the light L = 4 over the
 * parallelogram corner (-0.3, 0.2, 1), edges (0.8, 0, 0.2) and (0, 0.6, 0.1).
 *
 * Build and run:  make all && build/bin/light_pdf
 *                 build/bin/light_pdf --method light --samples 1e7 --csv
 */
#include "examples/common/cli.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"
#include "samplers/planar.h"

static const char *const methods[] = {"light", "cosine", "all", NULL};
static const char *const extra_cols[] = {"variance"};

typedef struct light {
    vec3 corner, u, v, n; /* n: unit normal of the light's plane */
    double radiance;
} light;

/* L cos theta where the ray from the origin along d meets the light, else
 * 0 (the shading point is the origin, its normal +z). */
static double radiance_cos(vec3 d, void *ctx)
{
    const light *l = ctx;
    double along = vec3_dot(l->n, d);
    if (d.z <= 0.0 || along == 0.0)
        return 0.0;
    double r = vec3_dot(l->n, l->corner) / along;
    if (!(r > 0.0))
        return 0.0;
    vec2 st = smp_parallelogram_invert(vec3_scale(d, r), l->corner, l->u, l->v);
    bool hit = st.x >= 0.0 && st.x <= 1.0 && st.y >= 0.0 && st.y <= 1.0;
    return hit ? l->radiance * d.z : 0.0;
}

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *method = "all";
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "directions per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "sampling density (default all)", methods, 0, 0},
        APP_OPT_CSV(&csv),
    };
    app_parse("light_pdf", "light_pdf [--method light|cosine|all] [--samples N] [--seed S] [--csv]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("light_pdf", n, 2.2e-07);

    /* BEGIN SNIPPET light_pdf_main */
    light l = {vec3_make(-0.3, 0.2, 1.0), vec3_make(0.8, 0.0, 0.2), vec3_make(0.0, 0.6, 0.1),
               vec3_make(0.0, 0.0, 0.0), 4.0};
    l.n = vec3_normalize(vec3_cross(l.u, l.v));
    vec3 origin = vec3_make(0.0, 0.0, 0.0), up = vec3_make(0.0, 0.0, 1.0);
    const vec3 corners[4] = {l.corner, vec3_add(l.corner, l.u),
                             vec3_add(vec3_add(l.corner, l.u), l.v), vec3_add(l.corner, l.v)};
    double exact = pdf_polygon_irradiance(origin, up, corners, 4, l.radiance);
    const pdf pdfs[2] = {pdf_toward_quad(origin, l.corner, l.u, l.v), pdf_cosine(up)};

    app_table t = {stdout, csv, extra_cols, 1, "light_pdf"};
    app_table_begin(&t);
    for (int m = 0; m < 2; m++) {
        if (!app_selected(method, methods[m]))
            continue;
        mc_rng rng = mc_rng_derive(seed, (uint64_t)m);
        mc_estimate e = pdf_integrate((pdf_fn){radiance_cos, &l}, &pdfs[m], &rng, n);
        app_table_row(&t, methods[m], e, exact, &e.variance);
    }
    /* END SNIPPET light_pdf_main */
    return 0;
}
