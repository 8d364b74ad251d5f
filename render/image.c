/* render/image.c - pixel accumulation, statistics, gamma, PFM/PNG/PPM. */
#include "render/image.h"

#include <ctype.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "render/names.h"

rt_image *rt_image_create(int width, int height)
{
    if (width < 1 || height < 1)
        return NULL;
    rt_image *img = malloc(sizeof *img);
    rt_pixel *px = calloc((size_t)width * (size_t)height, sizeof *px);
    if (!img || !px) {
        free(img);
        free(px);
        return NULL;
    }
    img->width = width;
    img->height = height;
    img->px = px;
    return img;
}

void rt_image_destroy(rt_image *img)
{
    if (!img)
        return;
    free(img->px);
    free(img);
}

void rt_image_clear(rt_image *img)
{
    memset(img->px, 0, (size_t)img->width * (size_t)img->height * sizeof *img->px);
}

/* BEGIN SNIPPET pixel_add */
bool rt_pixel_add(rt_pixel *p, vec3 radiance)
{
    if (!vec3_is_finite(radiance)) {
        p->dropped++;
        return false;
    }
    /* Welford's update per channel: exact mean, stable variance. It is
     * mc_welford_add's update for three channels sharing one count, with
     * one division per sample (1 / n) instead of three; that rounds the
     * mean differently in the last bit, so the two are kept apart rather
     * than changing either's numbers. */
    double x[3] = {radiance.x, radiance.y, radiance.z};
    p->n++;
    double inv_n = 1.0 / (double)p->n;
    for (int c = 0; c < 3; c++) {
        double d = x[c] - p->mean[c];
        p->mean[c] += d * inv_n;
        p->m2[c] += d * (x[c] - p->mean[c]);
    }
    return true;
}
/* END SNIPPET pixel_add */

vec3 rt_image_get(const rt_image *img, int x, int y)
{
    const rt_pixel *p = &img->px[(size_t)y * (size_t)img->width + (size_t)x];
    return vec3_make(p->mean[0], p->mean[1], p->mean[2]);
}

void rt_image_region_stats(const rt_image *img, int x0, int y0, int x1, int y1, mc_estimate out[3])
{
    double sum[3] = {0.0, 0.0, 0.0}, var[3] = {0.0, 0.0, 0.0};
    uint64_t n = 0, count = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            const rt_pixel *p = &img->px[(size_t)y * (size_t)img->width + (size_t)x];
            n += p->n;
            count++;
            for (int c = 0; c < 3; c++) {
                sum[c] += p->mean[c];
                /* The variance of a pixel's mean is s^2 / n. */
                if (p->n >= 2)
                    var[c] += p->m2[c] / (double)(p->n - 1) / (double)p->n;
            }
        }
    for (int c = 0; c < 3; c++) {
        double k = count ? (double)count : 1.0;
        out[c].n = n;
        out[c].value = sum[c] / k;
        out[c].std_error = sqrt(var[c]) / k;
        out[c].variance = out[c].std_error * out[c].std_error * (double)n;
    }
}

uint64_t rt_image_dropped(const rt_image *img)
{
    uint64_t d = 0;
    for (size_t i = 0; i < (size_t)img->width * (size_t)img->height; i++)
        d += img->px[i].dropped;
    return d;
}

rt_format rt_format_from_path(const char *path)
{
    const char *dot = strrchr(path, '.');
    if (!dot || strchr(dot, '/') || strlen(dot + 1) != 3)
        return RT_FORMAT_UNKNOWN;
    char ext[4];
    for (int i = 0; i < 4; i++)
        ext[i] = (char)tolower((unsigned char)dot[i + 1]);
    if (strcmp(ext, "pfm") == 0)
        return RT_FORMAT_PFM;
    if (strcmp(ext, "png") == 0)
        return RT_FORMAT_PNG;
    if (strcmp(ext, "ppm") == 0)
        return RT_FORMAT_PPM;
    return RT_FORMAT_UNKNOWN;
}

