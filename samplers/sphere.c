/* samplers/sphere.c - uniform directions on the sphere: inverse CDF,
 * normalized Gaussian, rejection from the ball.
 *
 * Density 1/(4 pi) per unit solid angle for all three.
 */
#include "samplers/sphere.h"

#include <math.h>

#include "mc/constants.h"
#include "mc/trig.h"
#include "samplers/spherical.h"

/* BEGIN SNIPPET sphere_inverse */
vec3 smp_uniform_sphere_sample(double u1, double u2)
{
    /* Archimedes: the band between heights z and z + dz has area 2 pi dz for
     * every z in [-1, 1], so z is uniform. */
    return smp_spherical_direction_turn(1.0 - 2.0 * u2, u1);
}

double smp_uniform_sphere_pdf(vec3 w)
{
    (void)w;
    return MC_INV_4PI;
}

vec2 smp_uniform_sphere_invert(vec3 w)
{
    return vec2_make(smp_spherical_phi(w) * MC_INV_2PI, 0.5 * (1.0 - w.z));
}
/* END SNIPPET sphere_inverse */

/* BEGIN SNIPPET sphere_gaussian */
/* Two standard normals from two uniforms (Box-Muller [@box-muller1958]): the radius has
 * P(R > r) = exp(-r^2 / 2), inverted as r = sqrt(-2 ln(1 - u)); 1 - u is in
 * (0, 1] so the logarithm is finite. */
static void box_muller(double u1, double u2, double *g1, double *g2)
{
    double r = sqrt(-2.0 * log1p(-u1)), s, c;
    mc_sincos_turn(u2, &s, &c); /* the angle is 2 pi u2 */
    *g1 = r * c;
    *g2 = r * s;
}

vec3 smp_uniform_sphere_sample_gaussian(double u1, double u2, double u3, double u4)
{
    /* The density of three independent normals depends on |g| only, so
     * g / |g| has the same law in every direction. */
    double x, y, z, unused;
    box_muller(u1, u2, &x, &y);
    box_muller(u3, u4, &z, &unused);
    double len = sqrt(x * x + y * y + z * z);
    if (len == 0.0)
        return vec3_make(0.0, 0.0, 1.0);
    return vec3_make(x / len, y / len, z / len);
}
/* END SNIPPET sphere_gaussian */

/* BEGIN SNIPPET sphere_rejection */
vec3 smp_uniform_sphere_sample_rejection(mc_rng *rng)
{
    /* Accepted points are uniform in the ball, whose density depends on |p|
     * only, so p / |p| is uniform. The centre is refused: it has no
     * direction. Coordinates are multiples of 2^-31, so an accepted
     * r^2 >= 2^-62 and the normalization is exact to rounding. */
    for (;;) {
        double x = 2.0 * mc_rng_uniform(rng) - 1.0;
        double y = 2.0 * mc_rng_uniform(rng) - 1.0;
        double z = 2.0 * mc_rng_uniform(rng) - 1.0;
        double r2 = x * x + y * y + z * z;
        if (r2 > 0.0 && r2 <= 1.0) {
            double len = sqrt(r2);
            return vec3_make(x / len, y / len, z / len);
        }
    }
}
/* END SNIPPET sphere_rejection */
