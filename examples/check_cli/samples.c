/* examples/check_cli/samples.c - the --samples door: points from a file
 * (examples/common/sample_reader.h) against a catalog row's density or a
 * program's (--pdf-exec, the protocol's pdf command only). */
#define _POSIX_C_SOURCE 200809L /* open's O_CLOEXEC */

#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The whole of a file, or of stdin for "-"; exits 2 when unreadable. */
static char *slurp(const char *path, size_t *len)
{
    int fd = strcmp(path, "-") == 0 ? 0 : open(path, O_RDONLY | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0)
        cli_fail("--samples: cannot open '%s': %s", path, strerror(errno));
    if (S_ISDIR(st.st_mode))
        cli_fail("--samples: '%s' is a directory", path);
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (;;) {
        if (buf && n == cap) {
            char *b = realloc(buf, cap * 2);
            if (!b)
                free(buf);
            buf = b, cap *= 2;
        }
        if (!buf)
            cli_fail("--samples: '%s': out of memory after %zu bytes", path, n);
        ssize_t k = read(fd, buf + n, cap - n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0)
            cli_fail("--samples: cannot read '%s': %s", path, strerror(errno));
        if (k == 0)
            break;
        n += (size_t)k;
    }
    if (fd > 0)
        close(fd);
    *len = n;
    return buf;
}

void cli_load_samples(cli_app *c)
{
    const char *path = c->a.samples, *shown = strcmp(path, "-") == 0 ? "stdin" : path;
    size_t len;
    char *buf = slurp(path, &len), err[300];
    double *pts;
    uint64_t n;
    if (!app_samples_parse(buf, len, c->a.format, c->dims, &pts, &n, err, sizeof err))
        cli_fail("%s: %s", shown, err);
    free(buf);
    if (c->a.have_n && c->a.n > n)
        cli_fail("%s has %llu samples, fewer than --n %llu", shown, (unsigned long long)n,
                 (unsigned long long)c->a.n);
    if (c->a.have_n)
        n = c->a.n;
    mcbox_sample *smp = malloc((size_t)n * sizeof *smp);
    if (!smp)
        cli_fail("out of memory for %llu samples", (unsigned long long)n);
    for (uint64_t i = 0; i < n; i++) {
        mcbox_sample *q = &smp[i];
        q->x[0] = q->x[1] = q->x[2] = 0.0;
        memcpy(q->x, pts + i * (uint64_t)c->dims, (size_t)c->dims * sizeof *pts);
        q->pdf = q->weight = (double)NAN;
        q->atom = -1;
    }
    free(pts);
    c->points = smp, c->n_points = n;
}

int cli_run_samples(cli_app *c, mcbox_check_result *r, mcbox_check_table *t)
{
    if (c->a.pdf_exec) {
        cli_child_start(c, c->a.pdf_exec);
        cli_hello(c, 0);
    }
    int rc = mcbox_check_points(&c->s, c->points, c->n_points, &c->a.o, r, t);
    if (c->a.pdf_exec)
        cli_child_end(c, rc == 0);
    free(c->points);
    c->points = NULL;
    return rc;
}
