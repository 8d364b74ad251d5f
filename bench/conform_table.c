/* bench/conform_table.c - mcbox's renderer against the conformance scenes
 * (conform/judge.h), as one Markdown table: for every scene and strategy,
 * the truth's error bound, the false-alarm rate of the image check over
 * many seeds (four renders of 32 x 32 at 64 samples per pixel, roulette
 * on, alpha 0.01: the rate must stay near or below 0.01), and the power:
 * the smallest bias over the whole image, and in a typical block of 4 x 4
 * pixels, that the check catches with probability 0.9, at 64 and at 1024
 * samples per pixel.
 *
 * Seeds: 7000 + 10 k for the k-th false-alarm run (renders 7000 + 10 k
 * .. + 3), 9000 for the power runs.
 *
 * Build and run: make conform-table   (or: make all && build/bench/conform_table)
 *   build/bench/conform_table [--seeds 100] [--only SCENE]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "conform/judge.h"
#include "conform/truth.h"
#include "examples/common/cli.h"

#define PROG "conform_table"

/* The power run's detectable relative bias, over the image and the
 * median block. */
static void power(const cf_scene *s, rt_path_settings ps, uint64_t spp, const double *truth,
                  double err, double out[2])
{
    cf_judge_job job = {.path = ps, .size = 32, .spp = spp, .renders = 4, .seed = 9000,
                        .truth = truth, .truth_error = err};
    mcbox_image_result r;
    out[0] = out[1] = -1.0;
    if (cf_judge(s, &job, NULL, &r, NULL) != 0)
        return;
    out[0] = r.image[0].detectable / r.image[0].truth;
    out[1] = r.block_detectable;
    mcbox_image_result_free(&r);
}

int main(int argc, char **argv)
{
    int seeds = 100;
    const char *only = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0) {
            puts("usage: " PROG " [--seeds 100] [--only SCENE]\n"
                 "mcbox's renderer against the conformance scenes: false alarms and power.");
            return 0;
        }
        if (strcmp(argv[i], "--version") == 0) {
            puts(PROG " (mcbox) " APP_VERSION);
            return 0;
        }
        uint64_t n;
        if (strcmp(argv[i], "--seeds") == 0 && i + 1 < argc &&
            app_parse_uint(argv[i + 1], 1, 100000, &n)) {
            seeds = (int)n;
            i++;
        } else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc && cf_scene_find(argv[i + 1])) {
            only = argv[++i];
        } else {
            fprintf(stderr, "%s: %s: not an option or a bad value (--help)\n", PROG, argv[i]);
            return 2;
        }
    }
    printf("| scene | strategy | truth error | false alarms | image 64 | block 64 | image 1024 | "
           "block 1024 |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; cf_scene_names[k]; k++) {
        const cf_scene *s = cf_scene_find(cf_scene_names[k]);
        if (only && strcmp(only, s->name) != 0)
            continue;
        /* The truth once per scene: the clipped sphere's takes a second. */
        double truth[32 * 32], err;
        if (cf_truth_image(s, 32, 32, truth, &err) != 0)
            return 1;
        for (int st = RT_UNIFORM; st <= RT_BDPT; st++) {
            rt_path_settings ps = rt_path_settings_default((rt_strategy)st);
            ps.russian_roulette = true;
            int fails = 0, runs = 0;
            double terr = 0.0;
            for (int i = 0; i < seeds; i++) {
                cf_judge_job job = {.path = ps, .size = 32, .spp = 64, .renders = 4,
                                    .seed = 7000 + 10 * (uint64_t)i, .truth = truth,
                                    .truth_error = err};
                mcbox_image_result r;
                int rc = cf_judge(s, &job, NULL, &r, &terr);
                if (rc != 0)
                    break;
                fails += !r.pass;
                runs++;
                mcbox_image_result_free(&r);
            }
            if (!runs) {
                printf("| %s | %s | | refused (no emitter) | | | | |\n", s->name,
                       rt_strategy_name((rt_strategy)st));
                continue;
            }
            double p64[2], p1024[2];
            power(s, ps, 64, truth, err, p64);
            power(s, ps, 1024, truth, err, p1024);
            printf("| %s | %s | %.1e | %d / %d | %.3g%% | %.3g%% | %.3g%% | %.3g%% |\n", s->name,
                   rt_strategy_name((rt_strategy)st), terr, fails, runs, 100 * p64[0],
                   100 * p64[1], 100 * p1024[0], 100 * p1024[1]);
            fflush(stdout);
        }
    }
    return 0;
}
