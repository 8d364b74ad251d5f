/* tests/test_cli.c - the command-line contract of every program in
 * $MC_BUILD/bin, whoever wrote it: bad input exits with status 2, prints
 * exactly one line on stderr starting with the program's name and nothing
 * on stdout; --help and --version exit 0.
 *
 * Programs are found at run time (one cmocka test each), so programs added
 * later are covered without editing this file. The cases depend on what
 * the program's --help mentions: an unknown flag and a missing value
 * always; --samples -3, abc, 0 and 1e30 when it takes --samples; --seed x
 * when it takes --seed. When the help shows subcommands (see
 * subcommands()), the cases are also run after each of them, whose own
 * --help decides which apply. Each run has a 20 s timeout. Fake programs that break
 * the contract in each way are the negative controls.
 */
#define _POSIX_C_SOURCE 200809L /* posix_spawn, mkdtemp, strdup, kill */

#include "tests/support/mc_test.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "tests/support/negctl.h"

extern char **environ;

#define TIMEOUT_S 20.0
#define CAPTURE 16384
#define MAX_PROGRAMS 256

typedef struct run {
    int status; /* exit status, or -1 (signal, timeout, spawn failure) */
    char out[CAPTURE], err[CAPTURE];
    size_t out_len, err_len;
} run;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Appends what fd has to buf (truncating at CAPTURE - 1); false at EOF. */
static bool drain(int fd, char *buf, size_t *len)
{
    char tmp[4096];
    ssize_t k = read(fd, tmp, sizeof tmp);
    if (k <= 0)
        return k < 0 && errno == EINTR;
    size_t room = CAPTURE - 1 - *len, take = (size_t)k < room ? (size_t)k : room;
    memcpy(buf + *len, tmp, take);
    *len += take;
    buf[*len] = '\0';
    return true;
}

/* Runs path with argv[1..] = args (NULL-terminated), stdin /dev/null,
 * capturing stdout and stderr; kills it (by its pid) after TIMEOUT_S. */
static void run_prog(const char *path, const char *const *args, run *r)
{
    memset(r, 0, sizeof *r);
    r->status = -1;
    const char *argv[16] = {path};
    int argc = 1;
    for (; args[argc - 1] && argc < 15; argc++)
        argv[argc] = args[argc - 1];
    argv[argc] = NULL;
    int po[2], pe[2];
    if (pipe(po) != 0)
        return;
    if (pipe(pe) != 0) {
        close(po[0]);
        close(po[1]);
        return;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, po[1], 1);
    posix_spawn_file_actions_adddup2(&fa, pe[1], 2);
    posix_spawn_file_actions_addclose(&fa, po[0]);
    posix_spawn_file_actions_addclose(&fa, pe[0]);
    pid_t pid;
    int rc = posix_spawn(&pid, path, &fa, NULL, (char *const *)argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(po[1]);
    close(pe[1]);
    if (rc == 0) {
        struct pollfd fds[2] = {{po[0], POLLIN, 0}, {pe[0], POLLIN, 0}};
        bool open_out = true, open_err = true;
        double deadline = now() + TIMEOUT_S;
        while ((open_out || open_err) && now() < deadline) {
            fds[0].fd = open_out ? po[0] : -1;
            fds[1].fd = open_err ? pe[0] : -1;
            if (poll(fds, 2, 100) <= 0)
                continue;
            if (open_out && (fds[0].revents & (POLLIN | POLLHUP)))
                open_out = drain(po[0], r->out, &r->out_len);
            if (open_err && (fds[1].revents & (POLLIN | POLLHUP)))
                open_err = drain(pe[0], r->err, &r->err_len);
        }
        if (open_out || open_err)
            kill(pid, SIGKILL);
        int ws;
        while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
        }
        if (!open_out && !open_err && WIFEXITED(ws))
            r->status = WEXITSTATUS(ws);
    }
    close(po[0]);
    close(pe[0]);
}

/* Checks one bad-input run; returns NULL when it keeps the contract, else
 * what is wrong (in buf). */
static const char *judge_bad(const char *name, const run *r, char *buf, size_t size)
{
    size_t nl = 0, len = strlen(name);
    for (size_t i = 0; i < r->err_len; i++)
        nl += r->err[i] == '\n';
    if (r->status != 2)
        snprintf(buf, size, "exit status %d, not 2", r->status);
    else if (r->out_len > 0)
        snprintf(buf, size, "wrote %zu bytes to stdout", r->out_len);
    else if (nl != 1 || r->err[r->err_len - 1] != '\n')
        snprintf(buf, size, "stderr has %zu lines, not exactly one: '%.200s'", nl, r->err);
    else if (strncmp(r->err, name, len) != 0 || (r->err[len] != ':' && r->err[len] != ' '))
        snprintf(buf, size, "stderr does not start with '%s:': '%.200s'", name, r->err);
    else
        return NULL;
    return buf;
}

enum { MAX_SUBS = 8, SUB_LEN = 32 };

/* Adds the lowercase name at p (letters, digits, '_', '-'; at most
 * SUB_LEN - 1 long) to subs unless present; returns the count. */
static int add_sub(char subs[][SUB_LEN], int n, const char *p)
{
    size_t k = 0;
    while (islower((unsigned char)p[k]) || isdigit((unsigned char)p[k]) || p[k] == '_' || p[k] == '-')
        k++;
    if (k == 0 || k >= SUB_LEN || !islower((unsigned char)p[0]) || n >= MAX_SUBS)
        return n;
    if (p[k] && !isspace((unsigned char)p[k]) && !strchr("|,})", p[k]))
        return n;
    for (int i = 0; i < n; i++)
        if (strlen(subs[i]) == k && strncmp(subs[i], p, k) == 0)
            return n;
    memcpy(subs[n], p, k);
    subs[n][k] = '\0';
    return n + 1;
}

