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
 * Builds of each exercise, chosen by a macro:
 *   (none)          the reader's code: the stub as shipped, or as edited;
 *   -DEX_REFERENCE  the stub replaced by the library's own implementation
 *                   (exercises/fixtures/NAME.h), which must pass;
 *   -DSLIP=k        the k-th classic wrong answer (same file), which must
 *                   fail, and fail the check it names (EX_SLIP_CHECK): a
 *                   negative control for the judge itself. A CONSISTENT
 *                   slip is one whose parts agree with each other (a
 *                   sampler and the density it really has): only a check
 *                   that knows the law the exercise asks for can catch it;
 *   -DALT=k         the k-th correct answer written differently from the
 *                   library's (another valid map, another formula), which
 *                   must pass: the judge must not demand one way of
 *                   writing the answer where the statement allows several.
 *
 * What a pass means. A sampler exercise is judged three ways: the reader's
 * points against the reader's own density (the consistency a renderer
 * needs: it divides by that density), the same points against the law the
 * exercise asks for (the reference density, with the reader's density
 * compared with it at every sample), and the reader's density against the
 * reference on a grid over the whole domain. The first alone would pass
 * the right machinery aimed at the wrong law. An estimator exercise is
 * judged on its value and error bar and on the variance of one sample,
 * which tells the sampling scheme asked for from another unbiased one.
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
#define EX_FAMILY 32

/* Which build this is. A fixture names a slip with EX_SLIP_NAME, says
 * whether its parts agree with each other with EX_SLIP_KIND
 * (EX_CONSISTENT or EX_INCONSISTENT) and names the check it must fail
 * with EX_SLIP_CHECK (a check's id, below); it names a correct
 * alternative with EX_ALT_NAME. */
#if defined(EX_REFERENCE) || defined(SLIP) || defined(ALT)
#define EX_FIXTURE 1
#endif
#define EX_CONSISTENT "consistent"
#define EX_INCONSISTENT "inconsistent"

typedef struct ex_judge ex_judge;

/* What an exercise file defines, once, as `const ex_exercise ex_this`:
 * {name, chapter, EX_VARIANT, judge, EX_KIND, EX_INTENDED}. */
typedef struct ex_exercise {
    const char *name;     /* "sphere": the file's name */
    const char *chapter;  /* "3 (#ch-sphere)" */
    const char *variant;  /* EX_VARIANT */
    void (*judge)(ex_judge *j);
    const char *kind;     /* EX_KIND: "yours", "reference", "alternative", or a slip's
                             EX_CONSISTENT / EX_INCONSISTENT */
    const char *intended; /* EX_INTENDED: the id of the check a slip must fail, else NULL */
} ex_exercise;
extern const ex_exercise ex_this;

#if defined(EX_REFERENCE)
#define EX_VARIANT "reference"
#define EX_KIND "reference"
#define EX_INTENDED NULL
#elif defined(SLIP)
#define EX_VARIANT "slip " EX_STR(SLIP) " (" EX_SLIP_KIND "): " EX_SLIP_NAME
#define EX_KIND EX_SLIP_KIND
#define EX_INTENDED EX_SLIP_CHECK
#elif defined(ALT)
#define EX_VARIANT "alternative " EX_STR(ALT) ": " EX_ALT_NAME
#define EX_KIND "alternative"
#define EX_INTENDED NULL
#else
#define EX_VARIANT "yours"
#define EX_KIND "yours"
#define EX_INTENDED NULL
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

/* Every check below has an `id`, a short name a slip's EX_SLIP_CHECK
 * refers to ("law", "z-test", ...), and a `what`, the line the reader
 * reads. Checks of the same id in one exercise count as one for a slip:
 * it must fail at least one of them. */

/* The law an exercise asks for: the reference density, per unit of the
 * same measure as the sampler's (thread-safe: the quadrature calls it from
 * several threads), and its name as the reader's messages say it ("the
 * cosine law"). */
typedef struct ex_law {
    const char *name;
    double (*pdf)(const double *x, void *ctx);
    void *ctx;
} ex_law;

/* The three judgements of a sampler exercise, each a check of its own:
 *   "consistent": the public check (mcbox_check_run) of s as it is: the
 *     points against the reader's density (s->pdf), the density's integral,
 *     the round trip when s has an inverse, the domain;
 *   "law": the same points (same seed) against law->pdf instead, with the
 *     reader's density reported at every sample (mcbox_sample.pdf) and
 *     compared with the law's (relative 1e-6): the intended law pinned;
 *   "density": the reader's density against the law's at the centres of a
 *     grid over the domain (64 x 128 in (cos theta, phi) for directions,
 *     128 x 128 over [-1, 1]^2 for the disc, 1024 cells of an interval),
 *     relative 1e-6, exactly 0 where the law is 0. Not statistical.
 * Each check prints its statistic, degrees of freedom, p-value, the
 * density's integral, the round-trip error and the reason of a failure,
 * and writes its observed-versus-expected picture when the run was given
 * --plot DIR. Two statistical tests. */
void ex_check_sampler_law(ex_judge *j, const char *what, const mcbox_sampler *s,
                          const ex_law *law, uint64_t seed, uint64_t samples);

/* The z-test of an estimate against the exact value: fails when the
 * two-sided p-value of z = (value - exact) / std_error is below the level,
 * or when the estimate or its error bar is not a finite number (a zero
 * error bar passes only with the exact value). One statistical test. */
void ex_check_estimate(ex_judge *j, const char *id, const char *what, mc_estimate e,
                       double exact, uint64_t seed);

/* The law of an estimator: the variance of one sample that e reports
 * against sigma2, that of the sampling scheme the exercise asks for
 * (`scheme`, for the message). The sample variance of n samples is nearly
 * normal with variance (mu4 - sigma2^2) / n, mu4 the fourth central moment
 * of one sample; fails when the two-sided p-value of that z is below the
 * level. An unbiased estimator drawn from another density passes the
 * z-test and the coverage and fails this. One statistical test. */
void ex_check_variance(ex_judge *j, const char *id, const char *what, mc_estimate e,
                       double sigma2, double mu4, const char *scheme, uint64_t seed);

/* The coverage of an error bar: `covered` of `runs` independent intervals
 * held the exact value where `nominal` of them should; a two-sided test of
 * the binomial count (normal approximation, runs * nominal * (1 - nominal)
 * >= 25 assumed). One statistical test. */
void ex_check_coverage(ex_judge *j, const char *id, const char *what, uint64_t covered,
                       uint64_t runs, double nominal, uint64_t seed);

/* Pearson's chi-square of k independent standard normal scores whose sum
 * of squares is `sum_sq`: fails when P(chi2_k >= sum_sq) is below the
 * level. One statistical test. */
void ex_check_z_family(ex_judge *j, const char *id, const char *what, double sum_sq, int k,
                       uint64_t seed);

/* A property that holds exactly (or to a stated round-off) or does not:
 * `figure` (printf) says what was measured. Not a statistical test. */
void ex_check_exact(ex_judge *j, const char *id, const char *what, bool ok, const char *figure,
                    ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
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
