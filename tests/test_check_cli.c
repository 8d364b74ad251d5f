/* tests/test_check_cli.c - `mcbox-check` of $MC_BUILD/bin, the command-line
 * door of check/check.h: a correct cosine sampler passes through every door
 * (a catalog row behind `warp serve`, the Python and C examples of
 * docs/protocol/, a text file of `warp sample`, raw f64 and f32 files), with
 * the C API's statistic to the bit; wrong samplers and densities are
 * rejected (exit 1); every malformed file and every misbehaving program is
 * bad input (exit 2, one line on stderr naming the line, sample or command,
 * nothing on stdout); the reports (--json, --junit, --plot) are written.
 * Every case of the sampler catalog passes through both doors (`warp
 * serve` and `warp sample`), and every catalog negative control is
 * rejected through both. By value: --atom's coordinates and counts, the
 * --plot data and the --json fields against the C API and closed forms,
 * the reported pdf just inside and just outside --pdf-tol, and the
 * readers' bounds (protocol lines, fields, batches, file lines, raw
 * records) at exactly full, one short and one over. No verdict still
 * writes --json and --junit; a program slow to exit keeps its verdict;
 * several assignments per --param; every `warp list` row described.
 * Seeds are fixed (7 for the uniforms, 3 for the files' samples); each
 * program run has a 120 s limit (timeout(1)).
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, realpath, WEXITSTATUS with system() */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <limits.h>
#include <unistd.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "tests/support/negctl.h"

enum { CAPTURE = 1 << 16 };

static char tmp[64];       /* this run's scratch directory */
static char root[2048];    /* the source tree, absolute ($MC_SOURCE or .) */

typedef struct run {
    int status;
    char out[CAPTURE], err[CAPTURE];
} run;

static run *r_; /* one capture buffer, reused */

/* Runs `mcbox-check ARGS` (shell words) from the build's bin directory. */
static run *check(const char *args)
{
    char cmd[8192], path[256];
    snprintf(cmd, sizeof cmd, "cd %s/bin && timeout -s KILL 120 ./mcbox-check %s >%s/out 2>%s/err",
             mc_test_build_dir(), args, tmp, tmp);
    int rc = system(cmd);
    r_->status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    snprintf(path, sizeof path, "%s/out", tmp);
    mc_test_read_text(path, r_->out, sizeof r_->out);
    snprintf(path, sizeof path, "%s/err", tmp);
    mc_test_read_text(path, r_->err, sizeof r_->err);
    return r_;
}

/* Runs a shell command from the build's bin directory; its exit status. */
static int shell(const char *fmt, const char *arg)
{
    char body[4096], cmd[8192];
    snprintf(body, sizeof body, fmt, arg);
    snprintf(cmd, sizeof cmd, "cd %s/bin && %s", mc_test_build_dir(), body);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static void write_file(const char *name, const void *data, size_t len)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", tmp, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, len, f), len);
    fclose(f);
}

static void write_text(const char *name, const char *text)
{
    write_file(name, text, strlen(text));
}

/* The number after "key": in a JSON object (NaN for null or missing). */
static double json_num(const char *json, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    return p && strncmp(p + strlen(k), "null", 4) != 0 ? strtod(p + strlen(k), NULL) : (double)NAN;
}

/* Whether r is a pass (status 0) whose JSON says so; prints what it got. */
static bool passed(const char *what, const run *r)
{
    bool ok = r->status == 0 && strstr(r->out, "\"pass\": true") != NULL;
    printf("%s: status %d, chi-square %.6g, dof %g, p %.4g%s%s", what, r->status,
           json_num(r->out, "statistic"), json_num(r->out, "dof"), json_num(r->out, "pvalue"),
           ok ? "\n" : ", stderr: ", ok ? "" : r->err);
    return ok;
}

/* Whether r is a verdict of fail (status 1) with a message containing
 * `why`. */
static bool rejected(const run *r, const char *why)
{
    return r->status == 1 && strstr(r->out, "FAIL") && strstr(r->out, why);
}

/* Whether r kept the bad-input contract with a message containing `want`
 * (or one of its alternatives separated by '|'). */
static bool refused(const char *what, const run *r, const char *want)
{
    const char *nl = strchr(r->err, '\n');
    bool named = false;
    for (const char *w = want; *w;) {
        size_t len = strcspn(w, "|");
        char one[256];
        snprintf(one, sizeof one, "%.*s", (int)len, w);
        named = named || strstr(r->err, one) != NULL;
        w += len + (w[len] == '|');
    }
    bool ok = r->status == 2 && r->out[0] == '\0' && strncmp(r->err, "mcbox-check: ", 13) == 0 &&
              nl && nl[1] == '\0' && named;
    printf("%s: %s%s", what, ok ? "" : "NOT REFUSED AS REQUIRED: ", r->err);
    if (!ok)
        printf("  (status %d, %zu bytes on stdout, expected '%s' in the message)\n", r->status,
               strlen(r->out), want);
    return ok;
}

/* --- the C API's statistic, in process ------------------------------------ */

static cat_state cosine_row;

static void cosine_sample(const double *u, mcbox_sample *out, void *ctx)
{
    cosine_row.row->sample_u(ctx, u, out->x);
}

/* As `warp serve` answers pdf: the direction normalized first. */
static void cosine_pdf_batch(const double *x, size_t n, double *out, void *ctx)
{
    for (size_t i = 0; i < n; i++) {
        double v[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
        double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        v[0] /= l, v[1] /= l, v[2] /= l;
        out[i] = isfinite(v[0]) ? cat_pdf(ctx, v) : 0.0;
    }
}

/* A catalog row behind `warp serve`, through the pipe, passes, and gives
 * the statistic, dof and p-value of mcbox_check_run on the same sampler
 * and density in process, to the last bit. */
static void test_check_cli_exec_matches_c_api(void **state)
{
    (void)state;
    char err[200];
    assert_true(cat_prepare_named("cosine", &cosine_row, err, sizeof err));
    mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
    s.sample = cosine_sample, s.pdf_batch = cosine_pdf_batch, s.ctx = &cosine_row;
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = 200000, o.seed = 7;
    mcbox_check_result want;
    assert_int_equal(mcbox_check_run(&s, &o, &want, NULL), 0);
    run *r = check("--exec './warp serve cosine' --domain hemisphere --n 2e5 --seed 7 --invert --json");
    assert_seeded(passed("warp serve cosine", r), 7);
    assert_true(json_num(r->out, "statistic") == want.statistic);
    assert_true(json_num(r->out, "pvalue") == want.pvalue);
    assert_int_equal((int)json_num(r->out, "dof"), want.dof);
    assert_true(json_num(r->out, "invert_error") < 1e-12);
    printf("C API: chi-square %.17g, p %.17g: the same bits\n", want.statistic, want.pvalue);
}

/* The shipped examples of docs/protocol/ pass: the Python one (skipped
 * without python3) and the C one, compiled with the system's cc; both
 * report their pdf and answer invert. */
static void test_check_cli_protocol_examples(void **state)
{
    (void)state;
    char args[4096];
    if (shell("command -v python3 >/dev/null 2>&1%s", "") == 0) {
        snprintf(args, sizeof args,
                 "--exec 'python3 %s/docs/protocol/cosine.py' --domain hemisphere --n 1e5 --seed 7 "
                 "--invert --json", root);
        run *r = check(args);
        assert_seeded(passed("docs/protocol/cosine.py", r), 7);
        assert_true(json_num(r->out, "pdf_reported") == 1e5);
        assert_true(json_num(r->out, "pdf_mismatch") < 1e-12);
    } else {
        printf("docs/protocol/cosine.py: skipped, no python3 on this machine\n");
    }
    char cc[4096];
    snprintf(cc, sizeof cc, "cc -O2 -o %s/cosine %s/docs/protocol/cosine.c -lm", tmp, root);
    assert_int_equal(shell("%s", cc), 0);
    snprintf(args, sizeof args, "--exec %s/cosine --domain hemisphere --n 1e5 --seed 7 --invert --json",
             tmp);
    run *r = check(args);
    assert_seeded(passed("docs/protocol/cosine.c", r), 7);
    assert_true(json_num(r->out, "invert_error") < 1e-12);
}

/* Points from files: `warp sample` output as text (and with a UTF-8 BOM,
 * a header and a comment), raw f64 and f32 records of the row's samples,
 * all against --pdf cosine. */
static void test_check_cli_sample_files(void **state)
{
    (void)state;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "./warp sample cosine --n 100000 --seed 3 >%s/cos.txt", tmp);
    assert_int_equal(shell("%s", cmd), 0);
    char args[512];
    snprintf(args, sizeof args, "--samples %s/cos.txt --pdf cosine --json", tmp);
    assert_seeded(passed("warp sample cosine | --samples", check(args)), 3);
    snprintf(cmd, sizeof cmd, "{ printf '\\357\\273\\277x,y,z\\r\\n# cosine\\r\\n'; cat %s/cos.txt; } >%s/bom.txt",
             tmp, tmp);
    assert_int_equal(shell("%s", cmd), 0);
    snprintf(args, sizeof args, "--samples %s/bom.txt --pdf cosine --json", tmp);
    assert_seeded(passed("UTF-8 BOM, header, comment, CRLF", check(args)), 3);
    /* Raw records of the row's own samples. */
    cat_state st;
    char err[200];
    assert_true(cat_prepare_named("cosine", &st, err, sizeof err));
    mc_rng rng = mc_rng_derive(3u, 1u);
    enum { N = 100000 };
    double *d = malloc(N * 3 * sizeof *d);
    float *f = malloc(N * 3 * sizeof *f);
    assert_true(d && f);
    for (int i = 0; i < N; i++) {
        cat_sample(&st, &rng, d + 3 * i);
        for (int j = 0; j < 3; j++)
            f[3 * i + j] = (float)d[3 * i + j];
    }
    write_file("cos.f64", d, N * 3 * sizeof *d); /* x86-64: little-endian already */
    write_file("cos.f32", f, N * 3 * sizeof *f);
    free(d);
    free(f);
    snprintf(args, sizeof args, "--samples %s/cos.f64 --format f64 --pdf cosine --json", tmp);
    assert_seeded(passed("raw f64", check(args)), 3);
    snprintf(args, sizeof args, "--samples - --format f32 --pdf cosine --json <%s/cos.f32", tmp);
    assert_seeded(passed("raw f32 on stdin", check(args)), 3);
}

