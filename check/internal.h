/* check/internal.h - inside mcbox only: the state of one check of a
 * user's sampler, shared by the check's parts: check.c (the samples),
 * chart.c (the chart of the domain), quadrature.c (the cells'
 * probabilities and how sure they are) and verdict.c (the verdict and
 * what a pass proves). Not installed. */
#ifndef CHK_INTERNAL_H
#define CHK_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "mc/gof.h"
#include "mc/rng.h"

/* Directions must be unit vectors to within this (relative): a sampler
 * computing in single precision is still on the sphere. */
#define CHK_UNIT_TOL 1e-6
/* Points per call of pdf_batch. */
#define CHK_BATCH 4096
/* The check keeps the point of the first sample in each chart cell (to
 * ask the density there when the quadrature finds a cell empty) for charts
 * of at most this many cells. */
#define CHK_HINT_MAX_CELLS (1 << 20)

struct mcbox_check {
    mcbox_sampler s;
    mcbox_check_options o;
    int dims;
    /* The chart: a catalog state, either a row's (MCBOX_CATALOG) or one
     * made here for a basic domain around a copy of a row that only gives
     * its chart kind and interval; the density is always the user's. */
    cat_row row;
    cat_state st;
    mc_gof_spec spec;
    int chart_cells;
    mc_rng rng;
    double *obs;    /* chart cells, then atoms */
    double *hint_x; /* per chart cell: the first sample's point there (dims doubles), or NaN */
    uint64_t n;     /* samples added */
    mcbox_check_result r;
    /* Worst cases, for the message. */
    uint64_t first_nonfinite, first_outside, first_bad_atom, first_bad_pdf, worst_pdf_at,
        worst_weight_at, worst_invert_at;
    double bad_pdf_value;
    double example[3];
    double rep_pdf, cb_pdf;
    double sum_weight;
    double sum_dir[3]; /* the sum of the direction samples, for the lobe hint */
    bool invalid;
    char invalid_msg[200];
};

/* --- chart.c ------------------------------------------------------------- */

/* Sets up c->row and c->st, the chart of c->s.domain; false with a message
 * otherwise. */
bool chk_make_chart(mcbox_check *c, char *err, size_t errlen);

/* Whether the chart point p lies outside the domain (beyond the
 * triangle's hypotenuse): the density is 0 there whatever the user's
 * function says. */
bool chk_masked(const mcbox_check *c, const double p[2]);

/* The chart's density at p: the user's density times the Jacobian. */
double chk_chart_density(const double p[2], void *ctx);

/* Whether a finite point lies in the domain (the chart's rectangle is
 * checked by the histogram). */
bool chk_in_domain(const mcbox_check *c, const double x[3]);

/* Whether the domain's points are directions. */
bool chk_directions(const mcbox_check *c);

/* The chart's coordinate names, a cell and a point as the messages write
 * them. */
void chk_chart_labels(const mcbox_check *c, char *x, char *y, size_t size);
void chk_describe_cell(const mcbox_check *c, int k, char *buf, size_t size);
void chk_coords(const mcbox_check *c, const double x[3], char *buf, size_t size);

/* --- quadrature.c -------------------------------------------------------- */

/* What the quadrature knows of its answer. */
typedef struct chk_quad_report {
    double error;         /* the estimate of |sum of cell probabilities - the integral| */
    uint64_t evaluations; /* densities asked for */
    int missed_cell;      /* a cell that integrates to 0 though a sample in it has a
                             positive density, after refinement; -1 if none */
    double missed_x[3];
} chk_quad_report;

/* The user's density at n points at(i, src) (NULL: not needed, out[i]
 * left as it is): pdf_batch in batches of CHK_BATCH, or pdf at each.
 * Returns -1 when out of memory. */
typedef const double *(*chk_point_at)(size_t i, const void *src);
int chk_densities(const mcbox_check *c, size_t n, chk_point_at at, const void *src, double *out);

/* Every chart cell's probability under the user's density into
 * prob[0 .. chart_cells) and the quadrature's report. Returns 0, or -1
 * when out of memory. */
int chk_cell_probs(mcbox_check *c, double *prob, chk_quad_report *rep);

/* --- verdict.c ----------------------------------------------------------- */

/* Fills c->r's verdict, message, warning and power from the expected
 * counts expct[0 .. cells) (atoms last), finite_exp (every one finite) and
 * the quadrature's report. */
void chk_verdict(mcbox_check *c, const double *expct, size_t cells, bool finite_exp,
                 const chk_quad_report *q);

/* printf into r->message. */
void chk_set_message(mcbox_check_result *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;


/* --- rules.c: the fixed rules on boxes of the chart --------------------------- */

/* The check rule runs on the box cut in two (1D) or four (2D) unequal
 * pieces, at this fraction of each side. Two rules symmetric about the
 * box's centre both give exactly half the box's mass for any jump lying
 * between their middle nodes, a band a fifth of the cell wide, and so
 * would agree on a wrong value; so would the same rule on equal halves
 * for a jump between their inner nodes. An irrational cut leaves no such
 * band. */
#define CHECK_CUT 0.6180339887498949

/* The quadrature nodes' points; where the chart maps a node to no point
 * (its Jacobian is 0) no density is needed. */
typedef struct chk_nodes {
    const double *pts, *jac;
} chk_nodes;

/* chk_point_at over a chk_nodes: node at's point, NULL where its Jacobian is 0. */
const double *chk_node_point(size_t at, const void *src);
/* The point of chart point p into pt and the chart's Jacobian there; 0
 * (and pt zeroed) where the chart maps p to no point of the domain. */
double chk_chart_node(const mcbox_check *c, const double p[2], double *pt);
/* The tensor Gauss-Legendre rule of n points per axis on the chart box b
 * (x0, x1, y0, y1): points into pts, weights times the Jacobian into jac;
 * returns the nodes written, or 0. */
size_t chk_rule_nodes(const mcbox_check *c, const double b[4], int n, double *pts, double *jac);
/* The rule's sum over nodes [from, from + count); NaN at a negative or
 * non-finite density. */
double chk_rule_sum(const double *jac, const double *vals, size_t from, size_t count);
/* The rules' orders: quad_order and half of it. */
void chk_orders(const mcbox_check *c, int *q, int *h);
/* The pieces a box is cut into: two in 1D, four in 2D; piece k of box b
 * cut at the fraction `cut` of each side. */
int chk_sub_boxes(const mcbox_check *c);
void chk_sub_box(const double b[4], int dims, int k, double cut, double out[4]);
/* The probes per part for a rule of q points, and every density one part
 * asks for (its two rules and its probes). */
size_t chk_probes_of(const mcbox_check *c, int q);
size_t chk_nodes_of(const mcbox_check *c);
/* The probe pairs of box b (a point just inside each side, then the
 * rule's outermost node on the same line); returns the points written. */
size_t chk_probe_nodes(const mcbox_check *c, const double b[4], int q, double *pts, double *jac);
/* The error bound of the sides whose probes show the support's edge. */
double chk_edge_error(const double *jac, const double *vals, size_t from, int dims, int q,
                      const double box[4]);


/* --- check.c, shared with run.c -------------------------------------------- */

/* The stream handed to sample_stream: PCG32, the generator of the
 * uniforms. */
struct mcbox_stream {
    mc_rng rng;
};

/* A result with every figure unset (NaN or 0) and no verdict. */
void chk_fresh_result(mcbox_check_result *r);
/* Whether the options are in range; else the reason in err. */
bool chk_options_valid(const mcbox_check_options *o, char *err, size_t errlen);

#endif /* CHK_INTERNAL_H */
