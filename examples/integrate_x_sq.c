/* examples/integrate_x_sq.c - this book's #ch-integration, after Shirley,
 * "Ray Tracing: The Rest of Your Life" (v1.123), chapter 2 "One Dimensional
 * MC Integration":
 * the integral of x^2 over [0, 2] (exactly 8/3) by importance sampling with
 * three densities:
 *
 *   uniform    p = 1/2       x = 2u
 *   linear     p = x/2       x = sqrt(4u)
 *   quadratic  p = 3x^2/8    x = 2 cbrt(u)   (proportional to the integrand)
 *
 * What it shows: the closer p follows the integrand, the smaller the
 * variance per sample (the `variance` column: 256/45, 8/9 and 0 exactly); the
 * quadratic density, proportional to x^2, has zero variance: every sample
 * is 8/3. Its spread is then only round-off (~1e-32), so a standard error
 * below 1e-12 of the estimate is reported as 0.
 *
 * Build and run:  make all && build/bin/integrate_x_sq --pdf all
 */
#include "examples/common/cli.h"
#include "mc/integrate.h"
#include "samplers/warp1d.h"

static const char *const pdfs[] = {"uniform", "linear", "quadratic", "all", NULL};
static const char *const extra_cols[] = {"variance"};

static double x_squared(double x, void *params)
{
    (void)params;
    return x * x;
}

/* BEGIN SNIPPET x_sq_run */
/* The uniform density of [0, 2] as a warp. */
static double uniform02_sample(double u) { return 2.0 * u; }
static double uniform02_pdf(double x) { return x >= 0.0 && x <= 2.0 ? 0.5 : 0.0; }

static void run(const app_table *t, const char *name, mc_warp1 w, uint64_t seed, uint64_t n)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_estimate e = mc_integrate_is((mc_fn1){x_squared, NULL}, w, &rng, n, NULL);
    /* Relative spread below 1e-12 is round-off of f/p (about 1e-16 per
     * sample), not sampling noise. */
    if (e.std_error < 1e-12 * e.value)
        e.std_error = 0.0;
    app_table_row(t, name, e, 8.0 / 3.0, &e.variance);
}
/* END SNIPPET x_sq_run */

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *pdf = "all";
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "samples per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--pdf", APP_CHOICE, &pdf, "sampling density (default all)", pdfs, 0, 0},
        APP_OPT_CSV(&csv),
    };
    app_parse("integrate_x_sq", "integrate_x_sq [--pdf uniform|linear|quadratic|all] [--samples N]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("integrate_x_sq", n, 1.4e-07);

    app_table t = {stdout, csv, extra_cols, 1, "integrate_x_sq"};
    app_table_begin(&t);
    if (app_selected(pdf, "uniform"))
        run(&t, "uniform", (mc_warp1){uniform02_sample, uniform02_pdf}, seed, n);
    if (app_selected(pdf, "linear"))
        run(&t, "linear", (mc_warp1){smp_linear_sample, smp_linear_pdf}, seed, n);
    if (app_selected(pdf, "quadratic"))
        run(&t, "quadratic", (mc_warp1){smp_quadratic_sample, smp_quadratic_pdf}, seed, n);
    return 0;
}
