/* render/fast/hit4.c - a root leaf against four rays at once, and one ray
 * against four of its quads at once; render/leaf4.c builds the lanes they
 * read. */
#include "render/fast/hit4.h"

#include <stddef.h>

#if RT_ISA_X86
/* Hand-written AVX2: with the rays traced one by one instead (the
 * portable path), make bench's book render took 20-45% longer
 * (docs/performance.md), far above the 5% that a second copy of the
 * quad and sphere tests must pay for. */
#include <immintrin.h>

/* Exactness. Every lane computes rt_quad_hit_distance's and
 * rt_sphere_hit_distance's expressions in the same order, without FMA (a
 * fused multiply-add rounds once where the scalar code rounds twice; the
 * avx2 target does not enable it), so that its distance is the scalar one
 * bit for bit. The layouts of hit4.h leave out terms of rt_quad_hit_distance's dot products whose factor from
 * the quad is exactly zero: such a term is a zero times a finite number,
 * a signed zero, and adding a signed zero leaves a nonzero sum unchanged
 * and a zero sum zero, at most of the other sign. No decision sees that
 * sign: a zero n . d gives t = +-inf or NaN either way, which the range
 * test rejects; a zero n . o makes t = +-0 or the same nonzero t, and the
 * fast path runs only for tmin >= 0, which rejects both zeros; -0 passes
 * a >= 0 as +0 does. The factors from the ray are finite as needed: d and
 * o are; t is where it passes the range test; and a coordinate of
 * h = o + t d - q left out of both edge dot products is along an axial
 * normal n_k = +-1 (to rounding), where t d_k = (plane - n_k o_k) / n_k to
 * rounding, as large as the scene's coordinates. Every other coordinate
 * of h meets a nonzero factor in a or b, so an infinite or NaN one makes
 * that sum infinite or NaN and the edge test fails, as in
 * rt_quad_hit_distance. */

/* The four rays, coordinate by coordinate. */
typedef struct lanes {
    __m256d o[3], d[3];
} lanes;

/* Each lane's nearest hit so far: its distance (tmax at first) and the
 * primitive's index (-1 at first), as a double's bits for the blends. */
typedef struct nearest {
    __m256d t, i;
} nearest;

#define AVX2 __attribute__((target("avx2"), always_inline)) static inline
#define LOAD(x) _mm256_load_pd(x)
#define ADD _mm256_add_pd
#define SUB _mm256_sub_pd
#define MUL _mm256_mul_pd

/* BEGIN SNIPPET quad_axis_lanes */
/* (o + t d)_c - q_c: a coordinate of h in rt_quad_hit_distance. */
AVX2 __m256d h_at(const lanes *L, __m256d t, int c, const double *q)
{
    return SUB(ADD(L->o[c], MUL(t, L->d[c])), LOAD(q));
}

AVX2 __m256d quad_axis(const lanes *L, const rt_quad_axis *w, __m256d *a, __m256d *b)
{
    __m256d n = LOAD(w->n);
    __m256d t = _mm256_div_pd(SUB(LOAD(w->plane), MUL(n, L->o[w->k])), MUL(n, L->d[w->k]));
    *a = MUL(h_at(L, t, w->i, w->qi), LOAD(w->ea));
    *b = MUL(h_at(L, t, w->j, w->qj), LOAD(w->eb));
    return t;
}
/* END SNIPPET quad_axis_lanes */

/* Two terms are added in either order to the same bits. */
AVX2 __m256d quad_turned(const lanes *L, const rt_quad_turned *w, __m256d *a, __m256d *b)
{
    __m256d ni = LOAD(w->ni), nk = LOAD(w->nk);
    __m256d dn = ADD(MUL(ni, L->d[w->i]), MUL(nk, L->d[w->k]));
    __m256d on = ADD(MUL(ni, L->o[w->i]), MUL(nk, L->o[w->k]));
    __m256d t = _mm256_div_pd(SUB(LOAD(w->plane), on), dn);
    __m256d hi = h_at(L, t, w->i, w->qi), hk = h_at(L, t, w->k, w->qk);
    *a = ADD(MUL(hi, LOAD(w->ai)), MUL(hk, LOAD(w->ak)));
    *b = MUL(h_at(L, t, w->j, w->qj), LOAD(w->bj));
    return t;
}

