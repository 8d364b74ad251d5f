/* render/bdpt_mis.c - the densities with which each strategy makes a
 * joined path, and the balance heuristic's weights over the strategies
 * (Veach's thesis, 1997, 10.3 and 9.2 [@veach1997]; this book's #ch-caustic). */
#include <math.h>

#include "mc/constants.h"
#include "render/bdpt_internal.h"
#include "render/lights.h"

/* --- densities of the joined path ------------------------------------- */

static double emitter_area(const rt_prim *e)
{
    if (e->kind == RT_PRIM_QUAD)
        return vec3_length(vec3_cross(e->as.quad.u, e->as.quad.v));
    return 4.0 * MC_PI * e->as.sphere.radius * e->as.sphere.radius;
}

double rt_bdpt_origin_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x)
{
    if (x->emitter < 0 || (x->kind == RT_BDPT_SURFACE && !x->front_face))
        return 0.0;
    const rt_prim *e = &rt_scene_emitter_prims(c->scene)[x->emitter];
    return 1.0 / ((double)rt_scene_emitter_count(c->scene) * emitter_area(e));
}

/* BEGIN SNIPPET emit_pdf */
double rt_bdpt_emit_pdf_at(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n, vec3 d)
{
    double cos_e = vec3_dot(n, d);
    double cosine = cos_e > 0.0 ? cos_e * MC_INV_PI : 0.0;
    if (!(c->aim > 0.0))
        return cosine;
    return (1.0 - c->aim) * cosine + c->aim * rt_lights_at_value(at, d);
}
/* END SNIPPET emit_pdf */

double rt_bdpt_emit_pdf(const rt_bdpt_ctx *c, vec3 p, vec3 n, vec3 d)
{
    rt_lights_at at;
    rt_bdpt_emit_prepare(c, p, &at);
    return rt_bdpt_emit_pdf_at(c, &at, n, d);
}

/* Whether x is a vertex a shadow ray may join (i its place in a path of
 * n vertices): the camera, the start of a light subpath, a Lambertian
 * surface. */
static bool joinable(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x, int i, int n)
{
    if (i == n - 1)
        return true;
    if (i == 0)
        return rt_bdpt_origin_pdf(c, x) > 0.0;
    return !x->delta && x->m && x->m->kind == RT_MAT_LAMBERT;
}

/* Which walk makes the next vertex from a vertex: a subpath's own
 * (cosine sampling at a Lambertian surface, from either end) or the
 * start of a light subpath (emission, rt_bdpt_emit_pdf). */
typedef enum role { AS_LIGHT, AS_CAMERA, AS_ORIGIN } role;

/* The density per unit solid angle with which `from` sends its next ray
 * along the unit direction dir (toward the next vertex) in role r: the
 * film's for the camera, emission's (rt_bdpt_emit_pdf) from the start of
 * a light subpath, a Lambertian surface's sampling density; 0 through a specular
 * vertex (the caller counts that as 1). */
static double dir_pdf_along(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r, vec3 dir)
{
    if (from->kind == RT_BDPT_CAMERA) {
        /* rt_bdpt_camera_dir's cosine and test (from is the camera's
         * origin). */
        double cos_theta = vec3_dot(dir, c->forward);
        if (!(cos_theta > 0.0))
            return 0.0;
        double film = c->pixel_area * (double)c->camera->width * (double)c->camera->height;
        return 1.0 / (film * cos_theta * cos_theta * cos_theta);
    }
    if (r == AS_ORIGIN || from->kind == RT_BDPT_LIGHT)
        return rt_bdpt_emit_pdf(c, from->p, from->kind == RT_BDPT_LIGHT ? from->ng : from->ns, dir);
    if (from->delta || !from->m || from->m->kind != RT_MAT_LAMBERT)
        return 0.0;
    return rt_cosine_value(from->ns, dir);
}

