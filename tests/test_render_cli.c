/* tests/test_render_cli.c - the cornell_box program: bad input exits 2
 * with one line on stderr naming the program, good input writes the image
 * in the format of its extension, Ctrl-C, SIGTERM and SIGHUP write what was
 * rendered and exit 128 + the signal, and whatever stops the program (a
 * signal, a write error, a refused size) leaves at the output path either
 * the previous file or a complete new image, and no temporary file. Runs
 * the program built in $MC_BUILD/bin. */
#define _POSIX_C_SOURCE 200809L

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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
        mc_test_read_text(path, bufs[i], lens[i]);
    }
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/* Reads the file at path into buf (at most size - 1 bytes, NUL-terminated);
 * returns the byte count, or -1 when it cannot be opened. */
static long slurp(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
    return (long)n;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

/* Whether dir holds a leftover temporary file of the output `base`
 * (named ".base.XXXXXX"). */
static bool has_temp_file(const char *dir, const char *base)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    char prefix[256];
    snprintf(prefix, sizeof prefix, ".%s.", base);
    bool found = false;
    for (struct dirent *e; (e = readdir(d));)
        found |= strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    closedir(d);
    return found;
}

/* A PNG file is complete when it starts with the signature and ends with
 * the IEND chunk (length 0, type, CRC). */
static bool png_complete(const char *path)
{
    static char buf[1 << 20];
    long n = slurp(path, buf, sizeof buf);
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    return n > 20 && memcmp(buf, "\x89PNG\r\n\x1a\n", 8) == 0 && memcmp(buf + n - 12, iend, 12) == 0;
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
                         "--gamma 3", "--threads -2", "--frobnicate", "stray", "--sampler nope",
                         "--sampler sobol --spp 5e9", "--reference", "--reference %s/no-such.pfm"};
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
    /* One sample per pixel: no pixel variance, so no standard error. */
    snprintf(args, sizeof args, "--width 8 --spp 1 -o %s/cli_ok.png", b);
    assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
    if (!strstr(out, "n/a") || strstr(out, "0.000e+00"))
        fail_msg("--spp 1: the standard error is not n/a: '%s'", out);
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
        size_t n = mc_test_read_text(full, err, sizeof err);
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

/* SIGTERM (what timeout(1) and batch schedulers send) and SIGHUP stop a
 * long render like Ctrl-C: exit 128 + signal, the partial image with its
 * sample count, and the old file at the path replaced by a complete PNG,
 * never truncated, with no temporary file left. Retried with a longer
 * delay when the signal arrives before main() installs its handler. */
static void test_cli_sigterm_sighup_replace_file_whole(void **state)
{
    (void)state;
    char err[4096], full[8192], path[1024], errpath[1024];
    const char *b = mc_test_build_dir();
    static const int sigs[2] = {SIGTERM, SIGHUP};
    static const char *const names[2] = {"TERM", "HUP"}, *const words[2] = {"terminated", "hung up"};
    snprintf(path, sizeof path, "%s/cli_term.png", b);
    snprintf(errpath, sizeof errpath, "%s/cli.err", b);
    for (int k = 0; k < 2; k++) {
        int rc = -1;
        for (int delay = 1; delay <= 4; delay *= 2) {
            write_text(path, "the previous image\n");
            snprintf(full, sizeof full,
                     "timeout --preserve-status -s %s %d %s/bin/cornell_box --scene book --width 64 "
                     "--spp 1e6 -o %s >/dev/null 2>%s",
                     names[k], delay, b, path, errpath);
            rc = system(full);
            assert_true(WIFEXITED(rc));
            slurp(errpath, err, sizeof err);
            if (err[0])
                break;
            printf("SIG%s after %d s arrived before the program started; retrying\n", names[k], delay);
        }
        if (WEXITSTATUS(rc) != 128 + sigs[k] || !strstr(err, words[k]) || !strstr(err, "samples"))
            fail_msg("SIG%s: exit %d, stderr '%s'", names[k], WEXITSTATUS(rc), err);
        if (!png_complete(path))
            fail_msg("SIG%s: %s is not a complete PNG", names[k], path);
        assert_false(has_temp_file(b, "cli_term.png"));
    }
    remove(path);
}

/* A write error while the image is written (here the file-size limit,
 * with SIGXFSZ ignored so that write(2) fails with EFBIG) leaves the old
 * file as it was and no temporary file; exit 1 with one line. */
