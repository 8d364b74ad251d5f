/* render/sampler.c - the kinds of sampler by name, and the padded Sobol
 * requests. */
#include "render/sampler.h"

#include <string.h>

#include "mc/qmc.h"

const char *const rt_sampler_names[] = {"stratified", "independent", "sobol", NULL};

bool rt_sampler_parse(const char *name, rt_sampler_kind *out)
{
    for (int i = 0; rt_sampler_names[i]; i++)
        if (strcmp(name, rt_sampler_names[i]) == 0) {
            *out = (rt_sampler_kind)i;
            return true;
        }
    return false;
}

const char *rt_sampler_name(rt_sampler_kind kind)
{
    return (unsigned)kind <= (unsigned)RT_SAMPLER_SOBOL ? rt_sampler_names[kind] : "?";
}

rt_sampler rt_sampler_pixel(rt_sampler_kind kind, uint64_t seed, uint64_t spp, mc_rng rng,
                            uint64_t pixel)
{
    rt_sampler s = rt_sampler_from_rng(rng);
    if (kind == RT_SAMPLER_SOBOL) {
        s.sobol = true;
        s.n = (uint32_t)spp;
        s.seed = seed;
        s.pixel = pixel;
    }
    return s;
}

/* Every request, 1D or 2D, is one call of mc_sobol_padded2 with the
 * request's first dimension as its `pair`: dimensions are never handed out
 * twice within a sample, so no two requests of a sample share a
 * permutation or a scramble. A 1D request keeps the first coordinate and
 * moves on by one dimension, as pbrt's Get1D does; a 2D request moves on
 * by two. */
double rt_sampler_sobol_1d(rt_sampler *s)
{
    double u[2];
    mc_sobol_padded2(s->seed, s->pixel, s->dim, s->k, s->n, u);
    s->dim += s->reuse_dim ? 0u : 1u;
    return u[0];
}

void rt_sampler_sobol_2d(rt_sampler *s, double *u1, double *u2)
{
    double u[2];
    mc_sobol_padded2(s->seed, s->pixel, s->dim, s->k, s->n, u);
    s->dim += 2u;
    *u1 = u[0];
    *u2 = u[1];
}
