/* pdf/chart.h - charts of the sphere of directions in which the density of
 * a pdf object is smooth on every histogram cell.
 *
 * Checking a pdf object (toward a light, mixtures, lists: Shirley, "Ray
 * Tracing: The Rest of Your Life" (v1.123), chapters 7, 8 and 10; this book's
 * #ch-lights and #ch-mixture) means histogramming its directions and
 * integrating its value() over every cell by adaptive quadrature. Quadrature
 * is fast on smooth integrands and hopeless on a jump that cuts a cell along
 * a curve: it bisects toward the jump until its 1e-12 target and runs out of
 * subintervals (about a second per cell). A parallelogram light seen in
 * (cos theta, phi) has exactly such edges. A chart is a map from a
 * rectangle onto (part of) the sphere of directions chosen so that every
 * jump of the density lies on a line x = const or y = const that the
 * caller makes a cell edge; the density of the chart is value(d) times the
 * Jacobian d omega / (dx dy).
 *
 * - spherical: (cos theta, phi) about an axis over [cos_lo, 1] x [0, 2 pi);
 *   Jacobian 1, because d omega = d(cos theta) d phi. For densities with
 *   rotational structure: uniform, cosine lobe, a sphere's cone (whose rim
 *   is the line cos theta = cos_lo when cos_lo is the rim).
 * - light plane: the whole sphere seen through a parallelogram's plane.
 *   Directions that hit the plane map to its edge coordinates (s, t),
 *   stretched from the whole line to (-1, 2) so that the light is exactly
 *   the unit square [0, 1]^2; directions that miss the plane are
 *   (cos theta, phi) about its normal, laid out in x in [2, 3]. Rectangle
 *   [-1, 3] x [-1, 2]; joints on the integer lines.
 * - quad and cap: the light's (s, t) on [0, 1]^2 beside a sphere's cone on
 *   [1, 2] x [0, 1]; directions toward neither are not covered. For a list
 *   of one parallelogram and one sphere whose cones are disjoint.
 *
 * Nothing here allocates except through mc_quad (the caller's workspace).
 */
#ifndef PDF_CHART_H
#define PDF_CHART_H

#include "mc/onb.h"
#include "mc/quad.h"
#include "mc/vec3.h"

typedef enum pdf_chart_kind {
    PDF_CHART_SPHERICAL,
    PDF_CHART_LIGHT_PLANE,
    PDF_CHART_QUAD_AND_CAP
} pdf_chart_kind;

typedef struct pdf_chart {
    pdf_chart_kind kind;
    onb frame; /* spherical: about frame.n; light plane: frame.n = toward; quad and cap: cone axis
                */
    double cos_lo; /* spherical: lower end of cos theta; quad and cap: the cone's cos theta_max */
    double one_minus_cos_lo; /* 1 - cos_lo; for the quad and cap, without cancellation */
    /* Light plane, quad and cap: the parallelogram corner + s u + t v seen
     * from origin, and its unit normal on the side away from origin. */
    vec3 origin, corner, u, v, toward;
} pdf_chart;

/* (cos theta, phi) about `axis` (any nonzero length) with cos theta in
 * [cos_lo, 1], cos_lo in [-1, 1). */
pdf_chart pdf_chart_spherical(vec3 axis, double cos_lo);

/* The light-plane chart of the parallelogram (corner, u, v), u and v not
 * parallel, seen from `origin` off its plane. */
pdf_chart pdf_chart_light_plane(vec3 origin, vec3 corner, vec3 u, vec3 v);

/* The parallelogram beside the cone of the sphere (center, radius) seen
 * from `origin` outside it; cos theta_max = sqrt(1 - R^2 / d^2) computed
 * from the geometry by smp_sphere_cone_cos_theta_max, and 1 - cos theta_max
 * by smp_sphere_cone_one_minus_cos, as pdf_toward_sphere does, so that the
 * cap ends where that pdf's cone does. The two must not
 * overlap as seen from origin. */
pdf_chart pdf_chart_quad_and_cap(vec3 origin, vec3 corner, vec3 u, vec3 v, vec3 center,
                                 double radius);

/* The chart's rectangle [lo[0], hi[0]] x [lo[1], hi[1]]. */
void pdf_chart_rect(const pdf_chart *c, double lo[2], double hi[2]);

/* The unit direction at chart point x (inside the rectangle) and, in
 * *jacobian, d omega / (dx dy) there (>= 0, finite inside the open
 * rectangle). */
vec3 pdf_chart_direction(const pdf_chart *c, const double x[2], double *jacobian);

/* The chart point of the unit direction d. Where the chart does not cover
 * d the point lies outside the chart's rectangle: the quad-and-cap chart
 * returns x[0] = NaN (outside every rectangle), the spherical chart
 * returns its (cos theta, phi) all the same, with cos theta < cos_lo; the
 * light-plane chart covers every direction. Directions on the
 * parallelogram's edge within 1e-9 of its edge coordinates count as on it,
 * the slack pdf/pdf.c allows for the same round-off. */
void pdf_chart_point(const pdf_chart *c, vec3 d, double x[2]);

/* The integral over the chart's rectangle of f(d) times the Jacobian, i.e.
 * of f over the directions the chart covers, per unit solid angle. The
 * rectangle is cut at its joints into pieces on which a density that jumps
 * only there is smooth; the light plane's four outer corners, where a
 * whole arc of the plane's horizon crowds into one point, are refined
 * geometrically toward the corner (40 halvings). q from mc_quad_create. */
double pdf_chart_integrate(const pdf_chart *c, double (*f)(vec3 d, void *ctx), void *ctx,
                           mc_quad *q);

#endif /* PDF_CHART_H */
