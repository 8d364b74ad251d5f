/* render/bdpt_seen.c - the paths only the camera side can make, each
 * estimated apart from the strategies: the lamp seen directly or through
 * glass and mirrors (E S* L) and the caustic seen through the sphere
 * (E (S+ D)+ S+ L); render/bdpt.h says why, this book's #ch-caustic how. */
#include <math.h>

#include "mc/onb.h"
#include "mc/qmc.h"
#include "render/bdpt_internal.h"
#include "render/lights.h"

/* --- which paths are estimated apart ---------------------------------- */

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

int rt_bdpt_through_vertices(const rt_bdpt_vertex *cam, int nc, int *jd)
{
    /* The camera subpath's longest start in which no two neighbouring
     * vertices could be joined (the camera counts as joinable: a splat
     * joins it): glass and mirrors, with Lambertian vertices only
     * between two of them. Each of those Lambertian vertices ends a
     * prefix that only s = 0 can continue to an emitter through glass. */
    int n = 0;
    if (nc < 2 || !chain_material(cam[1].m))
        return 0;
    for (int j = 2; j < nc; j++) {
        if (chain_material(cam[j].m))
            continue;
        if (!cam[j].m || cam[j].m->kind != RT_MAT_LAMBERT || !chain_material(cam[j - 1].m))
            break;
        jd[n++] = j;
    }
    return n;
}

bool rt_bdpt_estimated_apart(const rt_path_settings *ps, const rt_bdpt_vertex *cam, int t,
                             const int *jd, int njd)
{
    if (all_chain(cam, 1, t - 1))
        return !ps->neg.seen_twice;
    /* The last through vertex with glass or mirrors between it and the
     * emitter at t - 1: every vertex after it chain, and at least one. */
    for (int i = njd - 1; i >= 0; i--)
        if (jd[i] + 2 <= t - 1)
            return all_chain(cam, jd[i] + 1, t - 1) && !ps->neg.through_twice;
    return false;
}

/* --- E S* L: the lamp seen directly or through glass and mirrors ------ */

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

/* seen_any's value once its ray r has been traced: h its first hit, NULL
 * for none. */
static vec3 seen_at(const rt_bdpt_ctx *c, rt_ray r, const rt_hit *h, int left, int splits,
                    bool through_only, mc_rng *rng, uint64_t *segments)
{
    vec3 zero = vec3_make(0.0, 0.0, 0.0);
    if (!h)
        return zero;
    const rt_material *m = rt_scene_material(c->scene, h->material);
    vec3 e = through_only ? zero : rt_material_emitted(m, h);
    if (!chain_material(m))
        return e;
    return vec3_add(e, through_chain_vertex(c, r, h, m, left, splits, rng, segments));
}

/* The first hits of the n rays r (hit[k] whether r[k] hit, h[k] its
 * record), four at a time through rt_scene_hit4 (the same hits as
 * rt_scene_hit) and the rest one by one; c->one_ray_at_a_time traces each
 * alone. The rays of seen_at draw nothing before their first hit, so
 * tracing those together and then running each ray's chain in order
 * draws the stream as tracing each ray whole before the next does. */
static void first_hits(const rt_bdpt_ctx *c, const rt_ray *r, int n, rt_hit *h, bool *hit,
                       uint64_t *segments)
{
    int k = 0;
    for (; !c->one_ray_at_a_time && k + RT_LANES <= n; k += RT_LANES) {
        unsigned mask = rt_scene_hit4(c->scene, &r[k], HUGE_VAL, &h[k]);
        for (int j = 0; j < RT_LANES; j++)
            hit[k + j] = (mask >> j) & 1u;
    }
    for (; k < n; k++)
        hit[k] = rt_scene_hit(c->scene, r[k], HUGE_VAL, &h[k]);
    *segments += (uint64_t)n;
}

/* rt_bdpt_seen_emission with `left` segments and `splits` splits to go;
 * through_only: only what comes through a glass or mirror vertex first
 * (the emitter met first is left out). */
static vec3 seen_any(const rt_bdpt_ctx *c, rt_ray r, int left, int splits, bool through_only,
                     mc_rng *rng, uint64_t *segments)
{
    rt_hit h;
    if (left < 1)
        return vec3_make(0.0, 0.0, 0.0);
    ++*segments;
    bool hit = rt_scene_hit(c->scene, r, HUGE_VAL, &h);
    return seen_at(c, r, hit ? &h : NULL, left, splits, through_only, rng, segments);
}

