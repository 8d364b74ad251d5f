/* tests/test_qmc_cli.c - the `qmc` program of $MC_BUILD/bin: every bad
 * input it must refuse (exit 2, one line on stderr naming the program,
 * nothing on stdout), the points it prints (the library's points, to the
 * last bit, index 0 first), and the rows of its table (an error bar for
 * every random method, none for unscrambled Sobol, the same bytes for the
 * same seed). tests/test_cli.c runs the generic cases on it as on every
 * program; these are the cases only qmc has.
 */
#define _POSIX_C_SOURCE 200809L /* WEXITSTATUS with system() */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "mc/qmc.h"
#include "tests/support/negctl.h"

enum { CAPTURE = 1 << 20 };

typedef struct run {
    int status;
    char *out, *err;
} run;

/* Runs `qmc ARGS` (shell words) from the build's bin directory. */
static run qmc(const char *args)
{
    static char out[CAPTURE], err[4096];
    const char *b = mc_test_build_dir();
    char cmd[2048], path[1024];
    snprintf(cmd, sizeof cmd, "cd %s/bin && ./qmc %s >../qmc_cli.out 2>../qmc_cli.err", b, args);
    int rc = system(cmd);
    run r = {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, out, err};
    snprintf(path, sizeof path, "%s/qmc_cli.out", b);
    mc_test_read_text(path, out, sizeof out);
    snprintf(path, sizeof path, "%s/qmc_cli.err", b);
    mc_test_read_text(path, err, sizeof err);
    return r;
}

/* Whether r kept the bad-input contract; prints why not. */
static bool refused(const char *args, run r)
{
    const char *nl = strchr(r.err, '\n');
    bool ok = r.status == 2 && r.out[0] == '\0' && strncmp(r.err, "qmc: ", 5) == 0 && nl && nl[1] == '\0';
    if (!ok)
        printf("qmc %s: status %d, stdout %zu bytes, stderr '%s'\n", args, r.status, strlen(r.out), r.err);
    else
        printf("qmc %s -> %s", args, r.err);
    return ok;
}

/* Every input qmc must refuse: names it does not know, counts out of range,
 * a dimension beyond the method's table or wrong for pi, too few
 * scrambles for an error bar, scrambles of a deterministic set, more
 * Sobol points than 32-bit indices, junk numbers, a stray word. */
static void test_qmc_cli_bad_input(void **state)
{
    (void)state;
    static const char *const bad[] = {
        "--integrand nope",
        "--method nope",
        "--samples 0",
        "--samples -5",
        "--samples 1e30",
        "--samples 12abc",
        "--dim 0",
        "--dim 1025",
        "--dim 2.5",
        "--method halton --dim 65",
        "--method sobol-owen --dim 1025",
        "--integrand pi --dim 3",
        "--integrand pi --dim 1",
        "--scrambles 1",
        "--scrambles 0",
        "--scrambles x",
        "--method sobol --scrambles 4",
        "--method sobol --samples 5e9",
        "--samples 1e12 --scrambles 100",
        "--seed -1",
        "--seed 1.5",
        "--integrand smooth --integrand peak",
        "stray",
        "points --method all",
        "points --method halton --dim 65",
        "points --method nope",
        "points --samples 0",
        "points --dim 0",
        "points --integrand pi",
        "points --scrambles 4",
        "points --method sobol-xor --samples 5e9",
        "points stray",
    };
    int failures = 0;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        failures += !refused(bad[i], qmc(bad[i]));
    printf("%zu bad inputs, %d not refused as the contract says\n", sizeof bad / sizeof bad[0], failures);
    assert_int_equal(failures, 0);
}

/* Parses the CSV of `qmc points` for (method, d, n, seed) and compares
 * every coordinate with the library's cursor; returns the number of
 * mismatches (a missing row, a wrong index, a coordinate that differs in
 * any bit), printing the first. */
static int points_mismatches(mc_qmc_method method, const char *name, unsigned d, unsigned n, uint64_t seed,
                             uint64_t lib_seed)
{
    char args[256];
    snprintf(args, sizeof args, "points --method %s --dim %u --samples %u --seed %llu", name, d, n,
             (unsigned long long)seed);
    run r = qmc(args);
    assert_int_equal(r.status, 0);
    static char header[8192];
    snprintf(header, sizeof header, "i");
    for (unsigned j = 1; j <= d; j++)
        snprintf(header + strlen(header), sizeof header - strlen(header), ",x%u", j);
    if (strncmp(r.out, header, strlen(header)) != 0 || r.out[strlen(header)] != '\n') {
        printf("%s: header is not '%s'\n", args, header);
        return 1;
    }
    const char *p = r.out + strlen(header) + 1;
    int bad = 0;
    for (unsigned i = 0; i < n; i++) {
        char *end;
        unsigned long long idx = strtoull(p, &end, 10);
        mc_qmc_cursor c = mc_qmc_begin(method, lib_seed, 0, i);
        bool row_ok = idx == i && *end == ',';
        for (unsigned j = 0; j < d && row_ok; j++) {
            double x = strtod(end + 1, &end), want = mc_qmc_next(&c);
            row_ok = x == want && (*end == ',' || *end == '\n');
        }
        if (!row_ok && bad++ == 0 && seed == lib_seed)
            printf("%s: row %u differs from the library's point\n", args, i);
        p = strchr(p, '\n');
        if (!p)
            return bad + 1;
        p++;
    }
    return bad + (*p != '\0');
}

