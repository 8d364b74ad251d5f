/* render/render.c - the job's defaults and a pixel's sampler; the loop is
 * render/drive.c's. */
#include "render/render.h"

rt_render_job rt_render_job_default(const rt_scene *scene, rt_camera camera)
{
    /* The rest zero: all threads, passes of about 16, no progress, no
     * cancel flag, four paths at a time, the stratified sampler. */
    return (rt_render_job){
        .scene = scene,
        .camera = camera,
        .path = rt_path_settings_default(RT_MIXTURE),
        .spp = 100,
        .seed = 1,
    };
}

rt_sampler rt_render_sampler(const rt_render_job *job, mc_rng rng, uint64_t pixel)
{
    rt_sampler s = rt_sampler_pixel(job->sampler, job->seed, job->spp, rng, pixel);
    s.reuse_dim = job->path.neg.sampler_reuse_dim;
    return s;
}
