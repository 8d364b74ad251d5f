/* mc/vec3.h - the 3-vector value type.
 *
 * Directions, points and colours are all vec3, passed and returned by value
 * (24 bytes: cheaper to copy than to alias). Everything here is static
 * inline so that it costs nothing at -O2 and links at -O0. Serves this
 * book's #ch-sphere onwards.
 */
#ifndef MC_VEC3_H
#define MC_VEC3_H

#include <math.h>
#include <stdbool.h>

typedef struct vec3 {
    double x, y, z;
} vec3;

/* The vector (x, y, z). */
static inline vec3 vec3_make(double x, double y, double z) { vec3 v = {x, y, z}; return v; }
/* a + b. */
static inline vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
/* a - b. */
static inline vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
/* -a. */
static inline vec3 vec3_neg(vec3 a) { return vec3_make(-a.x, -a.y, -a.z); }
/* s a. */
static inline vec3 vec3_scale(vec3 a, double s) { return vec3_make(s * a.x, s * a.y, s * a.z); }
/* Componentwise product (colour times colour). */
static inline vec3 vec3_mul(vec3 a, vec3 b) { return vec3_make(a.x * b.x, a.y * b.y, a.z * b.z); }
/* a + s b, the ray-point form. */
static inline vec3 vec3_madd(vec3 a, vec3 b, double s) { return vec3_make(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
/* The dot product a . b. */
static inline double vec3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/* The cross product a x b (right-handed). */
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* |a|^2. */
static inline double vec3_length_sq(vec3 a) { return vec3_dot(a, a); }
/* |a|. */
static inline double vec3_length(vec3 a) { return sqrt(vec3_dot(a, a)); }
/* a / |a|; the caller guarantees a != 0. */
static inline vec3 vec3_normalize(vec3 a) { return vec3_scale(a, 1.0 / vec3_length(a)); }
/* True when all three components are finite (no NaN, no infinity). */
static inline bool vec3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
/* Component i (0, 1 or 2) of a. */
static inline double vec3_at(vec3 a, int i) { return i == 0 ? a.x : (i == 1 ? a.y : a.z); }
/* Componentwise minimum and maximum. */
static inline vec3 vec3_min(vec3 a, vec3 b) { return vec3_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 vec3_max(vec3 a, vec3 b) { return vec3_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

/* The largest coordinate of v, as fmax(v.x, fmax(v.y, v.z)) gives it (a
 * NaN coordinate is passed over, NaN only when all are), in comparisons
 * that stay inline where fmax is a library call (gcc keeps fmax's NaN
 * rule out of line): Russian roulette takes it at every path vertex. */
static inline double vec3_max_component(vec3 v)
{
    double m = v.y > v.z || v.z != v.z ? v.y : v.z;
    return v.x > m || m != m ? v.x : m;
}

#endif /* MC_VEC3_H */
