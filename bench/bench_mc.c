/* bench/bench_mc.c - throughput of the random number generator and of the
 * pi estimators (chapter 1, "A Simple Monte Carlo Program").
 *
 * Prints one table: uniform doubles per second from one PCG32 stream, the
 * book-style scalar pi loop (one stream, one point at a time), and the
 * blocked SIMD/OpenMP kernel of mc/pi.h on one and two threads, with the
 * speed-up over the scalar loop and over the book's own program. It also
 * checks that the 1- and 2-thread pi estimates are bit-identical and exits
 * 1 if they are not.
 *
 * The book's program is not part of mcbox. Its rate is a constant measured
 * once on another machine (26 M points/s), unless --book-pi PATH (or
 * MC_BOOK_PI, which `make bench` sets when `make book-program` has built
 * it) names the book's pi.cc of release v1.123.0 built by
 * tools/book_program.sh with 10000^2 iterations. Then that program is run
 * here three times before anything else, and its points per second (two
 * per iteration: one for the plain estimate, one for the stratified one)
 * over the median time replace the constant: two programs timed on one
 * machine. --quick (or MC_BENCH_QUICK=1) runs every loop 64 times
 * shorter.
 *
 * A second table ("Quasi-Monte Carlo" chapter) gives the point sources of
 * mc/qmc.h in millions of coordinates per second (points per second per
 * dimension) with the ratio to PCG32's uniform doubles: Sobol points by
 * index, with a random digital shift, Owen scrambled (through their
 * functions, which hash the scramble's seed at every call; through the
 * cursor, which hashes it once per point; and through mc_qmc_fill, which
 * fills runs of 1024 samples one dimension at a time), permuted Halton, and
 * the renderer's padded pairs. Each row is the median thread CPU time of
 * five runs over D = 4 dimensions of consecutive indices.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_mc)
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "mc/pi.h"
#include "mc/qmc.h"
#include "mc/rng.h"

/* Points/s of the book's pi program, measured once on the machine the
 * project targeted then; the default of the "vs book" column. */
#define BOOK_RATE 26e6

/* The points the book's pi.cc makes as tools/book_program.sh builds it:
 * sqrt_N = 10000, a plain and a stratified point per iteration. */
#define BOOK_PI_POINTS (2.0 * 10000.0 * 10000.0)

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

/* ---- quasi-Monte Carlo point sources ---- */

/* Dimensions per point in the QMC rows. */
enum { QMC_DIM = 4 };

/* A loop of app_bench_ns over n coordinates of one point source; the run's
 * rng only picks the scramble seed. */
static double q_pcg(void *ctx, uint64_t n, mc_rng *rng)
{
    (void)ctx;
    double acc = 0.0;
    for (uint64_t k = 0; k < n; k++)
        acc += mc_rng_uniform(rng);
    return acc;
}

static double q_method(void *ctx, uint64_t n, mc_rng *rng)
{
    int which = *(const int *)ctx;
    uint64_t seed = mc_rng_u32(rng), points = n / QMC_DIM;
    double acc = 0.0;
    for (uint32_t i = 0; i < points; i++) {
        for (unsigned d = 0; d < QMC_DIM; d++) {
            switch (which) {
            case 0:
                acc += mc_sobol(i, d);
                break;
            case 1:
                acc += mc_sobol_xor(i, d, seed, 3u);
                break;
            case 2:
                acc += mc_sobol_owen(i, d, seed, 3u);
                break;
            default:
                acc += mc_halton_permuted(i, d, seed, 3u);
                break;
            }
        }
    }
    return acc;
}

static double q_cursor(void *ctx, uint64_t n, mc_rng *rng)
{
    mc_qmc_method method = *(const mc_qmc_method *)ctx;
    uint64_t seed = mc_rng_u32(rng), points = n / QMC_DIM;
    double acc = 0.0;
    for (uint64_t i = 0; i < points; i++) {
        mc_qmc_cursor c = mc_qmc_begin(method, seed, 3u, i);
        for (unsigned d = 0; d < QMC_DIM; d++)
            acc += mc_qmc_next(&c);
    }
    return acc;
}

