/* render/leaf4.h - the scene's accelerator for a root leaf: its quads
 * laid out four to a vector, and the tests that read them.
 *
 * A small scene (the Cornell box of chapters 4-10 of "Ray Tracing: The Rest
 * of Your Life": twelve quads and a sphere) is a single BVH leaf, or is
 * treated as one (RT_LEAF_LANES_MAX_PRIMS). Its quads
 * are copied here by kind, every field repeated in four lanes, so that
 * each primitive is tested against four rays with plain vector loads: four
 * independent computations where one ray's tests are a dependent chain. A
 * quad's normal and dual edge vectors (rt_quad) often have coordinates
 * that are exactly zero: the walls of a room are axis-aligned, the sides
 * of a box turned about the vertical have a zero y in the normal.
 * rt_quad_hit_distance's dot products then reduce exactly to fewer terms
 * (render/fast/hit4.c says why the results are the same bits), and each
 * kind has its own layout. A ray traced alone (a shadow ray, a path of the
 * light and mis strategies) is tested against four quads at once instead,
 * one quad per lane.
 *
 * The tests themselves are instruction-set code and live in render/fast/
 * (hit4.c); a scene holds them as an rt_leaf_tests, given to it by
 * whoever builds it (rt_scene_use_leaf_tests; render/scenes.c gives the
 * engine's, render/engine.h). With none, or where a test does not apply,
 * rays go through the BVH one by one (rt_bvh_hit): the reference, and the
 * same bits.
 */
#ifndef RT_LEAF4_H
#define RT_LEAF4_H

#include <stdbool.h>
#include <stdint.h>

#include "render/bvh.h"

/* Rays tested together, one per vector lane. */
#define RT_LANES 4

/* A scene of at most this many primitives is laid out in lanes whole, even
 * where the BVH splits it: testing every quad four at a time costs less
 * than the BVH's walk for a room with two boxes in it (the all-diffuse
 * Cornell box, 18 quads: a bdpt render 1.3x as fast, a mixture render
 * 2.7x, the same images; docs/performance.md). The BVH serves larger
 * scenes. */
#define RT_LEAF_LANES_MAX_PRIMS 32

/* An axis-aligned quad (a wall, the light, the top of an unturned box):
 * normal along axis k, the dual edge vectors along i and j. */
typedef struct rt_quad_axis {
    double n[RT_LANES], plane[RT_LANES], qi[RT_LANES], qj[RT_LANES];
    double ea[RT_LANES], eb[RT_LANES];
    int64_t prim[RT_LANES];
    int32_t k, i, j, unused;
    double pad[2]; /* to 256 bytes, with the rows at multiples of 32 */
} rt_quad_axis;

/* A quad whose plane holds coordinate axis j (a side of a box turned about
 * it): the normal's j coordinate is zero, one dual edge vector lies along
 * j (b), the other has a zero j coordinate (a); i < k are the other two
 * axes. */
typedef struct rt_quad_turned {
    double ni[RT_LANES], nk[RT_LANES], plane[RT_LANES];
    double qi[RT_LANES], qj[RT_LANES], qk[RT_LANES];
    double ai[RT_LANES], ak[RT_LANES], bj[RT_LANES];
    int64_t prim[RT_LANES];
    int32_t i, j, k, unused;
    double pad[6]; /* to 384 bytes */
} rt_quad_turned;

/* A quad in a coordinate plane with its edges off the axes (the top of a
 * box turned about the vertical): normal along axis k, both dual edge
 * vectors with a zero k coordinate; i < j are the other two axes. */
typedef struct rt_quad_flat {
    double n[RT_LANES], plane[RT_LANES], qi[RT_LANES], qj[RT_LANES];
    double ai[RT_LANES], aj[RT_LANES], bi[RT_LANES], bj[RT_LANES];
    int64_t prim[RT_LANES];
    int32_t k, i, j, unused;
    double pad[2]; /* to 320 bytes */
} rt_quad_flat;

/* Any other quad: the thirteen numbers of rt_quad's test (normal, plane,
 * corner, ea, eb, coordinate by coordinate). */
typedef struct rt_quad_lanes {
    double f[13][RT_LANES];
    int64_t prim[RT_LANES];
} rt_quad_lanes;

