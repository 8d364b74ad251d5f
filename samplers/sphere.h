/* samplers/sphere.h - uniform directions on the whole unit sphere, three
 * ways.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), the second
 * chapter 2 "MC Integration on the Sphere of Directions" and chapter 5
 * "Generating Random Directions" (this book's #ch-sphere): the inverse-CDF
 * mapping (z uniform in [-1, 1], Archimedes' hat-box theorem), a normalized
 * vector of three independent normals (the Gaussian is rotation invariant),
 * and rejection from the unit ball (that book's random_in_unit_sphere,
 * normalized). All three have the density 1/(4 pi) per unit solid angle;
 * the tests check that they agree.
 */
#ifndef SMP_SPHERE_H
#define SMP_SPHERE_H

#include "mc/rng.h"
#include "mc/vec2.h"
#include "mc/vec3.h"

/* phi = 2 pi u1, z = 1 - 2 u2 (u1, u2 in [0,1)): the unit direction. */
vec3 smp_uniform_sphere_sample(double u1, double u2);
/* 1/(4 pi) per unit solid angle, for every unit w. */
double smp_uniform_sphere_pdf(vec3 w);
/* (phi / 2 pi, (1 - z) / 2) of the unit direction w. */
vec2 smp_uniform_sphere_invert(vec3 w);

/* Box-Muller turns (u1, u2) and (u3, u4), each in [0,1)^2, into four
 * independent standard normals; three of them, normalized, are uniform on
 * the sphere. If all three are 0 the result is +z: that needs u1 = 0 and
 * either u3 = 0 or cos(2 pi u4) = 0, which mc_sincos_turn makes exact at
 * u4 = 1/4 and 3/4; with 32-bit uniforms (mc_rng_uniform) the probability
 * is about 3 * 2^-64. No inverse: the map is many to one. */
vec3 smp_uniform_sphere_sample_gaussian(double u1, double u2, double u3, double u4);

/* Draws points of the cube [-1,1)^3 from rng until one lies in the unit
 * ball (not at its centre), and normalizes it. Acceptance probability
 * pi/6, so 6/pi = 1.91 tries (5.7 uniforms) per direction on average. */
vec3 smp_uniform_sphere_sample_rejection(mc_rng *rng);

#endif /* SMP_SPHERE_H */
