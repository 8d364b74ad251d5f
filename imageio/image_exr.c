/* imageio/image_exr.c - the OpenEXR reader of imageio/image_io.h, through the
 * C API of the library made for the format (OpenEXRCore): the file's first
 * part, scanline or tiled, channels R, G, B or Y of any pixel type, read
 * from memory as floats. */
#include "imageio/internal.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <OpenEXR/openexr.h>

typedef struct exr_src {
    reader *r;
    char msg[160]; /* the library's first complaint: the cause, not its echoes */
    exr_context_t ctx;
    exr_decode_pipeline_t dec;
    bool tiled;
    int y_min;      /* the data window's first row */
    float *scratch; /* a plane of floats per channel read */
    size_t plane;
} exr_src;

/* Keeps the message for why, where the default handler prints it. */
static void exr_on_error(exr_const_context_t ctx, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    exr_src *s = exr_get_user_data(ctx, &ud) == EXR_ERR_SUCCESS ? ud : NULL;
    if (s && !s->msg[0])
        snprintf(s->msg, sizeof s->msg, "%s", msg ? msg : exr_get_default_error_message(code));
}

static int64_t exr_from_memory(exr_const_context_t ctx, void *ud, void *out, uint64_t size,
                               uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    const reader *r = ((exr_src *)ud)->r;
    uint64_t k = offset < r->n ? r->n - offset : 0;
    (void)ctx, (void)error_cb;
    k = size < k ? size : k; /* a short read: the library names the truncation */
    memcpy(out, r->b + (k ? offset : 0), k);
    return (int64_t)k;
}

static int64_t exr_size(exr_const_context_t ctx, void *ud)
{
    (void)ctx;
    return (int64_t)((exr_src *)ud)->r->n;
}

static int exr_fail(exr_src *s, exr_result_t rc)
{
    const char *msg = s->msg[0] ? s->msg : exr_get_default_error_message(rc);
    return FAIL(s->r, "bad or truncated EXR: %s", msg);
}

/* The picture channel a file channel goes to: R, G, B, or Y for grey. */
static int exr_channel(const reader *r, const char *name)
{
    const char *set = r->grey ? "Y" : "RGB";
    const char *at = name[0] && !name[1] ? strchr(set, name[0]) : NULL;
    return at ? (int)(at - set) : -1;
}

/* One part of flat image data, uncropped, with R, G and B or else Y
 * channels, none subsampled; then the picture's size. */
static int exr_layout(exr_src *s)
{
    reader *r = s->r;
    int parts = 0, found = 0;
    exr_storage_t st = EXR_STORAGE_LAST_TYPE;
    exr_attr_box2i_t dw, dp;
    const exr_attr_chlist_t *cl = NULL;
    if (exr_get_count(s->ctx, &parts) || parts != 1)
        return FAIL(r, "an EXR of %d parts: one part expected", parts);
    if (exr_get_storage(s->ctx, 0, &st) || (st != EXR_STORAGE_SCANLINE && st != EXR_STORAGE_TILED))
        return FAIL(r, "a deep EXR: flat scanline or tiled image data expected");
    if (exr_get_data_window(s->ctx, 0, &dw) || exr_get_display_window(s->ctx, 0, &dp) ||
        exr_get_channels(s->ctx, 0, &cl))
        return exr_fail(s, EXR_ERR_MISSING_REQ_ATTR);
    if (memcmp(&dw, &dp, sizeof dw) != 0) /* four int32_t, no padding */
        return FAIL(r, "EXR data window (%d, %d)-(%d, %d) is not the display window "
                       "(%d, %d)-(%d, %d)",
                    dw.min.x, dw.min.y, dw.max.x, dw.max.y, dp.min.x, dp.min.y, dp.max.x, dp.max.y);
    for (int i = 0; i < cl->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &cl->entries[i];
        const char *at = e->name.length == 1 ? strchr("RGBY", e->name.str[0]) : NULL;
        if (at && (e->x_sampling != 1 || e->y_sampling != 1))
            return FAIL(r, "EXR channel %s is subsampled", e->name.str);
        found |= at ? 1 << (at - "RGBY") : 0;
        found |= strcmp(e->name.str, "RY") == 0 || strcmp(e->name.str, "BY") == 0 ? 16 : 0;
    }
    r->grey = (found & 7) != 7;
    if (r->grey && !(found & 8))
        return FAIL(r, "EXR without R, G and B channels or a Y channel");
    /* Y beside RY and BY is the luminance of a colour image, not grey. */
    if (r->grey && (found & 16))
        return FAIL(r, "a luminance-chroma EXR (Y, RY, BY): R, G and B, or Y alone, expected");
    s->tiled = st == EXR_STORAGE_TILED;
    s->y_min = dw.min.y;
    return img_start(r, (long)dw.max.x - dw.min.x + 1, (long)dw.max.y - dw.min.y + 1, 0);
}

