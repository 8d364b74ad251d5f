/* mc/rng.h - PCG32 random number streams.
 *
 * The generator is O'Neill's PCG32 [@oneill2014] (XSH-RR output, 64-bit LCG state), the one
 * pbrt and Nori use: small, fast, statistically strong, and with 2^63
 * selectable streams. State is always explicit; there is no global generator
 * and no rand() anywhere in mcbox. Serves every chapter of this book,
 * starting with #ch-pi.
 *
 * Streams: mc_rng_seed(rng, seed, stream) is PCG's own (initstate, initseq)
 * seeding, bit-compatible with the reference pcg32_srandom_r. For threads,
 * pixels and test cases use mc_rng_derive(seed, index): it hashes both
 * numbers so that consecutive indices give unrelated starting points on
 * distinct PCG streams.
 */
#ifndef MC_RNG_H
#define MC_RNG_H

#include <stdint.h>

typedef struct mc_rng {
    uint64_t state; /* LCG state */
    uint64_t inc;   /* stream selector, always odd */
} mc_rng;

#define MC_PCG32_MULT UINT64_C(6364136223846793005)

/* Seeds rng exactly as the reference pcg32_srandom_r(initstate = seed,
 * initseq = stream) does; any 64-bit values are valid. */
void mc_rng_seed(mc_rng *rng, uint64_t seed, uint64_t stream);

/* A generator for sub-task `index` of a computation seeded with `seed`
 * (a thread's block, a pixel, a test case). Deterministic in (seed, index);
 * different indices select different PCG streams and hashed start states. */
mc_rng mc_rng_derive(uint64_t seed, uint64_t index);

/* BEGIN SNIPPET rng_u32_uniform */
/* The next 32 uniformly distributed bits. */
static inline uint32_t mc_rng_u32(mc_rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * MC_PCG32_MULT + rng->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
}

/* A uniform double in [0, 1): u32 * 2^-32. Its resolution is 2^-32
 * (about 2.3e-10); every value is an exact multiple of 2^-32 and the largest
 * is 1 - 2^-32, so 1.0 is never returned. */
static inline double mc_rng_uniform(mc_rng *rng)
{
    return (double)mc_rng_u32(rng) * 0x1p-32;
}
/* END SNIPPET rng_u32_uniform */

/* An unbiased integer in [0, bound) by rejection of the 2^32 mod bound
 * lowest outputs (PCG's pcg32_boundedrand_r; same sequence). bound >= 1. */
uint32_t mc_rng_bounded(mc_rng *rng, uint32_t bound);

/* Advances rng by delta steps in O(log delta) (Brown's LCG jump-ahead). */
void mc_rng_advance(mc_rng *rng, uint64_t delta);

#endif /* MC_RNG_H */
