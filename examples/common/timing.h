/* examples/common/timing.h - the clocks and the robust summary the
 * benchmarks of bench/ share.
 *
 * A benchmark times a loop with one of two clocks: the CPU time of the
 * calling thread, which other jobs on a shared machine (make -j, parallel
 * tests) do not inflate, for single-threaded loops; and the monotonic wall
 * clock for loops that run on several OpenMP threads, whose CPU time would
 * add up over the threads. Repetitions are summarized by their median, so
 * one slow run (page faults, a busy core) does not move a table. Serves
 * the throughput tables of `make bench` (chapters 1, 5-8 and 10). Program
 * code, not a library: POSIX clocks are fine here.
 */
#ifndef APP_TIMING_H
#define APP_TIMING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mc/rng.h"

/* CPU seconds used so far by the calling thread. */
double app_thread_seconds(void);

/* Seconds on the monotonic wall clock from an arbitrary origin. */
double app_wall_seconds(void);

/* The median of x[0..n) (n >= 1; the mean of the middle two for even n).
 * Sorts x in place. */
double app_median(double *x, size_t n);

/* The most repetitions app_bench_ns takes. */
#define APP_BENCH_MAX_REPS 64

/* The median over `reps` (1 .. APP_BENCH_MAX_REPS) runs of loop(ctx, n,
 * rng), in nanoseconds of the calling thread's CPU time per iteration.
 * Run k gets rng = mc_rng_derive(seed, k), seeded before its clock starts.
 * loop returns a value computed from all its work, which is stored to a
 * volatile so that the optimizer cannot drop the work. */
double app_bench_ns(double (*loop)(void *ctx, uint64_t n, mc_rng *rng), void *ctx, uint64_t n,
                    uint64_t seed, int reps);

/* Whether the environment asks for the benchmarks' quick runs:
 * MC_BENCH_QUICK set to anything but "0" (each benchmark's --quick says
 * what it shortens). */
bool app_bench_quick(void);

/* The median wall time in seconds of `runs` (1 .. APP_BENCH_MAX_REPS)
 * runs of the program at path, without arguments, its standard output
 * thrown away: the way make bench times another project's program (the
 * book's) beside mcbox's. When a run cannot be started or does not exit
 * with status 0, prints one line on stderr, "PROG: WHAT PATH: why", and
 * returns NAN. */
double app_time_program(const char *prog, const char *what, const char *path, int runs);

#endif /* APP_TIMING_H */
