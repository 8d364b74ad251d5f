/* examples/projected_area.c - the mean projected area of a convex body
 * over all directions is a quarter of its surface area (Cauchy's formula;
 * the Cranberry Lair blog post on SAH BVH construction uses it to turn
 * surface areas into hit probabilities). For
 * a 2.385 x 1 x 0.5 box (area 8.155, mean shadow 2.03875) and a sphere of
 * radius 1 (area 4 pi, shadow always pi), two estimates each:
 *
 *   exact       uniform directions, the exact shadow area in each: for the
 *               box half the sum of |d . n| A over its faces (a point of
 *               the shadow is covered by one front and one back face);
 *               for the sphere always pi r^2 (zero variance);
 *   rays        uniform directions, one line per direction through a
 *               uniform point of a square window perpendicular to it that
 *               covers the body; window area times hit (0 or 1).
 *
 * Build and run:  make all && build/bin/projected_area
 *                 build/bin/projected_area --body box --samples 1e7 --csv
 */
#include "examples/common/cli.h"
#include "pdf/experiments.h"

static const char *const bodies[] = {"box", "sphere", "all", NULL};
static const char *const extra_cols[] = {"area"};

/* BEGIN SNIPPET projected_area_run */
static void run(const app_table *t, const char *name, pdf_body b, bool by_rays, uint64_t seed,
                uint64_t index, uint64_t n)
{
    mc_rng rng = mc_rng_derive(seed, index);
    mc_estimate e = pdf_mean_projected_area(b, by_rays, &rng, n);
    double area = pdf_body_area(b);
    app_table_row(t, name, e, area / 4.0, &area);
}
/* END SNIPPET projected_area_run */

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *body = "all";
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "directions per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--body", APP_CHOICE, &body, "convex body (default all)", bodies, 0, 0},
        APP_OPT_CSV(&csv),
    };
    app_parse("projected_area",
              "projected_area [--body box|sphere|all] [--samples N] [--seed S] [--csv]", argc, argv,
              opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("projected_area", n, 2.5e-07);

    const pdf_body box = {true, vec3_make(1.1925, 0.5, 0.25), 0.0};
    const pdf_body sphere = {false, vec3_make(0.0, 0.0, 0.0), 1.0};
    app_table t = {stdout, csv, extra_cols, 1, "projected_area"};
    app_table_begin(&t);
    if (app_selected(body, "box")) {
        run(&t, "box-exact", box, false, seed, 0u, n);
        run(&t, "box-rays", box, true, seed, 1u, n);
    }
    if (app_selected(body, "sphere")) {
        run(&t, "sphere-exact", sphere, false, seed, 2u, n);
        run(&t, "sphere-rays", sphere, true, seed, 3u, n);
    }
    return 0;
}
