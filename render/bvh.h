/* render/bvh.h - a bounding volume hierarchy over the scene's primitives.
 *
 * Construction is top-down with the surface area heuristic evaluated on
 * RT_BVH_BINS centroid bins (the binned SAH of pbrt [@pharr2023] and of the cranberray
 * posts, which use 12 buckets): at each node the split minimises
 *     C_trav + (A_left N_left + A_right N_right) / A_parent
 * (areas of bounding boxes, N primitive counts, one unit per primitive
 * test), or the node becomes a leaf when that is cheaper. The nodes live in
 * one flat array in depth-first order (a node's first child follows it);
 * traversal is iterative, with an explicit stack, nearer child first.
 * A leaf tests its primitives one after the other, keeping the nearest by
 * selects. A small scene's tree is a single leaf (the Cornell box: twelve
 * quads and a sphere); the fast path (render/fast/hit4.h) tests such a
 * leaf against four rays at once, and one ray against four of its quads
 * at once.
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

typedef struct rt_bvh_node {
    double b[2][3];  /* bounds: b[0] = lo, b[1] = hi (indexable by ray sign) */
    int32_t first;   /* leaf: first primitive; interior: index of the 2nd child */
    int32_t count;   /* leaf: number of primitives (>= 1); interior: 0 */
    int32_t axis;    /* interior: the split axis (0, 1, 2) */
} rt_bvh_node;

typedef struct rt_bvh {
    rt_bvh_node *nodes; /* nodes[0] is the root */
    int n_nodes;
    int depth;          /* levels below the root, < RT_BVH_MAX_DEPTH (checked by rt_bvh_build) */
} rt_bvh;

/* Builds the hierarchy over prims[0..n) (n >= 1), reordering the array so
 * that every leaf holds a contiguous range. Allocates the nodes; returns
 * 0, or -1 when out of memory or when the tree would be RT_BVH_MAX_DEPTH
 * levels deep or deeper, too deep for the traversal stack (possible only
 * for about 2^24 primitives or more); bvh is then empty. */
int rt_bvh_build(rt_bvh *bvh, rt_prim *prims, int n);

/* Frees the nodes; the struct may be reused. */
void rt_bvh_destroy(rt_bvh *bvh);

/* The distance to the closest primitive that r meets within (tmin, tmax),
 * HUGE_VAL if none; *index receives its index in prims (-1 if none). */
double rt_bvh_closest(const rt_bvh *bvh, const rt_prim *prims, rt_ray r, double tmin, double tmax,
                      int *index);

/* rt_bvh_closest followed by the hit record of the closest primitive:
 * false when r meets nothing in (tmin, tmax), else *h is filled in (the
 * renderer's query: one call, the ray passed by address). */
bool rt_bvh_hit(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                rt_hit *h);

/* The same answer by testing every primitive: the reference for the BVH
 * tests. */
double rt_prims_closest(const rt_prim *prims, int n, rt_ray r, double tmin, double tmax, int *index);

#endif /* RT_BVH_H */
