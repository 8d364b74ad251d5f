/* render/bvh.c - binned SAH construction and stack traversal. */
#include "render/bvh.h"

#include <stdlib.h>
#include <string.h>

/* Cost of visiting a node relative to one primitive test. A slab test
 * costs about one quad test, but a node visit adds the stack and a branch
 * whose outcome depends on the ray, where a leaf's tests run branch-free
 * one after the other (and four rays at a time on the fast path): a node
 * visit is worth about four primitive tests. */
#define COST_TRAVERSAL 4.0

/* Past this depth the SAH is replaced by a median split, which halves the
 * count at every level: the tree then stays below 40 + log2(n) levels
 * whatever the input (coincident or adversarial centroids). That fits the
 * fixed traversal stack (RT_BVH_MAX_DEPTH) for n below 2^24; for larger n
 * rt_bvh_build checks the depth reached and fails if it does not fit. */
#define SAH_DEPTH_LIMIT 40

typedef struct builder {
    rt_prim *prims;
    rt_aabb *boxes;
    vec3 *centers;
    rt_bvh_node *nodes;
    int n_nodes;
    int depth;
} builder;

static void swap_items(builder *b, int i, int j)
{
    rt_prim p = b->prims[i];
    rt_aabb x = b->boxes[i];
    vec3 c = b->centers[i];
    b->prims[i] = b->prims[j];
    b->boxes[i] = b->boxes[j];
    b->centers[i] = b->centers[j];
    b->prims[j] = p;
    b->boxes[j] = x;
    b->centers[j] = c;
}

/* Moves the items of [start, end) whose centre along axis is below the
 * k-th smallest to the front (Hoare's quickselect). */
static void select_median(builder *b, int start, int end, int k, int axis)
{
    while (end - start > 1) {
        double pivot = vec3_at(b->centers[start + (end - start) / 2], axis);
        int i = start, j = end - 1;
        while (i <= j) {
            while (vec3_at(b->centers[i], axis) < pivot)
                i++;
            while (vec3_at(b->centers[j], axis) > pivot)
                j--;
            if (i <= j)
                swap_items(b, i++, j--);
        }
        if (k <= j)
            end = j + 1;
        else if (k >= i)
            start = i;
        else
            return;
    }
}

typedef struct split {
    int axis;
    int bin;      /* items in bins 0..bin go left; -1: make a leaf */
    double lo, scale;
} split;

/* The SAH split of [start, end) over centroid bins along the widest axis
 * of the centroids, or bin = -1 when a leaf is cheaper (or unavoidable). */
static split find_split(const builder *b, int start, int end, rt_aabb node_box)
{
    /* BEGIN SNIPPET sah_binning */
    split s = {0, -1, 0.0, 0.0};
    rt_aabb cb = rt_aabb_empty();
    for (int i = start; i < end; i++)
        cb = rt_aabb_add_point(cb, b->centers[i]);
    vec3 ext = vec3_sub(cb.hi, cb.lo);
    s.axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    double width = vec3_at(ext, s.axis);
    int n = end - start;
    if (n <= 1 || !(width > 0.0))
        return s;
    s.lo = vec3_at(cb.lo, s.axis);
    s.scale = RT_BVH_BINS / width;
    int count[RT_BVH_BINS] = {0};
    rt_aabb box[RT_BVH_BINS];
    for (int k = 0; k < RT_BVH_BINS; k++)
        box[k] = rt_aabb_empty();
    for (int i = start; i < end; i++) {
        int k = (int)((vec3_at(b->centers[i], s.axis) - s.lo) * s.scale);
        k = k < RT_BVH_BINS ? k : RT_BVH_BINS - 1;
        count[k]++;
        box[k] = rt_aabb_union(box[k], b->boxes[i]);
    }
    /* END SNIPPET sah_binning */
    /* BEGIN SNIPPET sah_sweep */
    /* Sweep from the right to get the area and count right of every
     * boundary, then from the left evaluating the cost. */
    double right_area[RT_BVH_BINS];
    int right_count[RT_BVH_BINS];
    rt_aabb acc = rt_aabb_empty();
    int cnt = 0;
    for (int k = RT_BVH_BINS - 1; k > 0; k--) {
        acc = rt_aabb_union(acc, box[k]);
        cnt += count[k];
        right_area[k] = rt_aabb_area(acc);
        right_count[k] = cnt;
    }
    double parent = rt_aabb_area(node_box), best = HUGE_VAL;
    acc = rt_aabb_empty();
    cnt = 0;
    for (int k = 0; k < RT_BVH_BINS - 1; k++) {
        acc = rt_aabb_union(acc, box[k]);
        cnt += count[k];
        if (cnt == 0 || right_count[k + 1] == 0)
            continue;
        double cost = COST_TRAVERSAL +
                      (rt_aabb_area(acc) * cnt + right_area[k + 1] * right_count[k + 1]) / parent;
        if (cost < best) {
            best = cost;
            s.bin = k;
        }
    }
    if (n <= RT_BVH_MAX_LEAF && (double)n <= best)
        s.bin = -1;
    return s;
    /* END SNIPPET sah_sweep */
}

