/* mc/gof.h - goodness of fit of a sampler to its claimed density: the
 * histogram, the per-cell quadrature and the Pearson test in one call.
 *
 * mc/chi2.h has the statistic; this module adds the two steps in front of
 * it that every user repeats: count samples in the cells of a rectangle of
 * some parameterization, and integrate the claimed density over each cell
 * (adaptive quadrature, never the value at the cell centre) to get the
 * expected counts. The `warp` tool, the chi-square figures of `make plots`
 * and the test suite's harness (tests/support/chi2_harness, a thin wrapper
 * that adds names and CSV dumps) all run through it. Serves this book's
 * #ch-directions and #ch-tests, and every sampler and pdf object after
 * them.
 *
 * Parameterizations: (cos theta, phi) for directions, where a density per
 * unit solid angle is already a density of the rectangle, because
 * d omega = d(cos theta) d phi; (r^2, phi) for discs (density per unit
 * area / 2); (x, y) for planar shapes; x for 1D; index + 1/2 in [0, k] for
 * a discrete distribution of k outcomes (the density is then the
 * probability, constant over each unit cell).
 *
 * Allocation: the caller owns the count arrays; the only allocation is the
 * quadrature workspaces (mc_quad_create) of mc_gof_expected.
 */
#ifndef MC_GOF_H
#define MC_GOF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mc/chi2.h"
#include "mc/quad.h"
#include "mc/rng.h"

/* One experiment over a 1D interval or a 2D rectangle. */
typedef struct mc_gof_spec {
    int dims;            /* 1 or 2 */
    double lo[2], hi[2]; /* the rectangle (lo[1], hi[1] ignored when dims == 1) */
    int cells[2];        /* cells per dimension, >= 1 (cells[1] ignored when dims == 1) */
    /* Draws one sample, mapped into the parameterization, into out. */
    void (*sample)(mc_rng *rng, void *ctx, double out[2]);
    /* The claimed density with respect to the Lebesgue measure of the
     * parameterization, 0 outside its support. Called from several threads
     * at once: must not write ctx. */
    double (*pdf)(const double x[2], void *ctx);
    void *ctx;
} mc_gof_spec;

/* Number of cells: cells[0] (1D) or cells[0] * cells[1] (2D). Cell (i, j)
 * has index i * cells[1] + j. */
int mc_gof_cell_count(const mc_gof_spec *spec);

/* A sample at most MC_GOF_EDGE_TOL of the rectangle's width outside it is
 * put in the edge cell: a cos theta of 1 + 1 ulp is round-off, not a bug. */
#define MC_GOF_EDGE_TOL 1e-12
/* A cell whose probability integrates below this counts as expected-zero:
 * the quadrature's absolute tolerance (MC_QUAD_EPSABS) is 1e-12. */
#define MC_GOF_ZERO_CELL_PROB 1e-13
/* The fraction of the samples that may land in expected-zero cells before
 * the test rejects: samples exactly on a support boundary that coincides
 * with a cell edge; any real leak of mass is far larger. */
#define MC_GOF_ZERO_CELL_FRAC 1e-6

/* Cells with an expected count below this are pooled (the textbook rule
 * of thumb for the chi-square approximation). */
#define MC_GOF_MIN_EXPECTED 5.0

/* The subintervals GSL's adaptive rule may use per level, for each cell:
 * GSL's usual ample workspace; the densities of mcbox converge in far
 * fewer. */
#define MC_GOF_QUAD_LIMIT 1000

/* The bounds of cell c (0 <= c < mc_gof_cell_count): box = {x0, x1, y0,
 * y1}, y0 = y1 = 0 when dims == 1. Edges come from the index, not by
 * accumulation, so the last edge is exactly hi. */
void mc_gof_cell_box(const mc_gof_spec *spec, int c, double box[4]);

/* The cell of the point x of the parameterization (0 <= c <
 * mc_gof_cell_count), or -1 when x lies outside the rectangle by more than
 * MC_GOF_EDGE_TOL (NaN coordinates are outside). */
