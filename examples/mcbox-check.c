/* examples/mcbox-check.c - the command-line door of mcbox/check.h: test a
 * sampler written in any language against its density (chapter 5,
 * Generating Random Directions, and every sampler after it).
 *
 *   mcbox-check --exec CMD --domain D [...]   the sampler and its density
 *       are a program that speaks docs/check-protocol.md on stdin/stdout
 *   mcbox-check --samples FILE --pdf NAME     points from a file, the density
 *       of a catalog row (warp list)
 *   mcbox-check --samples FILE --pdf-exec CMD --domain D   the density from
 *       a program
 *
 * The uniforms are those mcbox_check_run would give an in-process sampler
 * (mcbox_check_uniforms), so a program and a C callback of the same warp
 * get the same statistic. Exit 0 pass, 1 fail, 2 bad input, or a program
 * that broke the protocol (then it is killed and reaped, and no verdict is
 * printed: never one from half the data).
 *
 * Build and run:  make all
 *   build/bin/mcbox-check --exec 'build/bin/warp serve cosine' --domain hemisphere
 *   build/bin/warp sample cosine --n 1e5 | build/bin/mcbox-check --samples - --pdf cosine
 */
#define _POSIX_C_SOURCE 200809L /* fork, poll, kill, waitpid, strsignal */

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "examples/common/cli.h"
#include "examples/common/exec_proto.h"
#include "examples/common/outfile.h"
#include "examples/common/sample_reader.h"

#define PROG "mcbox-check"
#define MAX_PARAMS 16
#define MAX_ATOMS 64
#define BATCH APP_PROTO_MAX_BATCH
/* Bytes of a program's stderr kept for the message when it fails. */
#define TAIL 1024

static const char USAGE[] =
    "usage: mcbox-check --exec CMD --domain D [options]\n"
    "       mcbox-check --samples FILE|- --pdf NAME [--param k=v]... [options]\n"
    "       mcbox-check --samples FILE|- --pdf-exec CMD --domain D [options]\n"
    "Tests a sampler's points against its density: Pearson's chi-square test on the\n"
    "domain's chart, with normalization, domain, pdf-consistency and inverse checks.\n"
    "Exit status 0 pass, 1 fail, 2 bad input or a program that broke the protocol\n"
    "(one line on stderr, nothing on stdout). Protocol: docs/check-protocol.md.\n"
    "The sampler and its density:\n"
    "  --exec CMD         a program run with /bin/sh -c CMD: samples from mcbox's uniforms\n"
    "                     (or its own generator) and its density, over pipes\n"
    "  --samples FILE     the points of FILE (- for stdin), one sample per line\n"
    "  --format F         csv (default; numbers separated by spaces, tabs or commas), f32 or\n"
    "                     f64 (raw little-endian records)\n"
    "  --pdf NAME         the density of a catalog row (see warp list) for --samples\n"
    "  --pdf-exec CMD     the density from a program (the protocol's pdf command)\n"
    "  --param k=v        a parameter of the --pdf row or of a catalog --domain (repeatable)\n"
    "  --domain D         interval, square, disc, triangle, sphere, hemisphere, or a row\n"
    "                     of the catalog (warp list)\n"
    "  --interval A,B     the interval's ends (default 0,1)\n"
    "  --uniforms K       uniforms per sample, 0 to 16 (default 2, 1 for an interval, the\n"
    "                     row's own for a catalog row);\n"
    "                     0: the program draws from its own generator\n"
    "  --invert           also check the program's inverse: invert(sample(u)) = u\n"
    "  --atom 'x,y,z:m'   a discrete atom at that point with probability m (repeatable)\n"
    "  --timeout SEC      the longest wait for the program (default 60)\n"
    "The check:\n"
    "  --n N              samples (default 1e6 for --exec; for --samples the file's, or\n"
    "                     its first N)\n"
    "  --seed S           seed of the uniforms (default 1)\n"
    "  --alpha A          family-wise significance level, in (0, 1) (default 0.01)\n"
    "  --tests M          tests the level is shared over (Sidak; default 1)\n"
    "  --cells NXxNY      histogram cells (NX for an interval; default the chart's)\n"
    "  --lobe-width W     sphere, hemisphere: histogram theta / (theta + W) about +z\n"
    "Reports:\n"
    "  --name NAME        the sampler's name in reports (letters, digits, . _ -)\n"
    "  --json             print the whole result as one JSON object instead of the summary\n"
    "  --junit FILE       write a JUnit XML test suite of one test case\n"
    "  --plot DIR         write DIR/NAME.png (gnuplot) and DIR/NAME.dat: observed and\n"
    "                     expected counts, and (observed - expected) / sqrt(expected)\n"
    "  --help, --version\n" APP_NUMBER_GRAMMAR "\n";

typedef struct args {
    const char *exec, *samples, *pdf, *pdf_exec, *domain, *interval, *name, *junit, *plot;
    const char *params[MAX_PARAMS], *atoms[MAX_ATOMS];
    int n_params, n_atoms;
    app_samples_format format;
    int uniforms;
    bool have_uniforms, have_n, have_seed, have_format, have_timeout, invert, json;
    uint64_t n;
    double timeout;
    mcbox_check_options o;
} args;

/* The child process that speaks the protocol. */
typedef struct child {
    const char *cmd;
    pid_t pid;             /* 0: none, or reaped */
    int in, out, err;      /* our ends of its stdin, stdout, stderr (-1: closed) */
    char rbuf[1 << 16];    /* its stdout, read but not yet split into lines */
    size_t rpos, rlen;
    char line[APP_PROTO_MAX_LINE + 1];
    size_t line_len;
    char tail[TAIL];       /* the end of its stderr */
    size_t tail_len;
    int status;            /* waitpid's, once reaped */
    bool reaped;
} child;

typedef struct app {
    args a;
    mcbox_sampler s;
    int dims;
    char domain_word[64]; /* DOMAIN of hello */
    char params[1024];    /* the --param assignments, "k=v k=v" */
    child ch;
    bool have_child;
    app_outfile junit;
    bool junit_open;
    char *text;           /* a command's text */
    size_t text_cap;
    uint64_t batch;       /* commands sent after hello */
    char where[160];      /* the command being answered, for messages */
    /* invert answers of the current batch, looked up by point */
    double inv_x[BATCH * 3], inv_u[BATCH * MCBOX_MAX_UNIFORMS];
    size_t inv_n, inv_at;
    double atom_x[MAX_ATOMS * 3], atom_mass[MAX_ATOMS];
    cat_state *row_state; /* --pdf: the row's density */
    /* where the answers of the exchange under way go */
    mcbox_sample *ans_smp;
    double *ans_vals;
    int ans_count;
    /* --samples: the file's points */
    mcbox_sample *points;
    uint64_t n_points;
} app;