/* Partitions [start, end) and returns the first index of the right part. */
static int partition(builder *b, int start, int end, split s, int depth)
{
    if (depth >= SAH_DEPTH_LIMIT) {
        int mid = start + (end - start) / 2;
        select_median(b, start, end, mid, s.axis);
        return mid;
    }
    int i = start, j = end - 1;
    while (i <= j) {
        int k = (int)((vec3_at(b->centers[i], s.axis) - s.lo) * s.scale);
        k = k < RT_BVH_BINS ? k : RT_BVH_BINS - 1; /* the same binning as find_split */
        if (k <= s.bin)
            i++;
        else
            swap_items(b, i, j--);
    }
    return i;
}

static int build_node(builder *b, int start, int end, int depth)
{
    int index = b->n_nodes++;
    rt_bvh_node *node = &b->nodes[index];
    rt_aabb box = rt_aabb_empty();
    for (int i = start; i < end; i++)
        box = rt_aabb_union(box, b->boxes[i]);
    memset(node, 0, sizeof *node);
    for (int a = 0; a < 3; a++) {
        node->b[0][a] = vec3_at(box.lo, a);
        node->b[1][a] = vec3_at(box.hi, a);
    }
    if (depth > b->depth)
        b->depth = depth;
    split s = find_split(b, start, end, box);
    /* Coincident centroids (width 0) leave no split: one leaf, whatever
     * its size, unless the depth rule forces a median split. */
    bool forced = (depth >= SAH_DEPTH_LIMIT && end - start > RT_BVH_MAX_LEAF) || end - start > INT16_MAX;
    if (s.bin < 0 && !forced) {
        node->first = start;
        node->count = (int16_t)(end - start);
        return index;
    }
    int mid = partition(b, start, end, s, forced ? SAH_DEPTH_LIMIT : depth);
    if (mid == start || mid == end) /* only when every centroid coincides */
        mid = start + (end - start) / 2;
    node->axis = s.axis;
    build_node(b, start, mid, depth + 1);
    int right = build_node(b, mid, end, depth + 1);
    b->nodes[index].first = right; /* b->nodes did not move: preallocated */
    b->nodes[index].count = 0;
    return index;
}

int rt_bvh_build(rt_bvh *bvh, rt_prim *prims, int n)
{
    memset(bvh, 0, sizeof *bvh);
    builder b = {prims, malloc((size_t)n * sizeof(rt_aabb)), malloc((size_t)n * sizeof(vec3)),
                 malloc((size_t)(2 * n - 1) * sizeof(rt_bvh_node)), 0, 0};
    if (!b.boxes || !b.centers || !b.nodes) {
        free(b.boxes);
        free(b.centers);
        free(b.nodes);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        b.boxes[i] = rt_prim_bounds(&prims[i]);
        b.centers[i] = rt_aabb_center(b.boxes[i]);
    }
    build_node(&b, 0, n, 0);
    free(b.boxes);
    free(b.centers);
    /* The traversal pushes one node per interior level: a deeper tree
     * would overflow its stack. */
    if (b.depth >= RT_BVH_MAX_DEPTH) {
        free(b.nodes);
        return -1;
    }
    bvh->nodes = b.nodes;
    bvh->n_nodes = b.n_nodes;
    bvh->depth = b.depth;
    return 0;
}

void rt_bvh_destroy(rt_bvh *bvh)
{
    free(bvh->nodes);
    memset(bvh, 0, sizeof *bvh);
}