AVX2 __m256d quad_flat(const lanes *L, const rt_quad_flat *w, __m256d *a, __m256d *b)
{
    __m256d n = LOAD(w->n);
    __m256d t = _mm256_div_pd(SUB(LOAD(w->plane), MUL(n, L->o[w->k])), MUL(n, L->d[w->k]));
    __m256d hi = h_at(L, t, w->i, w->qi), hj = h_at(L, t, w->j, w->qj);
    *a = ADD(MUL(hi, LOAD(w->ai)), MUL(hj, LOAD(w->aj)));
    *b = ADD(MUL(hi, LOAD(w->bi)), MUL(hj, LOAD(w->bj)));
    return t;
}

/* rt_quad_hit_distance in full; q->f in rt_quad_lanes's order. */
AVX2 __m256d quad_other(const lanes *L, const rt_quad_lanes *q, __m256d *a, __m256d *b)
{
    const __m256d *o = L->o, *d = L->d;
    __m256d dn = ADD(ADD(MUL(LOAD(q->f[0]), d[0]), MUL(LOAD(q->f[1]), d[1])), MUL(LOAD(q->f[2]), d[2]));
    __m256d on = ADD(ADD(MUL(LOAD(q->f[0]), o[0]), MUL(LOAD(q->f[1]), o[1])), MUL(LOAD(q->f[2]), o[2]));
    __m256d t = _mm256_div_pd(SUB(LOAD(q->f[3]), on), dn);
    __m256d hx = h_at(L, t, 0, q->f[4]), hy = h_at(L, t, 1, q->f[5]), hz = h_at(L, t, 2, q->f[6]);
    *a = ADD(ADD(MUL(hx, LOAD(q->f[7])), MUL(hy, LOAD(q->f[8]))), MUL(hz, LOAD(q->f[9])));
    *b = ADD(ADD(MUL(hx, LOAD(q->f[10])), MUL(hy, LOAD(q->f[11]))), MUL(hz, LOAD(q->f[12])));
    return t;
}

/* rt_sphere_hit_distance: the nearer root if it is beyond tmin, else the farther
 * (t1 = h - sq <= h + sq = t2 also in floating point); *disc gets the
 * discriminant, whose sign says whether the roots are real. */
AVX2 __m256d sphere(const lanes *L, const rt_sphere *s, __m256d lo, __m256d *disc)
{
    __m256d cx = SUB(_mm256_set1_pd(s->center.x), L->o[0]), cy = SUB(_mm256_set1_pd(s->center.y), L->o[1]),
            cz = SUB(_mm256_set1_pd(s->center.z), L->o[2]);
    __m256d h = ADD(ADD(MUL(L->d[0], cx), MUL(L->d[1], cy)), MUL(L->d[2], cz));
    __m256d c = SUB(ADD(ADD(MUL(cx, cx), MUL(cy, cy)), MUL(cz, cz)), _mm256_set1_pd(s->radius * s->radius));
    *disc = SUB(MUL(h, h), c);
    __m256d sq = _mm256_sqrt_pd(_mm256_max_pd(*disc, _mm256_setzero_pd())); /* max: 0 for a NaN */
    __m256d t1 = SUB(h, sq), t2 = ADD(h, sq);
    return _mm256_blendv_pd(t2, t1, _mm256_cmp_pd(t1, lo, _CMP_GT_OQ));
}

