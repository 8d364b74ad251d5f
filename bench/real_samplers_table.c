/* bench/real_samplers_table.c - the verdicts of the public check on light
 * and lobe samplers written from their papers (tests/support/real_samplers.h):
 * every sampler, correct and wrong, on each of its charts, through each door
 * (C API, mcbox-check --exec, mcbox-check --samples), at 10^5, 3 x 10^5 and
 * 10^6 samples, as one Markdown table of verdict and statistic; then the
 * false-alarm rate of densities with jumps (the tilted cone and the
 * spherical triangle on the whole sphere's default chart) over many seeds
 * through the C door, with the Kolmogorov-Smirnov test of the p-values
 * against the uniform law and the counts of rejections at 0.01 and 0.05
 * against their binomial laws.
 *
 * Every run is at alpha 0.01 (one test per run: the table shows each run's
 * own verdict). Seeds: 1000 + 10 x the sampler's index + the chart's for
 * the table (the same at every door, so the doors see the same points),
 * 5000 + k for the false-alarm runs.
 *
 * Build and run: make real-table   (or: make all && build/bench/real_samplers_table)
 *   build/bench/real_samplers_table [--counts 1e5,3e5,1e6] [--doors c,exec,samples]
 *       [--only NAME] [--chart sphere|hemisphere|polygon|cap|lobe] [--fa-seeds 200]
 *       [--fa-n 1e5] [--no-table] [--no-fa]
 * mcbox-check is found in $MC_BUILD/bin (default build/bin).
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, realpath */

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tests/support/real_doors.h"
#include "tests/support/real_samplers.h"

#define PROG "real_samplers_table"

typedef struct opts {
    uint64_t counts[8];
    int n_counts;
    bool doors[RS_DOORS];
    const char *only, *chart;
    int fa_seeds;
    uint64_t fa_n;
    bool table, fa;
} opts;

_Noreturn static void fail(const char *what)
{
    fprintf(stderr, "%s: %s\n", PROG, what);
    exit(2);
}

static opts parse(int argc, char **argv)
{
    opts o = {{100000, 300000, 1000000}, 3, {true, true, true}, NULL, NULL, 200, 100000, true, true};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            puts("usage: " PROG " [--counts 1e5,3e5,1e6] [--doors c,exec,samples] [--only NAME]\n"
                 "       [--chart NAME] [--fa-seeds 200] [--fa-n 1e5] [--no-table] [--no-fa]\n"
                 "The real samplers x charts x doors x sample counts, as a Markdown table of\n"
                 "verdicts, then the false-alarm runs (p-values of correct samplers over seeds).");
            exit(0);
        }
        if (strcmp(a, "--version") == 0) {
            printf("%s (mcbox) %s\n", PROG, mcbox_version());
            exit(0);
        }
        if (strcmp(a, "--counts") == 0 && v) {
            o.n_counts = 0;
            for (char *p = argv[++i]; *p && o.n_counts < 8;) {
                char *end;
                double x = strtod(p, &end);
                if (end == p || !(x >= 1.0))
                    fail("--counts takes numbers >= 1 separated by commas");
                o.counts[o.n_counts++] = (uint64_t)x;
                p = *end == ',' ? end + 1 : end;
            }
        } else if (strcmp(a, "--doors") == 0 && v) {
            i++;
            o.doors[RS_DOOR_C] = strstr(v, "c") == v || strstr(v, ",c") != NULL;
            o.doors[RS_DOOR_EXEC] = strstr(v, "exec") != NULL;
            o.doors[RS_DOOR_SAMPLES] = strstr(v, "samples") != NULL;
        } else if (strcmp(a, "--only") == 0 && v) {
            o.only = argv[++i];
        } else if (strcmp(a, "--chart") == 0 && v) {
            o.chart = argv[++i];
        } else if (strcmp(a, "--fa-seeds") == 0 && v) {
            o.fa_seeds = atoi(argv[++i]);
            if (o.fa_seeds < 5 || o.fa_seeds > 100000)
                fail("--fa-seeds takes 5 .. 100000");
        } else if (strcmp(a, "--fa-n") == 0 && v) {
            o.fa_n = (uint64_t)strtod(argv[++i], NULL);
        } else if (strcmp(a, "--no-table") == 0) {
            o.table = false;
        } else if (strcmp(a, "--no-fa") == 0) {
            o.fa = false;
        } else {
            fail("unknown option (see the comment at the top of bench/real_samplers_table.c)");
        }
    }
    return o;
}

