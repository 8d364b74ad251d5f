/* render/shapes.c - quad and sphere construction, hit records, bounds. */
#include "render/shapes.h"

rt_quad rt_quad_make(vec3 q, vec3 u, vec3 v)
{
    rt_quad s;
    vec3 n = vec3_cross(u, v);
    double len_sq = vec3_length_sq(n);
    /* w = (u x v) / |u x v|^2 turns cross products with the edges into the
     * edge coordinates: (a u + b v) x v = a (u x v), so w . (h x v) = a. */
    vec3 w = vec3_scale(n, 1.0 / len_sq);
    s.q = q;
    s.u = u;
    s.v = v;
    s.normal = vec3_scale(n, 1.0 / sqrt(len_sq));
    s.plane = vec3_dot(s.normal, q);
    s.ea = vec3_cross(v, w);
    s.eb = vec3_cross(w, u);
    return s;
}

rt_sphere rt_sphere_make(vec3 center, double radius, double orient)
{
    rt_sphere s = {center, radius, orient < 0.0 ? -1.0 : 1.0};
    return s;
}

/* Widens b by the padding on every side. Flat boxes need it (the slab
 * test of a zero-width slab is 0 * inf when the ray runs inside the plane),
 * and a hit that the closed edge test accepts may lie a rounding error
 * outside the exact box; padding keeps the BVH's answers equal to brute
 * force. */
static rt_aabb pad(rt_aabb b)
{
    double size = fmax(fmax(fabs(b.lo.x), fabs(b.hi.x)),
                       fmax(fmax(fabs(b.lo.y), fabs(b.hi.y)), fmax(fabs(b.lo.z), fabs(b.hi.z))));
    double e = RT_BOX_PAD * (1.0 + size);
    vec3 d = vec3_make(e, e, e);
    b.lo = vec3_sub(b.lo, d);
    b.hi = vec3_add(b.hi, d);
    return b;
}

rt_aabb rt_prim_bounds(const rt_prim *p)
{
    rt_aabb b = rt_aabb_empty();
    if (p->kind == RT_PRIM_QUAD) {
        const rt_quad *s = &p->as.quad;
        b = rt_aabb_add_point(b, s->q);
        b = rt_aabb_add_point(b, vec3_add(s->q, s->u));
        b = rt_aabb_add_point(b, vec3_add(s->q, s->v));
        b = rt_aabb_add_point(b, vec3_add(vec3_add(s->q, s->u), s->v));
    } else {
        const rt_sphere *s = &p->as.sphere;
        vec3 r = vec3_make(s->radius, s->radius, s->radius);
        b.lo = vec3_sub(s->center, r);
        b.hi = vec3_add(s->center, r);
    }
    return pad(b);
}
