/* samplers/planar.c - square, disc, triangle, parallelogram, sphere surface.
 *
 * Densities are per unit area. Every sample maps (u1, u2) in [0,1)^2 by
 * inverting a CDF, so each has a closed-form inverse; the round-trip tests
 * hold them to 1e-9.
 */
#include "samplers/planar.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "mc/constants.h"
#include "mc/trig.h"
#include "samplers/sphere.h"
#include "samplers/spherical.h"

/* Support tests allow 4 ulps of 1 beyond the exact boundary: the sample
 * formulas round at most a few times, and a sample the pdf then rejects by
 * one ulp would be a false domain failure. */
#define EDGE_SLACK (4.0 * DBL_EPSILON)

vec2 smp_unit_square_sample(double u1, double u2)
{
    return vec2_make(u1, u2);
}

double smp_unit_square_pdf(vec2 p)
{
    return p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0 ? 1.0 : 0.0;
}

vec2 smp_unit_square_invert(vec2 p)
{
    return p;
}

/* BEGIN SNIPPET disc_polar */
vec2 smp_disc_polar_sample(double u1, double u2)
{
    /* The area within radius r is pi r^2: P(R <= r) = r^2 = u2. */
    double r = sqrt(u2), s, c;
    mc_sincos_turn(u1, &s, &c); /* the angle is 2 pi u1 */
    return vec2_make(r * c, r * s);
}

static double disc_pdf(vec2 p)
{
    return p.x * p.x + p.y * p.y <= 1.0 + EDGE_SLACK ? MC_INV_PI : 0.0;
}

double smp_disc_polar_pdf(vec2 p)
{
    return disc_pdf(p);
}

vec2 smp_disc_polar_invert(vec2 p)
{
    return vec2_make(smp_spherical_phi(vec3_make(p.x, p.y, 0.0)) * MC_INV_2PI,
                     p.x * p.x + p.y * p.y);
}
/* END SNIPPET disc_polar */

/* BEGIN SNIPPET disc_concentric_sample */
vec2 smp_disc_concentric_sample(double u1, double u2)
{
    double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
    if (a == 0.0 && b == 0.0)
        return vec2_make(0.0, 0.0);
    /* The square shell max(|a|, |b|) = r goes to the circle of radius r;
     * along the shell the angle is linear in the other coordinate, a
     * quarter turn per side. Area is preserved: the shell of width dr has
     * area 8 r dr on the square (side 2r) and 2 pi r dr on the disc, both
     * proportional to r dr, and the whole square maps to the whole disc. */
    double r, phi;
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = MC_PI_4 * (b / a);
    } else {
        r = b;
        phi = MC_PI_2 - MC_PI_4 * (a / b);
    }
    return vec2_make(r * cos(phi), r * sin(phi));
}
/* END SNIPPET disc_concentric_sample */

double smp_disc_concentric_pdf(vec2 p)
{
    return disc_pdf(p);
}

/* BEGIN SNIPPET disc_concentric_invert */
vec2 smp_disc_concentric_invert(vec2 p)
{
    double r = sqrt(p.x * p.x + p.y * p.y);
    if (r == 0.0)
        return vec2_make(0.5, 0.5);
    double a, b;
    if (fabs(p.x) >= fabs(p.y)) {
        /* First case of the sample: (x, y) = a (cos t, sin t) with
         * t = (pi/4)(b/a) in [-pi/4, pi/4], so cos t > 0 and a has the sign
         * of x. */
        a = copysign(r, p.x);
        double t = atan2(p.y / a, p.x / a);
        b = a * t / MC_PI_4;
    } else {
        /* Second case: (x, y) = b (cos s, sin s), s = pi/2 - (pi/4)(a/b) in
         * [pi/4, 3 pi/4], so sin s > 0 and b has the sign of y. */
        b = copysign(r, p.y);
        double s = atan2(p.y / b, p.x / b);
        a = (MC_PI_2 - s) * b / MC_PI_4;
    }
    return vec2_make(0.5 * (a + 1.0), 0.5 * (b + 1.0));
}
/* END SNIPPET disc_concentric_invert */

