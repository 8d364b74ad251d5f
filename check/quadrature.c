/* check/quadrature.c - the probability of every chart cell under a user's
 * density, with an honest estimate of its error.
 *
 * A density with a jump inside a cell (a light's edge, a cone's rim, a
 * spherical triangle's sides crossing a (cos theta, phi) chart) defeats a
 * rule of fixed order: its error falls only as fast as the area of the
 * cell that the jump cuts, and two rules of different order can agree on
 * a wrong value. So every cell, whatever the door, gets fixed
 * Gauss-Legendre rules in batches: the rule of quad_order points per axis,
 * as a check the rule of half that order on the cell cut unequally (see
 * CHECK_CUT), and probes just inside every side (see EDGE_PROBE). A cell
 * whose rules disagree, or whose density drops to 0 at a side, is halved
 * along each axis, and so on, worst parts first, until the estimated
 * error is below ERR_TARGET, quad_depth halvings are reached or
 * EVAL_BUDGET densities have been asked for (a density behind pdf_batch,
 * a pipe or a GPU, is asked once per round). A pointwise pdf also gets
 * GSL's adaptive rule on every cell, as the suite's own harness integrates
 * it (mc/gof.h); its value stands where the fixed rules call the cell
 * smooth, and elsewhere only where it agrees with the refinement (see
 * pointwise_probs).
 * A part's error estimate starts from three times its two rules' difference:
 * for an error that falls as h^a with the part's width h, the finer rule's
 * error is the difference times 2^-a / (1 - 2^-a), which is 1 for a jump
 * (a = 1) and 2.41 for an inverse square root singularity (a = 1/2, the
 * density of uniform theta at the pole).
 *
 * A cell whose rules find nothing although a sample landed in it where the
 * density is positive (a sliver of the support between the nodes) is
 * halved toward that sample until the rules see the support, or reported.
 * The rules themselves, the probes and the error they bound are in
 * check/rules.c.
 */
#include "check/internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The refinement stops when the error estimate of the whole integral is
 * below this: a hundredth of quad_error_max's default, and a tenth of a
 * count per cell of a 5000-cell chart at 10^6 samples. */
#define ERR_TARGET 1e-5
/* GSL's value of a cell where it reports a failure (its round-off test
 * fires on cells whose density is tiny but smooth) is kept when its own
 * error estimate is below this: a ten-millionth of a count per 10^6
 * samples, far below any histogram's resolution. */
#define GSL_TRUSTED_ERR 1e-10
/* At most this many densities asked for by the refinement (the first pass
 * over every cell comes on top): about 8 s through a pipe at 10^6 a
 * second. */
#define EVAL_BUDGET (UINT64_C(1) << 23)

/* --- adaptive refinement of fixed rules ------------------------------------ */

/* A part of a chart cell, with its two rules' values. */
typedef struct part {
    double box[4];
    double hint[2]; /* a chart point inside where the density is positive, or NaN */
    double full, half;
    double group; /* 3 |sum of the part and its siblings - their parent's rule| / siblings */
    double edge;  /* the bound of edge_error for the sides with a jump beyond the outer nodes */
    int cell, depth;
} part;

static double part_error(const part *p)
{
    return 3.0 * fabs(p->full - p->half) + p->group + p->edge;
}

/* Whether the two rules agree to the accuracy a smooth cell gets. */
static bool converged(const part *p)
{
    return part_error(p) <= 3e-13 + 3e-9 * fabs(p->full);
}

/* Whether part p holds the hint point h. */
static bool hint_in(const part *p, const double h[2], int dims)
{
    return !isnan(h[0]) && h[0] >= p->box[0] && h[0] <= p->box[1] &&
           (dims == 1 || (h[1] >= p->box[2] && h[1] <= p->box[3]));
}

/* Whether a part finds no mass though a sample in it has some. */
static bool blind(const part *p)
{
    return !isnan(p->hint[0]) && p->full == 0.0 && p->half == 0.0;
}

/* Both rules on parts[0 .. m); adds to *evals. Returns -1 when out of
 * memory or when a rule could not be made. */
