/* render/bdpt.c - the two subpaths, their joins and the power heuristic
 * over all of them (Veach's thesis, 1997, its chapter 10; this book's
 * #ch-caustic). */
#include "render/bdpt.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "render/jitter.h"
#include "render/lights.h"
#include "samplers/sphere.h"

rt_bdpt_ctx rt_bdpt_ctx_make(const rt_scene *scene, const rt_path_settings *ps,
                             const rt_camera *camera)
{
    rt_bdpt_ctx c = {scene, ps, camera, vec3_make(0.0, 0.0, 1.0), 0.0};
    /* The centre of the image plane at distance 1 is the view axis. */
    vec3 centre = vec3_add(camera->corner,
                           vec3_add(vec3_scale(camera->du, 0.5 * (double)camera->width),
                                    vec3_scale(camera->dv, 0.5 * (double)camera->height)));
    c.forward = vec3_normalize(centre);
    c.pixel_area = vec3_length(camera->du) * vec3_length(camera->dv);
    return c;
}

/* The unit direction from the camera to p and its cosine with the view
 * axis; false behind the camera. */
static bool camera_dir(const rt_bdpt_ctx *c, vec3 p, vec3 *dir, double *cos_theta)
{
    *dir = vec3_normalize(vec3_sub(p, c->camera->origin));
    *cos_theta = vec3_dot(*dir, c->forward);
    return *cos_theta > 0.0;
}

/* BEGIN SNIPPET camera_importance */
bool rt_bdpt_camera_importance(const rt_bdpt_ctx *c, vec3 p, size_t *px, double *importance)
{
    vec3 dir;
    double cos_theta;
    if (!camera_dir(c, p, &dir, &cos_theta))
        return false;
    /* Where the direction meets the plane at distance 1, in pixel units
     * (du and dv are orthogonal). */
    const rt_camera *cam = c->camera;
    vec3 rel = vec3_sub(vec3_scale(dir, 1.0 / cos_theta), cam->corner);
    double x = vec3_dot(rel, cam->du) / vec3_length_sq(cam->du);
    double y = vec3_dot(rel, cam->dv) / vec3_length_sq(cam->dv);
    if (!(x >= 0.0 && x < (double)cam->width && y >= 0.0 && y < (double)cam->height))
        return false;
    *px = (size_t)y * (size_t)cam->width + (size_t)x;
    double cos3 = c->ps->neg.splat_drop_cos3 ? 1.0 : cos_theta * cos_theta * cos_theta;
    *importance = 1.0 / (c->pixel_area * cos3);
    return true;
}
/* END SNIPPET camera_importance */

/* --- densities of the joined path ------------------------------------- */

static double emitter_area(const rt_prim *e)
{
    if (e->kind == RT_PRIM_QUAD)
        return vec3_length(vec3_cross(e->as.quad.u, e->as.quad.v));
    return 4.0 * MC_PI * e->as.sphere.radius * e->as.sphere.radius;
}

/* The density per unit area with which a light subpath starts at x:
 * 1 / (emitters x area) on the emitting side of an emitter, else 0. */
static double origin_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x)
{
    if (x->emitter < 0 || (x->kind == RT_BDPT_SURFACE && !x->front_face))
        return 0.0;
    const rt_prim *e = &rt_scene_emitter_prims(c->scene)[x->emitter];
    return 1.0 / ((double)rt_scene_emitter_count(c->scene) * emitter_area(e));
}

/* Whether x is a vertex a shadow ray may join (i its place in a path of
 * n vertices): the camera, the start of a light subpath, a Lambertian
 * surface. */
static bool joinable(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x, int i, int n)
{
    if (i == n - 1)
        return true;
    if (i == 0)
        return origin_pdf(c, x) > 0.0;
    return !x->delta && x->m && x->m->kind == RT_MAT_LAMBERT;
}

/* Which walk makes the next vertex from a vertex: a subpath's own
 * (cosine sampling at a Lambertian surface, from either end) or the
 * start of a light subpath (cosine emission). */
typedef enum role { AS_LIGHT, AS_CAMERA, AS_ORIGIN } role;

/* The density per unit solid angle with which `from` sends its next ray
 * toward `to` in role r: the film's for the camera, cosine emission from
 * the start of a light subpath, a Lambertian surface's sampling density;
 * 0 through a specular vertex (the caller counts that as 1). */
static double dir_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r, vec3 to)
{
    if (from->kind == RT_BDPT_CAMERA) {
        vec3 dir;
        double cos_theta;
        if (!camera_dir(c, to, &dir, &cos_theta))
            return 0.0;
        double film = c->pixel_area * (double)c->camera->width * (double)c->camera->height;
        return 1.0 / (film * cos_theta * cos_theta * cos_theta);
    }
    vec3 dir = vec3_normalize(vec3_sub(to, from->p));
    if (r == AS_ORIGIN || from->kind == RT_BDPT_LIGHT) {
        double cos_e = vec3_dot(from->kind == RT_BDPT_LIGHT ? from->ng : from->ns, dir);
        return cos_e > 0.0 ? cos_e * MC_INV_PI : 0.0;
    }
    if (from->delta || !from->m || from->m->kind != RT_MAT_LAMBERT)
        return 0.0;
    return rt_cosine_value(from->ns, dir);
}