/* BEGIN SNIPPET triangle */
vec2 smp_triangle_sample(double u1, double u2)
{
    /* The marginal of x is 2 (1 - x) (the chord length at x, normalized), so
     * P(X >= x) = (1 - x)^2 = u1; given x, y is uniform on [0, 1 - x]. */
    double s = sqrt(u1);
    return vec2_make(1.0 - s, u2 * s);
}

double smp_triangle_pdf(vec2 p)
{
    return p.x >= 0.0 && p.y >= 0.0 && p.x + p.y <= 1.0 + EDGE_SLACK ? 2.0 : 0.0;
}

vec2 smp_triangle_invert(vec2 p)
{
    double s = 1.0 - p.x;
    return vec2_make(s * s, s > 0.0 ? p.y / s : 0.5);
}
/* END SNIPPET triangle */

/* The out-of-plane tolerance of the parallelogram and sphere-surface pdfs
 * (documented in planar.h): far above the ~1e-16 relative round-off of a
 * sample, far below any real miss. */
#define ON_SURFACE_TOL 1e-9

vec3 smp_parallelogram_sample(double u1, double u2, vec3 corner, vec3 edge_u, vec3 edge_v)
{
    return vec3_add(corner, vec3_add(vec3_scale(edge_u, u1), vec3_scale(edge_v, u2)));
}

/* Edge coordinates by the dual basis: with n = u x v, the vector
 * (v x n) / |n|^2 is orthogonal to v and has unit dot product with u, so its
 * dot product with p - corner picks out the u coordinate (likewise for v).
 * *plane_dist gets the distance of p from the plane. */
static vec2 edge_coords(vec3 p, vec3 corner, vec3 edge_u, vec3 edge_v, double *plane_dist)
{
    vec3 d = vec3_sub(p, corner), n = vec3_cross(edge_u, edge_v);
    double nn = vec3_dot(n, n);
    double a = vec3_dot(vec3_cross(edge_v, n), d) / nn;
    double b = vec3_dot(vec3_cross(n, edge_u), d) / nn;
    if (plane_dist)
        *plane_dist = fabs(vec3_dot(d, n)) / sqrt(nn);
    return vec2_make(a, b);
}

double smp_parallelogram_pdf(vec3 p, vec3 corner, vec3 edge_u, vec3 edge_v)
{
    double dist = 0.0;
    vec2 ab = edge_coords(p, corner, edge_u, edge_v, &dist);
    double size = vec3_length(edge_u) + vec3_length(edge_v);
    double lo = -EDGE_SLACK, hi = 1.0 + EDGE_SLACK;
    if (!(dist <= ON_SURFACE_TOL * size) || !(ab.x >= lo && ab.x <= hi && ab.y >= lo && ab.y <= hi))
        return 0.0;
    return 1.0 / vec3_length(vec3_cross(edge_u, edge_v));
}

vec2 smp_parallelogram_invert(vec3 p, vec3 corner, vec3 edge_u, vec3 edge_v)
{
    return edge_coords(p, corner, edge_u, edge_v, NULL);
}

vec3 smp_sphere_surface_sample(double u1, double u2, vec3 center, double radius)
{
    return vec3_madd(center, smp_uniform_sphere_sample(u1, u2), radius);
}

double smp_sphere_surface_pdf(vec3 p, vec3 center, double radius)
{
    double r = vec3_length(vec3_sub(p, center));
    if (!(fabs(r - radius) <= ON_SURFACE_TOL * radius))
        return 0.0;
    return 1.0 / (MC_4PI * radius * radius);
}

vec2 smp_sphere_surface_invert(vec3 p, vec3 center, double radius)
{
    (void)radius; /* the direction alone fixes (u1, u2) */
    return smp_uniform_sphere_invert(vec3_normalize(vec3_sub(p, center)));
}
