/* examples/figure_paths.c - the data of the book's figures of
 * bidirectional path tracing (`make plots`; #ch-caustic), from the
 * renderer's own scene, camera, ray casts and weights:
 *   path     one path of three segments in the "lambert" Cornell box,
 *            built as the renderer builds one: the camera ray of a pixel
 *            (rt_camera_ray, rt_scene_hit), a cosine-weighted bounce
 *            (pdf_cosine_direction) and a point drawn on the lamp
 *            (smp_parallelogram_sample); then the balance heuristic's
 *            weight of each of its four strategies (rt_bdpt_mis_weight).
 *            CSV curve,x,y,z: the edges of the room's quads ("room",
 *            "lamp"; a row "break" ends a polyline), the vertices x0 (on
 *            the lamp) .. x3 (the camera), and "weight:S" rows with the
 *            weight in x.
 *   weights  the same path with its wall vertex x1 moved up the vertical
 *            line z = 280 of the green wall x = 555, below the lamp: height,w_s0,w_s1,w_s2,w_s3,sum, the
 *            weights of the strategies s = 0 .. 3 (s light vertices) at
 *            each height where x2 sees that point of the wall.
 * Build and run:  make all && build/bin/figure_paths path
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "examples/common/cli.h"
#include "mc/onb.h"
#include "mc/rng.h"
#include "pdf/pdf.h"
#include "render/bdpt.h"
#include "render/scenes.h"
#include "samplers/planar.h"

#define PROG "figure_paths"

typedef struct setup {
    rt_scene *scene;
    rt_camera camera;
    rt_path_settings ps;
    rt_bdpt_ctx ctx;
    rt_bdpt_vertex x[4]; /* x[0] on the lamp .. x[3] the camera */
} setup;

static rt_bdpt_vertex surface(const setup *s, const rt_hit *h)
{
    return (rt_bdpt_vertex){.kind = RT_BDPT_SURFACE, .p = h->p, .ng = h->normal, .ns = h->normal,
                            .front_face = h->front_face, .m = rt_scene_material(s->scene, h->material),
                            .emitter = -1};
}

/* The path: camera, a floor point near the green wall, a bounce's hit on
 * a wall, the lamp. */
static void build(setup *s, uint64_t seed)
{
    rt_camera_params cp;
    s->scene = rt_scene_named("lambert", &cp);
    if (!s->scene)
        app_fail(PROG, "out of memory");
    s->camera = rt_camera_make(cp, 600, 600);
    s->ps = rt_path_settings_default(RT_BDPT);
    s->ps.max_depth = 3;
    s->ctx = rt_bdpt_ctx_make(s->scene, &s->ps, &s->camera);
    s->x[3] = (rt_bdpt_vertex){.kind = RT_BDPT_CAMERA, .p = s->camera.origin, .ng = s->ctx.forward,
                               .ns = s->ctx.forward, .emitter = -1};
    rt_hit h;
    if (!rt_scene_hit(s->scene, rt_camera_ray(&s->camera, 100.5, 560.5), HUGE_VAL, &h))
        app_fail(PROG, "the camera ray left the room");
    s->x[2] = surface(s, &h);
    /* The bounce: the first draw of the stream whose hit is a white or
     * coloured wall (not the lamp, not a box), so that the picture is
     * readable; the draws themselves are the renderer's. */
    mc_rng rng = mc_rng_derive(seed, 0);
    onb frame = onb_from_w(h.normal);
    rt_hit h1;
    for (int tries = 0;; tries++) {
        if (tries == 1000)
            app_fail(PROG, "--seed %llu: no bounce reached a wall", (unsigned long long)seed);
        double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
        vec3 d = pdf_cosine_direction(&frame, u1, u2);
        const rt_material *m;
        if (rt_scene_hit(s->scene, rt_ray_make(h.p, d), HUGE_VAL, &h1) &&
            (m = rt_scene_material(s->scene, h1.material))->kind == RT_MAT_LAMBERT &&
            (fabs(h1.p.x - 555.0) < 1e-6 || fabs(h1.p.x) < 1e-6 || fabs(h1.p.z - 555.0) < 1e-6))
            break;
    }
    s->x[1] = surface(s, &h1);
    const rt_prim *lamp = &rt_scene_emitter_prims(s->scene)[0];
    vec3 y0 = smp_parallelogram_sample(mc_rng_uniform(&rng), mc_rng_uniform(&rng), lamp->as.quad.q,
                                       lamp->as.quad.u, lamp->as.quad.v);
    s->x[0] = (rt_bdpt_vertex){.kind = RT_BDPT_LIGHT, .p = y0, .ng = lamp->as.quad.normal,
                               .ns = lamp->as.quad.normal, .front_face = true,
                               .m = rt_scene_material(s->scene, lamp->material), .emitter = 0};
}

