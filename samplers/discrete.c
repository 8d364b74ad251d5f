/* samplers/discrete.c - CDF table with binary search, and Vose's alias
 * table, both in caller storage. */
#include "samplers/discrete.h"

#include <math.h>

/* The sum of the weights, or a value <= 0 when any weight is negative or
 * not finite (so the callers reject the input with one test). */
static double weight_sum(const double *w, size_t n)
{
    double sum = 0.0;
    for (size_t k = 0; k < n; k++) {
        if (!(w[k] >= 0.0) || !isfinite(w[k]))
            return -1.0;
        sum += w[k];
    }
    return isfinite(sum) ? sum : -1.0;
}

/* --- CDF table --------------------------------------------------------- */

/* BEGIN SNIPPET cdf_table_init */
bool smp_discrete_cdf_init(smp_discrete_cdf *d, const double *weights, size_t n, double *storage)
{
    double sum = n > 0 ? weight_sum(weights, n) : -1.0;
    if (!(sum > 0.0))
        return false;
    /* The running sum divided once at each step (not a running sum of
     * rounded p_k) keeps cdf monotone; from the last positive weight on it
     * is set to exactly 1, so u < 1 can never land on a trailing zero-weight
     * event through a final cdf of 0.9999999999999999. */
    size_t last = 0;
    double acc = 0.0;
    for (size_t k = 0; k < n; k++) {
        acc += weights[k];
        storage[k] = acc / sum;
        if (weights[k] > 0.0)
            last = k;
    }
    for (size_t k = last; k < n; k++)
        storage[k] = 1.0;
    d->cdf = storage;
    d->n = n;
    return true;
}
/* END SNIPPET cdf_table_init */

/* BEGIN SNIPPET cdf_table_sample */
size_t smp_discrete_cdf_sample(const smp_discrete_cdf *d, double u, double *u_remapped)
{
    /* Invariant: the answer lies in [lo, hi]; cdf[n-1] = 1 > u. Ties
     * u == cdf[k] go to the right, so an event of weight 0 (cdf[k] ==
     * cdf[k-1]) is never the smallest k with u < cdf[k]. */
    size_t lo = 0, hi = d->n - 1;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (u < d->cdf[mid])
            hi = mid;
        else
            lo = mid + 1;
    }
    if (u_remapped) {
        double below = lo > 0 ? d->cdf[lo - 1] : 0.0;
        double r = (u - below) / (d->cdf[lo] - below);
        *u_remapped = r < 1.0 ? (r > 0.0 ? r : 0.0) : nextafter(1.0, 0.0);
    }
    return lo;
}
/* END SNIPPET cdf_table_sample */

double smp_discrete_cdf_pmf(const smp_discrete_cdf *d, size_t k)
{
    if (k >= d->n)
        return 0.0;
    return k > 0 ? d->cdf[k] - d->cdf[k - 1] : d->cdf[0];
}

double smp_discrete_cdf_invert(const smp_discrete_cdf *d, size_t k, double r)
{
    double below = k > 0 ? d->cdf[k - 1] : 0.0;
    return below + r * (d->cdf[k] - below);
}

/* --- alias table ------------------------------------------------------- */

/* Vose's construction keeps two work lists, "small" (scaled probability
 * q = n p < 1) and "large" (q >= 1). Each index is on at most one list at a
 * time and an index's alias field is only written when it leaves the lists
 * for good, so the lists are threaded through the alias fields themselves:
 * no scratch memory. `none` marks the end of a list. */
static void push(smp_alias_cell *c, size_t *head, size_t k)
{
    c[k].alias = *head;
    *head = k;
}

static size_t pop(smp_alias_cell *c, size_t *head)
{
    size_t k = *head;
    *head = c[k].alias;
    return k;
}

bool smp_alias_init(smp_alias *a, const double *weights, size_t n, smp_alias_cell *storage)
{
    double sum = n > 0 ? weight_sum(weights, n) : -1.0;
    if (!(sum > 0.0))
        return false;
    /* BEGIN SNIPPET alias_build */
    smp_alias_cell *c = storage;
    const size_t none = n;
    size_t small = none, large = none, positive = 0;
    for (size_t k = 0; k < n; k++) {
        c[k].pmf = weights[k] / sum;
        if (c[k].pmf > 0.0)
            positive = k;
        c[k].threshold = c[k].pmf * (double)n; /* q_k while building */
        push(c, c[k].threshold < 1.0 ? &small : &large, k);
    }
    /* A small column s is topped up to 1 by a large one l, which gives away
     * 1 - q_s; Vose computes the remainder as (q_l + q_s) - 1, which loses
     * less than q_l - (1 - q_s). */
    while (small != none && large != none) {
        size_t s = pop(c, &small), l = pop(c, &large);
        c[s].alias = l;
        c[l].threshold = (c[l].threshold + c[s].threshold) - 1.0;
        push(c, c[l].threshold < 1.0 ? &small : &large, l);
    }
    /* What is left is full up to rounding: its columns keep their event.
     * The q of the active columns always sum to their count (up to
     * rounding), so a zero-weight column, 1 short, cannot be left over;
     * should rounding ever leave one, it points at a positive event. */
    while (large != none) {
        size_t l = pop(c, &large);
        c[l].threshold = 1.0;
        c[l].alias = l;
    }
    while (small != none) {
        size_t s = pop(c, &small);
        c[s].threshold = c[s].pmf > 0.0 ? 1.0 : 0.0;
        c[s].alias = c[s].pmf > 0.0 ? s : positive;
    }
    /* END SNIPPET alias_build */
    a->cells = c;
    a->n = n;
    return true;
}

/* BEGIN SNIPPET alias_sample */
size_t smp_alias_sample(const smp_alias *a, double u, double *u_remapped)
{
    double un = u * (double)a->n;
    size_t k = (size_t)un;
    if (k >= a->n) /* u within rounding of 1 */
        k = a->n - 1;
    double f = un - (double)k; /* uniform in [0, 1) given the column */
    const smp_alias_cell *c = &a->cells[k];
    bool keep = f < c->threshold;
    if (u_remapped) {
        double r = keep ? f / c->threshold : (f - c->threshold) / (1.0 - c->threshold);
        *u_remapped = r < 1.0 ? (r > 0.0 ? r : 0.0) : nextafter(1.0, 0.0);
    }
    return keep ? k : c->alias;
}
/* END SNIPPET alias_sample */

double smp_alias_pmf(const smp_alias *a, size_t k)
{
    return k < a->n ? a->cells[k].pmf : 0.0;
}
