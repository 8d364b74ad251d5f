/* tests/support/real_samplers.c - the samplers of real_samplers.h, each
 * from its paper; the comments give the step and the Jacobian. */
#define _POSIX_C_SOURCE 200809L /* strtok_r */

#include "tests/support/real_samplers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/rng.h"

static vec3 vec_of(const double x[3])
{
    return vec3_make(x[0], x[1], x[2]);
}

static void put(mcbox_sample *out, vec3 w)
{
    out->x[0] = w.x, out->x[1] = w.y, out->x[2] = w.z;
}

static double clamp1(double x)
{
    return fmax(-1.0, fmin(1.0, x));
}

/* The part of v orthogonal to the unit vector a, normalized. */
static vec3 ortho(vec3 v, vec3 a)
{
    return vec3_normalize(vec3_madd(v, a, -vec3_dot(v, a)));
}

/* --- spherical triangle: Arvo, "Stratified sampling of spherical
 * triangles", SIGGRAPH 1995 [@arvo1995-triangles] -------------------------------------------- */

double rs_triangle_solid_angle(vec3 a, vec3 b, vec3 c)
{
    double det = fabs(vec3_dot(a, vec3_cross(b, c)));
    double den = 1.0 + vec3_dot(a, b) + vec3_dot(b, c) + vec3_dot(c, a);
    return 2.0 * atan2(det, den);
}

/* The angle of the spherical triangle at vertex a (between the great
 * circles ab and ac): the angle of the normals a x b and a x c, whose dot
 * product is b.c - (a.b)(a.c) and whose cross product has length
 * |a . (b x c)| (Lagrange's identities for unit a). */
static double vertex_angle(vec3 a, vec3 b, vec3 c)
{
    double det = fabs(vec3_dot(a, vec3_cross(b, c)));
    return atan2(det, vec3_dot(b, c) - vec3_dot(a, b) * vec3_dot(a, c));
}

/* The shape's vertices are given at any length: their directions. */
static void unit_vertices(const rs_shape *sh, vec3 *a, vec3 *b, vec3 *c)
{
    *a = vec3_normalize(sh->v[0]), *b = vec3_normalize(sh->v[1]), *c = vec3_normalize(sh->v[2]);
}

static double triangle_area(const rs_shape *sh)
{
    vec3 a, b, c;
    unit_vertices(sh, &a, &b, &c);
    /* Girard: the area is the angle excess. */
    return vertex_angle(a, b, c) + vertex_angle(b, c, a) + vertex_angle(c, a, b) - MC_PI;
}

/* Arvo's Figure 2. The first uniform picks the sub-triangle A B C_hat of
 * area u1 times the whole (C_hat on the arc AC), solving the area formula
 * for cos of the arc A C_hat (q); the second picks the point on the arc
 * B C_hat with z = cos(angle to B) uniform in [cos(B C_hat), 1], which is
 * uniform in area because the area swept is linear in 1 - z there (the
 * strip between two circles about B). */
static vec3 triangle_sample(const rs_shape *sh, double u1, double u2, int slip)
{
    vec3 a, b, c;
    unit_vertices(sh, &a, &b, &c);
    double alpha = vertex_angle(a, b, c), area = triangle_area(sh);
    double cos_c = vec3_dot(a, b); /* the side opposite C */
    double area_hat = u1 * area;
    double s = sin(area_hat - alpha), t = cos(area_hat - alpha);
    double uu = t - cos(alpha), vv = s + sin(alpha) * cos_c;
    double q = ((vv * t - uu * s) * cos(alpha) - vv) / ((vv * s + uu * t) * sin(alpha));
    q = clamp1(q);
    vec3 c_hat = vec3_madd(vec3_scale(a, q), ortho(c, a), sqrt(fmax(0.0, 1.0 - q * q)));
    double cos_bc = clamp1(vec3_dot(c_hat, b));
    vec3 dir = ortho(c_hat, b);
    if (slip == 1) {
        /* The slip: the point uniform in arc length from B, not in cos. */
        double th = u2 * acos(cos_bc);
        return vec3_madd(vec3_scale(b, cos(th)), dir, sin(th));
    }
    double z = 1.0 - u2 * (1.0 - cos_bc);
    return vec3_madd(vec3_scale(b, z), dir, sqrt(fmax(0.0, 1.0 - z * z)));
}

