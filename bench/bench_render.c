/* bench/bench_render.c - throughput of the Cornell box renderer.
 *
 * Renders the book's final scene (chapter 10 of "Ray Tracing: The Rest of
 * Your Life") at 600 x 600, 100 samples per pixel, max depth 50, with the
 * book's mixture strategy, once for each thread count from 1 up to
 * --max-threads T (default 2), and prints wall time, paths/s and ray
 * segments/s for each, the speed-up over the book's own program (68 s for
 * this render on one thread of the reference machine, 0.53 M paths/s), the
 * dropped non-finite samples and the mean linear RGB of the image.
 *
 * Build: make bench (or make all); run: build/bench/bench_render
 * A quicker run: MC_BENCH_QUICK=1 (or --quick) renders 10 samples per
 * pixel instead of 100; --spp N and --max-threads T override.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "render/render.h"
#include "render/scenes.h"

#define BOOK_SECONDS 68.0 /* the book's C++ program, one thread, 100 spp */

static const char *const prog = "bench_render";

int main(int argc, char **argv)
{
    uint64_t spp = 100, seed = 1;
    bool quick = getenv("MC_BENCH_QUICK") && strcmp(getenv("MC_BENCH_QUICK"), "0") != 0;
    int max_threads = 2, width = 600;
    const app_opt opts[] = {
        {"--spp", APP_COUNT, &spp, "samples per pixel (100)", NULL, 0, 0},
        {"--quick", APP_FLAG, &quick, "10 samples per pixel (also MC_BENCH_QUICK=1)", NULL, 0, 0},
        {"--max-threads", APP_INT, &max_threads, "run 1, 2, ... up to this many threads (2)", NULL, 1, 256},
        {"--width", APP_INT, &width, "image width and height (600)", NULL, 1, 65536},
        {"--seed", APP_SEED, &seed, "random seed (1)", NULL, 0, 0},
    };
    app_parse(prog, "bench_render [--spp N] [--quick] [--max-threads T]", argc, argv, opts,
              sizeof opts / sizeof opts[0], NULL, 0);
    if (quick && spp == 100)
        spp = 10;
    rt_camera_params cp;
    rt_scene *scene = rt_scene_named("book", &cp);
    rt_image *img = rt_image_create(width, width);
    if (!scene || !img) {
        fprintf(stderr, "%s: out of memory\n", prog);
        return 1;
    }
    double book_paths_per_s = 600.0 * 600.0 * 100.0 / BOOK_SECONDS;
    printf("book scene %dx%d, %llu spp, max depth 50, mixture; the book's program: %.0f s, %.2f Mpaths/s\n"
           "(x_book: paths per second as a multiple of the book's program, not a thread speed-up)\n",
           width, width, (unsigned long long)spp, BOOK_SECONDS, book_paths_per_s * 1e-6);
    printf("%7s %10s %12s %15s %10s %9s\n", "threads", "wall_s", "Mpaths/s", "Msegments/s", "x_book", "dropped");
    for (int t = 1; t <= max_threads; t++) {
        rt_render_job job = rt_render_job_default(scene, rt_camera_make(cp, width, width));
        job.spp = spp;
        job.seed = seed;
        job.threads = t;
        rt_render_stats st;
        if (rt_render(&job, img, &st) != 0) {
            fprintf(stderr, "%s: render failed\n", prog);
            return 1;
        }
        double pps = (double)st.paths / st.seconds;
        printf("%7d %10.3f %12.3f %15.3f %9.1fx %9llu\n", t, st.seconds, pps * 1e-6,
               (double)st.segments / st.seconds * 1e-6, pps / book_paths_per_s,
               (unsigned long long)st.dropped);
    }
    mc_estimate rgb[3];
    rt_image_region_stats(img, 0, 0, width, width, rgb);
    printf("mean linear RGB: %.6f %.6f %.6f (standard errors %.1e %.1e %.1e)\n", rgb[0].value,
           rgb[1].value, rgb[2].value, rgb[0].std_error, rgb[1].std_error, rgb[2].std_error);
    rt_image_destroy(img);
    rt_scene_destroy(scene);
    return 0;
}
