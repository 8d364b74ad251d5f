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
        s.base = mc_qmc_stream_seed(seed, pixel);
    }
    return s;
}

/* mc_sobol_padded2's construction with the keys drawn from the pixel's
 * base, hashed once per pixel instead of once per request (the requests
 * took a third of a Sobol render's instructions that way). The request
 * at dimension d keys its index permutation and its first scramble with
 * the two halves of the 64-bit hash of (base, 2d), its second scramble
 * with half of that of (base, 2d + 1): each a full-avalanche hash
 * (mc_qmc_stream_seed), so keys of different requests, pixels and seeds
 * are independent. Dimensions are never handed out twice within a sample
 * (a 1D request moves on by one, as pbrt's Get1D does, a 2D request by
 * two), so no two requests of a sample share a permutation or a
 * scramble. */
static uint32_t sobol_index(const rt_sampler *s, uint64_t h)
{
    return mc_permutation_element(s->k, s->n, (uint32_t)h);
}

double rt_sampler_sobol_1d(rt_sampler *s)
{
    uint64_t h = mc_qmc_stream_seed(s->base, 2u * (uint64_t)s->dim);
    uint32_t v = mc_owen_scramble_u32(mc_sobol_u32(sobol_index(s, h), 0u), (uint32_t)(h >> 32));
    s->dim += s->reuse_dim ? 0u : 1u;
    return (double)v * 0x1p-32;
}

void rt_sampler_sobol_2d(rt_sampler *s, double *u1, double *u2)
{
    uint64_t h = mc_qmc_stream_seed(s->base, 2u * (uint64_t)s->dim);
    uint64_t h2 = mc_qmc_stream_seed(s->base, 2u * (uint64_t)s->dim + 1u);
    uint32_t index = sobol_index(s, h);
    *u1 = (double)mc_owen_scramble_u32(mc_sobol_u32(index, 0u), (uint32_t)(h >> 32)) * 0x1p-32;
    *u2 = (double)mc_owen_scramble_u32(mc_sobol_u32(index, 1u), (uint32_t)h2) * 0x1p-32;
    s->dim += 2u;
}
