/* mc/rng.c - PCG32 seeding, bounded draws, stream derivation, jump-ahead. */
#include "mc/rng.h"

void mc_rng_seed(mc_rng *rng, uint64_t seed, uint64_t stream)
{
    /* The reference seeding: select the stream, step once, add the seed,
     * step again, so that seed 0 does not start at state 0. */
    rng->state = 0u;
    rng->inc = (stream << 1u) | 1u;
    (void)mc_rng_u32(rng);
    rng->state += seed;
    (void)mc_rng_u32(rng);
}

/* BEGIN SNIPPET rng_derive */
/* SplitMix64's finaliser (Steele, Lea, Flood 2014) [@steele2014]: a bijective 64-bit mix
 * whose outputs for consecutive inputs look independent. */
static uint64_t splitmix64(uint64_t x)
{
    x += UINT64_C(0x9e3779b97f4a7c15);
    x = (x ^ (x >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    x = (x ^ (x >> 27)) * UINT64_C(0x94d049bb133111eb);
    return x ^ (x >> 31);
}

mc_rng mc_rng_derive(uint64_t seed, uint64_t index)
{
    /* Hashing the start state avoids the known correlation between PCG
     * streams that share a start state and differ only in increment. */
    mc_rng rng;
    mc_rng_seed(&rng, splitmix64(seed ^ splitmix64(index)), splitmix64(index ^ splitmix64(seed)));
    return rng;
}
/* END SNIPPET rng_derive */

uint32_t mc_rng_bounded(mc_rng *rng, uint32_t bound)
{
    /* Outputs below 2^32 mod bound would make the low residues more likely
     * than the high ones; rejecting them leaves a multiple of bound values. */
    uint32_t threshold = (uint32_t)(-bound) % bound;
    for (;;) {
        uint32_t r = mc_rng_u32(rng);
        if (r >= threshold)
            return r % bound;
    }
}

void mc_rng_advance(mc_rng *rng, uint64_t delta)
{
    /* The LCG step s -> a s + c composed delta times is s -> A s + C; build
     * A and C by repeated squaring (F. Brown, "Random number generation with
     * arbitrary strides", 1994) [@brown1994]. */
    uint64_t cur_mult = MC_PCG32_MULT, cur_plus = rng->inc;
    uint64_t acc_mult = 1u, acc_plus = 0u;
    while (delta > 0) {
        if (delta & 1u) {
            acc_mult *= cur_mult;
            acc_plus = acc_plus * cur_mult + cur_plus;
        }
        cur_plus = (cur_mult + 1u) * cur_plus;
        cur_mult *= cur_mult;
        delta >>= 1u;
    }
    rng->state = acc_mult * rng->state + acc_plus;
}
