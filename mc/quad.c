/* mc/quad.c - GSL QAGS in one dimension and nested in two. */
#include "mc/quad.h"

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_integration.h>

#include "mc/gsl_quiet.h"

struct mc_quad {
    size_t limit;
    gsl_integration_workspace *outer;
    gsl_integration_workspace *inner; /* the nested 2D rule needs its own */
};

mc_quad *mc_quad_create(size_t limit)
{
    /* The library must report, not abort: every GSL call made through q
     * comes after GSL's handler is off (once, not per thread: it is a
     * global). */
    mc_gsl_quiet();
    mc_quad *q = malloc(sizeof *q);
    if (!q)
        return NULL;
    q->limit = limit;
    q->outer = gsl_integration_workspace_alloc(limit);
    q->inner = gsl_integration_workspace_alloc(limit);
    if (!q->outer || !q->inner) {
        mc_quad_destroy(q);
        return NULL;
    }
    return q;
}

void mc_quad_destroy(mc_quad *q)
{
    if (!q)
        return;
    if (q->outer)
        gsl_integration_workspace_free(q->outer);
    if (q->inner)
        gsl_integration_workspace_free(q->inner);
    free(q);
}

static double call_fn1(double x, void *params)
{
    const mc_fn1 *fn = params;
    return fn->f(x, fn->params);
}

static int qags(gsl_integration_workspace *w, size_t limit, mc_fn1 fn, double a, double b,
                double *result, double *abserr)
{
    gsl_function g = {call_fn1, &fn};
    double err = 0.0;
    int status = gsl_integration_qags(&g, a, b, MC_QUAD_EPSABS, MC_QUAD_EPSREL, limit, w, result, &err);
    if (abserr)
        *abserr = err;
    return status;
}

int mc_quad_1d(mc_quad *q, mc_fn1 fn, double a, double b, double *result, double *abserr)
{
    return qags(q->outer, q->limit, fn, a, b, result, abserr);
}

/* State of the nested 2D rule: the outer integrand is x -> inner(x). */
typedef struct nested {
    mc_quad *q;
    mc_fn2 fn;
    double y0, y1;
    double x;          /* the outer abscissa being evaluated */
    double inner_err;  /* largest inner error estimate seen */
    int status;        /* first failing inner status, or 0 */
} nested;

/* BEGIN SNIPPET quad_nested_2d */
static double inner_integrand(double y, void *params)
{
    nested *s = params;
    return s->fn.f(s->x, y, s->fn.params);
}

static double outer_integrand(double x, void *params)
{
    nested *s = params;
    double value = 0.0, err = 0.0;
    s->x = x;
    mc_fn1 inner = {inner_integrand, s};
    int status = qags(s->q->inner, s->q->limit, inner, s->y0, s->y1, &value, &err);
    if (status && !s->status)
        s->status = status;
    if (err > s->inner_err)
        s->inner_err = err;
    return value;
}

int mc_quad_2d(mc_quad *q, mc_fn2 fn, double x0, double x1, double y0, double y1, double *result,
               double *abserr)
{
    nested s = {q, fn, y0, y1, 0.0, 0.0, 0};
    double err = 0.0;
    mc_fn1 outer = {outer_integrand, &s};
    int status = qags(q->outer, q->limit, outer, x0, x1, result, &err);
    if (abserr)
        *abserr = err + s.inner_err * fabs(x1 - x0);
    return status ? status : s.status;
}
/* END SNIPPET quad_nested_2d */

int mc_quad_gauss_legendre(int n, double a, double b, double *x, double *w)
{
    mc_gsl_quiet();
    gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc((size_t)n);
    if (!t)
        return -1;
    for (int i = 0; i < n; i++)
        gsl_integration_glfixed_point(a, b, (size_t)i, &x[i], &w[i], t);
    gsl_integration_glfixed_table_free(t);
    return 0;
}
