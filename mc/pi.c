/* mc/pi.c - hit-or-miss pi: the book's scalar loop, a SIMD-friendly lane
 * kernel, OpenMP blocks, and the jittered-grid estimator. */
#include "mc/pi.h"

#include <math.h>
#include <stdbool.h>

#include <omp.h>

#include "mc/strat.h"

/* No fused multiply-add contraction (Clang contracts by default; GCC does
 * not in ISO mode): x*x + y*y must round the same in every clone of the
 * kernels and in the scalar code, or the hit counts would depend on the
 * CPU the program runs on. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* One build runs on any x86-64 and still uses AVX-512 or AVX2 where the CPU
 * has them: the compiler emits one clone of each kernel per target and the
 * dynamic loader picks one by CPUID (GCC and Clang >= 14, glibc ifunc).
 * A NATIVE=1 build (-march=native) needs no clones. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX2__) && \
    (!defined(__clang__) || __clang_major__ >= 14)
#define KERNEL __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define KERNEL
#endif

/* Under the sanitizers' instrumentation Clang cannot vectorize the lane
 * loops and says so for every `omp simd`; that is expected there. */
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

enum { LANES = MC_PI_LANES };

/* Stream index spaces of mc_rng_derive, kept apart by their top bits. */
#define STRAT_ROWS UINT64_C(0x8000000000000000)
#define STRAT_LAST_ROW UINT64_C(0xC000000000000000)
#define STRAT_EXTRA UINT64_C(0xC000000000000001)

/* PCG32's output function of a state (the same as mc_rng_u32), written as
 * a pure function of the state so a loop over lanes can be vectorized. */
static inline uint32_t pcg_output(uint64_t old)
{
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
}

/* Two LCG steps at once: s -> a (a s + c) + c = a^2 s + (a + 1) c. */
#define PCG_MULT2 (MC_PCG32_MULT * MC_PCG32_MULT)

/* 1 when the cell-centred point of two 32-bit outputs is inside the unit
 * circle (see mc/pi.h): ((2a+1)^2 + (2b+1)^2) / 2^62 < 1 in exact integers;
 * each square is below 2^62, so the sum cannot overflow. */
static inline uint64_t inside_u32(uint32_t ux, uint32_t uy)
{
    uint64_t a = 2u * (uint64_t)(ux >> 2) + 1u, b = 2u * (uint64_t)(uy >> 2) + 1u;
    return a * a + b * b < (UINT64_C(1) << 62);
}

/* BEGIN SNIPPET pi_hits_scalar */
uint64_t mc_pi_hits_scalar(mc_rng *rng, uint64_t n)
{
    uint64_t hits = 0;
    for (uint64_t i = 0; i < n; i++) {
        double x = 2.0 * mc_rng_uniform(rng) - 1.0;
        double y = 2.0 * mc_rng_uniform(rng) - 1.0;
        if (x * x + y * y < 1.0)
            hits++;
    }
    return hits;
}
/* END SNIPPET pi_hits_scalar */

/* BEGIN SNIPPET pi_from_hits */
mc_estimate mc_pi_from_hits(uint64_t hits, uint64_t n)
{
    double p = (double)hits / (double)n;
    double var = n > 1 ? 16.0 * p * (1.0 - p) * ((double)n / (double)(n - 1)) : 0.0;
    mc_estimate e = {n, 4.0 * p, var, sqrt(var / (double)n)};
    return e;
}
/* END SNIPPET pi_from_hits */

/* `rounds` samples on each of the LANES streams (state[l], inc[l]), two
 * outputs per sample. Each lane's state advances independently, so the
 * inner loop has no dependence between lanes: that is what vectorizes. */
KERNEL static uint64_t lanes_hits(uint64_t *state, const uint64_t *inc, uint64_t rounds)
{
    uint64_t s[LANES], c1[LANES], c2[LANES], hits[LANES];
    for (int l = 0; l < LANES; l++) {
        s[l] = state[l];
        c1[l] = inc[l];
        c2[l] = (MC_PCG32_MULT + 1u) * inc[l];
        hits[l] = 0;
    }
    for (uint64_t r = 0; r < rounds; r++) {
#pragma omp simd
        for (int l = 0; l < LANES; l++) {
            uint64_t s0 = s[l];
            uint64_t s1 = s0 * MC_PCG32_MULT + c1[l];
            s[l] = s0 * PCG_MULT2 + c2[l];
            hits[l] += inside_u32(pcg_output(s0), pcg_output(s1));
        }
    }
    uint64_t total = 0;
    for (int l = 0; l < LANES; l++) {
        state[l] = s[l];
        total += hits[l];
    }
    return total;
}