/* Runs of 1024 consecutive samples, one dimension at a time. */
static double q_fill(void *ctx, uint64_t n, mc_rng *rng)
{
    mc_qmc_method method = *(const mc_qmc_method *)ctx;
    uint64_t seed = mc_rng_u32(rng), points = n / QMC_DIM;
    double acc = 0.0, out[1024];
    for (uint64_t i = 0; i < points; i += 1024u) {
        for (unsigned d = 0; d < QMC_DIM; d++) {
            mc_qmc_fill(method, seed, 3u, i, 1024u, d, out);
            for (int k = 0; k < 1024; k++)
                acc += out[k];
        }
    }
    return acc;
}

/* Two pairs of 64 samples per pixel, as a renderer draws them: the
 * pixel's key once per pixel (render/sampler.c), then the requests. */
static double q_padded(void *ctx, uint64_t n, mc_rng *rng)
{
    (void)ctx;
    uint64_t seed = mc_rng_u32(rng), points = n / QMC_DIM, key = 0;
    double acc = 0.0, u[2];
    for (uint64_t i = 0; i < points; i++) {
        if (i % 64u == 0)
            key = mc_sobol_padded_key(mc_qmc_stream_seed(seed, i / 64u));
        for (uint32_t pair = 0; pair < QMC_DIM / 2; pair++) {
            mc_sobol_padded2_keyed(key, 2u * pair, (uint32_t)(i % 64u), 64u, u);
            acc += u[0] + u[1];
        }
    }
    return acc;
}

static void qmc_row(const char *what, double ns, double pcg_ns)
{
    printf("%-36s %12.1f %10.2f %12.2f\n", what, 1e3 / ns, ns, ns / pcg_ns);
}

static void qmc_table(uint64_t n)
{
    const uint64_t seed = 2385u;
    static const int sobol = 0, xor = 1, owen = 2, halton = 3;
    static const mc_qmc_method c_rand = MC_QMC_RANDOM, c_owen = MC_QMC_SOBOL_OWEN,
                               c_halton = MC_QMC_HALTON, c_sobol = MC_QMC_SOBOL,
                               c_xor = MC_QMC_SOBOL_XOR;
    double pcg = app_bench_ns(q_pcg, NULL, n, seed, 5);
    printf("\n%-36s %12s %10s %12s\n", "point source (D = 4)", "M coord/s", "ns/coord",
           "x PCG32 time");
    qmc_row("PCG32 uniform doubles", pcg, pcg);
    qmc_row("Sobol by index", app_bench_ns(q_method, (void *)&sobol, n, seed, 5), pcg);
    qmc_row("Sobol XOR (mc_sobol_xor)", app_bench_ns(q_method, (void *)&xor, n, seed, 5), pcg);
    qmc_row("Sobol Owen (mc_sobol_owen)", app_bench_ns(q_method, (void *)&owen, n, seed, 5), pcg);
    qmc_row("Sobol Owen (cursor)", app_bench_ns(q_cursor, (void *)&c_owen, n, seed, 5), pcg);
    qmc_row("Sobol by index (mc_qmc_fill)", app_bench_ns(q_fill, (void *)&c_sobol, n, seed, 5),
            pcg);
    qmc_row("Sobol XOR (mc_qmc_fill)", app_bench_ns(q_fill, (void *)&c_xor, n, seed, 5), pcg);
    qmc_row("Sobol Owen (mc_qmc_fill)", app_bench_ns(q_fill, (void *)&c_owen, n, seed, 5), pcg);
    qmc_row("PCG32 (cursor, stream per point)", app_bench_ns(q_cursor, (void *)&c_rand, n, seed, 5),
            pcg);
    qmc_row("Halton permuted (mc_halton_permuted)",
            app_bench_ns(q_method, (void *)&halton, n / 16u, seed, 5), pcg);
    qmc_row("Halton permuted (cursor)", app_bench_ns(q_cursor, (void *)&c_halton, n / 16u, seed, 5),
            pcg);
    qmc_row("padded Owen Sobol pairs, 64 spp", app_bench_ns(q_padded, NULL, n, seed, 5), pcg);
}

