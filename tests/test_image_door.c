/* tests/test_image_door.c - mcbox-check's image door end to end: renders
 * written by the cornell_box and buggy_box programs (PFM, gamma-2 PNG, and
 * a PPM encoded here by the write_color of Shirley's books) judged against
 * a conformance scene, an exact truth file, a noisy reference and a
 * moment pair; a correct renderer passes, a buggy one fails with its bias
 * located, the wrong transfer curve is caught, and every bad input exits 2
 * with one line. Seeds 1 .. 3 (quad-wall, 32 x 32, 64 spp, mis). Runs the
 * programs built in $MC_BUILD/bin. */
#define _XOPEN_SOURCE 700 /* mkdtemp, realpath */

#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "imageio/image_io.h"
#include "conform/truth.h"

static char dir[1024], bin[1024];
static char out[1 << 16], err[4096];

/* Runs `cmd` (shell syntax, in the scratch directory, the build's bin/
 * first on PATH); returns its exit status, stdout in out, stderr in err. */
static int sh(const char *fmt, ...)
{
    char cmd[8192], body[3072];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(body, sizeof body, fmt, ap);
    va_end(ap);
    snprintf(cmd, sizeof cmd, "cd '%s' && export PATH='%s':\"$PATH\" && { %s; } >out.txt 2>err.txt",
             dir, bin, body);
    int rc = system(cmd);
    char path[1200];
    snprintf(path, sizeof path, "%s/out.txt", dir);
    mc_test_read_text(path, out, sizeof out);
    snprintf(path, sizeof path, "%s/err.txt", dir);
    mc_test_read_text(path, err, sizeof err);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static void expect_text(const char *text, const char *words)
{
    if (!strstr(text, words))
        fail_msg("expected '%s' in:\n%s", words, text);
}

/* Exit 2 with exactly one line on stderr, naming the program and saying
 * `words`. */
static void expect_refusal(int rc, const char *words)
{
    assert_int_equal(rc, 2);
    expect_text(err, "mcbox-check: ");
    expect_text(err, words);
    assert_int_equal(strchr(err, '\n') - err, (long)strlen(err) - 1);
}

static const char RENDER[] = "cornell_box --scene quad-wall --strategy mis --width 32 --spp 64";

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "%s/image_door.XXXXXX", mc_test_build_dir());
    char rel[1024];
    snprintf(rel, sizeof rel, "%s/bin", mc_test_build_dir());
    if (!mkdtemp(dir) || !realpath(rel, bin))
        return -1;
    for (int s = 1; s <= 3; s++)
        if (sh("%s --seed %d -o r%d.pfm && %s --seed %d -o r%d.png --gamma 2", RENDER, s, s,
               RENDER, s, s) != 0)
            return -1;
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static void test_pass_and_fail(void **state)
{
    (void)state;
    assert_int_equal(sh("mcbox-check --image r1.pfm --image r2.pfm --image r3.pfm --scene "
                        "quad-wall --junit ok.xml"), 0);
    expect_text(out, "render: pass");
    expect_text(out, "power: a bias of");
    assert_int_equal(sh("cat ok.xml"), 0);
    expect_text(out, "failures=\"0\" errors=\"0\"");
    assert_int_equal(sh("mcbox-check --json --name box --image r1.pfm --image r2.pfm --scene "
                        "quad-wall"), 0);
    expect_text(out, "{\"name\": \"box\", \"verdict\": \"pass\"");
    expect_text(out, "\"block_z\": [");
    /* The area density taken for the solid-angle one: brighter, most near
     * the emitter's plane, and the picture written. */
    assert_int_equal(sh("buggy_box --bug area-density --width 32 --seed 1 -o b1.pfm && "
                        "buggy_box --bug area-density --width 32 --seed 2 -o b2.pfm"), 0);
    assert_int_equal(sh("mcbox-check --image b1.pfm --image b2.pfm --scene quad-wall "
                        "--picture bias.png --junit bad.xml"), 1);
    expect_text(out, "render: FAIL");
    expect_text(out, "within 0.2 of the emitter's plane");
    expect_text(out, "brighter by");
    assert_int_equal(sh("head -c 8 bias.png | od -An -tx1"), 0);
    expect_text(out, "89 50 4e 47 0d 0a 1a 0a");
    assert_int_equal(sh("cat bad.xml"), 0);
    expect_text(out, "failures=\"1\"");
}

