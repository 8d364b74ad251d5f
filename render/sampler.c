/* render/sampler.c - the kinds of sampler by name, and the padded Sobol
 * requests. */
#include "render/sampler.h"

#include <stddef.h>

#include "mc/qmc.h"
#include "render/names.h"

const char *const rt_sampler_names[] = {"stratified", "independent", "sobol", "default", NULL};

bool rt_sampler_parse(const char *name, rt_sampler_kind *out)
{
    int i = rt_name_index(rt_sampler_names, name);
    if (i < 0)
        return false;
    *out = (rt_sampler_kind)i;
    return true;
}

const char *rt_sampler_name(rt_sampler_kind kind)
{
    return (unsigned)kind <= (unsigned)RT_SAMPLER_DEFAULT ? rt_sampler_names[kind] : "?";
}

/* The image's sequence is scrambled with keys of seed ^ this, apart
 * from the pixels' padded points (keyed by (seed, pixel)). */
#define IMAGE_SEQUENCE_KEY 0x1a6e5e9c1a6e5e9cull

rt_sampler rt_sampler_pixel(rt_sampler_kind kind, uint64_t seed, uint64_t spp, mc_rng rng,
                            uint64_t pixel)
{
    rt_sampler s = rt_sampler_from_rng(rng);
    if (kind == RT_SAMPLER_SOBOL) {
        s.sobol = true;
        s.n = mc_permutation_size_make((uint32_t)spp);
        s.base = mc_sobol_padded_key(mc_qmc_stream_seed(seed, pixel));
        s.first = pixel * spp;
        s.seed = seed;
        for (unsigned d = 0; d < RT_SAMPLER_IMAGE_DIMS; d++)
            s.image_key[d] = mc_qmc_key(seed ^ IMAGE_SEQUENCE_KEY, s.first >> 32, d);
    }
    return s;
}

void rt_sampler_image_point(const rt_sampler *s, unsigned n, double *u)
{
    uint64_t g = s->first + s->k;
    bool same_block = (g >> 32) == (s->first >> 32);
    for (unsigned d = 0; d < n; d++)
        u[d] = same_block ? mc_sobol_owen_keyed((uint32_t)g, d, s->image_key[d])
                          : mc_sobol_owen((uint32_t)g, d, s->seed ^ IMAGE_SEQUENCE_KEY, g >> 32);
}

/* Dimensions are never handed out twice within a sample (a 1D request
 * moves on by one, as pbrt's Get1D does, a 2D request by two), as
 * mc_sobol_padded1_sized and mc_sobol_padded2_sized require. */
double rt_sampler_sobol_1d(rt_sampler *s)
{
    double u = mc_sobol_padded1_sized(s->base, s->dim, s->k, s->n);
    s->dim += s->reuse_dim ? 0u : 1u;
    return u;
}

void rt_sampler_sobol_2d(rt_sampler *s, double *u1, double *u2)
{
    double u[2];
    mc_sobol_padded2_sized(s->base, s->dim, s->k, s->n, u);
    *u1 = u[0];
    *u2 = u[1];
    s->dim += 2u;
}