static void test_cli_write_error_keeps_old_file(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], path[1024], buf[256];
    const char *b = mc_test_build_dir();
    snprintf(path, sizeof path, "%s/cli_full.pfm", b);
    write_text(path, "the previous image\n");
    /* 64x64 PFM: 49 kB against a limit of 8 blocks of 512 bytes. */
    snprintf(args, sizeof args, "--width 64 --spp 2 -o %s", path);
    char full[8192];
    snprintf(full, sizeof full,
             "sh -c \"trap '' XFSZ; ulimit -f 8; exec %s/bin/cornell_box %s\" >%s/cli.out 2>%s/cli.err", b,
             args, b, b);
    int rc = system(full);
    snprintf(full, sizeof full, "%s/cli.err", b);
    slurp(full, err, sizeof err);
    (void)out;
    if (!WIFEXITED(rc) || WEXITSTATUS(rc) != 1 || count_lines(err) != 1 || strncmp(err, "cornell_box: ", 13))
        fail_msg("write error: exit %d, stderr '%s'", WEXITSTATUS(rc), err);
    assert_int_equal(slurp(path, buf, sizeof buf), (long)strlen("the previous image\n"));
    assert_string_equal(buf, "the previous image\n");
    assert_false(has_temp_file(b, "cli_full.pfm"));
    remove(path);
}

/* Refusals before any rendering, each exit 2 with one line and the old
 * file untouched: a directory that cannot be written (when not root,
 * for whom permissions do not apply), a path that is a directory, and an
 * image larger than the memory the process may use (an address-space
 * limit of 1 GB against the 5.6 GB a 8192x8192 image needs; without a
 * limit, 65536x65536 needs 357 GB). The line gives the size needed. */
static void test_cli_refusals_keep_old_file(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], dir[1024], path[1100], dpath[1100], buf[256];
    const char *b = mc_test_build_dir();
    snprintf(dir, sizeof dir, "%s/cli_ro", b);
    mkdir(dir, 0755);
    snprintf(path, sizeof path, "%s/old.png", dir);
    write_text(path, "the previous image\n");
    if (geteuid() != 0) {
        assert_int_equal(chmod(dir, 0555), 0);
        snprintf(args, sizeof args, "--width 8 --spp 1 -o %s", path);
        int rc = run(args, out, sizeof out, err, sizeof err);
        chmod(dir, 0755);
        if (rc != 2 || count_lines(err) != 1 || out[0])
            fail_msg("unwritable directory: exit %d, stderr '%s'", rc, err);
    } else {
        printf("running as root: the unwritable-directory case is skipped\n");
    }
    snprintf(args, sizeof args, "--width 8 --spp 1 -o %s/d.png", dir);
    snprintf(dpath, sizeof dpath, "%s/d.png", dir);
    mkdir(dpath, 0755);
    int rc = run(args, out, sizeof out, err, sizeof err);
    rmdir(dpath);
    if (rc != 2 || count_lines(err) != 1 || out[0])
        fail_msg("output path is a directory: exit %d, stderr '%s'", rc, err);
    snprintf(args, sizeof args, "--width 65536 -o %s", path);
    rc = run(args, out, sizeof out, err, sizeof err);
    if (rc != 2 || count_lines(err) != 1 || !strstr(err, "GB") || out[0])
        fail_msg("--width 65536: exit %d, stderr '%s'", rc, err);
    char full[8192];
    snprintf(full, sizeof full, "sh -c 'ulimit -v 1000000; exec %s/bin/cornell_box --width 8192 -o %s' "
             ">%s/cli.out 2>%s/cli.err", b, path, b, b);
    rc = system(full);
    snprintf(full, sizeof full, "%s/cli.err", b);
    slurp(full, err, sizeof err);
    /* AddressSanitizer reserves terabytes of address space for its shadow
     * memory and cannot start under such a limit. */
    if (strstr(err, "Sanitizer") || strstr(err, "ReserveShadowMemoryRange"))
        printf("sanitizer build: the address-space limit case is skipped\n");
    else if (!WIFEXITED(rc) || WEXITSTATUS(rc) != 2 || count_lines(err) != 1 || !strstr(err, "GB"))
        fail_msg("--width 8192 under a 1 GB limit: exit %d, stderr '%s'", WEXITSTATUS(rc), err);
    assert_int_equal(slurp(path, buf, sizeof buf), (long)strlen("the previous image\n"));
    assert_string_equal(buf, "the previous image\n");
    assert_false(has_temp_file(dir, "old.png"));
    remove(path);
    rmdir(dir);
}