/* Inside when w is on the inner side of the three great circles, the
 * sides oriented as the triangle is (for triangles within a hemisphere). */
static bool triangle_contains(const rs_shape *sh, vec3 w)
{
    vec3 a = sh->v[0], b = sh->v[1], c = sh->v[2];
    double o = vec3_dot(a, vec3_cross(b, c)) > 0.0 ? 1.0 : -1.0;
    return o * vec3_dot(w, vec3_cross(a, b)) >= 0.0 && o * vec3_dot(w, vec3_cross(b, c)) >= 0.0 &&
           o * vec3_dot(w, vec3_cross(c, a)) >= 0.0;
}

/* --- spherical rectangle: Urena, Fajardo and King, "An area-preserving
 * parametrization for spherical rectangles", EGSR 2013 [@urena2013] ----------------- */

/* The rectangle in its local frame (Section 3): x, y along the edges, z
 * their normal turned away from the viewer so that z0 < 0; the corners
 * at (x0 | x1, y0 | y1, z0); the solid angle S and the constants of the
 * inversion of Section 4. */
typedef struct rect_frame {
    vec3 x, y, z;
    double x0, x1, y0, y1, z0;
    double b0, b1, k, area;
} rect_frame;

static rect_frame rect_setup(const rs_shape *sh)
{
    rect_frame f;
    vec3 s = sh->v[0], ex = sh->v[1], ey = sh->v[2];
    double exl = vec3_length(ex), eyl = vec3_length(ey);
    f.x = vec3_scale(ex, 1.0 / exl), f.y = vec3_scale(ey, 1.0 / eyl);
    f.z = vec3_cross(f.x, f.y);
    f.z0 = vec3_dot(s, f.z);
    if (f.z0 > 0.0)
        f.z = vec3_neg(f.z), f.z0 = -f.z0;
    f.x0 = vec3_dot(s, f.x), f.y0 = vec3_dot(s, f.y);
    f.x1 = f.x0 + exl, f.y1 = f.y0 + eyl;
    vec3 v00 = vec3_make(f.x0, f.y0, f.z0), v01 = vec3_make(f.x0, f.y1, f.z0);
    vec3 v10 = vec3_make(f.x1, f.y0, f.z0), v11 = vec3_make(f.x1, f.y1, f.z0);
    /* The normals of the four planes through the viewer and an edge, and
     * the rectangle's internal angles between them (Section 3, eq. 3). */
    vec3 n0 = vec3_normalize(vec3_cross(v00, v10)), n1 = vec3_normalize(vec3_cross(v10, v11));
    vec3 n2 = vec3_normalize(vec3_cross(v11, v01)), n3 = vec3_normalize(vec3_cross(v01, v00));
    double g0 = acos(clamp1(-vec3_dot(n0, n1))), g1 = acos(clamp1(-vec3_dot(n1, n2)));
    double g2 = acos(clamp1(-vec3_dot(n2, n3))), g3 = acos(clamp1(-vec3_dot(n3, n0)));
    f.b0 = n0.z, f.b1 = n2.z;
    f.k = 2.0 * MC_PI - g2 - g3;
    f.area = g0 + g1 - f.k; /* the angle excess of the quadrilateral */
    return f;
}

/* Section 4: u1 fixes the area of the part x <= xu (solved for the
 * cosine cu of the angle of the plane through the viewer at x = xu), u2
 * the height hv = y / sqrt(y^2 + d^2) along the segment at xu, on which
 * the solid angle is linear in hv (the Jacobian of the projection of a
 * line onto the sphere). */
