/* render/ray.h - rays, hit records and axis-aligned boxes: the vocabulary
 * every part of the renderer shares.
 *
 * Serves the Cornell box of chapters 4-10 of "Ray Tracing: The Rest of Your
 * Life" (the scene every chapter renders) and the BVH of the cranberray
 * posts. Directions of rays are unit length everywhere in render/: the pdf
 * objects (pdf/pdf.h) require it, and it turns the ray parameter t into a
 * distance, which the light densities need.
 */
#ifndef RT_RAY_H
#define RT_RAY_H

#include <stdbool.h>

#include "mc/vec3.h"

/* The half line origin + t dir, t > 0; dir unit length. */
typedef struct rt_ray {
    vec3 origin;
    vec3 dir;
} rt_ray;

/* The ray from origin along dir (the caller normalizes dir). */
static inline rt_ray rt_ray_make(vec3 origin, vec3 dir)
{
    rt_ray r = {origin, dir};
    return r;
}

/* The point origin + t dir. */
static inline vec3 rt_ray_at(rt_ray r, double t) { return vec3_madd(r.origin, r.dir, t); }

/* Where a ray met a surface. The book's "set_face_normal" convention:
 * `normal` is the unit surface normal turned to face the incoming ray, and
 * `front_face` says whether the ray arrived on the side the geometric
 * (outward) normal points to. Emitters shine from their front face only. */
typedef struct rt_hit {
    double t;        /* distance along the ray */
    vec3 p;          /* the point */
    vec3 normal;     /* unit, dot(normal, ray.dir) <= 0 */
    bool front_face; /* dot(geometric normal, ray.dir) < 0 */
    int material;    /* index into the scene's material table */
    int prim;        /* index of the primitive (scene-internal numbering) */
} rt_hit;

/* An axis-aligned box [lo, hi] (componentwise). */
typedef struct rt_aabb {
    vec3 lo, hi;
} rt_aabb;

/* The empty box (lo = +inf, hi = -inf): the identity of rt_aabb_union. */
static inline rt_aabb rt_aabb_empty(void)
{
    rt_aabb b = {vec3_make(HUGE_VAL, HUGE_VAL, HUGE_VAL), vec3_make(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL)};
    return b;
}

/* The smallest box holding a and b. */
static inline rt_aabb rt_aabb_union(rt_aabb a, rt_aabb b)
{
    rt_aabb u = {vec3_min(a.lo, b.lo), vec3_max(a.hi, b.hi)};
    return u;
}

/* The smallest box holding a and the point p. */
static inline rt_aabb rt_aabb_add_point(rt_aabb a, vec3 p)
{
    rt_aabb u = {vec3_min(a.lo, p), vec3_max(a.hi, p)};
    return u;
}

/* Surface area of the box (0 for the empty box). The SAH uses it: a random
 * line that meets a convex parent meets a convex child inside it with
 * probability area(child) / area(parent), since the mean projected area of
 * a convex body is a quarter of its surface area (Cauchy). */
static inline double rt_aabb_area(rt_aabb a)
{
    vec3 e = vec3_sub(a.hi, a.lo);
    if (!(e.x >= 0.0 && e.y >= 0.0 && e.z >= 0.0))
        return 0.0;
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

/* The centre of the box. */
static inline vec3 rt_aabb_center(rt_aabb a) { return vec3_scale(vec3_add(a.lo, a.hi), 0.5); }

#endif /* RT_RAY_H */