static vec3 seen(const rt_bdpt_ctx *c, rt_ray r, int left, int splits, mc_rng *rng,
                 uint64_t *segments)
{
    return seen_any(c, r, left, splits, false, rng, segments);
}
/* END SNIPPET bdpt_seen */

vec3 rt_bdpt_seen_first(const rt_bdpt_ctx *c, rt_ray r, const rt_bdpt_vertex *cam, int nc,
                        int depth, mc_rng *aux, uint64_t *segments)
{
    /* seen_any's terms at the hit cam[1], rebuilt from the vertex
     * instead of tracing r a second time. */
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

/* --- E (S+ D)+ S+ L: the caustic seen through the sphere ------------ */

/* Cosine sampling at the Lambertian D: BRDF x cos / density is the
 * albedo, whatever the direction. The rays' uniforms are the points of
 * an Owen-scrambled Sobol set of n = 2^m points, a (0,m,2)-net under a
 * scramble keyed from aux: each point alone is uniform, so the mean stays
 * unbiased, and together they cover the hemisphere's strata evenly
 * (paired renders of the book scene: about 7% less variance than
 * independent directions, at the same cost). Their first segments go
 * through the scene together (first_hits). */
_Static_assert((RT_BDPT_THROUGH_RAYS & (RT_BDPT_THROUGH_RAYS - 1)) == 0 &&
                   (RT_BDPT_THROUGH_RAYS_NEAR & (RT_BDPT_THROUGH_RAYS_NEAR - 1)) == 0,
               "the through rays are a whole Sobol net: a power of two");

double rt_bdpt_target_share(const rt_scene *s, vec3 p, vec3 ns)
{
    const rt_light *t = rt_scene_targets(s);
    double share = 0.0;
    for (int i = 0; i < rt_scene_target_count(s); i++) {
        if (t[i].kind != RT_PRIM_SPHERE)
            continue;
        vec3 to = vec3_sub(t[i].center, p);
        double d_sq = vec3_length_sq(to), cos_alpha = vec3_dot(to, ns) / sqrt(d_sq);
        if (cos_alpha > 0.0)
            share += t[i].radius * t[i].radius / d_sq * cos_alpha;
    }
    return share;
}

/* BEGIN SNIPPET bdpt_through */
vec3 rt_bdpt_through_estimate(const rt_bdpt_ctx *c, const rt_bdpt_vertex *d, int jd, mc_rng *aux,
                              uint64_t *segments)
{
    vec3 sum = vec3_make(0.0, 0.0, 0.0);
    onb frame = onb_from_w(d->ns);
    uint64_t key = ((uint64_t)mc_rng_u32(aux) << 32) | mc_rng_u32(aux);
    uint32_t key0 = mc_qmc_key(key, 0u, 0u), key1 = mc_qmc_key(key, 0u, 1u);
    int left = max_segments(c) - jd;
    int n = rt_bdpt_target_share(c->scene, d->p, d->ns) > RT_BDPT_THROUGH_NEAR
                ? RT_BDPT_THROUGH_RAYS_NEAR
                : RT_BDPT_THROUGH_RAYS;
    rt_ray r[RT_BDPT_THROUGH_RAYS_NEAR];
    rt_hit h[RT_BDPT_THROUGH_RAYS_NEAR];
    bool hit[RT_BDPT_THROUGH_RAYS_NEAR];
    for (int i = 0; i < n; i++) {
        double u1 = mc_sobol_owen_keyed((uint32_t)i, 0u, key0);
        double u2 = mc_sobol_owen_keyed((uint32_t)i, 1u, key1);
        r[i] = rt_ray_make(d->p, pdf_cosine_direction(&frame, u1, u2));
    }
    if (left >= 1) {
        first_hits(c, r, n, h, hit, segments);
        for (int i = 0; i < n; i++)
            sum = vec3_add(sum, seen_at(c, r[i], hit[i] ? &h[i] : NULL, left, RT_BDPT_SPLITS, true,
                                        aux, segments));
    }
    return vec3_scale(vec3_mul(vec3_mul(d->beta, d->m->albedo), sum), 1.0 / n);
}
/* END SNIPPET bdpt_through */

/* --- the lamp's edges: more camera rays where the term changes -------- */

/* The streams of the terms: one per pixel for the edge test, one per
 * pixel sample (keys apart from the pixels' own streams, which are
 * mc_rng_derive(seed, pixel)). */
#define SEEN_EDGE_KEY 0x5ee9ed9e5ee9ed9eull
#define SEEN_SAMPLE_KEY 0x5ee95a3b1e5ee95aull
/* The edge term's points (rt_bdpt_seen_sample): keys of seed ^ this. */
#define SEEN_NET_KEY 0x5ee9e7c05ee9e7c0ull

mc_rng rt_bdpt_aux_stream(uint64_t seed, uint64_t sample)
{
    return mc_rng_derive(seed ^ SEEN_SAMPLE_KEY, sample);
}

bool rt_bdpt_seen_edge(const rt_bdpt_ctx *c, int x, int y, uint64_t seed, uint64_t *segments)
{
    const rt_camera *cam = c->camera;
    mc_rng rng = mc_rng_derive(seed ^ SEEN_EDGE_KEY, (uint64_t)y * (uint64_t)cam->width + (uint64_t)x);
    vec3 lo = vec3_make(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = vec3_scale(lo, -1.0);
    enum { n = 9 }; /* a 3 x 3 grid */
    rt_ray r[n];
    rt_hit h[n];
    bool hit[n];
    for (int j = 0; j <= 2; j++)
        for (int i = 0; i <= 2; i++) {
            /* The far corners are inside the pixel by an ulp's worth. */
            double px = fmin((double)x + 0.5 * i, nextafter((double)x + 1.0, 0.0));
            double py = fmin((double)y + 0.5 * j, nextafter((double)y + 1.0, 0.0));
            r[3 * j + i] = rt_camera_ray(cam, px, py);
        }
    int left = max_segments(c);
    if (left >= 1)
        first_hits(c, r, n, h, hit, segments);
    for (int k = 0; k < n; k++) {
        /* rt_bdpt_seen_emission's value, its first segment traced above. */
        vec3 v = left >= 1 ? seen_at(c, r[k], hit[k] ? &h[k] : NULL, left, RT_BDPT_SPLITS, false,
                                     &rng, segments)
                           : vec3_make(0.0, 0.0, 0.0);
        lo = vec3_make(fmin(lo.x, v.x), fmin(lo.y, v.y), fmin(lo.z, v.z));
        hi = vec3_make(fmax(hi.x, v.x), fmax(hi.y, v.y), fmax(hi.z, v.z));
    }
    return hi.x - lo.x > 0.01 || hi.y - lo.y > 0.01 || hi.z - lo.z > 0.01;
}

/* BEGIN SNIPPET bdpt_seen_sample */
vec3 rt_bdpt_seen_sample(const rt_bdpt_ctx *c, int x, int y, uint64_t seed, uint64_t k, mc_rng *aux,
                         uint64_t *segments)
{
    /* The points k n .. k n + n - 1 (n = RT_BDPT_EDGE_SUBSAMPLES = 2^m)
     * of the pixel's Owen-scrambled Sobol sequence: one aligned block, a
     * (0, m, 2)-net (for 64, one point in each cell of an 8 x 8 grid); and
     * the blocks of the pixel's samples together are the sequence's first
     * points, which fill the pixel evenly at every scale. Each point alone
     * is uniform over the pixel, so the mean is unbiased for the pixel's
     * mean. The indices run past 2^32 only beyond 2^26 samples per pixel:
     * each 2^26 samples then take a fresh scramble. */
    enum { n = RT_BDPT_EDGE_SUBSAMPLES };
    _Static_assert((n & (n - 1)) == 0, "a sample's rays are a whole Sobol net: a power of two");
    uint64_t pixel = (uint64_t)y * (uint64_t)c->camera->width + (uint64_t)x;
    uint64_t pixel_seed = mc_qmc_stream_seed(seed ^ SEEN_NET_KEY, pixel);
    uint64_t block = k / (UINT32_MAX / n + 1u);
    uint32_t key0 = mc_qmc_key(pixel_seed, block, 0u), key1 = mc_qmc_key(pixel_seed, block, 1u);
    uint32_t i0 = (uint32_t)(k * n);
    vec3 sum = vec3_make(0.0, 0.0, 0.0);
    for (uint32_t j = 0; j < n; j++) {
        uint32_t i = i0 + j;
        rt_ray sub = rt_camera_ray(c->camera, (double)x + mc_sobol_owen_keyed(i, 0u, key0),
                                   (double)y + mc_sobol_owen_keyed(i, 1u, key1));
        sum = vec3_add(sum, rt_bdpt_seen_emission(c, sub, aux, segments));
    }
    return vec3_scale(sum, 1.0 / n);
}
/* END SNIPPET bdpt_seen_sample */
