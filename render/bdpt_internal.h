/* render/bdpt_internal.h - what the files of the bidirectional path tracer
 * share among themselves (this book's #ch-caustic; Veach's thesis, 1997,
 * its chapter 10) [@veach1997]. Internal: render/bdpt*.c include it, and the value
 * tests (tests/test_render_values.c), which pin the weights against
 * densities written out by hand; no program does, and `make install` does
 * not ship it; render/bdpt.h is the contract.
 *
 * The module follows the algorithm's seams, one file each:
 *   bdpt.c       the context, the camera's importance, and rt_bdpt_sample,
 *                which runs the strategies over the two subpaths;
 *   bdpt_walk.c  the subpaths: the walk shared by both ends and the start
 *                of a light subpath on an emitter (Veach 10.2);
 *   bdpt_mis.c   the densities of a joined path and the balance heuristic's
 *                weights over the strategies (Veach 10.3 and 9.2);
 *   bdpt_join.c  the joins: a shadow ray between the two subpaths' ends
 *                (t >= 2) and the splat of a light subpath's end onto the
 *                film (t = 1);
 *   bdpt_seen.c  the families only the camera side can make, estimated
 *                apart: the lamp seen directly or through glass and
 *                mirrors (E S* L), the caustic through the sphere
 *                (E (S+ D)+ S+ L).
 */
#ifndef RT_BDPT_INTERNAL_H
#define RT_BDPT_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "render/bdpt.h"
#include "render/leaf4.h"
#include "render/lights.h"

/* The unit direction from the camera to p (*dir) and its cosine with the
 * view axis (*cos_theta); false behind the camera. */
static inline bool rt_bdpt_camera_dir(const rt_bdpt_ctx *c, vec3 p, vec3 *dir, double *cos_theta)
{
    *dir = vec3_normalize(vec3_sub(p, c->camera->origin));
    *cos_theta = vec3_dot(*dir, c->forward);
    return *cos_theta > 0.0;
}

/* The segment from the point a to the point b, as each of its readers
 * would compute it alone: the densities at its two ends, a join's
 * geometry factor and its shadow ray. d = b - a, its squared length, its
 * length, and the unit direction d / length (vec3_normalize's numbers).
 * Read from b, the direction is -dir and the difference a - b is -d:
 * negation is exact, and so are the signs it gives a dot product, so one
 * computation serves both ends bit for bit, with one square root and one
 * division where each reader had its own. */
typedef struct rt_bdpt_segment {
    vec3 d, dir;
    double dist_sq, dist;
} rt_bdpt_segment;

static inline rt_bdpt_segment rt_bdpt_segment_make(vec3 a, vec3 b)
{
    rt_bdpt_segment g;
    g.d = vec3_sub(b, a);
    g.dist_sq = vec3_length_sq(g.d);
    g.dist = sqrt(g.dist_sq);
    g.dir = vec3_scale(g.d, 1.0 / g.dist);
    return g;
}

/* --- the subpaths (bdpt_walk.c) --------------------------------------- */

/* Continues a subpath along r from its last vertex v[n - 1] with weight
 * beta, appending a vertex per hit to v, until max_n vertices, a miss,
 * absorption or roulette; `segment` is the sampler's segment of the first
 * hit, rr_gain the subpath's roulette gain (RT_BDPT_RR_GAIN_CAMERA for a
 * camera subpath, 1 for a light subpath; render/bdpt.h). Adds the rays
 * traced to *segments. Returns the vertex count. */
int rt_bdpt_walk(const rt_bdpt_ctx *c, rt_ray r, vec3 beta, rt_bdpt_vertex *v, int n, int max_n,
                 int segment, double rr_gain, rt_sampler *sampler, uint64_t *segments);

/* The light subpath into v: at most max_n vertices (0 without emitters),
 * its draws from the sampler's segments past the camera subpath's
 * (max_depth + 1 on). Returns the vertex count. */
int rt_bdpt_light_walk(const rt_bdpt_ctx *c, rt_sampler *sampler, rt_bdpt_vertex *v, int max_n,
                       uint64_t *segments);

/* The aim's targets seen from the emitting point p, into *at when
 * c->aim > 0 (rt_lights_prepare over rt_scene_targets); without an aim
 * *at is left alone, and the _at functions below do not read it. */
static inline void rt_bdpt_emit_prepare(const rt_bdpt_ctx *c, vec3 p, rt_lights_at *at)
{
    if (c->aim > 0.0)
        rt_lights_prepare(at, rt_scene_targets(c->scene), rt_scene_target_count(c->scene), p);
}

/* rt_bdpt_emit_direction and rt_bdpt_emit_pdf with the targets prepared
 * from the emitting point (rt_bdpt_emit_prepare): a light subpath
 * prepares them for its direction and its throughput, and
 * rt_bdpt_cache_pdfs for the weights of its joins. */
vec3 rt_bdpt_emit_direction_at(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n,
                               rt_sampler *sampler);
/* rt_bdpt_emit_direction_at from the 2D request's uniforms (u1, u2). */
vec3 rt_bdpt_emit_direction_uv(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n, double u1,
                               double u2);
