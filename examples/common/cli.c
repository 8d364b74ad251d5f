/* examples/common/cli.c - option parsing, errors, the result table. */
#include "examples/common/cli.h"

#include "examples/common/ticker.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

_Noreturn void app_fail(const char *prog, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(2);
}

bool app_selected(const char *choice, const char *name)
{
    return strcmp(choice, "all") == 0 || strcmp(choice, name) == 0;
}

bool app_parse_double(const char *s, double *out)
{
    /* strtod would skip leading spaces: " 5" is not a number here. */
    if (!s || !*s || isspace((unsigned char)*s))
        return false;
    char *end = NULL;
    errno = 0;
    double v = strtod(s, &end);
    if (errno == ERANGE || *end || end == s || !isfinite(v))
        return false;
    *out = v;
    return true;
}

bool app_parse_uint(const char *s, uint64_t min, uint64_t max, uint64_t *out)
{
    /* No sign and nothing before the first digit: strtoull skips spaces
     * and accepts a sign, so " -1" would wrap to 2^64 - 1; strtod would
     * take "inf", "nan" and ".5". */
    if (!s || !isdigit((unsigned char)*s))
        return false;
    bool hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    size_t digits = hex ? 2 : 0;
    while (hex ? isxdigit((unsigned char)s[digits]) : isdigit((unsigned char)s[digits]))
        digits++;
    uint64_t v;
    if (s[digits] == '\0' && !(hex && digits == 2)) {
        /* Plain digits or hex: every 64-bit value exactly (never octal:
         * base 0 would read "010" as 8). */
        char *end = NULL;
        errno = 0;
        unsigned long long u = strtoull(s, &end, hex ? 16 : 10);
        if (errno || *end)
            return false;
        v = (uint64_t)u;
    } else {
        /* A fraction or an exponent: "1e6", "2.5e3". Only whole numbers up
         * to 2^53, beyond which a double no longer names one integer. */
        double d;
        if (hex || !app_parse_double(s, &d) || d != floor(d) || d > 9007199254740992.0)
            return false;
        v = (uint64_t)d;
    }
    if (v < min || v > max)
        return false;
    *out = v;
    return true;
}

bool app_parse_count(const char *s, uint64_t max, uint64_t *out)
{
    return app_parse_uint(s, 1, max, out);
}

bool app_parse_seed(const char *s, uint64_t *out)
{
    return app_parse_uint(s, 0, UINT64_MAX, out);
}

int app_max_threads(void)
{
    /* More threads than this only queue for the processors, and each one
     * reserves a stack: thousands of them can fail inside the OpenMP
     * runtime, after the program has started printing. */
    int procs = omp_get_num_procs(), limit = omp_get_thread_limit();
    long most = 64L * (procs > 0 ? procs : 1);
    return (int)(most < limit ? most : limit);
}

int app_threads_used(int threads)
{
    int procs = omp_get_num_procs(), t = threads > 0 ? threads : omp_get_max_threads();
    /* More threads than processors run no faster. */
    return t < procs ? (t > 0 ? t : 1) : (procs > 0 ? procs : 1);
}

void app_announce(const char *prog, double seconds, const char *what)
{
    if (!(seconds > APP_ANNOUNCE_SECONDS))
        return;
    static const struct {
        double s;
        const char *unit;
    } units[] = {{86400.0, "days"}, {3600.0, "h"}, {60.0, "min"}, {1.0, "s"}};
    size_t k = 0;
    while (k + 1 < sizeof units / sizeof units[0] && seconds < 2.0 * units[k].s)
        k++;
    fprintf(stderr, "%s: about %.2g %s for %s\n", prog, seconds / units[k].s, units[k].unit, what);
    fflush(stderr);
    app_ticker_start(prog, seconds);
}

void app_announce_samples(const char *prog, uint64_t n, double seconds_per_sample)
{
    char what[96];
    snprintf(what, sizeof what, "%.3g samples per method, one thread", (double)n);
    app_announce(prog, (double)n * seconds_per_sample, what);
}