/* --- options ------------------------------------------------------------ */

/* Stores the value of a string option given at most once. */
static void once(const char **dest, const char *v, const char *name)
{
    if (*dest)
        app_fail(PROG, "%s given twice", name);
    if (!*v)
        app_fail(PROG, "%s: empty value", name);
    *dest = v;
}

static void parse_cells(const char *v, int cells[2])
{
    const char *x = strchr(v, 'x');
    char first[64];
    uint64_t a = 0, b = 0;
    size_t len = x ? (size_t)(x - v) : strlen(v);
    bool ok = len < sizeof first;
    if (ok) {
        memcpy(first, v, len);
        first[len] = '\0';
        ok = app_parse_uint(first, 1, 4096, &a) && (!x || app_parse_uint(x + 1, 1, 4096, &b));
    }
    if (!ok)
        app_fail(PROG, "--cells: '%s' is not NX or NXxNY with whole numbers from 1 to 4096", v);
    cells[0] = (int)a, cells[1] = (int)b;
}

static void parse_option(args *a, int argc, char **argv, int *i, bool *seen_alpha, bool *seen)
{
    static const char *const strings[] = {"--exec", "--samples", "--pdf", "--pdf-exec", "--domain",
                                          "--interval", "--name", "--junit", "--plot"};
    const char *s = argv[*i];
    size_t len = strcspn(s, "=");
    const char **dest[] = {&a->exec, &a->samples, &a->pdf, &a->pdf_exec, &a->domain,
                           &a->interval, &a->name, &a->junit, &a->plot};
    for (size_t k = 0; k < sizeof strings / sizeof strings[0]; k++)
        if (strlen(strings[k]) == len && strncmp(s, strings[k], len) == 0) {
            once(dest[k], app_option_value(PROG, argc, argv, i, len), strings[k]);
            return;
        }
#define IS(name) (len == strlen(name) && strncmp(s, name, len) == 0)
#define ONCE(flag, name)                                                                           \
    do {                                                                                           \
        if (flag)                                                                                  \
            app_fail(PROG, "%s given twice", name);                                                \
        flag = true;                                                                               \
    } while (0)
    if (IS("--invert") || IS("--json")) {
        if (s[len] == '=')
            app_fail(PROG, "%.*s takes no value", (int)len, s);
        bool *f = IS("--invert") ? &a->invert : &a->json;
        ONCE(*f, s);
        return;
    }
    const char *v = NULL;
    if (IS("--param") || IS("--atom")) {
        bool param = IS("--param");
        v = app_option_value(PROG, argc, argv, i, len);
        if (!*v)
            app_fail(PROG, "%s: empty value", param ? "--param" : "--atom");
        if (param ? a->n_params == MAX_PARAMS : a->n_atoms == MAX_ATOMS)
            app_fail(PROG, "more than %d %s options", param ? MAX_PARAMS : MAX_ATOMS,
                     param ? "--param" : "--atom");
        if (param)
            a->params[a->n_params++] = v;
        else
            a->atoms[a->n_atoms++] = v;
        return;
    }
    static const char *const valued[] = {"--format", "--uniforms", "--timeout", "--n", "--seed",
                                         "--alpha", "--tests", "--cells", "--lobe-width"};
    int which = -1;
    for (int k = 0; k < 9; k++)
        if (IS(valued[k]))
            which = k;
    if (which < 0) {
        if (s[0] == '-' && s[1] != '\0')
            app_fail(PROG, "unknown option '%.*s' (see --help)", (int)len, s);
        app_fail(PROG, "unexpected argument '%s' (see --help)", s);
    }
    v = app_option_value(PROG, argc, argv, i, len);
    ONCE(seen[which], valued[which]);
    uint64_t u;
    double d;
    switch (which) {
    case 0:
        if (!app_samples_format_parse(v, &a->format))
            app_fail(PROG, "--format: '%s' is not csv, f32 or f64", v);
        a->have_format = true;
        break;
    case 1:
        if (!app_parse_uint(v, 0, MCBOX_MAX_UNIFORMS, &u))
            app_fail(PROG, "--uniforms: '%s' is not a whole number from 0 to %d", v,
                     MCBOX_MAX_UNIFORMS);
        a->uniforms = (int)u, a->have_uniforms = true;
        break;
    case 2:
        if (!app_parse_double(v, &a->timeout) || !(a->timeout > 0.0 && a->timeout <= 1e6))
            app_fail(PROG, "--timeout: '%s' is not a number of seconds in (0, 1e6]", v);
        a->have_timeout = true;
        break;
    case 3:
        if (!app_parse_count(v, APP_MAX_SAMPLES, &a->n))
            app_fail(PROG, "--n: '%s' is not a whole number from 1 to 1e13", v);
        a->have_n = true;
        break;
    case 4:
        if (!app_parse_seed(v, &a->o.seed))
            app_fail(PROG, "--seed: '%s' is not a whole number from 0 to 2^64 - 1", v);
        a->have_seed = true;
        break;
    case 5:
        if (!app_parse_double(v, &a->o.alpha) || !(a->o.alpha > 0.0 && a->o.alpha < 1.0))
            app_fail(PROG, "--alpha: '%s' is not a number in (0, 1)", v);
        *seen_alpha = true;
        break;
    case 6:
        if (!app_parse_uint(v, 1, 1000000000, &u))
            app_fail(PROG, "--tests: '%s' is not a whole number from 1 to 1e9", v);
        a->o.tests = (int)u;
        break;
    case 7: parse_cells(v, a->o.cells); break;
    default:
        if (!app_parse_double(v, &d) || !(d > 0.0 && d <= 10.0))
            app_fail(PROG, "--lobe-width: '%s' is not a number in (0, 10]", v);
        a->o.lobe_width = d;
        break;
    }
#undef IS
#undef ONCE
}