const char *const rt_gamma_names[] = {"2", "2.2", "srgb", NULL};

bool rt_gamma_parse(const char *name, rt_gamma *out)
{
    int i = rt_name_index(rt_gamma_names, name);
    if (i < 0)
        return false;
    *out = (rt_gamma)i;
    return true;
}

double rt_gamma_encode(double linear, rt_gamma g)
{
    if (!(linear > 0.0))
        return 0.0;
    switch (g) {
    case RT_GAMMA_2:
        return sqrt(linear);
    case RT_GAMMA_2_2:
        return pow(linear, 1.0 / 2.2);
    case RT_GAMMA_SRGB:
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
    }
    return 0.0;
}

uint8_t rt_encode_byte(double encoded)
{
    double v = encoded > 0.0 ? (encoded < 1.0 ? encoded : 1.0) : 0.0;
    return (uint8_t)lround(255.0 * v);
}

/* One row of 8-bit display values. */
static void encode_row(const rt_image *img, int y, rt_gamma g, unsigned char *row)
{
    for (int x = 0; x < img->width; x++) {
        vec3 c = rt_image_get(img, x, y);
        row[3 * x] = rt_encode_byte(rt_gamma_encode(c.x, g));
        row[3 * x + 1] = rt_encode_byte(rt_gamma_encode(c.y, g));
        row[3 * x + 2] = rt_encode_byte(rt_gamma_encode(c.z, g));
    }
}

static int write_ppm(const rt_image *img, FILE *f, rt_gamma g)
{
    unsigned char *row = malloc(3 * (size_t)img->width);
    if (!row)
        return -1;
    int ok = fprintf(f, "P6\n%d %d\n255\n", img->width, img->height) > 0;
    for (int y = 0; y < img->height && ok; y++) {
        encode_row(img, y, g, row);
        ok = fwrite(row, 3, (size_t)img->width, f) == (size_t)img->width;
    }
    free(row);
    return ok ? 0 : -1;
}

static int write_pfm(const rt_image *img, FILE *f)
{
    /* The scale's sign gives the byte order: negative for little-endian. */
    const uint16_t probe = 1;
    bool little = *(const unsigned char *)&probe == 1;
    float *row = malloc(3 * sizeof(float) * (size_t)img->width);
    if (!row)
        return -1;
    int ok = fprintf(f, "PF\n%d %d\n%s\n", img->width, img->height, little ? "-1.0" : "1.0") > 0;
    for (int y = img->height - 1; y >= 0 && ok; y--) {
        for (int x = 0; x < img->width; x++) {
            vec3 c = rt_image_get(img, x, y);
            row[3 * x] = (float)c.x;
            row[3 * x + 1] = (float)c.y;
            row[3 * x + 2] = (float)c.z;
        }
        ok = fwrite(row, 3 * sizeof(float), (size_t)img->width, f) == (size_t)img->width;
    }
    free(row);
    return ok ? 0 : -1;
}

/* With NULL handlers libpng prints its messages to stderr before jumping;
 * library code never prints, so errors jump back silently (the caller sees
 * -1) and warnings, which change nothing in the file, are dropped. */
static void png_silent_error(png_structp png, png_const_charp msg)
{
    (void)msg;
    png_longjmp(png, 1);
}

static void png_silent_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* libpng reports errors by longjmp; nothing this function changes after
 * setjmp is read after the jump, so no local needs to be volatile. */
static int write_png(const rt_image *img, FILE *f, unsigned char *rows)
{
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_silent_error, png_silent_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < img->height; y++)
        png_write_row(png, rows + 3 * (size_t)img->width * (size_t)y);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int rt_image_write(const rt_image *img, FILE *f, rt_format format, rt_gamma g)
{
    int rc = -1;
    if (format == RT_FORMAT_PPM) {
        rc = write_ppm(img, f, g);
    } else if (format == RT_FORMAT_PFM) {
        rc = write_pfm(img, f);
    } else if (format == RT_FORMAT_PNG) {
        unsigned char *rows = malloc(3 * (size_t)img->width * (size_t)img->height);
        if (!rows)
            return -1;
        for (int y = 0; y < img->height; y++)
            encode_row(img, y, g, rows + 3 * (size_t)img->width * (size_t)y);
        rc = write_png(img, f, rows);
        free(rows);
    }
    return rc == 0 && fflush(f) == 0 && !ferror(f) ? 0 : -1;
}