/* --- every row of the catalog through both doors ------------------------- */

/* " --param k=v ..." for a case's "k=v k=v" (empty for NULL). */
static void param_words(const char *params, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (const char *p = params ? params : ""; *p;) {
        size_t len = strcspn(p, " ");
        if (len)
            used += (size_t)snprintf(out + used, size - used, " --param %.*s", (int)len, p);
        p += len + (p[len] == ' ');
    }
    assert_true(used < size);
}

/* The verdict of ROW (with a case's parameters and chart) through `warp
 * serve` behind --exec, and through `warp sample` into --samples with
 * --pdf ROW: 0 pass, 1 fail, anything else is printed and returned. */
/* Whether row_door leaves a row whose density is infinite at the pole on
 * its default chart through --exec (else it gets a lobe chart there). */
static bool plain_pole_chart;

static int row_door(const cat_row *row, const cat_case *tc, bool samples, const char *n,
                    uint64_t seed, int tests)
{
    char params[512], chart[96] = "", args[2048];
    param_words(tc ? tc->params : NULL, params, sizeof params);
    if (tc && tc->cells[0] > 0)
        snprintf(chart, sizeof chart, tc->cells[1] > 0 ? " --cells %dx%d" : " --cells %d",
                 tc->cells[0], tc->cells[1]);
    if (tc && tc->lobe_width > 0.0)
        snprintf(chart + strlen(chart), sizeof chart - strlen(chart), " --lobe-width %.17g",
                 tc->lobe_width);
    /* Fixed rules cannot certify a density infinite at the pole of the
     * (cos theta, phi) chart (their error falls as the square root of the
     * part's width there); a lobe chart about the pole makes it smooth. */
    else if (!samples && row->pole_infinite && !plain_pole_chart)
        snprintf(chart + strlen(chart), sizeof chart - strlen(chart), " --lobe-width 0.5");
    if (samples) {
        char cmd[1024];
        snprintf(cmd, sizeof cmd, "./warp sample %s%s --n %s --seed %llu >%s/row.txt", row->name,
                 params, n, (unsigned long long)seed, tmp);
        assert_int_equal(shell("%s", cmd), 0);
        snprintf(args, sizeof args, "--samples %s/row.txt --pdf %s%s%s --tests %d --json", tmp,
                 row->name, params, chart, tests);
    } else {
        snprintf(args, sizeof args,
                 "--exec './warp serve %s%s' --domain %s%s%s --n %s --seed %llu --tests %d --json",
                 row->name, params, row->name, params, chart, n, (unsigned long long)seed, tests);
    }
    run *r = check(args);
    if (r->status == 0 || r->status == 1) {
        printf("  %-22s %-8s %s: chi-square %10.2f, dof %4g, p %.3g, integral %.7f\n",
               tc ? tc->name : row->name, samples ? "samples" : "exec", r->status ? "fail" : "pass",
               json_num(r->out, "statistic"), json_num(r->out, "dof"), json_num(r->out, "pvalue"),
               json_num(r->out, "pdf_integral"));
        const char *m = strstr(r->out, "\"message\": \"");
        if (r->status == 1 && m)
            printf("    %.*s\n", (int)strcspn(m + 12, "\""), m + 12);
    }
    else
        printf("  %s (%s): status %d: %s", tc ? tc->name : row->name, samples ? "samples" : "exec",
               r->status, r->err);
    return r->status;
}

/* Whether the build runs under AddressSanitizer (gcc's macro, clang's
 * feature test). */
#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

/* Every case of every catalog row passes through one of the two doors,
 * --exec for the even positions in the catalog and --samples for the odd
 * ones (so each door sees half the rows, and tests/test_check.c puts every
 * case through the C API), 3 x 10^4 samples each, seed 11 + the case's
 * position (under the sanitizers, half of them); the family-wise level
 * 0.01 is shared over all of them (Sidak, --tests), so a correct catalog
 * fails this test with probability 0.01.
 * Every negative control of the catalog is rejected through both doors at
 * the same per-test level with 2 x 10^4 samples, seed 11 + its position. */
static void test_check_cli_every_row(void **state)
{
    negctl *t = *state;
    int cases = 0;
    for (size_t i = 0; i < cat_count(); i++)
        for (const cat_case *tc = cat_at(i)->cases; tc->name; tc++)
            cases++;
    int kept = 2 * (cases / 4) + (cases % 4 < 2 ? cases % 4 : 2);
    int tests = SANITIZED ? kept : cases, k = 0, failures = 0;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *row = cat_at(i);
        for (const cat_case *tc = row->cases; tc->name; tc++, k++) {
            int door = k % 2;
            /* Under the sanitizers, which look for memory errors rather
             * than statistics, every other case is enough to run every
             * row's parameters through the parsers of both doors' kinds. */
            if (SANITIZED && k % 4 >= 2)
                continue;
            if (row_door(row, tc, door == 1, "3e4", 11u + (uint64_t)k, tests) != 0) {
                failures++;
                print_error("%s through %s: seed %d\n", tc->name, door ? "--samples" : "--exec",
                            11 + k);
            }
        }
    }
    printf("catalog through mcbox-check: %d cases, one door each, %d failures\n", cases, failures);
    /* On its default chart the pole's row is a doubt, said as one (exit 2). */
    const cat_row *pole = cat_find("theta-phi");
    assert_non_null(pole);
    assert_true(pole->pole_infinite);
    plain_pole_chart = true;
    int st = row_door(pole, pole->cases, false, "3e4", 11u, tests);
    plain_pole_chart = false;
    printf("theta-phi through --exec on (cos theta, phi): exit %d (undetermined: 2)\n", st);
    assert_int_equal(st, 2);
    bool all = true;
    for (size_t i = 0; i < cat_negative_count(); i++) {
        const cat_row *row = cat_negative_at(i);
        /* Phong's n + 1 against n is subtle at the row's n = 40 (the C
         * API's test shows it with 10^6 samples); at n = 3, 2 x 10^4 do
         * (statistic 793 on 84 degrees of freedom, p 6e-116; the others
         * give statistics of 5000 and more on 55 to 98). */
        cat_case neg = {.name = row->name,
                        .params = strcmp(row->name, "wrong-phong-exponent") == 0 ? "n=3" : NULL};
        for (int door = 0; door < 2; door++) {
            char name[96];
            snprintf(name, sizeof name, "catalog %s", row->name);
            all &= negctl_record(t, name, door ? "mcbox-check --samples" : "mcbox-check --exec",
                                 row_door(row, &neg, door == 1, "2e4", 11u + i, tests) == 1);
        }
    }
    assert_int_equal(failures, 0);
    assert_true(all);
}

