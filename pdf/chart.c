/* pdf/chart.c - the three charts, their Jacobians and their quadrature. */
#include "pdf/chart.h"

#include <math.h>
#include <string.h>

#include "mc/constants.h"
#include "pdf/pdf.h"
#include "samplers/cone.h"
#include "samplers/planar.h"
#include "samplers/spherical.h"

/* Slack on a cone's rim in cos theta when a direction is classified as
 * in the cap: a direction generated on the rim comes back a few 1e-16
 * outside after the round trip through an ONB, and the chart's frame
 * (built from the normalized axis) need not be the pdf's to the last bit.
 * Deliberately looser than PDF_CONE_RIM_TOL: that one widens the support
 * of a density and so changes its integral, while this one only decides
 * which chart cell a generated sample falls in (clamped to the cap's
 * rectangle), so a looser value costs nothing and can never drop a sample
 * that value() accepts. The edge slack, by contrast, is PDF_QUAD_EDGE_TOL
 * itself: a direction goes to the quad's cells exactly when value() counts
 * it as hitting the quad. */
#define RIM_TOL 1e-12
/* Halvings toward a singular corner: leaves a corner square of side 2^-40
 * (1e-12), whose mass is far below any tolerance of the callers. */
#define CORNER_LEVELS 40

pdf_chart pdf_chart_spherical(vec3 axis, double cos_lo)
{
    pdf_chart c;
    memset(&c, 0, sizeof c);
    c.kind = PDF_CHART_SPHERICAL;
    c.frame = onb_from_w(vec3_normalize(axis));
    c.cos_lo = cos_lo;
    c.one_minus_cos_lo = 1.0 - cos_lo;
    return c;
}

pdf_chart pdf_chart_light_plane(vec3 origin, vec3 corner, vec3 u, vec3 v)
{
    pdf_chart c;
    memset(&c, 0, sizeof c);
    c.kind = PDF_CHART_LIGHT_PLANE;
    vec3 n = vec3_normalize(vec3_cross(u, v));
    c.toward = vec3_dot(n, vec3_sub(corner, origin)) > 0.0 ? n : vec3_neg(n);
    c.frame = onb_from_w(c.toward);
    c.origin = origin, c.corner = corner, c.u = u, c.v = v;
    return c;
}

pdf_chart pdf_chart_quad_and_cap(vec3 origin, vec3 corner, vec3 u, vec3 v, vec3 center,
                                 double radius)
{
    pdf_chart c = pdf_chart_light_plane(origin, corner, u, v);
    vec3 axis = vec3_sub(center, origin);
    c.kind = PDF_CHART_QUAD_AND_CAP;
    c.frame = onb_from_w(vec3_normalize(axis));
    c.one_minus_cos_lo = smp_sphere_cone_cap(vec3_length_sq(axis), radius, &c.cos_lo);
    return c;
}

void pdf_chart_rect(const pdf_chart *c, double lo[2], double hi[2])
{
    switch (c->kind) {
    case PDF_CHART_SPHERICAL:
        lo[0] = c->cos_lo, hi[0] = 1.0, lo[1] = 0.0, hi[1] = MC_2PI;
        return;
    case PDF_CHART_LIGHT_PLANE:
        lo[0] = -1.0, hi[0] = 3.0, lo[1] = -1.0, hi[1] = 2.0;
        return;
    case PDF_CHART_QUAD_AND_CAP:
        lo[0] = 0.0, hi[0] = 2.0, lo[1] = 0.0, hi[1] = 1.0;
        return;
    }
}

/* s = stretch(a): the identity on [0, 1]; beyond, with the excess e = a - 1
 * (or a below 0), s = 1 + tan(pi e / 2) / (pi / 2) (or tan(pi a / 2) /
 * (pi / 2)), so that a in (-1, 2) covers the whole line and the derivative
 * ds/da = sec^2(pi e / 2) is continuous (1 at both joints). */
static double stretch(double a, double *ds_da)
{
    double e = a < 0.0 ? a : (a > 1.0 ? a - 1.0 : 0.0);
    if (e == 0.0) {
        *ds_da = 1.0;
        return a;
    }
    double cs = cos(MC_PI_2 * e);
    *ds_da = 1.0 / (cs * cs);
    return (a < 0.0 ? 0.0 : 1.0) + tan(MC_PI_2 * e) / MC_PI_2;
}