/* The subcommands a help text shows, into subs (returns how many):
 * the lowercase word or a|b|c list after the program name on the "usage:"
 * line and on indented continuation lines that repeat the program name
 * ("usage: warp list" / "       warp sample NAME ..."), and the first words
 * of the indented lines under a line "commands:" or "subcommands:". */
static int subcommands(const char *help, const char *name, char subs[][SUB_LEN])
{
    int n = 0;
    size_t len = strlen(name);
    bool in_section = false;
    for (const char *p = help; p && *p;) {
        const char *eol = strchr(p, '\n'), *q = p;
        size_t linelen = eol ? (size_t)(eol - p) : strlen(p);
        bool indented = isspace((unsigned char)*p);
        if (strncmp(q, "usage:", 6) == 0)
            q += 6;
        while (*q == ' ' || *q == '\t')
            q++;
        if ((q != p || strncmp(p, "usage:", 6) == 0) && strncmp(q, name, len) == 0 && q[len] == ' ') {
            q += len;
            while (*q == ' ')
                q++;
            if (*q == '{' || *q == '(')
                q++;
            /* a|b|c or a,b: every name of the list */
            for (;;) {
                n = add_sub(subs, n, q);
                while (islower((unsigned char)*q) || isdigit((unsigned char)*q) || *q == '_' || *q == '-')
                    q++;
                if (*q != '|' && *q != ',')
                    break;
                q++;
            }
        } else if (in_section && indented) {
            n = add_sub(subs, n, q);
        }
        if (!indented) {
            size_t k = linelen;
            while (k > 0 && isspace((unsigned char)p[k - 1]))
                k--;
            in_section = (k == 9 && strncasecmp(p, "commands:", 9) == 0) ||
                         (k == 12 && strncasecmp(p, "subcommands:", 12) == 0);
        }
        p = eol ? eol + 1 : NULL;
    }
    return n;
}

/* Runs every bad-input case of the program (after `sub` when not NULL).
 * Returns the number of violations, each printed unless quiet. */
static int bad_input_cases(const char *path, const char *name, const char *sub, bool quiet)
{
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    const char *help_args[] = {sub ? sub : "--help", sub ? "--help" : NULL, NULL};
    run_prog(path, help_args, r);
    bool samples = strstr(r->out, "--samples") != NULL, seed = strstr(r->out, "--seed") != NULL;
    /* Each case: up to three words after the subcommand. */
    const char *cases[10][3] = {{"--no-such-flag", NULL, NULL}, {"--samples", "-3", NULL},
                                {"--samples", "abc", NULL},     {"--samples", "0", NULL},
                                {"--samples", "1e30", NULL},    {"--seed", "x", NULL},
                                {"--seed", NULL, NULL},         {"--samples", NULL, NULL},
                                {"--seed", " -1", NULL},        {"--seed", "0x", NULL}};
    int n_cases = 10, bad = 0;
    char why[512];
    for (int c = 0; c < n_cases; c++) {
        const char *flag = cases[c][0];
        bool needs_samples = strcmp(flag, "--samples") == 0, needs_seed = strcmp(flag, "--seed") == 0;
        /* The missing-value case is run with whichever of the two exists. */
        if ((needs_samples && !samples) || (needs_seed && !seed))
            continue;
        if (c == 7 && seed)
            continue;
        const char *args[5] = {NULL};
        int k = 0;
        if (sub)
            args[k++] = sub;
        for (int j = 0; j < 3 && cases[c][j]; j++)
            args[k++] = cases[c][j];
        run_prog(path, args, r);
        if (judge_bad(name, r, why, sizeof why)) {
            if (!quiet)
                printf("%s%s%s %s%s%s: %s\n", name, sub ? " " : "", sub ? sub : "", flag,
                       cases[c][1] ? " " : "", cases[c][1] ? cases[c][1] : "", why);
            bad++;
        }
    }
    free(r);
    return bad;
}

static void test_cli_program(void **state)
{
    const char *path = *state, *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    int bad = 0;
    const char *help[] = {"--help", NULL}, *version[] = {"--version", NULL};
    run_prog(path, version, r);
    if (r->status != 0 || r->out_len == 0) {
        printf("%s --version: exit status %d, %zu bytes of output\n", name, r->status, r->out_len);
        bad++;
    }
    run_prog(path, help, r);
    if (r->status != 0 || r->out_len == 0) {
        printf("%s --help: exit status %d, %zu bytes of output\n", name, r->status, r->out_len);
        bad++;
    }
    char subs[MAX_SUBS][SUB_LEN];
    int n_subs = subcommands(r->out, name, subs);
    free(r);
    bad += bad_input_cases(path, name, NULL, false);
    for (int i = 0; i < n_subs; i++) {
        printf("%s: the cases run again after its subcommand '%s'\n", name, subs[i]);
        bad += bad_input_cases(path, name, subs[i], false);
    }
    if (bad)
        fail_msg("%s: %d violation(s) of the command-line contract (listed above)", name, bad);
}

/* --- statistics that cannot be estimated ---------------------------------- */

/* Runs $MC_BUILD/bin/prog with args into r. */
static void run_named(const char *prog, const char *const *args, run *r)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/bin/%s", mc_test_build_dir(), prog);
    run_prog(path, args, r);
}

