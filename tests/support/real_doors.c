/* tests/support/real_doors.c - the three doors of the public check for the
 * samplers of real_samplers.h, and the tests of uniformity of p-values. */
#define _POSIX_C_SOURCE 200809L /* WEXITSTATUS, clock_gettime */

#include "tests/support/real_doors.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>

#include "mc/rng.h"

const char *rs_door_name(rs_door d)
{
    static const char *const names[] = {"C API", "--exec", "--samples"};
    return names[d];
}

const char *rs_verdict_name(rs_verdict v)
{
    static const char *const names[] = {"pass", "fail", "undetermined", "error"};
    return names[v];
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The number after "key": in a JSON object (NaN for null or missing). */
static double json_num(const char *json, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(json, k);
    return p && strncmp(p + strlen(k), "null", 4) != 0 ? strtod(p + strlen(k), NULL) : (double)NAN;
}

/* The string after "key": into out (escapes kept as written); "" if none. */
static void json_str(const char *json, const char *key, char *out, size_t size)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": \"", key);
    const char *p = strstr(json, k);
    size_t n = 0;
    if (p)
        for (p += strlen(k); *p && *p != '"' && n + 1 < size; p++) {
            if (*p == '\\' && p[1])
                out[n++] = *++p;
            else
                out[n++] = *p;
        }
    out[n] = '\0';
}

/* The whole text of a file, NUL-terminated, or NULL. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0;) {
        n += got;
        if (n + 1 == cap) {
            char *b = realloc(buf, cap *= 2);
            if (!b)
                free(buf);
            buf = b;
        }
    }
    fclose(f);
    if (buf)
        buf[n] = '\0';
    return buf;
}

static rs_verdict c_door(const rs_sampler *s, rs_chart c, uint64_t n, uint64_t seed, int tests,
                         rs_outcome *out)
{
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = n, o.seed = seed, o.alpha = 0.01, o.tests = tests;
    mcbox_sampler m = rs_mcbox_sampler(s, c, &o);
    mcbox_check_result r;
    if (mcbox_check_run(&m, &o, &r, NULL) != 0) {
        snprintf(out->message, sizeof out->message, "%s", r.message);
        return out->verdict = RS_ERROR;
    }
    out->statistic = r.statistic, out->pvalue = r.pvalue, out->dof = r.dof;
    out->pdf_integral = r.pdf_integral, out->pdf_integral_error = r.pdf_integral_error;
    out->power_rel_error = r.power_rel_error;
    snprintf(out->message, sizeof out->message, "%s", r.message);
    snprintf(out->warning, sizeof out->warning, "%s", r.warning);
    return out->verdict = r.pass ? RS_PASS : r.undetermined ? RS_UNDETERMINED : RS_FAIL;
}

/* Runs the command line `cmd` (stdout to the scratch file out.json,
 * stderr to err.txt) and reads mcbox-check's report back. */
static rs_verdict cli_door(const rs_env *e, const char *cmd, rs_outcome *out)
{
    char full[9000], path[512];
    snprintf(full, sizeof full, "%s >%s/out.json 2>%s/err.txt", cmd, e->tmp, e->tmp);
    int rc = system(full);
    int status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    snprintf(path, sizeof path, "%s/out.json", e->tmp);
    char *json = slurp(path);
    snprintf(path, sizeof path, "%s/err.txt", e->tmp);
    char *err = slurp(path);
    char verdict[32] = "";
    if (json) {
        json_str(json, "verdict", verdict, sizeof verdict);
        json_str(json, "message", out->message, sizeof out->message);
        json_str(json, "warning", out->warning, sizeof out->warning);
        out->statistic = json_num(json, "statistic"), out->pvalue = json_num(json, "pvalue");
        out->dof = (int)json_num(json, "dof"), out->pdf_integral = json_num(json, "pdf_integral");
        out->pdf_integral_error = json_num(json, "pdf_integral_error");
        out->power_rel_error = json_num(json, "power_rel_error");
    }
    if (status == 0)
        out->verdict = RS_PASS;
    else if (status == 1)
        out->verdict = RS_FAIL;
    else if (status == 2 && (strcmp(verdict, "undetermined") == 0 ||
                             (err && strstr(err, "undetermined"))))
        out->verdict = RS_UNDETERMINED;
    else
        out->verdict = RS_ERROR;
    if (!out->message[0] && err)
        snprintf(out->message, sizeof out->message, "%.*s", (int)strcspn(err, "\n"), err);
    if (!out->warning[0] && err && strstr(err, "warning: "))
        snprintf(out->warning, sizeof out->warning, "%s", strstr(err, "warning: ") + 9);
    if (out->verdict == RS_ERROR && !out->message[0])
        snprintf(out->message, sizeof out->message, "exit status %d", status);
    free(json);
    free(err);
    return out->verdict;
}