/* dir_pdf_along toward the point `to`. */
static double dir_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r, vec3 to)
{
    vec3 dir;
    if (from->kind == RT_BDPT_CAMERA) {
        double cos_theta;
        if (!rt_bdpt_camera_dir(c, to, &dir, &cos_theta))
            return 0.0;
    } else {
        dir = vec3_normalize(vec3_sub(to, from->p));
    }
    return dir_pdf_along(c, from, r, dir);
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

/* c_r of the splat of a path of n vertices, the strategy r = n - 1
 * (bdpt.h); every other strategy has c_r = 1. */
static double splat_scale(int n)
{
    return n == 3 ? RT_BDPT_DIRECT_SPLAT_SCALE : RT_BDPT_SPLAT_SCALE;
}

/* The balance heuristic's weight of strategy s from the densities of the
 * joined path of n vertices: pl[i], pc[i] as in rt_bdpt_mis_weight
 * (remapped), ok[r] whether strategy r can join. Strategy r + 1 differs
 * from r in making x[r] from the light side, so p_{r+1} / p_r =
 * pl[r] / pc[r]; the weight is c_s / sum_r c_r (p_r / p_s), in O(n),
 * with c_r the splat's scale (splat_scale). */
/* BEGIN SNIPPET bdpt_weight */
static double weight_from(const double *pl, const double *pc, bool *ok, int n, int s, int twice,
                          bool x1_specular)
{
    /* Light reached through a specular vertex right after the camera
     * subpath's last diffuse bounce (the caustic under the glass sphere):
     * with the deltas counted as 1 the densities of s = 0 and of the joins
     * are not comparable, and the heuristic would give the rare
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
    double splat = splat_scale(n);
    double own = s == n - 1 ? splat : 1.0;
    double sum = own * (s == twice ? 2.0 : 1.0), ratio = 1.0;
    for (int r = s + 1; r < n; r++) {
        ratio *= pl[r - 1] / pc[r - 1];
        if (ok[r])
            sum += ratio * (r == twice ? 2.0 : 1.0) * (r == n - 1 ? splat : 1.0);
    }
    ratio = 1.0;
    for (int r = s - 1; r >= 0; r--) {
        ratio *= pc[r] / pl[r];
        if (ok[r])
            sum += ratio * (r == twice ? 2.0 : 1.0);
    }
    return own / sum;
}
/* END SNIPPET bdpt_weight */

double rt_bdpt_mis_weight(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x, int n, int s)
{
    double pl[RT_BDPT_MAX_DEPTH + 2], pc[RT_BDPT_MAX_DEPTH + 2];
    bool ok[RT_BDPT_MAX_DEPTH + 2];
    /* pl[i]: the density of x[i] as the light subpath's walk would make
     * it from x[i-1] (and x[0] as its start); pc[i]: as the camera's would
     * from x[i+1]. Per unit area. */
    pl[0] = remap0(rt_bdpt_origin_pdf(c, x));
    for (int i = 1; i < n; i++)
        pl[i] = remap0(to_area(dir_pdf(c, &x[i - 1], i == 1 ? AS_ORIGIN : AS_LIGHT, x[i].p),
                               x[i - 1].p, &x[i]));
    for (int i = n - 2; i >= 0; i--)
        pc[i] = remap0(to_area(dir_pdf(c, &x[i + 1], AS_CAMERA, x[i].p), x[i + 1].p, &x[i]));
    pc[n - 1] = 1.0;
    /* Strategy r joins x[r-1] and x[r] (r = 0: the camera subpath ends on
     * the emitter). */
    ok[0] = rt_bdpt_origin_pdf(c, &x[0]) > 0.0;
    for (int r = 1; r < n; r++)
        ok[r] = joinable(c, &x[r - 1], r - 1, n) && joinable(c, &x[r], r, n);
    return weight_from(pl, pc, ok, n, s, c->ps->neg.mis_double - 1, n > 2 && x[1].delta);
}

/* --- the weights of the joins, from densities cached per subpath ------ */

/* The density of `to` made from `from` in role r, per unit area,
 * remapped. */
static double area_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r,
                       const rt_bdpt_vertex *to)
{
    return remap0(to_area(dir_pdf(c, from, r, to->p), from->p, to));
}

/* The density per unit solid angle pdf_dir of the direction along the
 * segment g toward `to` as a density per unit area at `to`, remapped:
 * to_area's numbers, |cos| at `to` read off g.d, whose sign does not
 * matter. */
static double area_along(double pdf_dir, const rt_bdpt_vertex *to, const rt_bdpt_segment *g)
{
    return remap0(pdf_dir * fabs(vec3_dot(to->ng, g->d)) / (g->dist * g->dist_sq));
}

/* area_pdf over the segment g between the two vertices, the direction
 * from `from` toward `to` given (g.dir or its negation). */
static double area_pdf_along(const rt_bdpt_ctx *c, const rt_bdpt_vertex *from, role r,
                             const rt_bdpt_vertex *to, vec3 dir, const rt_bdpt_segment *g)
{
    return area_along(dir_pdf_along(c, from, r, dir), to, g);
}

void rt_bdpt_cache_pdfs(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int nl,
                        const rt_bdpt_vertex *cam, int nc, rt_bdpt_subpath_pdfs *sp)
{
    /* Each segment gives the densities at both its ends: lf[i + 1] and
     * lr[i] between light vertices i and i + 1, cf[j + 1] and cr[j]
     * between camera vertices j and j + 1. */
    if (nl > 0)
        rt_bdpt_emit_prepare(c, light[0].p, &sp->emit_at);
    for (int i = 0; i < nl; i++) {
        if (i == 0)
            sp->lf[0] = remap0(rt_bdpt_origin_pdf(c, &light[0]));
        if (i + 1 < nl) {
            rt_bdpt_segment g = rt_bdpt_segment_make(light[i].p, light[i + 1].p);
            sp->lf[i + 1] = area_pdf_along(c, &light[i], i == 0 ? AS_ORIGIN : AS_LIGHT,
                                           &light[i + 1], g.dir, &g);
            sp->lr[i] = area_pdf_along(c, &light[i + 1], AS_CAMERA, &light[i], vec3_neg(g.dir), &g);
        } else {
            sp->lr[i] = 1.0;
        }
        sp->jl[i] = i == 0 || joinable(c, &light[i], i, i + 2);
    }
    for (int j = 0; j < nc; j++) {
        if (j == 0)
            sp->cf[0] = 1.0;
        if (j + 1 < nc) {
            rt_bdpt_segment g = rt_bdpt_segment_make(cam[j].p, cam[j + 1].p);
            sp->cf[j + 1] = area_pdf_along(c, &cam[j], AS_CAMERA, &cam[j + 1], g.dir, &g);
            sp->cr[j] = area_pdf_along(c, &cam[j + 1], AS_LIGHT, &cam[j], vec3_neg(g.dir), &g);
        } else {
            sp->cr[j] = 1.0;
        }
        sp->jc[j] = j == 0 || joinable(c, &cam[j], 1, 3);
    }
    /* The running sums. Strategy r joins x[r-1] and x[r], so on the light
     * side it can join when light vertices r-1 and r can; r = 0 (the
     * camera subpath ending on the lamp) is left out when the light
     * subpath's second vertex is specular, weight_from's rule for x[1]
     * (every join that reads la has s >= 2, where light[1] is x[1]). */
    bool second_delta = false; /* light[1] exists only for nl >= 2 */
    if (nl >= 2)
        second_delta = light[1].delta;
    for (int i = 0; i < nl; i++) {
        double q = sp->lr[i] / sp->lf[i];
        bool ok = i == 0 ? !second_delta : sp->jl[i - 1] && sp->jl[i];
        sp->la[i] = q * ((ok ? 1.0 : 0.0) + (i > 0 ? sp->la[i - 1] : 0.0));
    }
    /* On the camera side the strategy with t' camera vertices joins camera
     * vertices t' and t' - 1. */
    sp->ce[0] = 0.0;
    sp->ce_any[0] = false;
    for (int j = 1; j < nc; j++) {
        double q = sp->cr[j] / sp->cf[j];
        bool ok = sp->jc[j] && sp->jc[j - 1];
        /* t' = 1 is the splat, of a path of four vertices or more in
         * every join that reads ce. */
        sp->ce[j] = q * ((ok ? (j == 1 ? splat_scale(4) : 1.0) : 0.0) + sp->ce[j - 1]);
        sp->ce_any[j] = ok || sp->ce_any[j - 1];
    }
}

/* The path is light[0..s) then cam[0..t) reversed: x[i] = light[i] for
 * i < s, x[i] = cam[n - 1 - i] after. Only the densities at the two ends
 * of the join are not in the cache. */
double rt_bdpt_join_weight(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                           const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam, int t)
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
        pl[0] = remap0(rt_bdpt_origin_pdf(c, z));
        jn[0] = rt_bdpt_origin_pdf(c, z) > 0.0;
        pl[1] = area_pdf(c, z, AS_ORIGIN, &cam[t - 2]);
    } else {
        const rt_bdpt_vertex *y = &light[s - 1];
        pl[s] = area_pdf(c, y, s == 1 ? AS_ORIGIN : AS_LIGHT, z);
        pc[s - 1] = area_pdf(c, z, AS_CAMERA, y);
    }
    ok[0] = jn[0] && (s > 0 || rt_bdpt_origin_pdf(c, z) > 0.0);
    for (int r = 1; r < n; r++)
        ok[r] = jn[r - 1] && jn[r];
    /* x[1]: the second light vertex, the camera subpath's last, or the
     * one before it. */
    const rt_bdpt_vertex *x1 = s >= 2 ? &light[1] : s == 1 ? z : &cam[t - 2];
    return weight_from(pl, pc, ok, n, s, c->ps->neg.mis_double - 1, n > 2 && x1->delta);
}