/* A density per unit solid angle at `from` as a density per unit area at
 * `to`: times |cos| at `to` over the squared distance. */
static double to_area(double pdf_dir, vec3 from, const rt_bdpt_vertex *to)
{
    vec3 d = vec3_sub(to->p, from);
    double dist_sq = vec3_length_sq(d);
    return pdf_dir * fabs(vec3_dot(to->ng, d)) / (sqrt(dist_sq) * dist_sq);
}

/* A zero density, which only a specular neighbour leaves (any path with a
 * real zero contributes nothing), counts as 1: the deltas of the two
 * directions cancel in every ratio (Veach 10.3.5). */
static double remap0(double p) { return p != 0.0 ? p : 1.0; }

/* The power heuristic's weight of strategy s from the densities of the
 * joined path of n vertices: pl[i], pc[i] as in rt_bdpt_mis_weight
 * (remapped), ok[r] whether strategy r can join. Strategy r + 1 differs
 * from r in making x[r] from the light side, so p_{r+1} / p_r =
 * pl[r] / pc[r]; the weight is 1 / sum_r (p_r / p_s)^2, in O(n). */
/* BEGIN SNIPPET bdpt_weight */
static double weight_from(const double *pl, const double *pc, bool *ok, int n, int s, int twice,
                          bool x1_specular)
{
    /* Light reached through a specular vertex right after the camera
     * subpath's last diffuse bounce (the caustic under the glass sphere):
     * with the deltas counted as 1 the densities of s = 0 and of the joins
     * are not comparable, and the power heuristic would give the rare
     * camera path that finds the lamp through the glass a sizeable weight,
     * i.e. fireflies. Any weights that are functions of the path and sum
     * to 1 over the strategies that can make it keep the sum unbiased
     * (Veach 9.2): such a path goes to the joins alone when there is one. */
    if (x1_specular && ok[0])
        for (int r = 1; r < n; r++)
            if (ok[r]) {
                ok[0] = false;
                break;
            }
    /* The other way round for an emitter the camera sees directly (n = 2):
     * the camera ray finds it every time, each pixel sample adding its
     * exact radiance, while a light subpath's start lands in a random
     * pixel; the densities, which say nothing of that, favour the splats
     * because there are more light starts on the lamp than camera rays.
     * Such a path goes to s = 0 alone. */
    if (n == 2 && ok[0])
        ok[1] = false;
    if (!ok[s])
        return 0.0;
    double sum = s == twice ? 2.0 : 1.0, ratio = 1.0;
    for (int r = s + 1; r < n; r++) {
        ratio *= pl[r - 1] / pc[r - 1];
        if (ok[r])
            sum += ratio * ratio * (r == twice ? 2.0 : 1.0);
    }
    ratio = 1.0;
    for (int r = s - 1; r >= 0; r--) {
        ratio *= pc[r] / pl[r];
        if (ok[r])
            sum += ratio * ratio * (r == twice ? 2.0 : 1.0);
    }
    return 1.0 / sum;
}
/* END SNIPPET bdpt_weight */

double rt_bdpt_mis_weight(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x, int n, int s)
{
    double pl[RT_BDPT_MAX_DEPTH + 2], pc[RT_BDPT_MAX_DEPTH + 2];
    bool ok[RT_BDPT_MAX_DEPTH + 2];
    /* pl[i]: the density of x[i] as the light subpath's walk would make
     * it from x[i-1] (and x[0] as its start); pc[i]: as the camera's would
     * from x[i+1]. Per unit area. */
    pl[0] = remap0(origin_pdf(c, x));
    for (int i = 1; i < n; i++)
        pl[i] = remap0(to_area(dir_pdf(c, &x[i - 1], i == 1 ? AS_ORIGIN : AS_LIGHT, x[i].p),
                               x[i - 1].p, &x[i]));
    for (int i = n - 2; i >= 0; i--)
        pc[i] = remap0(to_area(dir_pdf(c, &x[i + 1], AS_CAMERA, x[i].p), x[i + 1].p, &x[i]));
    pc[n - 1] = 1.0;
    /* Strategy r joins x[r-1] and x[r] (r = 0: the camera subpath ends on
     * the emitter). */
    ok[0] = origin_pdf(c, &x[0]) > 0.0;
    for (int r = 1; r < n; r++)
        ok[r] = joinable(c, &x[r - 1], r - 1, n) && joinable(c, &x[r], r, n);
    return weight_from(pl, pc, ok, n, s, c->ps->neg.mis_double - 1, n > 2 && x[1].delta);
}

/* --- the walks ---------------------------------------------------------- */

static bool same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* The emitter whose primitive is the world primitive `prim` (the same
 * numbers: both are flattened from the same node), or -1. */
