/* render/bvh.h - a bounding volume hierarchy over the scene's primitives.
 *
 * Construction is top-down with the surface area heuristic evaluated on
 * RT_BVH_BINS centroid bins (the binned SAH of pbrt and of the cranberray
 * posts, which use 12 buckets): at each node the split minimises
 *     C_trav + (A_left N_left + A_right N_right) / A_parent
 * (areas of bounding boxes, N primitive counts, one unit per primitive
 * test), or the node becomes a leaf when that is cheaper. The nodes live in
 * one flat array in depth-first order (a node's first child follows it);
 * traversal is iterative, with an explicit stack, nearer child first.
 * Inside a leaf the quads are stored again four at a time, coordinate by
 * coordinate ("packets"), and tested together without a branch (AVX2
 * vectors where the processor has them). Spheres are tested one by one.
 * A small scene's tree is a single leaf (the Cornell box: twelve quads and
 * a sphere); for it rt_bvh_hit4 turns the loops around and tests each
 * primitive against four rays at once, so that the four tests are
 * independent instead of one ray's long chain (render/bvh4.h).
 * Serves the renderer of chapters 4-10 of "Ray Tracing: The Rest of Your
 * Life"; the book itself uses the BVH of its second volume.
 */
#ifndef RT_BVH_H
#define RT_BVH_H

#include <stdint.h>

#include "render/ray.h"
#include "render/shapes.h"

#define RT_BVH_BINS 16      /* SAH bins per split (>= 12) */
/* The SAH makes leaves of at most RT_BVH_MAX_LEAF primitives, except where
 * every centroid coincides: no plane separates those, and above the median
 * split depth they stay in one leaf of up to INT16_MAX primitives. */
#define RT_BVH_MAX_LEAF 16
/* The traversal stack: rt_bvh_build fails rather than return a tree whose
 * depth (levels below the root) is RT_BVH_MAX_DEPTH or more. */
#define RT_BVH_MAX_DEPTH 64
#define RT_PACKET 4         /* quads per packet (bvh.c's lane tournament assumes 4) */

typedef struct rt_bvh_node {
    double b[2][3];  /* bounds: b[0] = lo, b[1] = hi (indexable by ray sign) */
    int32_t first;   /* leaf: first primitive; interior: index of the 2nd child */
    int16_t count;   /* leaf: number of primitives (>= 1), quads first; interior: 0 */
    int16_t n_quads; /* leaf: how many of them are quads */
    int32_t packet;  /* leaf: first of its ceil(n_quads / RT_PACKET) packets */
    int32_t axis;    /* interior: the split axis (0, 1, 2) */
} rt_bvh_node;

/* RT_PACKET quads, structure of arrays (the fields of rt_quad). Unused
 * lanes have a zero normal, which makes their distance 0/0 = NaN: never a
 * hit. */
typedef struct rt_quad_packet {
    double nx[RT_PACKET], ny[RT_PACKET], nz[RT_PACKET], plane[RT_PACKET];
    double qx[RT_PACKET], qy[RT_PACKET], qz[RT_PACKET];
    double ax[RT_PACKET], ay[RT_PACKET], az[RT_PACKET];
    double bx[RT_PACKET], by[RT_PACKET], bz[RT_PACKET];
    int64_t prim[RT_PACKET]; /* index into prims; -1 for unused lanes (64-bit:
                              * the width of a double, for vector blends) */
} rt_quad_packet;

/* Rays traced together by rt_bvh_hit4. */
#define RT_BVH_LANES 4

typedef struct rt_bvh {
    rt_bvh_node *nodes; /* nodes[0] is the root */
    int n_nodes;
    int depth;          /* levels below the root, < RT_BVH_MAX_DEPTH (checked by rt_bvh_build) */
    rt_quad_packet *packets;
    int n_packets;
    /* The root leaf laid out for rt_bvh_hit4 (render/bvh4.h), NULL when
     * the root is not a leaf. */
    struct rt_bvh4 *root4;
} rt_bvh;

/* Builds the hierarchy over prims[0..n) (n >= 1), reordering the array so
 * that every leaf holds a contiguous range, quads first. Allocates the
 * nodes and packets; returns 0, or -1 when out of memory or when the tree
 * would be RT_BVH_MAX_DEPTH levels deep or deeper, too deep for the
 * traversal stack (possible only for about 2^24 primitives or more); bvh
 * is then empty. */
int rt_bvh_build(rt_bvh *bvh, rt_prim *prims, int n);

/* Frees the nodes and packets; the struct may be reused. */
void rt_bvh_destroy(rt_bvh *bvh);

/* The distance to the closest primitive that r meets within (tmin, tmax),
 * HUGE_VAL if none; *index receives its index in prims (-1 if none). The
 * same numbers as rt_prim_t: the packet test evaluates rt_quad_t's
 * expressions in the same order. */
double rt_bvh_closest(const rt_bvh *bvh, const rt_prim *prims, rt_ray r, double tmin, double tmax,
                      int *index);

/* rt_bvh_closest followed by the hit record of the closest primitive:
 * false when r meets nothing in (tmin, tmax), else *h is filled in (the
 * renderer's query: one call, the ray passed by address). */
bool rt_bvh_hit(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                rt_hit *h);

/* rt_bvh_hit for RT_BVH_LANES rays at once: h[k] is filled in for every
 * ray r[k] that meets a primitive in (tmin, tmax), and bit k of the result
 * is set for it; h[k] of a ray that meets nothing may be overwritten.
 * Each ray gets the same distance and hit record as from rt_bvh_hit (on
 * an exact tie between two primitives either may be reported). For a tree
 * whose root is a leaf (a small scene such as the Cornell box), processors
 * with AVX2 (or AVX-512, with mask registers) test each primitive against
 * the four rays in one vector instruction, four independent computations where a single ray's test is
 * one long dependent chain; otherwise the rays are traced one by one.
 * Callers with fewer rays repeat one of them. */
unsigned rt_bvh_hit4(const rt_bvh *bvh, const rt_prim *prims, const rt_ray r[RT_BVH_LANES],
                     double tmin, double tmax, rt_hit h[RT_BVH_LANES]);

/* The same answer by testing every primitive: the reference for the BVH
 * tests. */
double rt_prims_closest(const rt_prim *prims, int n, rt_ray r, double tmin, double tmax, int *index);

#endif /* RT_BVH_H */