/* The hits of plain block b holding `count` samples (see mc/pi.h). */
static uint64_t plain_block(uint64_t seed, uint64_t b, uint64_t count)
{
    uint64_t state[LANES], inc[LANES];
    for (int l = 0; l < LANES; l++) {
        mc_rng g = mc_rng_derive(seed, b * LANES + (uint64_t)l);
        state[l] = g.state;
        inc[l] = g.inc;
    }
    uint64_t hits = lanes_hits(state, inc, count / LANES);
    mc_rng lane0 = {state[0], inc[0]};
    for (uint64_t i = 0; i < count % LANES; i++) {
        uint32_t ux = mc_rng_u32(&lane0);
        hits += inside_u32(ux, mc_rng_u32(&lane0));
    }
    return hits;
}

static int thread_count(int threads)
{
    return threads > 0 ? threads : omp_get_max_threads();
}

uint64_t mc_pi_plain_hits_part(uint64_t seed, uint64_t n, uint64_t part, uint64_t parts, int threads)
{
    uint64_t blocks = (n + MC_PI_BLOCK - 1) / MC_PI_BLOCK, hits = 0;
    uint64_t mine = part < blocks ? (blocks - part + parts - 1) / parts : 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : hits) num_threads(thread_count(threads))
    for (uint64_t i = 0; i < mine; i++) {
        uint64_t b = part + i * parts;
        uint64_t count = b + 1 < blocks ? MC_PI_BLOCK : n - b * MC_PI_BLOCK;
        hits += plain_block(seed, b, count);
    }
    return hits;
}

mc_estimate mc_pi_plain(uint64_t seed, uint64_t n, int threads, uint64_t *hits_out)
{
    uint64_t hits = mc_pi_plain_hits_part(seed, n, 0, 1, threads);
    if (hits_out)
        *hits_out = hits;
    return mc_pi_from_hits(hits, n);
}

/* --- stratified ---------------------------------------------------------- */

/* BEGIN SNIPPET pi_jittered_cell */
/* A jittered grid of sx x sy cells: cell (i, j) is [i, i+1) x [j, j+1)
 * scaled by (1/sx, 1/sy). */
typedef struct grid {
    uint64_t sx, sy;
    double inv_sx, inv_sy;
} grid;

typedef struct tally {
    uint64_t hits;    /* points inside the quarter disc */
    uint64_t discord; /* pairs whose two cells disagree (squared difference 16) */
} tally;

static inline uint64_t inside_cell(const grid *g, uint64_t i, uint64_t j, uint32_t ux, uint32_t uy)
{
    double x = ((double)i + (double)ux * 0x1p-32) * g->inv_sx;
    double y = ((double)j + (double)uy * 0x1p-32) * g->inv_sy;
    return x * x + y * y < 1.0;
}
/* END SNIPPET pi_jittered_cell */

/* Rows j and j+1: the cells of column i form a pair; column i belongs to
 * lane i % LANES, which draws x, y in row j then x, y in row j+1. */
KERNEL static tally row_pair(const grid *g, uint64_t j, uint64_t *state, const uint64_t *inc)
{
    uint64_t s[LANES], hits[LANES], disc[LANES];
    for (int l = 0; l < LANES; l++) {
        s[l] = state[l];
        hits[l] = disc[l] = 0;
    }
    uint64_t full = g->sx - g->sx % LANES;
    for (uint64_t i0 = 0; i0 < full; i0 += LANES) {
#pragma omp simd
        for (int l = 0; l < LANES; l++) {
            uint64_t s0 = s[l], s1 = s0 * MC_PCG32_MULT + inc[l];
            uint64_t s2 = s1 * MC_PCG32_MULT + inc[l], s3 = s2 * MC_PCG32_MULT + inc[l];
            s[l] = s3 * MC_PCG32_MULT + inc[l];
            uint64_t a = inside_cell(g, i0 + (uint64_t)l, j, pcg_output(s0), pcg_output(s1));
            uint64_t b = inside_cell(g, i0 + (uint64_t)l, j + 1, pcg_output(s2), pcg_output(s3));
            hits[l] += a + b;
            disc[l] += a ^ b;
        }
    }
    tally t = {0, 0};
    for (uint64_t i = full; i < g->sx; i++) {
        mc_rng r = {s[i - full], inc[i - full]};
        uint32_t ux = mc_rng_u32(&r), uy = mc_rng_u32(&r);
        uint64_t a = inside_cell(g, i, j, ux, uy);
        ux = mc_rng_u32(&r);
        uy = mc_rng_u32(&r);
        uint64_t b = inside_cell(g, i, j + 1, ux, uy);
        s[i - full] = r.state;
        t.hits += a + b;
        t.discord += a ^ b;
    }
    for (int l = 0; l < LANES; l++) {
        t.hits += hits[l];
        t.discord += disc[l];
        state[l] = s[l];
    }
    return t;
}

