/* tests/support/mc_test.h - what every mcbox test program shares.
 *
 * Include after <cmocka.h>'s prerequisites; this header includes them.
 * Seeds: every statistical test takes its seed from mc_test_seed(default).
 * With MC_TEST_SEED=S in the environment each default d is replaced by a
 * seed derived from (S, d), so a soak run over many S measures the suite's
 * false-alarm rate while tests stay independent of one another.
 */
#ifndef MC_TEST_H
#define MC_TEST_H

#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* The seed a statistical test uses: default_seed, or derived from
 * $MC_TEST_SEED when that is set. */
uint64_t mc_test_seed(uint64_t default_seed);

/* Fails the test unless |a - b| <= tol (doubles; cmocka 1.1.5's
 * assert_float_equal casts to float). NaN never passes. */
#define assert_near(a, b, tol) mc_assert_near_impl((a), (b), (tol), #a, #b, __FILE__, __LINE__)
void mc_assert_near_impl(double a, double b, double tol, const char *sa, const char *sb,
                         const char *file, int line);

/* The z-test every estimator test uses: fails unless
 * |estimate - exact| / std_error < threshold, printing the label, the
 * numbers and the seed. Threshold 4 has a two-sided false-alarm rate of
 * 6.3e-5 per test for a normal statistic. */
#define assert_z_below(label, estimate, exact, std_error, threshold, seed)                          \
    mc_assert_z_impl((label), (estimate), (exact), (std_error), (threshold), (seed), __FILE__, __LINE__)
void mc_assert_z_impl(const char *label, double estimate, double exact, double std_error,
                      double threshold, uint64_t seed, const char *file, int line);

/* assert_true for a statistical check that is not a z-test (a comparison
 * of error sums, a chi-square verdict, a negative control's catch): fails
 * unless cond holds, printing the condition and the seed of its data.
 * Where the check pools several seeds, seed is the first of them. */
#define assert_seeded(cond, seed) mc_assert_seeded_impl((cond), #cond, (seed), __FILE__, __LINE__)
void mc_assert_seeded_impl(bool cond, const char *scond, uint64_t seed, const char *file, int line);

/* Reads the file at path into buf (size bytes, at least 1) as a string,
 * cut to size - 1 bytes; fails the test if the file cannot be opened.
 * Returns the number of bytes read. */
size_t mc_test_read_text(const char *path, char *buf, size_t size);

/* The directory holding the build under test ($MC_BUILD, default "build"). */
const char *mc_test_build_dir(void);

/* The source tree ($MC_SOURCE, default the current directory, "."). */
const char *mc_test_source_dir(void);

/* With MC_TEST_ONLY=PATTERN in the environment, only the tests whose names
 * match PATTERN (cmocka's wildcards * and ?) run: the book shows one test
 * of a long program. Call before cmocka_run_group_tests. */
void mc_test_select(void);

/* Whether the n = 2^m points (x[i], y[i]) (32-bit fractions), m <= 12,
 * are a (0,m,2)-net in base 2: every elementary interval of area 2^-m,
 * of shape 2^-a by 2^-(m-a), holds exactly one point. Each 1D projection
 * is then stratified too (a = m and a = 0). */
bool mc_test_is_02_net(const uint32_t *x, const uint32_t *y, unsigned m);

/* Whether the n = 2^m values v[i] (32-bit fractions), m <= 12, put one in
 * each interval of length 2^-m: a stratified 1D set. */
bool mc_test_strata_once(const uint32_t *v, unsigned m);

#endif /* MC_TEST_H */