static int emitter_of(const rt_scene *s, int prim)
{
    if (prim < 0)
        return -1;
    const rt_prim *p = &rt_scene_prims(s)[prim];
    const rt_prim *e = rt_scene_emitter_prims(s);
    for (int i = 0; i < rt_scene_emitter_count(s); i++) {
        if (p->kind != e[i].kind || p->material != e[i].material)
            continue;
        if (p->kind == RT_PRIM_QUAD ? same_vec(p->as.quad.q, e[i].as.quad.q) &&
                                          same_vec(p->as.quad.u, e[i].as.quad.u) &&
                                          same_vec(p->as.quad.v, e[i].as.quad.v)
                                    : same_vec(p->as.sphere.center, e[i].as.sphere.center) &&
                                          p->as.sphere.radius == e[i].as.sphere.radius &&
                                          p->as.sphere.orient == e[i].as.sphere.orient)
            return i;
    }
    return -1;
}

/* Continues a subpath along r from its last vertex, appending a vertex
 * per hit, until n vertices, a miss or absorption; `segment` is the
 * sampler's segment of the first hit. Returns the vertex count. */
static int walk(const rt_bdpt_ctx *c, rt_ray r, vec3 beta, rt_bdpt_vertex *v, int n,
                int max_n, int segment, rt_sampler *sampler, uint64_t *segments)
{
    const rt_scene *s = c->scene;
    const rt_path_settings *ps = c->ps;
    vec3 start = beta;
    for (int k = 0; n < max_n; k++) {
        rt_hit h;
        ++*segments;
        if (!rt_scene_hit(s, r, HUGE_VAL, &h))
            break;
        const rt_material *m = rt_scene_material(s, h.material);
        rt_bdpt_vertex *x = &v[n++];
        *x = (rt_bdpt_vertex){RT_BDPT_SURFACE, h.p, h.normal, h.normal, h.front_face, false, m,
                              emitter_of(s, h.prim), beta};
        if (n == max_n)
            break;
        rt_scatter sr;
        rt_sampler_segment(sampler, segment++);
        if (!rt_material_scatter(m, &r, &h, sampler, &sr))
            break;
        if (sr.specular) {
            x->delta = true;
            beta = vec3_mul(beta, sr.attenuation);
            r = sr.ray;
            continue;
        }
        vec3 dir = rt_cosine_generate(sr.normal, sampler);
        double sp = rt_material_scattering_pdf(m, &h, dir), pd = rt_cosine_value(sr.normal, dir);
        if (!(sp > 0.0 && pd > 0.0))
            break;
        beta = vec3_scale(vec3_mul(beta, sr.attenuation), sp / pd);
        r = rt_ray_make(h.p, dir);
        /* Russian roulette as in render/integrator.c, on the throughput
         * since the subpath's start: it changes how often a subpath goes
         * on, not what it estimates, and the MIS weights (functions of the
         * path alone) still sum to 1. It starts after RT_BDPT_RR_START
         * segments, not the path tracer's rr_start. */
        if (ps->russian_roulette && k + 1 >= RT_BDPT_RR_START) {
            double q = fmax(beta.x / start.x, fmax(beta.y / start.y, beta.z / start.z));
            q = q < 0.95 ? q : 0.95;
            if (!(q > 0.0) || rt_sampler_1d(sampler) >= q)
                break;
            beta = vec3_scale(beta, 1.0 / q);
        }
    }
    return n;
}

/* The light subpath: at most max_n vertices (0 without emitters). */
static int light_walk(const rt_bdpt_ctx *c, rt_sampler *sampler, rt_bdpt_vertex *v, int max_n,
                      uint64_t *segments)
{
    const rt_scene *s = c->scene;
    int ne = rt_scene_emitter_count(s);
    if (ne == 0 || max_n < 1)
        return 0;
    rt_sampler_segment(sampler, c->ps->max_depth + 1);
    int i = (int)rt_sampler_index(sampler, (uint32_t)ne);
    const rt_prim *e = &rt_scene_emitter_prims(s)[i];
    double u1, u2;
    rt_sampler_2d(sampler, &u1, &u2);
    vec3 p, n;
    if (e->kind == RT_PRIM_QUAD) {
        const rt_quad *q = &e->as.quad;
        p = vec3_add(q->q, vec3_add(vec3_scale(q->u, u1), vec3_scale(q->v, u2)));
        n = q->normal;
    } else {
        const rt_sphere *sp = &e->as.sphere;
        vec3 d = smp_uniform_sphere_sample(u1, u2);
        p = vec3_madd(sp->center, d, sp->radius);
        n = vec3_scale(d, sp->orient);
    }
    const rt_material *m = rt_scene_material(s, e->material);
    rt_bdpt_vertex y0 = {RT_BDPT_LIGHT, p, n, n, true, false, m, i, vec3_make(0.0, 0.0, 0.0)};
    y0.beta = vec3_scale(m->emission, 1.0 / origin_pdf(c, &y0));
    v[0] = y0;
    if (max_n == 1)
        return 1;
    /* Cosine-weighted emission: radiance Le times cos over the density
     * cos / pi is Le pi. */
    rt_sampler_2d(sampler, &u1, &u2);
    onb frame = onb_from_w(n);
    vec3 dir = pdf_cosine_direction(&frame, u1, u2);
    if (!(vec3_dot(dir, n) > 0.0))
        return 1;
    return walk(c, rt_ray_make(p, dir), vec3_scale(y0.beta, MC_PI), v, 1, max_n,
                c->ps->max_depth + 2, sampler, segments);
}