/* Decodes the chunk ci, whose first pixel is (x0, y0), as floats into
 * scratch and from there into the picture. */
static int exr_chunk(exr_src *s, const exr_chunk_info_t *ci, uint32_t x0, uint32_t y0)
{
    reader *r = s->r;
    uint32_t w = (uint32_t)r->pic->width, h = (uint32_t)r->pic->height;
    exr_result_t rc = s->dec.channels ? exr_decoding_update(s->ctx, 0, ci, &s->dec)
                                      : exr_decoding_initialize(s->ctx, 0, ci, &s->dec);
    for (int i = 0; !rc && i < s->dec.channel_count; i++) {
        exr_coding_channel_info_t *c = &s->dec.channels[i];
        int k = exr_channel(r, c->channel_name);
        c->decode_to_ptr = k < 0 ? NULL : (uint8_t *)(s->scratch + (size_t)k * s->plane);
        c->user_data_type = EXR_PIXEL_FLOAT;
        c->user_bytes_per_element = c->user_pixel_stride = sizeof(float);
        c->user_line_stride = (int32_t)sizeof(float) * c->width;
        /* The decoder writes into scratch: a chunk that would overrun the
         * image or a plane is refused before it runs. */
        if (k >= 0 && (x0 + (uint32_t)c->width > w || y0 + (uint32_t)c->height > h ||
                       (size_t)c->width * (size_t)c->height > s->plane))
            return FAIL(r, "bad EXR: a %d x %d chunk at (%u, %u)", c->width, c->height, x0, y0);
    }
    if (!rc)
        rc = exr_decoding_choose_default_routines(s->ctx, 0, &s->dec);
    if (!rc)
        rc = exr_decoding_run(s->ctx, 0, &s->dec);
    if (rc)
        return exr_fail(s, rc);
    for (int i = 0; i < s->dec.channel_count; i++) {
        const exr_coding_channel_info_t *c = &s->dec.channels[i];
        size_t cw = (size_t)c->width;
        int k = exr_channel(r, c->channel_name);
        for (size_t j = 0; k >= 0 && j < cw * (size_t)c->height; j++)
            img_put(r, (y0 + j / cw) * w + x0 + j % cw, k,
                (double)s->scratch[(size_t)k * s->plane + j]);
    }
    return 0;
}

/* Every chunk in turn: blocks of scanlines, or the tiles of level 0 (the
 * full resolution of a mipmapped file). */
static int exr_pixels(exr_src *s)
{
    reader *r = s->r;
    if (exr_layout(s))
        return -1;
    uint32_t w = (uint32_t)r->pic->width, h = (uint32_t)r->pic->height, cw = w, ch = 0;
    exr_result_t rc = s->tiled ? exr_get_tile_descriptor(s->ctx, 0, &cw, &ch, NULL, NULL)
                               : exr_get_scanlines_per_chunk(s->ctx, 0, (int32_t *)&ch);
    if (rc || cw < 1 || ch < 1)
        return exr_fail(s, rc ? rc : EXR_ERR_INVALID_ATTR);
    s->plane = (size_t)(cw < w ? cw : w) * (ch < h ? ch : h); /* chunks are cut to the image */
    if (!(s->scratch = malloc(3 * s->plane * sizeof(float))) || img_alloc(r))
        return FAIL(r, "out of memory for a %u x %u image", w, h);
    for (uint32_t y0 = 0; y0 < h; y0 += ch)
        for (uint32_t x0 = 0; x0 < w; x0 += cw) {
            exr_chunk_info_t ci;
            int tx = (int)(x0 / cw), ty = (int)(y0 / ch);
            rc = s->tiled ? exr_read_tile_chunk_info(s->ctx, 0, tx, ty, 0, 0, &ci)
                          : exr_read_scanline_chunk_info(s->ctx, 0, s->y_min + (int)y0, &ci);
            if (rc ? exr_fail(s, rc) : exr_chunk(s, &ci, x0, y0))
                return -1;
        }
    return 0;
}

int img_read_exr(reader *r)
{
    exr_src s = {.r = r};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = exr_on_error;
    init.user_data = &s;
    init.read_fn = exr_from_memory;
    init.size_fn = exr_size;
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    exr_result_t rc = exr_start_read(&s.ctx, "image", &init);
    int ok = rc ? exr_fail(&s, rc) : exr_pixels(&s);
    if (s.dec.channels)
        exr_decoding_destroy(s.ctx, &s.dec);
    exr_finish(&s.ctx);
    free(s.scratch);
    return ok;
}