int rt_image_save(const rt_image *img, const char *path, rt_gamma g)
{
    rt_format fmt = rt_format_from_path(path);
    if (fmt == RT_FORMAT_UNKNOWN)
        return -1;
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    int rc = rt_image_write(img, f, fmt, g);
    return fclose(f) == 0 ? rc : -1;
}

/* The next whitespace-separated token of a PNM-style header, at most
 * len - 1 characters; false at the end of the file. */
static bool header_token(FILE *f, char *tok, size_t len)
{
    int c;
    while ((c = fgetc(f)) != EOF && isspace(c))
        ;
    size_t n = 0;
    while (c != EOF && !isspace(c) && n + 1 < len) {
        tok[n++] = (char)c;
        c = fgetc(f);
    }
    tok[n] = '\0';
    /* The single whitespace character after the scale ends the header:
     * it has been consumed, and the data follow. */
    return n > 0 && (c == EOF || isspace(c));
}

static uint32_t swap32(uint32_t v)
{
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

rt_image *rt_image_read_pfm(FILE *f, const char **why)
{
    const char *dummy;
    why = why ? why : &dummy;
    char tok[4][32];
    for (int i = 0; i < 4; i++)
        if (!header_token(f, tok[i], sizeof tok[i])) {
            *why = "not a PFM file";
            return NULL;
        }
    if (strcmp(tok[0], "Pf") == 0) {
        *why = "a greyscale PFM (colour PF expected)";
        return NULL;
    }
    char *end1, *end2, *end3;
    long w = strtol(tok[1], &end1, 10), h = strtol(tok[2], &end2, 10);
    double scale = strtod(tok[3], &end3);
    if (strcmp(tok[0], "PF") != 0 || *end1 || *end2 || *end3 || !(scale != 0.0) || !isfinite(scale)) {
        *why = "not a PFM file";
        return NULL;
    }
    if (w < 1 || h < 1 || w > 65536 || h > 65536) {
        *why = "a size out of range";
        return NULL;
    }
    const uint16_t probe = 1;
    bool swap = (*(const unsigned char *)&probe == 1) != (scale < 0.0);
    rt_image *img = rt_image_create((int)w, (int)h);
    float *row = malloc(3 * sizeof(float) * (size_t)w);
    if (!img || !row) {
        free(row);
        rt_image_destroy(img);
        *why = "out of memory";
        return NULL;
    }
    /* Rows are stored bottom to top. */
    for (long y = h - 1; y >= 0; y--) {
        if (fread(row, 3 * sizeof(float), (size_t)w, f) != (size_t)w) {
            free(row);
            rt_image_destroy(img);
            *why = "truncated data";
            return NULL;
        }
        for (long x = 0; x < w; x++) {
            float c[3];
            for (int k = 0; k < 3; k++) {
                uint32_t bits;
                memcpy(&bits, &row[3 * x + k], sizeof bits);
                bits = swap ? swap32(bits) : bits;
                memcpy(&c[k], &bits, sizeof bits);
            }
            if (!rt_pixel_add(&img->px[y * w + x], vec3_make((double)c[0], (double)c[1], (double)c[2]))) {
                free(row);
                rt_image_destroy(img);
                *why = "non-finite values";
                return NULL;
            }
        }
    }
    free(row);
    return img;
}

double rt_image_mse(const rt_image *a, const rt_image *b)
{
    double sum = 0.0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            vec3 d = vec3_sub(rt_image_get(a, x, y), rt_image_get(b, x, y));
            sum += vec3_dot(d, d);
        }
    return sum / (3.0 * (double)a->width * (double)a->height);
}