/* BEGIN SNIPPET keep_nearest */
/* Keeps t where the lanes of `in` (t > tmin, the point inside) are nearer
 * than the best so far: t < best, the last condition of rt_quad_hit_distance, is
 * left to a minimum, so that the chain from one primitive to the next is
 * that one instruction. min(x, y) is x < y ? x : y, which keeps y on a
 * tie as rt_quad_hit_distance's strict t < tmax does. */
AVX2 void keep(nearest *nb, __m256d t, __m256d in, __m256d prim)
{
    __m256d tm = _mm256_blendv_pd(_mm256_set1_pd(HUGE_VAL), t, in);
    nb->i = _mm256_blendv_pd(nb->i, prim, _mm256_cmp_pd(tm, nb->t, _CMP_LT_OQ));
    nb->t = _mm256_min_pd(tm, nb->t);
}
/* END SNIPPET keep_nearest */

/* The lanes with t > lo and a, b in [0, 1], by vector masks. */
AVX2 __m256d inside(__m256d t, __m256d a, __m256d b, __m256d lo)
{
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    __m256d in = _mm256_and_pd(_mm256_cmp_pd(a, zero, _CMP_GE_OQ), _mm256_cmp_pd(a, one, _CMP_LE_OQ));
    in = _mm256_and_pd(in, _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_GE_OQ),
                                          _mm256_cmp_pd(b, one, _CMP_LE_OQ)));
    return _mm256_and_pd(in, _mm256_cmp_pd(t, lo, _CMP_GT_OQ));
}

/* The rays r[0..3] as lanes: a 4 x 4 transpose of (o, d.x) and a 4 x 2
 * one of (d.y, d.z). */
AVX2 lanes load_rays(const rt_ray r[RT_LANES])
{
    _Static_assert(sizeof(rt_ray) == 6 * sizeof(double), "rt_ray is o then d, packed");
    const double *p = (const double *)(const void *)r;
    __m256d r0 = _mm256_loadu_pd(p), r1 = _mm256_loadu_pd(p + 6), r2 = _mm256_loadu_pd(p + 12),
            r3 = _mm256_loadu_pd(p + 18);
    __m256d e0 = _mm256_unpacklo_pd(r0, r1), e1 = _mm256_unpackhi_pd(r0, r1); /* x0 x1 z0 z1, ... */
    __m256d e2 = _mm256_unpacklo_pd(r2, r3), e3 = _mm256_unpackhi_pd(r2, r3);
    __m256d yz02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 4)),
                                        _mm_loadu_pd(p + 16), 1);
    __m256d yz13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 10)),
                                        _mm_loadu_pd(p + 22), 1);
    lanes L = {{_mm256_permute2f128_pd(e0, e2, 0x20), _mm256_permute2f128_pd(e1, e3, 0x20),
                _mm256_permute2f128_pd(e0, e2, 0x31)},
               {_mm256_permute2f128_pd(e1, e3, 0x31), _mm256_unpacklo_pd(yz02, yz13),
                _mm256_unpackhi_pd(yz02, yz13)}};
    return L;
}

/* The 4 x 4 transpose: row k of the result is lane k of c0..c3. */
AVX2 void transpose(__m256d c0, __m256d c1, __m256d c2, __m256d c3, __m256d row[4])
{
    __m256d e0 = _mm256_unpacklo_pd(c0, c1), e1 = _mm256_unpackhi_pd(c0, c1);
    __m256d e2 = _mm256_unpacklo_pd(c2, c3), e3 = _mm256_unpackhi_pd(c2, c3);
    row[0] = _mm256_permute2f128_pd(e0, e2, 0x20), row[1] = _mm256_permute2f128_pd(e1, e3, 0x20);
    row[2] = _mm256_permute2f128_pd(e0, e2, 0x31), row[3] = _mm256_permute2f128_pd(e1, e3, 0x31);
}

/* A sphere's outward normal: rt_prim_hit_record's
 * orient (normalize(p - c)), normalize(v) being v (1 / sqrt(v . v)). */