/* The line of r->out that starts with `method` (NULL if none), copied. */
static const char *row_of(const run *r, const char *method, char *line, size_t size)
{
    size_t len = strlen(method);
    for (const char *p = r->out; p && *p;) {
        const char *eol = strchr(p, '\n');
        size_t k = eol ? (size_t)(eol - p) : strlen(p);
        if (k > len && strncmp(p, method, len) == 0 && (p[len] == ' ' || p[len] == ',')) {
            snprintf(line, size, "%.*s", (int)k, p);
            return line;
        }
        p = eol ? eol + 1 : NULL;
    }
    return NULL;
}

/* A standard error from fewer than 2 samples, or a sample variance of 0
 * that only too few samples produce (every sample missed the light), is
 * printed as n/a with its reason, never as 0; in CSV the stderr and z
 * fields are empty and the reason goes to stderr. A zero-variance
 * estimator's exact 0 stays a number. A chi-square test with no degrees
 * of freedom is refused with exit 2 before any output. */
static void test_cli_statistics_na(void **state)
{
    (void)state;
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    char line[1024];
    const char *pi1[] = {"--samples", "1", NULL};
    run_named("pi", pi1, r);
    assert_int_equal(r->status, 0);
    assert_non_null(row_of(r, "plain", line, sizeof line));
    if (!strstr(line, "n/a") || !strstr(line, "fewer than 2 samples"))
        fail_msg("pi --samples 1: '%s'", line);
    const char *light5[] = {"--samples", "5", NULL};
    run_named("light_pdf", light5, r);
    assert_int_equal(r->status, 0);
    assert_non_null(row_of(r, "cosine", line, sizeof line));
    if (!strstr(line, "n/a") || strstr(line, "0.000e+00"))
        fail_msg("light_pdf --samples 5, cosine row: '%s'", line);
    const char *mix5[] = {"--samples", "5", "--csv", NULL};
    run_named("mixture", mix5, r);
    assert_int_equal(r->status, 0);
    assert_non_null(row_of(r, "light-cosine", line, sizeof line));
    /* method,n,estimate,stderr,exact,z,variance: stderr and z empty. */
    char method[64];
    unsigned long long n;
    double est, exact;
    int used = 0;
    if (sscanf(line, "%63[^,],%llu,%lf,,%lf,,%n", method, &n, &est, &exact, &used) != 4 || used == 0)
        fail_msg("mixture --samples 5 --csv, light-cosine: '%s'", line);
    if (!strstr(r->err, "light-cosine: stderr and z n/a"))
        fail_msg("mixture --csv: no reason on stderr: '%s'", r->err);
    const char *xsq[] = {"--pdf", "quadratic", "--samples", "1000", NULL};
    run_named("integrate_x_sq", xsq, r);
    assert_int_equal(r->status, 0);
    assert_non_null(row_of(r, "quadratic", line, sizeof line));
    if (strstr(line, "n/a"))
        fail_msg("integrate_x_sq quadratic (zero variance, exact): '%s'", line);
    const char *chi5[] = {"pvalues", "--samples", "5", "--seeds", "2", NULL};
    run_named("plotdata_chi2", chi5, r);
    char why[512];
    if (judge_bad("plotdata_chi2", r, why, sizeof why))
        fail_msg("plotdata_chi2 pvalues --samples 5: %s", why);
    const char *tiny_flux[] = {"--flux", "1e-300", NULL};
    run_named("sphere_light", tiny_flux, r);
    if (judge_bad("sphere_light", r, why, sizeof why))
        fail_msg("sphere_light --flux 1e-300: %s", why);
    free(r);
}

/* --- one grammar, one answer ---------------------------------------------- */

/* Whether `cmd` (shell syntax, run from the build directory's bin) exits
 * 2 with one line on stderr naming `name` and nothing on stdout. */
static bool shell_refuses(const char *name, const char *cmd)
{
    char full[2048];
    const char *b = mc_test_build_dir();
    snprintf(full, sizeof full, "cd %s/bin && %s >../cli_g.out 2>../cli_g.err", b, cmd);
    int rc = system(full);
    run r;
    memset(&r, 0, sizeof r);
    r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    char path[1024];
    snprintf(path, sizeof path, "%s/cli_g.out", b);
    FILE *f = fopen(path, "rb");
    if (f) {
        r.out_len = fread(r.out, 1, CAPTURE - 1, f);
        fclose(f);
    }
    snprintf(path, sizeof path, "%s/cli_g.err", b);
    f = fopen(path, "rb");
    if (f) {
        r.err_len = fread(r.err, 1, CAPTURE - 1, f);
        fclose(f);
    }
    char why[512];
    if (judge_bad(name, &r, why, sizeof why)) {
        printf("'%s': %s\n", cmd, why);
        return false;
    }
    return true;
}

/* Counts and seeds share one grammar (1e3 is a seed as it is a count; 1.5
 * is neither); an option given twice, an option the subcommand does not
 * take, a discrete outcome that is not an index and a thread count past
 * the machine's limit are refused before any output; --help names each
 * default once. */