int mc_gof_cell_index(const mc_gof_spec *spec, const double x[2]);

/* Adds n samples drawn from rng to obs[0 .. mc_gof_cell_count) (the caller
 * zeroes it first) and returns how many fell outside the rectangle (NaN
 * coordinates count as outside). */
double mc_gof_histogram(const mc_gof_spec *spec, mc_rng *rng, uint64_t n, double *obs);

/* Writes the density's integral over every cell (its probability, no
 * zero threshold) to prob[0 .. mc_gof_cell_count). Cells are shared among
 * OpenMP threads, each with its own workspace. Returns 0, or -1 when a
 * workspace could not be allocated (its cells are then NaN). */
int mc_gof_cell_probs(const mc_gof_spec *spec, double *prob);

/* The same, keeping what the quadrature knows of each cell: GSL's error
 * estimate into err[c] and its status into status[c] (0 when it reached
 * its target; non-zero, typically where the density jumps inside the
 * cell, when prob[c] is only its best value). err and status may be NULL. */
int mc_gof_cell_probs_checked(const mc_gof_spec *spec, double *prob, double *err, int *status);

/* The density's integral over the box {x0, x1, y0, y1} (y ignored in 1D)
 * into *v and GSL's error estimate into *err, with the workspace q (whose
 * limit bounds the effort); returns GSL's status as above. */
int mc_gof_box_integral(const mc_gof_spec *spec, mc_quad *q, const double box[4], double *v,
                        double *err);

/* Writes n times the density's integral over every cell to
 * expct[0 .. mc_gof_cell_count), 0 for cells below MC_GOF_ZERO_CELL_PROB,
 * NaN for cells below -MC_QUAD_EPSABS (a negative density: rejected).
 * Cells are shared among OpenMP threads, each with its own workspace.
 * Returns 0, or -1 when a workspace could not be allocated (the contents
 * of expct are then unspecified). */
int mc_gof_expected(const mc_gof_spec *spec, uint64_t n, double *expct);

/* The expected counts of mc_gof_expected from cell probabilities
 * prob[0 .. cells) (as mc_gof_cell_probs writes them) and n samples: n p,
 * 0 below MC_GOF_ZERO_CELL_PROB, NaN below -MC_QUAD_EPSABS. expct may be
 * prob. */
void mc_gof_expected_of_probs(const double *prob, size_t cells, uint64_t n, double *expct);

/* The density's integral over the whole rectangle in one adaptive rule
 * (q from mc_quad_create); 1 to the quadrature's accuracy for a normalized
 * density whose support lies inside the rectangle. Where a support edge
 * crosses the rectangle (a triangle's hypotenuse) the sum of
 * mc_gof_cell_probs converges more reliably. */
double mc_gof_integrate(const mc_gof_spec *spec, mc_quad *q);

/* Outcome of mc_gof_test. */
typedef struct mc_gof_result {
    mc_chi2_result r; /* Pearson statistic, dof, p-value, pooling */
    double outside;   /* samples outside the rectangle */
    bool reject;      /* p < alpha, or any sample outside, or more than
                         MC_GOF_ZERO_CELL_FRAC n in expected-zero cells,
                         or a non-finite expected count */
} mc_gof_result;

/* Histograms n >= 1 samples drawn from rng, integrates the density over
 * every cell, pools cells with expected count < 5 and runs Pearson's test
 * at level alpha (0 < alpha < 1). obs and expct are caller-owned arrays of
 * mc_gof_cell_count(spec) doubles; they hold the tables afterwards (for
 * plots). If the workspaces cannot be allocated the result rejects with
 * p-value NaN. */
mc_gof_result mc_gof_test(const mc_gof_spec *spec, uint64_t n, mc_rng *rng, double alpha,
                          double *obs, double *expct);

#endif /* MC_GOF_H */
