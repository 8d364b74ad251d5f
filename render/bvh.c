/* render/bvh.c - binned SAH construction and stack traversal. */
#include "render/bvh.h"

#include "render/bvh4.h"

#include <stdlib.h>
#include <string.h>

/* Cost of visiting a node relative to one primitive test. A slab test of
 * a box costs about as much as one quad test done alone, but quads in a
 * leaf are tested four at a time (one packet): a node visit is worth about
 * four leaf primitives. */
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

/* Puts a leaf's quads first and copies them into packets, lane by lane. */
static void pack_leaf(rt_bvh *bvh, rt_bvh_node *node, rt_prim *prims)
{
    int first = node->first, end = node->first + node->count, q = first;
    for (int i = first; i < end; i++)
        if (prims[i].kind == RT_PRIM_QUAD) {
            rt_prim t = prims[q];
            prims[q++] = prims[i];
            prims[i] = t;
        }
    node->n_quads = (int16_t)(q - first);
    node->packet = bvh->n_packets;
    for (int i = first; i < q; i += RT_PACKET) {
        rt_quad_packet *pk = &bvh->packets[bvh->n_packets++];
        memset(pk, 0, sizeof *pk);
        for (int j = 0; j < RT_PACKET; j++) {
            pk->prim[j] = -1;
            if (i + j >= q)
                continue;
            const rt_quad *s = &prims[i + j].as.quad;
            pk->prim[j] = i + j;
            pk->nx[j] = s->normal.x, pk->ny[j] = s->normal.y, pk->nz[j] = s->normal.z;
            pk->plane[j] = s->plane;
            pk->qx[j] = s->q.x, pk->qy[j] = s->q.y, pk->qz[j] = s->q.z;
            pk->ax[j] = s->ea.x, pk->ay[j] = s->ea.y, pk->az[j] = s->ea.z;
            pk->bx[j] = s->eb.x, pk->by[j] = s->eb.y, pk->bz[j] = s->eb.z;
        }
    }
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
    /* Each leaf wastes less than one packet: at most n + n_nodes. */
    bvh->packets = malloc((size_t)(n + b.n_nodes) * sizeof *bvh->packets);
    if (!bvh->packets) {
        rt_bvh_destroy(bvh);
        return -1;
    }
    for (int i = 0; i < bvh->n_nodes; i++)
        if (bvh->nodes[i].count > 0)
            pack_leaf(bvh, &bvh->nodes[i], prims);
    const rt_bvh_node *root = &bvh->nodes[0];
    if (root->count > 0 && !(bvh->root4 = rt_bvh4_create(prims, root->count, root->n_quads))) {
        rt_bvh_destroy(bvh);
        return -1;
    }
    return 0;
}

void rt_bvh_destroy(rt_bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->packets);
    rt_bvh4_destroy(bvh->root4);
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

