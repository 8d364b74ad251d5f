/* imageio/image_io.c - a renderer's image read back as linear values and
 * the intervals its codes stand for (imageio/image_io.h).
 *
 * The whole file is read into memory first, so every decoder knows where
 * the data ends: a header that promises more pixels than the file can
 * hold fails before anything large is allocated, and a pipe reads like a
 * file. Integer decoders store raw codes in the value array; decode_codes
 * then maps them through a table, one curve evaluation per code. */
#include "imageio/image_io.h"
#include "imageio/internal.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <png.h>


const char *const img_transfer_names[] = {"linear", "gamma2", "gamma2.2", "srgb", "book", NULL};

int img_transfer_parse(const char *name, img_transfer *out)
{
    for (int i = 0; name && img_transfer_names[i]; i++)
        if (strcmp(name, img_transfer_names[i]) == 0) {
            *out = (img_transfer)i;
            return 0;
        }
    return -1;
}

double img_transfer_decode(img_transfer t, double e)
{
    e = e > 0.0 ? (e < 1.0 ? e : 1.0) : 0.0; /* NaN fails e > 0 too */
    switch (t) {
    case IMG_TRANSFER_GAMMA2:
    case IMG_TRANSFER_BOOK: return e * e;
    case IMG_TRANSFER_GAMMA22: return pow(e, 2.2);
    /* The forward curve leaves its linear piece at x = 0.0031308, where
     * e = 12.92 x: the inverse switches at that same e. */
    case IMG_TRANSFER_SRGB:
        return e <= 12.92 * 0.0031308 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
    case IMG_TRANSFER_LINEAR: break;
    }
    return e;
}

