/* check/chart.c - the chart in which the check histograms a user's points:
 * a rectangle of coordinates in which the domain's measure is a known
 * density (catalog/catalog.h), so that the expected count of a cell is the
 * integral of the user's density times the chart's Jacobian over it. */
#include "check/internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/constants.h"
#include "pdf/chart.h"

/* A planar point may cross the triangle's hypotenuse by round-off. */
#define PLANAR_SLACK (4.0 * DBL_EPSILON)
/* A direction may fall outside a cap by round-off in its cosine. */
#define CAP_SLACK 1e-12

/* The user's density as the catalog's charts call it. */
static double user_density(const double x[3], void *ctx)
{
    const mcbox_check *c = ctx;
    return c->s.pdf(x, c->s.ctx);
}

static vec3 vec_of(const double v[3])
{
    return vec3_make(v[0], v[1], v[2]);
}

static bool finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

bool chk_masked(const mcbox_check *c, const double p[2])
{
    return c->s.domain.kind == MCBOX_TRIANGLE && !(p[0] + p[1] <= 1.0);
}

double chk_chart_density(const double p[2], void *ctx)
{
    const mcbox_check *c = ctx;
    if (chk_masked(c, p))
        return 0.0;
    return cat_chart_density_of(&c->st, p, user_density, ctx);
}

bool chk_directions(const mcbox_check *c)
{
    switch (c->s.domain.kind) {
    case MCBOX_SPHERE:
    case MCBOX_HEMISPHERE:
    case MCBOX_CAP:
    case MCBOX_SPHERICAL_TRIANGLE:
    case MCBOX_SPHERICAL_QUAD: return true;
    case MCBOX_CATALOG: return c->st.row && c->st.row->point == CAT_DIRECTION;
    default: return false;
    }
}

/* The lobe chart's axis: the option's, else the cap's, else +z. */
static vec3 lobe_axis(const mcbox_check *c)
{
    const double *a = c->o.lobe_axis;
    if (a[0] != 0.0 || a[1] != 0.0 || a[2] != 0.0)
        return vec_of(a);
    if (c->s.domain.kind == MCBOX_CAP)
        return vec_of(c->s.domain.axis);
    return vec3_make(0.0, 0.0, 1.0);
}

/* The domain's own chart for the kinds that need geometry: a cap is
 * (cos theta, phi) about its axis down to its rim; a spherical polygon is
 * its own coordinates, so that its edges are cell edges. */
static bool geometric_chart(mcbox_check *c, char *err, size_t errlen)
{
    const mcbox_domain *d = &c->s.domain;
    if (d->kind == MCBOX_CAP) {
        if (!finite3(d->axis) || vec3_length(vec_of(d->axis)) == 0.0) {
            snprintf(err, errlen, "the cap's axis must be a finite nonzero vector");
            return false;
        }
        if (!(d->cos_max >= -1.0 && d->cos_max < 1.0)) {
            snprintf(err, errlen, "the cap's cos_max %g is not in [-1, 1)", d->cos_max);
            return false;
        }
        c->row.chart = CAT_CHART_DIRECTION;
        c->row.lo = d->cos_max;
        return true;
    }
    bool triangle = d->kind == MCBOX_SPHERICAL_TRIANGLE;
    for (int k = 0; k < 3; k++)
        if (!finite3(d->vertex[k])) {
            snprintf(err, errlen, "the polygon's vertex[%d] is not finite", k);
            return false;
        }
    vec3 a = vec_of(d->vertex[0]), e1 = vec_of(d->vertex[1]), e2 = vec_of(d->vertex[2]);
    if (triangle)
        e1 = vec3_sub(vec_of(d->vertex[1]), a), e2 = vec3_sub(vec_of(d->vertex[2]), vec_of(d->vertex[1]));
    vec3 n = vec3_cross(e1, e2);
    double nl = vec3_length(n);
    /* The plane must miss the origin, or the polygon is seen edge on. */
    if (!(nl > 0.0) || !(fabs(vec3_dot(n, a)) > 1e-9 * nl * vec3_length(a))) {
        snprintf(err, errlen, "the %s is degenerate or its plane passes through the origin",
                 triangle ? "triangle" : "parallelogram");
        return false;
    }
    c->row.chart = CAT_CHART_POLYGON;
    cat_use_polygon_chart(&c->st, triangle, a, e1, e2);
    return true;
}