/* Shirley's write_color: e = sqrt(x), code = int(256 clamp(e, 0, 0.999)). */
static unsigned char book_code(double x)
{
    double e = x > 0.0 ? sqrt(x) : 0.0;
    e = e < 0.0 ? 0.0 : e > 0.999 ? 0.999 : e;
    return (unsigned char)(256.0 * e);
}

static void write_book_ppm(const char *pfm, const char *ppm)
{
    char path[1200], why[256];
    img_picture p;
    snprintf(path, sizeof path, "%s/%s", dir, pfm);
    assert_int_equal(img_picture_read(path, IMG_TRANSFER_LINEAR, &p, why, sizeof why), 0);
    snprintf(path, sizeof path, "%s/%s", dir, ppm);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fprintf(f, "P6\n%d %d\n255\n", p.width, p.height);
    for (size_t i = 0; i < (size_t)p.width * (size_t)p.height * 3; i++)
        fputc(book_code(p.value[i]), f);
    assert_int_equal(fclose(f), 0);
    img_picture_free(&p);
}

static void test_eight_bit(void **state)
{
    (void)state;
    assert_int_equal(sh("mcbox-check --image r1.png --image r2.png --image r3.png --transfer "
                        "gamma2 --scene quad-wall"), 0);
    /* The same codes decoded with the wrong curve are not the truth. */
    assert_int_equal(sh("mcbox-check --image r1.png --image r2.png --image r3.png --transfer "
                        "srgb --scene quad-wall"), 1);
    for (int s = 1; s <= 3; s++) {
        char a[16], b[16];
        snprintf(a, sizeof a, "r%d.pfm", s);
        snprintf(b, sizeof b, "k%d.ppm", s);
        write_book_ppm(a, b);
    }
    assert_int_equal(sh("mcbox-check --image k1.ppm --image k2.ppm --image k3.ppm --transfer "
                        "book --scene quad-wall"), 0);
    expect_refusal(sh("mcbox-check --image r1.png --image r2.png --scene quad-wall"),
                   "--transfer");
}

static void test_truth_files(void **state)
{
    (void)state;
    /* The exact truth as a file, and a noisy reference with its noise. */
    const cf_scene *s = cf_scene_find("quad-wall");
    double g[32 * 32], rgb[32 * 32 * 3], se[32 * 32 * 3], e;
    assert_int_equal(cf_truth_image(s, 32, 32, g, &e), 0);
    for (int i = 0; i < 32 * 32 * 3; i++)
        rgb[i] = g[i / 3], se[i] = 1e-3 * g[i / 3];
    char path[1200], why[256];
    snprintf(path, sizeof path, "%s/truth.pfm", dir);
    assert_int_equal(img_picture_write_pfm(path, 32, 32, rgb, why, sizeof why), 0);
    snprintf(path, sizeof path, "%s/noise.pfm", dir);
    assert_int_equal(img_picture_write_pfm(path, 32, 32, se, why, sizeof why), 0);
    /* The file's own rounding (2^-24 of each value) is allowed for. */
    assert_int_equal(sh("mcbox-check --image r1.pfm --image r2.pfm --truth truth.pfm"), 0);
    assert_int_equal(sh("mcbox-scene truth quad-wall --size 32 -o exact.pfm && mcbox-check "
                        "--image r1.pfm --image r2.pfm --truth exact.pfm"), 0);
    assert_int_equal(sh("mcbox-check --image r1.pfm --image r2.pfm --reference truth.pfm "
                        "--reference-noise noise.pfm"), 0);
    /* A moment pair: the mean and the mean of squares of the three renders,
     * each one sample of the pixel. */
    img_picture p[3];
    double mean[32 * 32 * 3] = {0}, second[32 * 32 * 3] = {0};
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/r%d.pfm", dir, k + 1);
        assert_int_equal(img_picture_read(path, IMG_TRANSFER_LINEAR, &p[k], why, sizeof why), 0);
        for (int i = 0; i < 32 * 32 * 3; i++)
            mean[i] += p[k].value[i] / 3.0, second[i] += p[k].value[i] * p[k].value[i] / 3.0;
        img_picture_free(&p[k]);
    }
    snprintf(path, sizeof path, "%s/mean.pfm", dir);
    assert_int_equal(img_picture_write_pfm(path, 32, 32, mean, why, sizeof why), 0);
    snprintf(path, sizeof path, "%s/second.pfm", dir);
    assert_int_equal(img_picture_write_pfm(path, 32, 32, second, why, sizeof why), 0);
    assert_int_equal(sh("mcbox-check --image-mean mean.pfm --image-second second.pfm --spp 3 "
                        "--scene quad-wall"), 0);
    expect_text(out, "taken as independent");
}

