/* examples/common/exec_proto.c - commands and answers of the --exec
 * protocol, as text in memory. Lines are not NUL-terminated: every field
 * is copied to a small buffer before strtod or strtoull reads it. */
#include "examples/common/exec_proto.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A %.17g number takes at most 24 characters; a longer field is not one. */
#define FIELD_MAX 64
/* The most fields looked at on one line: a line with more is refused. */
#define MAX_FIELDS (MCBOX_MAX_UNIFORMS + 2)

static const char *const cmd_names[] = {"hello", "sample", "draw", "pdf", "invert"};

const char *app_proto_cmd_name(app_proto_cmd c)
{
    return (unsigned)c < 5u ? cmd_names[c] : "?";
}

/* --- fields ------------------------------------------------------------------ */

static bool is_sep(char c)
{
    return c == ' ' || c == '\t' || c == ',' || c == '\r';
}

typedef struct fields {
    int n;              /* fields on the line (counting stops past MAX_FIELDS) */
    const char *at[MAX_FIELDS + 1];
    size_t len[MAX_FIELDS + 1];
} fields;

/* Splits the line at runs of separators; a trailing CR is a separator. */
static void split(const char *line, size_t len, fields *f)
{
    f->n = 0;
    size_t i = 0;
    while (f->n <= MAX_FIELDS) {
        while (i < len && is_sep(line[i]))
            i++;
        if (i == len)
            return;
        size_t start = i;
        while (i < len && !is_sep(line[i]))
            i++;
        f->at[f->n] = line + start;
        f->len[f->n] = i - start;
        f->n++;
    }
}

/* The field as a C string in buf (FIELD_MAX bytes); false when too long. */
static bool field_text(const fields *f, int k, char *buf)
{
    if (f->len[k] >= FIELD_MAX)
        return false;
    memcpy(buf, f->at[k], f->len[k]);
    buf[f->len[k]] = '\0';
    return true;
}

/* Field k as a number (NaN and inf included); false when it is not one. */
static bool field_number(const fields *f, int k, double *x)
{
    char buf[FIELD_MAX], *end;
    if (!field_text(f, k, buf))
        return false;
    *x = strtod(buf, &end);
    return end != buf && *end == '\0';
}

/* Field k quoted for a message: printable ASCII only, at most 24 bytes. */
static const char *shown(const fields *f, int k, char *buf, size_t size)
{
    size_t n = 0, len = f->len[k] < 24 ? f->len[k] : 24;
    for (size_t i = 0; i < len && n + 4 < size; i++) {
        unsigned char c = (unsigned char)f->at[k][i];
        buf[n++] = c >= 0x20 && c < 0x7f ? (char)c : '?';
    }
    if (len < f->len[k] && n + 4 < size)
        buf[n++] = '.', buf[n++] = '.', buf[n++] = '.';
    buf[n] = '\0';
    return buf;
}

static bool is_word(const fields *f, int k, const char *w)
{
    return f->n > k && f->len[k] == strlen(w) && memcmp(f->at[k], w, f->len[k]) == 0;
}

/* "error MESSAGE" from the program: its message, quoted. */
static bool program_error(const char *line, size_t len, const fields *f, char *err, size_t errlen)
{
    if (!is_word(f, 0, "error"))
        return false;
    size_t skip = (size_t)(f->at[0] - line) + 5;
    while (skip < len && is_sep(line[skip]))
        skip++;
    size_t n = len - skip;
    while (n > 0 && line[skip + n - 1] == '\r')
        n--;
    snprintf(err, errlen, "the program reported an error: '%.*s'", (int)(n < 200 ? n : 200),
             line + skip);
    return true;
}

/* Whether the line holds the NUL byte: such text is not a protocol line. */
static bool has_nul(const char *line, size_t len)
{
    return memchr(line, '\0', len) != NULL;
}

/* --- mcbox-check's side ------------------------------------------------------- */