static args parse(int argc, char **argv)
{
    args a;
    memset(&a, 0, sizeof a);
    a.o = mcbox_check_defaults();
    a.timeout = 60.0;
    bool seen_alpha = false, seen[9] = {false};
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(USAGE, stdout);
            exit(0);
        }
        if (strcmp(argv[i], "--version") == 0) {
            printf("mcbox-check (mcbox) %s, library %s\n", APP_VERSION, mcbox_version());
            exit(0);
        }
    }
    for (int i = 1; i < argc; i++)
        parse_option(&a, argc, argv, &i, &seen_alpha, seen);
    /* Each door refuses what it would ignore. */
    if (!a.exec == !a.samples)
        app_fail(PROG, "%s (see --help)", a.exec ? "--exec and --samples exclude each other"
                                                 : "no sampler: give --exec CMD or --samples FILE");
    const char *extra = NULL;
    if (a.exec)
        extra = a.pdf ? "--pdf" : a.pdf_exec ? "--pdf-exec" : a.have_format ? "--format" : NULL;
    else
        extra = a.have_uniforms ? "--uniforms" : a.invert ? "--invert" : a.n_atoms ? "--atom"
              : a.have_seed ? "--seed" : NULL;
    if (extra)
        app_fail(PROG, "%s does not take %s (see --help)", a.exec ? "--exec" : "--samples", extra);
    if (a.samples && !a.pdf == !a.pdf_exec)
        app_fail(PROG, "--samples needs %s", a.pdf ? "--pdf or --pdf-exec, not both"
                                                   : "a density: --pdf NAME or --pdf-exec CMD");
    if (a.pdf && a.domain)
        app_fail(PROG, "--pdf NAME gives the domain: drop --domain %s", a.domain);
    if (!a.pdf && !a.domain)
        app_fail(PROG, "%s needs --domain D (see --help)", a.exec ? "--exec" : "--pdf-exec");
    if (a.pdf && a.have_timeout)
        app_fail(PROG, "--timeout applies to --exec and --pdf-exec only");
    if (a.name) {
        for (const char *p = a.name; *p; p++)
            if (!(('a' <= *p && *p <= 'z') || ('A' <= *p && *p <= 'Z') || ('0' <= *p && *p <= '9') ||
                  strchr("._-", *p)) || (p == a.name && *p == '.'))
                app_fail(PROG, "--name: '%s' is not letters, digits, '.', '_' and '-'", a.name);
        if (strlen(a.name) > 100)
            app_fail(PROG, "--name: longer than 100 characters");
    }
    return a;
}

/* --- the domain and the density of the options ---------------------------- */

static void parse_atom(app *c, int k)
{
    const char *v = c->a.atoms[k], *colon = strrchr(v, ':');
    char coords[256];
    double x[3] = {0.0, 0.0, 0.0}, mass;
    int got = 0;
    bool ok = colon && (size_t)(colon - v) < sizeof coords && app_parse_double(colon + 1, &mass) &&
              mass >= 0.0 && mass <= 1.0;
    if (ok) {
        memcpy(coords, v, (size_t)(colon - v));
        coords[colon - v] = '\0';
        for (char *p = coords, *save = NULL, *t; ok && (t = strtok_r(p, ",", &save)); p = NULL)
            ok = got < 3 && app_parse_double(t, &x[got++]);
    }
    if (!ok || got != c->dims)
        app_fail(PROG, "--atom: '%s' is not %d coordinate%s, a colon and a mass in [0, 1]", v,
                 c->dims, c->dims > 1 ? "s separated by commas" : "");
    memcpy(c->atom_x + (size_t)k * (size_t)c->dims, x, (size_t)c->dims * sizeof *x);
    c->atom_mass[k] = mass;
}

/* The catalog row `name` with the --param assignments, prepared into st;
 * exits with the catalog's message when it cannot. */
static void prepare_row(app *c, const char *name, cat_state *st)
{
    const cat_row *r = cat_find(name);
    if (!r)
        app_fail(PROG, "unknown catalog row '%s' (see warp list)", name);
    cat_values p;
    cat_defaults(r, &p);
    char err[256];
    size_t used = 0;
    for (int i = 0; i < c->a.n_params; i++) {
        if (!cat_set_param(r, &p, c->a.params[i], err, sizeof err))
            app_fail(PROG, "--param: %s", err);
        if (strchr(c->a.params[i], ' ') || used + strlen(c->a.params[i]) + 2 > sizeof c->params)
            app_fail(PROG, "--param: '%s' is malformed or too long", c->a.params[i]);
        used += (size_t)snprintf(c->params + used, sizeof c->params - used, "%s%s", used ? " " : "",
                                 c->a.params[i]);
    }
    if (!cat_prepare(r, &p, st, err, sizeof err))
        app_fail(PROG, "--param: %s", err);
}

static double row_pdf(const double *x, void *ctx)
{
    const app *c = ctx;
    return cat_pdf(c->row_state, x);
}

static void pdf_batch(const double *x, size_t n, double *out, void *ctx);
static void invert_cached(const double *x, double *u, void *ctx);

/* The sampler the options describe (callbacks included), or exit 2. */
static void setup(app *c)
{
    args *a = &c->a;
    const char *dom = a->pdf ? a->pdf : a->domain;
    mcbox_domain_kind kind;
    static cat_state st; /* large and self-referencing: not on the stack */
    /* --pdf always names a catalog row, even one called like a domain
     * ("hemisphere", "square"): the row is the density. */
    if (a->pdf || !mcbox_domain_parse(dom, &kind) || kind == MCBOX_CATALOG) {
        kind = MCBOX_CATALOG;
        prepare_row(c, dom, &st);
        c->row_state = &st;
    } else if (a->n_params) {
        app_fail(PROG, "--param applies to a catalog row, not to the domain %s", dom);
    }
    c->s = mcbox_sampler_init(kind);
    snprintf(c->domain_word, sizeof c->domain_word, "%s", dom);
    if (kind == MCBOX_CATALOG)
        c->s.domain.row = st.row->name, c->s.domain.params = c->params[0] ? c->params : NULL;
    if (a->interval) {
        char *end;
        double lo = strtod(a->interval, &end), hi = (double)NAN;
        bool ok = kind == MCBOX_INTERVAL && *end == ',' && app_parse_double(end + 1, &hi) &&
                  end != a->interval && isfinite(lo) && lo < hi;
        if (kind != MCBOX_INTERVAL)
            app_fail(PROG, "--interval applies to --domain interval only");
        if (!ok)
            app_fail(PROG, "--interval: '%s' is not A,B with finite A < B", a->interval);
        c->s.domain.a = lo, c->s.domain.b = hi;
    }
    c->dims = mcbox_domain_dims(&c->s.domain);
    /* A catalog row's program takes what the row's own sampler takes:
     * `warp serve ROW` refuses any other count. */
    if (kind == MCBOX_CATALOG)
        c->s.uniforms = st.row->uniforms;
    if (a->have_uniforms)
        c->s.uniforms = a->uniforms;
    if (a->invert && c->s.uniforms == 0)
        app_fail(PROG, "--invert needs uniforms: it compares invert(sample(u)) with u");
    for (int k = 0; k < a->n_atoms; k++)
        parse_atom(c, k);
    c->s.n_atoms = (size_t)a->n_atoms;
    c->s.atom_x = c->atom_x, c->s.atom_mass = c->atom_mass;
    if (a->pdf)
        c->s.pdf = row_pdf;
    else
        c->s.pdf_batch = pdf_batch;
    if (a->invert)
        c->s.invert = invert_cached;
    c->s.ctx = c;
    a->o.samples = a->have_n ? a->n : a->o.samples;
    if (!a->name)
        a->name = a->pdf ? a->pdf : "sampler";
}