static void test_cli_one_grammar(void **state)
{
    (void)state;
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    static const char *const good[][7] = {
        {"pi", "--seed", "1e3", "--samples", "1e3", NULL},
        {"pi", "--seed", "0x3e8", "--samples", "0x3e8", NULL},
        {"pi", "--samples", "2.5e3", "--threads", "1e0", NULL},
    };
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
        run_named(good[i][0], good[i] + 1, r);
        if (r->status != 0)
            fail_msg("%s %s %s %s %s: exit %d, '%s'", good[i][0], good[i][1], good[i][2], good[i][3],
                     good[i][4], r->status, r->err);
    }
    char threads[64];
    snprintf(threads, sizeof threads, "%ld", 64 * sysconf(_SC_NPROCESSORS_ONLN) + 1);
    const char *const bad[][8] = {
        {"pi", "--seed", "1.5", NULL},
        {"pi", "--samples", "1.5", NULL},
        {"pi", "--seed", "-1", NULL},
        {"pi", "--samples", " 5", NULL},
        {"pi", "--samples", "10", "--samples", "20", NULL},
        {"pi", "--threads", threads, NULL},
        {"cornell_box", "--threads", threads, "--width", "4", NULL},
        {"cornell_box", "--spp", "2", "--samples", "3", NULL},
        {"warp", "list", "--n", "3", NULL},
        {"warp", "pdf", "cosine", "--seed", "3", NULL},
        {"warp", "sample", "cosine", "--alpha", "0.1", NULL},
        {"warp", "sample", "cosine", "--seed", "1", "--seed", "2", NULL},
        {"plotdata_chi2", "cells", "--seeds", "3", NULL},
    };
    int failures = 0;
    char why[512];
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        run_named(bad[i][0], bad[i] + 1, r);
        if (judge_bad(bad[i][0], r, why, sizeof why)) {
            printf("%s %s %s ...: %s\n", bad[i][0], bad[i][1], bad[i][2] ? bad[i][2] : "", why);
            failures++;
        }
    }
    failures += !shell_refuses("warp", "printf '2.5\\n' | ./warp pdf discrete");
    failures += !shell_refuses("warp", "printf -- '-1\\n' | ./warp pdf alias");
    failures += !shell_refuses("warp", "printf '8\\n' | ./warp pdf discrete");
    const char *help[] = {"--help", NULL};
    run_named("cornell_box", help, r);
    if (strstr(r->out, "(book) (") || !strstr(r->out, "default book") || !strstr(r->out, "1e3"))
        fail_msg("cornell_box --help: the default twice, or no grammar: '%.400s'", r->out);
    free(r);
    if (failures)
        fail_msg("%d case(s) above were accepted or broke the contract", failures);
}

/* A run estimated to take more than a few seconds says so on stderr when
 * it starts (stderr is not a terminal here), in one line naming the
 * program and the time; a short run says nothing. The long runs are
 * stopped after 2 s (pi by SIGKILL, cornell_box by SIGTERM). */
static void test_cli_long_runs_announce(void **state)
{
    (void)state;
    const char *b = mc_test_build_dir();
    /* Each is stopped soon after it starts: the line must come first. */
    static const struct {
        const char *cmd, *prog;
    } cases[] = {
        {"timeout -s KILL 2 ./pi --samples 1e13 --threads 1", "pi"},
        {"timeout -s TERM 2 ./cornell_box --spp 1e13 --width 8 --threads 1 -o ../cli_long.png",
         "cornell_box"},
        {"timeout -s KILL 0.5 ./integrate_x_sq --samples 1e12", "integrate_x_sq"},
        {"timeout -s KILL 0.5 ./estimate_halfway --samples 1e12", "estimate_halfway"},
        {"timeout -s KILL 0.5 ./log_sin --samples 1e12", "log_sin"},
        {"timeout -s KILL 0.5 ./inverse_cdf --samples 1e12", "inverse_cdf"},
        {"timeout -s KILL 0.5 ./sphere_importance --samples 1e12", "sphere_importance"},
        {"timeout -s KILL 0.5 ./cos_cubed --samples 1e12", "cos_cubed"},
        {"timeout -s KILL 0.5 ./light_pdf --samples 1e12", "light_pdf"},
        {"timeout -s KILL 0.5 ./sphere_light --samples 1e12", "sphere_light"},
        {"timeout -s KILL 0.5 ./mixture --samples 1e12", "mixture"},
        {"timeout -s KILL 0.5 ./projected_area --samples 1e12", "projected_area"},
    };
    char full[2048], err[4096], name[64];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(full, sizeof full, "cd %s/bin && %s >/dev/null 2>../cli_long.err", b, cases[i].cmd);
        (void)system(full);
        snprintf(full, sizeof full, "%s/cli_long.err", b);
        mc_test_read_text(full, err, sizeof err);
        snprintf(name, sizeof name, "%s: about ", cases[i].prog);
        if (strncmp(err, name, strlen(name)) != 0 || !strstr(err, " for "))
            fail_msg("'%s': no announcement of its time: '%s'", cases[i].cmd, err);
    }
    /* On a terminal (script(1) gives the program one) the announcement is
     * followed by a progress line, redrawn once a second. */
    snprintf(full, sizeof full,
             "cd %s/bin && script -qec 'timeout -s KILL 2.5 ./mixture --samples 1e12' /dev/null "
             ">../cli_tty.out 2>&1",
             b);
    (void)system(full);
    snprintf(full, sizeof full, "%s/cli_tty.out", b);
    mc_test_read_text(full, err, sizeof err);
    if (!strstr(err, "mixture: about ") || !strstr(err, "\rmixture: 1 s of about "))
        fail_msg("mixture on a terminal: no progress line: '%s'", err);
    remove(full);
    snprintf(full, sizeof full, "%s/cli_long.png", b);
    remove(full);
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    const char *quick[] = {"--samples", "1e5", NULL};
    run_named("pi", quick, r);
    if (r->status != 0 || r->err_len != 0)
        fail_msg("pi --samples 1e5: exit %d, stderr '%s'", r->status, r->err);
    free(r);
}

/* --- the bad-input matrix -------------------------------------------------- */

/* Every option of every program, one row each: a new option or program is
 * covered by adding a row. `fast` are options that keep an accidental
 * acceptance short; the option under test is left out of them. */