/* The ratios beside the join are the only ones the join changes: the
 * light side's sum is pc[s-1] / pl[s-1] times (strategy s - 1's term
 * plus la[s-2]), the camera side's pl[s] / pc[s] times (strategy
 * s + 1's term plus ce[t-2]); weight_from's loops, unrolled into the
 * running sums. With s = 0 the first two camera-side densities are the
 * lamp's (its area density, then its emission density), not cached ones. The
 * splat's term (t' = 1) carries c = splat_scale(n): in ce[1] for the paths
 * of four vertices or more that read it, here for the rest. */
/* BEGIN SNIPPET bdpt_weight_running */
static double running_weight(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                             const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam, int t,
                             const rt_bdpt_segment *g)
{
    const rt_bdpt_vertex *z = &cam[t - 1];
    double splat = splat_scale(s + t);
    if (s == 0) {
        double origin = rt_bdpt_origin_pdf(c, z);
        if (!(origin > 0.0))
            return 0.0;
        double q1 = origin / sp->cf[t - 1];
        double q2 = area_pdf(c, z, AS_ORIGIN, &cam[t - 2]) / sp->cf[t - 2];
        bool ok1 = sp->jc[t - 2], ok2 = sp->jc[t - 2] && sp->jc[t - 3];
        /* Strategy 2 is the splat when t = 3. */
        double inner = q2 * ((ok2 ? (t == 3 ? splat : 1.0) : 0.0) + sp->ce[t - 3]);
        double sum = q1 * ((ok1 ? 1.0 : 0.0) + inner);
        /* weight_from's rule for light reached through a specular x[1]. */
        if (cam[t - 2].delta && (ok1 || ok2 || sp->ce_any[t - 3]))
            return 0.0;
        return 1.0 / (1.0 + sum);
    }
    const rt_bdpt_vertex *y = &light[s - 1];
    if (!(sp->jl[s - 1] && sp->jc[t - 1]))
        return 0.0;
    /* g runs from y to z: z sees y along -g.dir. */
    double ql = area_pdf_along(c, z, AS_CAMERA, y, vec3_neg(g->dir), g) / sp->lf[s - 1];
    bool ok_l = s == 1 || (sp->jl[s - 2] && sp->jl[s - 1]);
    double sum = ql * ((ok_l ? 1.0 : 0.0) + (s >= 2 ? sp->la[s - 2] : 0.0));
    if (t >= 2) {
        /* From the lamp (s = 1) the emission density, its targets
         * prepared once per light subpath. */
        double pdf_dir = s == 1 ? rt_bdpt_emit_pdf_at(c, &sp->emit_at, y->ng, g->dir)
                                : dir_pdf_along(c, y, AS_LIGHT, g->dir);
        double qc = area_along(pdf_dir, z, g) / sp->cf[t - 1];
        bool ok_c = sp->jc[t - 1] && sp->jc[t - 2];
        sum += qc * ((ok_c ? (t == 2 ? splat : 1.0) : 0.0) + sp->ce[t - 2]);
    }
    double own = t == 1 ? splat : 1.0;
    return own / (own + sum);
}
/* END SNIPPET bdpt_weight_running */

double rt_bdpt_join_weight_running(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                                   const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam,
                                   int t)
{
    rt_bdpt_segment g;
    if (s > 0)
        g = rt_bdpt_segment_make(light[s - 1].p, cam[t - 1].p);
    return rt_bdpt_join_weight_along(c, sp, light, s, cam, t, s > 0 ? &g : NULL);
}

double rt_bdpt_join_weight_along(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                                 const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam,
                                 int t, const rt_bdpt_segment *g)
{
    if (s + t <= 2 || c->ps->neg.mis_double)
        return rt_bdpt_join_weight(c, sp, light, s, cam, t);
    double w = running_weight(c, sp, light, s, cam, t, g);
    if (c->audit) {
        double ref = rt_bdpt_join_weight(c, sp, light, s, cam, t);
        double diff = ref != 0.0 ? fabs(w - ref) / ref : fabs(w);
        c->audit->joins++;
        if (!(diff <= c->audit->worst)) /* a NaN is kept too */
            c->audit->worst = diff;
    }
    return w;
}
