/* examples/qmc.c - this book's #ch-qmc: integrals over the unit
 * cube with closed forms (mc/testfn.h), estimated from random, jittered,
 * Halton and Sobol points, plain and scrambled.
 *
 * What it shows: on a smooth integrand, scrambled Sobol points are far more
 * accurate than random ones at equal cost, and still come with an honest
 * error bar: every random method is run as R independent replicates
 * (scrambles or streams) of N points, and the spread of the R estimates is
 * the standard error. Unscrambled Sobol points are deterministic: one set,
 * no error bar, only the actual error (abs_error). On the discontinuous pi
 * indicator the gain shrinks. `qmc points` prints the points themselves.
 *
 * Build and run:  make all && build/bin/qmc --integrand smooth --samples 4096
 *                 build/bin/qmc points --method sobol --dim 3 --samples 8
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "examples/common/mpi_split.h"
#include "mc/qmc.h"
#include "mc/testfn.h"

static const char *const integrands[] = {"pi", "smooth", "peak", "gauss", NULL};
static const char *const methods[] = {"mc", "jitter", "halton", "sobol", "sobol-xor", "sobol-owen", "all", NULL};
static const mc_qmc_method sources[] = {MC_QMC_RANDOM, MC_QMC_RANDOM, MC_QMC_HALTON,
                                        MC_QMC_SOBOL, MC_QMC_SOBOL_XOR, MC_QMC_SOBOL_OWEN};
enum { JITTER = 1, SOBOL = 3, N_METHODS = 6 };
static const char *const extra_cols[] = {"points", "scrambles", "abs_error"};
#define USAGE "qmc [--integrand pi|smooth|peak|gauss] [--method M|all] [--samples N] [--dim D]\n" \
              "           [--seed S] [--scrambles R] [--csv]\n" \
              "       qmc points [--method M] [--dim D] [--samples N] [--seed S]"

/* The side k of the jittered grid of at most n points in d dimensions, the
 * largest k with k^d <= n, and the grid's size k^d in *cells. */
static uint64_t jitter_side(uint64_t n, unsigned d, uint64_t *cells)
{
    uint64_t k = (uint64_t)pow((double)n, 1.0 / d) + 1, p = 0;
    for (; k >= 1; k--) { /* pow may round either way: step down to the exact k */
        p = 1;
        for (unsigned j = 0; j < d && p <= n; j++)
            p *= k;
        if (p <= n)
            break;
    }
    *cells = p;
    return k;
}

/* BEGIN SNIPPET qmc_point */
/* Point i of replicate r (a scramble, or an independent stream) of method m
 * in d dimensions. Jittered points take one uniform offset per dimension
 * from the replicate's generator, cell by cell in order of i. */
static void point(int m, uint64_t seed, uint64_t r, uint64_t i, unsigned d, uint64_t k, mc_rng *rng,
                  double *x)
{
    if (m == JITTER) {
        for (unsigned j = 0; j < d; j++, i /= k)
            x[j] = ((double)(i % k) + mc_rng_uniform(rng)) / (double)k;
        return;
    }
    mc_qmc_cursor c = mc_qmc_begin(sources[m], seed, r, i);
    for (unsigned j = 0; j < d; j++)
        x[j] = mc_qmc_next(&c);
}

/* The mean of f over n points of each of R replicates; the estimate is the
 * mean of the R replicate means, its standard error their spread / sqrt(R).
 * Sums are compensated (Neumaier): at 2^30 points the rounding of a plain
 * sum would be near the error of the best point sets. Under mpirun, rank
 * r of K computes the replicates r, r + K, ...; rank 0 gathers the means
 * and adds them in replicate order, so the result does not depend on K. */
