/* tests/test_render_cli.c - the cornell_box program: bad input exits 2
 * with one line on stderr naming the program, good input writes the image
 * in the format of its extension, Ctrl-C writes what was rendered and
 * exits 130. Runs the program built in $MC_BUILD/bin. */
#define _POSIX_C_SOURCE 200809L

#include "tests/support/mc_test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

/* Runs cornell_box with `args` (shell syntax); returns its exit status and
 * fills out/err with (the start of) its stdout and stderr. */
static int run(const char *args, char *out, size_t out_len, char *err, size_t err_len)
{
    const char *b = mc_test_build_dir();
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "%s/bin/cornell_box %s >%s/cli.out 2>%s/cli.err", b, args, b, b);
    int rc = system(cmd);
    char path[1024];
    char *bufs[2] = {out, err};
    size_t lens[2] = {out_len, err_len};
    static const char *const names[2] = {"cli.out", "cli.err"};
    for (int i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/%s", b, names[i]);
        FILE *f = fopen(path, "rb");
        assert_non_null(f);
        size_t n = fread(bufs[i], 1, lens[i] - 1, f);
        bufs[i][n] = '\0';
        fclose(f);
    }
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static int count_lines(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

static void test_cli_bad_input(void **state)
{
    (void)state;
    char out[4096], err[4096], args[1024];
    const char *b = mc_test_build_dir();
    const char *bad[] = {"--scene nope", "--strategy nope", "--width 0", "--spp 0",
                         "--max-depth -1", "-o /nonexistent-dir/x.png", "-o %s/x.jpg",
                         "--gamma 3", "--threads -2", "--frobnicate", "stray"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char opt[512];
        snprintf(opt, sizeof opt, bad[i], b);
        snprintf(args, sizeof args, "--width 4 --spp 1 -o %s/cli_ok.png %s", b, opt);
        int rc = run(args, out, sizeof out, err, sizeof err);
        if (rc != 2 || out[0] || count_lines(err) != 1 || strncmp(err, "cornell_box: ", 13) != 0)
            fail_msg("'%s': exit %d, stdout '%s', stderr '%s'", opt, rc, out, err);
    }
}

static void test_cli_writes_images(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], path[1024];
    const char *b = mc_test_build_dir();
    static const char *const ext[3] = {"pfm", "png", "ppm"};
    static const char *const magic[3] = {"PF\n8 8\n", "\x89PNG", "P6\n8 8\n255\n"};
    for (int i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "%s/cli_ok.%s", b, ext[i]);
        snprintf(args, sizeof args, "--scene lambert --width 8 --spp 3 --threads 1 -o %s", path);
        assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
        assert_non_null(strstr(out, "mean_linear_r"));
        FILE *f = fopen(path, "rb");
        assert_non_null(f);
        char head[16] = {0};
        size_t n = fread(head, 1, strlen(magic[i]), f);
        fclose(f);
        assert_int_equal(n, strlen(magic[i]));
        assert_true(memcmp(head, magic[i], n) == 0);
        remove(path);
    }
    assert_int_equal(run("--help", out, sizeof out, err, sizeof err), 0);
    assert_non_null(strstr(out, "--strategy"));
}

/* SIGINT after a second of a long render: exit 130, a complete PNG, and
 * the sample count on stderr. A signal that lands before main() runs (while
 * the loader maps the libraries, on a loaded machine) kills the process by
 * the default action, which no program can prevent; that case (exit 130
 * without the program's line) is retried with a longer delay, up to 1 + 2 +
 * 4 s. */
static void test_cli_sigint_writes_partial_image(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], path[1024];
    const char *b = mc_test_build_dir();
    snprintf(path, sizeof path, "%s/cli_int.png", b);
    snprintf(args, sizeof args, "--scene book --width 64 --spp 1e6 -o %s", path);
    for (int delay = 1; delay <= 4; delay *= 2) {
        /* timeout(1) sends SIGINT after `delay` s; --preserve-status passes
         * on the program's own exit status. */
        char full[8192];
        snprintf(full, sizeof full,
                 "timeout --preserve-status -s INT %d %s/bin/cornell_box %s >%s/cli.out 2>%s/cli.err",
                 delay, b, args, b, b);
        int rc = system(full);
        assert_true(WIFEXITED(rc));
        assert_int_equal(WEXITSTATUS(rc), 130);
        snprintf(full, sizeof full, "%s/cli.err", b);
        FILE *f = fopen(full, "rb");
        assert_non_null(f);
        size_t n = fread(err, 1, sizeof err - 1, f);
        err[n] = '\0';
        fclose(f);
        if (strstr(err, "interrupted") || n > 0)
            break;
        printf("SIGINT after %d s arrived before the program started; retrying\n", delay);
    }
    assert_non_null(strstr(err, "interrupted"));
    assert_non_null(strstr(err, "samples"));
    FILE *img = fopen(path, "rb");
    assert_non_null(img);
    unsigned char sig[8];
    assert_int_equal(fread(sig, 1, 8, img), 8);
    fclose(img);
    assert_true(memcmp(sig, "\x89PNG\r\n\x1a\n", 8) == 0);
    remove(path);
    (void)out;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli_bad_input),
        cmocka_unit_test(test_cli_writes_images),
        cmocka_unit_test(test_cli_sigint_writes_partial_image),
    };
    return cmocka_run_group_tests_name("test_render_cli", tests, NULL, NULL);
}