/* The root leaf laid out in lanes: its quads by kind, tested in this
 * order (axis, turned, flat, other), then its spheres; and for the hit
 * records, one row per primitive of the leaf: a quad's normal and 0, or a
 * sphere's centre and orient (+-1). For the one-ray test, the quads again
 * in n_packets rows of rt_quad_lanes, four quads to a row: lane l of row
 * p holds the (l n_packets + p)-th quad in the order of prims, so that
 * every quad of a lane comes before those of the next lane; a lane left
 * over is all zeros, with prim -1. */
typedef struct rt_leaf_lanes {
    rt_quad_axis *axis;
    rt_quad_turned *turned;
    rt_quad_flat *flat;
    rt_quad_lanes *other;
    int *spheres;       /* indices into prims */
    int n_axis, n_turned, n_flat, n_other, n_spheres;
    double (*rows)[4];
    rt_quad_lanes *packets;
    int n_packets;
} rt_leaf_lanes;

/* The layout of the leaf prims[0..n), or NULL when out of memory. */
rt_leaf_lanes *rt_leaf_lanes_create(const rt_prim *prims, int n);

/* Frees it (NULL is fine). */
void rt_leaf_lanes_destroy(rt_leaf_lanes *ll);

/* The four-wide tests of a root leaf's lanes, each NULL when there is
 * none (the zero value: the BVH alone). hit4: the nearest hit of each of
 * RT_LANES rays, for tmin >= 0; hit1: the nearest hit of one ray. Both
 * give rt_bvh_hit's answers bit for bit (see rt_leaf_lanes_hit).
 * occluded4: for shadow rays, whether each of RT_LANES rays meets
 * anything in (tmin, its own tmax), for tmin >= 0, without the hit
 * records (see rt_leaf_lanes_occluded). */
typedef struct rt_leaf_tests {
    unsigned (*hit4)(const rt_leaf_lanes *ll, const rt_prim *prims, const rt_ray r[RT_LANES],
                     double tmin, double tmax, rt_hit h[RT_LANES]);
    bool (*hit1)(const rt_leaf_lanes *ll, const rt_prim *prims, const rt_ray *r, double tmin,
                 double tmax, rt_hit *h);
    unsigned (*occluded4)(const rt_leaf_lanes *ll, const rt_prim *prims, const rt_ray r[RT_LANES],
                          double tmin, const double tmax[RT_LANES]);
} rt_leaf_tests;

/* rt_bvh_hit for RT_LANES rays at once: h[k] is filled in for every ray
 * r[k] that meets a primitive in (tmin, tmax), and bit k of the result is
 * set for it; h[k] of a ray that meets nothing may be overwritten. Each
 * ray gets the same distance and hit record as from rt_bvh_hit (on an
 * exact tie between two primitives either may be reported). With a test
 * t->hit4, a leaf layout ll (may be NULL) and tmin >= 0, every primitive
 * is tested against the four rays in vector lanes; otherwise the rays are
 * traced one by one. Callers with fewer rays repeat one of them. */
unsigned rt_leaf_lanes_hit(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                           const rt_prim *prims, const rt_ray r[RT_LANES], double tmin,
                           double tmax, rt_hit h[RT_LANES]);

/* Which of the RT_LANES shadow rays r[k] meet a primitive in (tmin,
 * tmax[k]): bit k of the result. The reference is rt_leaf_lanes_hit's
 * nearest hit out to the largest tmax[k], ray k blocked when that hit is
 * nearer than its own tmax[k]; a blocking hit exists exactly when the
 * nearest one is one. With a test t->occluded4, a leaf layout ll (may be
 * NULL) and tmin >= 0, the four rays meet every primitive in vector
 * lanes, each lane against its own tmax, and the answer is the same; no
 * hit record is made. Callers with fewer rays repeat one of them. */
unsigned rt_leaf_lanes_occluded(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                                const rt_prim *prims, const rt_ray r[RT_LANES], double tmin,
                                const double tmax[RT_LANES]);

/* rt_bvh_hit for one ray r: the same answer, the distance and hit record
 * bit for bit, and on an exact tie the same primitive (the first in
 * prims) when the BVH is one leaf (a BVH that splits may report the other
 * one of a tie). With a test t->hit1 and a leaf layout ll (may be NULL), r is
 * tested against the four quads of each of ll's packets in vector lanes,
 * then against the spheres; otherwise this is rt_bvh_hit. */
bool rt_leaf_lanes_hit1(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                        const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                        rt_hit *h);

#endif /* RT_LEAF4_H */
