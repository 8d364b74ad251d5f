/* mc/pi.h - estimating pi by throwing points at a square.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 1 "A
 * Simple Monte Carlo Program" (this book's #ch-pi): the fraction of uniform
 * points of the unit square that land in the quarter disc x^2 + y^2 < 1 is
 * pi/4, so 4 hits / n estimates pi. This module holds the estimators the
 * `pi` program, the tests and the benchmark share:
 *
 *  - mc_pi_hits_scalar: the book's loop, one stream, one point at a time;
 *  - mc_pi_plain: the same estimator, fast: MC_PI_LANES independent PCG32
 *    streams advance side by side so the compiler turns the lane loop into
 *    SIMD code (AVX-512, AVX2 or SSE2 chosen at run time), and OpenMP
 *    threads take fixed blocks of samples;
 *  - mc_pi_stratified: the jittered grid of mc/strat.h (sx x sy cells, one
 *    point each, plus n - sx sy plain points), with a standard error from
 *    collapsed strata.
 *
 * Reproducibility: the point set depends only on (seed, n). Sample block b
 * (samples [b B, (b+1) B) with B = MC_PI_BLOCK) is drawn by lanes
 * l = 0 .. MC_PI_LANES-1 from the generators mc_rng_derive(seed,
 * b * MC_PI_LANES + l); lane l takes samples b B + r * MC_PI_LANES + l for
 * rounds r, two u32 per sample (x first). A last partial block runs its
 * whole rounds the same way and the remaining (< MC_PI_LANES) samples on
 * lane 0. Threads only decide who computes which block, and hit counts are
 * integers, so any thread count gives bit-identical results.
 *
 * The hit test is exact integer arithmetic: from a 32-bit output u the
 * coordinate is the centre of one of 2^30 equal cells, X = (2 (u >> 2) + 1)
 * / 2^31, and X^2 + Y^2 < 1 is decided as (2a+1)^2 + (2b+1)^2 < 2^62 in
 * 64-bit integers. The bias of this 2^30 x 2^30 lattice is below 1e-12
 * relative, far under the standard error of any feasible run.
 * Counters are 64-bit throughout (the book's int overflows after 2^31).
 */
#ifndef MC_PI_H
#define MC_PI_H

#include <stdint.h>

#include "mc/rng.h"
#include "mc/stats.h"

#define MC_PI_LANES 16                 /* independent streams per block */
#define MC_PI_BLOCK (UINT64_C(1) << 18) /* samples per block of mc_pi_plain */

/* The number of the n next points (x, y) = (2 u1 - 1, 2 u2 - 1) from rng
 * (u = mc_rng_uniform) inside the unit circle: the book's loop, verbatim in
 * spirit, one scalar stream. Advances rng by 2 n outputs. */
uint64_t mc_pi_hits_scalar(mc_rng *rng, uint64_t n);

/* The pi estimate from `hits` of n >= 1 plain points: value 4 hits / n,
 * variance per sample 16 p (1 - p) n / (n - 1) with p = hits / n (the
 * unbiased variance of a 0/4 variable; 0 when n == 1), std_error
 * sqrt(variance / n). */
mc_estimate mc_pi_from_hits(uint64_t hits, uint64_t n);

/* Hit-or-miss estimate of pi from n >= 1 points drawn as described above,
 * on `threads` OpenMP threads (0: the OpenMP default). If hits is not NULL
 * it receives the hit count. */
mc_estimate mc_pi_plain(uint64_t seed, uint64_t n, int threads, uint64_t *hits);

/* Stratified estimate of pi from n >= 1 points: the jittered grid of
 * mc_strat_grid (sx x sy cells with one uniform point each) plus the
 * n - sx sy (< sx) extra uniform points, all averaged with weight 1/n, so
 * the estimate is unbiased for every n.
 *
 * Standard error by collapsed strata: cells are paired with a neighbour
 * (cell (i, 2m) with (i, 2m+1); an odd last row pairs along the row) and
 * the squared difference of each pair's two 0/4 values estimates the sum of
 * their variances plus the square of their mean difference, so the sum
 * over pairs, divided by n^2, over-estimates the grid's variance: the error
 * bar is conservative, never too small (tests/test_pi.c holds it to that
 * over 32 seeds on every run). A cell left without a partner adds the
 * largest variance a 0/4 variable can have (4); the extra points add their
 * own sample variance (4 each when there is only one). `variance` is n times
 * the variance of the estimate (the per-sample figure that gives
 * std_error = sqrt(variance / n)).
 *
 * Row pair m is drawn by lanes from mc_rng_derive(seed, 2^63 + m
 * MC_PI_LANES + l), column i by lane i % MC_PI_LANES (x, y in row 2m, then
 * x, y in row 2m+1); the odd last row, cell by cell, from index
 * 2^63 + 2^62 and the extra points from 2^63 + 2^62 + 1. Same
 * thread-independence as mc_pi_plain. */
mc_estimate mc_pi_stratified(uint64_t seed, uint64_t n, int threads, uint64_t *hits);

/* --- a run split into parts (several processes, e.g. under MPI) ----------
 * Part p of P (0 <= p < P) takes the blocks, or row pairs, whose index is
 * p modulo P. Its result is an integer tally, and integer sums do not
 * depend on their order: the parts' tallies summed give exactly the counts
 * of the one-call functions above, for any P and any thread count. */

/* The hits of the blocks b = part, part + parts, ... of mc_pi_plain(seed,
 * n, ...); parts >= 1. */
uint64_t mc_pi_plain_hits_part(uint64_t seed, uint64_t n, uint64_t part, uint64_t parts, int threads);

/* The integer tallies of the jittered grid of mc_pi_stratified. */
typedef struct mc_pi_tally {
    uint64_t hits;    /* grid points inside the quarter disc */
    uint64_t discord; /* cell pairs whose two points disagree */
    uint64_t lone;    /* 1 when a cell has no partner (sx and sy odd) */
} mc_pi_tally;

/* The tallies of row pairs m = part, part + parts, ... of the grid of
 * mc_pi_stratified(seed, n, ...); part 0 also takes the odd last row. */
mc_pi_tally mc_pi_stratified_part(uint64_t seed, uint64_t n, uint64_t part, uint64_t parts, int threads);

/* mc_pi_stratified from the summed tallies of all parts: draws the
 * n - sx sy extra points and forms the estimate and its error bar. */
mc_estimate mc_pi_stratified_finish(uint64_t seed, uint64_t n, mc_pi_tally grid_tally, uint64_t *hits);

#endif /* MC_PI_H */
