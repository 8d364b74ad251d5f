/* tests/support/real_doors.h - one sampler of real_samplers.h through each
 * door of the public check (chapter 15, Testing Your Own Sampler): the C
 * API (mcbox_check_run), `mcbox-check --exec` with the sampler served by a
 * program's `serve NAME` mode, and `mcbox-check --samples` on a raw f64
 * file written by its `sample NAME N SEED f64` mode, the density then
 * served by `--pdf-exec`. The outcome of each is read back into one struct,
 * so that a test or a table can compare doors.
 */
#ifndef RS_REAL_DOORS_H
#define RS_REAL_DOORS_H

#include <stdint.h>

#include "tests/support/real_samplers.h"

typedef enum rs_door { RS_DOOR_C, RS_DOOR_EXEC, RS_DOOR_SAMPLES } rs_door;
#define RS_DOORS 3

typedef enum rs_verdict {
    RS_PASS,
    RS_FAIL,
    RS_UNDETERMINED,
    RS_ERROR /* the check could not run: bad input, a broken program (message says) */
} rs_verdict;

typedef struct rs_outcome {
    rs_verdict verdict;
    double statistic, pvalue, pdf_integral, pdf_integral_error, power_rel_error;
    int dof;
    char message[600];
    char warning[300];
    double seconds; /* wall time of the whole door */
} rs_outcome;

/* Where the command-line doors find their programs. */
typedef struct rs_env {
    char check[1024]; /* the mcbox-check program */
    char self[1024];  /* a program with rs_main's serve and sample modes */
    char tmp[256];    /* a scratch directory for sample files */
} rs_env;

const char *rs_door_name(rs_door d);     /* "C API", "--exec", "--samples" */
const char *rs_verdict_name(rs_verdict v); /* "pass", "fail", "undetermined", "error" */

/* Runs s on chart c through door d with n samples from `seed`, alpha 0.01
 * shared over `tests` tests (Sidak); fills *out. Returns out->verdict. */
rs_verdict rs_door_run(const rs_env *e, const rs_sampler *s, rs_chart c, rs_door d, uint64_t n,
                       uint64_t seed, int tests, rs_outcome *out);

/* The p-values of the C door on the sphere's default chart, (cos theta,
 * phi) about +z, for n_seeds runs of n samples from seeds seed0 + k, into
 * p[0 .. n_seeds). The chart's expected counts do not depend on the seed,
 * so they are computed once, by mcbox_check_run with seed0 (its adaptive
 * quadrature is what a density with jumps makes slow); each seed's samples
 * are then histogrammed here as that chart bins them and judged by
 * mcbox_check_counts. The first `verify` seeds also run mcbox_check_run in
 * full: *mismatches counts those whose statistic is not the same double.
 * Returns 0, or -1 (message on stderr) when the chart is not the one
 * assumed or the check cannot run. */
int rs_sphere_pvalues(const rs_sampler *s, uint64_t n, uint64_t seed0, int n_seeds, int verify,
                      double *p, int *mismatches);

/* Kolmogorov-Smirnov test of p[0 .. n) against the uniform law on [0, 1]:
 * the statistic D_n into *d, and its asymptotic p-value with Stephens'
 * correction (Stephens 1970 [@stephens1970]: D (sqrt n + 0.12 + 0.11 / sqrt n)), good to a
 * few per cent for n >= 5. Sorts p. */
double rs_ks_uniform(double *p, int n, double *d);

/* P(X >= k) for X ~ Binomial(n, q). */
double rs_binomial_tail(int n, double q, int k);

#endif /* RS_REAL_DOORS_H */