/* --- the child: start, exchange, fail ------------------------------------ */

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void cleanup_outputs(app *c)
{
    if (c->junit_open)
        app_outfile_abort(&c->junit);
    c->junit_open = false;
}

/* Keeps the end of the child's stderr; false at its EOF. */
static bool read_stderr(child *ch)
{
    char buf[4096];
    ssize_t k = read(ch->err, buf, sizeof buf);
    if (k < 0 && (errno == EINTR || errno == EAGAIN))
        return true;
    if (k <= 0)
        return false;
    size_t m = (size_t)k;
    if (m >= TAIL) {
        memcpy(ch->tail, buf + m - TAIL, TAIL);
        ch->tail_len = TAIL;
    } else {
        size_t keep = ch->tail_len + m > TAIL ? TAIL - m : ch->tail_len;
        memmove(ch->tail, ch->tail + ch->tail_len - keep, keep);
        memcpy(ch->tail + keep, buf, m);
        ch->tail_len = keep + m;
    }
    return true;
}

/* The last non-empty line of the child's stderr, printable, into buf. */
static void stderr_line(const child *ch, char *buf, size_t size)
{
    size_t end = ch->tail_len;
    while (end > 0 && (ch->tail[end - 1] == '\n' || ch->tail[end - 1] == '\r' || ch->tail[end - 1] == ' '))
        end--;
    size_t start = end;
    while (start > 0 && ch->tail[start - 1] != '\n')
        start--;
    size_t k = 0;
    for (size_t i = start; i < end && k + 1 < size && k < 200; i++) {
        unsigned char b = (unsigned char)ch->tail[i];
        buf[k++] = b >= 0x20 && b < 0x7f ? (char)b : '?';
    }
    buf[k] = '\0';
}

/* Waits up to `seconds` for the child to end; true when it did. */
static bool reap_within(child *ch, double seconds)
{
    double end = now() + seconds;
    while (!ch->reaped) {
        pid_t r = waitpid(ch->pid, &ch->status, WNOHANG);
        if (r == ch->pid || (r < 0 && errno != EINTR)) {
            ch->reaped = true;
            break;
        }
        if (now() >= end)
            return false;
        struct timespec ts = {0, 5000000};
        nanosleep(&ts, NULL);
    }
    return true;
}

static void describe_status(const child *ch, char *buf, size_t size)
{
    if (!ch->reaped)
        snprintf(buf, size, "; it was killed");
    else if (WIFSIGNALED(ch->status))
        snprintf(buf, size, "; it was killed by signal %d (%s)", WTERMSIG(ch->status),
                 strsignal(WTERMSIG(ch->status)));
    else if (WIFEXITED(ch->status) && WEXITSTATUS(ch->status) > 128 && WEXITSTATUS(ch->status) < 160)
        snprintf(buf, size, "; it exited with status %d (a shell's: its command was killed by "
                 "signal %d, %s)", WEXITSTATUS(ch->status), WEXITSTATUS(ch->status) - 128,
                 strsignal(WEXITSTATUS(ch->status) - 128));
    else if (WIFEXITED(ch->status) && WEXITSTATUS(ch->status) != 0)
        snprintf(buf, size, "; it exited with status %d", WEXITSTATUS(ch->status));
    else
        buf[0] = '\0';
}

/* The program broke the protocol: kill it (its process group: a shell's
 * children too) and reap it, then one line naming the command, where it
 * was and what went wrong, and exit 2. `grace` seconds let a program that
 * is ending anyway (it closed its stdout) report its own status. */
_Noreturn static void child_fail(app *c, double grace, const char *fmt, ...)
{
    child *ch = &c->ch;
    char what[400], status[128] = "", err_line[220] = "";
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    bool ended = reap_within(ch, grace);
    if (!ended) {
        kill(-ch->pid, SIGKILL);
        kill(ch->pid, SIGKILL);
        while (waitpid(ch->pid, &ch->status, 0) < 0 && errno == EINTR) {
        }
    } else {
        describe_status(ch, status, sizeof status);
        kill(-ch->pid, SIGKILL); /* what it left running in its group */
    }
    if (ch->err >= 0) {
        fcntl(ch->err, F_SETFL, O_NONBLOCK);
        for (int k = 0; k < 64 && read_stderr(ch); k++) {
        }
    }
    stderr_line(ch, err_line, sizeof err_line);
    cleanup_outputs(c);
    fflush(stdout);
    fprintf(stderr, "%s: '%s': %s: %s%s%s%s%s\n", PROG, ch->cmd, c->where, what, status,
            ended ? "" : "; it was killed", err_line[0] ? "; its stderr: " : "", err_line);
    exit(2);
}

static void set_cloexec_nonblock(int fd, bool nonblock)
{
    fcntl(fd, F_SETFD, FD_CLOEXEC);
    if (nonblock)
        fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
}

/* Starts /bin/sh -c cmd in its own process group with pipes on its
 * stdin, stdout and stderr. */
