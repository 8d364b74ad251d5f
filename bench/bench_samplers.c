/* bench/bench_samplers.c - nanoseconds per sample of every warp in
 * samplers/ (chapters 5-7 and 10: the directions and points a renderer
 * draws at every bounce).
 *
 * Each sampler draws N samples from uniforms of one PCG32 stream (the
 * uniforms' cost included, as in a renderer; the row "rng 2 uniforms" is
 * that cost alone) and the median thread CPU time of five repetitions is
 * reported, so one slow run (page faults, a busy core) does not move the
 * table.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_samplers
 *                [--samples N] [--seed S])
 */
#include <stdio.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "mc/rng.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/lobes.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"

/* One sampler behind a common signature; param carries n, alpha, cos_max. */
typedef struct bench_case {
    const char *name;
    double (*draw)(mc_rng *rng, double param); /* returns a coordinate sum */
    double param;
} bench_case;

static double sum2(vec2 v)
{
    return v.x + v.y;
}
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

#define DRAW2(fn, expr)                                                                            \
    static double fn(mc_rng *r, double p)                                                          \
    {                                                                                              \
        (void)p;                                                                                   \
        double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r);                                     \
        return expr;                                                                               \
    }

static const vec3 corner = {0.3, -1.2, 2.385}, edge_u = {1.7, 0.2, -0.4}, edge_v = {-0.3, 0.9, 0.6};
static const vec3 center = {0.5, -1.0, 2.0};

DRAW2(d_square, sum2(smp_unit_square_sample(u1, u2)))
DRAW2(d_disc_polar, sum2(smp_disc_polar_sample(u1, u2)))
DRAW2(d_disc_conc, sum2(smp_disc_concentric_sample(u1, u2)))
DRAW2(d_triangle, sum2(smp_triangle_sample(u1, u2)))
DRAW2(d_para, sum3(smp_parallelogram_sample(u1, u2, corner, edge_u, edge_v)))
DRAW2(d_ball, sum3(smp_sphere_surface_sample(u1, u2, center, 1.7)))
DRAW2(d_sphere, sum3(smp_uniform_sphere_sample(u1, u2)))
DRAW2(d_hemi, sum3(smp_uniform_hemisphere_sample(u1, u2)))
DRAW2(d_flip, sum3(smp_hemisphere_flip_sample(u1, u2)))
DRAW2(d_cos, sum3(smp_cosine_hemisphere_sample(u1, u2)))
DRAW2(d_cos_malley, sum3(smp_cosine_hemisphere_sample_malley(u1, u2)))
DRAW2(d_cos_acos, sum3(smp_cosine_hemisphere_sample_acos(u1, u2)))
DRAW2(d_theta_phi, sum3(smp_theta_phi_sample(u1, u2)))
DRAW2(d_phong, sum3(smp_phong_lobe_sample(u1, u2, p)))
DRAW2(d_ggx, sum3(smp_ggx_sample(u1, u2, p)))
DRAW2(d_cone, sum3(smp_uniform_cone_sample(u1, u2, p)))

static double d_sphere_gauss(mc_rng *r, double p)
{
    (void)p;
    double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r), u3 = mc_rng_uniform(r),
           u4 = mc_rng_uniform(r);
    return sum3(smp_uniform_sphere_sample_gaussian(u1, u2, u3, u4));
}

static double d_sphere_reject(mc_rng *r, double p)
{
    (void)p;
    return sum3(smp_uniform_sphere_sample_rejection(r));
}

/* The sphere-cone as a light sampler uses it: 1 - cos theta_max from the
 * distance, then the cap. */
static double d_sphere_cone(mc_rng *r, double p)
{
    double u1 = mc_rng_uniform(r), u2 = mc_rng_uniform(r);
    double one_minus_cos = smp_sphere_cone_one_minus_cos(p * p, 1.0);
    return sum3(smp_uniform_cap_sample(u1, u2, one_minus_cos));
}

static const bench_case cases[] = {
    {"rng 2 uniforms", d_rng, 0.0},
    {"square", d_square, 0.0},
    {"disc-polar", d_disc_polar, 0.0},
    {"disc-concentric", d_disc_conc, 0.0},
    {"triangle", d_triangle, 0.0},
    {"parallelogram", d_para, 0.0},
    {"sphere-surface", d_ball, 0.0},
    {"sphere-inverse", d_sphere, 0.0},
    {"sphere-gaussian", d_sphere_gauss, 0.0},
    {"sphere-rejection", d_sphere_reject, 0.0},
    {"hemisphere", d_hemi, 0.0},
    {"hemisphere-flip", d_flip, 0.0},
    {"cosine", d_cos, 0.0},
    {"cosine-malley", d_cos_malley, 0.0},
    {"cosine-acos", d_cos_acos, 0.0},
    {"theta-phi", d_theta_phi, 0.0},
    {"phong-n1", d_phong, 1.0},
    {"phong-n40", d_phong, 40.0},
    {"ggx-a0.5", d_ggx, 0.5},
    {"ggx-a0.25", d_ggx, 0.25},
    {"ggx-a0.1", d_ggx, 0.1},
    {"cone-0.8", d_cone, 0.8},
    {"cone-0.2", d_cone, 0.2},
    {"cone--0.5", d_cone, -0.5},
    {"sphere-cone-d2R", d_sphere_cone, 2.0},
};

/* Draws n samples of the case (ctx) from rng; returns their coordinate sum. */
static double draw_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    const bench_case *c = ctx;
    double acc = 0.0;
    for (uint64_t i = 0; i < n; i++)
        acc += c->draw(rng, c->param);
    return acc;
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
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        printf("%-26s %.2f\n", cases[i].name,
               app_bench_ns(draw_loop, (void *)&cases[i], n, seed, 5));
    return 0;
}