static int eval_parts(const mcbox_check *c, part *parts, size_t m, uint64_t *evals)
{
    size_t total = m * chk_nodes_of(c);
    double *pts = malloc((total ? total : 1) * 3 * sizeof *pts);
    double *jac = malloc((total ? total : 1) * sizeof *jac);
    double *vals = calloc(total ? total : 1, sizeof *vals);
    int status = pts && jac && vals ? 0 : -1;
    size_t at = 0;
    for (size_t k = 0; status == 0 && k < m; k++) {
        int q, h;
        chk_orders(c, &q, &h);
        size_t nq = chk_rule_nodes(c, parts[k].box, q, pts + at * 3, jac + at);
        status = nq ? 0 : -1;
        at += nq;
        for (int b = 0; status == 0 && b < chk_sub_boxes(c); b++) {
            double sb[4];
            chk_sub_box(parts[k].box, c->spec.dims, b, CHECK_CUT, sb);
            size_t nh = chk_rule_nodes(c, sb, h, pts + at * 3, jac + at);
            status = nh ? 0 : -1;
            at += nh;
        }
        size_t np = status == 0 ? chk_probe_nodes(c, parts[k].box, q, pts + at * 3, jac + at) : 0;
        status = np ? 0 : -1;
        at += np;
    }
    chk_nodes nd = {pts, jac};
    if (status == 0)
        status = chk_densities(c, total, chk_node_point, &nd, vals);
    for (size_t k = 0, a = 0; status == 0 && k < m; k++) {
        int q, h;
        chk_orders(c, &q, &h);
        size_t nq = c->spec.dims == 2 ? (size_t)(q * q) : (size_t)q;
        size_t nh = (size_t)chk_sub_boxes(c) * (c->spec.dims == 2 ? (size_t)(h * h) : (size_t)h);
        parts[k].full = chk_rule_sum(jac, vals, a, nq);
        parts[k].half = chk_rule_sum(jac, vals, a + nq, nh);
        parts[k].edge = chk_edge_error(jac, vals, a + nq + nh, c->spec.dims, q, parts[k].box);
        a += nq + nh + chk_probes_of(c, q);
    }
    *evals += total;
    free(pts);
    free(jac);
    free(vals);
    return status;
}

static const double *hint_point(size_t k, const void *src)
{
    const double *h = (const double *)src + k * 3;
    return isnan(h[0]) ? NULL : h;
}

/* For every whole cell where samples landed: the density at the first of
 * them, and if it is positive, that sample's chart point as the part's
 * hint, which follows the part holding it down the halvings: a part that
 * holds a hint and whose rules find nothing has missed a sliver of the
 * support and is halved again. */
static int find_hints(mcbox_check *c, part *parts, size_t m, uint64_t *evals)
{
    if (!c->hint_x)
        return 0;
    double *pts = malloc((m ? m : 1) * 3 * sizeof *pts), *dens = malloc((m ? m : 1) * sizeof *dens);
    if (!pts || !dens) {
        free(pts);
        free(dens);
        return -1;
    }
    for (size_t k = 0; k < m; k++) {
        const double *x = c->hint_x + (size_t)parts[k].cell * (size_t)c->dims;
        bool want = c->obs[parts[k].cell] > 0.0 && !isnan(x[0]);
        pts[k * 3] = (double)NAN;
        if (want) {
            for (int j = 0; j < 3; j++)
                pts[k * 3 + (size_t)j] = j < c->dims ? x[j] : 0.0;
            (*evals)++;
        }
        dens[k] = 0.0;
    }
    int status = chk_densities(c, m, hint_point, pts, dens);
    for (size_t k = 0; status == 0 && k < m; k++) {
        if (!isnan(pts[k * 3]) && dens[k] > 0.0 && isfinite(dens[k])) {
            double p[2] = {0.0, 0.0};
            cat_chart_point(&c->st, pts + k * 3, p);
            if (hint_in(&parts[k], p, c->spec.dims))
                parts[k].hint[0] = p[0], parts[k].hint[1] = p[1];
        }
    }
    free(pts);
    free(dens);
    return status;
}

