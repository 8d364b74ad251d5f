/* samplers/hemisphere.c - uniform, flipped, cosine-weighted (three ways)
 * and uniform-angle directions about +z.
 *
 * Densities per unit solid angle; d omega = d(cos theta) d phi, so a
 * density that depends on theta only is sampled by drawing cos theta from
 * its marginal (density 2 pi p in cos theta) and phi uniformly.
 */
#include "samplers/hemisphere.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/spherical.h"

/* BEGIN SNIPPET hemisphere_uniform */
vec3 smp_uniform_hemisphere_sample(double u1, double u2)
{
    /* cos theta uniform on (0, 1]: 1 - u2 keeps u2 = 0 at the pole and never
     * reaches the rim. */
    return smp_spherical_direction_turn(1.0 - u2, u1);
}

double smp_uniform_hemisphere_pdf(vec3 w)
{
    return w.z >= 0.0 ? MC_INV_2PI : 0.0;
}
/* END SNIPPET hemisphere_uniform */

/* BEGIN SNIPPET hemisphere_uniform_invert */
vec2 smp_uniform_hemisphere_invert(vec3 w)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, 1.0 - w.z);
}
/* END SNIPPET hemisphere_uniform_invert */

/* BEGIN SNIPPET hemisphere_flip */
vec3 smp_hemisphere_flip_sample(double u1, double u2)
{
    vec3 w = smp_uniform_sphere_sample(u1, u2);
    w.z = fabs(w.z);
    return w;
}
/* END SNIPPET hemisphere_flip */

/* BEGIN SNIPPET hemisphere_cosine_sample */
vec3 smp_cosine_hemisphere_sample(double u1, double u2)
{
    /* The marginal of z = cos theta is 2 pi (z / pi) = 2 z on [0, 1]; its
     * CDF z^2 = 1 - u2 (1 - u2 rather than u2 keeps z > 0). */
    return smp_spherical_direction_turn(sqrt(1.0 - u2), u1);
}
/* END SNIPPET hemisphere_cosine_sample */

/* BEGIN SNIPPET hemisphere_cosine_malley */
/* Lifts a point of the unit disc straight up onto the hemisphere. */
static vec3 lift(vec2 d)
{
    double z = sqrt(fmax(0.0, 1.0 - d.x * d.x - d.y * d.y));
    return vec3_make(d.x, d.y, z);
}

vec3 smp_cosine_hemisphere_sample_malley(double u1, double u2)
{
    /* Projection onto the disc scales solid angle by cos theta: a density
     * 1/pi per unit disc area is (1/pi) cos theta per unit solid angle. */
    return lift(smp_disc_concentric_sample(u1, u2));
}
/* END SNIPPET hemisphere_cosine_malley */

/* BEGIN SNIPPET hemisphere_cosine_acos */
vec3 smp_cosine_hemisphere_sample_acos(double u1, double u2)
{
    /* The marginal of theta is 2 cos sin = sin 2 theta with CDF
     * (1 - cos 2 theta) / 2 = u2. */
    double theta = 0.5 * acos(1.0 - 2.0 * u2);
    return smp_spherical_direction_turn(cos(theta), u1);
}
/* END SNIPPET hemisphere_cosine_acos */

/* BEGIN SNIPPET hemisphere_cosine_pdf */
double smp_cosine_hemisphere_pdf(vec3 w)
{
    return w.z > 0.0 ? w.z * MC_INV_PI : 0.0;
}
/* END SNIPPET hemisphere_cosine_pdf */

/* BEGIN SNIPPET hemisphere_cosine_invert */
vec2 smp_cosine_hemisphere_invert(vec3 w)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, w.x * w.x + w.y * w.y);
}

vec2 smp_cosine_hemisphere_invert_malley(vec3 w)
{
    return smp_disc_concentric_invert(vec2_make(w.x, w.y));
}

vec2 smp_cosine_hemisphere_invert_acos(vec3 w)
{
    /* u2 = (1 - cos 2 theta) / 2 = sin^2 theta: the same as the book's. */
    return smp_cosine_hemisphere_invert(w);
}
/* END SNIPPET hemisphere_cosine_invert */

/* BEGIN SNIPPET hemisphere_theta_phi */
vec3 smp_theta_phi_sample(double u1, double u2)
{
    double theta = MC_PI_2 * u2, phi = MC_2PI * u1;
    double s = sin(theta);
    return vec3_make(s * cos(phi), s * sin(phi), cos(theta));
}

double smp_theta_phi_pdf(vec3 w)
{
    if (w.z < 0.0)
        return 0.0;
    /* sin theta as |w_xy|: exact near the pole where sqrt(1 - z^2) is not. */
    double sin_theta = sqrt(w.x * w.x + w.y * w.y);
    return sin_theta > 0.0 ? 1.0 / (MC_PI * MC_PI * sin_theta) : (double)INFINITY;
}

vec2 smp_theta_phi_invert(vec3 w)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, smp_spherical_theta(w) / MC_PI_2);
}
/* END SNIPPET hemisphere_theta_phi */
