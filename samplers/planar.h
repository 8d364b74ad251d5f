/* samplers/planar.h - uniform points on flat shapes and on a sphere's
 * surface: the unit square, the unit disc (two mappings), a triangle, a
 * parallelogram, and the surface of a sphere.
 *
 * The disc is the projection of the cosine-weighted hemisphere (Malley's
 * method; this book's #ch-directions); parallelograms and sphere surfaces
 * are the area lights of Shirley, "Ray Tracing: The Rest of Your Life"
 * (v1.123), chapter 7 "Sampling Lights Directly" and chapter 10 "Cleaning
 * Up pdf Management" (the sphere sampled as a light); this book's
 * #ch-lights. Every density here is per unit AREA of the shape;
 * samplers/measure.h converts one to per unit solid angle.
 *
 * Trio convention: smp_X_sample(u1, u2, shape...) maps (u1, u2) in [0,1)^2
 * to the shape, smp_X_pdf(point, shape...) is the density (0 off the shape,
 * never NaN), smp_X_invert(point, shape...) returns the (u1, u2) that
 * sample maps to point. Where a mapping uses polar coordinates, u1 drives
 * the azimuth and u2 the radius, as in the directional warps.
 */
#ifndef SMP_PLANAR_H
#define SMP_PLANAR_H

#include "mc/vec2.h"
#include "mc/vec3.h"

/* --- unit square [0,1]^2 ------------------------------------------------ */

/* The point (u1, u2) itself: the identity warp, the baseline of the suite. */
vec2 smp_unit_square_sample(double u1, double u2);
/* 1 per unit area on [0,1]^2, 0 elsewhere. */
double smp_unit_square_pdf(vec2 p);
/* The identity. */
vec2 smp_unit_square_invert(vec2 p);

/* --- unit disc, polar mapping ------------------------------------------- */

/* phi = 2 pi u1, r = sqrt(u2): the sqrt makes the density uniform in area,
 * because the area inside radius r is pi r^2, so r^2 must be uniform. */
vec2 smp_disc_polar_sample(double u1, double u2);
/* 1/pi per unit area for x^2 + y^2 <= 1 (plus 4 ulps of round-off), else 0. */
double smp_disc_polar_pdf(vec2 p);
/* (phi / 2 pi, r^2) of p; p in the disc. */
vec2 smp_disc_polar_invert(vec2 p);

/* --- unit disc, concentric mapping (Shirley and Chiu 1997) [@shirley-chiu1997] ---------- */

/* Maps the square [-1,1]^2 (as 2u - 1) to the disc ring by ring: square
 * shells to circles, so neighbouring points stay neighbours and the
 * distortion is far lower than the polar mapping's. */
vec2 smp_disc_concentric_sample(double u1, double u2);
/* 1/pi per unit area on the disc (same support as smp_disc_polar_pdf). */
double smp_disc_concentric_pdf(vec2 p);
/* The (u1, u2) that smp_disc_concentric_sample maps to p; p in the disc. */
vec2 smp_disc_concentric_invert(vec2 p);

/* --- triangle (0,0), (1,0), (0,1) --------------------------------------- */

/* s = sqrt(u1), point (1 - s, u2 s): u1 picks the vertical chord
 * x = 1 - s (of length s) with density proportional to its length, u2 a
 * uniform point on it. */
vec2 smp_triangle_sample(double u1, double u2);
/* 2 per unit area for x >= 0, y >= 0, x + y <= 1 (4 ulps of round-off), else 0. */
double smp_triangle_pdf(vec2 p);
/* (u1, u2) = ((1 - x)^2, y / (1 - x)); u2 = 0.5 at the vertex (1, 0). */
vec2 smp_triangle_invert(vec2 p);

/* --- parallelogram corner + a edge_u + b edge_v, (a, b) in [0,1]^2 ------- */

/* corner + u1 edge_u + u2 edge_v; edge_u and edge_v not parallel. */
vec3 smp_parallelogram_sample(double u1, double u2, vec3 corner, vec3 edge_u, vec3 edge_v);
/* 1 / |edge_u x edge_v| per unit area for points of the parallelogram, else
 * 0. A point counts as on it when its distance from the plane is at most
 * 1e-9 (|edge_u| + |edge_v|) (round-off of the sample's three additions is
 * about 1e-16 of that; a point off the light by a billionth of its size is
 * not on it) and its edge coordinates are in [0, 1]. */
double smp_parallelogram_pdf(vec3 p, vec3 corner, vec3 edge_u, vec3 edge_v);
/* The edge coordinates (a, b) of p projected on the plane (p - corner =
 * a edge_u + b edge_v + off-plane part). */
vec2 smp_parallelogram_invert(vec3 p, vec3 corner, vec3 edge_u, vec3 edge_v);

/* --- surface of the sphere |p - center| = radius ------------------------ */

/* center + radius * smp_uniform_sphere_sample(u1, u2); radius > 0. */
vec3 smp_sphere_surface_sample(double u1, double u2, vec3 center, double radius);
/* 1 / (4 pi radius^2) per unit area for points within 1e-9 radius of the
 * surface (see smp_parallelogram_pdf for the tolerance), else 0. */
double smp_sphere_surface_pdf(vec3 p, vec3 center, double radius);
/* smp_uniform_sphere_invert of the direction from center to p. */
vec2 smp_sphere_surface_invert(vec3 p, vec3 center, double radius);

#endif /* SMP_PLANAR_H */