static int by_error_desc(const void *a, const void *b)
{
    double da = part_error(*(const part *const *)a), db = part_error(*(const part *const *)b);
    return da < db ? 1 : da > db ? -1 : 0;
}

/* Replaces parts[i] by its halves (1D) or quarters (2D) at the end of
 * the array *parts (grown as needed); the hint goes to the part that
 * holds it. Returns the number of new parts, or 0 when out of memory. */
static size_t split_part(const mcbox_check *c, part **parts, size_t *m, size_t *cap, size_t i)
{
    int dims = c->spec.dims, n = chk_sub_boxes(c);
    if (*m + (size_t)n > *cap) {
        size_t nc = 2 * *cap + (size_t)n;
        part *g = realloc(*parts, nc * sizeof *g);
        if (!g)
            return 0;
        *parts = g, *cap = nc;
    }
    part p = (*parts)[i];
    for (int k = 0; k < n; k++) {
        part q = p;
        chk_sub_box(p.box, dims, k, 0.5, q.box);
        q.depth = p.depth + 1;
        q.group = 0.0, q.edge = 0.0;
        if (!hint_in(&q, p.hint, dims))
            q.hint[0] = q.hint[1] = (double)NAN;
        (*parts)[(*m)++] = q;
    }
    (*parts)[i].depth = -1; /* replaced */
    return (size_t)n;
}

/* Chooses the parts to halve this round: every blind part, then the
 * unconverged ones, worst first, until they carry half the estimated
 * error (when the error is above the target), within the budget. */
static size_t choose(const mcbox_check *c, part *parts, size_t m, part **pick, double total,
                     uint64_t room)
{
    size_t np = 0;
    for (size_t k = 0; k < m; k++)
        if (parts[k].depth >= 0 && parts[k].depth < c->o.quad_depth && blind(&parts[k]))
            pick[np++] = &parts[k];
    size_t forced = np;
    if (total > ERR_TARGET) {
        size_t first = np;
        for (size_t k = 0; k < m; k++)
            if (parts[k].depth >= 0 && parts[k].depth < c->o.quad_depth && !blind(&parts[k]) &&
                !converged(&parts[k]) && !isnan(part_error(&parts[k])))
                pick[np++] = &parts[k];
        qsort(pick + first, np - first, sizeof *pick, by_error_desc);
        double acc = 0.0;
        size_t k = first;
        while (k < np && acc < 0.5 * total)
            acc += part_error(pick[k++]);
        np = k;
    }
    /* Within the budget: each pick costs its children's nodes. */
    uint64_t cost = 0, each = (uint64_t)chk_sub_boxes(c) * chk_nodes_of(c);
    size_t k = 0;
    for (; k < np; k++) {
        if (cost + each > room && k >= forced)
            break;
        cost += each;
    }
    return k;
}

/* The first rules on the whole cells cells[0 .. m) into a new array of
 * parts (NULL when out of memory), with hints where a cell looks empty. */
static part *first_parts(mcbox_check *c, const int *cells, size_t m, chk_quad_report *rep)
{
    part *parts = malloc((m ? m : 1) * sizeof *parts);
    if (!parts)
        return NULL;
    for (size_t k = 0; k < m; k++) {
        part *p = &parts[k];
        mc_gof_cell_box(&c->spec, cells[k], p->box);
        p->hint[0] = p->hint[1] = (double)NAN;
        p->cell = cells[k], p->depth = 0, p->group = 0.0, p->edge = 0.0;
    }
    if (eval_parts(c, parts, m, &rep->evaluations) != 0 ||
        find_hints(c, parts, m, &rep->evaluations) != 0) {
        free(parts);
        return NULL;
    }
    return parts;
}

/* Refines the evaluated whole-cell parts (*parts)[0 .. m) until the error
 * target, the depth or the budget; their cells' probabilities and error
 * estimates into prob[] and err[] (indexed by cell). *parts may move. */
