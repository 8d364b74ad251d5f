/* tests/test_warp.c - the `warp` program ($MC_BUILD/bin/warp) does what
 * its usage promises: `list` names every sampler under its stable name with
 * domain, measure and parameters; `sample` prints points in the stated
 * format; `pdf` reads them back and prints densities that match known
 * values; `chi2` prints "chi2 dof p verdict" and passes correct samplers.
 * (Bad input, --help and --version are test_cli's.)
 */
#define _POSIX_C_SOURCE 200809L /* popen */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"

static const char *const NAMES[] = {"square",
                                    "disc-polar",
                                    "disc-concentric",
                                    "triangle",
                                    "parallelogram",
                                    "sphere-surface",
                                    "sphere-inverse",
                                    "sphere-gaussian",
                                    "sphere-rejection",
                                    "hemisphere",
                                    "hemisphere-flip",
                                    "cosine",
                                    "cosine-malley",
                                    "cosine-acos",
                                    "theta-phi",
                                    "phong",
                                    "ggx",
                                    "cone",
                                    "linear",
                                    "quadratic",
                                    "sine",
                                    "log-ends",
                                    "discrete",
                                    "alias",
                                    "quad-light",
                                    "sphere-light",
                                    "mixture",
                                    "uniform-pdf",
                                    "cosine-pdf",
                                    "light-list"};
enum { N_NAMES = sizeof NAMES / sizeof NAMES[0] };

/* Runs `warp ARGS` (with `input` on stdin when not NULL) and returns its
 * stdout in buf; the exit status in *status. */
static void warp(const char *args, const char *input, char *buf, size_t size, int *status)
{
    char cmd[4096];
    if (input)
        snprintf(cmd, sizeof cmd, "printf '%s' | %s/bin/warp %s", input, mc_test_build_dir(), args);
    else
        snprintf(cmd, sizeof cmd, "%s/bin/warp %s", mc_test_build_dir(), args);
    FILE *f = popen(cmd, "r");
    assert_non_null(f);
    size_t len = fread(buf, 1, size - 1, f);
    buf[len] = '\0';
    int rc = pclose(f);
    *status = rc >= 0 && (rc & 0x7f) == 0 ? (rc >> 8) & 0xff : -1;
}

static void test_warp_list(void **state)
{
    (void)state;
    static char out[1 << 14];
    int status;
    warp("list", NULL, out, sizeof out, &status);
    assert_int_equal(status, 0);
    int i = 0;
    for (char *line = strtok(out, "\n"); line; line = strtok(NULL, "\n"), i++) {
        char name[64], domain[64], measure[64], params[256];
        assert_int_equal(sscanf(line, "%63s %63s %63s %255[^\n]", name, domain, measure, params),
                         4);
        assert_true(i < N_NAMES);
        assert_string_equal(name, NAMES[i]);
        bool dir = (strstr(domain, "sphere") || strstr(domain, "cone")) && !strstr(domain, "surface");
        assert_string_equal(measure, dir ? "solid-angle"
                                         : (strchr(domain, '[')   ? "length"
                                            : strchr(domain, '{') ? "counting"
                                                                  : "area"));
    }
    assert_int_equal(i, N_NAMES);
}

/* Known densities read back through `pdf`: the cosine pdf at +z is 1/pi,
 * phong n = 10 at +z is 11 / (2 pi), the quad light seen straight on is
 * dist^2 / A = 1, the 1..8 weights give 1/36 and 8/36, the sphere light
 * (centre (0,0,2), radius 1) 1 / (2 pi (1 - sqrt 3 / 2)) inside its cone. */
static void test_warp_pdf_known_values(void **state)
{
    (void)state;
    static const struct {
        const char *args, *input;
        double a, b;
    } cases[] = {
        {"pdf cosine", "0 0 1\\n0 0 -1\\n", MC_INV_PI, 0.0},
        {"pdf phong --param n=10", "0 0 2\\n1 0 0\\n", 11.0 / MC_2PI, 0.0},
        {"pdf quad-light", "0 0 1\\n0 0 -1\\n", 1.0, 0.0},
        {"pdf discrete", "0\\n7\\n", 1.0 / 36.0, 8.0 / 36.0},
        {"pdf sphere-light", "0 0 1\\n0 1 0\\n", 1.0 / (MC_2PI * (1.0 - 0.86602540378443865)), 0.0},
    };
    char out[1024];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int status;
        warp(cases[i].args, cases[i].input, out, sizeof out, &status);
        assert_int_equal(status, 0);
        double a, b;
        assert_int_equal(sscanf(out, "%lf %lf", &a, &b), 2);
        assert_near(a, cases[i].a, 1e-12 * cases[i].a);
        assert_near(b, cases[i].b, 1e-12 * cases[i].b);
    }
}