bool chk_make_chart(mcbox_check *c, char *err, size_t errlen)
{
    const mcbox_domain *d = &c->s.domain;
    memset(&c->row, 0, sizeof c->row);
    double lw = c->o.lobe_width;
    const double *la = c->o.lobe_axis;
    bool rotated = la[0] != 0.0 || la[1] != 0.0 || la[2] != 0.0;
    if (rotated && (!finite3(la) || vec3_length(vec_of(la)) == 0.0)) {
        snprintf(err, errlen, "lobe_axis must be finite");
        return false;
    }
    if (d->kind == MCBOX_CATALOG) {
        const cat_row *r = d->row ? cat_find(d->row) : NULL;
        if (!r) {
            snprintf(err, errlen, "no row '%s' in the sampler catalog", d->row ? d->row : "(null)");
            return false;
        }
        cat_case cs = {r->name, d->params, {0, 0}, rotated ? 0.0 : lw, 0u, 0};
        if (!cat_prepare_case(r, &cs, &c->st, err, errlen))
            return false;
        if (rotated && lw > 0.0) {
            if (r->point != CAT_DIRECTION) {
                snprintf(err, errlen, "a lobe chart needs a row of directions");
                return false;
            }
            cat_use_lobe_chart_about(&c->st, lw, vec_of(la), MC_PI);
        }
        return true;
    }
    memset(&c->st, 0, sizeof c->st);
    c->row.name = mcbox_domain_name(d->kind);
    c->row.hi = 1.0;
    switch (d->kind) {
    case MCBOX_INTERVAL:
        if (!(isfinite(d->a) && isfinite(d->b) && d->a < d->b)) {
            snprintf(err, errlen, "the interval [%g, %g] is not finite with a < b", d->a, d->b);
            return false;
        }
        c->row.chart = CAT_CHART_LINE, c->row.lo = d->a, c->row.hi = d->b;
        break;
    case MCBOX_SQUARE:
    case MCBOX_TRIANGLE: c->row.chart = CAT_CHART_XY; break;
    case MCBOX_DISC: c->row.chart = CAT_CHART_DISC; break;
    case MCBOX_SPHERE:
    case MCBOX_HEMISPHERE:
        c->row.chart = CAT_CHART_DIRECTION;
        c->row.lo = d->kind == MCBOX_SPHERE ? -1.0 : 0.0;
        break;
    case MCBOX_CAP:
    case MCBOX_SPHERICAL_TRIANGLE:
    case MCBOX_SPHERICAL_QUAD:
        if (!geometric_chart(c, err, errlen))
            return false;
        break;
    default: snprintf(err, errlen, "unknown domain kind %d", (int)d->kind); return false;
    }
    c->st.row = &c->row;
    c->st.chart = c->row.chart;
    if (c->row.chart == CAT_CHART_DIRECTION) {
        vec3 axis = d->kind == MCBOX_CAP ? vec_of(d->axis) : vec3_make(0.0, 0.0, 1.0);
        c->st.dir_chart = pdf_chart_spherical(axis, c->row.lo);
    }
    if (lw > 0.0) {
        if (!chk_directions(c)) {
            snprintf(err, errlen, "a lobe chart needs a domain of directions");
            return false;
        }
        /* About the domain's own axis the chart ends at the domain's rim;
         * about any other axis it covers the whole sphere, and the
         * density is 0 in the cells outside the domain. */
        double theta_max = MC_PI;
        if (!rotated && d->kind == MCBOX_HEMISPHERE)
            theta_max = MC_PI_2;
        else if (!rotated && d->kind == MCBOX_CAP)
            theta_max = acos(d->cos_max);
        cat_use_lobe_chart_about(&c->st, lw, lobe_axis(c), theta_max);
    }
    return true;
}

static bool unit(const double x[3])
{
    return fabs(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1.0) <= CHK_UNIT_TOL;
}

bool chk_in_domain(const mcbox_check *c, const double x[3])
{
    const mcbox_domain *d = &c->s.domain;
    switch (d->kind) {
    case MCBOX_TRIANGLE: return x[0] >= 0.0 && x[1] >= 0.0 && x[0] + x[1] <= 1.0 + PLANAR_SLACK;
    case MCBOX_SPHERE:
    case MCBOX_SPHERICAL_TRIANGLE:
    case MCBOX_SPHERICAL_QUAD: return unit(x);
    case MCBOX_HEMISPHERE: return unit(x) && x[2] >= -CAP_SLACK;
    case MCBOX_CAP: {
        vec3 a = vec3_normalize(vec_of(d->axis));
        return unit(x) && vec3_dot(a, vec_of(x)) >= d->cos_max - CAP_SLACK;
    }
    case MCBOX_CATALOG: {
        const cat_row *r = c->st.row;
        if (r->point == CAT_DIRECTION && !unit(x))
            return false;
        return r->in_support ? r->in_support(&c->st, x) : true;
    }
    default: return true;
    }
}

static const char *const lobe_labels[2] = {"theta / (theta + w)", "phi"};

void chk_chart_labels(const mcbox_check *c, char *x, char *y, size_t size)
{
    const char *lx = "x", *ly = "y";
    switch (c->st.chart) {
    case CAT_CHART_LINE: lx = "x", ly = ""; break;
    case CAT_CHART_INDEX: lx = "outcome + 1/2", ly = ""; break;
    case CAT_CHART_XY: break;
    case CAT_CHART_DISC: lx = "r^2", ly = "phi"; break;
    case CAT_CHART_PARALLELOGRAM:
    case CAT_CHART_POLYGON: lx = "a", ly = "b"; break;
    case CAT_CHART_SURFACE: lx = "cos theta", ly = "phi"; break;
    case CAT_CHART_DIRECTION:
        if (c->st.dir_chart.kind == PDF_CHART_SPHERICAL)
            lx = "cos theta", ly = "phi";
        else
            lx = "chart x", ly = "chart y";
        break;
    case CAT_CHART_LOBE: lx = lobe_labels[0], ly = lobe_labels[1]; break;
    }
    snprintf(x, size, "%s", lx);
    snprintf(y, size, "%s", ly);
}

void chk_describe_cell(const mcbox_check *c, int k, char *buf, size_t size)
{
    if (k >= c->chart_cells) {
        snprintf(buf, size, "atom %d", k - c->chart_cells);
        return;
    }
    double b[4];
    mc_gof_cell_box(&c->spec, k, b);
    if (c->spec.dims == 2)
        snprintf(buf, size, "cell [%.4g, %.4g] x [%.4g, %.4g] of the chart", b[0], b[1], b[2], b[3]);
    else
        snprintf(buf, size, "cell [%.4g, %.4g] of the chart", b[0], b[1]);
}

void chk_coords(const mcbox_check *c, const double x[3], char *buf, size_t size)
{
    if (c->dims == 1)
        snprintf(buf, size, "(%.9g)", x[0]);
    else if (c->dims == 2)
        snprintf(buf, size, "(%.9g, %.9g)", x[0], x[1]);
    else
        snprintf(buf, size, "(%.9g, %.9g, %.9g)", x[0], x[1], x[2]);
}