static int refine(mcbox_check *c, part **pp, size_t m, double *prob, double *err,
                  chk_quad_report *rep)
{
    size_t cap = m, n = m;
    part *parts = *pp, **pick = NULL;
    int status = 0;
    uint64_t start = rep->evaluations;
    while (status == 0) {
        double total = 0.0;
        for (size_t k = 0; k < n; k++)
            if (parts[k].depth >= 0 && !isnan(part_error(&parts[k])))
                total += part_error(&parts[k]);
        free(pick);
        pick = malloc((n ? n : 1) * sizeof *pick);
        if (!pick) {
            status = -1;
            break;
        }
        uint64_t used = rep->evaluations - start;
        uint64_t room = used < EVAL_BUDGET ? EVAL_BUDGET - used : 0;
        size_t np = choose(c, parts, n, pick, total, room);
        if (np == 0)
            break;
        /* Indices, not pointers: splitting may move the array. */
        size_t *at = malloc(np * sizeof *at);
        if (!at) {
            status = -1;
            break;
        }
        for (size_t k = 0; k < np; k++)
            at[k] = (size_t)(pick[k] - parts);
        size_t from = n, kids = (size_t)chk_sub_boxes(c);
        double *parent = malloc(np * sizeof *parent);
        if (!parent)
            status = -1;
        for (size_t k = 0; k < np && status == 0; k++) {
            parent[k] = parts[at[k]].full;
            if (!split_part(c, &parts, &n, &cap, at[k]))
                status = -1;
        }
        free(at);
        if (status == 0)
            status = eval_parts(c, parts + from, n - from, &rep->evaluations);
        /* The children's sum against their parent's rule: the classic
         * estimate of adaptive quadrature, shared among them. */
        for (size_t k = 0; status == 0 && k < np; k++) {
            part *g = parts + from + k * kids;
            double sum = 0.0;
            for (size_t j = 0; j < kids; j++)
                sum += g[j].full;
            for (size_t j = 0; j < kids; j++)
                g[j].group = 3.0 * fabs(sum - parent[k]) / (double)kids;
        }
        free(parent);
    }
    for (size_t k = 0; k < n; k++)
        prob[parts[k].cell] = 0.0, err[parts[k].cell] = 0.0;
    for (size_t k = 0; status == 0 && k < n; k++) {
        const part *p = &parts[k];
        if (p->depth < 0)
            continue;
        prob[p->cell] += p->full;
        err[p->cell] += part_error(p);
        if (blind(p) && rep->missed_cell < 0) {
            rep->missed_cell = p->cell;
            double x[3] = {0.0, 0.0, 0.0};
            const double *hx = c->hint_x + (size_t)p->cell * (size_t)c->dims;
            for (int j = 0; j < c->dims; j++)
                x[j] = hx[j];
            memcpy(rep->missed_x, x, sizeof x);
        }
    }
    free(pick);
    *pp = parts;
    return status;
}

/* --- every cell ------------------------------------------------------------ */

/* A GSL workspace this small gives up quickly on a jump, where the
 * refinement above is the answer anyway, and suffices for the integrable
 * singularities (uniform theta at the pole) on which it succeeds. */
#define GSL_SMALL_LIMIT 64
/* A refined cell whose estimated error is below this is smooth enough for
 * GSL's full workspace to settle quickly. */
#define GSL_RETRY_ERR 1e-6

/* A pointwise density: GSL's adaptive rule on every cell, as the suite's
 * harness integrates it, where the first fixed rules agree (a smooth
 * cell) and GSL succeeds or its error estimate is negligible. The other
 * cells are refined as above, and GSL's value (from a small workspace) is
 * kept when it succeeds and lies within the refinement's error of the
 * refinement's value, so that a density the harness integrates exactly
 * gets the harness's bits; otherwise the refinement's value stands, with
 * its error estimate. GSL's own estimate is trusted only on cells the
 * fixed rules call smooth: on a cell cut by a jump it can report success
 * with a tiny error and a wrong value. */