size_t app_proto_format_hello(char *buf, size_t size, const char *domain, int dims, int uniforms,
                              uint64_t seed)
{
    size_t dl = domain ? strlen(domain) : 0;
    if (dl == 0 || dl > 63 || dims < 1 || dims > 3 || uniforms < 0 || uniforms > MCBOX_MAX_UNIFORMS)
        return 0;
    for (size_t i = 0; i < dl; i++)
        if (!isgraph((unsigned char)domain[i]))
            return 0;
    int k = snprintf(buf, size, "hello %d %s %d %d %llu\n", APP_PROTO_VERSION, domain, dims,
                     uniforms, (unsigned long long)seed);
    return k > 0 && (size_t)k < size ? (size_t)k : 0;
}

size_t app_proto_format_command(char *buf, size_t size, app_proto_cmd c, size_t k)
{
    if (c == APP_PROTO_HELLO || (unsigned)c > APP_PROTO_INVERT || k < 1 || k > APP_PROTO_MAX_BATCH)
        return 0;
    int n = snprintf(buf, size, "%s %zu\n", cmd_names[c], k);
    return n > 0 && (size_t)n < size ? (size_t)n : 0;
}

size_t app_proto_format_numbers(char *buf, size_t size, const double *v, int n)
{
    size_t used = 0;
    for (int i = 0; i < n; i++) {
        int k = snprintf(buf + used, size - used, "%.17g%c", v[i], i + 1 < n ? ' ' : '\n');
        if (k < 0 || (size_t)k >= size - used)
            return 0;
        used += (size_t)k;
    }
    return used;
}

bool app_proto_parse_ok(const char *line, size_t len, char *err, size_t errlen)
{
    fields f;
    split(line, len, &f);
    if (program_error(line, len, &f, err, errlen))
        return false;
    if (f.n == 1 && is_word(&f, 0, "ok") && !has_nul(line, len))
        return true;
    char q[40];
    if (f.n == 0)
        snprintf(err, errlen, "an empty line, not 'ok'");
    else
        snprintf(err, errlen, "'%s%s', not 'ok'", shown(&f, 0, q, sizeof q), f.n > 1 ? " ..." : "");
    return false;
}

/* Fields [first, first + count) as numbers into out; false with the
 * reason. */
static bool numbers_of(const fields *f, int first, int count, double *out, char *err, size_t errlen)
{
    char q[40];
    for (int k = 0; k < count; k++)
        if (!field_number(f, first + k, &out[k])) {
            snprintf(err, errlen, "value %d: '%s' is not a number", first + k + 1,
                     shown(f, first + k, q, sizeof q));
            return false;
        }
    return true;
}

bool app_proto_parse_sample(const char *line, size_t len, int dims, mcbox_sample *out, char *err,
                            size_t errlen)
{
    fields f;
    split(line, len, &f);
    out->pdf = out->weight = (double)NAN;
    out->atom = -1;
    if (program_error(line, len, &f, err, errlen))
        return false;
    if (has_nul(line, len)) {
        snprintf(err, errlen, "a NUL byte in the line (binary output, not numbers)");
        return false;
    }
    if (is_word(&f, 0, "atom")) {
        char buf[FIELD_MAX] = "", *end = buf, q[40];
        if (f.n != 2) {
            snprintf(err, errlen, "'atom' takes one index, the line has %d value%s after it",
                     f.n - 1, f.n == 2 ? "" : "s");
            return false;
        }
        errno = 0;
        unsigned long long j = field_text(&f, 1, buf) && isdigit((unsigned char)buf[0])
                                   ? strtoull(buf, &end, 10)
                                   : 0;
        if (!isdigit((unsigned char)buf[0]) || *end || errno || j > 2147483647ull) {
            snprintf(err, errlen, "atom '%s' is not an index from 0 to 2^31 - 1",
                     shown(&f, 1, q, sizeof q));
            return false;
        }
        out->atom = (int)j;
        return true;
    }
    if (f.n < dims || f.n > dims + 2) {
        snprintf(err, errlen, "%s%d value%s, expected %d coordinates (then a pdf and a weight "
                              "at most) or 'atom J'",
                 f.n > MAX_FIELDS ? "more than " : "", f.n > MAX_FIELDS ? MAX_FIELDS : f.n,
                 f.n == 1 ? "" : "s", dims);
        return false;
    }
    double v[5];
    if (!numbers_of(&f, 0, f.n, v, err, errlen))
        return false;
    for (int j = 0; j < dims; j++)
        out->x[j] = v[j];
    if (f.n > dims)
        out->pdf = v[dims];
    if (f.n > dims + 1)
        out->weight = v[dims + 1];
    return true;
}

