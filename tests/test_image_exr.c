/* tests/test_image_exr.c - the OpenEXR reader of the image check
 * (imageio/image_io.h, imageio/image_exr.c): files written through
 * OpenEXRCore's own writing API with known values: half scanlines under
 * four compressions with a data window off the origin, float tiles with
 * cut edge tiles, a uint Y channel, and the refusals. */
#include "tests/support/mc_test.h"

#include <OpenEXR/openexr.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imageio/image_io.h"
#include "tests/support/picture_files.h"

typedef struct exr_spec {
    int w, h;
    const char *names[4]; /* the channels, planes in this order */
    exr_pixel_type_t type;
    int tile;             /* tile side, 0 for scanlines */
    exr_compression_t comp;
    int origin;           /* the data window's first pixel, (origin, origin) */
    int crop;             /* a display window one pixel wider than the data */
} exr_spec;

/* An EXR through OpenEXRCore's writing API: planes holds one plane of
 * w * h samples (uint16_t half bits, float or uint32_t) per channel. */
static const char *write_exr(const char *name, exr_spec sp, const void *planes)
{
    const char *path = path_of(name);
    exr_context_t ctx;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    int part, nch = 0, bytes = sp.type == EXR_PIXEL_HALF ? 2 : 4;
    assert_int_equal(exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init), 0);
    exr_storage_t storage = sp.tile ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE;
    assert_int_equal(exr_add_part(ctx, "img", storage, &part), 0);
    exr_attr_box2i_t data = {.min = {.x = sp.origin, .y = sp.origin}}, shown;
    data.max.x = sp.origin + sp.w - 1, data.max.y = sp.origin + sp.h - 1, shown = data;
    shown.max.x += sp.crop;
    exr_attr_v2f_t centre = {.x = 0.0f, .y = 0.0f};
    assert_int_equal(exr_initialize_required_attr(ctx, part, &shown, &data, 1.0f, &centre, 1.0f,
                                                  EXR_LINEORDER_INCREASING_Y, sp.comp), 0);
    for (; nch < 4 && sp.names[nch]; nch++)
        assert_int_equal(exr_add_channel(ctx, part, sp.names[nch], sp.type,
                                         EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1), 0);
    if (sp.tile)
        assert_int_equal(exr_set_tile_descriptor(ctx, part, (uint32_t)sp.tile, (uint32_t)sp.tile,
                                                 EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN), 0);
    assert_int_equal(exr_write_header(ctx), 0);
    int32_t cw = sp.tile ? sp.tile : sp.w, ch = sp.tile;
    if (!sp.tile)
        assert_int_equal(exr_get_scanlines_per_chunk(ctx, part, &ch), 0);
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    for (int y0 = 0; y0 < sp.h; y0 += ch)
        for (int x0 = 0; x0 < sp.w; x0 += cw) {
            exr_chunk_info_t ci;
            assert_int_equal(sp.tile ? exr_write_tile_chunk_info(ctx, part, x0 / cw, y0 / ch, 0, 0, &ci)
                                     : exr_write_scanline_chunk_info(ctx, part, sp.origin + y0, &ci),
                             0);
            assert_int_equal(enc.channels ? exr_encoding_update(ctx, part, &ci, &enc)
                                          : exr_encoding_initialize(ctx, part, &ci, &enc), 0);
            for (int i = 0; i < enc.channel_count; i++) {
                exr_coding_channel_info_t *c = &enc.channels[i];
                size_t k = 0;
                while (strcmp(sp.names[k], c->channel_name) != 0)
                    k++;
                size_t at = k * (size_t)(sp.w * sp.h) + (size_t)(y0 * sp.w + x0);
                c->encode_from_ptr = (const uint8_t *)planes + at * (size_t)bytes;
                c->user_pixel_stride = bytes;
                c->user_line_stride = bytes * sp.w;
            }
            assert_int_equal(exr_encoding_choose_default_routines(ctx, part, &enc), 0);
            assert_int_equal(exr_encoding_run(ctx, part, &enc), 0);
        }
    assert_int_equal(exr_encoding_destroy(ctx, &enc), 0);
    assert_int_equal(exr_finish(&ctx), 0);
    return path;
}

/* Half bits of 0.5, 1, 2, 0.25, 65504 (the largest half) and 2^-24 (the
 * smallest), in scanline files of four lossless compressions, the data
 * window starting at (-2, -2). */
