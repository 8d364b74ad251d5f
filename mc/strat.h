/* mc/strat.h - jittered (stratified) sample sets.
 *
 * The stratified samples ("jittering") of Shirley, "Ray Tracing: The Rest
 * of Your Life" (v1.123), chapter 1 (this book's #ch-pi): split [0,1) into
 * n equal strata (1D) or [0,1)^2 into a grid of cells (2D) and put one
 * uniform point in each. For smooth integrands the error then falls faster
 * than N^-1/2.
 *
 * Any N, never a silent mismatch: the book's program takes a sqrt(N) x
 * sqrt(N) grid, traces floor(sqrt(N))^2 samples and divides by N, which is
 * biased whenever N is not a perfect square. Here a 2D set of N points is
 * the largest full grid sx x sy <= N with sx = floor(sqrt(N)) and
 * sy = floor(N / sx), followed by the N - sx sy (< sx) remaining points
 * drawn plainly uniform. Every point is returned and must be counted: the
 * grid part has mean exactly the integral, each extra point too, so the
 * plain average over all N points is unbiased. For a perfect square N the
 * set is the full sqrt(N) x sqrt(N) grid.
 */
#ifndef MC_STRAT_H
#define MC_STRAT_H

#include <stddef.h>

#include "mc/rng.h"

/* The grid that mc_jitter_2d uses for n points: *sx columns, *sy rows
 * (sx = floor(sqrt n), sy = floor(n / sx)); n - sx sy points are extra.
 * n >= 1. */
void mc_strat_grid(size_t n, size_t *sx, size_t *sy);

/* Writes n points of [0,1) to out[0..n): out[i] uniform in [i/n, (i+1)/n).
 * n >= 1. */
void mc_jitter_1d(mc_rng *rng, size_t n, double *out);

/* Writes n points of [0,1)^2 to xy[0..2n) as x, y pairs: first the sx x sy
 * grid row by row (cell (i, j) is [i/sx, (i+1)/sx) x [j/sy, (j+1)/sy)), then
 * the extra uniform points, as described above. n >= 1. */
void mc_jitter_2d(mc_rng *rng, size_t n, double *xy);

#endif /* MC_STRAT_H */
