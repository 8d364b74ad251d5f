/* samplers/hemisphere.h - directions on the hemisphere about +z: uniform,
 * cosine-weighted (three mappings) and uniform in (theta, phi).
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 3 "Light
 * Scattering" (the Lambertian pdf cos theta / pi) and chapter 5 "Generating
 * Random Directions" (this book's #ch-scattering and #ch-directions); an
 * onb (mc/onb.h) carries the results to a surface normal ((v1.123)
 * chapter 6 "Ortho-normal Bases"; this book's #ch-onb). Every density is
 * per unit SOLID ANGLE. Coordinates: u1 drives the azimuth phi = 2 pi u1,
 * u2 the polar angle. The hemisphere is z >= 0; its rim z = 0 has measure
 * zero, where the cosine density is 0.
 */
#ifndef SMP_HEMISPHERE_H
#define SMP_HEMISPHERE_H

#include "mc/vec2.h"
#include "mc/vec3.h"

/* --- uniform ------------------------------------------------------------ */

/* z = 1 - u2 (uniform in (0, 1]), phi = 2 pi u1. */
vec3 smp_uniform_hemisphere_sample(double u1, double u2);
/* 1/(2 pi) per unit solid angle for z >= 0, else 0; w unit. */
double smp_uniform_hemisphere_pdf(vec3 w);
/* (phi / 2 pi, 1 - z). */
vec2 smp_uniform_hemisphere_invert(vec3 w);

/* A uniform sphere direction (smp_uniform_sphere_sample) with z replaced by
 * |z|: the lower half folds onto the upper, doubling the density to
 * 1/(2 pi), so its pdf is smp_uniform_hemisphere_pdf. No inverse (two to
 * one). */
vec3 smp_hemisphere_flip_sample(double u1, double u2);

/* --- cosine-weighted: density cos theta / pi ---------------------------- */

/* The book's mapping: z = sqrt(1 - u2), phi = 2 pi u1. It is exactly the
 * polar disc sample (r^2 = u2) lifted to the hemisphere. */
vec3 smp_cosine_hemisphere_sample(double u1, double u2);
/* Malley's method [@malley1988]: a concentric-disc point (x, y) lifted to
 * z = sqrt(1 - x^2 - y^2). Uniform in area below, cosine-weighted above,
 * because the projection onto the disc has Jacobian cos theta. */
vec3 smp_cosine_hemisphere_sample_malley(double u1, double u2);
/* The mapping of the Cranberry Lair blog post deriving cosine-lobe
 * sampling: theta = acos(1 - 2 u2) / 2. Since
 * cos^2 theta = (1 + cos 2 theta) / 2 = 1 - u2, this is the book's mapping
 * written through angles (equal as functions of u, up to rounding). */
vec3 smp_cosine_hemisphere_sample_acos(double u1, double u2);
/* cos theta / pi = z / pi per unit solid angle for z > 0, else 0; w unit. */
double smp_cosine_hemisphere_pdf(vec3 w);
/* Inverse of the book's mapping: (phi / 2 pi, 1 - z^2), with 1 - z^2 taken
 * as x^2 + y^2 for precision near the pole. */
vec2 smp_cosine_hemisphere_invert(vec3 w);
/* Inverse of Malley's: smp_disc_concentric_invert of (x, y). */
vec2 smp_cosine_hemisphere_invert_malley(vec3 w);
/* Inverse of the acos mapping: (phi / 2 pi, sin^2 theta). Since
 * (1 - cos 2 theta) / 2 = sin^2 theta = 1 - z^2, the acos mapping is the
 * book's mapping, and this is smp_cosine_hemisphere_invert. */
vec2 smp_cosine_hemisphere_invert_acos(vec3 w);

/* --- uniform in (theta, phi): the Riemann-sum mapping ------------------- */

/* theta = (pi/2) u2, phi = 2 pi u1: uniform in the angles, NOT in solid
 * angle; directions crowd at the pole. */
vec3 smp_theta_phi_sample(double u1, double u2);
/* The angle density 1 / (2 pi * pi/2) divided by the Jacobian sin theta of
 * d omega = sin theta d theta d phi: 1 / (pi^2 sin theta) per unit solid
 * angle for z >= 0, else 0. Unbounded at the pole: +infinity for w = +z
 * exactly (an integrable singularity; the sampler reaches it only for
 * u2 = 0). */
double smp_theta_phi_pdf(vec3 w);
/* (phi / 2 pi, theta / (pi/2)). */
vec2 smp_theta_phi_invert(vec3 w);

#endif /* SMP_HEMISPHERE_H */
