/* samplers/cone.c - uniform directions in a cone; the cone of a sphere. */
#include "samplers/cone.h"

#include <math.h>

#include "mc/constants.h"
#include "mc/trig.h"
#include "samplers/spherical.h"

/* BEGIN SNIPPET uniform_cap */
/* 1 - w.z for a unit w. Near the axis 1 - z cancels (z is 1 rounded); the
 * identity 1 - z = (1 - z^2) / (1 + z) = (x^2 + y^2) / (1 + z) carries the
 * full relative accuracy of x and y instead. Below the equator 1 - z >= 1
 * and the plain subtraction is exact to an ulp. */
static double one_minus_z(vec3 w)
{
    return w.z > 0.0 ? (w.x * w.x + w.y * w.y) / (1.0 + w.z) : 1.0 - w.z;
}

vec3 smp_uniform_cap_sample(double u1, double u2, double one_minus_cos)
{
    /* The cap above cos theta_max has solid angle 2 pi h, linear in
     * cos theta: 1 - cos theta is uniform on [0, h]. With t = 1 - cos theta,
     * sin^2 theta = (1 - cos)(1 + cos) = t (2 - t), exact in t, so the
     * direction keeps its angle even when cos theta rounds to 1. */
    double t = u2 * one_minus_cos;
    double s2 = t * (2.0 - t);
    double sin_theta = sqrt(s2 > 0.0 ? s2 : 0.0);
    double s, c;
    mc_sincos_turn(u1, &s, &c);
    return vec3_make(sin_theta * c, sin_theta * s, 1.0 - t);
}

double smp_uniform_cap_pdf(vec3 w, double one_minus_cos)
{
    return one_minus_cos > 0.0 && one_minus_z(w) <= one_minus_cos
               ? 1.0 / (MC_2PI * one_minus_cos)
               : 0.0;
}

vec2 smp_uniform_cap_invert(vec3 w, double one_minus_cos)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, one_minus_z(w) / one_minus_cos);
}
/* END SNIPPET uniform_cap */

/* BEGIN SNIPPET uniform_cone */
vec3 smp_uniform_cone_sample(double u1, double u2, double cos_theta_max)
{
    return smp_uniform_cap_sample(u1, u2, 1.0 - cos_theta_max);
}

double smp_uniform_cone_pdf(vec3 w, double cos_theta_max)
{
    return w.z >= cos_theta_max ? 1.0 / (MC_2PI * (1.0 - cos_theta_max)) : 0.0;
}

vec2 smp_uniform_cone_invert(vec3 w, double cos_theta_max)
{
    return smp_uniform_cap_invert(w, 1.0 - cos_theta_max);
}
/* END SNIPPET uniform_cone */

/* BEGIN SNIPPET sphere_cone_cap */
double smp_sphere_cone_cap(double dist_sq, double radius, double *cos_theta_max)
{
    double r2 = radius * radius;
    /* From inside (or on) the sphere every ray hits it: the whole sphere of
     * directions (cos theta_max = -1), where the book's sqrt(1 - R^2/d^2) is
     * NaN. */
    if (!(dist_sq > r2)) {
        *cos_theta_max = -1.0;
        return 2.0;
    }
    /* (d^2 - R^2) / d^2 cannot exceed 1, unlike 1 - R^2/d^2 rounded. */
    double c = sqrt((dist_sq - r2) / dist_sq);
    *cos_theta_max = c;
    /* 1 - cos = (1 - cos^2) / (1 + cos) = sin^2 theta_max / (1 + cos): a
     * quotient of two accurate numbers (sin^2 = R^2 / d^2 to an ulp, and
     * 1 + cos in [1, 2]), where 1 - cos subtracts two nearly equal ones. */
    return (r2 / dist_sq) / (1.0 + c);
}
/* END SNIPPET sphere_cone_cap */

double smp_sphere_cone_cos_theta_max(double dist_sq, double radius)
{
    double c;
    smp_sphere_cone_cap(dist_sq, radius, &c);
    return c;
}

double smp_sphere_cone_one_minus_cos(double dist_sq, double radius)
{
    double c;
    return smp_sphere_cone_cap(dist_sq, radius, &c);
}