bool app_proto_parse_numbers(const char *line, size_t len, int count, double *out, char *err,
                             size_t errlen)
{
    fields f;
    split(line, len, &f);
    if (program_error(line, len, &f, err, errlen))
        return false;
    if (has_nul(line, len)) {
        snprintf(err, errlen, "a NUL byte in the line (binary output, not numbers)");
        return false;
    }
    if (count < 1 || count > MAX_FIELDS || f.n != count) {
        snprintf(err, errlen, "%s%d value%s, expected %d", f.n > MAX_FIELDS ? "more than " : "",
                 f.n > MAX_FIELDS ? MAX_FIELDS : f.n, f.n == 1 ? "" : "s", count);
        return false;
    }
    return numbers_of(&f, 0, count, out, err, errlen);
}

/* --- the program's side ------------------------------------------------------- */

/* Field k as a whole number of digits within [lo, hi]. */
static bool field_uint(const fields *f, int k, uint64_t lo, uint64_t hi, uint64_t *out)
{
    char buf[FIELD_MAX], *end;
    if (!field_text(f, k, buf) || !isdigit((unsigned char)buf[0]))
        return false;
    errno = 0;
    unsigned long long v = strtoull(buf, &end, 10);
    if (*end || errno || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

bool app_proto_parse_command(const char *line, size_t len, app_proto_request *r, char *err,
                             size_t errlen)
{
    fields f;
    split(line, len, &f);
    memset(r, 0, sizeof *r);
    char q[40];
    if (f.n == 0 || has_nul(line, len)) {
        snprintf(err, errlen, f.n ? "a NUL byte in a command" : "an empty line, not a command");
        return false;
    }
    if (is_word(&f, 0, "hello")) {
        uint64_t v[4];
        r->cmd = APP_PROTO_HELLO;
        if (f.n != 6 || !field_uint(&f, 1, 0, 1000000, &v[0]) || f.len[2] >= sizeof r->domain ||
            !field_uint(&f, 3, 1, 3, &v[1]) || !field_uint(&f, 4, 0, MCBOX_MAX_UNIFORMS, &v[2]) ||
            !field_uint(&f, 5, 0, UINT64_MAX, &v[3])) {
            snprintf(err, errlen, "malformed hello (expected 'hello VERSION DOMAIN DIMS UNIFORMS SEED')");
            return false;
        }
        r->version = (int)v[0];
        memcpy(r->domain, f.at[2], f.len[2]);
        r->domain[f.len[2]] = '\0';
        r->dims = (int)v[1], r->uniforms = (int)v[2], r->seed = v[3];
        return true;
    }
    for (int c = APP_PROTO_SAMPLE; c <= APP_PROTO_INVERT; c++)
        if (is_word(&f, 0, cmd_names[c])) {
            uint64_t k;
            if (f.n != 2 || !field_uint(&f, 1, 1, APP_PROTO_MAX_BATCH, &k)) {
                snprintf(err, errlen, "malformed '%s' (expected '%s K', K from 1 to %d)", cmd_names[c],
                         cmd_names[c], APP_PROTO_MAX_BATCH);
                return false;
            }
            r->cmd = (app_proto_cmd)c;
            r->k = (size_t)k;
            return true;
        }
    snprintf(err, errlen, "unknown command '%s'", shown(&f, 0, q, sizeof q));
    return false;
}
