/* pdf/experiments.h - the integrals over directions that the chapter
 * programs estimate, and the exact values they are compared with.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), the second
 * chapter 2 "MC Integration on the Sphere of Directions" (this book's
 * #ch-sphere): the integral of f over directions is the mean of f(d) / p(d)
 * for d drawn with a density p per unit solid angle that is positive
 * wherever f is not 0. Here that estimator is written for a pdf object of
 * pdf/pdf.h (the warps of samplers/ have theirs in the catalog,
 * cat_integrate), together with the closed forms the programs
 * sphere_importance, cos_cubed, light_pdf ((v1.123) chapter 7 "Sampling
 * Lights Directly"), sphere_light ((v1.123) chapter 10, and the point light
 * of equal flux of the lecture slides "Solving the Rendering Equation"),
 * mixture ((v1.123) chapter 8 "Mixture Densities") and projected_area (the
 * Cranberry Lair blog post on SAH BVH construction: the mean projected
 * area of a convex body is a quarter of its surface area) print. Library
 * code, so that the tests z-test exactly what the programs compute.
 * Nothing here allocates.
 */
#ifndef PDF_EXPERIMENTS_H
#define PDF_EXPERIMENTS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mc/rng.h"
#include "mc/stats.h"
#include "mc/vec3.h"
#include "pdf/pdf.h"

/* A real function of a unit direction, with its parameters. */
typedef struct pdf_fn {
    double (*f)(vec3 d, void *ctx);
    void *ctx;
} pdf_fn;

/* The estimate of the integral of f over the sphere of directions from
 * n >= 1 directions drawn from p: the mean of f(d) / value(d) with its
 * variance per sample and standard error. A direction whose density is 0
 * contributes 0 (unbiased only if f vanishes wherever p does: the
 * caller's contract). */
mc_estimate pdf_integrate(pdf_fn f, const pdf *p, mc_rng *rng, uint64_t n);

/* The irradiance at x (surface normal n, unit) from a planar convex
 * polygon v[0..k) (k >= 3, in order around its boundary) of uniform
 * radiance L, by Lambert's formula: with a_i the unit vectors from x to the
 * vertices, E = (L / 2) |sum_i gamma_i n . (a_i x a_{i+1}) / |a_i x a_{i+1}||,
 * gamma_i the angle between a_i and a_{i+1}. Each edge with x spans a
 * plane; the sum is the flux of the field of the polygon's spherical
 * projection through the normal. Exact when the whole polygon lies above
 * x's horizon (no clipping); x not in the polygon's plane. */
double pdf_polygon_irradiance(vec3 x, vec3 n, const vec3 *v, size_t k, double radiance);

/* The irradiance at x (normal n) from a Lambertian sphere of radius r and
 * total flux phi at distance d from its centre, whose direction makes the
 * angle theta with n, the sphere wholly above x's horizon: the radiance is
 * L = phi / (4 pi^2 r^2) (exitance pi L over area 4 pi r^2), and the cone
 * of half-angle asin(r / d) gives E = pi L (r / d)^2 cos theta =
 * phi cos theta / (4 pi d^2): exactly a point light of intensity
 * phi / (4 pi). cos_theta = cos theta. */
double pdf_sphere_light_irradiance(double phi, double d, double cos_theta);

/* The irradiance at x (normal n) from the sphere (center, radius) of
 * uniform radiance L, estimated from n_samples points drawn uniformly on
 * the sphere's WHOLE surface (density 1 / (4 pi r^2) per unit area):
 * a point q with outward normal m contributes
 * L max(0, n . w) max(0, -m . w) / |q - x|^2 * 4 pi r^2, w = (q - x) / |q - x|;
 * the far half, facing away, contributes 0 (from outside a sphere the
 * points that face x are exactly the visible ones). x outside the sphere. */
mc_estimate pdf_sphere_light_by_area(vec3 x, vec3 n, vec3 center, double radius, double radiance,
                                     mc_rng *rng, uint64_t n_samples);

/* A convex body centred at the origin: an axis-aligned box with half
 * extents `half` (all > 0), or a sphere of radius `radius` (> 0). */
typedef struct pdf_body {
    bool is_box;
    vec3 half;
    double radius;
} pdf_body;

/* The surface area: 8 (hx hy + hy hz + hz hx) or 4 pi r^2. */
double pdf_body_area(pdf_body b);

/* The area of the body's shadow on a plane perpendicular to the unit
 * direction d: for the box half the sum over its faces of |d . n_f| A_f
 * (each point of the shadow is covered by exactly two faces, one front
 * and one back); pi r^2 for the sphere. */
double pdf_body_projected_area(pdf_body b, vec3 d);

/* The mean projected area over uniformly distributed directions, from n
 * directions (Cauchy's formula says it is area / 4). by_rays false: the
 * exact shadow area in each direction; true: the shadow measured by one
 * ray per direction, aimed at a uniform point of a square window
 * perpendicular to d that covers the body (side 2 R, R the bounding
 * radius), counting window area times hit (0 or 1). */
mc_estimate pdf_mean_projected_area(pdf_body b, bool by_rays, mc_rng *rng, uint64_t n);

#endif /* PDF_EXPERIMENTS_H */