/* --- negative controls --------------------------------------------------- */

/* A tiny C sampler of the cosine lobe, compiled with the system's cc into
 * the scratch directory as `name`; pdf_answer is the C statement that
 * answers a pdf item, with z the point's third coordinate. */
static void build_sampler(const char *name, const char *pdf_answer)
{
    static const char head[] =
        "#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n"
        "int main(void) {\n  char line[512], cmd[16]; long k; const double pi = 3.14159265358979324;\n"
        "  while (fgets(line, sizeof line, stdin)) {\n"
        "    if (strncmp(line, \"hello\", 5) == 0) puts(\"ok\");\n"
        "    else if (sscanf(line, \"%15s %ld\", cmd, &k) == 2)\n"
        "      for (long i = 0; i < k && fgets(line, sizeof line, stdin); i++) {\n"
        "        double v[3] = {0, 0, 0}; char *p = line;\n"
        "        for (int j = 0; j < 3; j++) v[j] = strtod(p, &p);\n"
        "        if (cmd[0] == 's') { double r = sqrt(v[0]), phi = 2 * pi * v[1];\n"
        "          printf(\"%.17g %.17g %.17g\\n\", r * cos(phi), r * sin(phi), sqrt(1 - v[0])); }\n"
        "        else { double z = v[2]; (void)pi; ";
    static const char tail[] = "; }\n      }\n    fflush(stdout);\n  }\n  return 0;\n}\n";
    char src[64], cmd[512];
    snprintf(src, sizeof src, "%s.c", name);
    char *text = malloc(sizeof head + strlen(pdf_answer) + sizeof tail);
    assert_non_null(text);
    snprintf(text, sizeof head + strlen(pdf_answer) + sizeof tail, "%s%s%s", head, pdf_answer, tail);
    write_text(src, text);
    free(text);
    snprintf(cmd, sizeof cmd, "cc -O2 -o %s/%s %s/%s -lm", tmp, name, tmp, src);
    assert_int_equal(shell("%s", cmd), 0);
}

/* Wrong samplers and densities must be rejected (exit 1) with the message
 * of the check that caught them. */
static void test_check_cli_negative_controls(void **state)
{
    negctl *t = *state;
    char args[1024];
    bool all = true;
    /* A cosine sampler whose density is z, not z / pi: it integrates to pi. */
    build_sampler("nopi", "printf(\"%.17g\\n\", z >= 0 ? z : 0.0)");
    snprintf(args, sizeof args, "--exec %s/nopi --domain hemisphere --n 2e4 --seed 7", tmp);
    run *r = check(args);
    printf("%s", r->out);
    all &= negctl_record(t, "C cosine sampler, pdf without 1/pi", "normalization (exit 1)",
                         rejected(r, "integrates to 3.14159"));
    /* Uniform hemisphere samples checked against the cosine density. */
    char cmd[512];
    snprintf(cmd, sizeof cmd, "./warp sample hemisphere --n 100000 --seed 3 >%s/hemi.txt", tmp);
    assert_int_equal(shell("%s", cmd), 0);
    snprintf(args, sizeof args, "--samples %s/hemi.txt --pdf cosine", tmp);
    r = check(args);
    printf("%s", r->out);
    all &= negctl_record(t, "hemisphere samples against --pdf cosine", "chi-square (exit 1)",
                         rejected(r, "chi-square"));
    /* Densities that are negative or NaN somewhere: a failed verdict. */
    snprintf(cmd, sizeof cmd, "./warp sample cosine --n 100000 --seed 3 >%s/cos.txt", tmp);
    assert_int_equal(shell("%s", cmd), 0);
    build_sampler("negpdf", "printf(\"%.17g\\n\", z < 0.5 ? -1.0 : z / pi)");
    snprintf(args, sizeof args, "--samples %s/cos.txt --pdf-exec %s/negpdf --domain hemisphere", tmp,
             tmp);
    r = check(args);
    printf("%s", r->out);
    all &= negctl_record(t, "a density that is negative below z = 0.5", "density values (exit 1)",
                         rejected(r, "negative or non-finite"));
    build_sampler("nanpdf", "if (z < 0.5) puts(\"nan\"); else printf(\"%.17g\\n\", z / pi)");
    snprintf(args, sizeof args, "--samples %s/cos.txt --pdf-exec %s/nanpdf --domain hemisphere", tmp,
             tmp);
    r = check(args);
    printf("%s", r->out);
    all &= negctl_record(t, "a density that is NaN below z = 0.5", "density values (exit 1)",
                         rejected(r, "negative or non-finite"));
    assert_true(all);
}

/* --- bad input ----------------------------------------------------------- */

/* Malformed sample files: each refused with the line or sample named. */
static void test_check_cli_bad_files(void **state)
{
    (void)state;
    static const struct {
        const char *name, *text, *format, *want;
    } cases[] = {
        {"short.txt", "0 0 1\n0.6 0.8\n", "csv", "line 2: 2 fields, expected 3"},
        {"long.txt", "0 0 1 0.3183\n", "csv", "line 1: more than 3 fields"},
        {"text.txt", "# x y z\n0 0 1\n0 zero 1\n", "csv", "line 3: field 2: 'zero' is not a number"},
        {"nan.txt", "0 0 1\n0 0 nan\n", "csv", "line 2: field 3: 'nan' is not finite"},
        {"inf.txt", "x y z\n-inf 0 1\n", "csv", "line 2: field 1: '-inf' is not finite"},
        {"empty.txt", "", "csv", "no samples (the file is empty)"},
        {"comments.txt", "# nothing\n\n", "csv", "no samples"},
        {"utf16.txt", "\xff\xfe" "0\0 \0" "0\0", "csv", "line 1: UTF-16"},
        {"trunc.f32", "\0\0\0\0\0\0\0\0\0\0\x80\x3f" "\0\0\0\0\0", "f32",
         "sample 2 (byte 12): truncated record"},
        {"nan.f64", "\0\0\0\0\0\0\xf8\x7f", "f64", "sample 1 (byte 0): coordinate 1 is NaN"},
    };
    int failures = 0;
    char args[512];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t len = strlen(cases[i].text);
        if (strstr(cases[i].name, "utf16"))
            len = 8;
        if (strstr(cases[i].name, ".f"))
            len = strstr(cases[i].name, "f32") ? 17 : 8;
        write_file(cases[i].name, cases[i].text, len);
        bool interval = strstr(cases[i].name, "f64") != NULL;
        snprintf(args, sizeof args, "--samples %s/%s --format %s --pdf %s", tmp, cases[i].name,
                 cases[i].format, interval ? "linear" : "cosine");
        failures += !refused(cases[i].name, check(args), cases[i].want);
    }
    /* Raw records read as text: named as binary, with the option to pass. */
    double raw[6] = {0.25, 0.5, 0.8, 0.1, 0.2, 0.9};
    write_file("raw-as-text.f64", raw, sizeof raw);
    snprintf(args, sizeof args, "--samples %s/raw-as-text.f64 --pdf cosine", tmp);
    failures += !refused("f64 read as csv", check(args), "looks binary (byte 0 is 0x00, not text): "
                                                           "pass --format f32 or f64");
    /* A line of a million columns: refused before it is split. */
    size_t n = 2000000;
    char *big = malloc(n + 1);
    assert_non_null(big);
    for (size_t i = 0; i < n; i += 2)
        big[i] = '0', big[i + 1] = ' ';
    big[n] = '\n';
    write_file("wide.txt", big, n + 1);
    free(big);
    snprintf(args, sizeof args, "--samples %s/wide.txt --pdf cosine", tmp);
    failures += !refused("a million columns", check(args), "line 1: longer than 1 MiB");
    assert_int_equal(failures, 0);
}

