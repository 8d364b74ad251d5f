/* bench/bench_convergence.c - how fast each strategy's error falls with
 * the sample count, for each sampler, on both Cornell boxes.
 *
 * For the book's scene and the all-diffuse lambert box, every strategy
 * (with and without Russian roulette where both are in use) is rendered
 * with the stratified sampler (the pixel position jittered, PCG32 for the
 * rest) and with Owen-scrambled Sobol points (every dimension
 * stratified), at 16, 64, 256 and 1024 samples per pixel, twice with
 * different seeds. An unbiased image's squared error is its variance, and
 * two independent renders a and b differ by twice it on average: the
 * table gives per pixel MSE(a, b) / 2 at each count (no reference needed,
 * so a count of 1024 costs two renders), the slope of its logarithm
 * against the logarithm of the count by least squares (-1 for independent
 * samples; steeper where the points are stratified in the dimensions
 * that matter), and the efficiency 1 / (variance x seconds) at the
 * largest count. Last, per strategy, which sampler has the larger
 * efficiency and which one the strategy takes by default
 * (rt_render_sampler_kind): the default is the one this table measures
 * best.
 *
 * The image is small (64 x 64 by default; a pixel then covers more of the
 * scene than at 600 x 600, so the pixel position matters more), and the
 * seconds are those of --threads threads (2), on a machine that should be
 * otherwise idle: the slopes and the variances are deterministic (fixed
 * seeds; the same for any thread count), the seconds are not.
 *
 * Build: make bench (or make all); run: build/bench/bench_convergence
 * [--width W] [--max-spp N] [--threads T] [--quick] (--quick or
 * MC_BENCH_QUICK=1: 32 x 32, up to 256 samples per pixel).
 */
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "render/bdpt.h"
#include "render/render.h"
#include "render/scenes.h"

static const char *const prog = "bench_convergence";

/* The strategies, by rt_bdpt_strategy_parse's names, "+rr" for Russian
 * roulette. */
static const char *const rows[] = {"uniform", "cosine", "light",      "mixture", "mixture+rr",
                                   "mis",     "mis+rr", "lighttrace", "bdpt",    "bdpt+rr"};
#define NROWS (sizeof rows / sizeof rows[0])
#define MAX_COUNTS 8

static const rt_sampler_kind samplers[2] = {RT_SAMPLER_STRATIFIED, RT_SAMPLER_SOBOL};

/* One render of row `row` with `sampler` into img; its seconds, or a
 * negative number when it fails. */
static double render(const rt_scene *scene, rt_camera_params cp, const char *row,
                     rt_sampler_kind sampler, uint64_t spp, uint64_t seed, int threads,
                     rt_image *img, rt_sampler_kind *resolved_default)
{
    rt_render_job job = rt_render_job_default(scene, rt_camera_make(cp, img->width, img->width));
    char name[32];
    snprintf(name, sizeof name, "%s", row);
    job.path.russian_roulette = strstr(name, "+rr") != NULL;
    name[strcspn(name, "+")] = '\0';
    if (!rt_bdpt_strategy_parse(name, &job.path))
        return -1.0;
    job.spp = spp;
    job.seed = seed;
    job.threads = threads;
    *resolved_default = rt_render_sampler_kind(&job); /* job.sampler is RT_SAMPLER_DEFAULT */
    job.sampler = sampler;
    rt_render_stats st;
    return rt_render(&job, img, &st) == 0 ? st.seconds : -1.0;
}

/* The least-squares slope of log y against log x over n points (GSL's
 * straight-line fit). */