static vec3 rect_sample(const rs_shape *sh, double u1, double u2)
{
    rect_frame f = rect_setup(sh);
    double au = u1 * f.area + f.k;
    double fu = (cos(au) * f.b0 - f.b1) / sin(au);
    double cu = clamp1((fu > 0.0 ? 1.0 : -1.0) / sqrt(fu * fu + f.b0 * f.b0));
    /* |cu| = 1 makes xu infinite (never NaN: z0 != 0), and the clamp to
     * the rectangle's edges brings it back. */
    double xu = -(cu * f.z0) / sqrt(1.0 - cu * cu);
    xu = fmin(fmax(xu, f.x0), f.x1);
    double d = sqrt(xu * xu + f.z0 * f.z0);
    double h0 = f.y0 / sqrt(d * d + f.y0 * f.y0), h1 = f.y1 / sqrt(d * d + f.y1 * f.y1);
    double hv = h0 + u2 * (h1 - h0), hv2 = hv * hv;
    /* 1 - hv^2 below 2^-52 would divide by rounding: the point is at y1. */
    double yv = hv2 < 1.0 - 0x1p-52 ? hv * d / sqrt(1.0 - hv2) : f.y1;
    vec3 p = vec3_add(vec3_add(vec3_scale(f.x, xu), vec3_scale(f.y, yv)), vec3_scale(f.z, f.z0));
    return vec3_normalize(p);
}

/* Inside when the ray along w meets the rectangle's plane in front of the
 * viewer at edge coordinates (a, b) in [0, 1]^2. */
static bool rect_contains(const rs_shape *sh, vec3 w)
{
    vec3 s = sh->v[0], ex = sh->v[1], ey = sh->v[2], n = vec3_cross(ex, ey);
    double dn = vec3_dot(w, n);
    if (dn == 0.0)
        return false;
    double t = vec3_dot(s, n) / dn;
    if (!(t > 0.0))
        return false;
    vec3 p = vec3_sub(vec3_scale(w, t), s);
    double a = vec3_dot(p, ex) / vec3_length_sq(ex), b = vec3_dot(p, ey) / vec3_length_sq(ey);
    return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0;
}

/* --- the shapes ----------------------------------------------------------- */

double rs_shape_solid_angle(const rs_shape *sh)
{
    switch (sh->kind) {
    case RS_TRIANGLE: return triangle_area(sh);
    case RS_RECT: return rect_setup(sh).area;
    case RS_CONE: return MC_2PI * (1.0 - sh->cos_max);
    default: return MC_4PI;
    }
}

bool rs_shape_contains(const rs_shape *sh, vec3 w)
{
    switch (sh->kind) {
    case RS_TRIANGLE: return triangle_contains(sh, w);
    case RS_RECT: return rect_contains(sh, w);
    case RS_CONE: return vec3_dot(w, vec3_normalize(sh->axis)) >= sh->cos_max;
    case RS_BECKMANN: return w.z > 0.0;
    default: return true;
    }
}

/* A direction at cos_theta from the unit axis, at azimuth 2 pi u about it. */
static vec3 about(vec3 axis, double cos_theta, double sin_theta, double u)
{
    onb o = onb_from_w(axis);
    double phi = MC_2PI * u;
    return onb_to_world(&o, vec3_make(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta));
}

/* Uniform in the cone: cos theta uniform on [cos_max, 1], since the
 * solid angle element is d(cos theta) d phi (the slip: theta uniform,
 * whose density then grows toward the rim as sin theta / theta). */
static vec3 cone_sample(const rs_shape *sh, double u1, double u2, int slip)
{
    double ct, st;
    if (slip == 1) {
        double th = u1 * acos(sh->cos_max);
        ct = cos(th), st = sin(th);
    } else {
        ct = 1.0 - u1 * (1.0 - sh->cos_max);
        st = sqrt(fmax(0.0, (1.0 - ct) * (1.0 + ct)));
    }
    return about(vec3_normalize(sh->axis), ct, st, u2);
}

/* von Mises-Fisher by Jakob, "Numerically stable sampling of the von
 * Mises Fisher distribution on S^2" (2012) [@jakob2012]: inverting the marginal CDF of
 * w = cos theta, F(w) = (e^{kappa (w - 1)} - e^{-2 kappa}) / (1 - e^{-2 kappa}),
 * gives 1 - w = -log(u + (1 - u) e^{-2 kappa}) / kappa, computed as 1 - w
 * itself so that sin theta = sqrt((1 - w)(1 + w)) keeps its digits near
 * the pole. */
static vec3 vmf_sample(const rs_shape *sh, double kappa, double u1, double u2)
{
    double m = -log(u1 + (1.0 - u1) * exp(-2.0 * kappa)) / kappa; /* 1 - w, in [0, 2] */
    m = fmin(2.0, fmax(0.0, m));
    return about(vec3_normalize(sh->axis), 1.0 - m, sqrt(m * (2.0 - m)), u2);
}