static void row(const char *what, int threads, double rate, double scalar, double book)
{
    printf("%-30s %7d %12.1f %10.1fx %10.1fx\n", what, threads, rate / 1e6, rate / scalar,
           rate / book);
}

int main(int argc, char **argv)
{
    const char *prog = "bench_mc";
    bool quick = app_bench_quick();
    const char *book_pi = getenv("MC_BOOK_PI");
    const app_opt opts[] = {
        {"--quick", APP_FLAG, &quick, "every loop 64 times shorter (also MC_BENCH_QUICK=1)", NULL, 0,
         0},
        {"--book-pi", APP_STRING, &book_pi,
         "the book's pi.cc built with 10000^2 iterations (make book-program): time it here, the "
         "median of 3 runs, instead of the constant 26 M points/s (default $MC_BOOK_PI)",
         NULL, 0, 0},
    };
    app_parse(prog,
              "bench_mc [--quick] [--book-pi PATH]\n  throughput of the RNG, the pi kernels (1 and "
              "2 threads) and the QMC\n  point sources (see make bench)",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    double book = BOOK_RATE;
    if (book_pi && *book_pi) {
        double t = app_time_program(prog, "the book's pi program", book_pi, 3);
        if (isnan(t))
            return 2; /* a bad --book-pi: bad input */
        book = BOOK_PI_POINTS / t;
        printf("vs book: the book's pi.cc, timed here: %.3f s for %.0f points, %.1f M points/s "
               "(median of 3)\n",
               t, BOOK_PI_POINTS, book / 1e6);
    } else {
        printf("vs book: %.1f M points/s, a constant from another machine (--book-pi times the "
               "book's program here)\n",
               book / 1e6);
    }
    unsigned shift = quick ? 6u : 0u;
    uint64_t n = (UINT64_C(1) << 30) >> shift;
    double uni = rate_uniform((UINT64_C(1) << 28) >> shift);
    double scalar = rate_scalar_pi((UINT64_C(1) << 27) >> shift);
    mc_estimate e1, e2, s1, s2;
    double p1 = rate_pi(mc_pi_plain, n, 1, &e1), p2 = rate_pi(mc_pi_plain, n, 2, &e2);
    double q1 = rate_pi(mc_pi_stratified, n / 4, 1, &s1), q2 = rate_pi(mc_pi_stratified, n / 4, 2, &s2);

    printf("%-30s %7s %12s %11s %11s\n", "benchmark", "threads", "M/s", "vs scalar", "vs book");
    printf("%-30s %7d %12.1f %11s %11s\n", "rng uniform doubles", 1, uni / 1e6, "-", "-");
    row("pi scalar loop (book style)", 1, scalar, scalar, book);
    row("pi plain, SIMD lanes", 1, p1, scalar, book);
    row("pi plain, SIMD lanes", 2, p2, scalar, book);
    row("pi stratified, SIMD lanes", 1, q1, scalar, book);
    row("pi stratified, SIMD lanes", 2, q2, scalar, book);

    /* Identical means the estimate and its error bar, bit for bit. */
    bool same_plain = e1.value == e2.value && e1.std_error == e2.std_error;
    bool same_strat = s1.value == s2.value && s1.std_error == s2.std_error;
    printf("pi plain      n=%llu: %.10f +- %.2e (1 and 2 threads %s)\n", (unsigned long long)n,
           e1.value, e1.std_error, same_plain ? "identical" : "DIFFER");
    printf("pi stratified n=%llu: %.10f +- %.2e (1 and 2 threads %s)\n",
           (unsigned long long)(n / 4), s1.value, s1.std_error, same_strat ? "identical" : "DIFFER");
    qmc_table((UINT64_C(1) << 24) >> shift);
    return same_plain && same_strat ? 0 : 1;
}