/* An odd last row j: cells (2k, 2k+1) pair along the row; with sx odd its
 * last cell stays alone (*lone = 1). */
static tally last_row(const grid *g, uint64_t j, mc_rng *rng, int *lone)
{
    tally t = {0, 0};
    uint64_t prev = 0;
    for (uint64_t i = 0; i < g->sx; i++) {
        uint32_t ux = mc_rng_u32(rng);
        uint64_t h = inside_cell(g, i, j, ux, mc_rng_u32(rng));
        t.hits += h;
        if (i % 2 == 1)
            t.discord += h ^ prev;
        prev = h;
    }
    *lone = (int)(g->sx % 2);
    return t;
}

mc_pi_tally mc_pi_stratified_part(uint64_t seed, uint64_t n, uint64_t part, uint64_t parts, int threads)
{
    size_t sx, sy;
    mc_strat_grid((size_t)n, &sx, &sy);
    grid g = {sx, sy, 1.0 / (double)sx, 1.0 / (double)sy};
    uint64_t pairs = sy / 2, hits = 0, discord = 0;
    uint64_t mine = part < pairs ? (pairs - part + parts - 1) / parts : 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : hits, discord) \
    num_threads(thread_count(threads))
    for (uint64_t i = 0; i < mine; i++) {
        uint64_t m = part + i * parts, state[LANES], inc[LANES];
        for (int l = 0; l < LANES; l++) {
            mc_rng r = mc_rng_derive(seed, STRAT_ROWS + m * LANES + (uint64_t)l);
            state[l] = r.state;
            inc[l] = r.inc;
        }
        tally t = row_pair(&g, 2 * m, state, inc);
        hits += t.hits;
        discord += t.discord;
    }
    mc_pi_tally out = {hits, discord, 0};
    if (sy % 2 == 1 && part == 0) {
        mc_rng r = mc_rng_derive(seed, STRAT_LAST_ROW);
        int lone = 0;
        tally t = last_row(&g, sy - 1, &r, &lone);
        out.hits += t.hits;
        out.discord += t.discord;
        out.lone = (uint64_t)lone;
    }
    return out;
}

mc_estimate mc_pi_stratified(uint64_t seed, uint64_t n, int threads, uint64_t *hits_out)
{
    return mc_pi_stratified_finish(seed, n, mc_pi_stratified_part(seed, n, 0, 1, threads), hits_out);
}

mc_estimate mc_pi_stratified_finish(uint64_t seed, uint64_t n, mc_pi_tally grid_tally, uint64_t *hits_out)
{
    size_t sx, sy;
    mc_strat_grid((size_t)n, &sx, &sy);
    uint64_t hits = grid_tally.hits, discord = grid_tally.discord, lone = grid_tally.lone;
    /* BEGIN SNIPPET pi_stratified_error */
    /* The extra points: plain uniform, with their own sample variance. */
    uint64_t extra = n - (uint64_t)sx * sy, extra_hits = 0;
    mc_rng r = mc_rng_derive(seed, STRAT_EXTRA);
    for (uint64_t k = 0; k < extra; k++) {
        uint32_t ux = mc_rng_u32(&r);
        extra_hits += inside_u32(ux, mc_rng_u32(&r));
    }
    double extra_var = extra >= 2 ? mc_pi_from_hits(extra_hits, extra).variance : 4.0;
    double nd = (double)n;
    double sum_var = 16.0 * (double)discord + 4.0 * (double)lone + (double)extra * extra_var;
    hits += extra_hits;
    if (hits_out)
        *hits_out = hits;
    mc_estimate e = {n, 4.0 * (double)hits / nd, sum_var / nd, sqrt(sum_var) / nd};
    return e;
    /* END SNIPPET pi_stratified_error */
}