/* --- joining ------------------------------------------------------------ */

/* The densities of the two subpaths that do not depend on how they are
 * joined (a Lambertian vertex's density does not depend on the direction
 * the path arrived from), remapped: lf[i], lr[i] are pl and pc of light
 * vertex i within its subpath (pc from vertex i + 1), cf[j], cr[j] pc and
 * pl of camera vertex j (pl from vertex j + 1); jl, jc whether the vertex
 * can be joined. */
typedef struct subpath_pdfs {
    double lf[RT_BDPT_MAX_DEPTH], lr[RT_BDPT_MAX_DEPTH];
    double cf[RT_BDPT_MAX_DEPTH + 1], cr[RT_BDPT_MAX_DEPTH + 1];
    bool jl[RT_BDPT_MAX_DEPTH], jc[RT_BDPT_MAX_DEPTH + 1];
} subpath_pdfs;

/* The density of `to` made from `from` (as_origin: from starts a light
 * subpath), per unit area, remapped. */
static double area_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r,
                       const rt_bdpt_vertex *to)
{
    return remap0(to_area(dir_pdf(c, from, r, to->p), from->p, to));
}

static void cache_pdfs(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int nl,
                       const rt_bdpt_vertex *cam, int nc, subpath_pdfs *sp)
{
    for (int i = 0; i < nl; i++) {
        sp->lf[i] = i == 0 ? remap0(origin_pdf(c, &light[0])) : area_pdf(c, &light[i - 1], i == 1 ? AS_ORIGIN : AS_LIGHT,
                                                                  &light[i]);
        sp->lr[i] = i + 1 < nl ? area_pdf(c, &light[i + 1], AS_CAMERA, &light[i]) : 1.0;
        sp->jl[i] = i == 0 || joinable(c, &light[i], i, i + 2);
    }
    for (int j = 0; j < nc; j++) {
        sp->cf[j] = j == 0 ? 1.0 : area_pdf(c, &cam[j - 1], AS_CAMERA, &cam[j]);
        sp->cr[j] = j + 1 < nc ? area_pdf(c, &cam[j + 1], AS_LIGHT, &cam[j]) : 1.0;
        sp->jc[j] = j == 0 || joinable(c, &cam[j], 1, 3);
    }
}

/* rt_bdpt_mis_weight of strategy (s, t) from the cached densities and the
 * few that the join changes: in O(s + t). */
static double join_weight(const rt_bdpt_ctx *c, const subpath_pdfs *sp, const rt_bdpt_vertex *light,
                          int s, const rt_bdpt_vertex *cam, int t)
{
    int n = s + t;
    double pl[RT_BDPT_MAX_DEPTH + 2], pc[RT_BDPT_MAX_DEPTH + 2];
    bool ok[RT_BDPT_MAX_DEPTH + 2], jn[RT_BDPT_MAX_DEPTH + 2];
    const rt_bdpt_vertex *z = &cam[t - 1];
    for (int i = 0; i < s; i++) {
        pl[i] = sp->lf[i];
        pc[i] = sp->lr[i];
        jn[i] = sp->jl[i];
    }
    for (int i = s; i < n; i++) {
        int j = n - 1 - i; /* x[i] is camera vertex j */
        pc[i] = sp->cf[j];
        pl[i] = sp->cr[j];
        jn[i] = sp->jc[j];
    }
    if (s == 0) {
        pl[0] = remap0(origin_pdf(c, z));
        jn[0] = origin_pdf(c, z) > 0.0;
        pl[1] = area_pdf(c, z, AS_ORIGIN, &cam[t - 2]);
    } else {
        const rt_bdpt_vertex *y = &light[s - 1];
        pl[s] = area_pdf(c, y, s == 1 ? AS_ORIGIN : AS_LIGHT, z);
        pc[s - 1] = area_pdf(c, z, AS_CAMERA, y);
    }
    ok[0] = jn[0] && (s > 0 || origin_pdf(c, z) > 0.0);
    for (int r = 1; r < n; r++)
        ok[r] = jn[r - 1] && jn[r];
    /* x[1]: the second light vertex, the camera subpath's last, or the
     * one before it. */
    const rt_bdpt_vertex *x1 = s >= 2 ? &light[1] : s == 1 ? z : &cam[t - 2];
    return weight_from(pl, pc, ok, n, s, c->ps->neg.mis_double - 1, n > 2 && x1->delta);
}