double rt_bdpt_emit_pdf_at(const rt_bdpt_ctx *c, const rt_lights_at *at, vec3 n, vec3 d);

/* --- densities and weights (bdpt_mis.c) ------------------------------- */

/* The density per unit area with which a light subpath starts at x:
 * 1 / (emitters x area) on the emitting side of an emitter, else 0. */
double rt_bdpt_origin_pdf(const rt_bdpt_ctx *c, const rt_bdpt_vertex *x);

/* The densities of the two subpaths that do not depend on how they are
 * joined (a Lambertian vertex's density does not depend on the direction
 * the path arrived from), remapped: lf[i], lr[i] are pl and pc of light
 * vertex i within its subpath (pc from vertex i + 1), cf[j], cr[j] pc and
 * pl of camera vertex j (pl from vertex j + 1); jl, jc whether the vertex
 * can be joined. pl and pc as in rt_bdpt_mis_weight.
 *
 * And the running sums of the balance heuristic's denominator, one per
 * vertex, that make a join's weight O(1) (the recursive form of the
 * weights that vertex connection and merging renderers use
 * [@georgiev2012]): la[i] is
 * the sum over the strategies r <= i that make light vertices 0..r-1 from
 * the light (ok ones only) of prod_{k=r..i} lr[k] / lf[k]; ce[j] the
 * sum over the strategies with t' = 1..j camera vertices of
 * prod_{m=t'..j} cr[m] / cf[m]; ce_any[j] whether any of those can
 * join. */
typedef struct rt_bdpt_subpath_pdfs {
    double lf[RT_BDPT_MAX_DEPTH], lr[RT_BDPT_MAX_DEPTH];
    double cf[RT_BDPT_MAX_DEPTH + 1], cr[RT_BDPT_MAX_DEPTH + 1];
    bool jl[RT_BDPT_MAX_DEPTH], jc[RT_BDPT_MAX_DEPTH + 1];
    double la[RT_BDPT_MAX_DEPTH], ce[RT_BDPT_MAX_DEPTH + 1];
    bool ce_any[RT_BDPT_MAX_DEPTH + 1];
    /* With an emission aim (c->aim > 0): the targets seen from light[0],
     * prepared once for the emission densities of its joins. */
    rt_lights_at emit_at;
} rt_bdpt_subpath_pdfs;

/* Fills *sp for the light subpath light[0..nl) and the camera subpath
 * cam[0..nc). */
void rt_bdpt_cache_pdfs(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int nl,
                        const rt_bdpt_vertex *cam, int nc, rt_bdpt_subpath_pdfs *sp);

/* rt_bdpt_mis_weight of strategy (s, t), the path light[0..s) joined to
 * cam[0..t) reversed, from the cached densities sp and the few that the
 * join changes, the path's densities gathered and summed again: in
 * O(s + t). The reference for rt_bdpt_join_weight_running. */
double rt_bdpt_join_weight(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                           const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam, int t);

/* The same weight in O(1), from the running sums of sp and the two
 * densities the join changes; what the joins use. It equals
 * rt_bdpt_join_weight to rounding (the products are associated
 * differently): tests/test_render_values.c holds every join of renders of
 * both scenes to 1e-12, the splat's scale on paths of three vertices
 * included. Paths of two vertices (the lamp seen directly, whose rule
 * gives it all to s = 0) and the negative control neg.mis_double go to
 * rt_bdpt_join_weight, which is O(1) there too. With c->audit set, both
 * are computed and the record updated. */
double rt_bdpt_join_weight_running(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                                   const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam,
                                   int t);

/* rt_bdpt_join_weight_running with the segment from light[s - 1] to
 * cam[t - 1] already made (g, unread when s = 0): the same number, the
 * join's own square root shared. */
double rt_bdpt_join_weight_along(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp,
                                 const rt_bdpt_vertex *light, int s, const rt_bdpt_vertex *cam,
                                 int t, const rt_bdpt_segment *g);

/* The record of c->audit: joins weighed, and the largest relative
 * difference |running - reference| / reference (absolute where the
 * reference is 0). */
typedef struct rt_bdpt_weight_audit {
    uint64_t joins;
    double worst;
} rt_bdpt_weight_audit;

/* --- the joins (bdpt_join.c) ------------------------------------------ */

/* The joins of one sample and their shadow rays, traced four at a time
 * through the scene's four-ray shadow test (rt_scene_occluded4) once four
 * are waiting, or one by one with c->one_ray_at_a_time. Each entry adds
 * its value, if its ray is clear (or it has none), to the sample's sum L
 * (a join) or to a pixel's splat sums (a splat), and the entries are
 * added in the order they were made: the same sums, bit for bit, as
 * tracing each ray when its join is made. A ray clear over (tmin, tmax)
 * is one that meets nothing nearer than its tmax: the same answer as
 * rt_scene_hit's. */