static void test_exr_half_scanlines(void **state)
{
    (void)state;
    static const uint16_t half[3][6] = {{0x3800, 0x3C00, 0x4000, 0x3400, 0x7BFF, 0x0001},
                                        {0x3C00, 0x0000, 0x3800, 0x4000, 0x3400, 0x7BFF},
                                        {0x0001, 0x3400, 0x0000, 0x3C00, 0x4000, 0x3800}};
    static const double val[7] = {0.5, 1.0, 2.0, 0.25, 65504.0, 5.9604644775390625e-08, 0.0};
    static const int from[3][6] = {{0, 1, 2, 3, 4, 5}, {1, 6, 0, 2, 3, 4}, {5, 3, 6, 1, 2, 0}};
    static const exr_compression_t comps[4] = {EXR_COMPRESSION_NONE, EXR_COMPRESSION_RLE,
                                               EXR_COMPRESSION_ZIP, EXR_COMPRESSION_PIZ};
    for (int k = 0; k < 4; k++) {
        exr_spec sp = {3, 2, {"R", "G", "B"}, EXR_PIXEL_HALF, 0, comps[k], -2, 0};
        img_picture p;
        read_ok(write_exr("half.exr", sp, half), IMG_TRANSFER_LINEAR, &p);
        assert_string_equal(p.format, "exr");
        assert_true(p.bits == 0 && !p.lo && p.width == 3 && p.height == 2);
        for (int c = 0; c < 3; c++)
            for (int i = 0; i < 6; i++)
                assert_near(V(p, i % 3, i / 3, c), val[from[c][i]], 0.0);
        img_picture_free(&p);
    }
    refused(path_of("half.exr"), IMG_TRANSFER_SRGB,
            "a float image is linear; --transfer applies to 8- and 16-bit files");
}

/* Float samples in 2 x 2 tiles of a 5 x 3 image (edge tiles cut) whose
 * data window starts at (3, 3); a Y channel of uints replicated, with an
 * alpha channel beside it ignored. */
static void test_exr_tiles_grey_uint(void **state)
{
    (void)state;
    float rgb[3][15];
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < 15; i++)
            rgb[c][i] = (float)(c * 100 + i) * 0.125f;
    exr_spec sp = {5, 3, {"R", "G", "B"}, EXR_PIXEL_FLOAT, 2, EXR_COMPRESSION_ZIPS, 3, 0};
    img_picture p;
    read_ok(write_exr("tiles.exr", sp, rgb), IMG_TRANSFER_LINEAR, &p);
    assert_true(p.width == 5 && p.height == 3);
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < 15; i++)
            assert_near(V(p, i % 5, i / 5, c), (c * 100 + i) * 0.125, 0.0);
    img_picture_free(&p);
    static const uint32_t y[2][4] = {{7, 0, 123456, 1}, {1, 2, 3, 4}};
    exr_spec grey = {2, 2, {"Y", "A"}, EXR_PIXEL_UINT, 0, EXR_COMPRESSION_NONE, 0, 0};
    read_ok(write_exr("grey.exr", grey, y), IMG_TRANSFER_LINEAR, &p);
    for (int i = 0; i < 12; i++)
        assert_near(p.value[i], y[0][i / 3], 0.0);
    img_picture_free(&p);
}

static void test_exr_refusals(void **state)
{
    (void)state;
    uint16_t half[3][4] = {{0x3800, 0x3800, 0x3800, 0x3800}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    exr_spec sp = {2, 2, {"R", "G", "B"}, EXR_PIXEL_HALF, 0, EXR_COMPRESSION_NONE, 0, 0};
    half[2][3] = 0xB800; /* -0.5, blue of (1, 1) */
    refused(write_exr("neg.exr", sp, half), IMG_TRANSFER_LINEAR, "negative value -0.5 at pixel (1, 1)");
    half[1][2] = 0x7E00; /* NaN, green of (0, 1) */
    refused(write_exr("nan.exr", sp, half), IMG_TRANSFER_LINEAR,
            "non-finite value at pixel (0, 1) channel G");
    half[0][1] = 0x7C00; /* +infinity, red of (1, 0) */
    refused(write_exr("inf.exr", sp, half), IMG_TRANSFER_LINEAR,
            "non-finite value at pixel (1, 0) channel R");
    sp.crop = 1;
    refused(write_exr("crop.exr", sp, half), IMG_TRANSFER_LINEAR,
            "EXR data window (0, 0)-(1, 1) is not the display window (0, 0)-(2, 1)");
    static const exr_spec others[3] = {
        {2, 2, {"A"}, EXR_PIXEL_HALF, 0, EXR_COMPRESSION_NONE, 0, 0},
        {2, 2, {"R", "G"}, EXR_PIXEL_HALF, 0, EXR_COMPRESSION_NONE, 0, 0},
        {2, 2, {"Y", "RY", "BY"}, EXR_PIXEL_HALF, 0, EXR_COMPRESSION_NONE, 0, 0}};
    static const char *const why[3] = {"EXR without R, G and B", "EXR without R, G and B",
                                       "a luminance-chroma EXR"};
    for (int i = 0; i < 3; i++)
        refused(write_exr("other.exr", others[i], half), IMG_TRANSFER_LINEAR, why[i]);
    refused(cut_copy("neg.exr", "cut.exr", 10), IMG_TRANSFER_LINEAR, "bad or truncated EXR");
}

/* Every refusal of the Netpbm readers and of the magic, with its reason. */
int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exr_half_scanlines),
        cmocka_unit_test(test_exr_tiles_grey_uint),
        cmocka_unit_test(test_exr_refusals),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_image_exr", tests, make_dir, remove_dir);
}