/* `qmc points` prints the library's points in index order with enough
 * digits to read back every bit: unscrambled Sobol in 8 dimensions (1024
 * points), dimensions up to 1024, Owen-scrambled and XOR-scrambled Sobol,
 * permuted Halton in 64 dimensions. The first points of dimension 1 are
 * 0, 1/2, 1/4, 3/4. Negative control: the same comparison against the
 * library's points of another seed must find mismatches. A jittered set
 * has one point in each cell of the largest grid that fits. */
static void test_qmc_cli_points_match_library(void **state)
{
    negctl *t = *state;
    assert_int_equal(points_mismatches(MC_QMC_SOBOL, "sobol", 8, 1024, 1, 1), 0);
    assert_int_equal(points_mismatches(MC_QMC_SOBOL, "sobol", 1024, 4, 1, 1), 0);
    assert_int_equal(points_mismatches(MC_QMC_SOBOL_OWEN, "sobol-owen", 5, 256, 2385, 2385), 0);
    assert_int_equal(points_mismatches(MC_QMC_SOBOL_XOR, "sobol-xor", 3, 64, 77, 77), 0);
    assert_int_equal(points_mismatches(MC_QMC_HALTON, "halton", 64, 32, 5, 5), 0);
    assert_int_equal(points_mismatches(MC_QMC_RANDOM, "mc", 3, 32, 9, 9), 0);
    run r = qmc("points --method sobol --dim 1 --samples 4");
    assert_string_equal(r.out, "i,x1\n0,0\n1,0.5\n2,0.25\n3,0.75\n");
    assert_true(negctl_record(t, "the library's points of another seed", "bitwise comparison",
                              points_mismatches(MC_QMC_SOBOL_OWEN, "sobol-owen", 5, 16, 2385, 2386) > 0));
    r = qmc("points --method jitter --dim 2 --samples 10 --seed 3");
    int rows = 0, cell[9] = {0};
    for (const char *p = strchr(r.out, '\n'); p && p[1]; p = strchr(p + 1, '\n')) {
        unsigned i;
        double x, y;
        assert_int_equal(sscanf(p + 1, "%u,%lf,%lf", &i, &x, &y), 3);
        cell[(int)(3 * x) + 3 * (int)(3 * y)]++;
        rows++;
    }
    assert_int_equal(rows, 9);
    for (int k = 0; k < 9; k++)
        assert_int_equal(cell[k], 1);
}

/* The estimate table: every random method has a standard error and a z,
 * unscrambled Sobol has neither (empty CSV fields, "none" in the table
 * with a note saying why); the same seed gives the same bytes, another
 * seed other numbers; a jittered grid reports the points it used. */
static void test_qmc_cli_table(void **state)
{
    (void)state;
    run r = qmc("--integrand peak --dim 3 --samples 1200 --scrambles 4 --seed 7 --csv");
    assert_int_equal(r.status, 0);
    char first[8192];
    snprintf(first, sizeof first, "%s", r.out);
    assert_non_null(strstr(first, "method,n,estimate,stderr,exact,z,points,scrambles,abs_error\n"));
    static const char *const random_methods[] = {"mc", "jitter", "halton", "sobol-xor", "sobol-owen"};
    for (size_t m = 0; m < 5; m++) {
        char key[32];
        snprintf(key, sizeof key, "\n%s,", random_methods[m]);
        const char *row = strstr(first, key);
        assert_non_null(row);
        unsigned long long n;
        double est, se, exact, z, pts, reps;
        assert_int_equal(sscanf(row + 1 + strlen(random_methods[m]) + 1, "%llu,%lf,%lf,%lf,%lf,%lf,%lf", &n,
                                &est, &se, &exact, &z, &pts, &reps),
                         7);
        assert_true(se > 0.0 && reps == 4.0 && (double)n == pts * reps);
        assert_true(pts == (m == 1 ? 1000.0 : 1200.0)); /* jitter: a 10 x 10 x 10 grid */
    }
    const char *sobol = strstr(first, "\nsobol,");
    assert_non_null(sobol);
    unsigned long long n;
    double est, exact;
    int used = 0;
    assert_int_equal(sscanf(sobol + 7, "%llu,%lf,,%lf,,%n", &n, &est, &exact, &used), 3);
    assert_true(used > 0 && n == 1200);
    r = qmc("--integrand peak --dim 3 --samples 1200 --scrambles 4 --seed 7 --csv");
    assert_string_equal(r.out, first);
    r = qmc("--integrand peak --dim 3 --samples 1200 --scrambles 4 --seed 8 --csv");
    assert_true(strcmp(r.out, first) != 0);
    r = qmc("--method sobol --samples 64");
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "none"));
    assert_non_null(strstr(r.out, "no standard error"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_qmc_cli_bad_input),
        cmocka_unit_test(test_qmc_cli_points_match_library),
        cmocka_unit_test(test_qmc_cli_table),
    };
    return cmocka_run_group_tests_name("test_qmc_cli", tests, negctl_group_setup, negctl_group_teardown);
}
