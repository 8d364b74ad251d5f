/* conform/judge.h - mcbox's own renderer held against a conformance
 * scene: K renders of the scene from seeds seed, seed + 1, ..., judged by
 * the image check (mcbox/image.h) against the scene's truth, with its
 * regions. The tests, the table of make conform-table and the book's runs
 * share it. */
#ifndef CF_JUDGE_H
#define CF_JUDGE_H

#include <stdint.h>

#include "check/image.h"
#include "conform/conform.h"
#include "render/integrator.h"
#include "render/sampler.h"

/* How to render: the path settings (strategy, depth, roulette, negative
 * controls), the sampler, the image size, samples per pixel, the renders
 * and the first seed. */
typedef struct cf_judge_job {
    rt_path_settings path;
    rt_sampler_kind sampler;
    int size;          /* width = height, >= 1 */
    uint64_t spp;      /* >= 1 */
    int renders;       /* 2 .. 64 */
    uint64_t seed;
    int threads;       /* 0: all */
    /* The truth at this size (cf_truth_image's values and error bound),
     * when the caller has it already; NULL: computed here. */
    const double *truth;
    double truth_error;
} cf_judge_job;

/* The scene's regions as the image check takes them (out holds
 * CF_MAX_REGIONS); returns how many. */
int cf_image_regions(const cf_scene *s, mcbox_image_region *out);

/* Renders and judges. Returns 0 with the verdict in *r (free it with
 * mcbox_image_result_free), 1 when the job cannot render the scene (a
 * strategy that starts light paths on emitters, light tracing or
 * bidirectional, in a scene lit by its sky alone), -1 when out of memory
 * or on bad arguments. *truth_error (may be NULL)
 * receives the bound the truth was given. */
int cf_judge(const cf_scene *s, const cf_judge_job *job, const mcbox_image_options *opt,
             mcbox_image_result *r, double *truth_error);

#endif /* CF_JUDGE_H */
