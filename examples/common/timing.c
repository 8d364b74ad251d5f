/* examples/common/timing.c - POSIX clocks and the median for bench/. */
/* clock_gettime and its clocks are POSIX, not ISO C17. */
#define _POSIX_C_SOURCE 200809L

#include "examples/common/timing.h"

#include <stdlib.h>
#include <time.h>

static double seconds_of(clockid_t clock)
{
    struct timespec t;
    clock_gettime(clock, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double app_thread_seconds(void)
{
    return seconds_of(CLOCK_THREAD_CPUTIME_ID);
}

double app_wall_seconds(void)
{
    return seconds_of(CLOCK_MONOTONIC);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double app_median(double *x, size_t n)
{
    qsort(x, n, sizeof x[0], cmp_double);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

double app_bench_ns(double (*loop)(void *ctx, uint64_t n, mc_rng *rng), void *ctx, uint64_t n,
                    uint64_t seed, int reps)
{
    double t[APP_BENCH_MAX_REPS];
    reps = reps < 1 ? 1 : (reps > APP_BENCH_MAX_REPS ? APP_BENCH_MAX_REPS : reps);
    for (int k = 0; k < reps; k++) {
        mc_rng rng = mc_rng_derive(seed, (uint64_t)k);
        double t0 = app_thread_seconds();
        volatile double sink = loop(ctx, n, &rng);
        (void)sink;
        t[k] = (app_thread_seconds() - t0) * 1e9 / (double)n;
    }
    return app_median(t, (size_t)reps);
}