/* The slab test: the ray is inside the box for t in the intersection of
 * three slabs' intervals; taking the near plane of each slab by the sign of
 * the direction avoids the min/max pair per axis. */
/* BEGIN SNIPPET slab_test */
static inline bool box_hit(const rt_bvh_node *nd, vec3 o, vec3 inv, const int neg[3], double tmin,
                           double tmax)
{
    double t0 = (nd->b[neg[0]][0] - o.x) * inv.x, t1 = (nd->b[1 - neg[0]][0] - o.x) * inv.x;
    double u0 = (nd->b[neg[1]][1] - o.y) * inv.y, u1 = (nd->b[1 - neg[1]][1] - o.y) * inv.y;
    double v0 = (nd->b[neg[2]][2] - o.z) * inv.z, v1 = (nd->b[1 - neg[2]][2] - o.z) * inv.z;
    tmin = t0 > tmin ? t0 : tmin;
    tmin = u0 > tmin ? u0 : tmin;
    tmin = v0 > tmin ? v0 : tmin;
    tmax = t1 < tmax ? t1 : tmax;
    tmax = u1 < tmax ? u1 : tmax;
    tmax = v1 < tmax ? v1 : tmax;
    return tmin <= tmax;
}
/* END SNIPPET slab_test */

/* The nearest of prims[first..end) within (tmin, *best): each candidate
 * is tested in full and kept by selects, not branches, since which one
 * wins is unpredictable. A tie keeps the earlier primitive. */
static inline void leaf_closest(const rt_prim *prims, int first, int end, rt_ray r, double tmin,
                                double *best, int *best_i)
{
    for (int i = first; i < end; i++) {
        double t = rt_prim_hit_distance(&prims[i], r, tmin, *best);
        *best_i = t < *best ? i : *best_i;
        *best = t < *best ? t : *best;
    }
}

double rt_bvh_closest(const rt_bvh *bvh, const rt_prim *prims, rt_ray r, double tmin, double tmax,
                      int *index)
{
    int best_i = -1;
    double best = tmax;
    /* BEGIN SNIPPET bvh_traversal */
    /* A root that is a leaf (a small scene such as the Cornell box) is
     * tested straight away, without its box:
     * the slab test only culls, so skipping it changes no answer, and a
     * ray inside a closed room always meets the box anyway. */
    if (bvh->nodes[0].count > 0) {
        leaf_closest(prims, 0, bvh->nodes[0].count, r, tmin, &best, &best_i);
        *index = best_i;
        return best_i >= 0 ? best : HUGE_VAL;
    }
    vec3 inv = vec3_make(1.0 / r.dir.x, 1.0 / r.dir.y, 1.0 / r.dir.z);
    int neg[3] = {inv.x < 0.0, inv.y < 0.0, inv.z < 0.0};
    int stack[RT_BVH_MAX_DEPTH];
    int sp = 0, node = 0;
    for (;;) {
        const rt_bvh_node *nd = &bvh->nodes[node];
        if (box_hit(nd, r.origin, inv, neg, tmin, best)) {
            if (nd->count == 0) {
                /* Visit the child on the ray's side of the split first:
                 * its hits shorten `best` and cull the other. */
                int near = node + 1, far = nd->first;
                if (neg[nd->axis]) {
                    near = nd->first;
                    far = node + 1;
                }
                stack[sp++] = far;
                node = near;
                continue;
            }
            leaf_closest(prims, nd->first, nd->first + nd->count, r, tmin, &best, &best_i);
        }
        if (sp == 0)
            break;
        node = stack[--sp];
    }
    /* END SNIPPET bvh_traversal */
    *index = best_i;
    return best_i >= 0 ? best : HUGE_VAL;
}

bool rt_bvh_hit(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                rt_hit *h)
{
    int i;
    double t = rt_bvh_closest(bvh, prims, *r, tmin, tmax, &i);
    if (i < 0)
        return false;
    rt_prim_hit_record(&prims[i], i, *r, t, h);
    return true;
}

double rt_prims_closest(const rt_prim *prims, int n, rt_ray r, double tmin, double tmax, int *index)
{
    double best = tmax;
    int best_i = -1;
    leaf_closest(prims, 0, n, r, tmin, &best, &best_i);
    *index = best_i;
    return best_i >= 0 ? best : HUGE_VAL;
}
