/* examples/common/cli.h - the command-line conventions of every mcbox
 * program, in one place.
 *
 * Programs (not the library) print and exit. This module parses options
 * from a table, answers --help and --version, and turns every bad input
 * into one line "prog: what is wrong" on stderr and exit status 2. It also
 * prints the result table every chapter program shares: a readable table by
 * default, or with --csv the header line then one row per method with the
 * columns method,n,estimate,stderr,exact,z (then any extra columns).
 */
#ifndef APP_CLI_H
#define APP_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "mc/stats.h"

#define APP_VERSION "0.1.0"

/* Largest accepted --samples: 10^13 keeps every 64-bit counter and every
 * double-precision sample index exact. */
#define APP_MAX_SAMPLES 10000000000000ULL

/* The one grammar of every count, seed and whole-number option, printed
 * by --help: digits (1000), hex after 0x (0x3e8), or a decimal number with
 * a fraction or an exponent that is a whole number (1e3, 2.5e3; at most
 * 2^53, past which a double no longer names one integer). No sign (a
 * minus only where the option takes negative values), no spaces, no
 * "inf" or "nan". */
#define APP_NUMBER_GRAMMAR                                                                    \
    "N, S, T and whole-number values: digits (1000), hex (0x3e8), or with an exponent or a\n" \
    "fraction that makes a whole number (1e3, 2.5e3; at most 2^53); no sign, no spaces."

typedef enum app_opt_kind {
    APP_FLAG,   /* bool *: set when present, takes no value */
    APP_COUNT,  /* uint64_t *: 1 .. APP_MAX_SAMPLES, APP_NUMBER_GRAMMAR */
    APP_SEED,   /* uint64_t *: 0 .. 2^64 - 1, APP_NUMBER_GRAMMAR */
    APP_INT,    /* int *: within [min, max], APP_NUMBER_GRAMMAR after an optional '-' */
    APP_DOUBLE, /* double *: finite, within [min, max] */
    APP_CHOICE, /* const char **: one of the NULL-terminated `choices` */
    APP_STRING  /* const char **: any non-empty string */
} app_opt_kind;

typedef struct app_opt {
    const char *name;           /* long name with the dashes: "--samples" */
    app_opt_kind kind;
    void *dest;                 /* where the value goes (type per kind) */
    const char *help;           /* one line for --help */
    const char *const *choices; /* APP_CHOICE only */
    double min, max;            /* APP_INT, APP_DOUBLE bounds */
} app_opt;

/* The option-table rows every chapter program shares, in one wording. */
#define APP_OPT_SEED(dest) {"--seed", APP_SEED, (dest), "random seed (default 1)", NULL, 0, 0}
#define APP_OPT_CSV(dest) {"--csv", APP_FLAG, (dest), "print CSV instead of a table", NULL, 0, 0}

/* True when `choice`, the value of a --method style option whose choices
 * end with "all", selects the row `name`: it is "all" or name itself. */
bool app_selected(const char *choice, const char *name);

/* Parses argv against opts[0..n). Handles --help (prints `usage` and the
 * option list to stdout, exits 0) and --version (exits 0). On any error
 * (unknown option, missing or malformed value, out of range) prints one line
 * "prog: ..." to stderr and exits 2. Positional arguments are not allowed
 * unless `positional` is not NULL: then they are stored there in order
 * (at most max_positional, else an error) and their count returned. */
int app_parse(const char *prog, const char *usage, int argc, char **argv, const app_opt *opts,
              size_t n, const char **positional, int max_positional);

/* For programs that parse their own argv (subcommands): the value of the
 * option argv[*i] whose name is len characters long, given as "--opt=v"
 * or "--opt v" (then *i moves past it). A missing value is "prog: --opt
 * needs a value" on stderr and exit 2. */
const char *app_option_value(const char *prog, int argc, char **argv, int *i, size_t len);

/* Parses a whole number in APP_NUMBER_GRAMMAR within [min, max]. Returns
 * false for anything else. */
bool app_parse_uint(const char *s, uint64_t min, uint64_t max, uint64_t *out);

/* A sample count: app_parse_uint within 1 .. max. */
bool app_parse_count(const char *s, uint64_t max, uint64_t *out);

/* A seed: app_parse_uint within 0 .. 2^64 - 1. */
bool app_parse_seed(const char *s, uint64_t *out);

/* The most OpenMP threads a --threads option accepts: 64 per processor,
 * or the OpenMP thread limit when lower. */
int app_max_threads(void);

/* Splits one --param value into its "key=value" assignments: blanks
 * separate them (commas belong to vectors, "axis=0,0,1 cos_max=0.9"), as
 * `warp list` prints a row's parameters. Each is copied into storage (size
 * bytes, NUL-separated) and pointed to from out[0 ..), at most max. Returns
 * the count (>= 1), or -1 with the reason in err: no assignment, a word
 * without a key or a value, too many, or storage too small. */
int app_split_assignments(const char *value, char *storage, size_t size, const char **out, int max,
                          char *err, size_t errlen);

/* Parses a finite double with nothing after it. */
bool app_parse_double(const char *s, double *out);

/* Runs estimated to take longer than this many seconds announce it. */
#define APP_ANNOUNCE_SECONDS 5.0

/* Says on stderr, before a run estimated to take `seconds` (more than
 * APP_ANNOUNCE_SECONDS), how long it will take and what it is:
 * "prog: about 2.3 h for what"; on a terminal a progress line follows
 * (ticker.h). `threads` is the --threads value (0: all)
 * that the estimate assumed. Silent for shorter runs. */
void app_announce(const char *prog, double seconds, const char *what);

/* app_announce for a chapter program that draws n samples per method,
 * about seconds_per_sample for one sample of every method together (the
 * programs measured theirs with --samples 1e6 on the project's machine:
 * an estimate, so runs near the bound may or may not announce). */
void app_announce_samples(const char *prog, uint64_t n, double seconds_per_sample);

/* The number of threads a --threads value of `threads` runs (0: all). */
int app_threads_used(int threads);

/* Prints "prog: message" to stderr and exits with status 2. */
_Noreturn void app_fail(const char *prog, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The shared result table. extra_cols (may be NULL) names columns printed
 * after z. */
typedef struct app_table {
    FILE *out;
    bool csv;
    const char *const *extra_cols;
    size_t n_extra;
    const char *prog; /* may be NULL; with csv, names the program in the
                       * stderr note of a row whose stderr is n/a */
} app_table;

/* Prints the header (CSV header line, or the table's title row). */
void app_table_begin(const app_table *t);

/* Why the standard error (and so z) of e cannot be estimated, or NULL
 * when it can: fewer than 2 samples; a std_error of NaN (the estimator's
 * way of saying so, e.g. an image with pixels of one sample); or a sample
 * variance of 0 with an estimate that is not the exact value, which only
 * too few samples produce (a zero-variance estimator hits the exact value
 * up to rounding). */
const char *app_no_stderr_reason(mc_estimate e, double exact);

/* Prints one row: method, e.n, e.value, e.std_error, exact (NaN: unknown,
 * printed empty), z = (value - exact) / std_error (empty when exact is
 * unknown or std_error is 0), then extra[0..n_extra). A standard error
 * that cannot be estimated (app_no_stderr_reason) is printed as "n/a",
 * z too, and the reason after the row; in CSV both fields are empty and
 * the reason goes to stderr as "prog: method: stderr and z n/a: why"
 * when t->prog is set. */
void app_table_row(const app_table *t, const char *method, mc_estimate e, double exact,
                   const double *extra);

#endif /* APP_CLI_H */
