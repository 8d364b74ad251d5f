/* samplers/lobes.h - glossy lobes about +z: the Phong lobe cos^n theta and
 * the GGX (Trowbridge-Reitz) microfacet distribution.
 *
 * From the table of hemisphere mappings in the lecture slides "Solving the
 * Rendering Equation"; they extend Shirley, "Ray Tracing: The Rest of Your
 * Life" (v1.123), chapter 5 "Generating Random Directions" beyond the
 * Lambertian case (this book's #ch-directions). Densities are per unit
 * SOLID ANGLE on the hemisphere z >= 0; phi = 2 pi u1 and u2 drives the
 * polar angle, as in samplers/hemisphere.h.
 */
#ifndef SMP_LOBES_H
#define SMP_LOBES_H

#include "mc/vec2.h"
#include "mc/vec3.h"

/* --- Phong lobe --------------------------------------------------------- */

/* cos theta = (1 - u2)^(1/(n+1)), the inverse of the CDF 1 - cos^(n+1) of
 * the polar marginal (n+1) cos^n sin. n >= 0 (n = 0 is uniform, n = 1
 * cosine-weighted). */
vec3 smp_phong_lobe_sample(double u1, double u2, double n);
/* (n+1)/(2 pi) cos^n theta per unit solid angle for z >= 0, else 0: the
 * integral of cos^n over the hemisphere is 2 pi / (n+1). */
double smp_phong_lobe_pdf(vec3 w, double n);
/* (phi / 2 pi, 1 - cos^(n+1) theta). */
vec2 smp_phong_lobe_invert(vec3 w, double n);

/* --- GGX / Trowbridge-Reitz half vectors -------------------------------- */

/* The microfacet normal h with cos^2 theta_h = (1 - u2) / (u2 (alpha^2 - 1)
 * + 1), the inverse CDF of the polar marginal 2 pi D cos sin. alpha in
 * (0, 1]: the roughness (the lecture slides "Solving the Rendering
 * Equation" set alpha = r_p^2). */
vec3 smp_ggx_sample(double u1, double u2, double alpha);
/* D(h) cos theta_h per unit solid angle, where
 * D = alpha^2 / (pi (cos^2 theta_h (alpha^2 - 1) + 1)^2) is the normal
 * distribution (whose projected area integrates to 1, which is why this is a
 * density); 0 for z < 0. */
double smp_ggx_pdf(vec3 h, double alpha);
/* (phi / 2 pi, u2) with u2 = (1 - c) / (c (alpha^2 - 1) + 1), c = cos^2 theta_h. */
vec2 smp_ggx_invert(vec3 h, double alpha);

#endif /* SMP_LOBES_H */