/* Programs that break the protocol: each run ends with exit 2, the
 * program killed and reaped, one line naming the command and what is
 * wrong; nothing on stdout (never a verdict from half the data). */
static void test_check_cli_bad_programs(void **state)
{
    (void)state;
    /* A shell sampler answering each item with the line ANSWER. */
#define SH_SAMPLER(answer)                                                                         \
    "read h; echo ok; while read c k; do i=0; while [ $i -lt $k ]; do read u; " answer            \
    "; i=$((i+1)); done; done"
    static const struct {
        const char *name, *script, *extra, *want;
    } cases[] = {
        {"crash", "kill -SEGV $$", "", "killed by signal 11"},
        {"hang", "sleep 100 & echo $! >HANG_PID; wait", "--timeout 1", "within the 1 s of --timeout"},
        {"garbage", "while read l; do echo 'hello there'; done", "", "hello: answer 1 of 1: 'hello ...', not 'ok'"},
        {"few-values", SH_SAMPLER("echo 0 0"), "", "answer 1 of 10: 2 values, expected 3"},
        {"many-values", SH_SAMPLER("echo 0 0 1 0.3 1 7"), "", "answer 1 of 10: 6 values"},
        {"text-value", SH_SAMPLER("echo 0 zero 1"), "", "value 2: 'zero' is not a number"},
        /* K + 1 lines in one write: read together with the K answers. */
        {"many-lines",
         "read h; echo ok; while read c k; do i=0; s=''; while [ $i -lt $k ]; do read u; "
         "s=\"$s 0 0 1\\n\"; i=$((i+1)); done; printf \"$s 0 0 1\\n\"; done",
         "", "more output than the 10 answer lines asked for"},
        /* One line too many per item, in separate writes: read with the
         * answers, or before the next command, or as its answers. */
        {"many-lines-slow", SH_SAMPLER("echo 0 0 1; echo 0 0 1"), "",
         "more output than|values, expected 1"},
        {"few-lines", "read h; echo ok; read c k; read u; echo 0 0 1; sleep 100", "--timeout 1",
         "1 of 10 answers read"},
        {"close-stdout", "read h; echo ok; exec >&-; sleep 100", "", "closed its stdout"},
        {"exit-early", SH_SAMPLER("echo 0 0 1; exit 3"), "", "exited with status 3"},
        {"error", "read h; echo 'error no such domain'", "", "reported an error: 'no such domain'"},
        /* The bytes follow the first command, not the hello: sent with the
         * hello's 'ok' they are extra output of the hello instead, and which
         * of the two a read sees depends on the scheduler. */
        {"binary", "read h; printf 'ok\\n'; read c k; head -c 5000 /dev/zero; sleep 100", "",
         "longer than 4096 bytes (garbage"},
    };
    int failures = 0;
    char args[1024], file[64];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(file, sizeof file, "%s.sh", cases[i].name);
        char script[512], *at;
        snprintf(script, sizeof script, "%s", cases[i].script);
        if ((at = strstr(script, "HANG_PID")) != NULL) /* the sleep's pid, into the scratch dir */
            snprintf(at, sizeof script - (size_t)(at - script), "%s/hang.pid; wait", tmp);
        write_text(file, script);
        /* Sourced by the shell mcbox-check starts: `exec >&-` and `kill $$`
         * act on that shell itself, which no parent shell outlives. */
        snprintf(args, sizeof args, "--exec '. %s/%s' --domain hemisphere --n 10 %s", tmp, file,
                 cases[i].extra);
        failures += !refused(cases[i].name, check(args), cases[i].want);
    }
    /* The hang was cut at its timeout, and nothing of it is left running:
     * its sleep (a grandchild) was killed with the program's process group. */
    assert_int_equal(shell("sleep 0.3; kill -0 $(cat %s/hang.pid) 2>/dev/null", tmp), 1);
    assert_int_equal(failures, 0);
#undef SH_SAMPLER
}

/* Options that make no sense together, or are malformed. */
static void test_check_cli_bad_options(void **state)
{
    (void)state;
    static const char *const cases[][2] = {
        {"--exec ./warp", "needs --domain"},
        {"--exec x --samples y --domain disc", "exclude each other"},
        {"--samples x", "needs a density"},
        {"--samples x --pdf cosine --pdf-exec y --domain disc", "not both"},
        {"--samples x --pdf nope", "unknown catalog row 'nope'"},
        {"--samples x --pdf phong --param n=-1", "n must be"},
        {"--exec x --domain plane", "'plane' is neither a domain (interval, square, disc, triangle, "
                                    "sphere, hemisphere, cap, spherical-triangle, spherical-quad)"},
        {"--exec x --domain cap", "--domain cap needs --param cos_max"},
        {"--exec x --domain cap --param 'axis=0,0,1 cos_max=0.9 n=3'", "cap takes axis"},
        {"--exec x --domain cap --param axis=0,1 --param cos_max=0.9", "three finite numbers"},
        {"--exec x --domain spherical-triangle --param 'a=0,0,1 b=1,0,1'", "needs --param c="},
        {"--exec x --domain spherical-quad --param corner=0,0,1", "needs --param u="},
        {"--exec x --domain phong --param 'n=3 =4'", "'=4' is not key=value"},
        {"--exec x --domain disc --lobe-axis 0,0,0", "--lobe-axis"},
        {"--exec x --domain disc --norm-tol -1", "--norm-tol"},
        {"--exec x --domain disc --pdf-tol nan", "--pdf-tol"},
        {"--exec x --domain disc --quad-order 65", "--quad-order"},
        {"--exec x --domain disc --quad-depth 31", "--quad-depth"},
        {"--exec x --domain disc --quad-error-max 0", "--quad-error-max"},
        {"--exec x --domain disc --param n=1", "--param applies to a catalog row or to the domains cap"},
        {"--exec x --domain disc --interval 0,1", "--domain interval only"},
        {"--exec x --domain interval --interval 1,0", "finite A < B"},
        {"--exec x --domain disc --uniforms 17", "--uniforms"},
        {"--exec x --domain disc --uniforms 0 --invert", "--invert needs uniforms"},
        {"--exec x --domain disc --atom 1,2,3:0.5", "--atom"},
        {"--exec x --domain disc --atom 0,0:1.5", "--atom"},
        {"--exec x --domain disc --cells 0x5", "--cells"},
        {"--exec x --domain disc --tests 0", "--tests"},
        {"--exec x --domain disc --timeout 0", "--timeout"},
        {"--exec x --domain disc --name a/b", "--name"},
        {"--exec x --domain disc --format f32", "does not take --format"},
        {"--samples x --pdf cosine --seed 3", "does not take --seed"},
        {"--exec x --domain disc --invert --invert", "given twice"},
        {"--exec x --domain disc --plot /nonexistent-dir", "not a writable directory"},
        {"--exec x --domain disc --junit /nonexistent-dir/x.xml", "--junit"},
        {"--samples /nonexistent-file --pdf cosine", "cannot open"},
        {"--exec 'sleep 100' --domain disc --n 0", "--n"},
    };
    int failures = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        failures += !refused(cases[i][0], check(cases[i][0]), cases[i][1]);
    assert_int_equal(failures, 0);
}

