/* tests/test_render_geometry.c - shapes, boxes, instances, the BVH, the
 * camera: known answers and agreement with brute force. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/rng.h"
#include "render/bvh.h"
#include "render/engine.h"
#include "render/fast/hit4.h"
#include "render/camera.h"
#include "render/scene.h"
#include "render/scenes.h"
#include "samplers/sphere.h"
#include "tests/support/negctl.h"

/* Builds s and gives it the engine's leaf tests, as render/scenes.c does
 * for its scenes: the renderer's entry points then run what it runs. */
static void build_with_engine(rt_scene *s)
{
    assert_int_equal(rt_scene_build(s), 0);
    rt_scene_use_leaf_tests(s, rt_engine_get()->leaf);
}

static vec3 v3(double x, double y, double z) { return vec3_make(x, y, z); }

static rt_ray random_ray(mc_rng *rng, vec3 lo, vec3 hi)
{
    vec3 o = v3(lo.x + (hi.x - lo.x) * mc_rng_uniform(rng), lo.y + (hi.y - lo.y) * mc_rng_uniform(rng),
                lo.z + (hi.z - lo.z) * mc_rng_uniform(rng));
    double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
    return rt_ray_make(o, smp_uniform_sphere_sample(u1, u2));
}

/* Known answers: a ray down the middle of a quad, its closed edges, a
 * parallel ray, a sphere from outside and from inside. */