static void child_start(app *c, const char *cmd)
{
    child *ch = &c->ch;
    memset(ch, 0, sizeof *ch);
    ch->cmd = cmd;
    int pin[2], pout[2], perr[2];
    if (pipe(pin) || pipe(pout) || pipe(perr))
        app_fail(PROG, "cannot make pipes for '%s': %s", cmd, strerror(errno));
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        app_fail(PROG, "cannot start '%s': %s", cmd, strerror(errno));
    if (pid == 0) {
        /* Async-signal-safe calls only until exec: the parent may hold
         * OpenMP threads. SIGPIPE back to its default, which exec would
         * otherwise keep ignored. */
        setpgid(0, 0);
        signal(SIGPIPE, SIG_DFL);
        dup2(pin[0], 0);
        dup2(pout[1], 1);
        dup2(perr[1], 2);
        int fds[6] = {pin[0], pin[1], pout[0], pout[1], perr[0], perr[1]};
        for (int k = 0; k < 6; k++)
            if (fds[k] > 2)
                close(fds[k]);
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    setpgid(pid, pid); /* also here: no race with the kill of a failure */
    close(pin[0]);
    close(pout[1]);
    close(perr[1]);
    ch->pid = pid, ch->in = pin[1], ch->out = pout[0], ch->err = perr[0];
    set_cloexec_nonblock(ch->in, true);
    set_cloexec_nonblock(ch->out, true);
    set_cloexec_nonblock(ch->err, true);
    c->have_child = true;
}

/* Called with each answer line (i from 0); false with the reason. */
typedef bool (*answer_fn)(app *c, size_t i, const char *line, size_t len, char *err, size_t errlen);

/* Writes text[0 .. n) to the child while reading k answer lines from it
 * (a program may answer line by line while the batch is still being
 * written: both directions are polled, so neither pipe can fill up and
 * block the two processes). Every wait is bounded by --timeout. */
static void exchange(app *c, const char *text, size_t n, size_t k, answer_fn fn)
{
    child *ch = &c->ch;
    size_t written = 0, got = 0;
    double deadline = now() + c->a.timeout;
    char err[300];
    /* Output before the command is sent is more than the previous command
     * asked for (what comes later is caught by the answers' own format, or
     * at the end of the run). */
    struct pollfd early = {ch->out, POLLIN, 0};
    if (c->batch > 0 && poll(&early, 1, 0) > 0 && (early.revents & POLLIN)) {
        ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
        if (m > 0)
            child_fail(c, 0.0, "before it, more output than the previous command asked for");
        if (m == 0)
            child_fail(c, 1.0, "it closed its stdout");
    }
    while (written < n || got < k) {
        /* Lines already read first: they may complete the batch. */
        while (got < k && ch->rpos < ch->rlen) {
            char b = ch->rbuf[ch->rpos++];
            if (b != '\n') {
                if (ch->line_len == APP_PROTO_MAX_LINE)
                    child_fail(c, 0.0, "answer %zu is longer than %d bytes (garbage, not numbers)",
                               got + 1, APP_PROTO_MAX_LINE);
                ch->line[ch->line_len++] = b;
                continue;
            }
            if (!fn(c, got, ch->line, ch->line_len, err, sizeof err))
                child_fail(c, 0.0, "answer %zu of %zu: %s", got + 1, k, err);
            got++;
            ch->line_len = 0;
        }
        if (got == k && ch->rpos < ch->rlen)
            child_fail(c, 0.0, "more output than the %zu answer line%s asked for", k, k > 1 ? "s" : "");
        if (written == n && got == k)
            break;
        struct pollfd p[3] = {{written < n ? ch->in : -1, POLLOUT, 0},
                              {ch->out, POLLIN, 0},
                              {ch->err, POLLIN, 0}};
        double left = deadline - now();
        if (left <= 0.0)
            child_fail(c, 0.0, "no %s within the %g s of --timeout (%zu of %zu answer%s read)",
                       written < n ? "progress reading our input" : "answer", c->a.timeout, got, k,
                       k > 1 ? "s" : "");
        int r = poll(p, 3, (int)fmin(left * 1000.0 + 1.0, 1e9));
        if (r < 0 && errno != EINTR)
            child_fail(c, 0.0, "poll: %s", strerror(errno));
        if (r <= 0)
            continue;
        if (p[0].revents & (POLLOUT | POLLERR | POLLHUP)) {
            ssize_t w = write(ch->in, text + written, n - written);
            if (w > 0)
                written += (size_t)w, deadline = now() + c->a.timeout;
            else if (w < 0 && errno != EAGAIN && errno != EINTR)
                child_fail(c, 1.0, "it closed its stdin after %zu of %zu answers (%s)", got, k,
                           strerror(errno));
        }
        if (p[2].revents & (POLLIN | POLLHUP | POLLERR)) {
            if (!read_stderr(ch)) {
                close(ch->err);
                ch->err = -1;
            }
        }
        if (p[1].revents & (POLLIN | POLLHUP | POLLERR)) {
            ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
            if (m == 0)
                child_fail(c, 1.0, "it closed its stdout after %zu of %zu answer%s", got, k,
                           k > 1 ? "s" : "");
            if (m > 0)
                ch->rpos = 0, ch->rlen = (size_t)m, deadline = now() + c->a.timeout;
        }
    }
}

/* Room for a command and k lines of m numbers. */
static char *text_room(app *c, size_t k, int m)
{
    size_t need = 64 + k * ((size_t)m * 26 + 1);
    if (need > c->text_cap) {
        free(c->text);
        c->text = malloc(need);
        c->text_cap = c->text ? need : 0;
        if (!c->text)
            child_fail(c, 0.0, "out of memory");
    }
    return c->text;
}

/* "cmd K" and the K lines of m numbers of v into the command text. */
static size_t format_batch(app *c, app_proto_cmd cmd, const double *v, size_t k, int m, size_t stride)
{
    char *t = text_room(c, k, m);
    size_t cap = c->text_cap, used = app_proto_format_command(t, cap, cmd, k);
    for (size_t i = 0; m > 0 && i < k; i++)
        used += app_proto_format_numbers(t + used, cap - used, v + i * stride, m);
    c->batch++;
    snprintf(c->where, sizeof c->where, "command %llu (%s %zu)", (unsigned long long)c->batch,
             app_proto_cmd_name(cmd), k);
    return used;
}

/* Reads to EOF after the last command: the program must exit 0 without
 * another line. */
static void child_end(app *c)
{
    child *ch = &c->ch;
    snprintf(c->where, sizeof c->where, "after the last command (end of its input)");
    close(ch->in);
    ch->in = -1;
    double deadline = now() + c->a.timeout;
    while (ch->out >= 0 || ch->err >= 0) {
        struct pollfd p[2] = {{ch->out, POLLIN, 0}, {ch->err, POLLIN, 0}};
        double left = deadline - now();
        if (left <= 0.0)
            child_fail(c, 0.0, "it did not exit within the %g s of --timeout", c->a.timeout);
        if (poll(p, 2, (int)(left * 1000.0 + 1.0)) <= 0)
            continue;
        if (p[1].revents && !read_stderr(ch))
            close(ch->err), ch->err = -1;
        if (p[0].revents) {
            ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
            if (m > 0)
                child_fail(c, 0.0, "it wrote %zd byte%s more than the answers asked for", m,
                           m > 1 ? "s" : "");
            if (m == 0)
                close(ch->out), ch->out = -1;
        }
    }
    if (!reap_within(ch, fmax(0.0, deadline - now())))
        child_fail(c, 0.0, "it did not exit within the %g s of --timeout", c->a.timeout);
    if (!WIFEXITED(ch->status) || WEXITSTATUS(ch->status) != 0)
        child_fail(c, 0.0, "it did not exit with status 0");
    c->have_child = false;
}

/* --- the protocol's commands --------------------------------------------- */

static bool answer_ok(app *c, size_t i, const char *line, size_t len, char *err, size_t errlen)
{
    (void)c, (void)i;
    return app_proto_parse_ok(line, len, err, errlen);
}

static void hello(app *c, int uniforms)
{
    char line[160];
    size_t n = app_proto_format_hello(line, sizeof line, c->domain_word, c->dims, uniforms,
                                      c->a.o.seed);
    snprintf(c->where, sizeof c->where, "hello");
    if (!n)
        app_fail(PROG, "--domain: '%s' is not one word of at most 63 bytes", c->domain_word);
    exchange(c, line, n, 1, answer_ok);
}

static bool answer_sample(app *c, size_t i, const char *line, size_t len, char *err, size_t errlen)
{
    mcbox_sample *q = &c->ans_smp[i];
    q->x[0] = q->x[1] = q->x[2] = 0.0;
    return app_proto_parse_sample(line, len, c->dims, q, err, errlen);
}

static bool answer_numbers(app *c, size_t i, const char *line, size_t len, char *err, size_t errlen)
{
    return app_proto_parse_numbers(line, len, c->ans_count, c->ans_vals + i * (size_t)c->ans_count,
                                   err, errlen);
}

/* The density over the pipe, in batches of the protocol's size. */
static void pdf_batch(const double *x, size_t n, double *out, void *ctx)
{
    app *c = ctx;
    for (size_t done = 0; done < n;) {
        size_t k = n - done < BATCH ? n - done : BATCH;
        size_t len = format_batch(c, APP_PROTO_PDF, x + done * (size_t)c->dims, k, c->dims,
                                  (size_t)c->dims);
        c->ans_vals = out + done, c->ans_count = 1;
        exchange(c, c->text, len, k, answer_numbers);
        done += k;
    }
}

/* The check asks for invert(x) one point at a time; the answers of the
 * batch's points came in one command, so it looks them up by value (in
 * the order asked, so the search is one step), and asks the program
 * directly for a point it was not given. */
static void invert_cached(const double *x, double *u, void *ctx)
{
    app *c = ctx;
    int nu = c->s.uniforms, d = c->dims;
    for (size_t step = 0; step < c->inv_n; step++) {
        size_t i = (c->inv_at + step) % c->inv_n;
        if (memcmp(c->inv_x + i * 3, x, (size_t)d * sizeof *x) == 0) {
            memcpy(u, c->inv_u + i * (size_t)nu, (size_t)nu * sizeof *u);
            c->inv_at = i + 1;
            return;
        }
    }
    size_t len = format_batch(c, APP_PROTO_INVERT, x, 1, d, 3);
    c->ans_vals = u, c->ans_count = nu;
    exchange(c, c->text, len, 1, answer_numbers);
}

/* The inverses of a batch's finite non-atom points, before the check asks. */
static void invert_batch(app *c, const mcbox_sample *smp, size_t k)
{
    c->inv_n = c->inv_at = 0;
    for (size_t i = 0; i < k; i++) {
        bool finite = smp[i].atom == -1;
        for (int j = 0; j < c->dims; j++)
            finite = finite && isfinite(smp[i].x[j]);
        if (finite) {
            double *x = c->inv_x + c->inv_n * 3;
            x[0] = smp[i].x[0], x[1] = c->dims > 1 ? smp[i].x[1] : 0.0;
            x[2] = c->dims > 2 ? smp[i].x[2] : 0.0;
            c->inv_n++;
        }
    }
    if (c->inv_n == 0)
        return;
    size_t len = format_batch(c, APP_PROTO_INVERT, c->inv_x, c->inv_n, c->dims, 3);
    c->ans_vals = c->inv_u, c->ans_count = c->s.uniforms;
    exchange(c, c->text, len, c->inv_n, answer_numbers);
}

/* --exec: the incremental check, one protocol batch at a time. */
static int run_exec(app *c, mcbox_check_result *r, mcbox_check_table *t)
{
    int nu = c->s.uniforms;
    mcbox_check *chk = mcbox_check_begin(&c->s, &c->a.o, r);
    if (!chk) {
        cleanup_outputs(c);
        app_fail(PROG, "the check could not run: %s", r->message);
    }
    child_start(c, c->a.exec);
    hello(c, nu);
    mcbox_sample *smp = malloc(BATCH * sizeof *smp);
    double *u = malloc(BATCH * (size_t)(nu ? nu : 1) * sizeof *u);
    if (!smp || !u)
        child_fail(c, 0.0, "out of memory");
    for (uint64_t done = 0; done < c->a.o.samples;) {
        size_t k = (size_t)(c->a.o.samples - done < BATCH ? c->a.o.samples - done : BATCH), len;
        for (size_t i = 0; nu && i < k; i++)
            mcbox_check_uniforms(chk, u + i * (size_t)nu);
        if (nu)
            len = format_batch(c, APP_PROTO_SAMPLE, u, k, nu, (size_t)nu);
        else
            len = format_batch(c, APP_PROTO_DRAW, NULL, k, 0, 0);
        c->ans_smp = smp;
        exchange(c, c->text, len, k, answer_sample);
        if (c->a.invert)
            invert_batch(c, smp, k);
        mcbox_check_add(chk, smp, nu ? u : NULL, k);
        done += k;
    }
    int rc = mcbox_check_finish(chk, r, t);
    child_end(c);
    free(smp);
    free(u);
    return rc;
}

/* --- --samples ------------------------------------------------------------ */

/* The whole of a file, or of stdin for "-"; exits 2 when unreadable. */
static char *slurp(const char *path, size_t *len)
{
    int fd = strcmp(path, "-") == 0 ? 0 : open(path, O_RDONLY | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0)
        app_fail(PROG, "--samples: cannot open '%s': %s", path, strerror(errno));
    if (S_ISDIR(st.st_mode))
        app_fail(PROG, "--samples: '%s' is a directory", path);
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (buf && n == cap) {
            char *b = realloc(buf, cap * 2);
            if (!b)
                free(buf);
            buf = b, cap *= 2;
        }
        if (!buf)
            app_fail(PROG, "--samples: '%s': out of memory after %zu bytes", path, n);
        ssize_t k = read(fd, buf + n, cap - n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0)
            app_fail(PROG, "--samples: cannot read '%s': %s", path, strerror(errno));
        if (k == 0)
            break;
        n += (size_t)k;
    }
    if (fd > 0)
        close(fd);
    *len = n;
    return buf;
}

