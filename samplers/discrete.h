/* samplers/discrete.h - sampling one of n events with given weights.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 2 "One
 * Dimensional MC Integration", in its discrete form: the first
 * inverse-transform example of the lecture slides "Solving the Rendering
 * Equation" (this book's #ch-integration): events k = 0 .. n-1 with
 * probabilities p_k = w_k / sum(w). Two samplers, both built from a weight
 * array into storage the caller provides (nothing here allocates):
 *
 *  - smp_discrete_cdf: the CDF table P_k = p_0 + ... + p_k and a binary
 *    search for the first k with u < P_k: O(n) to build, O(log n) a draw,
 *    and monotone in u (nearby u give nearby k, which keeps stratification);
 *  - smp_alias: Walker's alias table in Vose's O(n) construction: a draw
 *    picks a column k = floor(u n) and keeps k or takes its alias by
 *    comparing the rest of u n with a threshold: O(1) a draw, not monotone.
 *
 * Events of weight 0 are never drawn by either. Both return, if asked, the
 * part of u that the choice did not use, rescaled to [0, 1) ("u_remapped"),
 * so one uniform can pick an event and then drive a continuous warp.
 * The mixture densities of (v1.123) chapter 8 "Mixture Densities" (this
 * book's #ch-mixture) do not use these tables: pdf/pdf.c picks a component
 * with its own running sum over the few weights of a mixture.
 */
#ifndef SMP_DISCRETE_H
#define SMP_DISCRETE_H

#include <stdbool.h>
#include <stddef.h>

/* --- CDF table --------------------------------------------------------- */

typedef struct smp_discrete_cdf {
    double *cdf; /* caller storage of n doubles: cdf[k] = p_0 + ... + p_k */
    size_t n;
} smp_discrete_cdf;

/* Builds the table for weights[0..n) into storage[0..n) (n >= 1; weights
 * finite and >= 0 with a positive sum). cdf[k] is 1 exactly from the last
 * event of positive weight on. Returns false, leaving *d unusable, for
 * invalid input. */
bool smp_discrete_cdf_init(smp_discrete_cdf *d, const double *weights, size_t n, double *storage);

/* The event for u in [0, 1): the smallest k with u < cdf[k]. If
 * u_remapped is not NULL it receives (u - cdf[k-1]) / p_k in [0, 1). */
size_t smp_discrete_cdf_sample(const smp_discrete_cdf *d, double u, double *u_remapped);

/* p_k (0 for k >= n). */
double smp_discrete_cdf_pmf(const smp_discrete_cdf *d, size_t k);

/* The u that sample maps to event k with remapped value r in [0, 1):
 * cdf[k-1] + r p_k. k < n. */
double smp_discrete_cdf_invert(const smp_discrete_cdf *d, size_t k, double r);

/* --- alias table ------------------------------------------------------- */

typedef struct smp_alias_cell {
    double threshold; /* keep this column's event when the rest of u n < threshold */
    double pmf;       /* p_k of this column's own event */
    size_t alias;     /* the event taken otherwise */
} smp_alias_cell;

typedef struct smp_alias {
    smp_alias_cell *cells; /* caller storage of n cells */
    size_t n;
} smp_alias;

/* Builds the alias table for weights[0..n) into storage[0..n) (same input
 * rules as smp_discrete_cdf_init). Returns false for invalid input. */
bool smp_alias_init(smp_alias *a, const double *weights, size_t n, smp_alias_cell *storage);

/* The event for u in [0, 1). If u_remapped is not NULL it receives a value
 * in [0, 1) that is uniform given the event (the position of u within the
 * part of its column that chose it). */
size_t smp_alias_sample(const smp_alias *a, double u, double *u_remapped);

/* p_k (0 for k >= n). */
double smp_alias_pmf(const smp_alias *a, size_t k);

#endif /* SMP_DISCRETE_H */
