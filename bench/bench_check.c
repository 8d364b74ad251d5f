/* bench/bench_check.c - samples per second through the doors of the public
 * check (check/check.h): the cosine-weighted hemisphere at 10^6 samples
 * through the C API (the sampler a function call away), and through
 * `mcbox-check --exec` with the sampler in another process: `warp serve
 * cosine` (C) and docs/protocol/cosine.py (Python, when python3 is there).
 * Each figure is the median wall time of three runs of the whole check
 * (sampling, histogram, quadrature of the expected counts, statistic), so
 * it is what a user's CI pays.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_check)
 * The programs are found in $MC_BUILD/bin (default build/bin); run from the
 * repository's top directory, where docs/protocol/cosine.py lives.
 */
#define _POSIX_C_SOURCE 200809L /* access */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check/check.h"
#include "examples/common/timing.h"
#include "samplers/hemisphere.h"

#define N 1000000u
#define REPS 3

static void cosine_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    vec3 w = smp_cosine_hemisphere_sample_malley(u[0], u[1]);
    out->x[0] = w.x, out->x[1] = w.y, out->x[2] = w.z;
}

static double cosine_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return smp_cosine_hemisphere_pdf(vec3_make(x[0], x[1], x[2]));
}

static void row(const char *door, double seconds, const char *verdict)
{
    printf("%-44s %8.3f s %10.3g samples/s  %s\n", door, seconds, (double)N / seconds, verdict);
}

/* The median wall time of REPS runs of a shell command; its last exit
 * status in *status. */
static double time_command(const char *cmd, int *status)
{
    double t[REPS];
    for (int k = 0; k < REPS; k++) {
        double t0 = app_wall_seconds();
        int rc = system(cmd);
        t[k] = app_wall_seconds() - t0;
        *status = rc;
    }
    return app_median(t, REPS);
}

int main(int argc, char **argv)
{
    /* No options: the table is fixed. Anything else is a mistake to hear of. */
    if (argc > 1) {
        if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
            puts("usage: bench_check   (samples per second through the check's doors; no options)");
            return 0;
        }
        if (strcmp(argv[1], "--version") == 0) {
            puts("bench_check (mcbox) 0.1.0");
            return 0;
        }
        fprintf(stderr, "bench_check: unknown argument '%s' (it takes none; see --help)\n", argv[1]);
        return 2;
    }
    mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
    s.sample = cosine_sample, s.pdf = cosine_pdf;
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = N;
    double t[REPS];
    mcbox_check_result r;
    for (int k = 0; k < REPS; k++) {
        double t0 = app_wall_seconds();
        if (mcbox_check_run(&s, &o, &r, NULL) != 0) {
            fprintf(stderr, "bench_check: %s\n", r.message);
            return 1;
        }
        t[k] = app_wall_seconds() - t0;
    }
    printf("cosine hemisphere, %u samples, the whole check (median of %d runs)\n", N, REPS);
    row("C API (mcbox_check_run)", app_median(t, REPS), r.pass ? "pass" : "FAIL");

    const char *b = getenv("MC_BUILD") ? getenv("MC_BUILD") : "build";
    char cmd[1024];
    int status = 0;
    snprintf(cmd, sizeof cmd,
             "%s/bin/mcbox-check --exec '%s/bin/warp serve cosine' --domain hemisphere "
             "--n %u >/dev/null",
             b, b, N);
    double sec = time_command(cmd, &status);
    row("--exec 'warp serve cosine' (C, a pipe)", sec, status == 0 ? "pass" : "FAIL");
    int failed = status != 0;
    if (system("command -v python3 >/dev/null 2>&1") == 0 &&
        access("docs/protocol/cosine.py", R_OK) == 0) {
        snprintf(cmd, sizeof cmd,
                 "%s/bin/mcbox-check --exec 'python3 docs/protocol/cosine.py' --domain hemisphere "
                 "--n %u >/dev/null",
                 b, N);
        sec = time_command(cmd, &status);
        row("--exec 'python3 docs/protocol/cosine.py'", sec, status == 0 ? "pass" : "FAIL");
        failed |= status != 0;
    } else {
        printf("%-44s (no python3 or not run from the top directory)\n",
               "--exec 'python3 docs/protocol/cosine.py'");
    }
    return failed || !r.pass;
}