AVX2 void sphere_outward(const __m256d p[3], const __m256d c[3], __m256d orient, __m256d out[3])
{
    __m256d v[3] = {SUB(p[0], c[0]), SUB(p[1], c[1]), SUB(p[2], c[2])};
    __m256d len2 = ADD(ADD(MUL(v[0], v[0]), MUL(v[1], v[1])), MUL(v[2], v[2]));
    __m256d s = _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(len2));
    for (int k = 0; k < 3; k++)
        out[k] = MUL(orient, MUL(s, v[k]));
}

/* rt_prim_hit_record for the four lanes at once, from each primitive's
 * row (a quad's normal, or a sphere's centre and orient): the point, the
 * outward normal, rt_hit_set_face's side test and flip, lane by lane in
 * the scalar code's order. A lane that missed gets primitive 0's record,
 * which the caller may not read. */
AVX2 unsigned records(const rt_leaf_lanes *b4, const rt_prim *prims, const lanes *L, nearest nb,
                      rt_hit h[RT_LANES])
{
    _Static_assert(offsetof(rt_hit, t) == 0 && offsetof(rt_hit, p) == 8 && offsetof(rt_hit, normal) == 32 &&
                       offsetof(rt_hit, front_face) >= 56 && offsetof(rt_hit, material) >= 56 &&
                       offsetof(rt_hit, prim) >= 56,
                   "t, p and normal are the first 7 doubles of rt_hit, the rest follows");
    __m256i hit = _mm256_cmpgt_epi64(_mm256_castpd_si256(nb.i), _mm256_set1_epi64x(-1));
    int64_t is[RT_LANES];
    _mm256_storeu_si256((__m256i *)(void *)is, _mm256_and_si256(_mm256_castpd_si256(nb.i), hit));
    const double *w0 = b4->rows[is[0]], *w1 = b4->rows[is[1]], *w2 = b4->rows[is[2]], *w3 = b4->rows[is[3]];
    __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_load_pd(w0)), _mm_load_pd(w2), 1);
    __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_load_pd(w1)), _mm_load_pd(w3), 1);
    __m256d c = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_load_pd(w0 + 2)), _mm_load_pd(w2 + 2), 1);
    __m256d d = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_load_pd(w1 + 2)), _mm_load_pd(w3 + 2), 1);
    __m256d out[3] = {_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b), _mm256_unpacklo_pd(c, d)};
    __m256d orient = _mm256_unpackhi_pd(c, d), p[3];
    for (int k = 0; k < 3; k++)
        p[k] = ADD(L->o[k], MUL(nb.t, L->d[k]));
    /* Spheres are a few percent of the hits: their square root and
     * division only where a lane has one, a well-predicted branch. */
    __m256d sph = _mm256_cmp_pd(orient, _mm256_setzero_pd(), _CMP_NEQ_OQ);
    if (_mm256_movemask_pd(sph)) {
        __m256d s[3];
        sphere_outward(p, out, orient, s);
        for (int k = 0; k < 3; k++)
            out[k] = _mm256_blendv_pd(out[k], s[k], sph);
    }
    __m256d f = ADD(ADD(MUL(L->d[0], out[0]), MUL(L->d[1], out[1])), MUL(L->d[2], out[2]));
    __m256d front = _mm256_cmp_pd(f, _mm256_setzero_pd(), _CMP_LT_OQ);
    __m256d flip = _mm256_andnot_pd(front, _mm256_set1_pd(-0.0)), tp[4], nr[4];
    transpose(nb.t, p[0], p[1], p[2], tp);
    transpose(_mm256_xor_pd(out[0], flip), _mm256_xor_pd(out[1], flip), _mm256_xor_pd(out[2], flip),
              flip, nr);
    unsigned fb = (unsigned)_mm256_movemask_pd(front);
    for (int k = 0; k < RT_LANES; k++) {
        char *hk = (char *)(void *)&h[k];
        _mm256_storeu_pd((double *)(void *)hk, tp[k]);
        _mm256_storeu_pd((double *)(void *)(hk + offsetof(rt_hit, normal)), nr[k]);
        h[k].front_face = (fb >> k) & 1u;
        h[k].material = prims[is[k]].material;
        h[k].prim = (int)is[k];
    }
    return (unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(hit));
}