static void table(const rs_env *e, const opts *o)
{
    printf("| sampler | what is wrong | chart | door |");
    for (int k = 0; k < o->n_counts; k++)
        printf(" n = %.0e |", (double)o->counts[k]);
    printf("\n|---|---|---|---|");
    for (int k = 0; k < o->n_counts; k++)
        printf("---|");
    printf("\n");
    for (size_t i = 0; i < rs_count(); i++) {
        const rs_sampler *s = rs_at(i);
        if (o->only && strcmp(o->only, s->name) != 0)
            continue;
        for (int c = 0; c < s->n_charts; c++)
            for (int d = 0; d < RS_DOORS; d++) {
                if (!o->doors[d] || (o->chart && strcmp(o->chart, rs_chart_name(s->charts[c]))))
                    continue;
                printf("| %s | %s | %s | %s |", s->name, s->wrong ? s->wrong : "(correct)",
                       rs_chart_name(s->charts[c]), rs_door_name((rs_door)d));
                fflush(stdout);
                for (int k = 0; k < o->n_counts; k++) {
                    rs_outcome r;
                    /* The same seed at every door: the same points. */
                    uint64_t seed = 1000u + 10u * (uint64_t)i + (uint64_t)c;
                    rs_door_run(e, s, s->charts[c], (rs_door)d, o->counts[k], seed, 1, &r);
                    printf(" %s%s, chi2 %.4g (dof %d), p %.2g, int %.6f, %.1f s |",
                           rs_verdict_name(r.verdict), r.warning[0] ? " (warned)" : "", r.statistic,
                           r.dof, r.pvalue, r.pdf_integral, r.seconds);
                    fflush(stdout);
                    if (r.verdict != RS_PASS)
                        fprintf(stderr, "  %s %s %s n=%llu: %s%s%s\n", s->name,
                                rs_chart_name(s->charts[c]), rs_door_name((rs_door)d),
                                (unsigned long long)o->counts[k], r.message,
                                r.warning[0] ? " | warning: " : "", r.warning);
                }
                printf("\n");
            }
    }
}

/* The false-alarm rate of a density with jumps on the sphere's default
 * chart, whose cells its edge cuts: the cone about a tilted axis and the
 * spherical triangle, C door, the expected counts computed once
 * (rs_sphere_pvalues), the first 5 seeds run in full through
 * mcbox_check_run as well (their statistics must be the same doubles). */
static void false_alarms(const opts *o)
{
    const char *names[] = {"cone", "triangle"};
    int n = o->fa_seeds;
    double *p = malloc((size_t)n * sizeof *p);
    if (!p)
        fail("no memory");
    printf("\nFalse alarms on the sphere's default chart, C API, %d seeds (5000 + k), %llu samples "
           "each, alpha 0.01:\n\n",
           n, (unsigned long long)o->fa_n);
    printf("| sampler | p < 0.01 | p < 0.05 | KS D, p | p-value deciles | full runs that differ |\n"
           "|---|---|---|---|---|---|\n");
    for (int q = 0; q < 2; q++) {
        int mismatches = 0, rej01 = 0, rej05 = 0;
        if (rs_sphere_pvalues(rs_find(names[q]), o->fa_n, 5000u, n, 5, p, &mismatches) != 0)
            fail("the false-alarm runs could not run");
        for (int k = 0; k < n; k++)
            rej01 += p[k] < 0.01, rej05 += p[k] < 0.05;
        double d, ks = rs_ks_uniform(p, n, &d);
        printf("| %s | %d (P(>=) = %.3g) | %d (P(>=) = %.3g) | %.4f, %.3g |", names[q], rej01,
               rs_binomial_tail(n, 0.01, rej01), rej05, rs_binomial_tail(n, 0.05, rej05), d, ks);
        for (int k = 1; k < 10; k++)
            printf(" %.2f", p[k * n / 10]);
        printf(" | %d of 5 |\n", mismatches);
        fflush(stdout);
    }
    free(p);
}

int main(int argc, char **argv)
{
    int rc = rs_main(argc, argv);
    if (rc >= 0)
        return rc;
    opts o = parse(argc, argv);
    rs_env e;
    const char *build = getenv("MC_BUILD") ? getenv("MC_BUILD") : "build";
    char real[PATH_MAX];
    snprintf(e.check, sizeof e.check, "%s/bin/mcbox-check", build);
    if (!realpath(e.check, real) || access(real, X_OK) != 0)
        fail("no mcbox-check in $MC_BUILD/bin (make all first)");
    if (strlen(real) >= sizeof e.check)
        fail("the path of mcbox-check is too long");
    memcpy(e.check, real, strlen(real) + 1);
    if (!realpath("/proc/self/exe", real))
        fail("cannot find this program's own path");
    if (strlen(real) >= sizeof e.self)
        fail("this program's path is too long");
    memcpy(e.self, real, strlen(real) + 1);
    snprintf(e.tmp, sizeof e.tmp, "/tmp/real-table-XXXXXX");
    if (!mkdtemp(e.tmp))
        fail("cannot make a scratch directory");
    if (o.table)
        table(&e, &o);
    if (o.fa)
        false_alarms(&o);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf %s", e.tmp);
    return system(cmd) == 0 ? 0 : 1;
}
