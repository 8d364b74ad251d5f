/* bench/bench_samplers.c - nanoseconds per sample of every warp in
 * samplers/ (chapters 5-7 and 10: the directions and points a renderer
 * draws at every bounce).
 *
 * The samplers are the test cases of the catalog (catalog/catalog.h), in
 * its order, plus the two shapes and the sphere-cone the catalog has no
 * row for. Each sampler draws N samples from uniforms of one PCG32 stream (the
 * uniforms' cost included, as in a renderer; the row "rng 2 uniforms" is
 * that cost alone) and the median thread CPU time of five repetitions is
 * reported, so one slow run (page faults, a busy core) does not move the
 * table.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_samplers
 *                [--samples N] [--seed S])
 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "catalog/catalog.h"

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "mc/rng.h"
#include "samplers/cone.h"
#include "samplers/planar.h"

/* A sampler that is not a row of the catalog behind a common signature. */
typedef struct bench_case {
    const char *name;
    double (*draw)(mc_rng *rng, double param); /* returns a coordinate sum */
    double param;
} bench_case;

static double sum3(vec3 v)
{
    return v.x + v.y + v.z;
}

/* The two uniforms every warp consumes, alone. */
static double d_rng(mc_rng *r, double p)
{
    (void)p;
    return mc_rng_uniform(r) + mc_rng_uniform(r);
}

static const vec3 corner = {0.3, -1.2, 2.385}, edge_u = {1.7, 0.2, -0.4}, edge_v = {-0.3, 0.9, 0.6};
static const vec3 center = {0.5, -1.0, 2.0};

static double d_para(mc_rng *r, double p)
{
    (void)p;
    double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r);
    return sum3(smp_parallelogram_sample(u1, u2, corner, edge_u, edge_v));
}

static double d_ball(mc_rng *r, double p)
{
    (void)p;
    double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r);
    return sum3(smp_sphere_surface_sample(u1, u2, center, 1.7));
}

/* The sphere-cone as a light sampler uses it: 1 - cos theta_max from the
 * distance, then the cap. */
static double d_sphere_cone(mc_rng *r, double p)
{
    double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r);
    double one_minus_cos = smp_sphere_cone_one_minus_cos(p * p, 1.0);
    return sum3(smp_uniform_cap_sample(u1, u2, one_minus_cos));
}

/* Shapes after the flat rows, the sphere-cone last (the table's order). */
static const bench_case first = {"rng 2 uniforms", d_rng, 0.0};
static const bench_case shapes[] = {
    {"parallelogram", d_para, 0.0},
    {"sphere-surface", d_ball, 0.0},
};
static const bench_case last = {"sphere-cone-d2R", d_sphere_cone, 2.0};

static double bench_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    const bench_case *c = ctx;
    double acc = 0.0;
    for (uint64_t i = 0; i < n; i++)
        acc += c->draw(rng, c->param);
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
    print_row(first.name, app_bench_ns(bench_loop, (void *)&first, n, seed, 5));
    /* Every test case of the catalog's sampler rows. */
    bool shapes_done = false;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        if (!shapes_done && strcmp(r->family, "planar") != 0) {
            for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++)
                print_row(shapes[k].name, app_bench_ns(bench_loop, (void *)&shapes[k], n, seed, 5));
            shapes_done = true;
        }
        for (const cat_case *c = r->cases; c->name; c++) {
            static cat_state s; /* large (tables' storage) */
            char err[256];
            if (!cat_prepare_case(r, c, &s, err, sizeof err))
                app_fail("bench_samplers", "%s", err);
            print_row(c->name, app_bench_ns(draw_loop, &s, n, seed, 5));
        }
    }
    print_row(last.name, app_bench_ns(bench_loop, (void *)&last, n, seed, 5));
    return 0;
}
