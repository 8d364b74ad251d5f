/* samplers/cone.h - uniform directions in a cone about +z, and the cone
 * that a sphere subtends from a point.
 *
 * Chapter 10 ("Cleaning Up pdf Management", the book's random_to_sphere):
 * from a point outside a sphere of radius R at distance d, the sphere fills
 * the cone of half-angle theta_max with sin theta_max = R / d, so
 * cos theta_max = sqrt(1 - R^2 / d^2); sampling that cone uniformly samples
 * every direction that can hit the sphere, and nothing else. The book's
 * formula takes the square root of a negative number from inside the sphere
 * (NaN); here every direction hits the sphere from inside, so the cone is
 * the whole sphere: cos theta_max = -1. Exactly on the surface (the book's
 * tangent case, whose exact answer is the hemisphere, cos theta_max = 0) the
 * agreed contract also returns -1: a superset of the directions that hit,
 * which keeps an estimator that samples the cone unbiased, and the same
 * answer as a point a rounding error inside.
 */
#ifndef SMP_CONE_H
#define SMP_CONE_H

#include "mc/vec2.h"
#include "mc/vec3.h"

/* z = 1 - u2 (1 - cos_theta_max), phi = 2 pi u1: z uniform on
 * [cos_theta_max, 1] because the solid angle is linear in cos theta.
 * cos_theta_max in [-1, 1) (-1: the whole sphere, 0: the hemisphere). */
vec3 smp_uniform_cone_sample(double u1, double u2, double cos_theta_max);
/* 1 / (2 pi (1 - cos_theta_max)) per unit solid angle for z >= cos_theta_max,
 * else 0; the denominator is the cone's solid angle. */
double smp_uniform_cone_pdf(vec3 w, double cos_theta_max);
/* (phi / 2 pi, (1 - z) / (1 - cos_theta_max)). */
vec2 smp_uniform_cone_invert(vec3 w, double cos_theta_max);

/* The cosine of the half-angle of the cone of directions from a point at
 * squared distance dist_sq from the centre of a sphere of radius radius
 * (radius >= 0): sqrt(1 - radius^2 / dist_sq) outside the sphere, -1 from
 * inside or on it (the whole sphere of directions, instead of the book's
 * NaN). Computed as sqrt((d^2 - R^2) / d^2), which cannot exceed 1; that
 * form is not where accuracy is lost. The cancellation that matters is in
 * the cone's solid angle 2 pi (1 - cos_theta_max) ~ pi R^2 / d^2 for tiny
 * R / d: cos_theta_max is 1 - R^2 / (2 d^2) rounded next to 1 (absolute
 * error ~1e-16), so 1 - cos_theta_max, and with it the cone pdf, has a
 * relative error of about 2e-16 d^2 / R^2: percent level at R / d = 1e-7,
 * worse below. Once R / d is below about 1e-8 the result is exactly 1 and
 * the cone pdf is +inf. This is a known limitation (pdf_valid rejects
 * cos_theta_max == 1). Returns 1 for radius = 0 too (a point: callers must
 * not sample a sphere of radius 0). */
double smp_sphere_cone_cos_theta_max(double dist_sq, double radius);

#endif /* SMP_CONE_H */