static mc_estimate estimate(const app_mpi *mpi, const mc_testfn *f, int m, uint64_t seed,
                            uint64_t n, uint64_t reps, uint64_t k)
{
    double x[MC_TESTFN_MAX_DIM], *means = calloc(reps, sizeof *means);
    if (!means)
        app_fail("qmc", "out of memory for %llu replicates", (unsigned long long)reps);
    for (uint64_t r = (uint64_t)mpi->rank; r < reps; r += (uint64_t)mpi->size) {
        mc_rng rng = mc_rng_derive(seed, r);
        double s = 0.0, comp = 0.0;
        for (uint64_t i = 0; i < n; i++) {
            point(m, seed, r, i, f->dim, k, &rng, x);
            double v = mc_testfn_eval(f, x), t = s + v;
            comp += fabs(s) >= fabs(v) ? (s - t) + v : (v - t) + s;
            s = t;
        }
        means[r] = (s + comp) / (double)n;
    }
    if (!app_mpi_gather_rows(mpi, means, sizeof *means, (int)reps))
        app_fail("qmc", "gathering the replicates from the other processes failed");
    mc_welford w = mc_welford_init();
    for (uint64_t r = 0; r < reps; r++)
        mc_welford_add(&w, means[r]);
    free(means);
    mc_estimate e = mc_welford_estimate(&w);
    e.n = n * reps;
    e.variance = e.std_error * e.std_error * (double)e.n; /* per evaluation, as other programs print */
    if (reps < 2)
        e.std_error = e.variance = (double)NAN;
    return e;
}
/* END SNIPPET qmc_point */

static int method_index(const char *name)
{
    for (int m = 0; m < N_METHODS; m++)
        if (strcmp(methods[m], name) == 0)
            return m;
    return -1;
}

/* What a method cannot do with these arguments (NULL: nothing). */
static const char *refuse(int m, unsigned d, uint64_t n, char *buf, size_t size)
{
    if (d > mc_qmc_max_dim(sources[m]))
        snprintf(buf, size, "--dim %u: %s has %u dimensions", d, methods[m], mc_qmc_max_dim(sources[m]));
    else if (m >= SOBOL && n > UINT64_C(1) << 32)
        snprintf(buf, size, "--samples: %s has 2^32 points", methods[m]);
    else
        return NULL;
    return buf;
}