static int pointwise_probs(mcbox_check *c, part **pp, double *prob, double *err,
                           chk_quad_report *rep)
{
    part *first = *pp;
    int cells = c->chart_cells, failed = 0;
    signed char *redo = malloc((size_t)cells);
    int *gst = malloc((size_t)cells * sizeof *gst);
    if (!redo || !gst) {
        free(redo);
        free(gst);
        return -1;
    }
    for (int k = 0; k < cells; k++)
        redo[k] = !converged(&first[k]) || blind(&first[k]);
#pragma omp parallel reduction(| : failed)
    {
        mc_quad *big = mc_quad_create(MC_GOF_QUAD_LIMIT), *small = mc_quad_create(GSL_SMALL_LIMIT);
        failed |= !big || !small;
#pragma omp for schedule(dynamic, 16)
        for (int k = 0; k < cells; k++) {
            if (!big || !small)
                continue;
            gst[k] = mc_gof_box_integral(&c->spec, redo[k] ? small : big, first[k].box, &prob[k],
                                         &err[k]);
            if (!redo[k] && gst[k] != 0 && !(err[k] <= GSL_TRUSTED_ERR))
                redo[k] = 1;
        }
        mc_quad_destroy(big);
        mc_quad_destroy(small);
    }
    size_t m = 0;
    part *box = malloc((size_t)cells * sizeof *box);
    if (box)
        memcpy(box, first, (size_t)cells * sizeof *box);
    for (int k = 0; k < cells; k++)
        if (redo[k])
            first[m++] = first[k];
    double *rp = failed ? NULL : malloc((size_t)cells * 2 * sizeof *rp);
    mc_quad *big = mc_quad_create(MC_GOF_QUAD_LIMIT);
    int status = rp && box && big ? 0 : -1;
    if (status == 0 && m > 0)
        status = refine(c, pp, m, rp, rp + cells, rep);
    for (int k = 0; status == 0 && k < cells; k++) {
        if (!redo[k])
            continue;
        double v = rp[k], e = rp[cells + k];
        /* A cell the refinement finds nearly smooth after all, or where
         * the small workspace succeeded, gets GSL's full workspace, as the
         * harness gives it (the two need not give the same bits). */
        if ((gst[k] == 0 || e <= GSL_RETRY_ERR) && big)
            gst[k] = mc_gof_box_integral(&c->spec, big, box[k].box, &prob[k], &err[k]);
        double d = fabs(prob[k] - v);
        bool gsl_ok = gst[k] == 0 || err[k] <= GSL_TRUSTED_ERR;
        /* Two independent methods that agree within the refinement's
         * estimate: GSL's value stands, and their difference (or GSL's
         * own estimate, if larger) measures its error; the refinement's
         * estimate is loose where the density is singular. Where they
         * disagree beyond it, one of them missed something: the
         * refinement's value stands, and the difference joins its error. */
        if (gsl_ok && d <= fmax(e, GSL_TRUSTED_ERR)) {
            e = fmax(err[k], d);
        } else {
            prob[k] = v;
            if (gsl_ok)
                e += d;
        }
        err[k] = e;
    }
    free(rp);
    free(box);
    mc_quad_destroy(big);
    free(redo);
    free(gst);
    return status;
}

int chk_cell_probs(mcbox_check *c, double *prob, chk_quad_report *rep)
{
    int cells = c->chart_cells;
    memset(rep, 0, sizeof *rep);
    rep->missed_cell = -1;
    int *all = malloc((size_t)cells * sizeof *all);
    double *err = malloc((size_t)cells * sizeof *err);
    part *parts = NULL;
    int status = all && err ? 0 : -1;
    for (int k = 0; status == 0 && k < cells; k++)
        all[k] = k;
    if (status == 0 && !(parts = first_parts(c, all, (size_t)cells, rep)))
        status = -1;
    if (status == 0 && c->s.pdf) {
        status = pointwise_probs(c, &parts, prob, err, rep);
    } else if (status == 0) {
        status = refine(c, &parts, (size_t)cells, prob, err, rep);
    }
    double total = 0.0;
    for (int k = 0; status == 0 && k < cells; k++)
        total += isnan(err[k]) ? 0.0 : err[k];
    rep->error = total;
    free(all);
    free(err);
    free(parts);
    return status;
}