typedef enum opt_kind { K_COUNT, K_SEED, K_WHOLE, K_REAL, K_CHOICE, K_FLAG, K_PATH } opt_kind;

typedef struct matrix_prog {
    const char *name;
    const char *pre[3];   /* subcommand words, NULL-terminated */
    const char *fast[10]; /* option, value pairs, NULL-terminated */
} matrix_prog;

typedef struct matrix_row {
    int prog;           /* index into matrix_progs */
    const char *option; /* with its dashes */
    opt_kind kind;
    const char *good;   /* a valid value (the repeated-option case) */
} matrix_row;

static const matrix_prog matrix_progs[] = {
    {"cornell_box", {NULL}, {"--width", "4", "--spp", "1", "-o", "/tmp/mcbox-matrix.png", NULL}},
    {"cos_cubed", {NULL}, {"--samples", "100", NULL}},
    {"estimate_halfway", {NULL}, {"--samples", "100", NULL}},
    {"integrate_x_sq", {NULL}, {"--samples", "100", NULL}},
    {"inverse_cdf", {NULL}, {"--samples", "100", NULL}},
    {"light_pdf", {NULL}, {"--samples", "100", NULL}},
    {"log_sin", {NULL}, {"--samples", "100", NULL}},
    {"mixture", {NULL}, {"--samples", "100", NULL}},
    {"pi", {NULL}, {"--samples", "100", NULL}},
    {"plotdata_chi2", {"pvalues", NULL}, {"--samples", "2000", "--seeds", "1", NULL}},
    {"projected_area", {NULL}, {"--samples", "100", NULL}},
    {"sphere_importance", {NULL}, {"--samples", "100", NULL}},
    {"sphere_light", {NULL}, {"--samples", "100", NULL}},
    {"sphere_plot", {NULL}, {"--samples", "100", NULL}},
    {"warp", {"sample", "cosine", NULL}, {"--n", "10", NULL}},
    {"warp", {"chi2", "cosine", NULL}, {"--n", "2000", NULL}},
};

static const matrix_row matrix_rows[] = {
    {0, "--scene", K_CHOICE, "book"}, {0, "--width", K_WHOLE, "4"}, {0, "--spp", K_COUNT, "1"},
    {0, "--samples", K_COUNT, "1"}, {0, "--max-depth", K_WHOLE, "3"}, {0, "--strategy", K_CHOICE, "mis"},
    {0, "--threads", K_WHOLE, "1"}, {0, "--seed", K_SEED, "2"}, {0, "-o", K_PATH, "/tmp/mcbox-matrix.png"},
    {0, "--gamma", K_CHOICE, "srgb"}, {0, "--csv", K_FLAG, NULL}, {0, "--roulette", K_FLAG, NULL},
    {0, "--emit-aim", K_REAL, "0.2"},
    {1, "--samples", K_COUNT, "100"}, {1, "--seed", K_SEED, "2"}, {1, "--method", K_CHOICE, "all"},
    {1, "--csv", K_FLAG, NULL},
    {2, "--samples", K_COUNT, "100"}, {2, "--seed", K_SEED, "2"}, {2, "--csv", K_FLAG, NULL},
    {3, "--samples", K_COUNT, "100"}, {3, "--seed", K_SEED, "2"}, {3, "--pdf", K_CHOICE, "all"},
    {3, "--csv", K_FLAG, NULL},
    {4, "--samples", K_COUNT, "100"}, {4, "--seed", K_SEED, "2"}, {4, "--csv", K_FLAG, NULL},
    {5, "--samples", K_COUNT, "100"}, {5, "--seed", K_SEED, "2"}, {5, "--method", K_CHOICE, "all"},
    {5, "--csv", K_FLAG, NULL},
    {6, "--samples", K_COUNT, "100"}, {6, "--seed", K_SEED, "2"}, {6, "--method", K_CHOICE, "all"},
    {6, "--csv", K_FLAG, NULL},
    {7, "--samples", K_COUNT, "100"}, {7, "--seed", K_SEED, "2"}, {7, "--method", K_CHOICE, "all"},
    {7, "--csv", K_FLAG, NULL},
    {8, "--samples", K_COUNT, "100"}, {8, "--seed", K_SEED, "2"}, {8, "--method", K_CHOICE, "all"},
    {8, "--threads", K_WHOLE, "1"}, {8, "--csv", K_FLAG, NULL},
    {9, "--samples", K_COUNT, "2000"}, {9, "--seed", K_SEED, "2"}, {9, "--seeds", K_WHOLE, "1"},
    {9, "--cos-cells", K_WHOLE, "4"}, {9, "--phi-cells", K_WHOLE, "4"},
    {10, "--samples", K_COUNT, "100"}, {10, "--seed", K_SEED, "2"}, {10, "--body", K_CHOICE, "all"},
    {10, "--csv", K_FLAG, NULL},
    {11, "--samples", K_COUNT, "100"}, {11, "--seed", K_SEED, "2"}, {11, "--method", K_CHOICE, "all"},
    {11, "--csv", K_FLAG, NULL},
    {12, "--samples", K_COUNT, "100"}, {12, "--seed", K_SEED, "2"}, {12, "--method", K_CHOICE, "all"},
    {12, "--flux", K_REAL, "10"}, {12, "--radius", K_REAL, "0.5"}, {12, "--distance", K_REAL, "3"},
    {12, "--theta", K_REAL, "30"}, {12, "--csv", K_FLAG, NULL},
    {13, "--samples", K_COUNT, "100"}, {13, "--seed", K_SEED, "2"}, {13, "--method", K_CHOICE, "inverse"},
    {14, "--n", K_COUNT, "10"}, {14, "--samples", K_COUNT, "10"}, {14, "--seed", K_SEED, "2"},
    {14, "--param", K_CHOICE, NULL},
    {15, "--n", K_COUNT, "2000"}, {15, "--seed", K_SEED, "2"}, {15, "--alpha", K_REAL, "0.01"},
};

