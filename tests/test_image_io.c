/* tests/test_image_io.c - the image readers of the image check
 * (imageio/image_io.h): PFM in both byte orders, PPM (P6 with a comment,
 * 16-bit, P3) and PNG files written here by hand or through libpng with
 * known values (OpenEXR: tests/test_image_exr.c), the intervals of codes under
 * every transfer against hand-derived numbers, grey replication, row
 * order, and every refusal with its reason. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "tests/support/mc_test.h"

#include <dirent.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "imageio/image_io.h"

#include "tests/support/picture_files.h"

static void test_transfer_names_and_decode(void **state)
{
    (void)state;
    static const char *const names[] = {"linear", "gamma2", "gamma2.2", "srgb", "book"};
    img_transfer t = IMG_TRANSFER_LINEAR;
    for (int i = 0; i < 5; i++) {
        assert_string_equal(img_transfer_names[i], names[i]);
        assert_int_equal(img_transfer_parse(names[i], &t), 0);
        assert_int_equal(t, i);
    }
    assert_null(img_transfer_names[5]);
    assert_int_equal(img_transfer_parse("sRGB", &t), -1);
    assert_int_equal(img_transfer_parse("2.2", &t), -1);
    assert_int_equal(t, IMG_TRANSFER_BOOK);
    assert_near(img_transfer_decode(IMG_TRANSFER_LINEAR, 0.2385), 0.2385, 0.0);
    assert_near(img_transfer_decode(IMG_TRANSFER_GAMMA2, 0.7), 0.49, 1e-15);
    assert_near(img_transfer_decode(IMG_TRANSFER_BOOK, 0.7), 0.49, 1e-15);
    assert_near(img_transfer_decode(IMG_TRANSFER_GAMMA22, 0.5), 0.21763764082403103, 1e-15);
    assert_near(img_transfer_decode(IMG_TRANSFER_SRGB, 0.5), 0.21404114048223255, 1e-15);
    assert_near(img_transfer_decode(IMG_TRANSFER_SRGB, 0.0323), 0.0323 / 12.92, 1e-17);
    assert_near(img_transfer_decode(IMG_TRANSFER_SRGB, 1.7), 1.0, 0.0);
    assert_near(img_transfer_decode(IMG_TRANSFER_GAMMA22, -0.3), 0.0, 0.0);
    assert_near(img_transfer_decode(IMG_TRANSFER_GAMMA2, (double)NAN), 0.0, 0.0);
}

/* A 3 x 2 colour PFM whose file rows run bottom to top: the picture's
 * top row is the file's second row, in either byte order. */
static void test_pfm_byte_orders_and_row_order(void **state)
{
    (void)state;
    /* 0.25, 0.5, 1, 2, 3.5, 0.75, 1.5, 0.125, 6, 0 as IEEE bits. */
    static const uint32_t bits[10] = {0x3E800000, 0x3F000000, 0x3F800000, 0x40000000, 0x40600000,
                                      0x3F400000, 0x3FC00000, 0x3E000000, 0x40C00000, 0x00000000};
    static const double val[10] = {0.25, 0.5, 1.0, 2.0, 3.5, 0.75, 1.5, 0.125, 6.0, 0.0};
    for (int little = 0; little < 2; little++) {
        const char *head = little ? "PF\n3 2\n-1.0\n" : "PF 3\n2\n1\n";
        unsigned char b[32 + 72];
        size_t h = strlen(head);
        memcpy(b, head, h);
        for (int i = 0; i < 18; i++) /* sample i of the file: bits[(i * 7) % 10] */
            put_bits(b + h + 4 * i, bits[i * 7 % 10], little);
        img_picture p;
        read_ok(write_bytes("rows.pfm", b, h + 72), IMG_TRANSFER_LINEAR, &p);
        assert_true(p.width == 3 && p.height == 2 && p.bits == 0 && !p.lo && !p.hi);
        assert_string_equal(p.format, "pfm");
        for (int i = 0; i < 18; i++) /* file sample i: file row i / 9, from the bottom */
            assert_near(V(p, i % 9 / 3, 1 - i / 9, i % 3), val[i * 7 % 10], 0.0);
        img_picture_free(&p);
        assert_null(p.value);
        img_picture_free(&p); /* twice: harmless */
    }
}