/* kappa / (2 pi (1 - e^{-2 kappa})) e^{kappa (cos - 1)}, with cos - 1 =
 * -|w - axis|^2 / 2 for unit w (no cancellation near the pole). */
static double vmf_pdf(const rs_shape *sh, vec3 w)
{
    double d2 = vec3_length_sq(vec3_sub(w, vec3_normalize(sh->axis)));
    return sh->kappa / (MC_2PI * -expm1(-2.0 * sh->kappa)) * exp(-0.5 * sh->kappa * d2);
}

/* Beckmann normals drawn proportionally to D(h) cos theta_h (Walter et
 * al., "Microfacet models for refraction through rough surfaces", EGSR
 * 2007, eq. 28) [@walter2007]: tan^2 theta = -alpha^2 log(1 - u1), phi = 2 pi u2. */
static vec3 beckmann_sample(double alpha, double u1, double u2)
{
    double t2 = -alpha * alpha * log(1.0 - u1);
    double ct = 1.0 / sqrt(1.0 + t2), st = sqrt(t2) * ct;
    return about(vec3_make(0.0, 0.0, 1.0), ct, st, u2);
}

/* D(h) cos theta_h = exp(-tan^2 / alpha^2) / (pi alpha^2 cos^3) per unit
 * solid angle, on the upper hemisphere. */
static double beckmann_pdf(const rs_shape *sh, vec3 w)
{
    if (!(w.z > 0.0))
        return 0.0;
    double a2 = sh->alpha * sh->alpha, t2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return exp(-t2 / a2) / (MC_PI * a2 * w.z * w.z * w.z);
}

/* --- the samplers as callbacks ------------------------------------------- */

static double claimed_pdf(const double *x, void *ctx)
{
    const rs_sampler *s = ctx;
    const rs_shape *sh = s->shape;
    vec3 w = vec_of(x);
    double p;
    switch (sh->kind) {
    case RS_VMF: p = vmf_pdf(sh, w); break;
    case RS_BECKMANN: p = beckmann_pdf(sh, w); break;
    default: p = rs_shape_contains(sh, w) ? 1.0 / rs_shape_solid_angle(sh) : 0.0; break;
    }
    return s->pdf_scale * p;
}

static void sample_any(const double *u, mcbox_sample *out, void *ctx)
{
    const rs_sampler *s = ctx;
    const rs_shape *sh = s->shape;
    vec3 w;
    switch (sh->kind) {
    case RS_TRIANGLE: w = triangle_sample(sh, u[0], u[1], s->slip); break;
    case RS_RECT: w = rect_sample(sh, u[0], u[1]); break;
    case RS_CONE: w = cone_sample(sh, u[0], u[1], s->slip); break;
    case RS_VMF: w = vmf_sample(sh, s->draw > 0.0 ? s->draw : sh->kappa, u[0], u[1]); break;
    default: w = beckmann_sample(s->draw > 0.0 ? s->draw : sh->alpha, u[0], u[1]); break;
    }
    put(out, w);
    out->pdf = claimed_pdf(out->x, ctx); /* what the renderer would report */
}


/* --- the suite ------------------------------------------------------------ */

/* "High-entropy" shapes: tilted, no vertex or axis along a coordinate
 * axis, no round number that could hide a missing factor. */
static const rs_shape tri_shape = {
    RS_TRIANGLE, {{0.3, -0.2, 1.25}, {1.1, 0.4, 0.62}, {-0.15, 0.95, 0.83}}, {0, 0, 0}, 0, 0, 0};
static const rs_shape small_tri_shape = {
    RS_TRIANGLE, {{0.52, 0.31, 0.79}, {0.63, 0.28, 0.76}, {0.55, 0.41, 0.74}}, {0, 0, 0}, 0, 0, 0};
/* Corner, then two orthogonal edges ((0.99, 0.18, 0) . (-0.16, 0.88, 0.4) = 0):
 * a rectangle in a plane tilted about both x and y. */
static const rs_shape rect_shape = {
    RS_RECT, {{-0.6, -0.5, 1.3}, {0.99, 0.18, 0.0}, {-0.16, 0.88, 0.4}}, {0, 0, 0}, 0, 0, 0};
