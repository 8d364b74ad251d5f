/* examples/common/sample_reader.c - text and raw sample files from a buffer.
 *
 * Every access is bounded by the buffer's end: the text is not
 * NUL-terminated, so a field is copied to a small NUL-terminated buffer
 * before strtod reads it.
 */
#include "examples/common/sample_reader.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Longer fields are not numbers anyone writes: 17 significant digits, a
 * sign, a point and an exponent fit in 32 characters. */
#define FIELD_MAX 128

bool app_samples_format_parse(const char *name, app_samples_format *f)
{
    static const char *const names[] = {"csv", "f32", "f64"};
    for (int i = 0; i < 3; i++)
        if (strcmp(name, names[i]) == 0) {
            *f = (app_samples_format)i;
            return true;
        }
    return false;
}

/* Growable array of doubles; false when out of memory. */
typedef struct grow {
    double *v;
    size_t n, cap;
} grow;

static bool push(grow *g, const double *x, int dims)
{
    if (g->n + (size_t)dims > g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 1024;
        double *v = realloc(g->v, cap * sizeof *v);
        if (!v)
            return false;
        g->v = v, g->cap = cap;
    }
    memcpy(g->v + g->n, x, (size_t)dims * sizeof *x);
    g->n += (size_t)dims;
    return true;
}

static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* A field quoted for a message: at most 24 characters, anything that is
 * not printable ASCII shown as '?'. */
static void quote(const char *t, size_t len, char *out, size_t size)
{
    size_t k = 0, show = len < 24 ? len : 24;
    for (size_t i = 0; i < show && k + 4 < size; i++)
        out[k++] = t[i] >= 0x20 && t[i] < 0x7f ? t[i] : '?';
    if (show < len && k + 4 < size)
        out[k++] = '.', out[k++] = '.', out[k++] = '.';
    out[k] = '\0';
}

typedef enum field_kind { F_NUMBER, F_NONFINITE, F_TEXT } field_kind;

/* Reads the field t[0 .. len) as a number. An underflow to a subnormal or
 * zero is still the number written; an overflow is infinite. */
static field_kind number(const char *t, size_t len, double *x)
{
    char tmp[FIELD_MAX];
    if (len >= sizeof tmp)
        return F_TEXT;
    memcpy(tmp, t, len);
    tmp[len] = '\0';
    char *end;
    *x = strtod(tmp, &end);
    if (end == tmp || *end)
        return F_TEXT;
    return isfinite(*x) ? F_NUMBER : F_NONFINITE;
}

/* The length of the line at p (rem bytes left) without its line end, and
 * in *next where the following line starts; SIZE_MAX for a line longer
 * than APP_SAMPLES_MAX_LINE, found without scanning past that length. */
static size_t line_at(const char *p, size_t rem, size_t *next)
{
    size_t limit = rem < (size_t)APP_SAMPLES_MAX_LINE + 2 ? rem : (size_t)APP_SAMPLES_MAX_LINE + 2;
    const char *nl = memchr(p, '\n', limit);
    size_t len;
    if (nl) {
        len = (size_t)(nl - p);
        *next = len + 1;
    } else {
        if (rem > limit)
            return SIZE_MAX;
        len = rem;
        *next = rem;
    }
    if (len > 0 && p[len - 1] == '\r')
        len--;
    return len > APP_SAMPLES_MAX_LINE ? SIZE_MAX : len;
}

/* Splits one line into fields and reads the first `dims` into x. Returns
 * 0 for a sample, 1 for a line to skip (blank, comment, or the header
 * when may_be_header), -1 with a message in err. */