static void test_pfm_grey_replicated(void **state)
{
    (void)state;
    unsigned char b[64];
    size_t h = strlen("Pf\n2 1\n-2.5\n");
    memcpy(b, "Pf\n2 1\n-2.5\n", h);
    put_bits(b + h, 0x40190000, 1); /* 2.390625 */
    put_bits(b + h + 4, 0x3E800000, 1);
    img_picture p;
    read_ok(write_bytes("grey.pfm", b, h + 8), IMG_TRANSFER_LINEAR, &p);
    for (int c = 0; c < 3; c++) {
        assert_near(V(p, 0, 0, c), 2.390625, 0.0);
        assert_near(V(p, 1, 0, c), 0.25, 0.0);
    }
    img_picture_free(&p);
}

/* The writer's bytes: the header, then the bottom row first, each float
 * little-endian; they read back to the float of every value. */
static void test_pfm_writer(void **state)
{
    (void)state;
    const double rgb[12] = {0.25, 0.5, 1.0, 2.0, 3.5, 0.75, 1.5, 0.125, 6.0, 0.0, 2.385, 1e-3};
    char why[128] = "";
    const char *path = path_of("written.pfm");
    assert_int_equal(img_picture_write_pfm(path, 2, 2, rgb, why, sizeof why), 0);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    unsigned char b[64];
    assert_int_equal(fread(b, 1, sizeof b, f), 12 + 48);
    fclose(f);
    assert_memory_equal(b, "PF\n2 2\n-1.0\n", 12);
    static const unsigned char bottom[8] = {0, 0, 0xC0, 0x3F, 0, 0, 0, 0x3E}; /* 1.5, 0.125 */
    assert_memory_equal(b + 12, bottom, 8);
    img_picture p;
    read_ok(path, IMG_TRANSFER_LINEAR, &p);
    for (int i = 0; i < 12; i++)
        assert_near(p.value[i], (double)(float)rgb[i], 0.0);
    img_picture_free(&p);
    assert_int_equal(img_picture_write_pfm(path, 0, 2, rgb, why, sizeof why), -1);
    const char *nowhere = "/nonexistent/dir/x.pfm";
    assert_int_equal(img_picture_write_pfm(nowhere, 2, 2, rgb, why, sizeof why), -1);
    assert_non_null(strstr(why, "cannot create /nonexistent/dir/x.pfm"));
}

/* A P6 with comments and the same codes in a P3, linear: code k is k/255
 * and stands for [(k - 0.5)/255, (k + 0.5)/255], cut at 0 and open above
 * 255. */
static void test_ppm_p6_comment_and_p3(void **state)
{
    (void)state;
    static const char p6[] = "P6\n# by hand\n3 1 # three pixels\n255\n\x00\x01\x80\xfe\xff\x07\x63\x00\x01";
    static const char p3[] = "P3 3 1\n255\n0 1 128 254 # a comment\n 255 7 99 0 1\n";
    const char *paths[2] = {write_bytes("c.ppm", p6, sizeof p6 - 1),
                            write_bytes("a.ppm", p3, sizeof p3 - 1)};
    static const int code[9] = {0, 1, 128, 254, 255, 7, 99, 0, 1};
    for (int f = 0; f < 2; f++) {
        img_picture p;
        read_ok(paths[f], IMG_TRANSFER_LINEAR, &p);
        assert_string_equal(p.format, "ppm");
        assert_true(p.bits == 8 && p.width == 3 && p.height == 1);
        for (int i = 0; i < 9; i++) {
            int k = code[i];
            assert_near(p.value[i], k / 255.0, 1e-15);
            assert_near(p.lo[i], k == 0 ? 0.0 : (k - 0.5) / 255.0, 1e-15);
            if (k == 255)
                assert_true(isinf(p.hi[i]) && p.hi[i] > 0);
            else
                assert_near(p.hi[i], (k + 0.5) / 255.0, 1e-15);
        }
        img_picture_free(&p);
    }
}

