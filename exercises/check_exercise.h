/* exercises/check_exercise.h - the judge every exercise shares.
 *
 * Serves every chapter that has an exercise (exercises/README.md has the
 * table). An exercise is one file, exercises/NAME.c: a statement, the
 * function(s) the reader writes, and a judge(), which calls the checks
 * below. The checks are mcbox's own: a sampler goes through the public
 * check API (check/check.h, installed as <mcbox/check.h>), an estimator
 * through a z-test against the exact value (mc/stats.h), a point set
 * through exact properties. main() lives in check_exercise.c; it prints
 * each check's figures and the verdict, and exits 0 (pass), 1 (fail) or 2
 * (the check could not run).
 *
 * Three builds of each exercise, chosen by a macro:
 *   (none)          the reader's code: the stub as shipped, or as edited;
 *   -DEX_REFERENCE  the stub replaced by the library's own implementation
 *                   (exercises/fixtures/NAME.h), which must pass;
 *   -DSLIP=k        the k-th classic wrong answer (same file), which must
 *                   fail: a negative control for the judge itself.
 *
 * False alarms. Every statistical test of every exercise runs at the Sidak
 * level that keeps the probability of one or more false rejections among
 * the EX_FAMILY statistical tests of all the reference rows of `make
 * exercises` at EX_ALPHA. The seeds are fixed, so the table is the same on
 * every run; `--seed S` draws another table (for soak runs).
 */
#ifndef EX_CHECK_EXERCISE_H
#define EX_CHECK_EXERCISE_H

#include <stdbool.h>
#include <stdint.h>

#include "check/check.h" /* installed as <mcbox/check.h> */
#include "mc/constants.h"
#include "mc/rng.h"
#include "mc/stats.h"
#include "mc/vec3.h"

/* The family-wise false-alarm rate of the whole table, and the number of
 * statistical tests it is shared over: the sum, over the exercises, of the
 * tests their reference build runs (exercises/run.sh adds them up and
 * fails when this number is stale). */
#define EX_ALPHA 0.01
#define EX_FAMILY 18

/* Which build this is; a fixture names its slip with EX_SLIP_NAME. */
#if defined(EX_REFERENCE) || defined(SLIP)
#define EX_FIXTURE 1
#endif

typedef struct ex_judge ex_judge;

/* What an exercise file defines, once, as `const ex_exercise ex_this`. */
typedef struct ex_exercise {
    const char *name;    /* "sphere": the file's name */
    const char *chapter; /* "3 (#ch-sphere)" */
    const char *variant; /* EX_VARIANT */
    void (*judge)(ex_judge *j);
} ex_exercise;
extern const ex_exercise ex_this;

#if defined(EX_REFERENCE)
#define EX_VARIANT "reference"
#elif defined(SLIP)
#define EX_VARIANT "slip " EX_STR(SLIP) ": " EX_SLIP_NAME
#else
#define EX_VARIANT "yours"
#endif
#define EX_STR(x) EX_STR_(x)
#define EX_STR_(x) #x

/* The seed a check uses: `base` (the number the exercise states), unless
 * the run was given --seed S, which replaces every base by a hash of
 * (S, base). */
uint64_t ex_seed(const ex_judge *j, uint64_t base);

/* The sample count a check uses: `n` (the number the exercise states),
 * unless the run was given --samples N. */
uint64_t ex_samples(const ex_judge *j, uint64_t n);

/* Runs the public check (mcbox_check_run) on s with `samples` samples from
 * `seed`, at the table's Sidak level; prints the statistic, degrees of
 * freedom, p-value, the density's integral, the round-trip error and the
 * reason of a failure; writes the observed-versus-expected picture when
 * the run was given --plot DIR. One statistical test. */
void ex_check_sampler(ex_judge *j, const char *what, const mcbox_sampler *s, uint64_t seed,
                      uint64_t samples);

/* The z-test of an estimate against the exact value: fails when the
 * two-sided p-value of z = (value - exact) / std_error is below the level,
 * or when the estimate or its error bar is not a finite number (a zero
 * error bar passes only with the exact value). One statistical test. */
void ex_check_estimate(ex_judge *j, const char *what, mc_estimate e, double exact, uint64_t seed);

/* The coverage of an error bar: `covered` of `runs` independent intervals
 * held the exact value where `nominal` of them should; a two-sided test of
 * the binomial count (normal approximation, runs * nominal * (1 - nominal)
 * >= 25 assumed). One statistical test. */
void ex_check_coverage(ex_judge *j, const char *what, uint64_t covered, uint64_t runs,
                       double nominal, uint64_t seed);

/* Pearson's chi-square of k independent standard normal scores whose sum
 * of squares is `sum_sq`: fails when P(chi2_k >= sum_sq) is below the
 * level. One statistical test. */
void ex_check_z_family(ex_judge *j, const char *what, double sum_sq, int k, uint64_t seed);

/* A property that holds exactly (or to a stated round-off) or does not:
 * `figure` (printf) says what was measured. Not a statistical test. */
void ex_check_exact(ex_judge *j, const char *what, bool ok, const char *figure, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* For helpers an exercise gives the reader, which a build may not call
 * (clang warns about unused static functions of the main file). */
#if defined(__GNUC__)
#define EX_MAYBE_UNUSED __attribute__((unused))
#else
#define EX_MAYBE_UNUSED
#endif

/* A direction exercise's functions: sample from two uniforms, the density
 * per unit solid angle, and the inverse (NULL when the exercise has
 * none). */
typedef struct ex_direction_fns {
    vec3 (*sample)(double u1, double u2);
    double (*pdf)(vec3 w);
    void (*invert)(vec3 w, double u[2]);
} ex_direction_fns;

/* A sampler of domain `kind` (a direction domain) over fns, which must
 * outlive it: the public check's callbacks for the three functions. */
mcbox_sampler ex_direction_sampler(mcbox_domain_kind kind, const ex_direction_fns *fns);

/* Conversions between the check API's coordinates and vec3. */
static inline vec3 ex_vec3(const double *x) { return vec3_make(x[0], x[1], x[2]); }
static inline void ex_put3(double *x, vec3 v) { x[0] = v.x, x[1] = v.y, x[2] = v.z; }

#endif /* EX_CHECK_EXERCISE_H */