#define PRIM(w) _mm256_load_pd((const double *)(const void *)(w).prim)
/* Every quad of one kind: its distances, then INSIDE and KEEP. */
#define QUADS(n, kind, test, INSIDE, KEEP)                                                          \
    for (int q = 0; q < b4->n; q++) {                                                                \
        __m256d a, b, t = test(&L, &b4->kind[q], &a, &b);                                            \
        KEEP(&nb, t, INSIDE(t, a, b, lo), PRIM(b4->kind[q]));                                        \
    }

/* The root leaf against the four rays, each lane keeping its nearest
 * hit; then the records. */
/* BEGIN SNIPPET hit4_avx2 */
__attribute__((target("avx2"))) static unsigned hit4_avx2(const rt_leaf_lanes *b4, const rt_prim *prims,
                                                         const rt_ray r[RT_LANES], double tmin,
                                                         double tmax, rt_hit h[RT_LANES])
{
    lanes L = load_rays(r);
    const __m256d lo = _mm256_set1_pd(tmin);
    nearest nb = {_mm256_set1_pd(tmax), _mm256_castsi256_pd(_mm256_set1_epi64x(-1))};
    QUADS(n_axis, axis, quad_axis, inside, keep)
    QUADS(n_turned, turned, quad_turned, inside, keep)
    QUADS(n_flat, flat, quad_flat, inside, keep)
    QUADS(n_other, other, quad_other, inside, keep)
    for (int j = 0; j < b4->n_spheres; j++) {
        int i = b4->spheres[j];
        __m256d disc, t = sphere(&L, &prims[i].as.sphere, lo, &disc);
        __m256d in = _mm256_and_pd(_mm256_cmp_pd(disc, _mm256_setzero_pd(), _CMP_GE_OQ),
                                   _mm256_cmp_pd(t, lo, _CMP_GT_OQ));
        keep(&nb, t, in, _mm256_castsi256_pd(_mm256_set1_epi64x(i)));
    }
    return records(b4, prims, &L, nb, h);
}
/* END SNIPPET hit4_avx2 */

/* A shadow ray's lane: its own tmax, and whether a hit nearer than that
 * has been met. */
typedef struct blocked {
    __m256d tmax, any;
} blocked;

/* keep's counterpart for shadow rays: a lane is blocked by any hit that
 * `in` admits (t > tmin, the point inside) nearer than its own tmax. keep
 * admits the same hits and ends with their minimum, so "some admitted
 * hit is nearer than tmax" is "the nearest is", the reference's
 * question. The primitive is not needed. */
AVX2 void block(blocked *nb, __m256d t, __m256d in, __m256d prim)
{
    (void)prim;
    nb->any = _mm256_or_pd(nb->any, _mm256_and_pd(in, _mm256_cmp_pd(t, nb->tmax, _CMP_LT_OQ)));
}

/* The root leaf against four shadow rays: hit4_avx2's tests, each lane
 * against its own tmax, and no records. */