/* Every sampler writes the same file with one thread and with two. */
static void test_cli_samplers_thread_count(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], p1[1024], p2[1024], b1[65536], b2[65536];
    const char *b = mc_test_build_dir();
    static const char *const samplers[3] = {"independent", "stratified", "sobol"};
    snprintf(p1, sizeof p1, "%s/cli_s1.pfm", b);
    snprintf(p2, sizeof p2, "%s/cli_s2.pfm", b);
    for (int i = 0; i < 3; i++) {
        snprintf(args, sizeof args, "--scene book --width 16 --spp 6 --sampler %s --threads 1 -o %s",
                 samplers[i], p1);
        assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
        snprintf(args, sizeof args, "--scene book --width 16 --spp 6 --sampler %s --threads 2 -o %s",
                 samplers[i], p2);
        assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
        long n1 = slurp(p1, b1, sizeof b1), n2 = slurp(p2, b2, sizeof b2);
        if (n1 <= 0 || n1 != n2 || memcmp(b1, b2, (size_t)n1) != 0)
            fail_msg("--sampler %s: 1 and 2 threads give different files", samplers[i]);
    }
    remove(p1);
    remove(p2);
}

/* The run mode without instruction-set code (MCBOX_ISA=portable,
 * render/engine.h) writes the same bytes as the default engine, for every
 * strategy on the three Cornell scenes; tests/test_render_engine.c shows
 * that the variable does select the portable engine. */
static void test_cli_portable_engine_same_bytes(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], p1[1024], p2[1024], b1[65536], b2[65536];
    const char *b = mc_test_build_dir();
    static const char *const scenes[] = {"book", "book-metal", "lambert"};
    static const char *const strategies[] = {"uniform", "cosine", "light", "mixture", "mis",
                                             "lighttrace", "bdpt", "bdpt --roulette"};
    snprintf(p1, sizeof p1, "%s/cli_isa1.pfm", b);
    snprintf(p2, sizeof p2, "%s/cli_isa2.pfm", b);
    int compared = 0;
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        for (size_t j = 0; j < sizeof strategies / sizeof strategies[0]; j++) {
            snprintf(args, sizeof args, "--scene %s --width 16 --spp 6 --strategy %s -o %s", scenes[i],
                     strategies[j], p1);
            assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
            /* run() puts the program's path first: the variable goes in
             * through the environment of this process, which the shell
             * passes on. */
            assert_int_equal(setenv("MCBOX_ISA", "portable", 1), 0);
            snprintf(args, sizeof args, "--scene %s --width 16 --spp 6 --strategy %s -o %s", scenes[i],
                     strategies[j], p2);
            int rc = run(args, out, sizeof out, err, sizeof err);
            assert_int_equal(unsetenv("MCBOX_ISA"), 0);
            assert_int_equal(rc, 0);
            long n1 = slurp(p1, b1, sizeof b1), n2 = slurp(p2, b2, sizeof b2);
            if (n1 <= 0 || n1 != n2 || memcmp(b1, b2, (size_t)n1) != 0)
                fail_msg("--scene %s --strategy %s: MCBOX_ISA=portable writes other bytes", scenes[i],
                         strategies[j]);
            compared++;
        }
    printf("MCBOX_ISA=portable = the default engine, byte for byte, in %d renders\n", compared);
    remove(p1);
    remove(p2);
}

/* --reference: against the image the same command wrote, the RMSE is
 * only the float rounding of the file (below 1e-6 of values near 1);
 * against another seed's, it is positive; a missing file, a file that is
 * not a PFM and a PFM of another size each give exit 2 and one line,
 * before any rendering. */