/* --- reports --------------------------------------------------------------- */

/* The human summary names the verdict and the figures; --junit writes a
 * suite of one test case (a failure element on fail); --plot writes the
 * data file and a PNG. */
static void test_check_cli_reports(void **state)
{
    (void)state;
    char args[1024], path[256], text[4096];
    snprintf(args, sizeof args,
             "--exec './warp serve linear' --domain interval --interval 0,2 --uniforms 1 --n 2e4 "
             "--name lin --junit %s/lin.xml --plot %s", tmp, tmp);
    run *r = check(args);
    printf("%s%s", r->out, r->err);
    assert_int_equal(r->status, 0);
    assert_non_null(strstr(r->out, "lin: pass"));
    assert_non_null(strstr(r->out, "chi-square"));
    assert_non_null(strstr(r->out, "pdf integral"));
    snprintf(path, sizeof path, "%s/lin.xml", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "<testsuite name=\"mcbox-check\" tests=\"1\" failures=\"0\""));
    assert_null(strstr(text, "<failure"));
    snprintf(path, sizeof path, "%s/lin.png", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_memory_equal(text, "\x89PNG", 4);
    snprintf(path, sizeof path, "%s/lin.dat", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "# lin: chart cells"));
    /* A 2D chart, and a failing check's JUnit. */
    snprintf(args, sizeof args,
             "--samples %s/hemi.txt --pdf cosine --name hemi --junit %s/hemi.xml --plot %s --json",
             tmp, tmp, tmp);
    r = check(args);
    assert_int_equal(r->status, 1);
    assert_non_null(strstr(r->out, "\"pass\": false"));
    assert_true(json_num(r->out, "samples") == 1e5);
    assert_true(json_num(r->out, "pvalue") < 1e-6);
    snprintf(path, sizeof path, "%s/hemi.xml", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "failures=\"1\""));
    assert_non_null(strstr(text, "<failure type=\"fail\" message=\"chi-square"));
    snprintf(path, sizeof path, "%s/hemi.png", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_memory_equal(text, "\x89PNG", 4);
}

/* --- by value: atoms, plot data, JSON, the pdf tolerance, readers' bounds -- */

/* The C program of a sampler with an atom at +z of mass 0.3 and a cosine
 * lobe of mass 0.7: u1 < 0.3 answers "atom 0", else the lobe from u1
 * rescaled to [0, 1); its density 0.7 z / pi. */
static const char ATOM_SAMPLER[] =
    "#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n"
    "int main(void) {\n  char line[512], cmd[16]; long k; const double pi = 3.14159265358979324;\n"
    "  while (fgets(line, sizeof line, stdin)) {\n"
    "    if (strncmp(line, \"hello\", 5) == 0) puts(\"ok\");\n"
    "    else if (sscanf(line, \"%15s %ld\", cmd, &k) == 2)\n"
    "      for (long i = 0; i < k && fgets(line, sizeof line, stdin); i++) {\n"
    "        double v[3] = {0, 0, 0}; char *p = line;\n"
    "        for (int j = 0; j < 3; j++) v[j] = strtod(p, &p);\n"
    "        if (cmd[0] == 's' && v[0] < 0.3) puts(\"atom 0\");\n"
    "        else if (cmd[0] == 's') { double u = (v[0] - 0.3) / 0.7, r = sqrt(u), phi = 2 * pi * v[1];\n"
    "          printf(\"%.17g %.17g %.17g\\n\", r * cos(phi), r * sin(phi), sqrt(1 - u)); }\n"
    "        else printf(\"%.17g\\n\", v[2] >= 0 ? 0.7 * v[2] / pi : 0.0);\n"
    "      }\n    fflush(stdout);\n  }\n  return 0;\n}\n";

static void atom_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    if (u[0] < 0.3) {
        out->atom = 0;
        out->x[0] = out->x[1] = 0.0, out->x[2] = 1.0;
        return;
    }
    double v = (u[0] - 0.3) / 0.7, r = sqrt(v), phi = 2 * 3.14159265358979324 * u[1];
    out->x[0] = r * cos(phi), out->x[1] = r * sin(phi), out->x[2] = sqrt(1 - v);
}

static void atom_pdf_batch(const double *x, size_t n, double *out, void *ctx)
{
    (void)ctx;
    for (size_t i = 0; i < n; i++)
        out[i] = x[3 * i + 2] >= 0 ? 0.7 * x[3 * i + 2] / 3.14159265358979324 : 0.0;
}

/* The array "key": [a, b, c] of a JSON text into v (n numbers); false when
 * absent. */
static bool json_array(const char *json, const char *key, double *v, int n)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": [", key);
    const char *p = strstr(json, k);
    if (!p)
        return false;
    p += strlen(k);
    for (int j = 0; j < n; j++) {
        char *end;
        v[j] = strtod(p, &end);
        if (end == p)
            return false;
        p = end + strspn(end, ", ");
    }
    return true;
}

/* --atom reaches the check with its coordinates and mass: "atom 0" answers
 * are the atom at +z, the run passes with no bad atom, and the atom's cell
 * holds the count the C API gives for the same sampler and seed (the
 * uniforms below 0.3, counted here too), expected 0.3 n. */
static void test_check_cli_atoms_by_value(void **state)
{
    (void)state;
    char src[256], cmd[768], args[1024];
    snprintf(src, sizeof src, "%s/atom.c", tmp);
    write_text("atom.c", ATOM_SAMPLER);
    snprintf(cmd, sizeof cmd, "cc -O2 -o %s/atom %s -lm", tmp, src);
    assert_int_equal(shell("%s", cmd), 0);
    snprintf(args, sizeof args, "--exec %s/atom --domain hemisphere --atom 0,0,1:0.3 --n 5e4 --seed 7 "
             "--json", tmp);
    run *r = check(args);
    assert_seeded(passed("atom at +z, mass 0.3", r), 7);
    assert_true(json_num(r->out, "bad_atoms") == 0.0);
    double x[3], mass = json_num(strstr(r->out, "\"atoms\""), "mass");
    assert_true(json_array(strstr(r->out, "\"atoms\""), "x", x, 3));
    assert_true(x[0] == 0.0 && x[1] == 0.0 && x[2] == 1.0 && mass == 0.3);
    /* The same through the C API, and the uniforms counted directly. */
    mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
    double ax[3] = {0.0, 0.0, 1.0}, am = 0.3;
    s.sample = atom_sample, s.pdf_batch = atom_pdf_batch;
    s.n_atoms = 1, s.atom_x = ax, s.atom_mass = &am;
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = 50000, o.seed = 7;
    mcbox_check_result want;
    mcbox_check_table t;
    assert_int_equal(mcbox_check_run(&s, &o, &want, &t), 0);
    mcbox_check_result ignored;
    mcbox_check *c = mcbox_check_begin(&s, &o, &ignored);
    assert_non_null(c);
    double u[2], below = 0.0;
    for (int i = 0; i < 50000; i++) {
        mcbox_check_uniforms(c, u);
        below += u[0] < 0.3;
    }
    mcbox_check_finish(c, &ignored, NULL);
    size_t atom_cell = (size_t)t.nx * (size_t)t.ny;
    printf("atom cell: observed %g (uniforms below 0.3: %g), expected %g\n",
           json_num(strstr(r->out, "\"atoms\""), "observed"), below,
           json_num(strstr(r->out, "\"atoms\""), "expected"));
    assert_true(json_num(strstr(r->out, "\"atoms\""), "observed") == t.observed[atom_cell]);
    assert_true(t.observed[atom_cell] == below);
    assert_near(json_num(strstr(r->out, "\"atoms\""), "expected"), 0.3 * 50000, 1e-9 * 50000);
    assert_true(json_num(r->out, "statistic") == want.statistic);
    mcbox_check_table_free(&t);
}