static int text_line(const char *p, size_t len, int dims, bool may_be_header, double *x, char *err,
                     size_t errlen)
{
    const char *q = p, *end = p + len;
    while (q < end && is_blank(*q))
        q++;
    if (q == end || *q == '#')
        return 1;
    int fields = 0, numeric = 0;
    char shown[40];
    /* The first field that is wrong, reported when the line is not a
     * header: its position, text and kind. */
    int bad_at = 0;
    field_kind bad_kind = F_NUMBER;
    const char *bad_t = NULL;
    size_t bad_len = 0;
    for (;;) {
        const char *t = q;
        while (q < end && !is_blank(*q) && *q != ',')
            q++;
        if (q == t) {
            snprintf(err, errlen, "field %d is empty (two separators in a row, or one at the start)",
                     fields + 1);
            return -1;
        }
        double v;
        field_kind k = number(t, (size_t)(q - t), &v);
        fields++;
        numeric += k != F_TEXT;
        if (fields <= dims)
            x[fields - 1] = v;
        if (k != F_NUMBER && !bad_at)
            bad_at = fields, bad_kind = k, bad_t = t, bad_len = (size_t)(q - t);
        /* A header has to be read to its end; a data line is wrong as soon
         * as it has one field too many. */
        if (fields > dims && !may_be_header)
            break;
        while (q < end && is_blank(*q))
            q++;
        if (q == end)
            break;
        if (*q == ',') {
            q++;
            while (q < end && is_blank(*q))
                q++;
            if (q == end) {
                snprintf(err, errlen, "field %d is empty (a comma at the end of the line)", fields + 1);
                return -1;
            }
        }
    }
    if (may_be_header && numeric == 0)
        return 1;
    if (bad_at && bad_at <= dims) {
        quote(bad_t, bad_len, shown, sizeof shown);
        if (bad_kind == F_TEXT)
            snprintf(err, errlen, "field %d: '%s' is not a number", bad_at, shown);
        else
            snprintf(err, errlen, "field %d: '%s' is not finite (NaN and inf are not coordinates)",
                     bad_at, shown);
        return -1;
    }
    if (fields != dims) {
        snprintf(err, errlen, "%s%d field%s, expected %d (one point per line%s)",
                 fields > dims ? "more than " : "", fields > dims ? dims : fields,
                 (fields > dims ? dims : fields) != 1 ? "s" : "", dims,
                 fields > dims ? "; pdf and weight columns are not read from files" : "");
        return -1;
    }
    return 0;
}

/* Raw records read as text give fields of garbage and a message about the
 * first one; a control byte (NUL above all: a float of 0 or 1 has two or
 * more) in the first 4 KiB says "binary" at once, and what to pass. Text
 * has none but blanks and line ends. */
static bool looks_binary(const char *buf, size_t len, char *err, size_t errlen)
{
    size_t head = len < 4096 ? len : 4096;
    for (size_t i = 0; i < head; i++) {
        unsigned char b = (unsigned char)buf[i];
        if ((b < 0x20 && !is_blank((char)b) && b != '\n') || b == 0x7f) {
            snprintf(err, errlen, "looks binary (byte %zu is 0x%02X, not text): pass --format f32 "
                                  "or f64 for raw records", i, b);
            return true;
        }
    }
    return false;
}

