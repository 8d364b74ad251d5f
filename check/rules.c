/* check/rules.c - the fixed rules of check/quadrature.c: the density at
 * many points (a callback, or batches through a pipe), the chart's tensor
 * Gauss-Legendre rule on a box, the unequal pieces of the check rule, and
 * the probes just inside a box's sides with the error they bound. */
#include "check/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* --- densities at points -------------------------------------------------- */

int chk_densities(const mcbox_check *c, size_t n, chk_point_at at, const void *src, double *out)
{
    if (c->s.pdf) {
        /* The pdf callback is documented as safe from several threads. */
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < n; i++) {
            const double *x = at(i, src);
            if (x)
                out[i] = c->s.pdf(x, c->s.ctx);
        }
        return 0;
    }
    double *pts = malloc(CHK_BATCH * 3 * sizeof *pts);
    size_t *idx = malloc(CHK_BATCH * sizeof *idx);
    int status = pts && idx ? 0 : -1;
    size_t m = 0;
    for (size_t i = 0; status == 0 && i <= n; i++) {
        const double *x = i < n ? at(i, src) : NULL;
        if (x) {
            memcpy(pts + m * (size_t)c->dims, x, (size_t)c->dims * sizeof *pts);
            idx[m++] = i;
        }
        if (m == CHK_BATCH || (i == n && m > 0)) {
            double vals[CHK_BATCH];
            c->s.pdf_batch(pts, m, vals, c->s.ctx);
            for (size_t k = 0; k < m; k++)
                out[idx[k]] = vals[k];
            m = 0;
        }
    }
    free(pts);
    free(idx);
    return status;
}

/* --- fixed rules on boxes of the chart ------------------------------------- */

typedef struct recorder {
    double *at;
    bool called;
} recorder;

static double record_point(const double x[3], void *ctx)
{
    recorder *rec = ctx;
    memcpy(rec->at, x, 3 * sizeof *x);
    rec->called = true;
    return 1.0;
}

const double *chk_node_point(size_t at, const void *src)
{
    const chk_nodes *nd = src;
    return nd->jac[at] != 0.0 ? nd->pts + at * 3 : NULL;
}

/* The point of chart point p into pt and the chart's Jacobian there; 0
 * (and pt zeroed) where the chart maps p to no point of the domain. */
double chk_chart_node(const mcbox_check *c, const double p[2], double *pt)
{
    recorder rec = {pt, false};
    double jv = 0.0;
    if (!chk_masked(c, p))
        jv = cat_chart_density_of(&c->st, p, record_point, &rec);
    if (!rec.called)
        memset(pt, 0, 3 * sizeof *pt);
    return rec.called ? jv : 0.0;
}

/* The tensor Gauss-Legendre rule of n points per axis on the chart box b
 * (x0, x1, y0, y1): its nodes' points into pts and their weights times
 * the chart's Jacobian into jac (0 where the chart maps a node to no
 * point, or beyond the triangle). Returns the nodes written, or 0 when
 * the rule could not be made. */
size_t chk_rule_nodes(const mcbox_check *c, const double b[4], int n, double *pts, double *jac)
{
    int dims = c->spec.dims;
    double gx[64], gw[64], gy[64], gv[64];
    if (mc_quad_gauss_legendre(n, b[0], b[1], gx, gw) != 0 ||
        (dims == 2 && mc_quad_gauss_legendre(n, b[2], b[3], gy, gv) != 0))
        return 0;
    size_t count = dims == 2 ? (size_t)n * (size_t)n : (size_t)n;
    for (size_t k = 0; k < count; k++) {
        size_t i = dims == 2 ? k / (size_t)n : k, j = dims == 2 ? k % (size_t)n : 0;
        double p[2] = {gx[i], dims == 2 ? gy[j] : 0.0};
        double w = gw[i] * (dims == 2 ? gv[j] : 1.0);
        jac[k] = w * chk_chart_node(c, p, pts + k * 3);
    }
    return count;
}

/* The rule's sum over nodes [from, from + count): the Jacobian-weighted
 * densities, NaN when a density there is negative or not finite (the test
 * then rejects the cell instead of pooling it away). */
double chk_rule_sum(const double *jac, const double *vals, size_t from, size_t count)
{
    double sum = 0.0;
    for (size_t a = from; a < from + count; a++) {
        if (jac[a] != 0.0 && !(vals[a] >= 0.0 && isfinite(vals[a])))
            return (double)NAN;
        sum += jac[a] * vals[a];
    }
    return sum;
}

/* The rules' orders: quad_order and half of it, at every depth, so that
 * a part's nodes lie four times as densely (in 2D) as its parent's and a
 * sliver of the support one of the parent's nodes found is not lost. */
void chk_orders(const mcbox_check *c, int *q, int *h)
{
    *q = c->o.quad_order;
    *h = *q / 2 > 0 ? *q / 2 : 1;
}

/* The pieces a box is cut into, for the check rule and for halving: two
 * in 1D, four in 2D. */