/* 16-bit big-endian samples under gamma 2: code k is (k/65535)^2. */
static void test_ppm_16_bit(void **state)
{
    (void)state;
    static const char b[] = "P6\n1 2\n65535\n\x00\x00\x80\x00\xff\xff\x00\x01\x12\x34\xff\xfe";
    img_picture p;
    read_ok(write_bytes("wide.ppm", b, sizeof b - 1), IMG_TRANSFER_GAMMA2, &p);
    assert_int_equal(p.bits, 16);
    static const int code[6] = {0, 32768, 65535, 1, 0x1234, 65534};
    for (int i = 0; i < 6; i++) {
        double e = code[i] / 65535.0, lo = (code[i] - 0.5) / 65535.0, hi = (code[i] + 0.5) / 65535.0;
        assert_near(p.value[i], e * e, 1e-15);
        assert_near(p.lo[i], i == 0 ? 0.0 : lo * lo, 1e-15);
        if (i == 2)
            assert_true(isinf(p.hi[i]) && p.hi[i] > 0);
        else
            assert_near(p.hi[i], hi * hi, 1e-15);
    }
    img_picture_free(&p);
    refused(path_of("wide.ppm"), IMG_TRANSFER_BOOK, "transfer book is for 8-bit files");
}

/* Codes 0, 1, 128, 254, 255 under every transfer: value, lo, hi. The
 * gamma 2.2 and sRGB numbers were evaluated from the curves elsewhere
 * (sRGB 128 -> 0.2158605, the well-known middle grey). */
static void test_intervals_every_transfer(void **state)
{
    (void)state;
    static const char b[] = "P6 5 1 255 \x00\x00\x00\x01\x01\x01\x80\x80\x80\xfe\xfe\xfe\xff\xff\xff";
    const char *path = write_bytes("codes.ppm", b, sizeof b - 1);
    const double inf = (double)INFINITY, a = 255.0, s = 256.0;
#define SQ(x) ((x) * (x))
    const double want[5][5][3] = {
        {{0, 0, 0.5 / a}, {1 / a, 0.5 / a, 1.5 / a}, {128 / a, 0.5, 128.5 / a},
         {254 / a, 253.5 / a, 254.5 / a}, {1, 254.5 / a, inf}},
        {{0, 0, SQ(0.5 / a)}, {SQ(1 / a), SQ(0.5 / a), SQ(1.5 / a)},
         {SQ(128 / a), 0.25, SQ(128.5 / a)}, {SQ(254 / a), SQ(253.5 / a), SQ(254.5 / a)},
         {1, SQ(254.5 / a), inf}},
        {{0, 0, 1.104957598001188e-06},
         {5.077051900661759e-06, 1.104957598001188e-06, 1.2388318801139925e-05},
         {0.2195197180748679, 0.217637640824031, 0.2214106382812988},
         {0.9913928435929399, 0.9871044803371161, 0.9956913488173136},
         {1, 0.9956913488173136, inf}},
        {{0, 0, 0.00015176349177441876},
         {0.0003035269835488375, 0.00015176349177441876, 0.00045529047532325625},
         {0.21586050011389926, 0.21404114048223255, 0.21768884898113222},
         {0.9911020971138298, 0.986670533535366, 0.9955452497210776},
         {1, 0.9955452497210776, inf}},
        /* book: code 128 stands for [(128/256)^2, (129/256)^2). */
        {{SQ(0.5 / s), 0, SQ(1 / s)}, {SQ(1.5 / s), SQ(1 / s), SQ(2 / s)},
         {SQ(128.5 / s), 0.25, SQ(129 / s)}, {SQ(254.5 / s), SQ(254 / s), SQ(255 / s)},
         {SQ(255.5 / s), SQ(255 / s), inf}},
    };
#undef SQ
    for (int t = 0; t < 5; t++) {
        img_picture p;
        read_ok(path, (img_transfer)t, &p);
        for (size_t i = 0; i < 15; i++) {
            const double *w = want[t][i / 3];
            if (fabs(p.value[i] - w[0]) > 1e-13 || fabs(p.lo[i] - w[1]) > 1e-13 ||
                !(p.hi[i] == w[2] || fabs(p.hi[i] - w[2]) <= 1e-13))
                fail_msg("%s sample %zu: %.17g [%.17g, %.17g], expected %.17g [%.17g, %.17g]",
                         img_transfer_names[t], i, p.value[i], p.lo[i], p.hi[i], w[0], w[1], w[2]);
        }
        img_picture_free(&p);
    }
}

