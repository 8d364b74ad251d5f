/* samplers/spherical.h - spherical coordinates about +z, shared by every
 * directional warp and by the tests that histogram directions.
 *
 * A direction is (sin theta cos phi, sin theta sin phi, cos theta); theta is
 * the angle from +z, phi in [0, 2 pi) the azimuth from +x towards +y. The
 * warps take cos theta rather than theta because d omega = d(cos theta) d phi:
 * in (cos theta, phi) a density per unit solid angle is a plain density of
 * the rectangle [-1, 1] x [0, 2 pi). Serves this book's #ch-sphere and
 * #ch-directions.
 */
#ifndef SMP_SPHERICAL_H
#define SMP_SPHERICAL_H

#include <math.h>

#include "mc/constants.h"
#include "mc/trig.h"
#include "mc/vec3.h"

/* The unit direction with polar cosine cos_theta (in [-1, 1]) and azimuth
 * phi (radians, any value). sin theta is taken as sqrt(1 - cos^2), clamped
 * at 0 so that a cos_theta of 1 + 1 ulp cannot give NaN. */
static inline vec3 smp_spherical_direction(double cos_theta, double phi)
{
    double sin_theta = sqrt(fmax(0.0, (1.0 - cos_theta) * (1.0 + cos_theta)));
    return vec3_make(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

/* BEGIN SNIPPET spherical_direction_turn */
/* The same direction with azimuth phi = 2 pi u, u a fraction of a turn
 * (the samplers' u in [0, 1)). mc_sincos_turn reduces u exactly, which
 * makes this both cheaper than cos and sin of the product 2 pi u and more
 * accurate (it skips that product's rounding). */
static inline vec3 smp_spherical_direction_turn(double cos_theta, double u)
{
    /* The clamp as a comparison rather than fmax, which gcc leaves as a
     * library call on this hot path; NaN maps to 0 either way. */
    double s2 = (1.0 - cos_theta) * (1.0 + cos_theta);
    double sin_theta = sqrt(s2 > 0.0 ? s2 : 0.0);
    double s, c;
    mc_sincos_turn(u, &s, &c);
    return vec3_make(sin_theta * c, sin_theta * s, cos_theta);
}
/* END SNIPPET spherical_direction_turn */

/* The azimuth of w in [0, 2 pi); 0 on the z axis. */
static inline double smp_spherical_phi(vec3 w)
{
    double phi = atan2(w.y, w.x);
    /* atan2 returns (-pi, pi]; adding 2 pi to a tiny negative angle can round
     * to exactly 2 pi, which is outside [0, 2 pi). */
    if (phi < 0.0) {
        phi += MC_2PI;
        if (phi >= MC_2PI)
            phi = 0.0;
    }
    return phi;
}

/* The polar angle of w (w need not be unit length) in [0, pi]. atan2 of
 * (|w_xy|, z) keeps full precision near both poles, where acos(z) loses
 * half its digits. */
static inline double smp_spherical_theta(vec3 w)
{
    return atan2(sqrt(w.x * w.x + w.y * w.y), w.z);
}

#endif /* SMP_SPHERICAL_H */
