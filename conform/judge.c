/* conform/judge.c - K renders of a conformance scene through the image
 * check. */
#include "conform/judge.h"

#include <stdlib.h>
#include <string.h>

#include "conform/build.h"
#include "conform/truth.h"
#include "render/render.h"

int cf_image_regions(const cf_scene *s, mcbox_image_region *out)
{
    for (int g = 0; g < s->n_regions; g++) {
        const cf_region *rg = &s->regions[g];
        out[g] = (mcbox_image_region){rg->name, rg->x0, rg->y0, rg->x1, rg->y1};
    }
    return s->n_regions;
}

int cf_judge(const cf_scene *s, const cf_judge_job *job, const mcbox_image_options *opt,
             mcbox_image_result *r, double *truth_error)
{
    if (!s || !job || job->size < 1 || job->spp < 1 || job->renders < 2 || job->renders > 64)
        return -1;
    rt_camera_params cp;
    rt_scene *scene = cf_build(s, &cp);
    size_t n = (size_t)job->size * (size_t)job->size;
    double *grey = malloc(n * sizeof *grey), *truth = malloc(3 * n * sizeof *truth);
    double *img[64] = {NULL};
    rt_image *im = rt_image_create(job->size, job->size);
    int rc = scene && grey && truth && im ? 0 : -1;
    double err = job->truth_error;
    if (rc == 0 && job->truth)
        memcpy(grey, job->truth, n * sizeof *grey);
    else if (rc == 0)
        rc = cf_truth_image(s, job->size, job->size, grey, &err);
    for (size_t i = 0; rc == 0 && i < 3 * n; i++)
        truth[i] = grey[i / 3];
    /* Light paths start on emitters, and a sky is none: a strategy that
     * splats would render the sky's scene black. */
    if (rc == 0 && rt_strategy_splats(job->path.strategy) && rt_scene_emitter_count(scene) == 0)
        rc = 1;
    for (int k = 0; rc == 0 && k < job->renders; k++) {
        rt_render_job rj = rt_render_job_default(scene, rt_camera_make(cp, job->size, job->size));
        rj.path = job->path;
        rj.sampler = job->sampler;
        rj.spp = job->spp;
        rj.seed = job->seed + (uint64_t)k;
        rj.threads = job->threads;
        if (rt_render(&rj, im, NULL) != 0) {
            rc = -1;
            break;
        }
        img[k] = malloc(3 * n * sizeof *img[k]);
        if (!img[k]) {
            rc = -1;
            break;
        }
        for (size_t i = 0; i < n; i++) {
            vec3 c = rt_image_get(im, (int)(i % (size_t)job->size), (int)(i / (size_t)job->size));
            img[k][3 * i] = c.x, img[k][3 * i + 1] = c.y, img[k][3 * i + 2] = c.z;
        }
    }
    if (rc == 0) {
        mcbox_image_region regions[CF_MAX_REGIONS];
        mcbox_image_options o = opt ? *opt : (mcbox_image_options){0};
        if (!o.regions) {
            o.regions = regions;
            o.n_regions = cf_image_regions(s, regions);
        }
        mcbox_image_set set = {.width = job->size, .height = job->size, .truth = truth,
                               .truth_error = err + CF_DEPTH_PROMISE, .n_renders = job->renders,
                               .renders = (const double *const *)img};
        if (truth_error)
            *truth_error = set.truth_error;
        rc = mcbox_image_check(&set, &o, r) == 0 ? 0 : -1;
    }
    for (int k = 0; k < job->renders; k++)
        free(img[k]);
    rt_image_destroy(im);
    free(grey);
    free(truth);
    rt_scene_destroy(scene);
    return rc;
}
