/* render/lighttrace.c - the row kernel of the strategies that splat. */
#include "render/lighttrace.h"

/* BEGIN SNIPPET splat_row */
rt_row_counts rt_row_splat(const rt_row *r)
{
    const rt_render_job *job = r->job;
    rt_row_counts n = {0, 0};
    int w = r->img->width;
    bool weighted = rt_bdpt_weighted(&job->path);
    for (int x = 0; x < w; x++) {
        size_t idx = (size_t)r->y * (size_t)w + (size_t)x;
        rt_sampler sampler = rt_render_sampler(job, r->streams[idx], idx);
        rt_cell c = r->c0;
        /* The weighted sum leaves out the paths E S* L: the seen term
         * (render/bdpt.h), for which the first pass finds the edges. */
        if (weighted && r->k0 == 0)
            r->edges[idx] = rt_bdpt_seen_edge(r->ctx, x, r->y, job->seed, &n.segments);
        for (uint64_t k = r->k0; k < r->k1; k++) {
            rt_ray ray = rt_sample_ray(&job->camera, r->jt, x, r->y, k, &c, &sampler);
            mc_rng aux = rt_bdpt_aux_stream(job->seed, (uint64_t)idx * job->spp + k);
            vec3 L = rt_bdpt_sample(r->ctx, ray, &sampler, &aux, weighted && !r->edges[idx],
                                    r->splats, &n.segments);
            if (weighted && r->edges[idx])
                L = vec3_add(L, rt_bdpt_seen_sample(r->ctx, x, r->y, job->seed, k, &aux,
                                                    &n.segments));
            if (!rt_pixel_add(&r->img->px[idx], L))
                n.dropped++;
        }
        r->streams[idx] = sampler.rng;
    }
    return n;
}
/* END SNIPPET splat_row */