/* The points of --samples into c->points, or exit 2 naming the line or
 * sample that is wrong. */
static void load_samples(app *c)
{
    const char *path = c->a.samples, *shown = strcmp(path, "-") == 0 ? "stdin" : path;
    size_t len;
    char *buf = slurp(path, &len), err[300];
    double *pts;
    uint64_t n;
    if (!app_samples_parse(buf, len, c->a.format, c->dims, &pts, &n, err, sizeof err))
        app_fail(PROG, "%s: %s", shown, err);
    free(buf);
    if (c->a.have_n && c->a.n > n)
        app_fail(PROG, "%s has %llu samples, fewer than --n %llu", shown, (unsigned long long)n,
                 (unsigned long long)c->a.n);
    if (c->a.have_n)
        n = c->a.n;
    mcbox_sample *smp = malloc((size_t)n * sizeof *smp);
    if (!smp)
        app_fail(PROG, "out of memory for %llu samples", (unsigned long long)n);
    for (uint64_t i = 0; i < n; i++) {
        mcbox_sample *q = &smp[i];
        q->x[0] = q->x[1] = q->x[2] = 0.0;
        memcpy(q->x, pts + i * (uint64_t)c->dims, (size_t)c->dims * sizeof *pts);
        q->pdf = q->weight = (double)NAN;
        q->atom = -1;
    }
    free(pts);
    c->points = smp, c->n_points = n;
}