#define RT_BDPT_QUEUE 16
typedef struct rt_bdpt_shadows {
    rt_ray r[RT_LANES];
    double tmax[RT_LANES];
    int n_rays;                 /* rays waiting, <= RT_LANES */
    int n;                      /* entries waiting, <= RT_BDPT_QUEUE */
    vec3 v[RT_BDPT_QUEUE];      /* what each entry adds */
    int ray[RT_BDPT_QUEUE];     /* its ray in r, -1 for none */
    size_t px[RT_BDPT_QUEUE];   /* a splat's pixel; SIZE_MAX for a join */
    vec3 L;
    rt_splats *splats;
    uint64_t *segments;
} rt_bdpt_shadows;

/* An empty queue adding to L and splats, counting its rays in
 * *segments. */
rt_bdpt_shadows rt_bdpt_shadows_begin(vec3 L, rt_splats *splats, uint64_t *segments);

/* Traces what is waiting and returns the sum L. */
vec3 rt_bdpt_shadows_end(const rt_bdpt_ctx *c, rt_bdpt_shadows *q);

/* The contribution of strategy (s, t) with t >= 2 (s = 0: the camera
 * subpath's own hit on an emitter), weighted by the cached densities sp
 * (NULL: unweighted), with roulette on its shadow ray when aux is given
 * (RT_BDPT_JOIN_FLOOR), queued on q to add to its sum. */
void rt_bdpt_join(const rt_bdpt_ctx *c, const rt_bdpt_subpath_pdfs *sp, const rt_bdpt_vertex *light,
                  int s, const rt_bdpt_vertex *cam, int t, mc_rng *aux, rt_bdpt_shadows *q);

/* Strategy (s, 1), s >= 1: the light subpath's end seen by the camera
 * vertex cam0, times the camera importance (and the weight from sp, NULL:
 * unweighted), queued on q to add to the splat sums of the pixel it is
 * seen in; roulette on the shadow ray when aux is given. */
void rt_bdpt_splat_to_camera(const rt_bdpt_ctx *c, const rt_bdpt_vertex *light, int s,
                             const rt_bdpt_vertex *cam0, const rt_bdpt_subpath_pdfs *sp,
                             mc_rng *aux, rt_bdpt_shadows *q);

/* --- the families estimated apart (bdpt_seen.c) ----------------------- */

/* The Lambertian vertices D of the camera subpath cam[0..nc) that no
 * join can reach from the camera's side: the subpath starts with glass or
 * mirrors, and every Lambertian vertex up to D has glass or mirrors on
 * both sides (camera, glass, glass, D: the floor seen through the sphere;
 * then glass, D': a wall seen in the ball from that floor). Their indices
 * go into jd[] in order (room for nc); returns how many. */
int rt_bdpt_through_vertices(const rt_bdpt_vertex *cam, int nc, int *jd);

/* Whether the path of s = 0 that ends at camera vertex t - 1 (an emitter)
 * is one the weighted render estimates apart: E S* L (the vertices
 * between the camera and the emitter are all glass or mirrors), or
 * E (S+ D)+ S+ L, the last D one of the njd through vertices jd[]
 * (rt_bdpt_through_vertices) with glass or mirrors alone after it: no
 * other strategy can make either. The negative-control hooks of ps
 * (ps->neg) keep them in. */
bool rt_bdpt_estimated_apart(const rt_path_settings *ps, const rt_bdpt_vertex *cam, int t,
                             const int *jd, int njd);

/* The share of the cosine-weighted hemisphere about the unit normal ns
 * at p that the light list's spheres (rt_scene_targets) cover:
 * sum (r / d)^2 max(cos alpha, 0) over the spheres of radius r whose
 * centre is at distance d, at angle alpha from ns. The projected solid
 * angle of a sphere wholly above the horizon is pi (r / d)^2 cos alpha,
 * and the hemisphere's is pi; a sphere that crosses the horizon counts
 * less than it covers (the part below subtracts), and quads count
 * nothing. */
double rt_bdpt_target_share(const rt_scene *s, vec3 p, vec3 ns);

/* The paths E (S+ D)+ S+ L through the through vertex D = d = cam[jd]:
 * the mean over RT_BDPT_THROUGH_RAYS cosine-sampled directions at D
 * (RT_BDPT_THROUGH_RAYS_NEAR where rt_bdpt_target_share of D exceeds
 * RT_BDPT_THROUGH_NEAR) of what comes back through glass and mirrors,
 * times the subpath's weight up to D; the draws come from aux. Adds the
 * rays traced to *segments. */
vec3 rt_bdpt_through_estimate(const rt_bdpt_ctx *c, const rt_bdpt_vertex *d, int jd, mc_rng *aux,
                              uint64_t *segments);

/* rt_bdpt_seen_emission of the camera ray r from its first hit, which the
 * camera subpath cam[0..nc) has found already (vertex 1; none when r met
 * nothing): the same term without tracing r again, within depth
 * segments. */
vec3 rt_bdpt_seen_first(const rt_bdpt_ctx *c, rt_ray r, const rt_bdpt_vertex *cam, int nc,
                        int depth, mc_rng *aux, uint64_t *segments);

#endif /* RT_BDPT_INTERNAL_H */