static double unstretch(double s)
{
    if (s < 0.0)
        return atan(s * MC_PI_2) / MC_PI_2;
    if (s > 1.0)
        return 1.0 + atan((s - 1.0) * MC_PI_2) / MC_PI_2;
    return s;
}

/* The direction from origin to the plane point corner + s u + t v, and the
 * solid angle per unit (s, t) there: the normalized direction changes by
 * u_perp / r per unit s (u_perp = u without its component along the
 * direction), so d omega = |u_perp x v_perp| / r^2 ds dt. That is the
 * |cos| A / r^2 of Shirley, "Ray Tracing: The Rest of Your Life" (v1.123),
 * chapter 7 (this book's #ch-lights), derived a second way, as a check on
 * pdf.c. */
static vec3 plane_direction(const pdf_chart *c, double s, double t, double *jac)
{
    vec3 to = vec3_sub(vec3_madd(vec3_madd(c->corner, c->u, s), c->v, t), c->origin);
    double r = vec3_length(to);
    vec3 d = vec3_scale(to, 1.0 / r);
    vec3 up = vec3_madd(c->u, d, -vec3_dot(d, c->u));
    vec3 vp = vec3_madd(c->v, d, -vec3_dot(d, c->v));
    *jac = vec3_length(vec3_cross(up, vp)) / (r * r);
    return d;
}

/* The edge coordinates where the ray origin + r d, r > 0, meets the plane;
 * false when it does not. */
static bool plane_coords(const pdf_chart *c, vec3 d, double *s, double *t)
{
    double along = vec3_dot(d, c->toward);
    if (!(along > 0.0))
        return false;
    double r = vec3_dot(vec3_sub(c->corner, c->origin), c->toward) / along;
    vec2 st = smp_parallelogram_invert(vec3_madd(c->origin, d, r), c->corner, c->u, c->v);
    *s = st.x, *t = st.y;
    return isfinite(st.x) && isfinite(st.y);
}

vec3 pdf_chart_direction(const pdf_chart *c, const double x[2], double *jacobian)
{
    switch (c->kind) {
    case PDF_CHART_SPHERICAL:
        *jacobian = 1.0;
        return onb_to_world(&c->frame, smp_spherical_direction(x[0], x[1]));
    case PDF_CHART_LIGHT_PLANE:
        if (x[0] < 2.0) {
            double ds, dt, j;
            double s = stretch(x[0], &ds), t = stretch(x[1], &dt);
            vec3 d = plane_direction(c, s, t, &j);
            *jacobian = j * ds * dt;
            return d;
        }
        /* Behind the plane: cos theta = x - 3 in [-1, 0] about the normal
         * toward it, phi = 2 pi (y + 1) / 3, so d omega = (2 pi / 3) dx dy. */
        *jacobian = MC_2PI / 3.0;
        return onb_to_world(&c->frame,
                            smp_spherical_direction(x[0] - 3.0, MC_2PI * (x[1] + 1.0) / 3.0));
    case PDF_CHART_QUAD_AND_CAP:
        if (x[0] < 1.0)
            return plane_direction(c, x[0], x[1], jacobian);
        /* 1 - cos theta = (x - 1) h, phi = 2 pi y: the cap sampler's own
         * map with (u1, u2) = (y, x - 1), d omega = 2 pi h dx dy. */
        *jacobian = MC_2PI * c->one_minus_cos_lo;
        return onb_to_world(&c->frame,
                            smp_uniform_cap_sample(x[1], x[0] - 1.0, c->one_minus_cos_lo));
    }
    *jacobian = 0.0;
    return vec3_make(0.0, 0.0, 1.0);
}