static bool parse_text(const char *buf, size_t len, int dims, grow *g, char *err, size_t errlen)
{
    size_t at = 0;
    if (len >= 2 && (((unsigned char)buf[0] == 0xff && (unsigned char)buf[1] == 0xfe) ||
                     ((unsigned char)buf[0] == 0xfe && (unsigned char)buf[1] == 0xff))) {
        snprintf(err, errlen, "line 1: UTF-16 text (byte-order mark %02X %02X): write the samples "
                              "as UTF-8 or ASCII", (unsigned char)buf[0], (unsigned char)buf[1]);
        return false;
    }
    if (looks_binary(buf, len, err, errlen))
        return false;
    if (len >= 3 && (unsigned char)buf[0] == 0xef && (unsigned char)buf[1] == 0xbb &&
        (unsigned char)buf[2] == 0xbf)
        at = 3;
    bool first = true;
    char why[200];
    for (uint64_t line = 1; at < len; line++) {
        size_t next, n = line_at(buf + at, len - at, &next);
        if (n == SIZE_MAX) {
            snprintf(err, errlen, "line %llu: longer than 1 MiB (%u bytes)", (unsigned long long)line,
                     APP_SAMPLES_MAX_LINE);
            return false;
        }
        double x[3];
        int rc = text_line(buf + at, n, dims, first, x, why, sizeof why);
        if (rc < 0) {
            snprintf(err, errlen, "line %llu: %s", (unsigned long long)line, why);
            return false;
        }
        /* The header may only be the first line that is not blank or a
         * comment. */
        const char *q = buf + at;
        while (q < buf + at + n && is_blank(*q))
            q++;
        if (q < buf + at + n && *q != '#')
            first = false;
        if (rc == 0 && !push(g, x, dims)) {
            snprintf(err, errlen, "out of memory after %zu samples", g->n / (size_t)dims);
            return false;
        }
        at += next;
    }
    if (g->n == 0) {
        snprintf(err, errlen, "no samples (%s)",
                 len == 0 ? "the file is empty" : "only blank lines, comments or a header");
        return false;
    }
    return true;
}

/* Little-endian IEEE-754 values, whatever the host's byte order. */
static double f64_at(const unsigned char *b)
{
    uint64_t bits = 0;
    for (int i = 7; i >= 0; i--)
        bits = bits << 8 | b[i];
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static double f32_at(const unsigned char *b)
{
    uint32_t bits = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
    float v;
    memcpy(&v, &bits, sizeof v);
    return (double)v;
}

static bool parse_raw(const unsigned char *buf, size_t len, int dims, size_t width, grow *g,
                      char *err, size_t errlen)
{
    size_t rec = (size_t)dims * width, n = len / rec;
    const char *type = width == 4 ? "float32" : "float64";
    if (len == 0) {
        snprintf(err, errlen, "no samples (the file is empty)");
        return false;
    }
    if (len % rec) {
        snprintf(err, errlen, "sample %zu (byte %zu): truncated record: %zu of its %zu bytes (%d %s "
                              "values) before the end of the file", n + 1, n * rec, len % rec, rec,
                 dims, type);
        return false;
    }
    g->v = malloc(n * (size_t)dims * sizeof *g->v);
    if (!g->v) {
        snprintf(err, errlen, "out of memory for %zu samples", n);
        return false;
    }
    g->n = g->cap = n * (size_t)dims;
    for (size_t i = 0; i < n * (size_t)dims; i++) {
        const unsigned char *b = buf + i * width;
        double v = width == 4 ? f32_at(b) : f64_at(b);
        if (!isfinite(v)) {
            snprintf(err, errlen, "sample %zu (byte %zu): coordinate %zu is %s", i / (size_t)dims + 1,
                     i * width, i % (size_t)dims + 1, isnan(v) ? "NaN" : "infinite");
            return false;
        }
        g->v[i] = v;
    }
    return true;
}

bool app_samples_parse(const char *buf, size_t len, app_samples_format fmt, int dims,
                       double **points, uint64_t *n, char *err, size_t errlen)
{
    *points = NULL;
    *n = 0;
    if (dims < 1 || dims > 3) {
        snprintf(err, errlen, "points of %d coordinates (1, 2 or 3 are read)", dims);
        return false;
    }
    grow g = {NULL, 0, 0};
    bool ok = fmt == APP_SAMPLES_TEXT
                  ? parse_text(buf, len, dims, &g, err, errlen)
                  : parse_raw((const unsigned char *)buf, len, dims, fmt == APP_SAMPLES_F32 ? 4 : 8,
                              &g, err, errlen);
    if (!ok) {
        free(g.v);
        return false;
    }
    *points = g.v;
    *n = g.n / (size_t)dims;
    return true;
}