int chk_sub_boxes(const mcbox_check *c)
{
    return c->spec.dims == 2 ? 4 : 2;
}

/* Piece k of box b cut at the fraction `cut` of each side. */
void chk_sub_box(const double b[4], int dims, int k, double cut, double out[4])
{
    int hx = dims == 2 ? k / 2 : k, hy = k % 2;
    double mx = b[0] + cut * (b[1] - b[0]), my = b[2] + cut * (b[3] - b[2]);
    out[0] = hx ? mx : b[0], out[1] = hx ? b[1] : mx;
    out[2] = b[2], out[3] = b[3];
    if (dims == 2)
        out[2] = hy ? my : b[2], out[3] = hy ? b[3] : my;
}

/* Both rules' nodes lie at least a fiftieth of the side from the box's
 * edges: a jump between the outermost nodes and an edge is invisible to
 * both, which then agree on a value that counts (or misses) the sliver
 * beyond it. So every side is probed: the chart's density a tiny fraction
 * EDGE_PROBE of the side inside the edge, against its value at the full
 * rule's outermost node on the same line; a side where one is 0 (or
 * below EDGE_JUMP of the other) is marked, and the part's error grows by
 * EDGE_SHARE (more than the outermost node's share of the side, 0.0199
 * for 8 points) of the mass the side's largest density would give the
 * whole part (see edge_error). A jump closer to the edge than EDGE_PROBE
 * holds too little of the cell to matter. */
#define EDGE_PROBE 1e-4
#define EDGE_JUMP 1e-3
#define EDGE_SHARE 0.03

size_t chk_probes_of(const mcbox_check *c, int q)
{
    return c->spec.dims == 2 ? (size_t)(8 * q) : 4u;
}

/* The densities one part asks for: its two rules and its probes. */
size_t chk_nodes_of(const mcbox_check *c)
{
    int q, h;
    chk_orders(c, &q, &h);
    size_t nq = c->spec.dims == 2 ? (size_t)(q * q) : (size_t)q;
    size_t nh = c->spec.dims == 2 ? (size_t)(h * h) : (size_t)h;
    return nq + (size_t)chk_sub_boxes(c) * nh + chk_probes_of(c, q);
}

/* The probe pairs of box b into pts and the chart's Jacobian (weight 1)
 * into jac: for each side, and each of the q Gauss-Legendre positions
 * along it (one in 1D), the point EDGE_PROBE inside the edge, then the
 * rule's outermost node. Returns the points written, or 0. */
size_t chk_probe_nodes(const mcbox_check *c, const double b[4], int q, double *pts, double *jac)
{
    int dims = c->spec.dims;
    double g[64], w[64], gy[64];
    if (mc_quad_gauss_legendre(q, 0.0, 1.0, g, w) != 0)
        return 0;
    int along = dims == 2 ? q : 1;
    if (dims == 1)
        gy[0] = 0.0;
    else
        for (int j = 0; j < q; j++)
            gy[j] = g[j];
    size_t k = 0;
    for (int side = 0; side < 2 * dims; side++) {
        int axis = side / 2, high = side % 2;
        double t_probe = high ? 1.0 - EDGE_PROBE : EDGE_PROBE, t_node = high ? g[q - 1] : g[0];
        for (int j = 0; j < along; j++)
            for (int which = 0; which < 2; which++, k++) {
                double t = which ? t_node : t_probe, s = gy[j];
                double u = axis == 0 ? t : s, v = axis == 0 ? s : t;
                double p[2] = {b[0] + u * (b[1] - b[0]), dims == 2 ? b[2] + v * (b[3] - b[2]) : 0.0};
                jac[k] = chk_chart_node(c, p, pts + k * 3);
            }
    }
    return k;
}

/* For every side whose probes show the support's edge (one value 0, or
 * below EDGE_JUMP of the other): EDGE_SHARE times the box's measure times
 * the larger value, a bound on what the rules can misplace between their
 * outermost nodes and the edge (the rules' own values may both be 0 when
 * the support is a sliver along the edge). A smooth density, however
 * steep, and an integrable singularity at the edge change by less than
 * that factor over a fiftieth of the side; the rules' own difference
 * measures their error there. */
double chk_edge_error(const double *jac, const double *vals, size_t from, int dims, int q,
                         const double box[4])
{
    int along = dims == 2 ? q : 1;
    double measure = (box[1] - box[0]) * (dims == 2 ? box[3] - box[2] : 1.0), e = 0.0;
    for (int side = 0; side < 2 * dims; side++) {
        double top = 0.0;
        for (int j = 0; j < along; j++) {
            size_t a = from + (size_t)(2 * (side * along + j));
            double x = fabs(jac[a] * vals[a]), y = fabs(jac[a + 1] * vals[a + 1]);
            if (!isfinite(x) || !isfinite(y))
                continue;
            if (fmin(x, y) <= EDGE_JUMP * fmax(x, y) && fmax(x, y) > 0.0)
                top = fmax(top, fmax(x, y));
        }
        e += EDGE_SHARE * measure * top;
    }
    return e;
}