/* The nearest quad of a leaf's packets. Each packet evaluates rt_quad_t's
 * expressions on its four lanes at once, in the same order, so the
 * distances are bit for bit those of rt_quad_t. Every packet is tested
 * against the same tmax (the best distance when the leaf was entered),
 * so that no packet waits for the previous one; each lane keeps its
 * nearest distance and primitive by selects (vector blends), and a
 * tournament of comparisons turned into indices picks the nearest lane at
 * the end (an exact tie goes to the lower lane, then the earlier packet;
 * either answer is a correct closest hit). Plain
 * conditionals on the winner would compile to branches that mispredict
 * about half the time; a bit mask keeps the index. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void packets_closest(const rt_quad_packet *pk, int n_packets, rt_ray r, double tmin,
                                   double *best, int *best_i)
{
    double m[RT_PACKET], tmax = *best;
    int64_t mi[RT_PACKET];
    for (int j = 0; j < RT_PACKET; j++) {
        m[j] = HUGE_VAL;
        mi[j] = -1;
    }
    for (int p = 0; p < n_packets; p++, pk++)
        for (int j = 0; j < RT_PACKET; j++) {
            double dn = pk->nx[j] * r.dir.x + pk->ny[j] * r.dir.y + pk->nz[j] * r.dir.z;
            double on = pk->nx[j] * r.origin.x + pk->ny[j] * r.origin.y + pk->nz[j] * r.origin.z;
            double tj = (pk->plane[j] - on) / dn;
            double hx = (r.origin.x + tj * r.dir.x) - pk->qx[j];
            double hy = (r.origin.y + tj * r.dir.y) - pk->qy[j];
            double hz = (r.origin.z + tj * r.dir.z) - pk->qz[j];
            double a = hx * pk->ax[j] + hy * pk->ay[j] + hz * pk->az[j];
            double b = hx * pk->bx[j] + hy * pk->by[j] + hz * pk->bz[j];
            int ok = (tj > tmin) & (tj < tmax) & (a >= 0.0) & (a <= 1.0) & (b >= 0.0) & (b <= 1.0);
            int closer = ok & (tj < m[j]);
            m[j] = closer ? tj : m[j];
            mi[j] = closer ? pk->prim[j] : mi[j];
        }
    int i01 = m[1] < m[0], i23 = 2 + (m[3] < m[2]);
    int k = i01 + (m[i23] < m[i01]) * (i23 - i01);
    int32_t closer = -(int32_t)(m[k] < *best);
    *best_i = (closer & (int32_t)mi[k]) | (~closer & *best_i);
    *best = m[k] < *best ? m[k] : *best;
}

#if defined(__x86_64__) && defined(__GNUC__)
#define RT_BVH_AVX2 1
#include <immintrin.h>

/* rt_quad_t on four lanes: q[f] points to the four lanes of the quad's
 * field f, in rt_quad_packet order (normal, plane, corner, ea, eb); o and
 * d are the ray's origin and direction; each lane its own quad or ray.
 * The same expressions in the same order (no FMA: a fused multiply-add
 * rounds once where rt_quad_t rounds twice), so the same distances bit
 * for bit. Returns t; *ok gets the lanes with t in (lo, hi) and the hit
 * inside the quad. Ordered comparisons: a NaN (an unused lane's 0/0, a
 * ray in the plane) fails every one. The fields are loaded where they are
 * used, so that they stay memory operands instead of thirteen registers. */
__attribute__((target("avx2"), always_inline)) static inline __m256d
quad_t4(const double *const q[13], const __m256d o[3], const __m256d d[3], __m256d lo, __m256d hi,
        __m256d *ok)
{
#define F(k) _mm256_loadu_pd(q[k])
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    __m256d dn = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(F(0), d[0]), _mm256_mul_pd(F(1), d[1])),
                               _mm256_mul_pd(F(2), d[2]));
    __m256d on = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(F(0), o[0]), _mm256_mul_pd(F(1), o[1])),
                               _mm256_mul_pd(F(2), o[2]));
    __m256d t = _mm256_div_pd(_mm256_sub_pd(F(3), on), dn);
    __m256d hx = _mm256_sub_pd(_mm256_add_pd(o[0], _mm256_mul_pd(t, d[0])), F(4));
    __m256d hy = _mm256_sub_pd(_mm256_add_pd(o[1], _mm256_mul_pd(t, d[1])), F(5));
    __m256d hz = _mm256_sub_pd(_mm256_add_pd(o[2], _mm256_mul_pd(t, d[2])), F(6));
    __m256d a = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(hx, F(7)), _mm256_mul_pd(hy, F(8))),
                              _mm256_mul_pd(hz, F(9)));
    __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(hx, F(10)), _mm256_mul_pd(hy, F(11))),
                              _mm256_mul_pd(hz, F(12)));
#undef F
    __m256d in = _mm256_and_pd(_mm256_cmp_pd(t, lo, _CMP_GT_OQ), _mm256_cmp_pd(t, hi, _CMP_LT_OQ));
    in = _mm256_and_pd(in, _mm256_and_pd(_mm256_cmp_pd(a, zero, _CMP_GE_OQ), _mm256_cmp_pd(a, one, _CMP_LE_OQ)));
    *ok = _mm256_and_pd(in, _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_GE_OQ), _mm256_cmp_pd(b, one, _CMP_LE_OQ)));
    return t;
}

/* packets_closest written with AVX2 intrinsics (quad_t4, one quad per
 * lane). Two things the compiler does not do by itself from the loop
 * above: the lanes start at the leaf's tmax, so "t < tmax" and "closer
 * than this lane's best" are one comparison; and the nearest lane is
 * found by a vector minimum, a mask of the lanes equal to it and the
 * lowest set bit, without a data-dependent branch (a tie goes to the
 * lower lane, then to the earlier packet, as above). */
