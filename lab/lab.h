/* lab/lab.h - the warp lab's WebAssembly interface: what the book's lab
 * page (lab/lab.js) calls in the module built from the catalog, the
 * samplers, the pdf objects and the goodness-of-fit harness.
 *
 * The page and the module share nothing but numbers and the module's
 * memory: strings go in through lab_input's buffer and come out as
 * NUL-terminated strings at the returned addresses; tables come out as
 * arrays of doubles. Seeds travel as two 32-bit halves, because a
 * JavaScript number holds no 64-bit integer. One row is selected at a time
 * (lab_select); every other call works on it.
 *
 * Serves the book's warp lab page, which follows #ch-directions and
 * #ch-tests (the chi-square test of a warp) and #ch-scattering (the
 * importance-sampled estimate).
 */
#ifndef LAB_LAB_H
#define LAB_LAB_H

#include <stdint.h>

/* Where the point source of a run comes from. */
enum lab_source {
    LAB_INDEPENDENT = 0, /* PCG32 uniforms, as `warp chi2` draws them */
    LAB_JITTERED = 1,    /* one jittered point per cell of a grid (mc/strat.h) */
    LAB_SOBOL = 2        /* Owen-scrambled Sobol points (mc/qmc.h) */
};

/* The buffer (LAB_INPUT_SIZE bytes) the page writes its strings into. */
#define LAB_INPUT_SIZE 4096
char *lab_input(void);

/* The catalog as JSON: every row, then every negative control, each with
 * its name, domain, measure, point kind, chart, uniforms, the sources it
 * can take, what is wrong with it (null for a real sampler) and its
 * parameters (key, kind, default, range). */
const char *lab_catalog(void);

/* Selects the row named on the first line of the input buffer with the
 * "key=value" assignments of the following lines. 1 on success, 0 with a
 * message (lab_error) otherwise; the previous selection then stays. */
int lab_select(void);
const char *lab_error(void);

/* Bit k set: the selected row takes the point source k. */
int lab_sources(void);

/* `warp chi2` for the selected row: n samples from the source, seeded by
 * (seed_hi, seed_lo), histogrammed on the row's chart at the resolution
 * cat_gof_spec_for picks for n, Pearson's test at level alpha. 1 on
 * success, 0 with a message. The results stay until the next call:
 * lab_result, lab_observed, lab_expected and lab_line. */
int lab_chi2(uint32_t seed_hi, uint32_t seed_lo, double n, double alpha, int source);

/* The last run's numbers: statistic, dof, p-value, reject (0 or 1),
 * samples outside the chart, cells pooled, observed total, expected total,
 * chart dims, lo[0], hi[0], lo[1], hi[1], cells[0], cells[1], samples in
 * expected-zero cells, milliseconds spent (filled in by the page). */
#define LAB_RESULT_COUNT 17
double *lab_result(void);
/* Its observed and expected counts per cell, cell (i, j) at i cells[1] + j. */
double *lab_observed(void);
double *lab_expected(void);
/* Its statistic, dof, p-value and verdict as `warp chi2` prints them. */
const char *lab_line(void);

/* The first n (<= LAB_MAX_POINTS) points of the source (a jittered source:
 * a set of n points) and their images:
 * for each, u1, u2 (NaN where the row draws from a generator instead of
 * from uniforms, u2 NaN for one uniform), the point x, y, z and its chart
 * point c1, c2: LAB_POINT_STRIDE doubles each. NULL with a message if n is
 * out of range. */
#define LAB_MAX_POINTS 16384
#define LAB_POINT_STRIDE 7
double *lab_points(uint32_t seed_hi, uint32_t seed_lo, int n, int source);

/* The running estimate: kind 0 is pi by hit-or-miss (4 times the fraction
 * of uniform points of the unit square inside the quarter disc), kind 1 the
 * integral of cos^3 theta over the hemisphere (exactly pi / 2) by
 * importance sampling from the selected row, which must be a direction
 * row. n samples from the generator of (seed_hi, seed_lo), through
 * mc_integrate_sampler, recorded at up to 80 counts spaced evenly in
 * log n: the number of samples, the mean and its standard error, three
 * doubles each. Returns how many were recorded, or 0 with a message. */
int lab_estimate(int kind, uint32_t seed_hi, uint32_t seed_lo, double n);
double *lab_estimate_table(void);
/* The final estimate, its standard error and the exact value in %.6f, and
 * the z score in %.2f, separated by spaces. */
const char *lab_estimate_line(void);

/* --- the own-warp box (lab/own.c) ------------------------------------------
 * A sampler written by the reader in JavaScript, judged as the exercises
 * judge theirs (ex_check_sampler_law) against a catalog row as the law
 * asked for. The page calls lab_own_prepare(seed, n), reads the 2 n
 * uniforms at lab_own_uniforms (PCG32, the stream mcbox_check_run hands a
 * sampler of two uniforms), writes the reader's n points (three doubles
 * each, unused coordinates 0) at lab_own_points and the reader's density at
 * each at lab_own_pdfs, then calls lab_own_check with the law's row on the
 * first line of the input buffer and its name on the second. The check
 * calls back into the page for the reader's pdf and invert (the module's
 * imports lab.pdf(x0, x1, x2) and lab.invert(x0, x1, x2, u), u a pointer to
 * two doubles). Three checks follow, k = 0, 1, 2: your points against your
 * density (chi-square, the density's integral, the round trip when
 * has_invert), your points against the law (your density at the samples
 * compared with the law's), your density against the law's on a grid.
 * lab_own_report(k) is "status\tname\tkey\tfigure\twhy\txlabel\tylabel",
 * status 0 pass, 1 fail, 2 could not run; lab_own_result(k) is status,
 * statistic, dof, p-value, level, integral, its error, round-trip error,
 * largest relative pdf difference, samples, outside, cells pooled, power
 * (relative error detected), then the chart: dims, nx, ny, lo0, hi0, lo1,
 * hi1 (NaN where a check has none; the grid check: status, points that
 * differ, points). Observed and expected counts of checks 0 and 1 as in
 * lab_observed. lab_own_prepare and lab_own_check return 1, or 0 for n
 * outside 1 .. LAB_OWN_MAX_SAMPLES, no memory, or an unknown row. */
#define LAB_OWN_MAX_SAMPLES 1000000
#define LAB_OWN_CHECKS 3
#define LAB_OWN_RESULT_COUNT 20
int lab_own_prepare(uint32_t seed_hi, uint32_t seed_lo, double n);
double *lab_own_uniforms(void);
double *lab_own_points(void);
double *lab_own_pdfs(void);
int lab_own_check(uint32_t seed_hi, uint32_t seed_lo, int has_invert);
const char *lab_own_report(int k);
double *lab_own_result(int k);
double *lab_own_observed(int k);
double *lab_own_expected(int k);

#endif /* LAB_LAB_H */
