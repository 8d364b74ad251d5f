/* render/render.c - the job's defaults and a pixel's sampler; the loop is
 * render/drive.c's. */
#include "render/render.h"

rt_render_job rt_render_job_default(const rt_scene *scene, rt_camera camera)
{
    /* The rest zero: all threads, passes of about 16, no progress, no
     * cancel flag, four paths at a time. */
    return (rt_render_job){
        .scene = scene,
        .camera = camera,
        .path = rt_path_settings_default(RT_MIXTURE),
        .spp = 100,
        .seed = 1,
        .sampler = RT_SAMPLER_DEFAULT,
    };
}

/* BEGIN SNIPPET default_sampler */
rt_sampler_kind rt_render_sampler_kind(const rt_render_job *job)
{
    if (job->sampler != RT_SAMPLER_DEFAULT)
        return job->sampler;
    /* Sobol points stratify every dimension of a path, not only the pixel
     * position; they pay where a sample is dear (the joins of
     * bidirectional paths, next-event estimation's shadow rays) and cost
     * more than they give where it is cheap (the book's integrator traces
     * four paths at a time, and a Sobol request costs several PCG32
     * draws). `make bench` measures both kinds for every strategy. */
    bool dear = job->path.strategy == RT_BDPT || job->path.strategy == RT_MIS ||
                job->path.strategy == RT_LIGHTTRACE;
    return dear && job->spp <= UINT32_MAX ? RT_SAMPLER_SOBOL : RT_SAMPLER_STRATIFIED;
}
/* END SNIPPET default_sampler */

rt_sampler rt_render_sampler(const rt_render_job *job, mc_rng rng, uint64_t pixel)
{
    rt_sampler s = rt_sampler_pixel(rt_render_sampler_kind(job), job->seed, job->spp, rng, pixel);
    s.reuse_dim = job->path.neg.sampler_reuse_dim;
    return s;
}