static int points(int argc, char **argv)
{
    uint64_t n = 16, seed = 1;
    const char *method = "sobol";
    int dim = 2;
    const app_opt opts[] = {
        {"--method", APP_CHOICE, &method, "point source (default sobol)", methods, 0, 0},
        {"--dim", APP_INT, &dim, "dimensions (default 2)", NULL, 1, MC_TESTFN_MAX_DIM},
        {"--samples", APP_COUNT, &n, "number of points (default 16)", NULL, 0, 0},
        APP_OPT_SEED(&seed),
    };
    app_parse("qmc", USAGE, argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    int m = method_index(method);
    char why[128];
    if (m < 0)
        app_fail("qmc", "points: --method all is not one point set");
    if (refuse(m, (unsigned)dim, n, why, sizeof why))
        app_fail("qmc", "%s", why);
    uint64_t k = 0;
    if (m == JITTER)
        k = jitter_side(n, (unsigned)dim, &n);
    static double x[MC_TESTFN_MAX_DIM];
    mc_rng rng = mc_rng_derive(seed, 0);
    printf("i");
    for (int j = 1; j <= dim; j++)
        printf(",x%d", j);
    for (uint64_t i = 0; i < n; i++) {
        point(m, seed, 0, i, (unsigned)dim, k, &rng, x);
        printf("\n%llu", (unsigned long long)i);
        for (int j = 0; j < dim; j++)
            printf(",%.17g", x[j]);
    }
    printf("\n");
    return 0;
}

int main(int argc, char **argv)
{
    app_mpi mpi = app_mpi_start(&argc, &argv);
    if (argc > 1 && strcmp(argv[1], "points") == 0) { /* printed once, by rank 0 */
        int rc = points(argc - 1, argv + 1);
        app_mpi_end(&mpi);
        return rc;
    }
    uint64_t n = 4096, seed = 1;
    const char *integrand = "smooth", *method = "all";
    int dim = 2, reps = 0;
    bool csv = false;
    const app_opt opts[] = {
        {"--integrand", APP_CHOICE, &integrand, "integrand (default smooth)", integrands, 0, 0},
        {"--method", APP_CHOICE, &method, "point source (default all)", methods, 0, 0},
        {"--samples", APP_COUNT, &n, "points per scramble (default 4096)", NULL, 0, 0},
        {"--dim", APP_INT, &dim, "dimensions (default 2; pi: 2 only)", NULL, 1, MC_TESTFN_MAX_DIM},
        APP_OPT_SEED(&seed),
        {"--scrambles", APP_INT, &reps, "independent scrambles or streams R (default 16)", NULL, 1, 1e6},
        APP_OPT_CSV(&csv),
    };
    app_parse("qmc", USAGE, argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    static mc_testfn f;
    if (!mc_testfn_init(&f, (mc_testfn_kind)(strcmp(integrand, "pi") == 0       ? MC_TESTFN_PI
                                             : strcmp(integrand, "smooth") == 0 ? MC_TESTFN_SMOOTH
                                             : strcmp(integrand, "peak") == 0   ? MC_TESTFN_PEAK
                                                                                : MC_TESTFN_GAUSS),
                        (unsigned)dim))
        app_fail("qmc", "--dim %d: the pi indicator is defined in 2 dimensions only", dim);
    if (strcmp(method, "sobol") == 0 && reps > 0)
        app_fail("qmc", "--scrambles: unscrambled sobol points are one deterministic set");
    if (reps == 1)
        app_fail("qmc", "--scrambles 1: an error bar needs at least 2 independent replicates");
    uint64_t r = reps ? (uint64_t)reps : 16;
    if (n > APP_MAX_SAMPLES / r)
        app_fail("qmc", "--samples %llu times --scrambles %llu is more than 1e13 evaluations",
                 (unsigned long long)n, (unsigned long long)r);
    char why[128];
    for (int m = 0; m < N_METHODS; m++)
        if (app_selected(method, methods[m]) && refuse(m, (unsigned)dim, n, why, sizeof why))
            app_fail("qmc", "%s", why);
    /* A rough cost per evaluation and dimension, used only for the time
     * the announcement foretells; nothing else depends on it. */
    app_announce_samples("qmc", n * r, 3e-8 * dim * (strcmp(method, "all") == 0 ? N_METHODS : 1));
    app_mpi_setup_done(&mpi);

    app_table t = {stdout, csv, extra_cols, 3, NULL};
    app_table_begin(&t);
    double exact = mc_testfn_exact(&f);
    bool shown_sobol = false;
    for (int m = 0; m < N_METHODS; m++) {
        if (!app_selected(method, methods[m]))
            continue;
        uint64_t k = 0, pts = n, reps_m = m == SOBOL ? 1 : r;
        if (m == JITTER)
            k = jitter_side(n, (unsigned)dim, &pts);
        mc_estimate e = estimate(&mpi, &f, m, seed, pts, reps_m, k);
        double extra[3] = {(double)pts, (double)reps_m, fabs(e.value - exact)};
        if (m != SOBOL) {
            app_table_row(&t, methods[m], e, exact, extra);
        } else if (csv) { /* no error bar: stderr and z empty */
            printf("sobol,%llu,%.17g,,%.17g,,%.17g,%.17g,%.17g\n", (unsigned long long)e.n, e.value, exact,
                   extra[0], extra[1], extra[2]);
        } else {
            printf("%-14s %14llu %18.12f %12s %18.12f %8s %14.6g %14.6g %14.6g\n", "sobol",
                   (unsigned long long)e.n, e.value, "none", exact, "-", extra[0], extra[1], extra[2]);
            shown_sobol = true;
        }
    }
    if (shown_sobol)
        printf("\nsobol: one deterministic point set, so no standard error and no z; abs_error is\n"
               "its actual error. The scrambled methods' errors come from %llu independent replicates.\n",
               (unsigned long long)r);
    app_mpi_end(&mpi);
    return 0;
}
