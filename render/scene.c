/* render/scene.c - the object tree, flattening, lights and hit queries. */
#include "render/scene.h"

#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"

typedef enum node_kind { NODE_PRIM, NODE_LIST, NODE_TRANSLATE, NODE_ROTATE_Y, NODE_FLIP } node_kind;

typedef struct node {
    node_kind kind;
    rt_prim prim;        /* NODE_PRIM, in the node's own frame */
    int first, count;    /* NODE_LIST: children[first .. first + count) */
    int child;           /* instances */
    vec3 offset;         /* NODE_TRANSLATE */
    double sin_t, cos_t; /* NODE_ROTATE_Y */
} node;

struct rt_scene {
    rt_material *materials;
    int n_materials, cap_materials;
    node *nodes;
    int n_nodes, cap_nodes;
    int *children;
    int n_children, cap_children;
    int *world;
    int n_world, cap_world;
    int light_objs[RT_MAX_LIGHTS];
    int n_light_objs;
    double t_min;
    vec3 background;
    bool failed, built;
    /* Built by rt_scene_build. */
    rt_prim *prims;
    int n_prims, cap_prims;
    rt_bvh bvh;
    rt_leaf_lanes *lanes; /* the root leaf in lanes, NULL if none */
    rt_leaf_tests leaf;   /* the tests that read them (none: the BVH alone) */
    rt_prim lights[RT_MAX_LIGHTS];
    rt_light fast_lights[RT_MAX_LIGHTS];
    int n_lights;
    rt_prim emitters[RT_MAX_LIGHTS];
    rt_light fast_emitters[RT_MAX_LIGHTS];
    int n_emitters;
    rt_light fast_targets[RT_MAX_LIGHTS]; /* the light list's entries that do not emit */
    int n_targets;
};

/* Makes room for one more element of `size` bytes in *arr. */
static bool grow(rt_scene *s, void **arr, int *cap, int n, size_t size)
{
    if (s->failed)
        return false;
    if (n < *cap)
        return true;
    int nc = *cap ? 2 * *cap : 16;
    void *p = realloc(*arr, (size_t)nc * size);
    if (!p) {
        s->failed = true;
        return false;
    }
    *arr = p;
    *cap = nc;
    return true;
}

rt_scene *rt_scene_create(void)
{
    rt_scene *s = calloc(1, sizeof *s);
    if (s)
        s->t_min = 1e-3;
    return s;
}

void rt_scene_destroy(rt_scene *s)
{
    if (!s)
        return;
    free(s->materials);
    free(s->nodes);
    free(s->children);
    free(s->world);
    free(s->prims);
    rt_bvh_destroy(&s->bvh);
    rt_leaf_lanes_destroy(s->lanes);
    free(s);
}

int rt_scene_add_material(rt_scene *s, rt_material m)
{
    if (!grow(s, (void **)&s->materials, &s->cap_materials, s->n_materials, sizeof m))
        return -1;
    s->materials[s->n_materials] = m;
    return s->n_materials++;
}

static bool valid(rt_scene *s, rt_object o)
{
    if (o < 0 || o >= s->n_nodes)
        s->failed = true;
    return !s->failed;
}

static rt_object new_node(rt_scene *s, node n)
{
    if (!grow(s, (void **)&s->nodes, &s->cap_nodes, s->n_nodes, sizeof n))
        return -1;
    s->nodes[s->n_nodes] = n;
    return s->n_nodes++;
}

rt_object rt_scene_sphere(rt_scene *s, vec3 center, double radius, int material)
{
    node n = {.kind = NODE_PRIM};
    n.prim.kind = RT_PRIM_SPHERE;
    n.prim.material = material;
    n.prim.as.sphere = rt_sphere_make(center, radius, 1.0);
    if (!(radius > 0.0))
        s->failed = true;
    return new_node(s, n);
}

rt_object rt_scene_quad(rt_scene *s, vec3 q, vec3 u, vec3 v, int material)
{
    node n = {.kind = NODE_PRIM};
    n.prim.kind = RT_PRIM_QUAD;
    n.prim.material = material;
    n.prim.as.quad = rt_quad_make(q, u, v);
    if (!(vec3_length_sq(vec3_cross(u, v)) > 0.0))
        s->failed = true;
    return new_node(s, n);
}

rt_object rt_scene_list(rt_scene *s, const rt_object *items, int n)
{
    if (n < 1)
        s->failed = true;
    node nd = {.kind = NODE_LIST, .first = s->n_children, .count = n};
    for (int i = 0; i < n && !s->failed; i++) {
        if (!valid(s, items[i]) ||
            !grow(s, (void **)&s->children, &s->cap_children, s->n_children, sizeof(int)))
            return -1;
        s->children[s->n_children++] = items[i];
    }
    return s->failed ? -1 : new_node(s, nd);
}