static cat_state plot_row;

static double plot_row_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return cat_pdf(&plot_row, x);
}

/* `ROW` samples (seed 3) into a file, checked with --cells and --plot; the
 * JSON fields and every line of the .dat file against mcbox_check_points
 * on the same points, and against values computed here: the cell centres,
 * the counts of a histogram of the points, the expected counts from the
 * density's integral in closed form (linear: (b^2 - a^2) / 4 per cell;
 * square: 1 / cells) and the residuals. */
static void plot_by_value(const char *row, int nx, int ny, double hi)
{
    enum { N = 20000 };
    char err[200], args[1024], path[256], name[64];
    assert_true(cat_prepare_named(row, &plot_row, err, sizeof err));
    int dims = cat_point_dims(plot_row.row);
    mc_rng rng = mc_rng_derive(3u, 2u);
    mcbox_sample *pts = calloc(N, sizeof *pts);
    double *hist = calloc((size_t)nx * (size_t)(ny ? ny : 1), sizeof *hist);
    char *text = malloc((size_t)N * 64);
    assert_true(pts && hist && text);
    size_t used = 0;
    for (int i = 0; i < N; i++) {
        cat_sample(&plot_row, &rng, pts[i].x);
        pts[i].pdf = pts[i].weight = (double)NAN, pts[i].atom = -1;
        used += (size_t)snprintf(text + used, 64, dims == 1 ? "%.17g\n" : "%.17g %.17g\n",
                                 pts[i].x[0], pts[i].x[1]);
        int ci = (int)(pts[i].x[0] / hi * nx), cj = dims == 2 ? (int)(pts[i].x[1] * ny) : 0;
        hist[ci * (ny ? ny : 1) + cj] += 1.0;
    }
    snprintf(name, sizeof name, "%s-points.txt", row);
    write_file(name, text, used);
    free(text);
    snprintf(args, sizeof args, "--samples %s/%s --pdf %s --cells %dx%d --name byvalue-%s --plot %s "
             "--json", tmp, name, row, nx, ny, row, tmp);
    if (ny == 0)
        snprintf(args, sizeof args, "--samples %s/%s --pdf %s --cells %d --name byvalue-%s --plot %s "
                 "--json", tmp, name, row, nx, row, tmp);
    run *r = check(args);
    assert_seeded(passed(row, r), 3);
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = row, s.pdf = plot_row_pdf;
    mcbox_check_options o = mcbox_check_defaults();
    o.cells[0] = nx, o.cells[1] = ny;
    mcbox_check_result want;
    mcbox_check_table t;
    assert_int_equal(mcbox_check_points(&s, pts, N, &o, &want, &t), 0);
    const struct {
        const char *key;
        double v;
    } fields[] = {{"statistic", want.statistic}, {"pvalue", want.pvalue}, {"dof", want.dof},
                  {"samples", (double)want.samples}, {"cells", (double)want.cells},
                  {"cells_pooled", (double)want.cells_pooled}, {"pdf_integral", want.pdf_integral},
                  {"power_rel_error", want.power_rel_error}, {"scale_detectable", want.scale_detectable},
                  {"cells_90", (double)want.cells_90}, {"level", want.level}};
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++)
        if (!(json_num(r->out, fields[k].key) == fields[k].v))
            fail_msg("%s: JSON %s = %.17g, the C API's %.17g", row, fields[k].key,
                     json_num(r->out, fields[k].key), fields[k].v);
    assert_true(strstr(r->out, "\"verdict\": \"pass\"") != NULL);
    /* The .dat: one line per cell, x major, centre(s), observed, expected,
     * residual. */
    snprintf(path, sizeof path, "%s/byvalue-%s.dat", tmp, row);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[512];
    int cells = 0, ry = ny ? ny : 1;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n')
            continue;
        double v[5];
        char *p = line;
        for (int j = 0; j < dims + 3; j++)
            v[j] = strtod(p, &p);
        int i = cells / ry, j = cells % ry;
        double cx = (i + 0.5) * hi / nx, a = i * hi / nx, b = (i + 1) * hi / nx;
        double o_ = v[dims], e_ = v[dims + 1], z = v[dims + 2];
        double e_closed = dims == 1 ? N * (b * b - a * a) / 4.0 : (double)N / (nx * ny);
        assert_near(v[0], cx, 1e-8);
        if (dims == 2)
            assert_near(v[1], (j + 0.5) / ny, 1e-8);
        assert_true(o_ == t.observed[cells] && o_ == hist[cells]);
        assert_true(e_ == t.expected[cells]);
        assert_near(e_, e_closed, 1e-9 * e_closed);
        assert_near(z, (o_ - e_) / sqrt(e_), 1e-8 * fmax(1.0, fabs(z)));
        cells++;
    }
    fclose(f);
    assert_int_equal(cells, nx * ry);
    printf("%s: %d cells of the .dat and the JSON fields match the C API and the closed forms\n",
           row, cells);
    mcbox_check_table_free(&t);
    free(pts);
    free(hist);
}

static void test_check_cli_plot_and_json_by_value(void **state)
{
    (void)state;
    plot_by_value("linear", 16, 0, 2.0);
    plot_by_value("square", 4, 3, 1.0);
    /* The picture shares one colour scale between observed and expected
     * and marks samples in cells expected empty: the script says so. */
    char path[256];
    snprintf(path, sizeof path, "%s/byvalue-square.png", tmp);
    char head[8];
    mc_test_read_text(path, head, sizeof head);
    assert_memory_equal(head, "\x89PNG", 4);
}

/* A line filter between `warp serve` and mcbox-check, compiled once into
 * the scratch directory as `filter MODE ARG`: each line out as it comes in
 * (flushed, as the protocol needs), sample lines (3 fields) changed: "pad
 * W" pads every line with blanks to W bytes; "zeros L" writes the third
 * field with leading zeros to L bytes; "append S..." adds the fields S...; "pdf
 * E" adds the pdf column z / pi (1 + E). */
static const char FILTER[] =
    "#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n"
    "int main(int argc, char **argv) {\n  char line[8192], f[3][128];\n  if (argc < 3) return 2;\n"
    "  while (fgets(line, sizeof line, stdin)) {\n    line[strcspn(line, \"\\n\")] = 0;\n"
    "    int n = sscanf(line, \"%127s %127s %127s\", f[0], f[1], f[2]);\n"
    "    if (!strcmp(argv[1], \"pad\")) printf(\"%-*s\\n\", atoi(argv[2]), line);\n"
    "    else if (n != 3) puts(line);\n"
    "    else if (!strcmp(argv[1], \"zeros\")) printf(\"%s %s %0*d%s\\n\", f[0], f[1],\n"
    "      (int)(atoi(argv[2]) - strlen(f[2])), 0, f[2]);\n"
    "    else if (!strcmp(argv[1], \"append\")) { fputs(line, stdout);\n"
    "      for (int a = 2; a < argc; a++) printf(\" %s\", argv[a]); putchar('\\n'); }\n"
    "    else printf(\"%s %.17g\\n\", line, atof(f[2]) / 3.14159265358979324 * (1 + atof(argv[2])));\n"
    "    fflush(stdout);\n  }\n  return 0;\n}\n";

static void build_filter(void)
{
    static bool built;
    char cmd[512];
    if (built)
        return;
    write_text("filter.c", FILTER);
    snprintf(cmd, sizeof cmd, "cc -O2 -o %s/filter %s/filter.c", tmp, tmp);
    assert_int_equal(shell("%s", cmd), 0);
    built = true;
}

/* Whether r is a verdict (0 or 1), not bad input; prints it otherwise. */
static bool verdict(const char *what, const run *r);