static int run_samples(app *c, mcbox_check_result *r, mcbox_check_table *t)
{
    if (c->a.pdf_exec) {
        child_start(c, c->a.pdf_exec);
        hello(c, 0);
    }
    int rc = mcbox_check_points(&c->s, c->points, c->n_points, &c->a.o, r, t);
    if (c->a.pdf_exec)
        child_end(c);
    free(c->points);
    return rc;
}

/* --- reports ---------------------------------------------------------------- */

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char b = (unsigned char)*s;
        if (b == '"' || b == '\\')
            fprintf(f, "\\%c", b);
        else if (b < 0x20)
            fprintf(f, "\\u%04x", b);
        else
            fputc(b, f);
    }
    fputc('"', f);
}

static void json_number(FILE *f, const char *key, double v, bool last)
{
    if (isfinite(v))
        fprintf(f, "\"%s\": %.17g%s", key, v, last ? "" : ", ");
    else
        fprintf(f, "\"%s\": null%s", key, last ? "" : ", ");
}

static void print_json(FILE *f, const app *c, const mcbox_check_result *r)
{
    fputs("{\"name\": ", f);
    json_string(f, c->a.name);
    fprintf(f, ", \"pass\": %s, \"message\": ", r->pass ? "true" : "false");
    json_string(f, r->message);
    fputs(", ", f);
    json_number(f, "statistic", r->statistic, false);
    fprintf(f, "\"dof\": %d, ", r->dof);
    json_number(f, "pvalue", r->pvalue, false);
    json_number(f, "level", r->level, false);
    const struct {
        const char *key;
        uint64_t v;
    } counts[] = {{"samples", r->samples},       {"cells", r->cells},
                  {"cells_pooled", r->cells_pooled}, {"outside", r->outside},
                  {"nonfinite", r->nonfinite},   {"in_zero_cells", r->in_zero_cells},
                  {"bad_atoms", r->bad_atoms},   {"bad_pdf", r->bad_pdf},
                  {"pdf_reported", r->pdf_reported}, {"weight_reported", r->weight_reported}};
    for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++)
        fprintf(f, "\"%s\": %llu, ", counts[k].key, (unsigned long long)counts[k].v);
    json_number(f, "pdf_integral", r->pdf_integral, false);
    json_number(f, "pdf_integral_error", r->pdf_integral_error, false);
    json_number(f, "pdf_mismatch", r->pdf_mismatch, false);
    json_number(f, "weight_mean", r->weight_mean, false);
    json_number(f, "weight_mismatch", r->weight_mismatch, false);
    json_number(f, "invert_error", r->invert_error, false);
    fprintf(f, "\"alpha\": %.17g, \"tests\": %d, \"seed\": %llu}\n", c->a.o.alpha, c->a.o.tests,
            (unsigned long long)c->a.o.seed);
}

static void print_summary(FILE *f, const app *c, const mcbox_check_result *r)
{
    fprintf(f, "%s: %s\n", c->a.name, r->pass ? "pass" : "FAIL");
    fprintf(f, "  chi-square %.6g, %d dof, p = %.4g (level %.4g)\n", r->statistic, r->dof,
            r->pvalue, r->level);
    fprintf(f, "  samples %llu: %llu outside, %llu non-finite, %llu in zero cells\n",
            (unsigned long long)r->samples, (unsigned long long)r->outside,
            (unsigned long long)r->nonfinite, (unsigned long long)r->in_zero_cells);
    fprintf(f, "  pdf integral %.9g", r->pdf_integral);
    if (r->pdf_integral_error > 0.0)
        fprintf(f, " (quadrature error %.2g)", r->pdf_integral_error);
    fprintf(f, "; pdf mismatch %.3g (%llu reported); bad pdf %llu\n", r->pdf_mismatch,
            (unsigned long long)r->pdf_reported, (unsigned long long)r->bad_pdf);
    if (!isnan(r->invert_error))
        fprintf(f, "  inverse error %.3g\n", r->invert_error);
    if (!r->pass)
        fprintf(f, "  why: %s\n", r->message);
}

static void xml_text(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

static bool write_junit(app *c, const mcbox_check_result *r, double seconds)
{
    FILE *f = c->junit.f;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<testsuite name=\"mcbox-check\" tests=\"1\" failures=\"%d\" errors=\"0\" "
               "time=\"%.3f\">\n  <testcase classname=\"mcbox-check\" name=\"",
            r->pass ? 0 : 1, seconds);
    xml_text(f, c->a.name);
    fprintf(f, "\" time=\"%.3f\">\n", seconds);
    if (!r->pass) {
        fputs("    <failure message=\"", f);
        xml_text(f, r->message);
        fputs("\">", f);
        xml_text(f, r->message);
        fputs("</failure>\n", f);
    }
    fputs("    <system-out>", f);
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (m) {
        print_summary(m, c, r);
        fclose(m);
        xml_text(f, text);
        free(text);
    }
    fputs("</system-out>\n  </testcase>\n</testsuite>\n", f);
    c->junit_open = false;
    return app_outfile_commit(&c->junit);
}