static void test_cli_reference(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048], ref[1024], txt[1024];
    const char *b = mc_test_build_dir();
    snprintf(ref, sizeof ref, "%s/cli_ref.pfm", b);
    snprintf(txt, sizeof txt, "%s/cli_ref.txt", b);
    snprintf(args, sizeof args, "--scene lambert --width 8 --spp 4 --threads 1 -o %s", ref);
    assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
    for (int seed = 1; seed <= 2; seed++) {
        snprintf(args, sizeof args,
                 "--scene lambert --width 8 --spp 4 --seed %d --threads 2 --reference %s -o %s/cli_r.pfm",
                 seed, ref, b);
        assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
        const char *at = strstr(out, "pixel RMSE ");
        assert_non_null(at);
        double rmse = -1.0, mse = -1.0;
        assert_int_equal(sscanf(at, "pixel RMSE %lf, MSE %lf", &rmse, &mse), 2);
        assert_near(rmse * rmse, mse, 1e-6 * mse);
        if (seed == 1 ? !(rmse < 1e-6) : !(rmse > 1e-3))
            fail_msg("seed %d: RMSE %g against the seed-1 image", seed, rmse);
    }
    write_text(txt, "not an image\n");
    const char *refs[3] = {"%s/no-such.pfm", "%s/cli_ref.txt", "%s/cli_ref.pfm"};
    for (int i = 0; i < 3; i++) {
        char r[1024];
        snprintf(r, sizeof r, refs[i], b);
        snprintf(args, sizeof args, "--scene lambert --width %d --spp 4 --reference %s -o %s/cli_r.pfm",
                 i == 2 ? 9 : 8, r, b);
        int rc = run(args, out, sizeof out, err, sizeof err);
        if (rc != 2 || out[0] || count_lines(err) != 1 || strncmp(err, "cornell_box: ", 13) != 0)
            fail_msg("--reference %s: exit %d, stdout '%s', stderr '%s'", r, rc, out, err);
    }
    remove(ref);
    remove(txt);
    snprintf(args, sizeof args, "%s/cli_r.pfm", b);
    remove(args);
}

/* The furnace prints its exact value, E (1 - rho^D) / (1 - rho) = 1 - 2^-50
 * for the named scene at depth 50, and a z that must be below 4 (seed 1,
 * 8 x 8 pixels, 16 samples each; false-alarm rate 6.3e-5); the lambert
 * scene's image mean has no closed form and leaves the field empty. */
static void test_cli_furnace_prints_exact(void **state)
{
    (void)state;
    char out[4096], err[4096], args[2048];
    const char *b = mc_test_build_dir();
    snprintf(args, sizeof args, "--scene furnace --width 8 --spp 16 --threads 1 --seed 1 --csv -o %s/cli_f.pfm",
             b);
    assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
    const char *row = strstr(out, "\nmean_linear_r,");
    assert_non_null(row);
    double n, estimate, std_error, exact, z;
    assert_int_equal(sscanf(row + 1, "mean_linear_r,%lf,%lf,%lf,%lf,%lf", &n, &estimate, &std_error, &exact, &z),
                     5);
    assert_near(exact, 1.0 - 0x1p-50, 0.0);
    assert_z_below("cornell_box furnace image mean", estimate, exact, std_error, 4.0, 1);
    assert_near(z, (estimate - exact) / std_error, 1e-5 * (1.0 + fabs(z)));
    snprintf(args, sizeof args, "--scene lambert --width 8 --spp 4 --threads 1 --csv -o %s/cli_f.pfm", b);
    assert_int_equal(run(args, out, sizeof out, err, sizeof err), 0);
    row = strstr(out, "\nmean_linear_r,");
    assert_non_null(row);
    const char *end = strchr(row + 1, '\n');
    size_t len = end ? (size_t)(end - row - 1) : strlen(row + 1);
    if (len < 2 || row[len] != ',' || row[len - 1] != ',')
        fail_msg("lambert: the exact and z fields are not empty: '%.*s'", (int)len, row + 1);
    snprintf(args, sizeof args, "%s/cli_f.pfm", b);
    remove(args);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli_bad_input),
        cmocka_unit_test(test_cli_writes_images),
        cmocka_unit_test(test_cli_sigint_writes_partial_image),
        cmocka_unit_test(test_cli_sigterm_sighup_replace_file_whole),
        cmocka_unit_test(test_cli_write_error_keeps_old_file),
        cmocka_unit_test(test_cli_refusals_keep_old_file),
        cmocka_unit_test(test_cli_furnace_prints_exact),
        cmocka_unit_test(test_cli_samplers_thread_count),
        cmocka_unit_test(test_cli_reference),
        cmocka_unit_test(test_cli_portable_engine_same_bytes),
    };
    return cmocka_run_group_tests_name("test_render_cli", tests, NULL, NULL);
}