static double log_slope(const double *x, const double *y, int n)
{
    double lx[MAX_COUNTS], ly[MAX_COUNTS], c0, c1, cov00, cov01, cov11, sumsq;
    for (int i = 0; i < n; i++) {
        lx[i] = log(x[i]);
        ly[i] = log(y[i]);
    }
    gsl_fit_linear(lx, 1, ly, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
    return c1;
}

/* The table of one scene; false when a render fails. */
static bool scene_table(const char *scene_name, int width, const uint64_t *counts, int ncounts,
                        int threads)
{
    rt_camera_params cp;
    rt_scene *scene = rt_scene_named(scene_name, &cp);
    rt_image *a = rt_image_create(width, width), *b = rt_image_create(width, width);
    bool ok = scene && a && b;
    if (ok) {
        printf("\n%s, %dx%d, %d threads: variance per pixel (linear RGB, summed over the "
               "channels) = MSE(seed 1, seed 2) / 2\n",
               scene_name, width, width, threads);
        printf("%-11s %-10s", "strategy", "sampler");
        for (int c = 0; c < ncounts; c++)
            printf(" %9s%-4llu", "var@", (unsigned long long)counts[c]);
        printf(" %7s %10s %11s\n", "slope", "seconds", "efficiency");
    }
    for (size_t r = 0; ok && r < NROWS; r++) {
        double eff[2] = {0.0, 0.0};
        rt_sampler_kind def = RT_SAMPLER_STRATIFIED;
        for (int k = 0; ok && k < 2; k++) {
            double n[MAX_COUNTS], var[MAX_COUNTS], seconds = 0.0;
            printf("%-11s %-10s", rows[r], rt_sampler_name(samplers[k]));
            for (int c = 0; ok && c < ncounts; c++) {
                double ta = render(scene, cp, rows[r], samplers[k], counts[c], 1, threads, a, &def);
                double tb = render(scene, cp, rows[r], samplers[k], counts[c], 2, threads, b, &def);
                ok = ta >= 0.0 && tb >= 0.0;
                n[c] = (double)counts[c];
                var[c] = 3.0 * rt_image_mse(a, b) / 2.0;
                seconds = 0.5 * (ta + tb);
                printf(" %13.4e", var[c]);
            }
            if (!ok)
                break;
            eff[k] = 1.0 / (var[ncounts - 1] * seconds);
            printf(" %7.3f %10.3f %11.4g\n", log_slope(n, var, ncounts), seconds, eff[k]);
            fflush(stdout);
        }
        if (ok) {
            int best = eff[1] > eff[0];
            printf("%-11s best at %llu spp: %s (%.2fx the other); default: %s%s\n", rows[r],
                   (unsigned long long)counts[ncounts - 1], rt_sampler_name(samplers[best]),
                   eff[best] / eff[1 - best], rt_sampler_name(def),
                   def == samplers[best] ? "" : " (not the best in this run)");
        }
    }
    if (!ok)
        fprintf(stderr, "%s: %s: a render failed\n", prog, scene_name);
    rt_image_destroy(a);
    rt_image_destroy(b);
    rt_scene_destroy(scene);
    return ok;
}

int main(int argc, char **argv)
{
    bool quick = app_bench_quick();
    int width = 0, threads = 2;
    uint64_t max_spp = 0;
    const app_opt opts[] = {
        {"--width", APP_INT, &width, "image width and height (64; --quick 32)", NULL, 8, 4096},
        {"--max-spp", APP_COUNT, &max_spp,
         "the largest sample count, 16 x a power of 4 (1024; --quick 256)", NULL, 0, 0},
        {"--threads", APP_INT, &threads, "OpenMP threads (2)", NULL, 1, 256},
        {"--quick", APP_FLAG, &quick, "32x32 up to 256 spp (also MC_BENCH_QUICK=1)", NULL, 0, 0},
    };
    app_parse(prog, "bench_convergence [--width W] [--max-spp N] [--threads T] [--quick]", argc,
              argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    if (width == 0)
        width = quick ? 32 : 64;
    if (max_spp == 0)
        max_spp = quick ? 256 : 1024;
    uint64_t counts[MAX_COUNTS];
    int ncounts = 0;
    for (uint64_t n = 16; n <= max_spp && ncounts < MAX_COUNTS; n *= 4)
        counts[ncounts++] = n;
    if (ncounts < 2 || counts[ncounts - 1] != max_spp)
        app_fail(prog, "--max-spp %llu: must be 16 x a power of 4 from 64 to %llu",
                 (unsigned long long)max_spp, 16ull << (2 * (MAX_COUNTS - 1)));
    printf("error against the sample count: %dx%d, %d to %llu samples per pixel, seeds 1 and 2\n",
           width, width, 16, (unsigned long long)max_spp);
    bool ok = scene_table("book", width, counts, ncounts, threads);
    ok = scene_table("lambert", width, counts, ncounts, threads) && ok;
    return ok ? 0 : 1;
}
