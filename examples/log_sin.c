/* examples/log_sin.c - this book's #ch-integration: an integral with no
 * elementary antiderivative: the integral of ln(sin x) over [0, pi], which
 * is -pi ln 2 (Euler), although the integrand is -infinity at both ends.
 *
 *   plain       x uniform on [0, pi]: weight pi ln(sin x), variance per
 *               sample pi^4 / 12 = 8.12 (finite: ln^2 is integrable);
 *   importance  x with density p(x) = -ln(2 d / pi) / pi, d = min(x, pi - x)
 *               (samplers/warp1d.h, smp_log_ends): variance 0.324.
 *
 * Why that density: near 0, ln(sin x) ~ ln x, and p has exactly this
 * logarithmic spike at both ends, so the weight ln(sin x) / p(x) tends to
 * -pi at the ends and to 0 at pi/2. It is bounded: Jordan's inequality
 * sin x >= 2x/pi on [0, pi/2] gives |ln sin x| <= -ln(2x/pi) = pi p(x),
 * so |weight| <= pi and the variance is finite; as the weight is nearly
 * constant where the integrand is large, it is 25 times smaller than
 * uniform sampling's. A density
 * that vanishes at the ends (sin(x)/2, say) would do the opposite: the
 * weight ln(sin x) / sin x blows up and the variance is infinite.
 *
 * Build and run:  make all && build/bin/log_sin --method all
 */
#include <math.h>

#include "examples/common/cli.h"
#include "mc/constants.h"
#include "mc/integrate.h"
#include "samplers/warp1d.h"

static const char *const methods[] = {"plain", "importance", "all", NULL};
static const char *const extra_cols[] = {"variance"};

static double log_sin(double x, void *params)
{
    (void)params;
    return log(sin(x));
}

int main(int argc, char **argv)
{
    uint64_t n = 1000000u, seed = 1u;
    const char *method = "all";
    bool csv = false;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "samples per method (default 1e6)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"--method", APP_CHOICE, &method, "estimator (default all)", methods, 0, 0},
        APP_OPT_CSV(&csv),
    };
    app_parse("log_sin", "log_sin [--method plain|importance|all] [--samples N] [--seed S] [--csv]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    app_announce_samples("log_sin", n, 4.2e-07);

    const double exact = -MC_PI * MC_LN2;
    const mc_fn1 f = {log_sin, NULL};
    app_table t = {stdout, csv, extra_cols, 1, "log_sin"};
    app_table_begin(&t);
    /* BEGIN SNIPPET log_sin_estimators */
    if (app_selected(method, "plain")) {
        mc_rng rng = mc_rng_derive(seed, 0u);
        mc_estimate e = mc_integrate_uniform(f, 0.0, MC_PI, &rng, n, NULL);
        app_table_row(&t, "plain", e, exact, &e.variance);
    }
    if (app_selected(method, "importance")) {
        mc_rng rng = mc_rng_derive(seed, 1u);
        mc_warp1 w = {smp_log_ends_sample, smp_log_ends_pdf};
        mc_estimate e = mc_integrate_is(f, w, &rng, n, NULL);
        app_table_row(&t, "importance", e, exact, &e.variance);
    }
    /* END SNIPPET log_sin_estimators */
    return 0;
}