int img_say(char *why, size_t len, const char *fmt, ...)
{
    if (why && len > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, len, fmt, ap);
        va_end(ap);
        for (char *c = why; *c; c++) /* libpng's and OpenEXR's messages too: one line */
            *c = (unsigned char)*c < 0x20 ? ' ' : *c;
    }
    return -1;
}
/* The bytes of the file at path (malloc'ed, *n of them), or NULL. */
static unsigned char *slurp(const char *path, size_t *n, char *why, size_t why_len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        img_say(why, why_len, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = (size_t)1 << 16, len = 0;
    unsigned char *b = malloc(cap), *more;
    while (b && (len += fread(b + len, 1, cap - len, f)) == cap) {
        more = cap <= SIZE_MAX / 2 ? realloc(b, cap *= 2) : NULL;
        if (!more)
            free(b);
        b = more;
    }
    bool bad = b && ferror(f);
    fclose(f);
    if (!b || bad) {
        free(b);
        img_say(why, why_len, bad ? "read error on %s" : "out of memory reading %s", path);
        return NULL;
    }
    *n = len;
    return b;
}

/* Checks the size and the transfer against what the file is; allocation
 * waits until the file is known to hold the pixels (alloc_picture). */
int img_start(reader *r, long w, long h, int bits)
{
    if (w < 1 || h < 1 || w > SIDE_MAX || h > SIDE_MAX)
        return FAIL(r, "image size %ld x %ld outside 1..%d", w, h, SIDE_MAX);
    if (bits == 0 && r->t != IMG_TRANSFER_LINEAR)
        return FAIL(r, "a float image is linear; --transfer applies to 8- and 16-bit files");
    if (bits == 16 && r->t == IMG_TRANSFER_BOOK)
        return FAIL(r, "transfer book is for 8-bit files (write_color writes bytes); "
                       "this file is 16-bit");
    r->pic->width = (int)w;
    r->pic->height = (int)h;
    r->pic->bits = bits;
    return 0;
}

int img_alloc(reader *r)
{
    img_picture *p = r->pic;
    size_t bytes = 3 * sizeof(double) * (size_t)p->width * (size_t)p->height;
    p->value = malloc(bytes);
    p->lo = p->bits ? malloc(bytes) : NULL;
    p->hi = p->bits ? malloc(bytes) : NULL;
    if (!p->value || (p->bits && (!p->lo || !p->hi)))
        return FAIL(r, "out of memory for a %d x %d image", p->width, p->height);
    return 0;
}

/* Stores channel c of pixel px (row-major); a grey file's one channel
 * goes to all three. */
void img_put(reader *r, size_t px, int c, double v)
{
    double *d = r->pic->value + 3 * px;
    if (r->grey)
        d[0] = d[1] = d[2] = v;
    else
        d[c] = v;
}

/* A float image is a radiance: finite and non-negative. The first
 * offender in reading order is named, so that the user can find it. */
static int check_floats(reader *r)
{
    const img_picture *p = r->pic;
    for (size_t i = 0; i < 3 * (size_t)p->width * (size_t)p->height; i++) {
        int x = (int)(i / 3 % (size_t)p->width), y = (int)(i / 3 / (size_t)p->width);
        if (!isfinite(p->value[i]))
            return FAIL(r, "non-finite value at pixel (%d, %d) channel %c", x, y,
                        r->grey ? 'Y' : "RGB"[i % 3]);
        if (p->value[i] < 0.0)
            return FAIL(r, "negative value %g at pixel (%d, %d)", p->value[i], x, y);
    }
    return 0;
}

/* Replaces the codes in r's values by what they stand for: the value and
 * the interval [lo, hi] of linear values the quantizer maps to the code. */
static int decode_codes(reader *r)
{
    img_picture *p = r->pic;
    const int max = p->bits == 16 ? 65535 : 255;
    const bool book = r->t == IMG_TRANSFER_BOOK;
    double *tab = malloc(3 * ((size_t)max + 1) * sizeof *tab);
    if (!tab)
        return FAIL(r, "out of memory");
    /* write_color truncates 256 e: code k holds e in [k/256, (k+1)/256),
     * stood for by the middle. The other curves round max e. */
    for (int k = 0; k <= max; k++) {
        double e[3] = {book ? (k + 0.5) / 256 : (double)k / max, book ? k / 256.0 : (k - 0.5) / max,
                       book ? (k + 1) / 256.0 : (k + 0.5) / max};
        for (int j = 0; j < 3; j++)
            tab[3 * k + j] = img_transfer_decode(r->t, e[j]);
    }
    /* All at or below 0 clamps to code 0, all above the top code's step
     * to the top code. */
    tab[1] = 0.0;
    tab[3 * max + 2] = (double)INFINITY;
    for (size_t i = 0; i < 3 * (size_t)p->width * (size_t)p->height; i++) {
        const double *row = tab + 3 * (size_t)p->value[i];
        p->value[i] = row[0];
        p->lo[i] = row[1];
        p->hi[i] = row[2];
    }
    free(tab);
    return 0;
}

/* --- PFM and PPM: Netpbm-style headers ----------------------------------- */

static bool is_blank(unsigned char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

/* The next token at *pos into tok (cap bytes, cut to fit), after blanks
 * and, in PPM, '#' comments to the end of the line. false at the end. */
static bool token(const reader *r, size_t *pos, char *tok, size_t cap)
{
    bool comments = r->pic->format[1] == 'p'; /* "ppm" */
    size_t i = *pos, k = 0;
    for (;;) {
        while (i < r->n && is_blank(r->b[i]))
            i++;
        if (!comments || i >= r->n || r->b[i] != '#')
            break;
        while (i < r->n && r->b[i] != '\n' && r->b[i] != '\r')
            i++;
    }
    for (; i < r->n && !is_blank(r->b[i]) && !(comments && r->b[i] == '#'); i++)
        if (k + 1 < cap)
            tok[k++] = (char)r->b[i];
    tok[k] = '\0';
    *pos = i;
    return k > 0;
}

/* The decimal integer tok, or -1 when it is not one or exceeds 10^9. */
static long number(const char *tok)
{
    long v = 0;
    for (const char *c = tok; *c; c++) {
        if (*c < '0' || *c > '9' || v > 100000000)
            return -1;
        v = 10 * v + (*c - '0');
    }
    return *tok ? v : -1;
}

/* Ascii P3: every sample a token up to maxval, nothing after the last. */
static int read_p3(reader *r, size_t pos, size_t w, long maxval)
{
    char tok[32];
    size_t count = 3 * w * (size_t)r->pic->height;
    /* A sample takes a digit and a blank: a shorter file is truncated
     * whatever its header says, and needs no allocation. */
    if (r->n - pos + 1 < 2 * count)
        return FAIL(r, "truncated data: %zu bytes cannot hold %zu samples", r->n - pos, count);
    if (img_alloc(r))
        return -1;
    for (size_t i = 0; i < count; i++) {
        long s = token(r, &pos, tok, sizeof tok) ? number(tok) : -2;
        if (s == -2)
            return FAIL(r, "truncated data: %zu of %zu samples", i, count);
        if (s < 0 || s > maxval)
            return FAIL(r, "bad sample '%s' at pixel (%zu, %zu): 0..%ld expected", tok, i / 3 % w,
                        i / 3 / w, maxval);
        r->pic->value[i] = (double)s;
    }
    if (token(r, &pos, tok, sizeof tok))
        return FAIL(r, "data after the last pixel: the header's size does not match the data");
    return 0;
}

/* PFM (float samples, either byte order, rows bottom to top) and PPM
 * (codes, big-endian, rows top to bottom): three header tokens after the
 * 2-byte magic, one blank, then exactly the samples the header promises. */
static int read_netpbm(reader *r)
{
    static const char *const names[2][3] = {{"width", "height", "maxval"},
                                            {"width", "height", "scale"}};
    bool pfm = r->pic->format[1] == 'f';
    char tok[3][32];
    long v[3];
    size_t pos = 2;
    for (int i = 0; i < 3; i++) {
        if (!token(r, &pos, tok[i], sizeof tok[i]))
            return FAIL(r, "truncated %s header: no %s", r->pic->format, names[pfm][i]);
        if ((v[i] = number(tok[i])) < 0 && !(pfm && i == 2))
            return FAIL(r, "bad %s header: %s '%s'", r->pic->format, names[pfm][i], tok[i]);
    }
    /* The scale's sign is the byte order (negative: little-endian); its
     * magnitude is unused, as by mcbox's writer and common readers. Read
     * without strtod, whose decimal point is the locale's. */
    if (pfm && (strspn(tok[2], "0123456789.eE+-") < strlen(tok[2]) ||
                !strpbrk(tok[2], "123456789")))
        return FAIL(r, "bad pfm header: scale '%s' (a non-zero number)", tok[2]);
    if (!pfm && v[2] != 255 && v[2] != 65535)
        return FAIL(r, "maxval %ld not supported (255 for 8-bit, 65535 for 16-bit)", v[2]);
    r->grey = r->b[1] == 'f';
    int bytes = pfm ? 4 : v[2] == 255 ? 1 : 2, nch = r->grey ? 1 : 3;
    if (img_start(r, v[0], v[1], pfm ? 0 : 8 * bytes))
        return -1;
    size_t w = (size_t)v[0], h = (size_t)v[1], count = w * h * (size_t)nch;
    size_t need = count * (size_t)bytes;
    if (r->b[1] == '3')
        return read_p3(r, pos, w, v[2]);
    if (pos >= r->n || !is_blank(r->b[pos]))
        return FAIL(r, "truncated data: no pixels after the %s header", r->pic->format);
    size_t have = r->n - ++pos;
    if (have < need)
        return FAIL(r, "truncated data: %zu bytes of pixels, %zu expected", have, need);
    if (have > need)
        return FAIL(r, "%zu bytes of pixels, %zu expected: the header's size is wrong", have, need);
    if (img_alloc(r))
        return -1;
    const unsigned char *q = r->b + pos;
    for (size_t i = 0; i < count; i++, q += bytes) {
        uint32_t u = 0;
        for (int j = 0; j < bytes; j++)
            u |= (uint32_t)q[j] << 8 * (pfm && tok[2][0] == '-' ? j : bytes - 1 - j);
        float f;
        memcpy(&f, &u, sizeof f);
        size_t x = i / (size_t)nch % w, y = i / (size_t)nch / w;
        img_put(r, (pfm ? h - 1 - y : y) * w + x, (int)(i % (size_t)nch), pfm ? (double)f : u);
    }
    return 0;
}

/* --- PNG (libpng) -------------------------------------------------------- */

typedef struct png_src {
    reader *r;
    size_t pos;
    bool ended; /* the file ended before the decoder did */
    char msg[160];
    unsigned char *pixels;
    png_bytep *rows;
} png_src;

static void png_on_error(png_structp png, png_const_charp msg)
{
    png_src *s = png_get_error_ptr(png);
    snprintf(s->msg, sizeof s->msg, "%s", msg);
    png_longjmp(png, 1);
}

/* A warning is no reason to refuse a file, and the library never prints. */
static void png_on_warning(png_structp png, png_const_charp msg)
{
    (void)png, (void)msg;
}

static void png_from_memory(png_structp png, png_bytep out, size_t len)
{
    png_src *s = png_get_io_ptr(png);
    if (len > s->r->n - s->pos) {
        s->ended = true;
        png_error(png, "the file ends early");
    }
    memcpy(out, s->r->b + s->pos, len);
    s->pos += len;
}

/* libpng reports errors by longjmp to the setjmp here; what this function
 * changes after it lives in *s, not in its own frame, so none is lost.
 * gAMA, sRGB and cHRM are not applied: the transfer is the user's. */
static int png_decode(png_structp png, png_infop info, png_src *s)
{
    reader *r = s->r;
    if (setjmp(png_jmpbuf(png)))
        return s->ended ? FAIL(r, "truncated data: the PNG ends before its image does")
                        : FAIL(r, "bad PNG: %s", s->msg);
    png_set_read_fn(png, s, png_from_memory);
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff); /* the range check is start()'s */
    png_read_info(png, info);
    uint64_t w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    int depth = png_get_bit_depth(png, info), color = png_get_color_type(png, info);
    if (img_start(r, (long)w, (long)h, depth == 16 ? 16 : 8))
        return -1;
    /* Deflate packs at most 258 bytes into two bits (1032:1): a file too
     * short to hold the filtered rows even so is truncated. */
    if (h * (1 + (w * png_get_channels(png, info) * (uint64_t)depth + 7) / 8) / 1032 > r->n)
        return FAIL(r, "truncated data: %zu bytes cannot hold a %d x %d PNG", r->n, (int)w, (int)h);
    if (color == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS))
        png_set_tRNS_to_alpha(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    size_t rowbytes = png_get_rowbytes(png, info);
    s->pixels = malloc(rowbytes * h);
    s->rows = malloc(sizeof *s->rows * h);
    if (!s->pixels || !s->rows || img_alloc(r))
        return FAIL(r, "out of memory for a %d x %d image", (int)w, (int)h);
    for (size_t y = 0; y < h; y++)
        s->rows[y] = s->pixels + y * rowbytes;
    png_read_image(png, s->rows);
    png_read_end(png, NULL);
    int nch = png_get_channels(png, info), bytes = depth == 16 ? 2 : 1, alpha = nch % 2 == 0;
    r->grey = nch <= 2;
    size_t stride = w * (size_t)nch; /* samples per row */
    for (size_t i = 0; i < h * stride; i++) {
        const unsigned char *q = s->pixels + i / stride * rowbytes + i % stride * (size_t)bytes;
        unsigned code = bytes == 2 ? (unsigned)(q[0] << 8 | q[1]) : q[0];
        size_t px = i / (size_t)nch;
        int c = (int)(i % (size_t)nch);
        if (c == nch - alpha && code < (bytes == 2 ? 65535u : 255u))
            return FAIL(r, "transparent pixel at (%d, %d)", (int)(px % w), (int)(px / w));
        if (c < nch - alpha)
            img_put(r, px, c, code);
    }
    return 0;
}

static int read_png(reader *r)
{
    png_src s = {.r = r};
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &s, png_on_error, png_on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int rc = info ? png_decode(png, info, &s) : FAIL(r, "out of memory");
    png_destroy_read_struct(&png, &info, NULL);
    free(s.rows);
    free(s.pixels);
    return rc;
}

/* --- the public functions --------------------------------------------------- */

/* The format is told by the first bytes, whatever the file's name. */
static int read_any(reader *r)
{
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char exr_sig[4] = {0x76, 0x2f, 0x31, 0x01};
    const unsigned char *b = r->b;
    char hex[16] = "";
    if (r->n >= 2 && b[0] == 'P' && b[1] && strchr("Ff36", b[1])) {
        r->pic->format = b[1] == 'F' || b[1] == 'f' ? "pfm" : "ppm";
        return read_netpbm(r) || (r->pic->bits ? decode_codes(r) : check_floats(r)) ? -1 : 0;
    }
    if (r->n >= 2 && b[0] == 'P' && b[1] && strchr("12457", b[1]))
        return FAIL(r, "a Netpbm P%c file: colour PPM (P6 or P3) expected", b[1]);
    if (r->n >= 8 && memcmp(b, png_sig, 8) == 0) {
        r->pic->format = "png";
        return read_png(r) || decode_codes(r) ? -1 : 0;
    }
    if (r->n >= 4 && memcmp(b, exr_sig, 4) == 0) {
        r->pic->format = "exr";
        return img_read_exr(r) || check_floats(r) ? -1 : 0;
    }
    for (size_t i = 0; i < 4 && i < r->n; i++)
        snprintf(hex + strlen(hex), sizeof hex - strlen(hex), "%s%02x", i ? " " : "", b[i]);
    if (r->n == 0)
        return FAIL(r, "not an image: the file is empty");
    return FAIL(r, "not an image: unknown magic bytes %s (PFM, PPM, PNG or OpenEXR expected)", hex);
}

int img_picture_read(const char *path, img_transfer t, img_picture *out, char *why,
                       size_t why_len)
{
    if (!out || !path)
        return img_say(why, why_len, "no file name or no picture to fill");
    memset(out, 0, sizeof *out);
    if ((unsigned)t > IMG_TRANSFER_BOOK)
        return img_say(why, why_len, "unknown transfer %d", (int)t);
    reader r = {.t = t, .pic = out, .why = why, .why_len = why_len};
    unsigned char *b = slurp(path, &r.n, why, why_len);
    if (!b)
        return -1;
    r.b = b;
    int rc = read_any(&r);
    free(b);
    if (rc)
        img_picture_free(out);
    return rc;
}

void img_picture_free(img_picture *p)
{
    if (!p)
        return;
    free(p->value);
    free(p->lo);
    free(p->hi);
    memset(p, 0, sizeof *p);
}

int img_picture_write_pfm(const char *path, int width, int height, const double *rgb, char *why,
                            size_t why_len)
{
    if (!path || !rgb || width < 1 || height < 1 || width > SIDE_MAX || height > SIDE_MAX)
        return img_say(why, why_len, "no PFM of %d x %d pixels: 1..%d each, with values", width, height,
                   SIDE_MAX);
    FILE *f = fopen(path, "wb");
    if (!f)
        return img_say(why, why_len, "cannot create %s: %s", path, strerror(errno));
    size_t w = (size_t)width;
    unsigned char *row = malloc(12 * w);
    bool ok = row && fprintf(f, "PF\n%d %d\n-1.0\n", width, height) > 0;
    for (size_t y = (size_t)height; ok && y-- > 0;) { /* the bottom row first */
        for (size_t i = 0; i < 3 * w; i++) {
            float v = (float)rgb[3 * w * y + i];
            uint32_t u;
            memcpy(&u, &v, sizeof u);
            for (int j = 0; j < 4; j++) /* little-endian, whatever the machine's order */
                row[4 * i + (size_t)j] = (unsigned char)(u >> 8 * j);
        }
        ok = fwrite(row, 12, w, f) == w;
    }
    ok = fclose(f) == 0 && ok;
    if (!ok) {
        remove(path);
        img_say(why, why_len, row ? "write error on %s" : "out of memory writing %s", path);
    }
    free(row);
    return ok ? 0 : -1;
}
