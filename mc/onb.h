/* mc/onb.h - orthonormal bases from a single vector.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 6
 * "Ortho-normal Bases" (this book's #ch-onb) [@shirley-rotl]: samplers produce directions
 * about +z; an ONB (s, t, n) carries them to a surface normal. The
 * construction is Duff et al., "Building an Orthonormal Basis, Revisited"
 * (JCGT 2017) [@duff2017]: no branch on a threshold, no singularity except the sign
 * choice at z = 0, exact to rounding for normals arbitrarily close to +-z.
 * The basis is right-handed: s x t = n.
 */
#ifndef MC_ONB_H
#define MC_ONB_H

#include <math.h>

#include "mc/vec3.h"

/* BEGIN SNIPPET onb_from_w */
typedef struct onb {
    vec3 s, t, n; /* tangent, bitangent, normal; s x t = n */
} onb;

/* The basis with third axis n (n must be unit length). */
static inline onb onb_from_w(vec3 n)
{
    /* copysign gives sign(+0) = +1 and sign(-0) = -1, so both signs of a
     * zero z land on a finite branch. */
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    onb o;
    o.s = vec3_make(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    o.t = vec3_make(b, sign + n.y * n.y * a, -n.y);
    o.n = n;
    return o;
}
/* END SNIPPET onb_from_w */

/* BEGIN SNIPPET onb_to_world_local */
/* The world vector with coordinates (a.x, a.y, a.z) in the basis. */
static inline vec3 onb_to_world(const onb *o, vec3 a)
{
    return vec3_add(vec3_add(vec3_scale(o->s, a.x), vec3_scale(o->t, a.y)), vec3_scale(o->n, a.z));
}

/* The coordinates of the world vector v in the basis. */
static inline vec3 onb_to_local(const onb *o, vec3 v)
{
    return vec3_make(vec3_dot(v, o->s), vec3_dot(v, o->t), vec3_dot(v, o->n));
}
/* END SNIPPET onb_to_world_local */

#endif /* MC_ONB_H */
