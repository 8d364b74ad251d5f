/* mc/gof.c - histogram, expected counts by per-cell quadrature, Pearson. */
#include "mc/gof.h"

#include <math.h>


int mc_gof_cell_count(const mc_gof_spec *spec)
{
    return spec->dims == 2 ? spec->cells[0] * spec->cells[1] : spec->cells[0];
}

/* BEGIN SNIPPET gof_histogram */
/* The cell of coordinate x in [lo, hi] cut into n cells, or -1 when x lies
 * outside by more than round-off (NaN fails both comparisons: outside). */
static int cell_of(double x, double lo, double hi, int n)
{
    double w = hi - lo, tol = MC_GOF_EDGE_TOL * w;
    if (!(x >= lo - tol && x <= hi + tol))
        return -1;
    int i = (int)floor((x - lo) / w * n);
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

int mc_gof_cell_index(const mc_gof_spec *spec, const double x[2])
{
    int nx = spec->cells[0], ny = spec->dims == 2 ? spec->cells[1] : 1;
    int i = cell_of(x[0], spec->lo[0], spec->hi[0], nx);
    int j = spec->dims == 2 ? cell_of(x[1], spec->lo[1], spec->hi[1], ny) : 0;
    return i < 0 || j < 0 ? -1 : i * ny + j;
}

double mc_gof_histogram(const mc_gof_spec *spec, mc_rng *rng, uint64_t n, double *obs)
{
    double outside = 0.0;
    for (uint64_t k = 0; k < n; k++) {
        double x[2] = {0.0, 0.0};
        spec->sample(rng, spec->ctx, x);
        int c = mc_gof_cell_index(spec, x);
        if (c < 0)
            outside += 1.0;
        else
            obs[c] += 1.0;
    }
    return outside;
}
/* END SNIPPET gof_histogram */

/* The density as the integrands mc_quad takes. */
static double density_1d(double x, void *params)
{
    const mc_gof_spec *s = params;
    double p[2] = {x, 0.0};
    return s->pdf(p, s->ctx);
}

static double density_2d(double x, double y, void *params)
{
    const mc_gof_spec *s = params;
    double p[2] = {x, y};
    return s->pdf(p, s->ctx);
}

/* BEGIN SNIPPET gof_integrate_box */
/* The density's integral over the box into *v, GSL's error estimate into
 * *err; the status is GSL's: non-zero when it could not certify its 1e-11
 * target (a jump of the density inside the cell, typically). The value is
 * still its best; callers that must know how good it is keep the status. */
static int integrate_box(const mc_gof_spec *s, mc_quad *q, double x0, double x1, double y0,
                         double y1, double *v, double *err)
{
    *v = 0.0;
    if (s->dims == 1)
        return mc_quad_1d(q, (mc_fn1){density_1d, (void *)s}, x0, x1, v, err);
    return mc_quad_2d(q, (mc_fn2){density_2d, (void *)s}, x0, x1, y0, y1, v, err);
}
/* END SNIPPET gof_integrate_box */

double mc_gof_integrate(const mc_gof_spec *spec, mc_quad *q)
{
    double v, err;
    (void)integrate_box(spec, q, spec->lo[0], spec->hi[0], spec->lo[1], spec->hi[1], &v, &err);
    return v;
}

void mc_gof_cell_box(const mc_gof_spec *spec, int c, double box[4])
{
    int nx = spec->cells[0], ny = spec->dims == 2 ? spec->cells[1] : 1;
    int i = c / ny, j = c % ny;
    double wx = (spec->hi[0] - spec->lo[0]) / nx;
    box[0] = spec->lo[0] + i * wx;
    box[1] = i == nx - 1 ? spec->hi[0] : box[0] + wx;
    box[2] = box[3] = 0.0;
    if (spec->dims == 2) {
        double wy = (spec->hi[1] - spec->lo[1]) / ny;
        box[2] = spec->lo[1] + j * wy;
        box[3] = j == ny - 1 ? spec->hi[1] : box[2] + wy;
    }
}

int mc_gof_cell_probs_checked(const mc_gof_spec *spec, double *prob, double *err, int *status)
{
    int cells = mc_gof_cell_count(spec);
    int failed = 0;
#pragma omp parallel reduction(| : failed)
    {
        mc_quad *q = mc_quad_create(MC_GOF_QUAD_LIMIT);
        failed |= q == NULL;
#pragma omp for schedule(dynamic, 16)
        for (int c = 0; c < cells; c++) {
            double b[4], v = (double)NAN, e = (double)NAN;
            int st = -1;
            mc_gof_cell_box(spec, c, b);
            if (q)
                st = integrate_box(spec, q, b[0], b[1], b[2], b[3], &v, &e);
            prob[c] = v;
            if (err)
                err[c] = e;
            if (status)
                status[c] = st;
        }
        mc_quad_destroy(q);
    }
    return failed ? -1 : 0;
}

int mc_gof_box_integral(const mc_gof_spec *spec, mc_quad *q, const double box[4], double *v,
                        double *err)
{
    return integrate_box(spec, q, box[0], box[1], box[2], box[3], v, err);
}

int mc_gof_cell_probs(const mc_gof_spec *spec, double *prob)
{
    return mc_gof_cell_probs_checked(spec, prob, NULL, NULL);
}

/* BEGIN SNIPPET gof_expected */
void mc_gof_expected_of_probs(const double *prob, size_t cells, uint64_t n, double *expct)
{
    /* The quadrature's own zero (its absolute tolerance is 1e-12) is an
     * exactly-zero cell for the test; NaN stays NaN. A cell clearly below
     * that zero is a pdf that goes negative, not round-off: it becomes NaN
     * so that the test rejects instead of pooling it away. */
    for (size_t c = 0; c < cells; c++) {
        double p = prob[c];
        expct[c] = p < -MC_QUAD_EPSABS         ? (double)NAN
                   : p < MC_GOF_ZERO_CELL_PROB ? 0.0
                                               : p * (double)n;
    }
}

int mc_gof_expected(const mc_gof_spec *spec, uint64_t n, double *expct)
{
    int status = mc_gof_cell_probs(spec, expct);
    mc_gof_expected_of_probs(expct, (size_t)mc_gof_cell_count(spec), n, expct);
    return status;
}
/* END SNIPPET gof_expected */

/* BEGIN SNIPPET gof_test */
mc_gof_result mc_gof_test(const mc_gof_spec *spec, uint64_t n, mc_rng *rng, double alpha,
                          double *obs, double *expct)
{
    mc_gof_result res = {{0.0, 0, (double)NAN, 0u, 0.0, 0.0, 0.0}, 0.0, true};
    int cells = mc_gof_cell_count(spec);
    for (int c = 0; c < cells; c++)
        obs[c] = 0.0;
    res.outside = mc_gof_histogram(spec, rng, n, obs);
    if (mc_gof_expected(spec, n, expct) != 0)
        return res;
    bool finite = true;
    for (int c = 0; c < cells; c++)
        finite = finite && isfinite(expct[c]);
    res.r = mc_chi2_pearson(obs, expct, (size_t)cells, MC_GOF_MIN_EXPECTED);
    res.reject = !finite || !(res.r.pvalue >= alpha) || res.outside > 0.0 ||
                 res.r.obs_in_zero_cells > MC_GOF_ZERO_CELL_FRAC * (double)n;
    return res;
}
/* END SNIPPET gof_test */
