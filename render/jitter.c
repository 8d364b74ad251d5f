/* render/jitter.c - the scrambled order of a pixel's cells. */
#include "render/jitter.h"

#include <stddef.h>

#include "mc/strat.h"

static uint64_t gcd(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* a b mod m for a, b < m < 2^63, by doubling (no 128-bit product). */
static uint64_t mulmod(uint64_t a, uint64_t b, uint64_t m)
{
    uint64_t r = 0;
    while (b) {
        if (b & 1u)
            r = r + a >= m ? r + a - m : r + a;
        a = a + a >= m ? a + a - m : a + a;
        b >>= 1u;
    }
    return r;
}

/* BEGIN SNIPPET jitter_make */
rt_jitter rt_jitter_make(uint64_t spp)
{
    size_t sx, sy;
    mc_strat_grid((size_t)spp, &sx, &sy);
    rt_jitter j = {sx, sy, (uint64_t)sx * sy, 1, 0, 0};
    /* A stride near m / golden ratio coprime to m is a permutation of the
     * cells whose prefixes spread over the pixel (the Fibonacci lattice
     * idea); coprimality makes it visit every cell exactly once. */
    uint64_t s = (uint64_t)(0.6180339887498949 * (double)j.m);
    s = s ? s : 1;
    while (gcd(s, j.m) != 1)
        s++;
    /* The loop stops by m - 1 (always coprime to m), so 1 <= s < m; for a
     * single cell s = 1, which also leaves the cell at 0. */
    j.stride = s;
    j.stride_i = s % j.sx;
    j.stride_j = s / j.sx;
    return j;
}
/* END SNIPPET jitter_make */

rt_jitter rt_jitter_none(void)
{
    rt_jitter j = {1, 1, 0, 1, 0, 0};
    return j;
}

rt_cell rt_jitter_cell(const rt_jitter *jt, uint64_t k)
{
    uint64_t c = k < jt->m ? mulmod(k, jt->stride, jt->m) : 0;
    rt_cell r = {c % jt->sx, c / jt->sx};
    return r;
}