static const rs_shape cone_shape = {RS_CONE, {{0, 0, 0}}, {0.61, -0.33, 0.72}, 0.8173, 0, 0};
static const rs_shape vmf_shape = {RS_VMF, {{0, 0, 0}}, {-0.31, 0.52, 0.79}, 0, 1000.0, 0};
static const rs_shape beckmann_shape = {RS_BECKMANN, {{0, 0, 0}}, {0, 0, 1}, 0, 0, 0.05};
/* The claimed density of the Beckmann twin that draws with alpha 0.05. */
static const rs_shape beckmann_narrow_shape = {RS_BECKMANN, {{0, 0, 0}}, {0, 0, 1}, 0, 0, 0.045};

#define CHARTS(...) (int)(sizeof((rs_chart[]){__VA_ARGS__}) / sizeof(rs_chart)), {__VA_ARGS__}
#define SAMPLER(name, what, wrong, shape, scale, draw, slip, ...)                                   \
    {name, what, wrong, &shape, sample_any, claimed_pdf, scale, draw, slip, CHARTS(__VA_ARGS__)}

static const rs_sampler suite[] = {
    SAMPLER("triangle", "spherical triangle, Arvo 1995 (0.534 sr, tilted)", NULL, tri_shape, 1.0,
            0.0, 0, RS_CHART_POLYGON, RS_CHART_SPHERE),
    SAMPLER("triangle-small", "spherical triangle, Arvo 1995 (small)", NULL, small_tri_shape, 1.0,
            0.0, 0, RS_CHART_POLYGON, RS_CHART_SPHERE),
    SAMPLER("rectangle", "spherical rectangle, Urena et al. 2013 (tilted)", NULL, rect_shape, 1.0,
            0.0, 0, RS_CHART_POLYGON, RS_CHART_SPHERE),
    SAMPLER("cone", "uniform cone about a tilted axis, cos theta uniform", NULL, cone_shape, 1.0,
            0.0, 0, RS_CHART_CAP, RS_CHART_SPHERE, RS_CHART_LOBE),
    SAMPLER("vmf", "von Mises-Fisher kappa 1000, Jakob 2012", NULL, vmf_shape, 1.0, 0.0, 0,
            RS_CHART_LOBE, RS_CHART_SPHERE),
    SAMPLER("beckmann", "Beckmann normals alpha 0.05, D(h) cos theta_h", NULL, beckmann_shape,
            1.0, 0.0, 0, RS_CHART_LOBE, RS_CHART_HEMISPHERE),
    SAMPLER("triangle-pdf-high", "Arvo's triangle", "density claimed 0.5% too high", tri_shape,
            1.005, 0.0, 0, RS_CHART_POLYGON, RS_CHART_SPHERE),
    SAMPLER("triangle-arc-slip", "Arvo's triangle",
            "second coordinate uniform in arc length from B, not in cos", tri_shape, 1.0, 0.0, 1,
            RS_CHART_POLYGON, RS_CHART_SPHERE),
    SAMPLER("cone-pdf-high", "uniform cone", "density claimed 0.5% too high", cone_shape, 1.005,
            0.0, 0, RS_CHART_CAP, RS_CHART_SPHERE),
    SAMPLER("cone-theta-uniform", "uniform cone", "theta uniform instead of cos theta", cone_shape,
            1.0, 0.0, 1, RS_CHART_CAP, RS_CHART_SPHERE),
    SAMPLER("vmf-900-as-1000", "von Mises-Fisher", "drawn with kappa 900, density kappa 1000",
            vmf_shape, 1.0, 900.0, 0, RS_CHART_LOBE, RS_CHART_SPHERE),
    SAMPLER("beckmann-0.05-as-0.045", "Beckmann", "drawn with alpha 0.05, density alpha 0.045",
            beckmann_narrow_shape, 1.0, 0.05, 0, RS_CHART_LOBE, RS_CHART_HEMISPHERE),
};
#undef SAMPLER
#undef CHARTS

enum { SUITE_SIZE = sizeof suite / sizeof suite[0] };

size_t rs_count(void)
{
    return SUITE_SIZE;
}

const rs_sampler *rs_at(size_t i)
{
    return i < SUITE_SIZE ? &suite[i] : NULL;
}