rt_object rt_scene_box(rt_scene *s, vec3 a, vec3 b, int material)
{
    vec3 dx = vec3_make(b.x - a.x, 0.0, 0.0), dy = vec3_make(0.0, b.y - a.y, 0.0);
    vec3 dz = vec3_make(0.0, 0.0, b.z - a.z);
    /* Corner and edge order chosen so that u x v points out of the box. */
    rt_object side[6] = {
        rt_scene_quad(s, vec3_make(a.x, a.y, b.z), dx, dy, material),           /* z = max */
        rt_scene_quad(s, vec3_make(b.x, a.y, a.z), vec3_neg(dx), dy, material), /* z = min */
        rt_scene_quad(s, vec3_make(b.x, a.y, b.z), vec3_neg(dz), dy, material), /* x = max */
        rt_scene_quad(s, a, dz, dy, material),                                  /* x = min */
        rt_scene_quad(s, vec3_make(a.x, b.y, b.z), dx, vec3_neg(dz), material), /* y = max */
        rt_scene_quad(s, a, dx, dz, material),                                  /* y = min */
    };
    return rt_scene_list(s, side, 6);
}

rt_object rt_scene_translate(rt_scene *s, rt_object child, vec3 offset)
{
    node n = {.kind = NODE_TRANSLATE, .child = child, .offset = offset};
    return valid(s, child) ? new_node(s, n) : -1;
}

rt_object rt_scene_rotate_y(rt_scene *s, rt_object child, double degrees)
{
    double theta = degrees * (MC_PI / 180.0);
    node n = {.kind = NODE_ROTATE_Y, .child = child, .sin_t = sin(theta), .cos_t = cos(theta)};
    return valid(s, child) ? new_node(s, n) : -1;
}

rt_object rt_scene_flip(rt_scene *s, rt_object child)
{
    node n = {.kind = NODE_FLIP, .child = child};
    return valid(s, child) ? new_node(s, n) : -1;
}

void rt_scene_add(rt_scene *s, rt_object o)
{
    if (valid(s, o) && grow(s, (void **)&s->world, &s->cap_world, s->n_world, sizeof(int)))
        s->world[s->n_world++] = o;
}

void rt_scene_add_light(rt_scene *s, rt_object o)
{
    if (!valid(s, o) || s->n_light_objs >= RT_MAX_LIGHTS) {
        s->failed = true;
        return;
    }
    s->light_objs[s->n_light_objs++] = o;
}

void rt_scene_set_t_min(rt_scene *s, double t_min) { s->t_min = t_min; }
void rt_scene_set_background(rt_scene *s, vec3 radiance) { s->background = radiance; }

/* --- flattening --------------------------------------------------------- */

/* A rigid motion p -> m p + t, and whether faces are flipped. */
typedef struct xform {
    double m[3][3];
    vec3 t;
    bool flip;
} xform;

static vec3 xf_vec(const xform *x, vec3 v)
{
    return vec3_make(x->m[0][0] * v.x + x->m[0][1] * v.y + x->m[0][2] * v.z,
                     x->m[1][0] * v.x + x->m[1][1] * v.y + x->m[1][2] * v.z,
                     x->m[2][0] * v.x + x->m[2][1] * v.y + x->m[2][2] * v.z);
}

static vec3 xf_point(const xform *x, vec3 p) { return vec3_add(xf_vec(x, p), x->t); }

/* The primitive moved by x: corner and centre as points, edges as vectors;
 * a flip swaps the edges (reversing u x v) or turns a sphere inside out. */
static rt_prim xf_prim(const xform *x, const rt_prim *p)
{
    rt_prim out = *p;
    if (p->kind == RT_PRIM_QUAD) {
        vec3 u = xf_vec(x, p->as.quad.u), v = xf_vec(x, p->as.quad.v);
        vec3 q = xf_point(x, p->as.quad.q);
        out.as.quad = x->flip ? rt_quad_make(q, v, u) : rt_quad_make(q, u, v);
    } else {
        const rt_sphere *sp = &p->as.sphere;
        out.as.sphere = rt_sphere_make(xf_point(x, sp->center), sp->radius,
                                       x->flip ? -sp->orient : sp->orient);
    }
    return out;
}

/* Appends the world-space primitives of object o under transform x.
 * Instances compose on the right: the child's frame is mapped first by the
 * instance, then by x. */