static void print_help(const char *usage, const app_opt *opts, size_t n)
{
    printf("usage: %s\n\n", usage);
    bool numbers = false;
    for (size_t i = 0; i < n; i++) {
        const app_opt *o = &opts[i];
        const char *arg = o->kind == APP_FLAG ? "" : (o->kind == APP_COUNT ? " N" : " VALUE");
        numbers |= o->kind == APP_COUNT || o->kind == APP_SEED || o->kind == APP_INT;
        printf("  %s%s\n      %s", o->name, arg, o->help);
        if (o->kind == APP_CHOICE) {
            printf("; one of ");
            for (const char *const *c = o->choices; *c; c++)
                printf("%s%s", *c, c[1] ? "|" : "");
        }
        printf("\n");
    }
    printf("  --help\n      print this help and exit\n  --version\n      print the version and exit\n");
    if (numbers)
        printf("\n%s\n", APP_NUMBER_GRAMMAR);
}

static void set_value(const char *prog, const app_opt *o, const char *v)
{
    switch (o->kind) {
    case APP_FLAG:
        *(bool *)o->dest = true;
        return;
    case APP_COUNT:
        if (!app_parse_count(v, APP_MAX_SAMPLES, o->dest))
            app_fail(prog, "%s: '%s' is not a whole number from 1 to 1e13", o->name, v);
        return;
    case APP_SEED:
        if (!app_parse_seed(v, o->dest))
            app_fail(prog, "%s: '%s' is not a whole number from 0 to 2^64 - 1", o->name, v);
        return;
    case APP_INT: {
        /* The grammar of counts, after an optional minus sign. */
        uint64_t u;
        bool neg = v[0] == '-';
        double d = app_parse_uint(v + neg, 0, UINT64_MAX, &u) ? (neg ? -(double)u : (double)u) : (double)NAN;
        if (!(d >= o->min && d <= o->max))
            app_fail(prog, "%s: '%s' is not a whole number from %g to %g", o->name, v, o->min, o->max);
        *(int *)o->dest = (int)d;
        return;
    }
    case APP_DOUBLE: {
        double d;
        if (!app_parse_double(v, &d) || d < o->min || d > o->max)
            app_fail(prog, "%s: '%s' is not a number from %g to %g", o->name, v, o->min, o->max);
        *(double *)o->dest = d;
        return;
    }
    case APP_CHOICE:
        for (const char *const *c = o->choices; *c; c++) {
            if (strcmp(*c, v) == 0) {
                *(const char **)o->dest = *c;
                return;
            }
        }
        app_fail(prog, "%s: unknown value '%s'", o->name, v);
    case APP_STRING:
        if (!*v)
            app_fail(prog, "%s: empty value", o->name);
        *(const char **)o->dest = v;
        return;
    }
}

int app_parse(const char *prog, const char *usage, int argc, char **argv, const app_opt *opts,
              size_t n, const char **positional, int max_positional)
{
    int npos = 0;
    /* Where the options given so far store their values: an option given
     * twice (or with its synonym, which shares the destination) is an
     * error, not a silent "the last one wins". */
    const void *seen[64];
    size_t n_seen = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            print_help(usage, opts, n);
            exit(0);
        }
        if (strcmp(a, "--version") == 0) {
            printf("%s (mcbox) %s\n", prog, APP_VERSION);
            exit(0);
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (!positional || npos >= max_positional)
                app_fail(prog, "unexpected argument '%s' (see --help)", a);
            positional[npos++] = a;
            continue;
        }
        /* Accept both "--name value" and "--name=value". */
        const char *eq = strchr(a, '=');
        size_t len = eq ? (size_t)(eq - a) : strlen(a);
        const app_opt *o = NULL;
        for (size_t k = 0; k < n; k++)
            if (strlen(opts[k].name) == len && strncmp(opts[k].name, a, len) == 0)
                o = &opts[k];
        if (!o)
            app_fail(prog, "unknown option '%.*s' (see --help)", (int)len, a);
        if (o->kind == APP_FLAG) {
            if (eq)
                app_fail(prog, "%s takes no value", o->name);
            set_value(prog, o, NULL);
        } else {
            const char *v = eq ? eq + 1 : (i + 1 < argc ? argv[++i] : NULL);
            if (!v)
                app_fail(prog, "%s needs a value", o->name);
            set_value(prog, o, v);
        }
        for (size_t k = 0; k < n_seen; k++)
            if (seen[k] == o->dest)
                app_fail(prog, "%s given twice (or with its synonym)", o->name);
        if (n_seen < sizeof seen / sizeof seen[0])
            seen[n_seen++] = o->dest;
    }
    return npos;
}