/* The sampler's reported pdf (z / pi times 1 + E) against --pdf-tol 1e-3:
 * E = 0.99e-3 passes, E = 1.01e-3 fails naming the relative difference. */
static void test_check_cli_pdf_tolerance_edge(void **state)
{
    (void)state;
    static const double off[2] = {0.99e-3, 1.01e-3};
    build_filter();
    for (int k = 0; k < 2; k++) {
        char args[1024];
        snprintf(args, sizeof args, "--exec './warp serve cosine | %s/filter pdf %.17g' --domain "
                 "hemisphere --n 2e4 --seed 7 --pdf-tol 1e-3 --json", tmp, off[k]);
        run *r = check(args);
        printf("reported pdf off by %g: status %d, pdf_mismatch %.6g\n", off[k], r->status,
               json_num(r->out, "pdf_mismatch"));
        assert_near(json_num(r->out, "pdf_mismatch"), off[k], 1e-9);
        assert_true(json_num(r->out, "pdf_reported") == 2e4);
        if (k == 0)
            assert_seeded(passed("inside --pdf-tol", r), 7);
        else
            assert_true(r->status == 1 && strstr(r->out, "relative difference"));
    }
}


static bool verdict(const char *what, const run *r)
{
    bool ok = r->status == 0 || r->status == 1;
    printf("%s: status %d%s%s", what, r->status, ok ? "\n" : ": ", ok ? "" : r->err);
    return ok;
}

/* The readers' bounds at exactly full, one short and one over: an answer
 * line of 4096 bytes (APP_PROTO_MAX_LINE), a number field of 63 bytes,
 * 5 values on a sample line (DIMS + pdf + weight), batches of 4096 items,
 * a sample-file line of 1 MiB, a file field of 127 bytes, raw files one
 * byte short and over. */
static void test_check_cli_reader_bounds(void **state)
{
    (void)state;
    char args[1024];
    int failures = 0;
    build_filter();
    /* Answer lines padded with blanks (separators) to exactly L bytes. */
    static const int widths[3] = {4095, 4096, 4097};
    for (int k = 0; k < 3; k++) {
        snprintf(args, sizeof args, "--exec './warp serve cosine | %s/filter pad %d' --domain hemisphere "
                 "--n 2000 --seed 7", tmp, widths[k]);
        run *r = check(args);
        char what[64];
        snprintf(what, sizeof what, "answer lines of %d bytes", widths[k]);
        failures += k < 2 ? !verdict(what, r) : !refused(what, r, "longer than 4096 bytes");
    }
    /* A number written with leading zeros to 62, 63 and 64 bytes: the
     * protocol reads fields of up to 63. */
    static const int field[3] = {62, 63, 64};
    for (int k = 0; k < 3; k++) {
        snprintf(args, sizeof args, "--exec './warp serve cosine | %s/filter zeros %d' --domain "
                 "hemisphere --n 2000 --seed 7", tmp, field[k]);
        run *r = check(args);
        char what[64];
        snprintf(what, sizeof what, "a field of %d bytes", field[k]);
        failures += k < 2 ? !verdict(what, r) : !refused(what, r, "is not a number");
    }
    /* 4, 5 and 6 values on a sample line of a direction. */
    static const char *const extra[3] = {"1", "1 1", "1 1 1"};
    for (int k = 0; k < 3; k++) {
        snprintf(args, sizeof args, "--exec './warp serve cosine | %s/filter append %s' "
                 "--domain hemisphere --n 2000 --seed 7", tmp, extra[k]);
        run *r = check(args);
        char what[64];
        snprintf(what, sizeof what, "%d values on a sample line", 4 + k);
        failures += k < 2 ? !verdict(what, r) : !refused(what, r, "6 values, expected 3 coordinates");
    }
    /* Batches: 4095 and 4096 items in one command, 4097 in two. */
    static const int n[3] = {4095, 4096, 4097};
    for (int k = 0; k < 3; k++) {
        char log[128], want[64], text[1 << 12];
        snprintf(log, sizeof log, "%s/commands%d.log", tmp, k);
        snprintf(args, sizeof args, "--exec \"tee %s | ./warp serve cosine\" --domain hemisphere "
                 "--n %d --seed 7", log, n[k]);
        failures += !verdict("batch bounds", check(args));
        snprintf(args, sizeof args, "grep -E '^(sample|pdf) ' %s | head -3 >%s.cmds", log, log);
        assert_int_equal(shell("%s", args), 0);
        snprintf(args, sizeof args, "%s.cmds", log);
        mc_test_read_text(args, text, sizeof text);
        snprintf(want, sizeof want, k < 2 ? "sample %d\npdf " : "sample 4096\nsample 1", n[k]);
        text[strcspn(text, "\n") + 1 + strcspn(text + strcspn(text, "\n") + 1, "\n")] = '\0';
        printf("%d samples: the first commands '%s'\n", n[k], text);
        failures += strncmp(text, want, strlen(want)) != 0;
    }
    /* A sample-file line of 1 MiB - 1, 1 MiB and 1 MiB + 1 bytes: "0 0 1"
     * and blanks. */
    static const size_t lens[3] = {(1u << 20) - 1, 1u << 20, (1u << 20) + 1};
    for (int k = 0; k < 3; k++) {
        size_t len = lens[k];
        char *big = malloc(len + 16);
        assert_non_null(big);
        memset(big, ' ', len);
        memcpy(big, "0.5 0 0.8660254037844386", 24);
        big[len] = '\n';
        memcpy(big + len + 1, "0 0.6 0.8\n", 10);
        write_file("wide-line.txt", big, len + 11);
        free(big);
        snprintf(args, sizeof args, "--samples %s/wide-line.txt --pdf cosine", tmp);
        char what[64];
        snprintf(what, sizeof what, "a file line of %zu bytes", len);
        failures += k < 2 ? !verdict(what, check(args)) : !refused(what, check(args), "longer than 1 MiB");
    }
    /* A file field of 126, 127 and 128 bytes (leading zeros). */
    static const int ff[3] = {126, 127, 128};
    for (int k = 0; k < 3; k++) {
        char line[512];
        int pad = ff[k] - 3;
        snprintf(line, sizeof line, "0.6 0 %0*d0.8\n0 0.6 0.8\n", pad, 0);
        write_text("wide-field.txt", line);
        snprintf(args, sizeof args, "--samples %s/wide-field.txt --pdf cosine", tmp);
        char what[64];
        snprintf(what, sizeof what, "a file field of %d bytes", ff[k]);
        failures += k < 2 ? !verdict(what, check(args)) : !refused(what, check(args), "field 3");
    }
    /* Raw f64 directions: 2 records exactly, one byte short, one over. */
    double rec[6] = {0.6, 0.0, 0.8, 0.0, 0.6, 0.8};
    static const int delta[3] = {0, -1, 1};
    for (int k = 0; k < 3; k++) {
        unsigned char bytes[64] = {0};
        memcpy(bytes, rec, sizeof rec);
        write_file("two.f64", bytes, sizeof rec + (size_t)(long)delta[k]);
        snprintf(args, sizeof args, "--samples %s/two.f64 --format f64 --pdf cosine", tmp);
        char what[64];
        snprintf(what, sizeof what, "2 f64 records %+d byte", delta[k]);
        failures += k == 0 ? !verdict(what, check(args))
                           : !refused(what, check(args), k == 1 ? "sample 2 (byte 24): truncated "
                                                                  "record: 23 of its 24 bytes"
                                                                : "sample 3 (byte 48): truncated "
                                                                  "record: 1 of its 24 bytes");
    }
    assert_int_equal(failures, 0);
}

/* No verdict still writes the reports: bad input (exit 2) with --json
 * prints {"verdict": "error", ...} and --junit an <error>. */
