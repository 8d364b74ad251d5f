/* bench/bench_mc.c - throughput of the random number generator and of the
 * pi estimators (chapter 1, "A Simple Monte Carlo Program").
 *
 * Prints one table: uniform doubles per second from one PCG32 stream, the
 * book-style scalar pi loop (one stream, one point at a time), and the
 * blocked SIMD/OpenMP kernel of mc/pi.h on one and two threads, with the
 * speed-up over the scalar loop and over the book's own program (26 M
 * samples/s measured on the reference machine). It also checks that the 1-
 * and 2-thread pi estimates are bit-identical and exits 1 if they are not.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_mc)
 */
#include <stdbool.h>
#include <stdio.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "mc/pi.h"
#include "mc/rng.h"

/* Samples/s of the book's program (drand48, one point per iteration),
 * measured once on the machine the project targets. */
#define BOOK_RATE 26e6

/* Keeps the optimizer from dropping work whose result is otherwise unused. */
static volatile double sink;

static double rate_uniform(uint64_t n)
{
    mc_rng rng = mc_rng_derive(1u, 0u);
    double t0 = app_wall_seconds(), acc = 0.0;
    for (uint64_t i = 0; i < n; i++)
        acc += mc_rng_uniform(&rng);
    double dt = app_wall_seconds() - t0;
    sink = acc;
    return (double)n / dt;
}

static double rate_scalar_pi(uint64_t n)
{
    mc_rng rng = mc_rng_derive(1u, 0u);
    double t0 = app_wall_seconds();
    uint64_t hits = mc_pi_hits_scalar(&rng, n);
    double dt = app_wall_seconds() - t0;
    sink = (double)hits;
    return (double)n / dt;
}

typedef mc_estimate (*pi_fn)(uint64_t seed, uint64_t n, int threads, uint64_t *hits);

/* The best of three runs (the first may pay for page faults and thread
 * start-up). */
static double rate_pi(pi_fn f, uint64_t n, int threads, mc_estimate *e)
{
    double best = 0.0;
    for (int k = 0; k < 3; k++) {
        double t0 = app_wall_seconds();
        *e = f(2385u, n, threads, NULL);
        double r = (double)n / (app_wall_seconds() - t0);
        if (r > best)
            best = r;
    }
    return best;
}

static void row(const char *what, int threads, double rate, double scalar)
{
    printf("%-30s %7d %12.1f %10.1fx %10.1fx\n", what, threads, rate / 1e6, rate / scalar,
           rate / BOOK_RATE);
}

int main(int argc, char **argv)
{
    app_parse("bench_mc",
              "bench_mc\n  throughput of the RNG and the pi kernels, 1 and 2 threads (see make bench)",
              argc, argv, NULL, 0, NULL, 0);
    uint64_t n = UINT64_C(1) << 30;
    double uni = rate_uniform(UINT64_C(1) << 28);
    double scalar = rate_scalar_pi(UINT64_C(1) << 27);
    mc_estimate e1, e2, s1, s2;
    double p1 = rate_pi(mc_pi_plain, n, 1, &e1), p2 = rate_pi(mc_pi_plain, n, 2, &e2);
    double q1 = rate_pi(mc_pi_stratified, n / 4, 1, &s1), q2 = rate_pi(mc_pi_stratified, n / 4, 2, &s2);

    printf("%-30s %7s %12s %11s %11s\n", "benchmark", "threads", "M/s", "vs scalar", "vs book");
    printf("%-30s %7d %12.1f %11s %11s\n", "rng uniform doubles", 1, uni / 1e6, "-", "-");
    row("pi scalar loop (book style)", 1, scalar, scalar);
    row("pi plain, SIMD lanes", 1, p1, scalar);
    row("pi plain, SIMD lanes", 2, p2, scalar);
    row("pi stratified, SIMD lanes", 1, q1, scalar);
    row("pi stratified, SIMD lanes", 2, q2, scalar);

    /* Identical means the estimate and its error bar, bit for bit. */
    bool same_plain = e1.value == e2.value && e1.std_error == e2.std_error;
    bool same_strat = s1.value == s2.value && s1.std_error == s2.std_error;
    printf("pi plain      n=%llu: %.10f +- %.2e (1 and 2 threads %s)\n", (unsigned long long)n,
           e1.value, e1.std_error, same_plain ? "identical" : "DIFFER");
    printf("pi stratified n=%llu: %.10f +- %.2e (1 and 2 threads %s)\n",
           (unsigned long long)(n / 4), s1.value, s1.std_error, same_strat ? "identical" : "DIFFER");
    return same_plain && same_strat ? 0 : 1;
}