const rs_sampler *rs_find(const char *name)
{
    for (size_t i = 0; i < SUITE_SIZE; i++)
        if (strcmp(rs_at(i)->name, name) == 0)
            return rs_at(i);
    return NULL;
}

const char *rs_chart_name(rs_chart c)
{
    static const char *const names[] = {"sphere", "hemisphere", "polygon", "cap", "lobe"};
    return names[c];
}

/* The lobe chart's width: the lobe's angular spread (1 / sqrt(kappa) for
 * vMF, alpha for Beckmann), a third of the cone's half angle. */
static double lobe_width(const rs_shape *sh)
{
    switch (sh->kind) {
    case RS_VMF: return 1.0 / sqrt(sh->kappa);
    case RS_BECKMANN: return sh->alpha;
    default: return acos(sh->cos_max) / 3.0;
    }
}

mcbox_sampler rs_mcbox_sampler(const rs_sampler *s, rs_chart c, mcbox_check_options *o)
{
    const rs_shape *sh = s->shape;
    mcbox_domain_kind k = MCBOX_SPHERE;
    if (c == RS_CHART_HEMISPHERE || (c == RS_CHART_LOBE && sh->kind == RS_BECKMANN))
        k = MCBOX_HEMISPHERE;
    else if (c == RS_CHART_POLYGON)
        k = sh->kind == RS_TRIANGLE ? MCBOX_SPHERICAL_TRIANGLE : MCBOX_SPHERICAL_QUAD;
    else if (c == RS_CHART_CAP)
        k = MCBOX_CAP;
    mcbox_sampler m = mcbox_sampler_init(k);
    m.sample = s->sample, m.pdf = s->pdf, m.ctx = (void *)s;
    for (int j = 0; j < 3; j++) {
        m.domain.vertex[j][0] = sh->v[j].x, m.domain.vertex[j][1] = sh->v[j].y;
        m.domain.vertex[j][2] = sh->v[j].z;
    }
    m.domain.axis[0] = sh->axis.x, m.domain.axis[1] = sh->axis.y, m.domain.axis[2] = sh->axis.z;
    m.domain.cos_max = sh->cos_max;
    o->lobe_width = 0.0;
    o->lobe_axis[0] = o->lobe_axis[1] = o->lobe_axis[2] = 0.0;
    if (c == RS_CHART_LOBE) {
        o->lobe_width = lobe_width(sh);
        if (sh->kind != RS_BECKMANN) /* Beckmann's lobe is about +z, the default */
            o->lobe_axis[0] = sh->axis.x, o->lobe_axis[1] = sh->axis.y, o->lobe_axis[2] = sh->axis.z;
    }
    return m;
}

#define V3 "%.17g,%.17g,%.17g"
#define XYZ(v) (v).x, (v).y, (v).z

size_t rs_cli_args(const rs_sampler *s, rs_chart c, char *buf, size_t size)
{
    const rs_shape *sh = s->shape;
    int n = 0;
    switch (c) {
    case RS_CHART_SPHERE: n = snprintf(buf, size, "--domain sphere"); break;
    case RS_CHART_HEMISPHERE: n = snprintf(buf, size, "--domain hemisphere"); break;
    case RS_CHART_POLYGON:
        n = sh->kind == RS_TRIANGLE
                ? snprintf(buf, size, "--domain spherical-triangle --param a=" V3 " --param b=" V3
                           " --param c=" V3, XYZ(sh->v[0]), XYZ(sh->v[1]), XYZ(sh->v[2]))
                : snprintf(buf, size, "--domain spherical-quad --param corner=" V3 " --param u=" V3
                           " --param v=" V3, XYZ(sh->v[0]), XYZ(sh->v[1]), XYZ(sh->v[2]));
        break;
    case RS_CHART_CAP:
        n = snprintf(buf, size, "--domain cap --param axis=" V3 " --param cos_max=%.17g",
                     XYZ(sh->axis), sh->cos_max);
        break;
    case RS_CHART_LOBE:
        n = sh->kind == RS_BECKMANN
                ? snprintf(buf, size, "--domain hemisphere --lobe-width %.17g", lobe_width(sh))
                : snprintf(buf, size, "--domain sphere --lobe-width %.17g --lobe-axis " V3,
                           lobe_width(sh), XYZ(sh->axis));
        break;
    }
    return n < 0 ? 0 : (size_t)n;
}