void pdf_chart_point(const pdf_chart *c, vec3 d, double x[2])
{
    double s, t;
    vec3 local = onb_to_local(&c->frame, d);
    x[0] = (double)NAN, x[1] = 0.0;
    switch (c->kind) {
    case PDF_CHART_SPHERICAL:
        x[0] = local.z, x[1] = smp_spherical_phi(local);
        return;
    case PDF_CHART_LIGHT_PLANE:
        if (plane_coords(c, d, &s, &t))
            x[0] = unstretch(s), x[1] = unstretch(t);
        else
            x[0] = 3.0 + local.z, x[1] = 3.0 * smp_spherical_phi(local) / MC_2PI - 1.0;
        return;
    case PDF_CHART_QUAD_AND_CAP:
        if (plane_coords(c, d, &s, &t) && s >= -PDF_QUAD_EDGE_TOL && s <= 1.0 + PDF_QUAD_EDGE_TOL &&
            t >= -PDF_QUAD_EDGE_TOL && t <= 1.0 + PDF_QUAD_EDGE_TOL) {
            x[0] = fmin(fmax(s, 0.0), 1.0), x[1] = fmin(fmax(t, 0.0), 1.0);
        } else if (local.z >= c->cos_lo - RIM_TOL) {
            vec2 cap = smp_uniform_cap_invert(local, c->one_minus_cos_lo);
            x[0] = fmin(1.0 + cap.y, 2.0), x[1] = cap.x;
        }
        return;
    }
}

typedef struct integrand {
    const pdf_chart *c;
    double (*f)(vec3 d, void *ctx);
    void *ctx;
} integrand;

static double chart_density(double x0, double x1, void *params)
{
    const integrand *in = params;
    const double x[2] = {x0, x1};
    double jac;
    vec3 d = pdf_chart_direction(in->c, x, &jac);
    return jac > 0.0 ? in->f(d, in->ctx) * jac : 0.0;
}

static double quad_box(mc_quad *q, mc_fn2 fn, double x0, double x1, double y0, double y1)
{
    double v = 0.0;
    /* A status means the 1e-11 target was not certified; the best value is
     * still accurate far beyond what a histogram or a 1e-6 check needs. */
    (void)mc_quad_2d(q, fn, fmin(x0, x1), fmax(x0, x1), fmin(y0, y1), fmax(y0, y1), &v, NULL);
    return v;
}

/* The unit square whose corner (cx, cy) is a corner of the light-plane
 * chart: as s and t both run to infinity, a whole arc of the plane's
 * horizon crowds into that point, and a kink of the density along the arc
 * (a cosine lobe's own horizon crossing it) makes one adaptive rule over
 * the square miss mass in proportion to the square's size (5e-6 for a
 * unit square in the tests). Cut it into the corner square of half the
 * side and three others, again and again. */
static double corner_square(mc_quad *q, mc_fn2 fn, double cx, double cy)
{
    double sx = cx < 0.0 ? 1.0 : -1.0, sy = cy < 0.0 ? 1.0 : -1.0; /* inward */
    double total = 0.0, h = 1.0;
    for (int level = 0; level < CORNER_LEVELS; level++, h /= 2.0) {
        double mx = cx + sx * h / 2.0, my = cy + sy * h / 2.0;
        double fx = cx + sx * h, fy = cy + sy * h;
        total += quad_box(q, fn, mx, fx, cy, my) + quad_box(q, fn, mx, fx, my, fy) +
                 quad_box(q, fn, cx, mx, my, fy);
    }
    return total;
}

double pdf_chart_integrate(const pdf_chart *c, double (*f)(vec3 d, void *ctx), void *ctx,
                           mc_quad *q)
{
    integrand in = {c, f, ctx};
    mc_fn2 fn = {chart_density, &in};
    double total = 0.0;
    switch (c->kind) {
    case PDF_CHART_SPHERICAL:
        /* Lobes about the axis have their horizon (a kink) at cos = 0. */
        if (c->cos_lo < 0.0)
            total += quad_box(q, fn, c->cos_lo, 0.0, 0.0, MC_2PI);
        return total + quad_box(q, fn, fmax(c->cos_lo, 0.0), 1.0, 0.0, MC_2PI);
    case PDF_CHART_LIGHT_PLANE:
        for (int i = -1; i < 3; i++)
            for (int j = -1; j < 2; j++) {
                bool corner = (i == -1 || i == 1) && (j == -1 || j == 1);
                if (corner)
                    total += corner_square(q, fn, i == -1 ? -1.0 : 2.0, j == -1 ? -1.0 : 2.0);
                else
                    total += quad_box(q, fn, i, i + 1.0, j, j + 1.0);
            }
        return total;
    case PDF_CHART_QUAD_AND_CAP:
        return quad_box(q, fn, 0.0, 1.0, 0.0, 1.0) + quad_box(q, fn, 1.0, 2.0, 0.0, 1.0);
    }
    return (double)NAN;
}
