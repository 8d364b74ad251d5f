/* bench/bench_samplers.c - nanoseconds per sample of every warp in
 * samplers/ and every pdf object of pdf/ (chapters 5-7 and 10: the
 * directions and points a renderer draws at every bounce).
 *
 * The samplers are the test cases of the catalog (catalog/catalog.h), in
 * its order. Each sampler draws N samples from uniforms of one PCG32 stream (the
 * uniforms' cost included, as in a renderer; the row "rng 2 uniforms" is
 * that cost alone) and the median thread CPU time of five repetitions is
 * reported, so one slow run (page faults, a busy core) does not move the
 * table.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_samplers
 *                [--samples N] [--seed S])
 */
#include <stdio.h>

#include "catalog/catalog.h"

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "mc/rng.h"

/* The two uniforms every warp consumes, alone. */
static double rng_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    (void)ctx;
    double acc = 0.0;
    for (uint64_t i = 0; i < n; i++)
        acc += mc_rng_uniform(rng) + mc_rng_uniform(rng);
    return acc;
}

/* Draws n samples of a catalog case (ctx: its state) from rng through the
 * catalog's dispatch (the cost of one indirect call is in the figure);
 * returns their coordinate sum. */
static double draw_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    const cat_state *s = ctx;
    double acc = 0.0, x[3];
    for (uint64_t i = 0; i < n; i++) {
        cat_sample(s, rng, x);
        acc += x[0] + x[1] + x[2];
    }
    return acc;
}

static void print_row(const char *name, double ns)
{
    printf("%-26s %.2f\n", name, ns);
}

int main(int argc, char **argv)
{
    uint64_t n = 500000u, seed = 2385u;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "samples per repetition (default 5e5)", NULL, 0, 0},
        {"--seed", APP_SEED, &seed, "seed of the uniform streams (default 2385)", NULL, 0, 0},
    };
    app_parse("bench_samplers",
              "bench_samplers [--samples N] [--seed S]\n"
              "  nanoseconds per sample of every sampler (median of 5 runs)",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    printf("%-26s %s\n", "sampler", "ns_per_sample");
    print_row("rng 2 uniforms", app_bench_ns(rng_loop, NULL, n, seed, 5));
    /* Every test case of the catalog's rows. */
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        for (const cat_case *c = r->cases; c->name; c++) {
            static cat_state s; /* large (tables' storage) */
            char err[256];
            if (!cat_prepare_case(r, c, &s, err, sizeof err))
                app_fail("bench_samplers", "%s", err);
            print_row(c->name, app_bench_ns(draw_loop, &s, n, seed, 5));
        }
    }
    return 0;
}