__attribute__((target("avx2"))) static inline void packets_closest_avx2(
    const rt_quad_packet *pk, int n_packets, rt_ray r, double tmin, double *best, int *best_i)
{
    const __m256d o[3] = {_mm256_set1_pd(r.origin.x), _mm256_set1_pd(r.origin.y),
                          _mm256_set1_pd(r.origin.z)},
                  d[3] = {_mm256_set1_pd(r.dir.x), _mm256_set1_pd(r.dir.y), _mm256_set1_pd(r.dir.z)},
                  lo = _mm256_set1_pd(tmin);
    __m256d m = _mm256_set1_pd(*best);
    __m256i mi = _mm256_set1_epi64x(-1);
    for (int p = 0; p < n_packets; p++, pk++) {
        const double *const fields[13] = {pk->nx, pk->ny, pk->nz, pk->plane, pk->qx, pk->qy, pk->qz,
                                          pk->ax, pk->ay, pk->az, pk->bx, pk->by, pk->bz};
        __m256d ok, t = quad_t4(fields, o, d, lo, m, &ok);
        m = _mm256_blendv_pd(m, t, ok);
        mi = _mm256_castpd_si256(_mm256_blendv_pd(
            _mm256_castsi256_pd(mi), _mm256_loadu_pd((const double *)(const void *)pk->prim), ok));
    }
    __m256d lo2 = _mm256_min_pd(m, _mm256_permute_pd(m, 0x5));
    __m256d lo4 = _mm256_min_pd(lo2, _mm256_permute2f128_pd(lo2, lo2, 0x1));
    double t = _mm256_cvtsd_f64(lo4);
    /* Every lane started at *best: a lane below it holds a hit. */
    unsigned mask = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(m, lo4, _CMP_EQ_OQ));
    int lane = __builtin_ctz(mask | 0x10u) & 3;
    int64_t lanes[RT_PACKET];
    _mm256_storeu_si256((__m256i *)(void *)lanes, mi);
    int32_t closer = -(int32_t)(t < *best);
    *best_i = (closer & (int32_t)lanes[lane]) | (~closer & *best_i);
    *best = t < *best ? t : *best;
}

/* rt_sphere_t's arithmetic in scalar SSE: the same numbers, with selects
 * where the compiler makes branches of the C version's conditions. Since
 * t1 = h - sq <= h + sq = t2 also in floating point, the nearer valid root
 * is t1 if t1 > tmin, else t2, kept if it is below tmax. Only lane 0
 * is read; the values are broadcast rather than set with _mm_set_sd,
 * whose register-to-register vmovq valgrind 3.19 cannot decode. */
__attribute__((target("avx2"))) static inline double sphere_t_avx2(const rt_sphere *s, rt_ray r,
                                                                    double tmin, double tmax)
{
    vec3 oc = vec3_sub(s->center, r.origin);
    double h = vec3_dot(r.dir, oc);
    double c = vec3_length_sq(oc) - s->radius * s->radius;
    __m128d disc = _mm_set1_pd(h * h - c), zero = _mm_setzero_pd(), hv = _mm_set1_pd(h);
    __m128d sq = _mm_sqrt_sd(zero, _mm_max_sd(disc, zero)); /* max gives 0 for a NaN disc */
    __m128d t1 = _mm_sub_sd(hv, sq), t2 = _mm_add_sd(hv, sq), lo = _mm_set1_pd(tmin);
    __m128d t = _mm_blendv_pd(t2, t1, _mm_cmp_sd(t1, lo, _CMP_GT_OQ));
    __m128d ok = _mm_and_pd(_mm_cmp_sd(disc, zero, _CMP_GE_OQ),
                            _mm_and_pd(_mm_cmp_sd(t, lo, _CMP_GT_OQ),
                                       _mm_cmp_sd(t, _mm_set1_pd(tmax), _CMP_LT_OQ)));
    return _mm_cvtsd_f64(_mm_blendv_pd(_mm_set1_pd(HUGE_VAL), t, ok));
}
#endif

