/* examples/common/timing.c - POSIX clocks and the median for bench/. */
/* clock_gettime and its clocks are POSIX, not ISO C17. */
#define _POSIX_C_SOURCE 200809L

#include "examples/common/timing.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

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

bool app_bench_quick(void)
{
    const char *q = getenv("MC_BENCH_QUICK");
    return q && strcmp(q, "0") != 0;
}

/* Wall seconds of one run of path, its standard output thrown away; NAN
 * (after a line on stderr) when it cannot be started or does not exit
 * with status 0. */
static double time_one_run(const char *prog, const char *what, const char *path)
{
    double t0 = app_wall_seconds();
    pid_t pid = fork();
    if (pid == 0) {
        int devnull = open("/dev/null", O_WRONLY);
        if (devnull < 0 || dup2(devnull, STDOUT_FILENO) < 0)
            _exit(126);
        execl(path, path, (char *)NULL);
        _exit(127);
    }
    int status = 0;
    while (pid > 0 && waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            pid = -1;
    double seconds = app_wall_seconds() - t0;
    if (pid < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "%s: %s %s: %s\n", prog, what, path,
                pid < 0                       ? "cannot be run"
                : !WIFEXITED(status)          ? "killed by a signal"
                : WEXITSTATUS(status) == 127 ? "cannot be started"
                                              : "failed");
        return (double)NAN;
    }
    return seconds;
}

double app_time_program(const char *prog, const char *what, const char *path, int runs)
{
    double t[APP_BENCH_MAX_REPS];
    if (runs < 1 || runs > APP_BENCH_MAX_REPS)
        return (double)NAN;
    for (int i = 0; i < runs; i++)
        if (isnan(t[i] = time_one_run(prog, what, path)))
            return (double)NAN;
    return app_median(t, (size_t)runs);
}
