/* render/shapes.h - the two primitives of the Cornell box: parallelograms
 * ("quads": corner Q, edges u and v) and spheres.
 *
 * The walls, the light and the boxes of chapters 4-10 of Shirley's "Ray
 * Tracing: The Rest of Your Life" (v1.123) are quads; the glass sphere of
 * its chapter 10 is a sphere.
 * Intersection is split in two so that the BVH can stay cheap: the
 * *_hit_distance functions only find the distance (static inline, called
 * for every candidate), and rt_prim_hit_record fills in the point and
 * normal once, for the closest candidate.
 */
#ifndef RT_SHAPES_H
#define RT_SHAPES_H

#include <math.h>

#include "mc/vec3.h"
#include "render/ray.h"

/* The parallelogram q + a u + b v, (a, b) in [0,1]^2, with what the hit
 * test needs precomputed. The geometric (front) normal is unit(u x v). */
typedef struct rt_quad {
    vec3 q, u, v;
    vec3 normal;  /* unit (u x v) */
    double plane; /* normal . q: the plane is normal . p = plane */
    vec3 ea, eb;  /* a = (p - q) . ea, b = (p - q) . eb for p in the plane */
} rt_quad;

/* The sphere |p - center| = radius. orient is +1 for the usual outward
 * front face and -1 for a sphere seen from inside (its normal flipped). */
typedef struct rt_sphere {
    vec3 center;
    double radius;
    double orient;
} rt_sphere;

typedef enum rt_prim_kind { RT_PRIM_QUAD, RT_PRIM_SPHERE } rt_prim_kind;

/* A primitive with its material: what the BVH holds. */
typedef struct rt_prim {
    rt_prim_kind kind;
    int material;
    union {
        rt_quad quad;
        rt_sphere sphere;
    } as;
} rt_prim;

/* The quad with corner q and edges u, v (not parallel, nonzero). */
rt_quad rt_quad_make(vec3 q, vec3 u, vec3 v);

/* The sphere (radius > 0), outward (orient +1) or inward (-1). */
rt_sphere rt_sphere_make(vec3 center, double radius, double orient);

/* Distance to the quad along r within (tmin, tmax), or HUGE_VAL. The edge
 * test is closed (a, b in [0, 1]) so that two quads sharing an edge leave
 * no crack between them. Branch-free: which candidate of a BVH leaf is the
 * nearest is unpredictable, so every one is computed in full and kept by a
 * select rather than by early exits. A ray parallel to the plane
 * gets t = +-inf or NaN (0 / 0 for a ray inside it), which every range
 * test below rejects. */
/* BEGIN SNIPPET quad_hit_distance */
static inline double rt_quad_hit_distance(const rt_quad *s, rt_ray r, double tmin, double tmax)
{
    double t = (s->plane - vec3_dot(s->normal, r.origin)) / vec3_dot(s->normal, r.dir);
    vec3 h = vec3_sub(rt_ray_at(r, t), s->q);
    /* With w = n / |u x v| (n unit), w . (h x v) = a and w . (u x h) = b;
     * by the triple product rule these are h . (v x w) and h . (w x u),
     * the precomputed ea and eb: two dot products per test. */
    double a = vec3_dot(h, s->ea), b = vec3_dot(h, s->eb);
    int ok = (t > tmin) & (t < tmax) & (a >= 0.0) & (a <= 1.0) & (b >= 0.0) & (b <= 1.0);
    return ok ? t : HUGE_VAL;
}
/* END SNIPPET quad_hit_distance */

/* Distance to the sphere along r within (tmin, tmax), or HUGE_VAL: the
 * nearer root of |o + t d - c|^2 = R^2 (|d| = 1) that is in range, else
 * the farther one (a ray leaving a glass sphere starts on it). Branch-free
 * like rt_quad_hit_distance; a negative discriminant (a miss) is clamped to 0 for the
 * square root and rejected by `real`. */
static inline double rt_sphere_hit_distance(const rt_sphere *s, rt_ray r, double tmin, double tmax)
{
    vec3 oc = vec3_sub(s->center, r.origin);
    double h = vec3_dot(r.dir, oc);
    double c = vec3_length_sq(oc) - s->radius * s->radius;
    double disc = h * h - c;
    double sq = sqrt(disc > 0.0 ? disc : 0.0);
    double t1 = h - sq, t2 = h + sq;
    int real = disc >= 0.0;
    int ok1 = real & (t1 > tmin) & (t1 < tmax), ok2 = real & (t2 > tmin) & (t2 < tmax);
    /* t1 <= t2, so the nearer valid root is the smaller of the two
     * candidates: two selects and a minimum instead of nested branches. */
    double a = ok1 ? t1 : HUGE_VAL, b = ok2 ? t2 : HUGE_VAL;
    return a < b ? a : b;
}

/* Distance to primitive p along r within (tmin, tmax), or HUGE_VAL. */
static inline double rt_prim_hit_distance(const rt_prim *p, rt_ray r, double tmin, double tmax)
{
    return p->kind == RT_PRIM_QUAD ? rt_quad_hit_distance(&p->as.quad, r, tmin, tmax)
                                   : rt_sphere_hit_distance(&p->as.sphere, r, tmin, tmax);
}

/* The book's set_face_normal: keep which side was hit, then turn the
 * normal against the ray so that scattering code never has to. */
static inline void rt_hit_set_face(rt_hit *h, vec3 dir, vec3 outward)
{
    h->front_face = vec3_dot(dir, outward) < 0.0;
    h->normal = h->front_face ? outward : vec3_neg(outward);
}

/* The full hit record of primitive p (index `index`) at distance t along
 * r. Inline: it follows every closest-hit query. */
static inline void rt_prim_hit_record(const rt_prim *p, int index, rt_ray r, double t, rt_hit *h)
{
    h->t = t;
    h->p = rt_ray_at(r, t);
    h->material = p->material;
    h->prim = index;
    if (p->kind == RT_PRIM_QUAD) {
        rt_hit_set_face(h, r.dir, p->as.quad.normal);
    } else {
        /* Normalized, not divided by the radius: the hit point is off the
         * sphere by rounding, a normal off unit length by e gives scattered
         * directions off by e, and the next hit along a non-unit direction
         * is off the sphere by a few e: inside a sphere (the furnace, a
         * glass ball) the error doubles at every bounce until, some 25
         * bounces later, a ray meets the surface it starts on. */
        const rt_sphere *s = &p->as.sphere;
        vec3 outward = vec3_scale(vec3_normalize(vec3_sub(h->p, s->center)), s->orient);
        rt_hit_set_face(h, r.dir, outward);
    }
}

/* The bounding box of a primitive, padded on every side by
 * RT_BOX_PAD * (1 + max|coord|), max|coord| the largest absolute value of
 * any coordinate of the unpadded box (quads are flat; see shapes.c). */
rt_aabb rt_prim_bounds(const rt_prim *p);

/* The relative padding of boxes (1e-9: far below the 1e-3 shadow-acne
 * offset of the book's 555-unit room, far above rounding). */
#define RT_BOX_PAD 1e-9

#endif /* RT_SHAPES_H */