rs_verdict rs_door_run(const rs_env *e, const rs_sampler *s, rs_chart c, rs_door d, uint64_t n,
                       uint64_t seed, int tests, rs_outcome *out)
{
    memset(out, 0, sizeof *out);
    out->statistic = out->pvalue = out->pdf_integral = (double)NAN;
    out->pdf_integral_error = out->power_rel_error = (double)NAN;
    double t0 = now();
    if (d == RS_DOOR_C) {
        c_door(s, c, n, seed, tests, out);
    } else {
        char args[2048], cmd[8192];
        rs_cli_args(s, c, args, sizeof args);
        if (d == RS_DOOR_EXEC) {
            snprintf(cmd, sizeof cmd,
                     "%s --exec '%s serve %s' %s --n %llu --seed %llu --tests %d --alpha 0.01 --json",
                     e->check, e->self, s->name, args, (unsigned long long)n,
                     (unsigned long long)seed, tests);
        } else {
            char make[4096];
            snprintf(make, sizeof make, "%s sample %s %llu %llu f64 >%s/points.f64", e->self,
                     s->name, (unsigned long long)n, (unsigned long long)seed, e->tmp);
            if (system(make) != 0) {
                snprintf(out->message, sizeof out->message, "could not write %s/points.f64", e->tmp);
                return out->verdict = RS_ERROR;
            }
            snprintf(cmd, sizeof cmd,
                     "%s --samples %s/points.f64 --format f64 --pdf-exec '%s serve %s' %s "
                     "--tests %d --alpha 0.01 --json",
                     e->check, e->tmp, e->self, s->name, args, tests);
        }
        cli_door(e, cmd, out);
    }
    out->seconds = now() - t0;
    return out->verdict;
}

/* The chart cell of the unit direction w on the sphere's default chart:
 * x = cos theta = w.z, y = phi = atan2(w.y, w.x) in [0, 2 pi), each cut
 * into equal parts from lo to hi, the last part closed. */
static size_t sphere_cell(const mcbox_check_table *t, const double *w)
{
    double phi = atan2(w[1], w[0]);
    if (phi < 0.0)
        phi += 2.0 * 3.14159265358979323846;
    int i = (int)floor((w[2] - t->lo[0]) / (t->hi[0] - t->lo[0]) * t->nx);
    int j = (int)floor((phi - t->lo[1]) / (t->hi[1] - t->lo[1]) * t->ny);
    i = i < 0 ? 0 : i >= t->nx ? t->nx - 1 : i;
    j = j < 0 ? 0 : j >= t->ny ? t->ny - 1 : j;
    return (size_t)i * (size_t)t->ny + (size_t)j;
}

int rs_sphere_pvalues(const rs_sampler *s, uint64_t n, uint64_t seed0, int n_seeds, int verify,
                      double *p, int *mismatches)
{
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = n, o.seed = seed0, o.alpha = 0.01;
    mcbox_sampler m = rs_mcbox_sampler(s, RS_CHART_SPHERE, &o);
    mcbox_check_result r;
    mcbox_check_table t;
    if (mcbox_check_run(&m, &o, &r, &t) != 0) {
        fprintf(stderr, "rs_sphere_pvalues: %s\n", r.message);
        return -1;
    }
    if (t.dims != 2 || strcmp(t.xlabel, "cos theta") != 0 || t.lo[0] != -1.0 || t.hi[0] != 1.0 ||
        t.lo[1] != 0.0 || t.cells != (size_t)t.nx * (size_t)t.ny) {
        fprintf(stderr, "rs_sphere_pvalues: the sphere's chart is not (cos theta, phi)\n");
        mcbox_check_table_free(&t);
        return -1;
    }
    double *obs = malloc(t.cells * sizeof *obs);
    *mismatches = 0;
    for (int k = 0; obs && k < n_seeds; k++) {
        memset(obs, 0, t.cells * sizeof *obs);
        mc_rng rng = mc_rng_derive(seed0 + (uint64_t)k, 0u); /* mcbox_check_run's stream */
        for (uint64_t i = 0; i < n; i++) {
            double u[2];
            u[0] = mc_rng_uniform(&rng);
            u[1] = mc_rng_uniform(&rng);
            mcbox_sample x = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
            s->sample(u, &x, (void *)s);
            obs[sphere_cell(&t, x.x)] += 1.0;
        }
        mcbox_check_result c;
        mcbox_check_counts(obs, t.expected, t.cells, &o, &c);
        p[k] = c.pvalue;
        if (k > 0 && k < verify) {
            o.seed = seed0 + (uint64_t)k;
            mcbox_check_run(&m, &o, &r, NULL);
        }
        /* Seed 0's full run is the one that gave the table. */
        if (k < verify)
            *mismatches += memcmp(&r.statistic, &c.statistic, sizeof(double)) != 0;
    }
    int rc = obs ? 0 : -1;
    mcbox_check_table_free(&t);
    free(obs);
    return rc;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double rs_ks_uniform(double *p, int n, double *d)
{
    qsort(p, (size_t)n, sizeof *p, cmp_double);
    double dmax = 0.0;
    for (int i = 0; i < n; i++) {
        double lo = p[i] - (double)i / n, hi = (double)(i + 1) / n - p[i];
        dmax = fmax(dmax, fmax(lo, hi));
    }
    *d = dmax;
    double sn = sqrt((double)n), t = dmax * (sn + 0.12 + 0.11 / sn);
    /* Kolmogorov's limit law: P(K > t) = 2 sum_k (-1)^(k-1) e^(-2 k^2 t^2). */
    double q = 0.0;
    for (int k = 1; k <= 100; k++)
        q += (k % 2 ? 2.0 : -2.0) * exp(-2.0 * k * k * t * t);
    return fmin(1.0, fmax(0.0, q));
}

double rs_binomial_tail(int n, double q, int k)
{
    double tail = 0.0;
    for (int j = k; j <= n; j++)
        tail += exp(lgamma(n + 1.0) - lgamma(j + 1.0) - lgamma(n - j + 1.0) + j * log(q) +
                    (n - j) * log1p(-q));
    return fmin(1.0, tail);
}