static void flatten(rt_scene *s, int o, xform x)
{
    const node *n = &s->nodes[o];
    switch (n->kind) {
    case NODE_PRIM:
        if (grow(s, (void **)&s->prims, &s->cap_prims, s->n_prims, sizeof(rt_prim)))
            s->prims[s->n_prims++] = xf_prim(&x, &n->prim);
        return;
    case NODE_LIST:
        for (int i = 0; i < n->count; i++)
            flatten(s, s->children[n->first + i], x);
        return;
    case NODE_TRANSLATE: {
        xform y = x;
        y.t = xf_point(&x, n->offset);
        flatten(s, n->child, y);
        return;
    }
    case NODE_ROTATE_Y: {
        /* x m R with R = [[c, 0, s], [0, 1, 0], [-s, 0, c]]. */
        xform y = x;
        for (int r = 0; r < 3; r++) {
            y.m[r][0] = x.m[r][0] * n->cos_t - x.m[r][2] * n->sin_t;
            y.m[r][2] = x.m[r][0] * n->sin_t + x.m[r][2] * n->cos_t;
        }
        flatten(s, n->child, y);
        return;
    }
    case NODE_FLIP: {
        xform y = x;
        y.flip = !x.flip;
        flatten(s, n->child, y);
        return;
    }
    }
}

static xform identity(void)
{
    xform x = {{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}, {0.0, 0.0, 0.0}, false};
    return x;
}

static bool materials_valid(const rt_scene *s, const rt_prim *p, int n)
{
    for (int i = 0; i < n; i++)
        if (p[i].material < 0 || p[i].material >= s->n_materials)
            return false;
    return true;
}

/* Each light must flatten to exactly one primitive. */
static int build_lights(rt_scene *s)
{
    for (int i = 0; i < s->n_light_objs; i++) {
        int before = s->n_prims;
        flatten(s, s->light_objs[i], identity());
        if (s->failed || s->n_prims != before + 1)
            return -1;
        s->lights[i] = s->prims[--s->n_prims];
        s->fast_lights[i] = rt_light_make(&s->lights[i]);
    }
    s->n_lights = s->n_light_objs;
    return 0;
}

int rt_scene_build(rt_scene *s)
{
    if (s->failed || s->built || s->n_world == 0 || build_lights(s) != 0)
        return -1;
    for (int i = 0; i < s->n_world; i++)
        flatten(s, s->world[i], identity());
    if (s->failed || !materials_valid(s, s->prims, s->n_prims) ||
        !materials_valid(s, s->lights, s->n_lights) ||
        rt_bvh_build(&s->bvh, s->prims, s->n_prims) != 0)
        return -1;
    /* A small scene, one leaf or up to RT_LEAF_LANES_MAX_PRIMS primitives:
     * laid out for the four-wide leaf tests, which then answer every ray
     * (render/leaf4.h says why the answers are the BVH's). */
    if ((s->bvh.nodes[0].count > 0 || s->n_prims <= RT_LEAF_LANES_MAX_PRIMS) &&
        !(s->lanes = rt_leaf_lanes_create(s->prims, s->n_prims)))
        return -1;
    for (int i = 0; i < s->n_lights; i++) {
        vec3 e = s->materials[s->lights[i].material].emission;
        if (e.x != 0.0 || e.y != 0.0 || e.z != 0.0) {
            s->emitters[s->n_emitters] = s->lights[i];
            s->fast_emitters[s->n_emitters++] = s->fast_lights[i];
        } else {
            s->fast_targets[s->n_targets++] = s->fast_lights[i];
        }
    }
    s->built = true;
    return 0;
}

/* --- queries ------------------------------------------------------------- */

bool rt_scene_hit(const rt_scene *s, rt_ray r, double tmax, rt_hit *h)
{
    return rt_leaf_lanes_hit1(&s->leaf, s->lanes, &s->bvh, s->prims, &r, s->t_min, tmax, h);
}

unsigned rt_scene_hit4(const rt_scene *s, const rt_ray r[RT_LANES], double tmax, rt_hit h[RT_LANES])
{
    return rt_leaf_lanes_hit(&s->leaf, s->lanes, &s->bvh, s->prims, r, s->t_min, tmax, h);
}

unsigned rt_scene_occluded4(const rt_scene *s, const rt_ray r[RT_LANES],
                            const double tmax[RT_LANES])
{
    return rt_leaf_lanes_occluded(&s->leaf, s->lanes, &s->bvh, s->prims, r, s->t_min, tmax);
}

bool rt_scene_hit_brute(const rt_scene *s, rt_ray r, double tmax, rt_hit *h)
{
    int i;
    double t = rt_prims_closest(s->prims, s->n_prims, r, s->t_min, tmax, &i);
    if (i < 0)
        return false;
    rt_prim_hit_record(&s->prims[i], i, r, t, h);
    return true;
}

/* The book's recursive hit: lists keep the closest, instances transform
 * the ray in and the hit record out. Rigid motions keep |dir| = 1, so t
 * is the same distance in every frame. */