/* The bad values of each kind (the option's own range decides for the
 * whole-number and real kinds: every value here is outside all of them). */
static const char *const *bad_values(opt_kind k)
{
    static const char *const count[] = {"-3", "0", "1e30", "abc", "", "nan", "inf", "1.5", " 5", "0x", NULL};
    static const char *const seed[] = {"-1", "abc", "", "nan", "inf", "1.5", "1e20", "0x", " 1", NULL};
    static const char *const whole[] = {"-1e9", "1e30", "abc", "", "nan", "inf", "1.5", NULL};
    static const char *const real[] = {"-1e9", "1e300", "abc", "", "nan", "inf", "-inf", NULL};
    static const char *const choice[] = {"nope", "", NULL};
    static const char *const path[] = {"/tmp", "/nonexistent-dir/x.png", "/proc/mcbox-x.png", "",
                                       "/tmp/mcbox-matrix.jpg", NULL};
    static const char *const none[] = {NULL};
    switch (k) {
    case K_COUNT: return count;
    case K_SEED: return seed;
    case K_WHOLE: return whole;
    case K_REAL: return real;
    case K_CHOICE: return choice;
    case K_PATH: return path;
    case K_FLAG: return none;
    }
    return none;
}

/* Builds the arguments: the program's subcommand words, its fast options
 * except `skip`, then the case's words. */
static int matrix_args(const matrix_prog *p, const char *skip, const char *const *words, const char **args)
{
    int k = 0;
    for (int i = 0; p->pre[i]; i++)
        args[k++] = p->pre[i];
    for (int i = 0; p->fast[i]; i += 2)
        if (!skip || strcmp(p->fast[i], skip) != 0) {
            args[k++] = p->fast[i];
            args[k++] = p->fast[i + 1];
        }
    for (int i = 0; words[i]; i++)
        args[k++] = words[i];
    args[k] = NULL;
    return k;
}

/* Runs one case; returns whether it met the contract (printing it if not). */
static bool matrix_case(const matrix_prog *p, const char *skip, const char *const *words, run *r, int *cases)
{
    const char *args[16];
    matrix_args(p, skip, words, args);
    char path[1024], why[512];
    snprintf(path, sizeof path, "%s/bin/%s", mc_test_build_dir(), p->name);
    run_prog(path, args, r);
    ++*cases;
    if (!judge_bad(p->name, r, why, sizeof why))
        return true;
    printf("matrix: %s", p->name);
    for (int i = 0; args[i]; i++)
        printf(" '%s'", args[i]);
    printf(": %s\n", why);
    return false;
}

/* Every row's option with every bad value of its kind, with its value
 * missing (last on the line) and given twice; every program with an
 * unknown flag and a stray argument. Prints the count of cases and of
 * those that met the contract; all must. */
static void test_cli_bad_input_matrix(void **state)
{
    (void)state;
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    int cases = 0, met = 0;
    const size_t n_progs = sizeof matrix_progs / sizeof matrix_progs[0];
    for (size_t i = 0; i < sizeof matrix_rows / sizeof matrix_rows[0]; i++) {
        const matrix_row *row = &matrix_rows[i];
        const matrix_prog *p = &matrix_progs[row->prog];
        const char *const *bad = bad_values(row->kind);
        /* --param takes k=v: bad ones are an unknown key and a bad value. */
        static const char *const param_bad[] = {"nope=1", "n=abc", "", "n", NULL};
        if (row->good == NULL && row->kind == K_CHOICE)
            bad = param_bad;
        for (int v = 0; bad[v]; v++) {
            const char *w[] = {row->option, bad[v], NULL};
            met += matrix_case(p, row->option, w, r, &cases);
        }
        if (row->kind == K_FLAG) {
            char with_value[64];
            snprintf(with_value, sizeof with_value, "%s=1", row->option);
            const char *w1[] = {with_value, NULL}, *w2[] = {row->option, row->option, NULL};
            met += matrix_case(p, row->option, w1, r, &cases);
            met += matrix_case(p, row->option, w2, r, &cases);
            continue;
        }
        const char *missing[] = {row->option, NULL};
        met += matrix_case(p, row->option, missing, r, &cases);
        if (row->good) {
            const char *twice[] = {row->option, row->good, row->option, row->good, NULL};
            met += matrix_case(p, row->option, twice, r, &cases);
        }
    }
    for (size_t i = 0; i < n_progs; i++) {
        const char *unknown[] = {"--no-such-flag", "1", NULL}, *stray[] = {"stray", NULL};
        met += matrix_case(&matrix_progs[i], NULL, unknown, r, &cases);
        met += matrix_case(&matrix_progs[i], NULL, stray, r, &cases);
    }
    free(r);
    remove("/tmp/mcbox-matrix.png");
    printf("bad-input matrix: %d cases, %d met the contract\n", cases, met);
    if (met != cases)
        fail_msg("%d of %d bad-input cases broke the contract (listed above)", cases - met, cases);
}

/* --- negative controls ---------------------------------------------------- */

static negctl tally;

/* Writes an executable shell script dir/name with the given body. */
static void write_script(const char *path, const char *body)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "#!/bin/sh\n%s\n", body);
    fclose(f);
    assert_int_equal(chmod(path, 0755), 0);
}