/* A PNG through libpng: colour type, depth, samples (top row first, one
 * per channel), an optional palette; its gAMA claim must be ignored. */
static const char *write_png(const char *name, int w, int h, int color, int depth,
                             const unsigned *s, const png_color *palette)
{
    const char *path = path_of(name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng could not write %s", path);
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, color, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (palette)
        png_set_PLTE(png, info, palette, 2);
    png_set_gAMA(png, info, 1.0 / 2.2);
    png_write_info(png, info);
    int nch = png_get_channels(png, info);
    unsigned char row[256];
    for (int y = 0; y < h; y++) {
        for (int i = 0; i < w * nch; i++) {
            unsigned v = s[y * w * nch + i];
            if (depth == 16)
                row[2 * i] = (unsigned char)(v >> 8), row[2 * i + 1] = (unsigned char)(v & 255);
            else
                row[i] = (unsigned char)v;
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    assert_int_equal(fclose(f), 0);
    return path;
}

static void test_png_kinds(void **state)
{
    (void)state;
    img_picture p;
    /* RGB 8-bit, 2 x 2: the first row written is the top row. */
    static const unsigned rgb[12] = {0, 1, 128, 254, 255, 7, 9, 8, 7, 6, 5, 4};
    read_ok(write_png("rgb.png", 2, 2, PNG_COLOR_TYPE_RGB, 8, rgb, NULL), IMG_TRANSFER_LINEAR, &p);
    assert_string_equal(p.format, "png");
    assert_int_equal(p.bits, 8);
    for (int i = 0; i < 12; i++)
        assert_near(p.value[i], rgb[i] / 255.0, 1e-15);
    img_picture_free(&p);
    /* Grey 16-bit, 3 x 1: each code on all three channels. */
    static const unsigned grey[3] = {0, 32768, 65535};
    read_ok(write_png("grey.png", 3, 1, PNG_COLOR_TYPE_GRAY, 16, grey, NULL), IMG_TRANSFER_LINEAR,
            &p);
    assert_int_equal(p.bits, 16);
    for (int i = 0; i < 9; i++)
        assert_near(p.value[i], grey[i / 3] / 65535.0, 1e-15);
    img_picture_free(&p);
    /* Palette: indices expanded to their colours, here under book. */
    static const png_color pal[2] = {{10, 20, 30}, {200, 100, 50}};
    static const unsigned idx[2] = {1, 0};
    read_ok(write_png("pal.png", 1, 2, PNG_COLOR_TYPE_PALETTE, 8, idx, pal), IMG_TRANSFER_BOOK, &p);
    assert_near(V(p, 0, 0, 0), (200.5 / 256) * (200.5 / 256), 1e-15);
    assert_near(V(p, 0, 1, 2), (30.5 / 256) * (30.5 / 256), 1e-15);
    img_picture_free(&p);
    /* RGBA opaque everywhere reads; one alpha of 254 at (1, 1) does not,
     * nor a 16-bit grey+alpha with alpha 0 at (1, 0). */
    unsigned rgba[16] = {1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255, 10, 11, 12, 255};
    read_ok(write_png("rgba.png", 2, 2, PNG_COLOR_TYPE_RGBA, 8, rgba, NULL), IMG_TRANSFER_LINEAR,
            &p);
    assert_near(V(p, 1, 1, 2), 12 / 255.0, 1e-15);
    img_picture_free(&p);
    rgba[15] = 254;
    refused(write_png("rgba.png", 2, 2, PNG_COLOR_TYPE_RGBA, 8, rgba, NULL), IMG_TRANSFER_LINEAR,
            "transparent pixel at (1, 1)");
    static const unsigned ga[4] = {100, 65535, 200, 0};
    refused(write_png("ga.png", 2, 1, PNG_COLOR_TYPE_GA, 16, ga, NULL), IMG_TRANSFER_LINEAR,
            "transparent pixel at (1, 0)");
    refused(path_of("grey.png"), IMG_TRANSFER_BOOK, "transfer book is for 8-bit files");
    refused(cut_copy("rgb.png", "cut.png", 20), IMG_TRANSFER_LINEAR, "truncated data");
}

static void test_refusals(void **state)
{
    (void)state;
    unsigned char b[128];
    size_t h = strlen("PF\n2 2\n-1.0\n");
    memcpy(b, "PF\n2 2\n-1.0\n", h);
    for (int i = 0; i < 12; i++)
        put_bits(b + h + 4 * i, 0x3F000000, 1);
    refused(write_bytes("t.pfm", b, h + 40), IMG_TRANSFER_LINEAR,
            "truncated data: 40 bytes of pixels, 48 expected");
    refused(write_bytes("l.pfm", b, h + 48), IMG_TRANSFER_GAMMA2,
            "a float image is linear; --transfer applies to 8- and 16-bit files");
    put_bits(b + h + 4 * 4, 0x7FC00000, 1); /* NaN: file row 0 is the bottom, pixel (1, 1) G */
    refused(write_bytes("n.pfm", b, h + 48), IMG_TRANSFER_LINEAR,
            "non-finite value at pixel (1, 1) channel G");
    put_bits(b + h + 4 * 6, 0xBC23D70A, 1); /* -0.01 at (0, 0): the top row, read first */
    refused(write_bytes("m.pfm", b, h + 48), IMG_TRANSFER_LINEAR,
            "negative value -0.01 at pixel (0, 0)");
    static const struct {
        const char *bytes, *want;
    } bad[] = {
        {"", "not an image: the file is empty"},
        {"GIF89a", "not an image: unknown magic bytes 47 49 46 38"},
        {"PF\n0 2\n-1.0\n", "image size 0 x 2 outside 1..65536"},
        {"P6\n70000 1\n255\n", "image size 70000 x 1 outside 1..65536"},
        {"P6\n2 1\n255\nabcde", "truncated data: 5 bytes of pixels, 6 expected"},
        {"P6\n2 1\n255\nabcdefg", "7 bytes of pixels, 6 expected: the header's size"},
        {"P6\n2 1\n1023\nabcdef", "maxval 1023 not supported"},
        {"P6\n2 x\n255\nabcdef", "bad ppm header: height 'x'"},
        {"P6\n2 1", "truncated ppm header: no maxval"},
        {"P3\n2 1\n255\n1 2 3 4 5", "truncated data"},
        {"P3\n1 1\n255\n1 256 3", "bad sample '256' at pixel (0, 0)"},
        {"P5\n2 1\n255\nab", "a Netpbm P5 file"},
        {"PF\n1 1\nx\n1234", "bad pfm header: scale 'x'"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        refused(write_bytes("bad", bad[i].bytes, strlen(bad[i].bytes)), IMG_TRANSFER_LINEAR,
                bad[i].want);
    refused(path_of("missing.pfm"), IMG_TRANSFER_LINEAR, "cannot open ");
    img_picture p;
    assert_int_equal(img_picture_read(path_of("bad"), IMG_TRANSFER_LINEAR, &p, NULL, 0), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_transfer_names_and_decode),
        cmocka_unit_test(test_pfm_byte_orders_and_row_order),
        cmocka_unit_test(test_pfm_grey_replicated),
        cmocka_unit_test(test_pfm_writer),
        cmocka_unit_test(test_ppm_p6_comment_and_p3),
        cmocka_unit_test(test_ppm_16_bit),
        cmocka_unit_test(test_intervals_every_transfer),
        cmocka_unit_test(test_png_kinds),
        cmocka_unit_test(test_refusals),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_image_io", tests, make_dir, remove_dir);
}
