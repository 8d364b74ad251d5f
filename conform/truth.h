/* conform/truth.h - the exact value of every pixel of a conformance scene.
 *
 * A pixel's value is the mean, over the pixel's square of the image plane,
 * of the radiance arriving along the camera ray through each point
 * (conform/conform.h's conventions). The radiance along one ray is a
 * closed form per scene:
 * - furnace-grey: every ray ends on the wall, which returns its emission
 *   E plus rho times what it receives, the same everywhere by symmetry:
 *   L = E + rho L, so L = E / (1 - rho).
 * - furnace-white: the sky L_s lights the white sphere evenly; a
 *   Lambertian surface of albedo 1 under uniform radiance L_s returns L_s,
 *   and so does every ray that misses it.
 * - quad-wall: the floor reflects rho / pi times its irradiance, and the
 *   irradiance from a polygon of uniform radiance L wholly above the
 *   point's tangent plane is Lambert's formula, L / 2 times the sum over
 *   the polygon's edges of the angle the edge subtends times the cosine
 *   between the floor's normal and the normal of the plane through the
 *   point and the edge (Arvo 1995 [@arvo1995-tensors], "Applications of Irradiance Tensors to
 *   the Simulation of Non-Lambertian Phenomena", eq. 10: the projected
 *   solid angle as a contour integral).
 * - sphere-wall: a sphere of uniform radiance L and radius r wholly above
 *   the tangent plane gives the irradiance of a point source of intensity
 *   pi r^2 L at its centre, E = L pi r^2 cos(theta) / d^2 (the projected
 *   solid angle of the cone it fills is pi sin^2(alpha) cos(theta) with
 *   sin(alpha) = r / d).
 * - sphere-horizon: the same sphere cut by the floor's plane: the part of
 *   its cone above the horizon, L times the integral of cos(theta) over
 *   it, in closed form along each ray of the cone's azimuth and by
 *   quadrature in the azimuth (cf_sphere_irradiance_clipped).
 * - glass-slab: the emitter is seen straight through the slab after 2k
 *   inner reflections, k = 0, 1, ...: L (1 - R)^2 (1 + R^2 + R^4 + ...)
 *   = L (1 - R) / (1 + R), R the unpolarized reflectance of the entry
 *   angle (the same at both faces, which are parallel). A renderer that
 *   does not follow polarization, as none of the ones these files are for
 *   does, computes exactly this.
 * The pixel mean is taken by a product Gauss-Legendre rule on the pixel,
 * compared with one of higher order and halved where they disagree.
 */
#ifndef CF_TRUTH_H
#define CF_TRUTH_H

#include "conform/conform.h"
#include "mc/vec3.h"

/* The radiance arriving at the camera along the unit direction d from the
 * scene's lookfrom, by the closed form above. */
double cf_radiance_along(const cf_scene *s, vec3 d);

/* Lambert's formula: the irradiance at p (unit normal n) from the
 * parallelogram q + a u + b v, (a, b) in [0, 1]^2, of uniform radiance L,
 * emitting from its front face (toward u x v) only. The parallelogram must
 * lie wholly on the side of p's tangent plane that n points to (0 is
 * returned for a point behind the emitter). */
double cf_quad_irradiance(vec3 p, vec3 n, vec3 q, vec3 u, vec3 v, double radiance);

/* The irradiance at p (unit normal n) from a sphere of uniform radiance L
 * wholly above p's tangent plane. */
double cf_sphere_irradiance(vec3 p, vec3 n, vec3 center, double radius, double radiance);

/* The same for a sphere whose centre is above p's tangent plane but which
 * the plane cuts: the irradiance L times the integral of the receiver's
 * cosine over the part of the sphere's cone above the plane, by the
 * closed form of the integral along each ray of the cone's azimuth and
 * Gauss-Legendre rules in the azimuth between the kinks (where the
 * horizon meets the cone's rim). cf_sphere_irradiance when the sphere is
 * wholly above the plane; NaN when its centre is not above it. */
double cf_sphere_irradiance_clipped(vec3 p, vec3 n, vec3 center, double radius, double radiance);

/* The exact pixel means of the scene at width x height (>= 1 each):
 * value[j * width + i] for pixel (i, j), rows from the top, one value per
 * pixel (the scenes are grey). *max_error (may be NULL) receives the
 * largest estimated quadrature error over the pixels. Returns 0, or -1 for
 * bad arguments. */
int cf_truth_image(const cf_scene *s, int width, int height, double *value, double *max_error);

#endif /* CF_TRUTH_H */
