/* samplers/lobes.c - the Phong lobe and GGX half-vector sampling.
 *
 * Both densities depend on theta only; each sample draws cos theta by
 * inverting the CDF of its polar marginal and phi = 2 pi u1.
 */
#include "samplers/lobes.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/spherical.h"

/* BEGIN SNIPPET phong_lobe */
vec3 smp_phong_lobe_sample(double u1, double u2, double n)
{
    /* In z = cos theta the marginal is (n+1) z^n on [0, 1], CDF z^(n+1);
     * solving z^(n+1) = 1 - u2 keeps z > 0 for u2 < 1. */
    double z = pow(1.0 - u2, 1.0 / (n + 1.0));
    return smp_spherical_direction_turn(z, u1);
}

double smp_phong_lobe_pdf(vec3 w, double n)
{
    /* The normalization: the integral of cos^n over the hemisphere is
     * 2 pi * int_0^1 z^n dz = 2 pi / (n + 1). */
    return w.z >= 0.0 ? (n + 1.0) * MC_INV_2PI * pow(w.z, n) : 0.0;
}

vec2 smp_phong_lobe_invert(vec3 w, double n)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, 1.0 - pow(w.z, n + 1.0));
}
/* END SNIPPET phong_lobe */

/* BEGIN SNIPPET ggx */
vec3 smp_ggx_sample(double u1, double u2, double alpha)
{
    /* With t = tan^2 theta, cos^2 (alpha^2 - 1) + 1 = cos^2 (alpha^2 + t) and
     * dt = 2 sin / cos^3 d theta turn the marginal 2 pi D cos sin d theta
     * into alpha^2 / (alpha^2 + t)^2 dt, whose CDF is t / (t + alpha^2).
     * Setting it to u2 and writing cos^2 = 1 / (1 + t) gives
     * cos^2 theta = (1 - u2) / (u2 (alpha^2 - 1) + 1); u2 < 1 keeps it > 0. */
    double a2 = alpha * alpha;
    double c2 = (1.0 - u2) / (u2 * (a2 - 1.0) + 1.0);
    return smp_spherical_direction_turn(sqrt(c2), u1);
}

double smp_ggx_pdf(vec3 h, double alpha)
{
    if (h.z < 0.0)
        return 0.0;
    double a2 = alpha * alpha, c2 = h.z * h.z;
    double d = c2 * (a2 - 1.0) + 1.0;
    /* D(h) cos theta_h: D alone integrates to 1 only against the projected
     * solid angle cos theta d omega. */
    return a2 / (MC_PI * d * d) * h.z;
}

vec2 smp_ggx_invert(vec3 h, double alpha)
{
    double a2 = alpha * alpha, c2 = h.z * h.z;
    return vec2_make(smp_spherical_phi(h) * MC_INV_2PI, (1.0 - c2) / (c2 * (a2 - 1.0) + 1.0));
}
/* END SNIPPET ggx */
