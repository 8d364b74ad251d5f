/* render/leaf4.c - the lanes of a root leaf: its quads sorted by the
 * kind of their normal and edges, each field repeated in four lanes, and
 * the packets of four quads for a ray traced alone; and the choice between
 * the four-wide tests (render/fast/hit4.c) and the BVH. */
#include "render/leaf4.h"

#include <stdlib.h>
#include <string.h>

/* The index of the only nonzero (or NaN) coordinate of (x, y, z), -1 if
 * there is not exactly one. */
static int single_axis(const double v[3])
{
    int nonzero = (v[0] != 0.0) + (v[1] != 0.0) + (v[2] != 0.0);
    return nonzero != 1 ? -1 : v[0] != 0.0 ? 0 : v[1] != 0.0 ? 1 : 2;
}

/* The axis j of a quad turned about a coordinate axis (rt_quad_turned):
 * n_j = 0 with the other two coordinates of n nonzero, one dual edge
 * vector along j and the other zero at j, nonzero at i and k. *swap says
 * that ea is the one along j. -1 for a quad of another kind. */
static int turned_axis(const double n[3], const double ea[3], const double eb[3], bool *swap)
{
    for (int j = 0; j < 3; j++) {
        int i = j == 0 ? 1 : 0, k = j == 2 ? 1 : 2;
        if (n[j] != 0.0 || n[i] == 0.0 || n[k] == 0.0)
            continue;
        *swap = single_axis(ea) == j;
        const double *a = *swap ? eb : ea, *b = *swap ? ea : eb;
        if (single_axis(b) == j && a[j] == 0.0 && a[i] != 0.0 && a[k] != 0.0)
            return j;
    }
    return -1;
}

#define EACH_LANE for (int l = 0; l < RT_LANES; l++)

/* The thirteen numbers of rt_quad_hit_distance in rt_quad_lanes's order:
 * normal, plane, corner, ea, eb. */
static void quad_fields(const rt_quad *s, double f[13])
{
    const double v[13] = {s->normal.x, s->normal.y, s->normal.z, s->plane, s->q.x, s->q.y, s->q.z,
                          s->ea.x, s->ea.y, s->ea.z, s->eb.x, s->eb.y, s->eb.z};
    memcpy(f, v, sizeof v);
}

/* Appends quad s (prims[prim]) to the layout of its kind. The edge test
 * is symmetric in a and b, so a turned quad may swap them. */
static void lay_out_quad(rt_leaf_lanes *b4, const rt_quad *s, int64_t prim)
{
    const double n[3] = {s->normal.x, s->normal.y, s->normal.z}, o[3] = {s->q.x, s->q.y, s->q.z};
    const double ea[3] = {s->ea.x, s->ea.y, s->ea.z}, eb[3] = {s->eb.x, s->eb.y, s->eb.z};
    int k = single_axis(n), ia = single_axis(ea), ib = single_axis(eb);
    bool swap = false;
    int tj = turned_axis(n, ea, eb, &swap);
    if (k >= 0 && ia >= 0 && ib >= 0) {
        rt_quad_axis *w = &b4->axis[b4->n_axis++];
        w->k = k, w->i = ia, w->j = ib;
        EACH_LANE w->n[l] = n[k], w->plane[l] = s->plane, w->qi[l] = o[ia], w->qj[l] = o[ib],
              w->ea[l] = ea[ia], w->eb[l] = eb[ib], w->prim[l] = prim;
    } else if (k >= 0 && ea[k] == 0.0 && eb[k] == 0.0) {
        rt_quad_flat *w = &b4->flat[b4->n_flat++];
        int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
        w->k = k, w->i = i, w->j = j;
        EACH_LANE w->n[l] = n[k], w->plane[l] = s->plane, w->qi[l] = o[i], w->qj[l] = o[j],
              w->ai[l] = ea[i], w->aj[l] = ea[j], w->bi[l] = eb[i], w->bj[l] = eb[j], w->prim[l] = prim;
    } else if (tj >= 0) {
        rt_quad_turned *w = &b4->turned[b4->n_turned++];
        const double *a = swap ? eb : ea, *b = swap ? ea : eb;
        int i = tj == 0 ? 1 : 0, kk = tj == 2 ? 1 : 2;
        w->i = i, w->j = tj, w->k = kk;
        EACH_LANE w->ni[l] = n[i], w->nk[l] = n[kk], w->plane[l] = s->plane, w->qi[l] = o[i],
              w->qj[l] = o[tj], w->qk[l] = o[kk], w->ai[l] = a[i], w->ak[l] = a[kk], w->bj[l] = b[tj],
              w->prim[l] = prim;
    } else {
        double f[13];
        quad_fields(s, f);
        rt_quad_lanes *w = &b4->other[b4->n_other++];
        EACH_LANE {
            for (int g = 0; g < 13; g++)
                w->f[g][l] = f[g];
            w->prim[l] = prim;
        }
    }
}

/* The packets of the one-ray test (hit4.h): quad number c of the leaf
 * (c-th in prims) goes to lane c / n_packets of row c % n_packets. */