/* --- the doors ------------------------------------------------------------ */

/* Up to `count` numbers of the line into v (separated by blanks or
 * commas); how many were read. */
static int numbers(char *line, double *v, int count)
{
    int k = 0;
    char *save = NULL;
    for (char *tok = strtok_r(line, " \t,\r\n", &save); tok && k < count;
         tok = strtok_r(NULL, " \t,\r\n", &save)) {
        char *end;
        v[k] = strtod(tok, &end);
        if (end == tok || *end)
            return -1;
        k++;
    }
    return k;
}

static int serve_error(FILE *out, const char *what)
{
    fprintf(out, "error %s\n", what);
    fflush(out);
    fprintf(stderr, "real_samplers serve: %s\n", what);
    return 2;
}

int rs_serve(const rs_sampler *s, FILE *in, FILE *out)
{
    char line[4096], cmd[16];
    long k;
    while (fgets(line, sizeof line, in)) {
        if (strncmp(line, "hello ", 6) == 0) {
            int version, dims;
            char domain[64];
            if (sscanf(line, "hello %d %63s %d", &version, domain, &dims) != 3 || version != 1 ||
                dims != 3)
                return serve_error(out, "this server speaks version 1 with directions (DIMS 3)");
            fputs("ok\n", out);
        } else if (sscanf(line, "%15s %ld", cmd, &k) == 2 && k > 0 &&
                   (strcmp(cmd, "sample") == 0 || strcmp(cmd, "pdf") == 0)) {
            bool sample = cmd[0] == 's';
            for (long i = 0; i < k; i++) {
                double v[3];
                if (!fgets(line, sizeof line, in) || numbers(line, v, 3) != (sample ? 2 : 3))
                    return serve_error(out, sample ? "a sample item is two uniforms"
                                                   : "a pdf item is three coordinates");
                if (sample) {
                    mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
                    s->sample(v, &o, (void *)s);
                    fprintf(out, "%.17g %.17g %.17g %.17g\n", o.x[0], o.x[1], o.x[2], o.pdf);
                } else {
                    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                    for (int j = 0; j < 3; j++)
                        v[j] /= l;
                    fprintf(out, "%.17g\n", l > 0.0 && isfinite(l) ? s->pdf(v, (void *)s) : 0.0);
                }
            }
        } else {
            return serve_error(out, "unknown command (this server answers hello, sample, pdf)");
        }
        fflush(out);
    }
    return 0;
}

int rs_write_samples(const rs_sampler *s, uint64_t n, uint64_t seed, bool f64, FILE *f)
{
    mc_rng rng = mc_rng_derive(seed, 0u); /* mcbox_check_run's stream */
    for (uint64_t i = 0; i < n; i++) {
        double u[2];
        u[0] = mc_rng_uniform(&rng);
        u[1] = mc_rng_uniform(&rng);
        mcbox_sample o = {{0, 0, 0}, (double)NAN, (double)NAN, -1};
        s->sample(u, &o, (void *)s);
        if (f64 ? fwrite(o.x, sizeof o.x[0], 3, f) != 3
                : fprintf(f, "%.17g %.17g %.17g\n", o.x[0], o.x[1], o.x[2]) < 0)
            return -1;
    }
    return fflush(f) == 0 ? 0 : -1;
}

int rs_main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[1], "serve") && strcmp(argv[1], "sample")))
        return -1;
    const rs_sampler *s = rs_find(argv[2]);
    if (!s) {
        fprintf(stderr, "%s: no sampler '%s'\n", argv[0], argv[2]);
        return 2;
    }
    if (strcmp(argv[1], "serve") == 0)
        return rs_serve(s, stdin, stdout);
    if (argc < 5) {
        fprintf(stderr, "%s: sample NAME N SEED [f64]\n", argv[0]);
        return 2;
    }
    uint64_t n = strtoull(argv[3], NULL, 10), seed = strtoull(argv[4], NULL, 10);
    bool f64 = argc > 5 && strcmp(argv[5], "f64") == 0;
    return rs_write_samples(s, n, seed, f64, stdout) == 0 ? 0 : 2;
}