/* BEGIN SNIPPET occluded4_avx2 */
__attribute__((target("avx2"))) static unsigned occluded4_avx2(const rt_leaf_lanes *b4,
                                                              const rt_prim *prims,
                                                              const rt_ray r[RT_LANES], double tmin,
                                                              const double tmax[RT_LANES])
{
    lanes L = load_rays(r);
    const __m256d lo = _mm256_set1_pd(tmin);
    blocked nb = {_mm256_loadu_pd(tmax), _mm256_setzero_pd()};
    QUADS(n_axis, axis, quad_axis, inside, block)
    QUADS(n_turned, turned, quad_turned, inside, block)
    QUADS(n_flat, flat, quad_flat, inside, block)
    QUADS(n_other, other, quad_other, inside, block)
    for (int j = 0; j < b4->n_spheres; j++) {
        __m256d disc, t = sphere(&L, &prims[b4->spheres[j]].as.sphere, lo, &disc);
        __m256d in = _mm256_and_pd(_mm256_cmp_pd(disc, _mm256_setzero_pd(), _CMP_GE_OQ),
                                   _mm256_cmp_pd(t, lo, _CMP_GT_OQ));
        block(&nb, t, in, _mm256_setzero_pd());
    }
    return (unsigned)_mm256_movemask_pd(nb.any);
}
/* END SNIPPET occluded4_avx2 */

/* BEGIN SNIPPET hit1_avx2 */
/* One ray against the root leaf: the ray in every lane, four quads in
 * each packet (quad_other: the full test, valid for any tmin), each lane
 * keeping its nearest; then the nearest lane, then the spheres. Every
 * quad of a lane comes before those of the next lane (hit4.h) and a lane
 * keeps the first of equal distances, so the lowest lane holding the
 * minimum holds the first quad at that distance, as in rt_bvh_hit; a
 * sphere wins a tie only from a later primitive. */
__attribute__((target("avx2"))) static bool hit1_avx2(const rt_leaf_lanes *b4, const rt_prim *prims,
                                                     const rt_ray *r, double tmin, double tmax,
                                                     rt_hit *h)
{
    lanes L = {{_mm256_set1_pd(r->origin.x), _mm256_set1_pd(r->origin.y), _mm256_set1_pd(r->origin.z)},
               {_mm256_set1_pd(r->dir.x), _mm256_set1_pd(r->dir.y), _mm256_set1_pd(r->dir.z)}};
    const __m256d lo = _mm256_set1_pd(tmin);
    nearest nb = {_mm256_set1_pd(tmax), _mm256_castsi256_pd(_mm256_set1_epi64x(-1))};
    QUADS(n_packets, packets, quad_other, inside, keep)
    __m256d m2 = _mm256_min_pd(nb.t, _mm256_permute_pd(nb.t, 0x5));
    __m256d m4 = _mm256_min_pd(m2, _mm256_permute2f128_pd(m2, m2, 0x1));
    /* No quad hit: every lane holds tmax and -1. */
    unsigned eq = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(nb.t, m4, _CMP_EQ_OQ));
    int64_t is[RT_LANES];
    _mm256_storeu_si256((__m256i *)(void *)is, _mm256_castpd_si256(nb.i));
    double best = _mm256_cvtsd_f64(m4);
    int best_i = (int)is[__builtin_ctz(eq | 0x10u) & 3];
    for (int j = 0; j < b4->n_spheres; j++) {
        int i = b4->spheres[j];
        __m256d disc, t4 = sphere(&L, &prims[i].as.sphere, lo, &disc);
        double t = _mm256_cvtsd_f64(t4);
        int closer = (_mm256_cvtsd_f64(disc) >= 0.0) & (t > tmin) &
                     ((t < best) | ((t == best) & (i < best_i)));
        best_i = closer ? i : best_i;
        best = closer ? t : best;
    }
    if (best_i < 0)
        return false;
    rt_prim_hit_record(&prims[best_i], best_i, *r, best, h);
    return true;
}
/* END SNIPPET hit1_avx2 */
#endif

rt_leaf_tests rt_fast_leaf_tests(rt_isa isa)
{
#if RT_ISA_X86
    if (isa == RT_ISA_AVX2)
        return (rt_leaf_tests){hit4_avx2, hit1_avx2, occluded4_avx2};
#else
    (void)isa;
#endif
    return (rt_leaf_tests){NULL, NULL, NULL};
}
