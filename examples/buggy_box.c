/* examples/buggy_box.c - this book's #ch-own-renderer: mcbox's renderer
 * with one classic bug switched on, rendering a conformance scene
 * (conform/conform.h) into a linear PFM, so that the image door of
 * mcbox-check can be seen catching it. The bugs are the renderer's
 * negative controls (render/integrator.h):
 *
 *   light-cosine   next-event estimation without the cosine at the light
 *                  (dividing by d^2 / A instead of d^2 / (A cos))
 *   area-density   the light's area density 1 / A taken for the
 *                  solid-angle density
 *   roulette       Russian roulette that keeps a survivor's throughput
 *                  instead of dividing it by the survival probability
 *   book-spp       floor(sqrt(spp))^2 samples divided by spp, the loop of
 *                  the book's release code, which darkens every pixel when
 *                  spp is not a square
 *   none           the correct renderer
 *
 * Build and run:  make all && build/bin/buggy_box --bug light-cosine -o bug.pfm
 *   build/bin/mcbox-check --image bug1.pfm --image bug2.pfm --scene quad-wall
 */
#include <stdio.h>
#include <string.h>

#include "conform/build.h"
#include "examples/common/cli.h"
#include "render/render.h"

static const char *const bugs[] = {"none", "light-cosine", "area-density", "roulette", "book-spp",
                                   NULL};

int main(int argc, char **argv)
{
    const char *prog = "buggy_box", *bug = "light-cosine", *scene = "quad-wall",
               *strategy = "mis", *out = "buggy.pfm";
    uint64_t spp = 64, seed = 1;
    int width = 64;
    const app_opt opts[] = {
        {"--bug", APP_CHOICE, &bug, "the bug (default light-cosine)", bugs, 0, 0},
        {"--scene", APP_CHOICE, &scene, "a conformance scene (default quad-wall)", cf_scene_names,
         0, 0},
        {"--strategy", APP_CHOICE, &strategy, "sampling strategy (default mis)",
         rt_strategy_names, 0, 0},
        {"--width", APP_INT, &width, "image width and height (default 64)", NULL, 1, 4096},
        {"--spp", APP_COUNT, &spp, "samples per pixel (default 64)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
        {"-o", APP_STRING, &out, "output .pfm, .png or .ppm (gamma 2) (default buggy.pfm)", NULL,
         0, 0},
    };
    app_parse(prog, "buggy_box [--bug B] [--scene S] [--strategy S] [--width W] [--spp N] "
                    "[--seed S] [-o FILE]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    if (rt_format_from_path(out) == RT_FORMAT_UNKNOWN)
        app_fail(prog, "-o %s: the extension must be .pfm, .png or .ppm", out);
    rt_camera_params cp;
    rt_scene *s = cf_build(cf_scene_find(scene), &cp);
    rt_image *img = rt_image_create(width, width);
    if (!s || !img)
        app_fail(prog, "out of memory");
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, width, width));
    rt_strategy st = RT_MIS;
    rt_strategy_parse(strategy, &st);
    job.path = rt_path_settings_default(st);
    job.path.russian_roulette = true;
    job.path.neg.light_drop_cos = strcmp(bug, "light-cosine") == 0;
    job.path.neg.light_area_density = strcmp(bug, "area-density") == 0;
    job.path.neg.roulette_no_divide = strcmp(bug, "roulette") == 0;
    job.path.neg.book_spp_divisor = strcmp(bug, "book-spp") == 0;
    job.spp = spp;
    job.seed = seed;
    /* Light paths start on emitters, and a sky is none. */
    int rc = rt_strategy_splats(st) && rt_scene_emitter_count(s) == 0 ? -1
                                                                      : rt_render(&job, img, NULL);
    if (rc != 0) {
        rt_image_destroy(img);
        rt_scene_destroy(s);
        app_fail(prog, "--strategy %s cannot render %s (no emitter to start light paths on)",
                 strategy, scene);
    }
    if (rt_image_save(img, out, RT_GAMMA_2) != 0)
        app_fail(prog, "cannot write %s", out);
    rt_image_destroy(img);
    rt_scene_destroy(s);
    return 0;
}