/* Fake programs that answer --help like a real one but break the contract
 * on bad input in one way each; the checks above must flag every one. */
static void test_cli_negative_controls(void **state)
{
    (void)state;
    static const char *const fakes[][2] = {
        {"fake_status1", "echo \"fake_status1: bad\" >&2; exit 1"},
        {"fake_stdout", "echo \"fake_stdout: bad\"; exit 2"},
        {"fake_two_lines", "echo \"fake_two_lines: bad\" >&2; echo more >&2; exit 2"},
        {"fake_no_name", "echo \"error: bad\" >&2; exit 2"},
    };
    char dir[] = "/tmp/mcbox-cli-XXXXXX";
    assert_non_null(mkdtemp(dir));
    bool all = true;
    for (size_t i = 0; i < sizeof fakes / sizeof fakes[0]; i++) {
        char path[128], body[512];
        snprintf(path, sizeof path, "%s/%s", dir, fakes[i][0]);
        snprintf(body, sizeof body,
                 "case \"$1\" in --help) echo 'usage: x [--samples N] [--seed S]'; exit 0;;"
                 " --version) echo 1; exit 0;; esac\n%s",
                 fakes[i][1]);
        write_script(path, body);
        all &= negctl_record(&tally, fakes[i][0], "bad-input contract",
                             bad_input_cases(path, fakes[i][0], NULL, true) > 0);
        unlink(path);
    }
    /* A program whose bad flags are refused on their own but accepted after
     * its subcommand: only the subcommand pass can catch it. */
    char path[128];
    snprintf(path, sizeof path, "%s/fake_sub", dir);
    write_script(path, "case \"$1\" in --help) echo 'usage: fake_sub run|check [options]';"
                       " echo '  --samples N'; exit 0;; --version) echo 1; exit 0;;"
                       " run) exit 0;; esac\necho \"fake_sub: bad\" >&2; exit 2");
    char subs[MAX_SUBS][SUB_LEN];
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    const char *help[] = {"--help", NULL};
    run_prog(path, help, r);
    int n_subs = subcommands(r->out, "fake_sub", subs);
    free(r);
    assert_int_equal(bad_input_cases(path, "fake_sub", NULL, true), 0);
    int flagged = 0;
    for (int i = 0; i < n_subs; i++)
        flagged += bad_input_cases(path, "fake_sub", subs[i], true) > 0;
    /* Only "run" misbehaves; "check" (the second subcommand) is fine. */
    all &= negctl_record(&tally, "fake_sub (bad only after its subcommand)", "subcommand pass",
                         n_subs == 2 && flagged == 1);
    unlink(path);
    rmdir(dir);
    assert_true(all);
}

/* The scheme both benchmarks share for the book's programs (bench_render's
 * renderer, bench_mc's pi): bench, run with `timed` (which names a fake
 * book program that logs each run to `log`), exits 0 after running it
 * three times; its output is left in r. */
static void run_timed(const char *bench, const char *const *timed, const char *log, run *r)
{
    run_prog(bench, timed, r);
    assert_int_equal(r->status, 0);
    FILE *f = fopen(log, "r");
    assert_non_null(f);
    int runs = 0;
    for (int c; (c = fgetc(f)) != EOF;)
        runs += c == '\n';
    fclose(f);
    assert_int_equal(runs, 3);
}

/* The rest of the scheme: run with `constant` (no book program) the
 * output holds constant_line; a book program at prog that fails, and one
 * that is not there, are bad input, one line naming the benchmark. */
static void check_constant_and_bad(const char *bench, const char *name, const char *const *timed,
                                   const char *const *constant, const char *constant_line,
                                   const char *prog, run *r)
{
    char why[512];
    run_prog(bench, constant, r);
    assert_int_equal(r->status, 0);
    assert_non_null(strstr(r->out, constant_line));
    write_script(prog, "exit 3");
    run_prog(bench, timed, r);
    assert_null(judge_bad(name, r, why, sizeof why));
    assert_non_null(strstr(r->err, "failed"));
    unlink(prog);
    run_prog(bench, timed, r);
    assert_null(judge_bad(name, r, why, sizeof why));
    assert_non_null(strstr(r->err, "cannot be started"));
}

/* bench_render --book-program: the program named is run three times and
 * the median of its times replaces the constant of another machine in the
 * x_book figures; a program that cannot be started, or fails, is bad
 * input. Without it the header says the time is that constant. A fake
 * book program that logs each run and sleeps 0.3 s stands in for the
 * book's (the time is checked only from below: a sleep cannot be
 * shorter). */
static void test_cli_bench_book_program(void **state)
{
    (void)state;
    char bench[1024], dir[] = "/tmp/mcbox-book-XXXXXX", prog[128], log[128], body[512];
    snprintf(bench, sizeof bench, "%s/bench/bench_render", mc_test_build_dir());
    assert_int_equal(access(bench, X_OK), 0);
    assert_non_null(mkdtemp(dir));
    snprintf(prog, sizeof prog, "%s/book", dir);
    snprintf(log, sizeof log, "%s/runs", dir);
    snprintf(body, sizeof body, "echo run >> '%s'; sleep 0.3; echo P3", log);
    write_script(prog, body);
    /* The user's own settings must not turn on the 600x600 error tables. */
    unsetenv("MC_BOOK_PROGRAM");
    unsetenv("MC_REF_BOOK");
    unsetenv("MC_REF_LAMBERT");
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    const char *timed[] = {"--book-program", prog, "--width", "8", "--spp", "1", "--max-threads", "1",
                           NULL};
    run_timed(bench, timed, log, r);
    const char *key = "the book's program: ", *at = strstr(r->out, key);
    assert_non_null(at);
    char *end;
    double seconds = strtod(at + strlen(key), &end);
    printf("bench_render timed the fake book program: %.3f s, after 3 runs\n", seconds);
    assert_true(seconds >= 0.3);
    assert_int_equal(strncmp(end, " s (timed here", 14), 0);
    const char *constant[] = {"--width", "8", "--spp", "1", "--max-threads", "1", NULL};
    check_constant_and_bad(bench, "bench_render", timed, constant,
                           "the book's program: 68.3 s (a constant from another machine)", prog, r);
    free(r);
    unlink(log);
    rmdir(dir);
}

