/* render/bvh4.h - the four-ray test of a tree whose root is a leaf, behind
 * rt_bvh_hit4 (bvh.h); internal to render/bvh*.c and their tests.
 *
 * A small scene (the Cornell box of chapters 4-10 of "Ray Tracing: The Rest
 * of Your Life": twelve quads and a sphere) is a single leaf. Its quads are
 * copied here by kind, every field repeated in four lanes, so that each
 * primitive is tested against four rays with plain vector loads. A quad's
 * normal and dual edge vectors (rt_quad) often have coordinates that are
 * exactly zero: the walls of a room are axis-aligned, the sides of a box
 * turned about the vertical have a zero y in the normal. rt_quad_t's dot
 * products then reduce exactly to fewer terms (bvh4.c says why the
 * results are the same bits), and each kind has its own layout.
 */
#ifndef RT_BVH4_H
#define RT_BVH4_H

#include <stdint.h>

#include "render/bvh.h"

/* An axis-aligned quad (a wall, the light, the top of an unturned box):
 * normal along axis k, the dual edge vectors along i and j. */
typedef struct rt_quad_axis {
    double n[RT_BVH_LANES], plane[RT_BVH_LANES], qi[RT_BVH_LANES], qj[RT_BVH_LANES];
    double ea[RT_BVH_LANES], eb[RT_BVH_LANES];
    int64_t prim[RT_BVH_LANES];
    int32_t k, i, j, unused;
    double pad[2]; /* to 256 bytes, with the rows at multiples of 32 */
} rt_quad_axis;

/* A quad whose plane holds coordinate axis j (a side of a box turned about
 * it): the normal's j coordinate is zero, one dual edge vector lies along
 * j (b), the other has a zero j coordinate (a); i < k are the other two
 * axes. */
typedef struct rt_quad_turned {
    double ni[RT_BVH_LANES], nk[RT_BVH_LANES], plane[RT_BVH_LANES];
    double qi[RT_BVH_LANES], qj[RT_BVH_LANES], qk[RT_BVH_LANES];
    double ai[RT_BVH_LANES], ak[RT_BVH_LANES], bj[RT_BVH_LANES];
    int64_t prim[RT_BVH_LANES];
    int32_t i, j, k, unused;
    double pad[6]; /* to 384 bytes */
} rt_quad_turned;

/* A quad in a coordinate plane with its edges off the axes (the top of a
 * box turned about the vertical): normal along axis k, both dual edge
 * vectors with a zero k coordinate; i < j are the other two axes. */
typedef struct rt_quad_flat {
    double n[RT_BVH_LANES], plane[RT_BVH_LANES], qi[RT_BVH_LANES], qj[RT_BVH_LANES];
    double ai[RT_BVH_LANES], aj[RT_BVH_LANES], bi[RT_BVH_LANES], bj[RT_BVH_LANES];
    int64_t prim[RT_BVH_LANES];
    int32_t k, i, j, unused;
    double pad[2]; /* to 320 bytes */
} rt_quad_flat;

/* Any other quad: the thirteen fields of rt_quad_packet (normal, plane,
 * corner, ea, eb, coordinate by coordinate). */
typedef struct rt_quad_lanes {
    double f[13][RT_BVH_LANES];
    int64_t prim[RT_BVH_LANES];
} rt_quad_lanes;

/* The root leaf laid out for rt_bvh_hit4: its quads by kind, tested in
 * this order (axis, turned, flat, other), then its spheres from prims; and
 * for the hit records, one row per primitive: a quad's normal and 0, or a
 * sphere's centre and orient (+-1). */
typedef struct rt_bvh4 {
    rt_quad_axis *axis;
    rt_quad_turned *turned;
    rt_quad_flat *flat;
    rt_quad_lanes *other;
    int n_axis, n_turned, n_flat, n_other;
    int n, n_quads;     /* the leaf's primitives prims[0..n), quads first */
    double (*rows)[4];
} rt_bvh4;

/* The layout of the leaf prims[0..n) (quads first, n_quads of them), or
 * NULL when out of memory. */
rt_bvh4 *rt_bvh4_create(const rt_prim *prims, int n, int n_quads);

/* Frees it (NULL is fine). */
void rt_bvh4_destroy(rt_bvh4 *b4);

/* The instruction sets of the four-lane test: none (rays one by one with
 * rt_bvh_hit), AVX2, and AVX-512 (F and VL) with 256-bit vectors. The
 * arithmetic is the same in all of them. */
typedef enum rt_bvh4_isa { RT_BVH4_SCALAR, RT_BVH4_AVX2, RT_BVH4_AVX512 } rt_bvh4_isa;

/* The best of them that this processor (and this build) supports. */
rt_bvh4_isa rt_bvh4_isa_best(void);

/* rt_bvh_hit4 with the given instruction set, which the processor must
 * support (rt_bvh4_isa_best() or below); the tests compare them. */
unsigned rt_bvh4_hit(rt_bvh4_isa isa, const rt_bvh *bvh, const rt_prim *prims,
                     const rt_ray r[RT_BVH_LANES], double tmin, double tmax, rt_hit h[RT_BVH_LANES]);

#endif /* RT_BVH4_H */