void app_table_begin(const app_table *t)
{
    if (t->csv) {
        fprintf(t->out, "method,n,estimate,stderr,exact,z");
        for (size_t i = 0; i < t->n_extra; i++)
            fprintf(t->out, ",%s", t->extra_cols[i]);
    } else {
        fprintf(t->out, "%-14s %14s %18s %12s %18s %8s", "method", "n", "estimate", "stderr", "exact", "z");
        for (size_t i = 0; i < t->n_extra; i++)
            fprintf(t->out, " %14s", t->extra_cols[i]);
    }
    fputc('\n', t->out);
}

const char *app_no_stderr_reason(mc_estimate e, double exact)
{
    if (e.n < 2)
        return "fewer than 2 samples";
    if (isnan(e.std_error))
        return "fewer than 2 samples in some pixels or cells";
    /* Every sample gave the same value, yet the estimate is not the exact
     * value: the sample variance of 0 is an artefact of too few samples
     * (all of them missed the light), not a zero-variance estimator, whose
     * estimate equals the exact value up to rounding. */
    if (e.std_error == 0.0 && !isnan(exact) &&
        fabs(e.value - exact) > 1e-12 * fmax(fabs(exact), 1e-300))
        return "all samples equal: too few to estimate the variance";
    return NULL;
}

void app_table_row(const app_table *t, const char *method, mc_estimate e, double exact,
                   const double *extra)
{
    bool has_exact = !isnan(exact);
    const char *why = app_no_stderr_reason(e, exact);
    bool has_se = why == NULL;
    bool has_z = has_exact && has_se && e.std_error > 0.0;
    double z = has_z ? mc_z_score(e.value, exact, e.std_error) : 0.0;
    if (t->csv) {
        fprintf(t->out, "%s,%llu,%.17g,", method, (unsigned long long)e.n, e.value);
        if (has_se)
            fprintf(t->out, "%.17g", e.std_error);
        fputc(',', t->out);
        if (has_exact)
            fprintf(t->out, "%.17g", exact);
        fputc(',', t->out);
        if (has_z)
            fprintf(t->out, "%.6g", z);
        for (size_t i = 0; i < t->n_extra; i++)
            fprintf(t->out, ",%.17g", extra[i]);
        /* The CSV columns are fixed; the reason goes to stderr. */
        if (why && t->prog)
            fprintf(stderr, "%s: %s: stderr and z n/a: %s\n", t->prog, method, why);
    } else {
        fprintf(t->out, "%-14s %14llu %18.12f ", method, (unsigned long long)e.n, e.value);
        if (has_se)
            fprintf(t->out, "%12.3e ", e.std_error);
        else
            fprintf(t->out, "%12s ", "n/a");
        if (has_exact)
            fprintf(t->out, "%18.12f ", exact);
        else
            fprintf(t->out, "%18s ", "-");
        if (has_z)
            fprintf(t->out, "%8.3f", z);
        else
            fprintf(t->out, "%8s", why && has_exact ? "n/a" : "-");
        for (size_t i = 0; i < t->n_extra; i++)
            fprintf(t->out, " %14.6g", extra[i]);
        if (why)
            fprintf(t->out, "  (stderr n/a: %s)", why);
    }
    fputc('\n', t->out);
}

const char *app_option_value(const char *prog, int argc, char **argv, int *i, size_t len)
{
    if (argv[*i][len] == '=')
        return argv[*i] + len + 1;
    if (*i + 1 >= argc)
        app_fail(prog, "%s needs a value", argv[*i]);
    return argv[++*i];
}

int app_split_assignments(const char *value, char *storage, size_t size, const char **out, int max,
                          char *err, size_t errlen)
{
    int n = 0;
    size_t used = 0;
    for (const char *p = value;;) {
        while (*p == ' ' || *p == '\t')
            p++;
        if (!*p)
            break;
        size_t len = strcspn(p, " \t");
        const char *eq = memchr(p, '=', len);
        if (!eq || eq == p || eq == p + len - 1) {
            snprintf(err, errlen, "'%.*s' is not key=value", (int)(len < 100 ? len : 100), p);
            return -1;
        }
        if (n == max || used + len + 1 > size) {
            snprintf(err, errlen, "more than %d assignments, or longer than %zu bytes", max, size);
            return -1;
        }
        memcpy(storage + used, p, len);
        storage[used + len] = '\0';
        out[n++] = storage + used;
        used += len + 1;
        p += len;
    }
    if (n == 0)
        snprintf(err, errlen, "no key=value assignment");
    return n ? n : -1;
}