static bool is_black(vec3 v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

/* What the end vertex x of a subpath sends toward the point `to`, per
 * unit of the subpath's beta: the emission factor (1 on the emitting
 * side) at the start of a light subpath, the Lambertian BRDF albedo / pi
 * on the side the subpath arrived from. */
static vec3 end_factor(const rt_bdpt_vertex *x, vec3 to)
{
    vec3 zero = vec3_make(0.0, 0.0, 0.0), d = vec3_sub(to, x->p);
    if (x->kind == RT_BDPT_LIGHT)
        return vec3_dot(x->ng, d) > 0.0 ? vec3_make(1.0, 1.0, 1.0) : zero;
    if (x->delta || !x->m || x->m->kind != RT_MAT_LAMBERT || !(vec3_dot(x->ns, d) > 0.0))
        return zero;
    return vec3_scale(x->m->albedo, MC_INV_PI);
}

/* True when nothing lies between the points a and b. */
static bool visible(const rt_scene *s, vec3 a, vec3 b, uint64_t *segments)
{
    vec3 d = vec3_sub(b, a);
    double dist = vec3_length(d);
    rt_hit h;
    ++*segments;
    return !rt_scene_hit(s, rt_ray_make(a, vec3_scale(d, 1.0 / dist)), dist - rt_scene_t_min(s), &h);
}

/* Russian roulette on a join whose value, if nothing is in the way,
 * would be v, worth `scale` times v to a pixel sample: when that is below
 * RT_BDPT_JOIN_FLOOR in every channel, the shadow ray is traced with
 * probability (its worth / the floor) and the value divided by it, else
 * always. Returns the factor, 0 for a join left out; its mean is 1, so
 * the estimate is unchanged in expectation. */
static double join_roulette(vec3 v, double scale, mc_rng *aux)
{
    double worth = scale * fmax(v.x, fmax(v.y, v.z));
    if (!aux || !(worth < RT_BDPT_JOIN_FLOOR))
        return 1.0;
    double q = worth / RT_BDPT_JOIN_FLOOR;
    return mc_rng_uniform(aux) < q ? 1.0 / q : 0.0;
}

/* The contribution of strategy (s, t) with t >= 2 (s = 0: the camera
 * subpath's own hit on an emitter), weighted by the cached densities sp
 * (NULL: unweighted), with roulette on its shadow ray when aux is given. */
/* BEGIN SNIPPET bdpt_join */
static vec3 join(const rt_bdpt_ctx *c, const subpath_pdfs *sp, const rt_bdpt_vertex *light, int s,
                 const rt_bdpt_vertex *cam, int t, mc_rng *aux, uint64_t *segments)
{
    const rt_bdpt_vertex *z = &cam[t - 1];
    vec3 zero = vec3_make(0.0, 0.0, 0.0), v;
    if (s == 0) {
        if (z->kind != RT_BDPT_SURFACE || !z->front_face || is_black(z->m->emission))
            return zero;
        v = vec3_mul(z->beta, z->m->emission);
        return sp ? vec3_scale(v, join_weight(c, sp, light, s, cam, t)) : v;
    }
    const rt_bdpt_vertex *y = &light[s - 1];
    vec3 fy = end_factor(y, z->p), fz = end_factor(z, y->p);
    if (is_black(fy) || is_black(fz))
        return zero;
    vec3 d = vec3_sub(z->p, y->p);
    double dist_sq = vec3_length_sq(d);
    double g = fabs(vec3_dot(y->ng, d)) * fabs(vec3_dot(z->ng, d)) / (dist_sq * dist_sq);
    if (!(g > 0.0))
        return zero;
    v = vec3_scale(vec3_mul(vec3_mul(y->beta, fy), vec3_mul(z->beta, fz)), g);
    if (sp)
        v = vec3_scale(v, join_weight(c, sp, light, s, cam, t));
    double f = join_roulette(v, 1.0, aux);
    if (f == 0.0 || !visible(c->scene, y->p, z->p, segments))
        return zero;
    return vec3_scale(v, f);
}
/* END SNIPPET bdpt_join */

/* Strategy (s, 1): the light subpath's end seen by the camera, splatted
 * with the camera importance (and weight w_fn's weight). */
/* BEGIN SNIPPET bdpt_splat */
static void splat_to_camera(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int s,
                            const rt_bdpt_vertex *cam0, const subpath_pdfs *sp, mc_rng *aux,
                            double *splat, uint64_t *segments)
{
    const rt_bdpt_vertex *y = &light[s - 1];
    size_t px;
    double we;
    if (!rt_bdpt_camera_importance(c, y->p, &px, &we))
        return;
    vec3 fy = end_factor(y, cam0->p);
    if (is_black(fy))
        return;
    vec3 d = vec3_sub(cam0->p, y->p);
    double dist_sq = vec3_length_sq(d);
    double g = fabs(vec3_dot(y->ng, d)) / (sqrt(dist_sq) * dist_sq);
    if (!(g > 0.0))
        return;
    vec3 v = vec3_scale(vec3_mul(y->beta, fy), g * we);
    if (sp)
        v = vec3_scale(v, join_weight(c, sp, light, s, cam0, 1));
    /* A splat is divided by the number of light subpaths, one per pixel
     * sample: to a pixel sample it is worth v over the pixel count. */
    double npix = (double)c->camera->width * (double)c->camera->height;
    double f = join_roulette(v, 1.0 / npix, aux);
    if (f == 0.0 || !visible(c->scene, y->p, cam0->p, segments))
        return;
    v = vec3_scale(v, f);
    /* A non-finite splat would spoil a pixel for good: left out (the
     * factors above are finite for any path that gets here). */
    if (!isfinite(v.x) || !isfinite(v.y) || !isfinite(v.z))
        return;
    splat[3 * px] += v.x;
    splat[3 * px + 1] += v.y;
    splat[3 * px + 2] += v.z;
}
/* END SNIPPET bdpt_splat */

/* --- what the camera sees through glass and mirrors ------------------- */

/* The vertices a chain of rt_bdpt_seen_emission goes on through: glass
 * and perfect mirrors. */
static bool chain_material(const rt_material *m)
{
    return m && (m->kind == RT_MAT_DIELECTRIC || (m->kind == RT_MAT_METAL && m->fuzz == 0.0));
}

/* Whether the camera vertices cam[from..to) are all glass or perfect
 * mirrors. */
static bool all_chain(const rt_bdpt_vertex *cam, int from, int to)
{
    for (int j = from; j < to; j++)
        if (!chain_material(cam[j].m))
            return false;
    return true;
}

/* The index jd of the Lambertian vertex D of the camera subpath
 * cam[0..nc) that follows one or more glass or mirror vertices right
 * after the camera (camera, glass, glass, D: the floor seen through the
 * sphere), or 0 if it has none. */
static int through_vertex(const rt_bdpt_vertex *cam, int nc)
{
    int j = 1;
    while (j < nc && chain_material(cam[j].m))
        j++;
    return j >= 2 && j < nc && cam[j].m && cam[j].m->kind == RT_MAT_LAMBERT ? j : 0;
}

/* Whether the path of s = 0 that ends at camera vertex t - 1 (an emitter)
 * is one the weighted render estimates apart: E S* L (the vertices
 * between the camera and the emitter are all glass or mirrors), or
 * E S+ D S+ L with D = cam[jd] (through_vertex; jd = 0 for none). The
 * negative-control hooks of ps (ps->neg) keep them in. */
static bool estimated_apart(const rt_path_settings *ps, const rt_bdpt_vertex *cam, int t, int jd)
{
    if (all_chain(cam, 1, t - 1))
        return !ps->neg.seen_twice;
    return jd > 0 && t - 1 >= jd + 2 && all_chain(cam, jd + 1, t - 1) && !ps->neg.through_twice;
}

/* BEGIN SNIPPET bdpt_seen */
static vec3 seen(const rt_bdpt_ctx *c, rt_ray r, int left, int splits, mc_rng *rng,
                 uint64_t *segments);

/* What comes back to the ray r that met the glass or mirror m at h, with
 * `left` segments (this one included) and `splits` splits to go: the
 * albedo times seen() along the reflection, or at glass along both
 * branches weighted by R and 1 - R, or along one drawn with those
 * probabilities once the splits are spent. */
static vec3 through_chain_vertex(const rt_bdpt_ctx *c, rt_ray r, const rt_hit *h,
                                 const rt_material *m, int left, int splits, mc_rng *rng,
                                 uint64_t *segments)
{
    vec3 more;
    if (m->kind == RT_MAT_METAL) {
        more = seen(c, rt_ray_make(h->p, rt_reflect(r.dir, h->normal)), left - 1, splits, rng, segments);
    } else {
        rt_ray refl, refr;
        double R = rt_glass_branches(m, &r, h, &refl, &refr);
        if (R >= 1.0)
            more = seen(c, refl, left - 1, splits, rng, segments);
        else if (splits > 0)
            more = vec3_add(vec3_scale(seen(c, refl, left - 1, splits - 1, rng, segments), R),
                            vec3_scale(seen(c, refr, left - 1, splits - 1, rng, segments), 1.0 - R));
        else
            more = seen(c, mc_rng_uniform(rng) < R ? refl : refr, left - 1, 0, rng, segments);
    }
    return vec3_mul(m->albedo, more);
}

/* rt_bdpt_seen_emission with `left` segments and `splits` splits to go;
 * through_only: only what comes through a glass or mirror vertex first
 * (the emitter met first is left out). */
static vec3 seen_any(const rt_bdpt_ctx *c, rt_ray r, int left, int splits, bool through_only,
                     mc_rng *rng, uint64_t *segments)
{
    vec3 zero = vec3_make(0.0, 0.0, 0.0);
    rt_hit h;
    if (left < 1)
        return zero;
    ++*segments;
    if (!rt_scene_hit(c->scene, r, HUGE_VAL, &h))
        return zero;
    const rt_material *m = rt_scene_material(c->scene, h.material);
    vec3 e = through_only ? zero : rt_material_emitted(m, &h);
    if (!chain_material(m))
        return e;
    return vec3_add(e, through_chain_vertex(c, r, &h, m, left, splits, rng, segments));
}

static vec3 seen(const rt_bdpt_ctx *c, rt_ray r, int left, int splits, mc_rng *rng,
                 uint64_t *segments)
{
    return seen_any(c, r, left, splits, false, rng, segments);
}
/* END SNIPPET bdpt_seen */

/* rt_bdpt_seen_emission of the camera ray r from its first hit, which the
 * camera subpath cam[0..nc) has found already (vertex 1; none when r met
 * nothing): the same term without tracing r again. */
static vec3 seen_first(const rt_bdpt_ctx *c, rt_ray r, const rt_bdpt_vertex *cam, int nc, int depth,
                       mc_rng *aux, uint64_t *segments)
{
    if (nc < 2)
        return vec3_make(0.0, 0.0, 0.0);
    const rt_bdpt_vertex *x = &cam[1];
    rt_hit h = {.p = x->p, .normal = x->ns, .front_face = x->front_face};
    vec3 e = rt_material_emitted(x->m, &h);
    if (!chain_material(x->m))
        return e;
    return vec3_add(e, through_chain_vertex(c, r, &h, x->m, depth, RT_BDPT_SPLITS, aux, segments));
}

/* The longest subpath of a render. */
static int max_segments(const rt_bdpt_ctx *c)
{
    return c->ps->max_depth < RT_BDPT_MAX_DEPTH ? c->ps->max_depth : RT_BDPT_MAX_DEPTH;
}

vec3 rt_bdpt_seen_emission(const rt_bdpt_ctx *c, rt_ray r, mc_rng *rng, uint64_t *segments)
{
    return seen(c, r, max_segments(c), RT_BDPT_SPLITS, rng, segments);
}

/* The paths E S+ D S+ L through the Lambertian vertex D = cam[jd]: the
 * mean over RT_BDPT_THROUGH_RAYS cosine-sampled directions at D of what
 * comes back through glass and mirrors (the albedo stands for BRDF x cos
 * / density), times the subpath's weight up to D. */
/* BEGIN SNIPPET bdpt_through */
static vec3 through_estimate(const rt_bdpt_ctx *c, const rt_bdpt_vertex *d, int jd, mc_rng *aux,
                             uint64_t *segments)
{
    vec3 sum = vec3_make(0.0, 0.0, 0.0);
    onb frame = onb_from_w(d->ns);
    for (int i = 0; i < RT_BDPT_THROUGH_RAYS; i++) {
        double u1 = mc_rng_uniform(aux), u2 = mc_rng_uniform(aux);
        rt_ray r = rt_ray_make(d->p, pdf_cosine_direction(&frame, u1, u2));
        sum = vec3_add(sum, seen_any(c, r, max_segments(c) - jd, RT_BDPT_SPLITS, true, aux, segments));
    }
    return vec3_scale(vec3_mul(vec3_mul(d->beta, d->m->albedo), sum), 1.0 / RT_BDPT_THROUGH_RAYS);
}
/* END SNIPPET bdpt_through */

/* The streams of the terms: one per pixel for the edge test, one per
 * pixel sample (keys apart from the pixels' own streams, which are
 * mc_rng_derive(seed, pixel)). */
#define SEEN_EDGE_KEY 0x5ee9ed9e5ee9ed9eull
#define SEEN_SAMPLE_KEY 0x5ee95a3b1e5ee95aull

mc_rng rt_bdpt_aux_stream(uint64_t seed, uint64_t sample)
{
    return mc_rng_derive(seed ^ SEEN_SAMPLE_KEY, sample);
}

bool rt_bdpt_seen_edge(const rt_bdpt_ctx *c, int x, int y, uint64_t seed, uint64_t *segments)
{
    const rt_camera *cam = c->camera;
    mc_rng rng = mc_rng_derive(seed ^ SEEN_EDGE_KEY, (uint64_t)y * (uint64_t)cam->width + (uint64_t)x);
    vec3 lo = vec3_make(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = vec3_scale(lo, -1.0);
    for (int j = 0; j <= 2; j++)
        for (int i = 0; i <= 2; i++) {
            /* The far corners are inside the pixel by an ulp's worth. */
            double px = fmin((double)x + 0.5 * i, nextafter((double)x + 1.0, 0.0));
            double py = fmin((double)y + 0.5 * j, nextafter((double)y + 1.0, 0.0));
            vec3 v = rt_bdpt_seen_emission(c, rt_camera_ray(cam, px, py), &rng, segments);
            lo = vec3_make(fmin(lo.x, v.x), fmin(lo.y, v.y), fmin(lo.z, v.z));
            hi = vec3_make(fmax(hi.x, v.x), fmax(hi.y, v.y), fmax(hi.z, v.z));
        }
    return hi.x - lo.x > 0.01 || hi.y - lo.y > 0.01 || hi.z - lo.z > 0.01;
}

/* BEGIN SNIPPET bdpt_seen_sample */
vec3 rt_bdpt_seen_sample(const rt_bdpt_ctx *c, int x, int y, mc_rng *aux, uint64_t *segments)
{
    /* One jittered ray in each cell of a g x g grid: the mean over the
     * cells of stratified points, unbiased for the pixel's mean. */
    enum { g = 8 };
    _Static_assert(g * g == RT_BDPT_EDGE_SUBSAMPLES, "the grid is RT_BDPT_EDGE_SUBSAMPLES cells");
    vec3 sum = vec3_make(0.0, 0.0, 0.0);
    for (int j = 0; j < g; j++)
        for (int i = 0; i < g; i++) {
            double u1 = mc_rng_uniform(aux), u2 = mc_rng_uniform(aux);
            rt_ray sub = rt_camera_ray(c->camera, (double)x + rt_jitter_in_cell((uint64_t)i, g, u1),
                                       (double)y + rt_jitter_in_cell((uint64_t)j, g, u2));
            sum = vec3_add(sum, rt_bdpt_seen_emission(c, sub, aux, segments));
        }
    return vec3_scale(sum, 1.0 / (g * g));
}
/* END SNIPPET bdpt_seen_sample */

/* BEGIN SNIPPET bdpt_strategies */
vec3 rt_bdpt_sample(const rt_bdpt_ctx *c, rt_ray camera_ray, rt_sampler *sampler, mc_rng *aux,
                    bool seen_here, double *splat, uint64_t *segments)
{
    const rt_path_settings *ps = c->ps;
    int depth = ps->max_depth < RT_BDPT_MAX_DEPTH ? ps->max_depth : RT_BDPT_MAX_DEPTH;
    rt_bdpt_vertex cam[RT_BDPT_MAX_DEPTH + 1], light[RT_BDPT_MAX_DEPTH];
    bool lighttrace = ps->strategy == RT_LIGHTTRACE;
    bool all = rt_bdpt_weighted(ps);
    cam[0] = (rt_bdpt_vertex){RT_BDPT_CAMERA, c->camera->origin, c->forward, c->forward, true,
                              false, NULL, -1, vec3_make(1.0, 1.0, 1.0)};
    vec3 L = vec3_make(0.0, 0.0, 0.0);
    if (depth < 1)
        return L;
    /* The camera ray has density W_j over its pixel: beta 1. */
    int nc = lighttrace ? 1
                        : walk(c, camera_ray, cam[0].beta, cam, 1, depth + 1, 0, sampler, segments);
    int nl = light_walk(c, sampler, light, depth, segments);
    subpath_pdfs sp;
    int jd = 0;
    if (all)
        cache_pdfs(c, light, nl, cam, nc, &sp);
    if (all && (jd = through_vertex(cam, nc)) > 0)
        L = through_estimate(c, &cam[jd], jd, aux, segments);
    if (all && seen_here)
        L = vec3_add(L, seen_first(c, camera_ray, cam, nc, depth, aux, segments));
    for (int t = 1; t <= nc; t++)
        for (int s = 0; s <= nl; s++) {
            if (s + t < 2 || s + t - 1 > depth || (t == 1 && s == 0))
                continue;
            /* (1, 1), a lamp seen directly, has weight 0 (weight_from). */
            if (all && s == 1 && t == 1)
                continue;
            if (!all && !lighttrace && (s != ps->bdpt_s || t != ps->bdpt_t))
                continue;
            if (t == 1) {
                splat_to_camera(c, light, s, &cam[0], all ? &sp : NULL, all ? aux : NULL, splat,
                                segments);
                continue;
            }
            if (all && s == 0 && estimated_apart(ps, cam, t, jd))
                continue; /* rt_bdpt_seen_sample's or through_estimate's */
            L = vec3_add(L, join(c, all ? &sp : NULL, light, s, cam, t, all ? aux : NULL, segments));
        }
    return L;
}
/* END SNIPPET bdpt_strategies */

bool rt_bdpt_strategy_parse(const char *name, rt_path_settings *ps)
{
    ps->bdpt_s = ps->bdpt_t = 0;
    if (strncmp(name, "bdpt:", 5) == 0) {
        /* Digits only: strtol would also take blanks and signs. */
        size_t digits = strspn(name + 5, "0123456789");
        if (digits == 0 || name[5 + digits] != ',' || strspn(name + 6 + digits, "0123456789") == 0)
            return false;
        char *end;
        long s = strtol(name + 5, &end, 10);
        if (end == name + 5 || *end != ',' || s < 0 || s > RT_BDPT_MAX_DEPTH)
            return false;
        const char *tp = end + 1;
        long t = strtol(tp, &end, 10);
        if (end == tp || *end != '\0' || t < 1 || t > RT_BDPT_MAX_DEPTH + 1 || s + t < 2)
            return false;
        ps->strategy = RT_BDPT;
        ps->bdpt_s = (int)s;
        ps->bdpt_t = (int)t;
        return true;
    }
    return rt_strategy_parse(name, &ps->strategy);
}
