/* samplers/cone.c - uniform directions in a cone; the cone of a sphere. */
#include "samplers/cone.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/spherical.h"

vec3 smp_uniform_cone_sample(double u1, double u2, double cos_theta_max)
{
    /* The cap above cos theta_max has solid angle 2 pi (1 - cos theta_max),
     * linear in cos theta: cos theta is uniform on [cos theta_max, 1]. */
    double z = 1.0 - u2 * (1.0 - cos_theta_max);
    return smp_spherical_direction_turn(z, u1);
}

double smp_uniform_cone_pdf(vec3 w, double cos_theta_max)
{
    return w.z >= cos_theta_max ? 1.0 / (MC_2PI * (1.0 - cos_theta_max)) : 0.0;
}

vec2 smp_uniform_cone_invert(vec3 w, double cos_theta_max)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, (1.0 - w.z) / (1.0 - cos_theta_max));
}

double smp_sphere_cone_cos_theta_max(double dist_sq, double radius)
{
    double r2 = radius * radius;
    /* From inside (or on) the sphere every ray hits it: the whole sphere of
     * directions, where the book's sqrt(1 - R^2/d^2) is NaN. */
    if (!(dist_sq > r2))
        return -1.0;
    return sqrt((dist_sq - r2) / dist_sq);
}