static void test_check_cli_error_reports(void **state)
{
    (void)state;
    char args[1024], path[256], text[4096];
    snprintf(args, sizeof args, "--exec ./nope --domain hemispher --json --junit %s/err.xml "
             "--name broken", tmp);
    run *r = check(args);
    printf("%s%s", r->out, r->err);
    assert_int_equal(r->status, 2);
    assert_non_null(strstr(r->out, "{\"name\": \"broken\", \"verdict\": \"error\", \"pass\": false"));
    assert_non_null(strstr(r->out, "neither a domain"));
    snprintf(path, sizeof path, "%s/err.xml", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "errors=\"1\""));
    assert_non_null(strstr(text, "<error type=\"error\" message=\"--domain: 'hemispher'"));
    /* A program that breaks the protocol, with the reports asked for. */
    snprintf(args, sizeof args, "--exec 'read h; echo nope' --domain hemisphere --json --junit %s/err2.xml",
             tmp);
    r = check(args);
    assert_int_equal(r->status, 2);
    assert_non_null(strstr(r->out, "\"verdict\": \"error\""));
    snprintf(path, sizeof path, "%s/err2.xml", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "<error type=\"error\" message=\"'"));
    /* Undetermined (a quadrature error no verdict may rest on): exit 2,
     * the figures on stdout, the reason on stderr, JSON and JUnit say so. */
    snprintf(args, sizeof args, "--exec './warp serve cone' --domain cone --n 2e4 "
             "--quad-error-max 1e-30 --json --junit %s/und.xml", tmp);
    r = check(args);
    printf("%s%s", r->out, r->err);
    assert_int_equal(r->status, 2);
    assert_non_null(strstr(r->out, "\"verdict\": \"undetermined\", \"pass\": false, "
                                   "\"undetermined\": true"));
    assert_true(json_num(r->out, "quad_error_max") == 1e-30);
    assert_non_null(strstr(r->err, "mcbox-check: undetermined"));
    snprintf(path, sizeof path, "%s/und.xml", tmp);
    mc_test_read_text(path, text, sizeof text);
    assert_non_null(strstr(text, "errors=\"1\""));
    assert_non_null(strstr(text, "<error type=\"undetermined\" message=\"undetermined"));
}

/* A program slow to exit after its last answer does not cost the verdict:
 * past --timeout it is killed, the verdict stands, a note says so. And a
 * catalog row whose sampler draws is named on stderr with its UNIFORMS. */
static void test_check_cli_slow_exit_and_uniforms(void **state)
{
    (void)state;
    run *r = check("--exec './warp serve cosine; sleep 30' --domain hemisphere --n 2e4 --seed 7 "
                   "--timeout 1 --json");
    assert_seeded(passed("sleeps 30 s after its input ends", r), 7);
    assert_non_null(strstr(r->err, "note: './warp serve cosine; sleep 30' had not exited 1 s"));
    assert_non_null(strstr(r->out, "\"note\": \"'./warp serve cosine; sleep 30' had not exited"));
    r = check("--exec './warp serve sphere-rejection' --domain sphere-rejection --n 2e4 --seed 7");
    assert_seeded(r->status == 0, 7);
    assert_non_null(strstr(r->err, "--domain sphere-rejection: the program gets UNIFORMS 0"));
    /* A program that expects two uniforms is sent draw: the timeout says why. */
    char args[512];
    snprintf(args, sizeof args, "--exec 'read h; echo ok; read c k; while read u; do :; done' "
             "--domain sphere-rejection --n 10 --timeout 1");
    r = check(args);
    printf("a program waiting for uniforms: status %d: %s", r->status, r->err);
    /* The note, then the one line of the error. */
    assert_int_equal(r->status, 2);
    assert_true(r->out[0] == '\0');
    assert_non_null(strstr(r->err, "\nmcbox-check: 'read h; echo ok; read c k; while read u; do :; "
                                   "done': command 1 (draw 10): no answer within the 1 s of --timeout "
                                   "(0 of 10 answers read); it was sent 'draw K' (UNIFORMS 0 in hello, "
                                   "the catalog row's own count): a program that maps uniforms needs "
                                   "--uniforms K"));
}

/* Several assignments in one --param, as warp list prints them, equal the
 * same as separate options; every row of warp list says what it is. */
static void test_check_cli_params_and_descriptions(void **state)
{
    (void)state;
    run *r = check("--exec './warp serve quad-light --param \"corner=-0.7,-0.4,1.2 u=1,0.1,0.35\" "
                   "--param v=-0.15,0.8,0.45' --domain quad-light "
                   "--param 'corner=-0.7,-0.4,1.2 u=1,0.1,0.35 v=-0.15,0.8,0.45' --n 3e4 --seed 7 --json");
    assert_seeded(passed("quad-light, one --param of three assignments", r), 7);
    double one = json_num(r->out, "statistic");
    r = check("--exec './warp serve quad-light --param corner=-0.7,-0.4,1.2 --param u=1,0.1,0.35 "
              "--param v=-0.15,0.8,0.45' --domain quad-light --param corner=-0.7,-0.4,1.2 "
              "--param u=1,0.1,0.35 --param v=-0.15,0.8,0.45 --n 3e4 --seed 7 --json");
    assert_true(json_num(r->out, "statistic") == one);
    /* warp list: a description after '#' on every row's line. */
    char cmd[256], text[1 << 14];
    snprintf(cmd, sizeof cmd, "./warp list >%s/list.txt", tmp);
    assert_int_equal(shell("%s", cmd), 0);
    snprintf(cmd, sizeof cmd, "%s/list.txt", tmp);
    mc_test_read_text(cmd, text, sizeof text);
    int missing = 0;
    for (size_t i = 0; i < cat_count(); i++) {
        char word[80];
        snprintf(word, sizeof word, "\n%s ", cat_at(i)->name);
        const char *line = i == 0 && strncmp(text, word + 1, strlen(word + 1)) == 0
                               ? text : strstr(text, word);
        const char *hash = line ? strstr(line, "  # ") : NULL;
        const char *nl = line ? strchr(line + 1, '\n') : NULL;
        bool ok = hash && (!nl || hash < nl) && strncmp(hash + 4, "(no description)", 16) != 0 &&
                  hash[4] != '\n';
        if (!ok)
            printf("warp list: row %s has no description\n", cat_at(i)->name);
        missing += !ok;
    }
    assert_int_equal(missing, 0);
}

static int setup(void **state)
{
    char real[PATH_MAX];
    if (negctl_group_setup(state) != 0 || !realpath(mc_test_source_dir(), real) ||
        strlen(real) >= sizeof root)
        return -1;
    memcpy(root, real, strlen(real) + 1);
    snprintf(tmp, sizeof tmp, "/tmp/mcbox-check-cli-XXXXXX");
    r_ = malloc(sizeof *r_);
    return mkdtemp(tmp) && r_ ? 0 : -1;
}

static int teardown(void **state)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmp);
    (void)!system(cmd);
    free(r_);
    return negctl_group_teardown(state);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_check_cli_exec_matches_c_api),
        cmocka_unit_test(test_check_cli_protocol_examples),
        cmocka_unit_test(test_check_cli_sample_files),
        cmocka_unit_test(test_check_cli_every_row),
        cmocka_unit_test(test_check_cli_negative_controls),
        cmocka_unit_test(test_check_cli_bad_files),
        cmocka_unit_test(test_check_cli_bad_programs),
        cmocka_unit_test(test_check_cli_bad_options),
        cmocka_unit_test(test_check_cli_reports),
        cmocka_unit_test(test_check_cli_atoms_by_value),
        cmocka_unit_test(test_check_cli_plot_and_json_by_value),
        cmocka_unit_test(test_check_cli_pdf_tolerance_edge),
        cmocka_unit_test(test_check_cli_reader_bounds),
        cmocka_unit_test(test_check_cli_error_reports),
        cmocka_unit_test(test_check_cli_slow_exit_and_uniforms),
        cmocka_unit_test(test_check_cli_params_and_descriptions),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_check_cli", tests, setup, teardown);
}