/* A path in a gnuplot single-quoted string: '' is a quote there. */
static void gp_quoted(FILE *f, const char *dir, const char *name, const char *ext)
{
    fputc('\'', f);
    for (const char *p = dir; *p; p++)
        fputs(*p == '\'' ? "''" : (char[2]){*p, '\0'}, f);
    fprintf(f, "/%s.%s'", name, ext);
}

static void plot_script(FILE *f, const app *c, const mcbox_check_table *t, const mcbox_check_result *r)
{
    fputs("set terminal pngcairo noenhanced size 1500,480 font ',9'\nset output ", f);
    gp_quoted(f, c->a.plot, c->a.name, "png");
    fprintf(f, "\nset multiplot layout 1,3 title '%s: %s, chi-square %.6g, %d dof, p = %.3g'\n",
            c->a.name, r->pass ? "pass" : "fail", r->statistic, r->dof, r->pvalue);
    fprintf(f, "set xlabel '%s'\n", t->xlabel);
    static const char *const titles[] = {"observed counts", "expected counts",
                                         "(observed - expected) / sqrt(expected)"};
    for (int k = 0; k < 3; k++) {
        fprintf(f, "set title '%s'\n", titles[k]);
        if (t->dims == 2) {
            fprintf(f, "set ylabel '%s'\nset xrange [%.17g:%.17g]\nset yrange [%.17g:%.17g]\n",
                    t->ylabel, t->lo[0], t->hi[0], t->lo[1], t->hi[1]);
            if (k == 2)
                fputs("set palette defined (-4 'blue', 0 'white', 4 'red')\nset cbrange [-4:4]\n", f);
            fputs("plot ", f);
            gp_quoted(f, c->a.plot, c->a.name, "dat");
            fprintf(f, " using 1:2:%d with image notitle\n", k + 3);
        } else {
            fputs("plot ", f);
            gp_quoted(f, c->a.plot, c->a.name, "dat");
            fprintf(f, " using 1:%d with steps notitle\n", k + 2);
        }
    }
    fputs("unset multiplot\n", f);
}

/* DIR/NAME.dat, then gnuplot reads the script on its stdin; its failure is
 * a warning, the verdict stands. */
static void plot(const app *c, const mcbox_check_table *t, const mcbox_check_result *r)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s.dat", c->a.plot, c->a.name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "%s: warning: cannot write %s: %s\n", PROG, path, strerror(errno));
        return;
    }
    fprintf(f, "# %s: chart cells: %s%s%s, observed, expected, (observed - expected) / sqrt(expected)\n",
            c->a.name, t->xlabel, t->dims == 2 ? ", " : "", t->dims == 2 ? t->ylabel : "");
    double dx = (t->hi[0] - t->lo[0]) / t->nx, dy = t->dims == 2 ? (t->hi[1] - t->lo[1]) / t->ny : 0.0;
    for (int i = 0; i < t->nx; i++) {
        for (int j = 0; j < t->ny; j++) {
            size_t k = (size_t)i * (size_t)t->ny + (size_t)j;
            double o = t->observed[k], e = t->expected[k];
            double z = e > 0.0 ? (o - e) / sqrt(e) : (o > 0.0 ? (double)NAN : 0.0);
            fprintf(f, "%.9g ", t->lo[0] + (i + 0.5) * dx);
            if (t->dims == 2)
                fprintf(f, "%.9g ", t->lo[1] + (j + 0.5) * dy);
            fprintf(f, "%.17g %.17g %.9g\n", o, e, z);
        }
        if (t->dims == 2)
            fputc('\n', f);
    }
    for (size_t k = (size_t)t->nx * (size_t)t->ny; k < t->cells; k++)
        fprintf(f, "# atom %zu: observed %.17g expected %.17g\n",
                k - (size_t)t->nx * (size_t)t->ny, t->observed[k], t->expected[k]);
    if (fclose(f) != 0) {
        fprintf(stderr, "%s: warning: cannot write %s\n", PROG, path);
        return;
    }
    int p[2];
    if (pipe(p) != 0)
        return;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(p[0], 0);
        dup2(null, 1);
        dup2(null, 2);
        close(p[0]);
        close(p[1]);
        signal(SIGPIPE, SIG_DFL);
        execlp("gnuplot", "gnuplot", (char *)NULL);
        _exit(127);
    }
    close(p[0]);
    FILE *g = pid > 0 ? fdopen(p[1], "w") : NULL;
    if (g) {
        plot_script(g, c, t, r);
        fclose(g);
    } else {
        close(p[1]);
    }
    int ws = 0;
    while (pid > 0 && waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    if (pid < 0 || !WIFEXITED(ws) || WEXITSTATUS(ws) != 0)
        fprintf(stderr, "%s: warning: gnuplot %s; %s is written, the verdict stands\n", PROG,
                pid > 0 && WIFEXITED(ws) && WEXITSTATUS(ws) == 127 ? "was not found"
                                                                   : "failed to draw the chart",
                path);
}

int main(int argc, char **argv)
{
    static app c; /* large (the invert cache): not on the stack */
    c.a = parse(argc, argv);
    signal(SIGPIPE, SIG_IGN); /* a program that dies is an EPIPE, reported */
    setup(&c);
    if (c.a.plot) {
        struct stat st;
        if (stat(c.a.plot, &st) != 0 || !S_ISDIR(st.st_mode) || access(c.a.plot, W_OK) != 0)
            app_fail(PROG, "--plot: '%s' is not a writable directory", c.a.plot);
    }
    if (c.a.samples)
        load_samples(&c);
    if (c.a.junit) {
        if (!app_outfile_open(&c.junit, c.a.junit))
            app_fail(PROG, "--junit: cannot write '%s': %s", c.a.junit, strerror(errno));
        fcntl(fileno(c.junit.f), F_SETFD, FD_CLOEXEC); /* not the programs' to hold */
        c.junit_open = true;
    }
    double t0 = now();
    mcbox_check_result r;
    mcbox_check_table t;
    int rc = c.a.exec ? run_exec(&c, &r, &t) : run_samples(&c, &r, &t);
    if (rc != 0) {
        cleanup_outputs(&c);
        app_fail(PROG, "the check could not run: %s", r.message);
    }
    if (c.a.json)
        print_json(stdout, &c, &r);
    else
        print_summary(stdout, &c, &r);
    fflush(stdout);
    if (c.junit_open && !write_junit(&c, &r, now() - t0))
        fprintf(stderr, "%s: warning: cannot write %s: %s\n", PROG, c.a.junit, strerror(errno));
    if (c.a.plot)
        plot(&c, &t, &r);
    mcbox_check_table_free(&t);
    free(c.text);
    return r.pass ? 0 : 1;
}