/* Every primitive of leaf nd: its packets of quads, then its spheres. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void leaf_closest(const rt_bvh *bvh, const rt_prim *prims, const rt_bvh_node *nd,
                                rt_ray r, double tmin, double *best, int *best_i, bool avx2)
{
    int n_packets = (nd->n_quads + RT_PACKET - 1) / RT_PACKET;
#ifdef RT_BVH_AVX2
    if (avx2)
        packets_closest_avx2(&bvh->packets[nd->packet], n_packets, r, tmin, best, best_i);
    else
#endif
        packets_closest(&bvh->packets[nd->packet], n_packets, r, tmin, best, best_i);
    /* Conditional moves, not branches: which candidate wins is
     * unpredictable. */
    for (int i = nd->first + nd->n_quads; i < nd->first + nd->count; i++) {
#ifdef RT_BVH_AVX2
        double t = avx2 ? sphere_t_avx2(&prims[i].as.sphere, r, tmin, *best)
                        : rt_sphere_t(&prims[i].as.sphere, r, tmin, *best);
#else
        double t = rt_sphere_t(&prims[i].as.sphere, r, tmin, *best);
#endif
        int32_t closer = -(int32_t)(t < *best);
        *best_i = (closer & i) | (~closer & *best_i);
        *best = t < *best ? t : *best;
    }
}

/* The traversal, inlined below into a baseline copy and, on x86-64, a
 * copy for processors with AVX2 that does a packet's four lanes in one
 * vector instruction. The AVX2 copy is compiled without FMA, so that both
 * compute bit for bit the same numbers. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline double closest(const rt_bvh *bvh, const rt_prim *prims, rt_ray r, double tmin,
                             double tmax, int *index, bool avx2)
{
    int best_i = -1;
    double best = tmax;
    /* BEGIN SNIPPET bvh_traversal */
    /* A root that is a leaf (a small scene such as the Cornell box: one
     * leaf of three packets) is tested straight away, without its box:
     * the slab test only culls, so skipping it changes no answer, and a
     * ray inside a closed room always meets the box anyway. */
    if (bvh->nodes[0].count > 0) {
        leaf_closest(bvh, prims, &bvh->nodes[0], r, tmin, &best, &best_i, avx2);
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
            leaf_closest(bvh, prims, nd, r, tmin, &best, &best_i, avx2);
        }
        if (sp == 0)
            break;
        node = stack[--sp];
    }
    /* END SNIPPET bvh_traversal */
    *index = best_i;
    return best_i >= 0 ? best : HUGE_VAL;
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"), flatten)) static double closest_avx2(const rt_bvh *bvh, const rt_prim *prims,
                                                           rt_ray r, double tmin, double tmax,
                                                           int *index)
{
    return closest(bvh, prims, r, tmin, tmax, index, true);
}
#endif

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool hit(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin,
                       double tmax, rt_hit *h, bool avx2)
{
    int i;
    double t = closest(bvh, prims, *r, tmin, tmax, &i, avx2);
    if (i < 0)
        return false;
    rt_prim_hit_record(&prims[i], i, *r, t, h);
    return true;
}

/* The baseline copy, out of line so that the dispatcher below stays a
 * test and a jump (inlined, its register saves and stack frame would run
 * before the test on every call). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static bool hit_base(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin,
                     double tmax, rt_hit *h)
{
    return hit(bvh, prims, r, tmin, tmax, h, false);
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"), flatten)) static bool hit_avx2(const rt_bvh *bvh, const rt_prim *prims,
                                                     const rt_ray *r, double tmin, double tmax,
                                                     rt_hit *h)
{
    return hit(bvh, prims, r, tmin, tmax, h, true);
}
#endif

bool rt_bvh_hit(const rt_bvh *bvh, const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                rt_hit *h)
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx2"))
        return hit_avx2(bvh, prims, r, tmin, tmax, h);
#endif
    return hit_base(bvh, prims, r, tmin, tmax, h);
}

double rt_bvh_closest(const rt_bvh *bvh, const rt_prim *prims, rt_ray r, double tmin, double tmax,
                      int *index)
{
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx2"))
        return closest_avx2(bvh, prims, r, tmin, tmax, index);
#endif
    return closest(bvh, prims, r, tmin, tmax, index, false);
}

double rt_prims_closest(const rt_prim *prims, int n, rt_ray r, double tmin, double tmax, int *index)
{
    double best = tmax;
    int best_i = -1;
    for (int i = 0; i < n; i++) {
        double t = rt_prim_t(&prims[i], r, tmin, best);
        best_i = t < best ? i : best_i;
        best = t < best ? t : best;
    }
    *index = best_i;
    return best_i >= 0 ? best : HUGE_VAL;
}