static void pack_quads(rt_leaf_lanes *b4, const rt_prim *prims, int n)
{
    int nq = 0;
    for (int i = 0; i < n; i++)
        nq += prims[i].kind == RT_PRIM_QUAD;
    b4->n_packets = (nq + RT_LANES - 1) / RT_LANES;
    memset(b4->packets, 0, (size_t)b4->n_packets * sizeof *b4->packets);
    for (int p = 0; p < b4->n_packets; p++)
        EACH_LANE b4->packets[p].prim[l] = -1;
    for (int i = 0, c = 0; i < n; i++) {
        if (prims[i].kind != RT_PRIM_QUAD)
            continue;
        double f[13];
        quad_fields(&prims[i].as.quad, f);
        rt_quad_lanes *w = &b4->packets[c % b4->n_packets];
        int l = c++ / b4->n_packets;
        for (int g = 0; g < 13; g++)
            w->f[g][l] = f[g];
        w->prim[l] = i;
    }
}

rt_leaf_lanes *rt_leaf_lanes_create(const rt_prim *prims, int n)
{
    _Static_assert(sizeof(rt_quad_axis) % 64 == 0 && sizeof(rt_quad_lanes) % 64 == 0 &&
                       sizeof(rt_quad_flat) % 64 == 0 && sizeof(rt_quad_turned) % 64 == 0,
                   "rows of 32-byte lanes stay aligned from one quad to the next");
    rt_leaf_lanes *b4 = calloc(1, sizeof *b4);
    if (!b4)
        return NULL;
    /* Sizes rounded up to the alignment, as aligned_alloc wants. */
    size_t nq = (size_t)(n > 0 ? n : 1), rows = ((size_t)n + 1) / 2 * 2;
    b4->axis = aligned_alloc(64, nq * sizeof *b4->axis);
    b4->turned = aligned_alloc(64, nq * sizeof *b4->turned);
    b4->flat = aligned_alloc(64, nq * sizeof *b4->flat);
    b4->other = aligned_alloc(64, nq * sizeof *b4->other);
    b4->spheres = malloc(nq * sizeof *b4->spheres);
    b4->rows = aligned_alloc(64, rows * sizeof *b4->rows);
    b4->packets = aligned_alloc(64, nq * sizeof *b4->packets);
    if (!b4->axis || !b4->turned || !b4->flat || !b4->other || !b4->spheres || !b4->rows ||
        !b4->packets) {
        rt_leaf_lanes_destroy(b4);
        return NULL;
    }
    memset(b4->axis, 0, nq * sizeof *b4->axis);
    memset(b4->turned, 0, nq * sizeof *b4->turned);
    memset(b4->flat, 0, nq * sizeof *b4->flat);
    pack_quads(b4, prims, n);
    for (int i = 0; i < n; i++) {
        if (prims[i].kind == RT_PRIM_QUAD) {
            const rt_quad *s = &prims[i].as.quad;
            lay_out_quad(b4, s, i);
            memcpy(b4->rows[i], (const double[4]){s->normal.x, s->normal.y, s->normal.z, 0.0},
                   sizeof b4->rows[i]);
        } else {
            const rt_sphere *s = &prims[i].as.sphere;
            b4->spheres[b4->n_spheres++] = i;
            memcpy(b4->rows[i], (const double[4]){s->center.x, s->center.y, s->center.z, s->orient},
                   sizeof b4->rows[i]);
        }
    }
    return b4;
}

void rt_leaf_lanes_destroy(rt_leaf_lanes *b4)
{
    if (!b4)
        return;
    free(b4->axis);
    free(b4->turned);
    free(b4->flat);
    free(b4->other);
    free(b4->spheres);
    free(b4->rows);
    free(b4->packets);
    free(b4);
}

/* BEGIN SNIPPET hit4_dispatch */
unsigned rt_leaf_lanes_hit(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                           const rt_prim *prims, const rt_ray r[RT_LANES], double tmin,
                           double tmax, rt_hit h[RT_LANES])
{
    /* tmin >= 0: the exactness argument of render/fast/hit4.c needs it. */
    if (t && t->hit4 && ll && tmin >= 0.0)
        return t->hit4(ll, prims, r, tmin, tmax, h);
    unsigned mask = 0;
    for (int k = 0; k < RT_LANES; k++)
        mask |= (unsigned)rt_bvh_hit(bvh, prims, &r[k], tmin, tmax, &h[k]) << k;
    return mask;
}
/* END SNIPPET hit4_dispatch */

unsigned rt_leaf_lanes_occluded(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                                const rt_prim *prims, const rt_ray r[RT_LANES], double tmin,
                                const double tmax[RT_LANES])
{
    if (t && t->occluded4 && ll && tmin >= 0.0)
        return t->occluded4(ll, prims, r, tmin, tmax);
    double far = tmax[0];
    for (int k = 1; k < RT_LANES; k++)
        far = tmax[k] > far ? tmax[k] : far;
    rt_hit h[RT_LANES];
    unsigned hit = rt_leaf_lanes_hit(t, ll, bvh, prims, r, tmin, far, h), blocked = 0u;
    for (int k = 0; k < RT_LANES; k++)
        if ((hit >> k) & 1u && h[k].t < tmax[k])
            blocked |= 1u << k;
    return blocked;
}

bool rt_leaf_lanes_hit1(const rt_leaf_tests *t, const rt_leaf_lanes *ll, const rt_bvh *bvh,
                        const rt_prim *prims, const rt_ray *r, double tmin, double tmax,
                        rt_hit *h)
{
    if (t && t->hit1 && ll)
        return t->hit1(ll, prims, r, tmin, tmax, h);
    return rt_bvh_hit(bvh, prims, r, tmin, tmax, h);
}