/* bench_mc --book-pi: the same scheme for the book's pi program. A fake
 * one that logs each run and sleeps 0.2 s; --quick keeps the loops short.
 * The header gives the median time (at least the sleep) and the points
 * per second it means, 2e8 over that time; without the option it names
 * the constant. */
static void test_cli_bench_book_pi(void **state)
{
    (void)state;
    char bench[1024], dir[] = "/tmp/mcbox-bookpi-XXXXXX", prog[128], log[128], body[512];
    snprintf(bench, sizeof bench, "%s/bench/bench_mc", mc_test_build_dir());
    assert_int_equal(access(bench, X_OK), 0);
    assert_non_null(mkdtemp(dir));
    snprintf(prog, sizeof prog, "%s/pi", dir);
    snprintf(log, sizeof log, "%s/runs", dir);
    snprintf(body, sizeof body, "echo run >> '%s'; sleep 0.2; echo 'Regular    Estimate of Pi = 3.14'",
             log);
    write_script(prog, body);
    unsetenv("MC_BOOK_PI");
    run *r = malloc(sizeof *r);
    assert_non_null(r);
    const char *timed[] = {"--book-pi", prog, "--quick", NULL};
    run_timed(bench, timed, log, r);
    const char *key = "vs book: the book's pi.cc, timed here: ", *at = strstr(r->out, key);
    assert_non_null(at);
    char *end;
    double seconds = strtod(at + strlen(key), &end);
    assert_int_equal(strncmp(end, " s for 200000000 points, ", 25), 0);
    double rate = strtod(end + 25, &end);
    printf("bench_mc timed the fake pi program: %.3f s, %.1f M points/s, after 3 runs\n", seconds,
           rate);
    assert_true(seconds >= 0.2);
    /* 2e8 points over the median time, as printed (to its rounding). */
    assert_true(fabs(rate - 200.0 / seconds) <= 0.05 + 200.0 / seconds * 0.01);
    const char *constant[] = {"--quick", NULL};
    check_constant_and_bad(bench, "bench_mc", timed, constant,
                           "vs book: 26.0 M points/s, a constant from another machine", prog, r);
    free(r);
    unlink(log);
    rmdir(dir);
}

static int report(void **state)
{
    (void)state;
    return negctl_report(&tally);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(void)
{
    static char *paths[MAX_PROGRAMS];
    static struct CMUnitTest tests[MAX_PROGRAMS + 7];
    static char names[MAX_PROGRAMS][96];
    size_t n = 0;
    /* Every program and every benchmark follows the same CLI rules. */
    static const char *const dirs[] = {"bin", "bench"};
    for (int k = 0; k < 2; k++) {
        char dir[1024];
        snprintf(dir, sizeof dir, "%s/%s", mc_test_build_dir(), dirs[k]);
        DIR *d = opendir(dir);
        for (struct dirent *e; d && (e = readdir(d)) && n < MAX_PROGRAMS;) {
            char path[2048];
            struct stat st;
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            if (e->d_name[0] != '.' && stat(path, &st) == 0 && S_ISREG(st.st_mode) &&
                access(path, X_OK) == 0)
                paths[n++] = strdup(path);
        }
        if (d)
            closedir(d);
    }
    qsort(paths, n, sizeof paths[0], by_name);
    /* No programs means the build directory is wrong: that must not pass. */
    if (n == 0) {
        fprintf(stderr, "test_cli: no programs in %s/bin or %s/bench\n", mc_test_build_dir(),
                mc_test_build_dir());
        return 1;
    }
    tests[0] = (struct CMUnitTest){"test_cli_negative_controls", test_cli_negative_controls, NULL, NULL,
                                   NULL};
    tests[1] = (struct CMUnitTest){"test_cli_statistics_na", test_cli_statistics_na, NULL, NULL, NULL};
    tests[2] = (struct CMUnitTest){"test_cli_one_grammar", test_cli_one_grammar, NULL, NULL, NULL};
    tests[3] = (struct CMUnitTest){"test_cli_long_runs_announce", test_cli_long_runs_announce, NULL, NULL,
                                   NULL};
    tests[4] = (struct CMUnitTest){"test_cli_bad_input_matrix", test_cli_bad_input_matrix, NULL, NULL, NULL};
    tests[5] = (struct CMUnitTest){"test_cli_bench_book_program", test_cli_bench_book_program, NULL, NULL,
                                   NULL};
    tests[6] = (struct CMUnitTest){"test_cli_bench_book_pi", test_cli_bench_book_pi, NULL, NULL, NULL};
    for (size_t i = 0; i < n; i++) {
        snprintf(names[i], sizeof names[i], "test_cli_%s", strrchr(paths[i], '/') + 1);
        tests[i + 7] = (struct CMUnitTest){names[i], test_cli_program, NULL, NULL, paths[i]};
    }
    int rc = _cmocka_run_group_tests("test_cli", tests, n + 7, NULL, report);
    for (size_t i = 0; i < n; i++)
        free(paths[i]);
    return rc;
}