static void test_shapes_known_hits(void **state)
{
    (void)state;
    rt_quad q = rt_quad_make(v3(0, 0, 5), v3(2, 0, 0), v3(0, 3, 0));
    assert_near(rt_quad_hit_distance(&q, rt_ray_make(v3(1, 1.5, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL), 5.0, 1e-15);
    /* The corner (a = b = 0) and the far corner (a = b = 1) belong to it. */
    assert_near(rt_quad_hit_distance(&q, rt_ray_make(v3(0, 0, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL), 5.0, 1e-15);
    assert_near(rt_quad_hit_distance(&q, rt_ray_make(v3(2, 3, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL), 5.0, 1e-15);
    assert_true(rt_quad_hit_distance(&q, rt_ray_make(v3(2.001, 1, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL) == HUGE_VAL);
    assert_true(rt_quad_hit_distance(&q, rt_ray_make(v3(1, 1, 5), v3(1, 0, 0)), 1e-3, HUGE_VAL) == HUGE_VAL);
    assert_true(rt_quad_hit_distance(&q, rt_ray_make(v3(1, 1, 0), v3(0, 0, 1)), 1e-3, 4.0) == HUGE_VAL);
    assert_near(q.normal.z, 1.0, 1e-15);
    rt_sphere s = rt_sphere_make(v3(0, 0, 10), 2.0, 1.0);
    assert_near(rt_sphere_hit_distance(&s, rt_ray_make(v3(0, 0, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL), 8.0, 1e-14);
    assert_near(rt_sphere_hit_distance(&s, rt_ray_make(v3(0, 0, 10), v3(0, 0, 1)), 1e-3, HUGE_VAL), 2.0, 1e-14);
    assert_true(rt_sphere_hit_distance(&s, rt_ray_make(v3(0, 2.5, 0), v3(0, 0, 1)), 1e-3, HUGE_VAL) == HUGE_VAL);
    /* Leaving the sphere from its surface: the far root. */
    assert_near(rt_sphere_hit_distance(&s, rt_ray_make(v3(0, 0, 8), v3(0, 0, 1)), 1e-3, HUGE_VAL), 4.0, 1e-14);
}

/* Every face of a box is met on its front face from outside, and the
 * normal at the hit faces the ray. */
static void test_box_faces_outward(void **state)
{
    (void)state;
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    rt_scene_add(s, rt_scene_box(s, v3(-1, -2, -3), v3(1, 2, 3), m));
    build_with_engine(s);
    vec3 dirs[6] = {v3(1, 0, 0), v3(-1, 0, 0), v3(0, 1, 0), v3(0, -1, 0), v3(0, 0, 1), v3(0, 0, -1)};
    for (int i = 0; i < 6; i++) {
        rt_hit h;
        vec3 o = vec3_scale(dirs[i], -10.0);
        assert_true(rt_scene_hit(s, rt_ray_make(o, dirs[i]), HUGE_VAL, &h));
        assert_true(h.front_face);
        assert_true(vec3_dot(h.normal, dirs[i]) < -0.999);
        /* From inside, every face is met from the back. */
        assert_true(rt_scene_hit(s, rt_ray_make(v3(0.1, 0.2, 0.3), dirs[i]), HUGE_VAL, &h));
        assert_false(h.front_face);
    }
    rt_scene_destroy(s);
}

/* rotate_y(+90) takes +x to -z (right-handed), translate adds, flip
 * swaps the faces. */
static void test_instances_known(void **state)
{
    (void)state;
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    rt_object ball = rt_scene_sphere(s, v3(3, 0, 0), 1.0, m);
    rt_object moved = rt_scene_translate(s, rt_scene_rotate_y(s, ball, 90.0), v3(0, 5, 0));
    rt_scene_add(s, rt_scene_flip(s, moved));
    build_with_engine(s);
    rt_hit h, t;
    rt_ray r = rt_ray_make(v3(0, 5, 0), v3(0, 0, -1));
    assert_true(rt_scene_hit(s, r, HUGE_VAL, &h));
    assert_near(h.t, 2.0, 1e-12);
    assert_false(h.front_face); /* flipped: the outside is the back */
    assert_true(rt_scene_hit_tree(s, r, HUGE_VAL, &t));
    assert_near(t.t, 2.0, 1e-12);
    assert_false(t.front_face);
    rt_scene_destroy(s);
}

/* Whether p is inside the book scene's tall box (265, 0, 295) + R(15 deg)
 * [0, 165] x [0, 330] x [0, 165]. */
static bool in_tall_box(vec3 p)
{
    double c = cos(15.0 * MC_PI / 180.0), s = sin(15.0 * MC_PI / 180.0);
    vec3 d = vec3_sub(p, v3(265, 0, 295));
    double x = c * d.x - s * d.z, z = s * d.x + c * d.z;
    return x >= -1 && x <= 166 && d.y >= -1 && d.y <= 331 && z >= -1 && z <= 166;
}

/* Flattened instances (transforms applied to the shapes once) against the
 * book's instances (every ray transformed) on the book scene: 10^5 random
 * rays from inside the room. Rigid motions in double precision differ by a
 * few ulps, so t and the normal may differ by rounding; a ray within 1e-9
 * of an edge could in principle flip between the two, which has
 * probability ~1e-8 per ray: none is expected. Origins inside the tall box
 * are left out: the box's bottom lies in the floor's plane, and which of
 * two coplanar faces is "closest" is decided by rounding (the book's scene
 * has this z-fight; rays from the room never see it). */
static void test_instances_flattened_match_tree(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_non_null(s);
    mc_rng rng = mc_rng_derive(11u, 0u);
    int hits = 0;
    for (int i = 0; i < 100000; i++) {
        rt_ray r = random_ray(&rng, v3(1, 1, 1), v3(554, 554, 554));
        if (in_tall_box(r.origin))
            continue;
        rt_hit a, b;
        bool ha = rt_scene_hit(s, r, HUGE_VAL, &a), hb = rt_scene_hit_tree(s, r, HUGE_VAL, &b);
        assert_int_equal(ha, hb);
        if (!ha)
            continue;
        hits++;
        assert_near(a.t, b.t, 1e-9 * (1.0 + b.t));
        assert_int_equal(a.material, b.material);
        assert_int_equal(a.front_face, b.front_face);
        assert_true(vec3_length(vec3_sub(a.normal, b.normal)) < 1e-9);
    }
    if (hits < 70000)
        fail_msg("only %d of 10^5 rays hit the scene", hits);
    rt_scene_destroy(s);
}

/* BVH closest hits equal brute force exactly (same primitive tests, so
 * the same t bit for bit; on a tie between primitives at equal t either
 * may win, so the t's are compared and the indices only when unique). */
static void check_bvh(const rt_scene *s, int n_rays, vec3 lo, vec3 hi, uint64_t seed)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    const rt_prim *prims = rt_scene_prims(s);
    int n = rt_scene_prim_count(s), hits = 0;
    for (int i = 0; i < n_rays; i++) {
        rt_ray r = random_ray(&rng, lo, hi);
        int ia, ib;
        double ta = rt_bvh_closest(rt_scene_bvh(s), prims, r, 1e-3, HUGE_VAL, &ia);
        double tb = rt_prims_closest(prims, n, r, 1e-3, HUGE_VAL, &ib);
        if (ta != tb || (ia != ib && rt_prim_hit_distance(&prims[ia], r, 1e-3, HUGE_VAL) != tb)) {
            fail_msg("ray %d: BVH t %.17g (prim %d), brute force t %.17g (prim %d)", i, ta, ia, tb, ib);
        }
        hits += ia >= 0;
    }
    printf("BVH (%d nodes, depth %d) = brute force on %d rays over %d primitives (%d hits)\n",
           rt_scene_bvh(s)->n_nodes, rt_scene_bvh(s)->depth, n_rays, n, hits);
    assert_true(hits > n_rays / 10);
}

/* rt_leaf_lanes_hit against rt_bvh_hit ray by ray: the same hit or miss, the
 * same distance bit for bit, and the same record when the primitive is
 * the same (on an exact tie another primitive at the same distance may
 * win). */
/* A ray whose direction has zero coordinates (along an axis or in an
 * axis plane), from a point with a coordinate snapped to lo or hi (on a
 * wall of the book's room): the cases where the dot products of a quad
 * test meet zeros and infinities. */
static rt_ray axis_ray(mc_rng *rng, vec3 lo, vec3 hi)
{
    rt_ray r = random_ray(rng, lo, hi);
    double c[3] = {r.dir.x, r.dir.y, r.dir.z}, o[3] = {r.origin.x, r.origin.y, r.origin.z};
    int zeros = 1 + (int)mc_rng_bounded(rng, 2u); /* one or two coordinates */
    for (int z = 0; z < zeros; z++)
        c[mc_rng_bounded(rng, 3u)] = 0.0;
    if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0)
        c[1] = -1.0;
    int a = (int)mc_rng_bounded(rng, 3u);
    o[a] = mc_rng_uniform(rng) < 0.5 ? vec3_at(lo, a) : vec3_at(hi, a);
    return rt_ray_make(v3(o[0], o[1], o[2]), vec3_normalize(v3(c[0], c[1], c[2])));
}

/* rt_leaf_lanes_hit with the tests of instruction set isa
 * (rt_fast_leaf_tests; for RT_ISA_COUNT rt_scene_hit4 with the scene's
 * own, the engine's: the renderer's entry) against rt_bvh_hit. */
static int check_hit4_isa(const rt_scene *s, int n_batches, vec3 lo, vec3 hi, uint64_t seed, int isa)
{
    rt_leaf_tests tests = rt_fast_leaf_tests(isa == RT_ISA_COUNT ? RT_ISA_PORTABLE : (rt_isa)isa);
    mc_rng rng = mc_rng_derive(seed, 0u);
    const rt_prim *prims = rt_scene_prims(s);
    const rt_bvh *b = rt_scene_bvh(s);
    int hits = 0;
    for (int i = 0; i < n_batches; i++) {
        rt_ray r[RT_LANES];
        rt_hit h4[RT_LANES];
        for (int k = 0; k < RT_LANES; k++)
            r[k] = i % 8 == 7 ? axis_ray(&rng, lo, hi) : random_ray(&rng, lo, hi);
        unsigned mask = isa == RT_ISA_COUNT
                            ? rt_scene_hit4(s, r, HUGE_VAL, h4)
                            : rt_leaf_lanes_hit(&tests, rt_scene_leaf_lanes(s), b, prims, r,
                                                1e-3, HUGE_VAL, h4);
        for (int k = 0; k < RT_LANES; k++) {
            rt_hit h1;
            bool hit = rt_bvh_hit(b, prims, &r[k], 1e-3, HUGE_VAL, &h1);
            if (hit != (((mask >> k) & 1u) != 0))
                fail_msg("batch %d lane %d: hit4 says %u, hit says %d", i, k, (mask >> k) & 1u, hit);
            if (!hit)
                continue;
            hits++;
            if (h4[k].t != h1.t)
                fail_msg("batch %d lane %d: t %.17g against %.17g", i, k, h4[k].t, h1.t);
            if (h4[k].prim != h1.prim) {
                if (rt_prim_hit_distance(&prims[h4[k].prim], r[k], 1e-3, HUGE_VAL) != h1.t)
                    fail_msg("batch %d lane %d: prim %d against %d", i, k, h4[k].prim, h1.prim);
                continue;
            }
            assert_true(h4[k].p.x == h1.p.x && h4[k].p.y == h1.p.y && h4[k].p.z == h1.p.z);
            assert_true(h4[k].normal.x == h1.normal.x && h4[k].normal.y == h1.normal.y &&
                        h4[k].normal.z == h1.normal.z);
            assert_int_equal(h4[k].front_face, h1.front_face);
            assert_int_equal(h4[k].material, h1.material);
        }
    }
    return hits;
}

/* check_hit4_isa through rt_scene_hit4 (the processor's best instruction
 * set), then every instruction set below the best on a fifth of the
 * rays: so the portable path stays tested on a processor with AVX2. */
static int check_hit4(const rt_scene *s, int n_batches, vec3 lo, vec3 hi, uint64_t seed)
{
    int hits = check_hit4_isa(s, n_batches, lo, hi, seed, RT_ISA_COUNT);
    for (int isa = 0; isa < (int)rt_isa_best(); isa++)
        check_hit4_isa(s, n_batches / 5, lo, hi, seed + 100u, isa);
    return hits;
}

/* The book scene (a root leaf: the four-lane vector test where AVX2 is
 * there, with its axis-aligned quads on their own path) with 2.5 x 10^5
 * batches of rays from all around and inside it and 5 x 10^4 from its
 * walls, one batch in eight along axes or axis planes; then the soup of
 * test_bvh_matches_brute_force's kind (a deep tree: ray by ray). */
static void test_bvh_hit4_matches_hit(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    int hits = check_hit4(s, 250000, v3(-100, -100, -900), v3(655, 655, 655), 16u);
    assert_true(hits > 250000);
    /* Rays from the room's walls (coordinates 0 and 555 exactly). */
    hits = check_hit4(s, 50000, v3(0, 0, 0), v3(555, 555, 555), 19u);
    assert_true(hits > 100000);
    rt_scene_destroy(s);
    /* The all-diffuse box, split by its BVH and in lanes whole. */
    s = rt_scene_named("lambert", &cp);
    assert_true(rt_scene_bvh(s)->nodes[0].count == 0 && rt_scene_leaf_lanes(s));
    hits = check_hit4(s, 50000, v3(0, 0, 0), v3(555, 555, 555), 27u);
    assert_true(hits > 100000);
    rt_scene_destroy(s);
    mc_rng rng = mc_rng_derive(17u, 0u);
    s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    for (int i = 0; i < 100; i++) {
        vec3 c = v3(100 * mc_rng_uniform(&rng), 100 * mc_rng_uniform(&rng), 100 * mc_rng_uniform(&rng));
        if (i % 2 == 0)
            rt_scene_add(s, rt_scene_sphere(s, c, 5.0, m));
        else
            rt_scene_add(s, rt_scene_quad(s, c, v3(10, 0, 3), v3(0, 8, -2), m));
    }
    build_with_engine(s);
    assert_true(rt_scene_bvh(s)->nodes[0].count == 0); /* not a leaf: the other path */
    hits = check_hit4(s, 20000, v3(-20, -20, -20), v3(120, 120, 120), 18u);
    printf("rt_scene_hit4 = rt_bvh_hit on 1.2 x 10^6 + 8 x 10^4 rays (%d hits in the soup)\n", hits);
    assert_true(hits > 8000);
    rt_scene_destroy(s);
}

/* A root leaf with a quad of every layout of render/fast/hit4.h:
 * axis-aligned, turned about x (its ea along x: a and b swapped) and
 * about z, flat in a z plane, in general position; a sphere and an inward
 * one around it all. */
static rt_scene *quad_kinds_scene(void)
{
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    rt_scene_add(s, rt_scene_quad(s, v3(0, 0, 0), v3(100, 0, 0), v3(0, 0, 100), m));
    rt_scene_add(s, rt_scene_quad(s, v3(10, 10, 10), v3(20, 0, 0), v3(0, 30, 40), m));
    rt_scene_add(s, rt_scene_quad(s, v3(20, 50, 30), v3(20, 15, 0), v3(0, 0, 25), m));
    rt_scene_add(s, rt_scene_quad(s, v3(50, 20, 80), v3(30, 10, 0), v3(-10, 25, 0), m));
    rt_scene_add(s, rt_scene_quad(s, v3(30, 30, 30), v3(10, 20, 30), v3(-20, 10, 5), m));
    rt_scene_add(s, rt_scene_sphere(s, v3(60, 60, 60), 15.0, m));
    rt_scene_add(s, rt_scene_flip(s, rt_scene_sphere(s, v3(50, 50, 50), 200.0, m)));
    build_with_engine(s);
    return s;
}

/* quad_kinds_scene with 2 x 10^4 batches through the public entry and
 * each instruction set. */
static void test_bvh_hit4_quad_kinds(void **state)
{
    (void)state;
    rt_scene *s = quad_kinds_scene();
    const rt_leaf_lanes *b4 = rt_scene_leaf_lanes(s);
    assert_non_null(b4);
    assert_int_equal(b4->n_axis, 1);
    assert_int_equal(b4->n_turned, 2);
    assert_int_equal(b4->n_flat, 1);
    assert_int_equal(b4->n_other, 1);
    assert_int_equal(b4->n_spheres, 2);
    int hits = check_hit4(s, 20000, v3(-20, -20, -20), v3(120, 120, 120), 21u);
    assert_true(hits == 4 * 20000); /* the inward sphere catches every ray */
    rt_scene_destroy(s);
}

/* rt_leaf_lanes_occluded with the tests of instruction set isa (for
 * RT_ISA_COUNT rt_scene_occluded4, the renderer's entry) against the
 * nearest hit of rt_bvh_hit, ray by ray: ray k blocked when that hit is
 * nearer than its own tmax[k]. The four lanes' tmax differ: infinite, a
 * uniform distance up to 900, the ray's nearest hit exactly (not blocked
 * by it: t < tmax fails) or the next double above it (blocked), so that
 * every lane meets the edge where its answer turns. *far_wrong counts the
 * batches where comparing every lane with the largest tmax instead (the
 * slip of a shadow test that forgets the lanes' own ends) would answer
 * otherwise. Returns the blocked rays. */
static int check_occluded4_isa(const rt_scene *s, int n_batches, vec3 lo, vec3 hi, uint64_t seed,
                               int isa, long *far_wrong)
{
    const char *name = isa == RT_ISA_COUNT ? "rt_scene_occluded4" : rt_isa_name((rt_isa)isa);
    rt_leaf_tests tests = rt_fast_leaf_tests(isa == RT_ISA_COUNT ? RT_ISA_PORTABLE : (rt_isa)isa);
    mc_rng rng = mc_rng_derive(seed, 0u);
    const rt_prim *prims = rt_scene_prims(s);
    const rt_bvh *b = rt_scene_bvh(s);
    double tmin = rt_scene_t_min(s);
    int blocked_rays = 0;
    for (int i = 0; i < n_batches; i++) {
        rt_ray r[RT_LANES];
        double tmax[RT_LANES], far = 0.0;
        rt_hit h[RT_LANES];
        bool hit[RT_LANES];
        for (int k = 0; k < RT_LANES; k++) {
            r[k] = i % 8 == 7 ? axis_ray(&rng, lo, hi) : random_ray(&rng, lo, hi);
            hit[k] = rt_bvh_hit(b, prims, &r[k], tmin, HUGE_VAL, &h[k]);
            unsigned kind = mc_rng_bounded(&rng, 4u);
            tmax[k] = kind == 0 ? HUGE_VAL : 900.0 * mc_rng_uniform(&rng);
            if (hit[k] && kind >= 2)
                tmax[k] = kind == 2 ? h[k].t : nextafter(h[k].t, HUGE_VAL);
            far = tmax[k] > far ? tmax[k] : far;
        }
        unsigned mask = isa == RT_ISA_COUNT
                            ? rt_scene_occluded4(s, r, tmax)
                            : rt_leaf_lanes_occluded(&tests, rt_scene_leaf_lanes(s), b, prims, r,
                                                     tmin, tmax);
        unsigned want = 0u, at_far = 0u;
        for (int k = 0; k < RT_LANES; k++) {
            want |= (unsigned)(hit[k] && h[k].t < tmax[k]) << k;
            at_far |= (unsigned)(hit[k] && h[k].t < far) << k;
        }
        if (mask != want)
            fail_msg("batch %d (%s): blocked lanes %#x, the nearest hits say %#x", i, name, mask,
                     want);
        *far_wrong += at_far != want;
        blocked_rays += __builtin_popcount(want);
    }
    return blocked_rays;
}

/* The shadow-ray test against the nearest hit: the book scene (10^5
 * batches of rays from all around and inside it, 5 x 10^4 from its
 * walls), the all-diffuse box (5 x 10^4 from its walls) and the leaf of
 * every quad layout (2 x 10^4), through the renderer's entry and every
 * instruction set the processor has. Control: a shadow test that compares
 * every lane with the largest tmax must disagree in some batch. */
static void test_occluded4_matches_hit(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    long far_wrong = 0;
    int blocked = 0;
    struct {
        rt_scene *s;
        int n;
        vec3 lo, hi;
        uint64_t seed;
    } runs[4] = {
        {rt_scene_named("book", &cp), 100000, v3(-100, -100, -900), v3(655, 655, 655), 31u},
        {NULL, 50000, v3(0, 0, 0), v3(555, 555, 555), 32u},
        {rt_scene_named("lambert", &cp), 50000, v3(0, 0, 0), v3(555, 555, 555), 33u},
        {quad_kinds_scene(), 20000, v3(-20, -20, -20), v3(120, 120, 120), 34u},
    };
    runs[1].s = runs[0].s;
    for (int j = 0; j < 4; j++) {
        assert_non_null(rt_scene_leaf_lanes(runs[j].s));
        blocked += check_occluded4_isa(runs[j].s, runs[j].n, runs[j].lo, runs[j].hi, runs[j].seed,
                                       RT_ISA_COUNT, &far_wrong);
        for (int isa = 0; isa < RT_ISA_COUNT; isa++)
            if (rt_isa_available((rt_isa)isa))
                check_occluded4_isa(runs[j].s, runs[j].n / 5, runs[j].lo, runs[j].hi,
                                    runs[j].seed + 100u, isa, &far_wrong);
    }
    printf("rt_scene_occluded4 = the nearest hit against each lane's tmax on 2.2 x 10^5 batches "
           "(%d rays blocked); against the largest tmax %ld batches would differ\n",
           blocked, far_wrong);
    assert_true(blocked > 100000);
    if (!negctl_record(nc, "every lane against the largest tmax", "occluded4 = nearest hit",
                       far_wrong > 0))
        fail_msg("comparing with the largest tmax changed no answer");
    rt_scene_destroy(runs[0].s);
    rt_scene_destroy(runs[2].s);
    rt_scene_destroy(runs[3].s);
}

/* A soup of 400 random quads and spheres of very different sizes, then the
 * book scene: 2 x 10^5 + 10^6 rays. */
static void test_bvh_matches_brute_force(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(12u, 0u);
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    for (int i = 0; i < 400; i++) {
        vec3 c = v3(100 * mc_rng_uniform(&rng), 100 * mc_rng_uniform(&rng), 100 * mc_rng_uniform(&rng));
        double size = pow(10.0, -1.0 + 2.5 * mc_rng_uniform(&rng));
        if (i % 3 == 0) {
            rt_scene_add(s, rt_scene_sphere(s, c, size, m));
        } else {
            vec3 u = vec3_scale(smp_uniform_sphere_sample(mc_rng_uniform(&rng), mc_rng_uniform(&rng)), size);
            vec3 v = vec3_scale(smp_uniform_sphere_sample(mc_rng_uniform(&rng), mc_rng_uniform(&rng)), size);
            rt_scene_add(s, rt_scene_quad(s, c, u, v, m));
        }
    }
    build_with_engine(s);
    const rt_bvh *b = rt_scene_bvh(s);
    assert_true(b->depth < RT_BVH_MAX_DEPTH);
    check_bvh(s, 200000, v3(-20, -20, -20), v3(120, 120, 120), 13u);
    rt_scene_destroy(s);

    rt_camera_params cp;
    s = rt_scene_named("book", &cp);
    check_bvh(s, 1000000, v3(-100, -100, -900), v3(655, 655, 655), 14u);
    rt_scene_destroy(s);
}

/* Whether two hit records hold the same bits (t, point and normal
 * compared as bits, so that -0 and +0 differ). */
static bool same_hit(const rt_hit *a, const rt_hit *b)
{
    double x[7] = {a->t, a->p.x, a->p.y, a->p.z, a->normal.x, a->normal.y, a->normal.z};
    double y[7] = {b->t, b->p.x, b->p.y, b->p.z, b->normal.x, b->normal.y, b->normal.z};
    return memcmp(x, y, sizeof x) == 0 && a->front_face == b->front_face &&
           a->material == b->material && a->prim == b->prim;
}

/* rt_leaf_lanes_hit1 with the tests of instruction set isa (rt_scene_hit
 * with the scene's own, the engine's: the renderer's entry, for
 * RT_ISA_COUNT) against rt_bvh_hit on n_rays rays,
 * one in eight along axes or axis planes: the same hit or miss and the
 * same record bit for bit, the primitive included. A ray in sixteen has
 * tmin 0 or -50 and one in sixteen a finite tmax (not through
 * rt_scene_hit, whose range is the scene's). Returns the hits. */
static int check_hit1_isa(const rt_scene *s, int n_rays, vec3 lo, vec3 hi, uint64_t seed, int isa)
{
    const char *name = isa == RT_ISA_COUNT ? "rt_scene_hit" : rt_isa_name((rt_isa)isa);
    rt_leaf_tests tests = rt_fast_leaf_tests(isa == RT_ISA_COUNT ? RT_ISA_PORTABLE : (rt_isa)isa);
    const rt_bvh *b = rt_scene_bvh(s);
    const rt_prim *prims = rt_scene_prims(s);
    mc_rng rng = mc_rng_derive(seed, 0u);
    int hits = 0;
    for (int i = 0; i < n_rays; i++) {
        rt_ray r = i % 8 == 7 ? axis_ray(&rng, lo, hi) : random_ray(&rng, lo, hi);
        double tmin = 1e-3, tmax = HUGE_VAL;
        if (isa != RT_ISA_COUNT && i % 16 == 3)
            tmin = i % 32 == 3 ? 0.0 : -50.0;
        if (isa != RT_ISA_COUNT && i % 16 == 5)
            tmax = 300.0 * mc_rng_uniform(&rng);
        rt_hit h1, h = {0};
        bool hit = isa == RT_ISA_COUNT
                       ? rt_scene_hit(s, r, HUGE_VAL, &h1)
                       : rt_leaf_lanes_hit1(&tests, rt_scene_leaf_lanes(s), b, prims, &r, tmin,
                                            tmax, &h1);
        if (hit != rt_bvh_hit(b, prims, &r, tmin, tmax, &h))
            fail_msg("ray %d (%s): hit1 says %d, rt_bvh_hit %d", i, name, hit, !hit);
        /* A BVH that splits may report the other primitive of an exact
         * tie (rt_leaf_lanes_hit1); a leaf reports the first. */
        bool tie = hit && h1.prim != h.prim && b->nodes[0].count == 0 && h1.t == h.t &&
                   rt_prim_hit_distance(&prims[h1.prim], r, tmin, tmax) == h.t;
        if (hit && !tie && !same_hit(&h1, &h))
            fail_msg("ray %d (%s): t %.17g prim %d against t %.17g prim %d", i, name, h1.t, h1.prim,
                     h.t, h.prim);
        hits += hit;
    }
    return hits;
}

/* check_hit1_isa through rt_scene_hit and with every instruction set the
 * processor has. */
static int check_hit1(const rt_scene *s, int n_rays, vec3 lo, vec3 hi, uint64_t seed)
{
    int hits = check_hit1_isa(s, n_rays, lo, hi, seed, RT_ISA_COUNT);
    for (int isa = 0; isa < RT_ISA_COUNT; isa++)
        if (rt_isa_available((rt_isa)isa))
            check_hit1_isa(s, n_rays, lo, hi, seed + 100u, isa);
    return hits;
}

/* The one-ray test of the root leaf against the reference: the book scene
 * (2.5 x 10^5 rays from all around and inside it, 5 x 10^4 from its
 * walls), the leaf with a quad of every layout (five quads: a packet and
 * a part of one), and a leaf of exact ties (a quad and a sphere each
 * twice, the copies apart in prims), where the first of the primitives at
 * the nearest distance must be the one reported. */
static void test_bvh_hit1_matches_hit(void **state)
{
    (void)state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_non_null(rt_scene_leaf_lanes(s));
    int hits = check_hit1(s, 250000, v3(-100, -100, -900), v3(655, 655, 655), 22u);
    int wall_hits = check_hit1(s, 50000, v3(0, 0, 0), v3(555, 555, 555), 23u);
    printf("rt_leaf_lanes_hit1 = rt_bvh_hit on 3 x 10^5 rays through the book's room (%d + %d hits)\n",
           hits, wall_hits);
    assert_true(hits > 50000 && wall_hits > 40000);
    rt_scene_destroy(s);
    /* The all-diffuse box: 18 quads, which the BVH splits, in lanes whole
     * (RT_LEAF_LANES_MAX_PRIMS). */
    s = rt_scene_named("lambert", &cp);
    assert_true(rt_scene_bvh(s)->nodes[0].count == 0);
    assert_non_null(rt_scene_leaf_lanes(s));
    hits = check_hit1(s, 100000, v3(-100, -100, -900), v3(655, 655, 655), 25u);
    wall_hits = check_hit1(s, 50000, v3(0, 0, 0), v3(555, 555, 555), 26u);
    printf("rt_leaf_lanes_hit1 = rt_bvh_hit on 1.5 x 10^5 rays through the lambert room (%d + %d "
           "hits)\n",
           hits, wall_hits);
    assert_true(hits > 20000 && wall_hits > 40000);
    rt_scene_destroy(s);
    s = quad_kinds_scene();
    assert_int_equal(rt_scene_leaf_lanes(s)->n_packets, 2);
    wall_hits = check_hit1(s, 40000, v3(-20, -20, -20), v3(120, 120, 120), 24u);
    assert_true(wall_hits == 40000); /* the inward sphere catches every ray */
    rt_scene_destroy(s);
    s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    int m2 = rt_scene_add_material(s, rt_lambertian(v3(0.25, 0.5, 0.75)));
    rt_object q = rt_scene_quad(s, v3(0, 0, 50), v3(100, 0, 0), v3(0, 100, 0), m);
    rt_object q2 = rt_scene_quad(s, v3(0, 0, 50), v3(100, 0, 0), v3(0, 100, 0), m2);
    rt_object ball = rt_scene_sphere(s, v3(50, 50, 45), 5.0, m2), ball2 = rt_scene_sphere(s, v3(50, 50, 45), 5.0, m);
    /* Between them quads as wide as the room's (so that the SAH keeps
     * one leaf): in prims ball 0, q 2, ball2 4, q2 6, eight quads, q
     * the second and q2 the fifth, so that q2 is in a lower lane than q
     * if the quads went to lanes in turn. */
    rt_object items[] = {ball, -1, q, -1, ball2, -1, q2, -1, -1, -1};
    for (int i = 0, z = 51; i < 10; i++)
        rt_scene_add(s, items[i] >= 0 ? items[i]
                                      : rt_scene_quad(s, v3(0, 0, z++), v3(100, 0, 0), v3(0, 100, 0), m));
    build_with_engine(s);
    assert_non_null(rt_scene_leaf_lanes(s));
    hits = check_hit1(s, 40000, v3(0, 0, -20), v3(100, 100, 120), 25u);
    /* Every hit on a copy is a tie, won by the first: ball and q, never
     * ball2 or q2. */
    mc_rng rng = mc_rng_derive(26u, 0u);
    int ties = 0;
    for (int i = 0; i < 10000; i++) {
        rt_hit h;
        if (!rt_scene_hit(s, random_ray(&rng, v3(0, 0, -20), v3(100, 100, 120)), HUGE_VAL, &h))
            continue;
        assert_true(h.prim != 4 && h.prim != 6);
        ties += h.prim == 0 || h.prim == 2;
    }
    printf("rt_leaf_lanes_hit1 = rt_bvh_hit on 8 x 10^4 rays through two leaves (%d + %d hits; "
           "%d ties in 10^4 rays)\n", wall_hits, hits, ties);
    assert_true(hits > 5000 && ties > 1000);
    rt_scene_destroy(s);
}

/* Coincident centroids and a long chain of nested boxes must still give a
 * tree within the fixed traversal stack. */
static void test_bvh_degenerate_inputs(void **state)
{
    (void)state;
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    for (int i = 0; i < 300; i++) /* concentric spheres: one centroid */
        rt_scene_add(s, rt_scene_sphere(s, v3(1, 2, 3), 1.0 + i, m));
    for (int i = 0; i < 300; i++) /* geometric sizes: a deep SAH tree */
        rt_scene_add(s, rt_scene_sphere(s, v3(pow(1.1, i), 0, 0), 1e-3, m));
    build_with_engine(s);
    assert_true(rt_scene_bvh(s)->depth < RT_BVH_MAX_DEPTH);
    check_bvh(s, 20000, v3(-50, -50, -50), v3(50, 50, 50), 15u);
    rt_scene_destroy(s);
}

/* The centre of the image looks at lookat; the top edge of the image is
 * vfov / 2 above the axis; the left edge is to the left (image right is
 * lookfrom->lookat x up). */
static void test_camera_geometry(void **state)
{
    (void)state;
    rt_camera_params p = {v3(278, 278, -800), v3(278, 278, 0), v3(0, 1, 0), 40.0};
    rt_camera c = rt_camera_make(p, 600, 400);
    rt_ray mid = rt_camera_ray(&c, 300.0, 200.0);
    assert_near(mid.dir.z, 1.0, 1e-15);
    rt_ray top = rt_camera_ray(&c, 300.0, 0.0);
    assert_near(atan2(top.dir.y, top.dir.z), 20.0 * MC_PI / 180.0, 1e-12);
    rt_ray left = rt_camera_ray(&c, 0.0, 200.0);
    /* Looking along +z with +y up, the image's right is -x. */
    assert_true(left.dir.x > 0.0);
    assert_near(atan2(left.dir.x, left.dir.z), atan(tan(20.0 * MC_PI / 180.0) * 1.5), 1e-12);
    assert_near(vec3_length(rt_camera_ray(&c, 13.7, 345.1).dir), 1.0, 1e-15);
}

/* Bad input to the scene builder is reported, not crashed on. */
static void test_scene_errors(void **state)
{
    (void)state;
    rt_scene *s = rt_scene_create();
    int m = rt_scene_add_material(s, rt_lambertian(v3(0.5, 0.5, 0.5)));
    rt_object q = rt_scene_quad(s, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), m);
    rt_scene_add(s, q);
    rt_scene_add_light(s, rt_scene_box(s, v3(0, 0, 0), v3(1, 1, 1), m)); /* six quads */
    assert_int_equal(rt_scene_build(s), -1);
    rt_scene_destroy(s);
    s = rt_scene_create();
    rt_scene_add(s, rt_scene_quad(s, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), 7)); /* no material 7 */
    assert_int_equal(rt_scene_build(s), -1);
    rt_scene_destroy(s);
    s = rt_scene_create();
    assert_int_equal(rt_scene_translate(s, 42, v3(1, 0, 0)), -1);
    assert_int_equal(rt_scene_build(s), -1);
    rt_scene_destroy(s);
    rt_camera_params cp;
    assert_null(rt_scene_named("no-such-scene", &cp));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shapes_known_hits),
        cmocka_unit_test(test_box_faces_outward),
        cmocka_unit_test(test_instances_known),
        cmocka_unit_test(test_instances_flattened_match_tree),
        cmocka_unit_test(test_bvh_matches_brute_force),
        cmocka_unit_test(test_bvh_hit4_matches_hit),
        cmocka_unit_test(test_bvh_hit4_quad_kinds),
        cmocka_unit_test(test_bvh_hit1_matches_hit),
        cmocka_unit_test(test_occluded4_matches_hit),
        cmocka_unit_test(test_bvh_degenerate_inputs),
        cmocka_unit_test(test_camera_geometry),
        cmocka_unit_test(test_scene_errors),
    };
    return cmocka_run_group_tests_name("test_render_geometry", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
