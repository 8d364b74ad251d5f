/* samplers/cone.h - uniform directions in a cone about +z, and the cone
 * that a sphere subtends from a point.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 10
 * "Cleaning Up pdf Management" (that book's random_to_sphere; this book's
 * #ch-directions and #ch-lights): from a point outside a sphere of radius R
 * at distance d, the sphere fills the cone of half-angle theta_max with
 * sin theta_max = R / d, so cos theta_max = sqrt(1 - R^2 / d^2); sampling
 * that cone uniformly samples every direction that can hit the sphere, and
 * nothing else. The book's formula takes the square root of a negative
 * number from inside the sphere (NaN); here every direction hits the sphere
 * from inside, so the cone is the whole sphere: cos theta_max = -1. Exactly
 * on the surface (the book's tangent case, whose exact answer is the
 * hemisphere, cos theta_max = 0) the agreed contract also returns -1: a
 * superset of the directions that hit, which keeps an estimator that
 * samples the cone unbiased, and the same answer as a point a rounding
 * error inside.
 *
 * Two parameterizations of the same cone. The cone's solid angle is
 * 2 pi h with h = 1 - cos theta_max, the height of the cap it cuts from the
 * unit sphere (Archimedes), and every density and warp below needs h, not
 * the cosine. When the cosine is the given datum (a cone of 60 degrees),
 * 1 - cos theta_max is accurate to an ulp and the smp_uniform_cone trio is
 * the natural interface. When the cone comes from a sphere, the cosine is
 * 1 - R^2 / (2 d^2) rounded next to 1: for a small or far sphere the
 * subtraction 1 - cos theta_max keeps only the rounding error (relative
 * error ~2e-16 d^2 / R^2: percent level at R / d = 1e-7, and h = 0, an
 * infinite density, below R / d ~ 1e-8). So the sphere's h is computed
 * directly, as (R^2 / d^2) / (1 + cos theta_max) (smp_sphere_cone_
 * one_minus_cos), and carried to the smp_uniform_cap trio, which never
 * forms 1 - cos theta_max.
 */
#ifndef SMP_CONE_H
#define SMP_CONE_H

#include "mc/vec2.h"
#include "mc/vec3.h"

/* --- the cone given by h = 1 - cos theta_max (the cap's height) ---------- */

/* 1 - cos theta = u2 h, phi = 2 pi u1: 1 - cos theta is uniform on [0, h]
 * because the solid angle is linear in cos theta. sin theta is taken from
 * 1 - cos theta (not from the rounded cosine), so a cone thinner than the
 * spacing of doubles below 1 (h < 1e-16) still gets directions spread over
 * its whole width. one_minus_cos = h in (0, 2] (2: the whole sphere, 1:
 * the hemisphere). */
vec3 smp_uniform_cap_sample(double u1, double u2, double one_minus_cos);
/* 1 / (2 pi h) per unit solid angle for unit w with 1 - w.z <= h, else 0;
 * 2 pi h is the cone's solid angle. 1 - w.z is evaluated as
 * (x^2 + y^2) / (1 + z) for z > 0, which keeps its relative accuracy near
 * the axis. 0 for h <= 0 (an empty cone has no density). */
double smp_uniform_cap_pdf(vec3 w, double one_minus_cos);
/* (phi / 2 pi, (1 - w.z) / h) for unit w, with 1 - w.z as in the pdf. */
vec2 smp_uniform_cap_invert(vec3 w, double one_minus_cos);

/* --- the cone given by cos theta_max ------------------------------------- */

/* smp_uniform_cap_sample with h = 1 - cos_theta_max. cos_theta_max in
 * [-1, 1) (-1: the whole sphere, 0: the hemisphere). */
vec3 smp_uniform_cone_sample(double u1, double u2, double cos_theta_max);
/* 1 / (2 pi (1 - cos_theta_max)) per unit solid angle for z >=
 * cos_theta_max, else 0; the denominator is the cone's solid angle. */
double smp_uniform_cone_pdf(vec3 w, double cos_theta_max);
/* smp_uniform_cap_invert with h = 1 - cos_theta_max:
 * (phi / 2 pi, (1 - z) / (1 - cos_theta_max)). */
vec2 smp_uniform_cone_invert(vec3 w, double cos_theta_max);

/* --- the cone a sphere subtends ------------------------------------------ */

/* The cosine of the half-angle of the cone of directions from a point at
 * squared distance dist_sq from the centre of a sphere of radius radius
 * (radius >= 0): sqrt(1 - radius^2 / dist_sq) outside the sphere, -1 from
 * inside or on it (the whole sphere of directions, instead of the book's
 * NaN). Computed as sqrt((d^2 - R^2) / d^2), which cannot exceed 1. The
 * cosine itself is accurate to an ulp, but for R / d below ~1e-8 it is
 * exactly 1: use it to test directions against the rim, and
 * smp_sphere_cone_one_minus_cos for the cone's size. Returns 1 for
 * radius = 0 (a point). */
double smp_sphere_cone_cos_theta_max(double dist_sq, double radius);

/* h = 1 - cos theta_max of the same cone, to a few ulps relative at every
 * R / d: (R^2 / d^2) / (1 + sqrt(1 - R^2 / d^2)), since
 * 1 - cos = sin^2 / (1 + cos) and sin theta_max = R / d. 2 from inside or
 * on the sphere (the whole sphere of directions, matching
 * smp_sphere_cone_cos_theta_max's -1). 0 for radius = 0 (a point: callers
 * must not sample it). Accurate while radius^2 and radius^2 / dist_sq are
 * normal doubles (radius > 1.5e-154 and R / d > 1.5e-154). */
double smp_sphere_cone_one_minus_cos(double dist_sq, double radius);

/* Both numbers of the cone at once, from one square root and the same
 * expressions: *cos_theta_max receives smp_sphere_cone_cos_theta_max and
 * the result is smp_sphere_cone_one_minus_cos, bit for bit (the pdf
 * objects and the renderer evaluate them at every diffuse hit). */
double smp_sphere_cone_cap(double dist_sq, double radius, double *cos_theta_max);

#endif /* SMP_CONE_H */