/* `sample` writes N points in the entry's format; every one of them has a
 * positive density according to `pdf` (which reads the same format). */
static void test_warp_sample_format(void **state)
{
    (void)state;
    static char out[1 << 16];
    static const char *const names[] = {"cone", "triangle", "sine", "alias", "mixture"};
    static const int dims[] = {3, 2, 1, 1, 3};
    char args[256];
    uint64_t seed = mc_test_seed(8201u);
    for (int k = 0; k < 5; k++) {
        int status;
        snprintf(args, sizeof args, "sample %s --n 200 --seed %llu", names[k],
                 (unsigned long long)seed);
        warp(args, NULL, out, sizeof out, &status);
        assert_int_equal(status, 0);
        int lines = 0;
        for (char *p = out; *p; lines++) {
            char *eol = strchr(p, '\n');
            assert_non_null(eol);
            int fields = 0;
            for (char *q = p; q < eol; fields++) {
                char *end;
                double v = strtod(q, &end);
                assert_true(end > q && isfinite(v));
                q = end;
            }
            assert_int_equal(fields, dims[k]);
            p = eol + 1;
        }
        assert_int_equal(lines, 200);
        snprintf(args, sizeof args, "sample %s --n 200 --seed %llu | %s/bin/warp pdf %s", names[k],
                 (unsigned long long)seed, mc_test_build_dir(), names[k]);
        warp(args, NULL, out, sizeof out, &status);
        assert_int_equal(status, 0);
        int positive = 0;
        for (char *line = strtok(out, "\n"); line; line = strtok(NULL, "\n"))
            positive += strtod(line, NULL) > 0.0;
        assert_int_equal(positive, 200);
    }
}

/* `chi2` on three entries (10^5 samples, level 1e-4: the false-alarm rate
 * of each): "chi2 dof p pass", exit status 0. */
static void test_warp_chi2(void **state)
{
    (void)state;
    static const char *const runs[] = {"chi2 mixture --param w=0.2",
                                       "chi2 alias --param weights=3,0,1.5,2.385",
                                       "chi2 ggx --param alpha=0.3"};
    char args[256], out[256], verdict[16];
    uint64_t seed = mc_test_seed(8202u);
    for (int k = 0; k < 3; k++) {
        int status, dof;
        double stat, p;
        snprintf(args, sizeof args, "%s --n 100000 --alpha 1e-4 --seed %llu", runs[k],
                 (unsigned long long)seed);
        warp(args, NULL, out, sizeof out, &status);
        assert_int_equal(sscanf(strchr(out, '\n') ? strchr(out, '\n') + 1 : out, "%lf %d %lf %15s", &stat, &dof, &p, verdict), 4);
        if (status != 0)
            printf("warp %s: %s", args, out);
        assert_int_equal(status, 0);
        assert_string_equal(verdict, "pass");
        assert_true(dof > 0 && p >= 1e-4 && stat > 0.0);
    }
}

/* The histogram follows the sample count: with 1000 samples `warp chi2`
 * still has degrees of freedom to test with (a grid sized for 10^6 samples
 * would pool every cell and pass anything), and with 10 samples it refuses
 * with exit status 2 rather than print a vacuous "pass". */
static void test_warp_chi2_small_n(void **state)
{
    (void)state;
    static const char *const names[] = {"cosine", "disc-polar", "linear", "quad-light", "mixture"};
    char args[256], out[256], verdict[16];
    for (int k = 0; k < 5; k++) {
        int status, dof;
        double stat, p;
        snprintf(args, sizeof args, "chi2 %s --n 1000 --alpha 1e-4 --seed 7", names[k]);
        warp(args, NULL, out, sizeof out, &status);
        assert_int_equal(sscanf(strchr(out, '\n') ? strchr(out, '\n') + 1 : out, "%lf %d %lf %15s", &stat, &dof, &p, verdict), 4);
        if (dof < 3)
            printf("warp %s: %s", args, out);
        assert_true(dof >= 3);
        snprintf(args, sizeof args, "chi2 %s --n 10 --seed 7 2>/dev/null", names[k]);
        warp(args, NULL, out, sizeof out, &status);
        assert_int_equal(status, 2);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_warp_list),
        cmocka_unit_test(test_warp_pdf_known_values),
        cmocka_unit_test(test_warp_sample_format),
        cmocka_unit_test(test_warp_chi2),
        cmocka_unit_test(test_warp_chi2_small_n),
    };
    return cmocka_run_group_tests_name("test_warp", tests, NULL, NULL);
}