static void row(const char *curve, vec3 p) { printf("%s,%.4f,%.4f,%.4f\n", curve, p.x, p.y, p.z); }

static void path(setup *s)
{
    printf("curve,x,y,z\n");
    const rt_prim *p = rt_scene_prims(s->scene);
    for (int i = 0; i < rt_scene_prim_count(s->scene); i++) {
        if (p[i].kind != RT_PRIM_QUAD)
            continue;
        const rt_quad *q = &p[i].as.quad;
        bool lamp = rt_scene_material(s->scene, p[i].material)->kind == RT_MAT_LIGHT;
        const double c[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
        for (int k = 0; k < 5; k++)
            row(lamp ? "lamp" : "room", smp_parallelogram_sample(c[k][0], c[k][1], q->q, q->u, q->v));
        printf("break,0,0,0\n");
    }
    for (int i = 0; i < 4; i++) {
        char name[8];
        snprintf(name, sizeof name, "x%d", i);
        row(name, s->x[i].p);
    }
    for (int sl = 0; sl < 4; sl++)
        printf("weight:%d,%.17g,0,0\n", sl, rt_bdpt_mis_weight(&s->ctx, s->x, 4, sl));
}

static void weights(setup *s)
{
    printf("height,w_s0,w_s1,w_s2,w_s3,sum\n");
    vec3 from = s->x[2].p;
    for (int k = 1; k < 555; k++) {
        vec3 target = vec3_make(555.0, (double)k, 280.0);
        vec3 d = vec3_sub(target, from);
        double dist = vec3_length(d);
        rt_hit h;
        /* Only where x2 sees the wall point (a box may hide it). */
        if (!rt_scene_hit(s->scene, rt_ray_make(from, vec3_scale(d, 1.0 / dist)), HUGE_VAL, &h) ||
            fabs(h.t - dist) > 1e-6 * dist)
            continue;
        s->x[1] = surface(s, &h);
        double w[4], sum = 0.0;
        for (int sl = 0; sl < 4; sl++)
            sum += w[sl] = rt_bdpt_mis_weight(&s->ctx, s->x, 4, sl);
        printf("%d,%.9g,%.9g,%.9g,%.9g,%.9g\n", k, w[0], w[1], w[2], w[3], sum);
    }
}

int main(int argc, char **argv)
{
    uint64_t seed = 1;
    const app_opt opts[] = {APP_OPT_SEED(&seed)};
    const char *cmd[1] = {NULL};
    int npos = app_parse(PROG, PROG " path|weights [--seed S]", argc, argv, opts, 1, cmd, 1);
    if (npos != 1 || (strcmp(cmd[0], "path") != 0 && strcmp(cmd[0], "weights") != 0))
        app_fail(PROG, "expected the command 'path' or 'weights' (see --help)");
    setup s;
    build(&s, seed);
    if (strcmp(cmd[0], "path") == 0)
        path(&s);
    else
        weights(&s);
    rt_scene_destroy(s.scene);
    return 0;
}