static bool tree_hit(const rt_scene *s, int o, rt_ray r, double tmin, double tmax, rt_hit *h)
{
    const node *n = &s->nodes[o];
    switch (n->kind) {
    case NODE_PRIM: {
        double t = rt_prim_hit_distance(&n->prim, r, tmin, tmax);
        if (!(t < tmax))
            return false;
        rt_prim_hit_record(&n->prim, -1, r, t, h);
        return true;
    }
    case NODE_LIST: {
        bool any = false;
        for (int i = 0; i < n->count; i++)
            if (tree_hit(s, s->children[n->first + i], r, tmin, tmax, h)) {
                any = true;
                tmax = h->t;
            }
        return any;
    }
    case NODE_TRANSLATE: {
        rt_ray local = rt_ray_make(vec3_sub(r.origin, n->offset), r.dir);
        if (!tree_hit(s, n->child, local, tmin, tmax, h))
            return false;
        h->p = vec3_add(h->p, n->offset);
        return true;
    }
    case NODE_ROTATE_Y: {
        double c = n->cos_t, sn = n->sin_t;
        /* World to object is the inverse (transpose) rotation. */
        rt_ray local = rt_ray_make(vec3_make(c * r.origin.x - sn * r.origin.z, r.origin.y,
                                             sn * r.origin.x + c * r.origin.z),
                                   vec3_make(c * r.dir.x - sn * r.dir.z, r.dir.y,
                                             sn * r.dir.x + c * r.dir.z));
        if (!tree_hit(s, n->child, local, tmin, tmax, h))
            return false;
        vec3 p = h->p, nn = h->normal;
        h->p = vec3_make(c * p.x + sn * p.z, p.y, -sn * p.x + c * p.z);
        h->normal = vec3_make(c * nn.x + sn * nn.z, nn.y, -sn * nn.x + c * nn.z);
        return true;
    }
    case NODE_FLIP:
        if (!tree_hit(s, n->child, r, tmin, tmax, h))
            return false;
        h->front_face = !h->front_face;
        return true;
    }
    return false;
}

bool rt_scene_hit_tree(const rt_scene *s, rt_ray r, double tmax, rt_hit *h)
{
    bool any = false;
    for (int i = 0; i < s->n_world; i++)
        if (tree_hit(s, s->world[i], r, s->t_min, tmax, h)) {
            any = true;
            tmax = h->t;
        }
    return any;
}

const rt_material *rt_scene_material(const rt_scene *s, int m) { return &s->materials[m]; }
int rt_scene_light_count(const rt_scene *s) { return s->n_lights; }

/* The pdf list toward the n primitives lights[0..n). */
static pdf prims_pdf(const rt_prim *lights, int n, vec3 origin, pdf *items, const pdf **ptrs)
{
    for (int i = 0; i < n; i++) {
        const rt_prim *l = &lights[i];
        items[i] = l->kind == RT_PRIM_QUAD
                       ? pdf_toward_quad(origin, l->as.quad.q, l->as.quad.u, l->as.quad.v)
                       : pdf_toward_sphere(origin, l->as.sphere.center, l->as.sphere.radius);
        ptrs[i] = &items[i];
    }
    return pdf_list((const pdf *const *)ptrs, (size_t)n);
}

pdf rt_scene_lights_pdf(const rt_scene *s, vec3 origin, pdf *items, const pdf **ptrs)
{
    return prims_pdf(s->lights, s->n_lights, origin, items, ptrs);
}

pdf rt_scene_emitters_pdf(const rt_scene *s, vec3 origin, pdf *items, const pdf **ptrs)
{
    return prims_pdf(s->emitters, s->n_emitters, origin, items, ptrs);
}

const rt_light *rt_scene_lights(const rt_scene *s) { return s->fast_lights; }
int rt_scene_emitter_count(const rt_scene *s) { return s->n_emitters; }
const rt_prim *rt_scene_emitter_prims(const rt_scene *s) { return s->emitters; }
const rt_light *rt_scene_emitters(const rt_scene *s) { return s->fast_emitters; }
int rt_scene_target_count(const rt_scene *s) { return s->n_targets; }
const rt_light *rt_scene_targets(const rt_scene *s) { return s->fast_targets; }
double rt_scene_t_min(const rt_scene *s) { return s->t_min; }
vec3 rt_scene_background(const rt_scene *s) { return s->background; }
int rt_scene_prim_count(const rt_scene *s) { return s->n_prims; }
const rt_prim *rt_scene_prims(const rt_scene *s) { return s->prims; }
const rt_bvh *rt_scene_bvh(const rt_scene *s) { return &s->bvh; }
const rt_leaf_lanes *rt_scene_leaf_lanes(const rt_scene *s) { return s->lanes; }
void rt_scene_use_leaf_tests(rt_scene *s, rt_leaf_tests t) { s->leaf = t; }