/* The book's Cornell box has no closed form: two bidirectional
 * references (seeds 1001, 1002, 512 spp) measure their own noise; the
 * book's mixture renders pass against them, the aluminium box's fail. */
static void test_cornell_references(void **state)
{
    (void)state;
    assert_int_equal(sh("for s in 1001 1002; do cornell_box --scene book --strategy bdpt "
                        "--roulette --width 24 --spp 512 --seed $s -o ref$s.pfm; done && "
                        "for s in 1 2 3; do cornell_box --scene book --width 24 --spp 128 "
                        "--seed $s -o c$s.pfm && cornell_box --scene book-metal --width 24 "
                        "--spp 128 --seed $s -o m$s.pfm; done"), 0);
    assert_int_equal(sh("mcbox-check --image c1.pfm --image c2.pfm --image c3.pfm --reference "
                        "ref1001.pfm --reference ref1002.pfm"), 0);
    expect_text(out, "against the mean of 2 references");
    assert_int_equal(sh("mcbox-check --image m1.pfm --image m2.pfm --image m3.pfm --reference "
                        "ref1001.pfm --reference ref1002.pfm"), 1);
    expect_refusal(sh("mcbox-check --image c1.pfm --image c2.pfm --reference ref1001.pfm"),
                   "--reference-noise");
}

static void test_bad_inputs(void **state)
{
    (void)state;
    expect_refusal(sh("mcbox-check --image r1.pfm --scene quad-wall"), "2 or more");
    expect_refusal(sh("mcbox-check --image r1.pfm --image r2.pfm --scene quad"),
                   "not a conformance scene");
    expect_refusal(sh("mcbox-check --image r1.pfm --image r2.pfm --scene quad-wall --truth r3.pfm"),
                   "exactly one of");
    expect_refusal(sh("mcbox-check --image r1.pfm --image r2.pfm"), "exactly one of");
    expect_refusal(sh("mcbox-check --image r1.pfm --image no.pfm --scene quad-wall"), "no.pfm");
    expect_refusal(sh("cornell_box --scene quad-wall --width 16 --spp 1 -o small.pfm && "
                      "mcbox-check --image r1.pfm --image small.pfm --scene quad-wall"),
                   "is 16x16, the first render 32x32");
    expect_refusal(sh("mcbox-check --image-mean r1.pfm --scene quad-wall"), "moment pair");
    expect_refusal(sh("mcbox-check --image r1.pfm --image r2.pfm --scene quad-wall --alpha 2"),
                   "--alpha 2");
    expect_refusal(sh("mcbox-check --image r1.pfm --image r2.pfm --scene quad-wall --bogus 1"),
                   "--bogus");
    /* A NaN, and a clamped 8-bit pixel where the truth is far below the
     * clamp. */
    double v[4 * 4 * 3];
    for (int i = 0; i < 48; i++)
        v[i] = 0.1;
    v[7] = (double)NAN;
    char path[1200], why[256];
    snprintf(path, sizeof path, "%s/nan.pfm", dir);
    assert_int_equal(img_picture_write_pfm(path, 4, 4, v, why, sizeof why), 0);
    expect_refusal(sh("cp nan.pfm nan2.pfm && mcbox-check --image nan.pfm --image nan2.pfm "
                      "--scene quad-wall"), "non-finite");
    expect_refusal(sh("printf 'P6\\n1 1\\n255\\n\\377\\377\\377' > top.ppm && cp top.ppm top2.ppm "
                      "&& mcbox-check --image top.ppm --image top2.ppm --transfer gamma2 "
                      "--scene quad-wall"), "clamped");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pass_and_fail),
        cmocka_unit_test(test_eight_bit),
        cmocka_unit_test(test_truth_files),
        cmocka_unit_test(test_cornell_references),
        cmocka_unit_test(test_bad_inputs),
    };
    mc_test_select();
    return cmocka_run_group_tests(tests, setup, teardown);
}
