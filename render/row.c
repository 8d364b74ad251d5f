/* render/row.c - the reference row kernel: one path after the other. */
#include "render/row.h"

/* BEGIN SNIPPET render_row */
rt_row_counts rt_row_reference(const rt_row *r)
{
    const rt_render_job *job = r->job;
    rt_row_counts n = {0, 0};
    int w = r->img->width;
    for (int x = 0; x < w; x++) {
        size_t idx = (size_t)r->y * (size_t)w + (size_t)x;
        rt_sampler sampler = rt_render_sampler(job, r->streams[idx], idx);
        rt_pixel *px = &r->img->px[idx];
        rt_cell c = r->c0;
        for (uint64_t k = r->k0; k < r->k1; k++) {
            rt_ray ray = rt_sample_ray(&job->camera, r->jt, x, r->y, k, &c, &sampler);
            vec3 L = rt_radiance(job->scene, &job->path, ray, &sampler, &n.segments);
            if (!rt_pixel_add(px, L))
                n.dropped++;
        }
        r->streams[idx] = sampler.rng;
    }
    return n;
}
/* END SNIPPET render_row */
