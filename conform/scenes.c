/* conform/scenes.c - the tables of the conformance scenes.
 *
 * Each scene is built so that its truth is a closed form (conform/truth.c
 * derives each one): no emitter is in view (its radiance would not fit in
 * [0, 1), and its silhouette would cut pixels the quadrature must then
 * resolve), and every reflector is flat or absorbs, so that light reflects
 * off at most one diffuse surface on its way to the camera, except in the
 * furnaces, whose series sum in closed form.
 */
#include "conform/conform.h"

#include <stddef.h>
#include <string.h>

/* 2 atan(1/2) in degrees: from 2 units above the floor, the view spans
 * [-1, 1] of it in both directions. */
#define WALL_FOV 53.13010235415598

/* The floor of the wall scenes: y = 0, [-1.2, 1.2]^2, facing +y
 * ((0, 0, 2.4) x (2.4, 0, 0) = (0, 5.76, 0)), wider than the view so that
 * no pixel sees its edge. */
#define WALL_FLOOR                                                                           \
    {.kind = CF_QUAD, .q = {-1.2, 0.0, -1.2}, .u = {0.0, 0.0, 2.4}, .v = {2.4, 0.0, 0.0},   \
     .material = 0}

/* Looking straight down from 2 above the floor: up in the image is -z, so
 * that right in the image is +x (the camera's u = vup x w). */
#define WALL_CAMERA .lookfrom = {0.0, 2.0, 0.0}, .lookat = {0.0, 0.0, 0.0}, .vup = {0.0, 0.0, -1.0}

/* The sphere scenes' regions: beside the emitter, and the far side. */
#define SPHERE_REGIONS                                                                        \
    .n_regions = 2,                                                                           \
    .regions = {{"nearest the emitter", 0.8, 0.3, 1.0, 0.7}, {"farthest from it", 0.0, 0.0, 0.25, 1.0}}

static const cf_scene scenes[] = {
    {
        .name = "furnace-grey",
        .summary = "inside a sphere that emits 0.4 and reflects half: every pixel 0.8",
        .lookfrom = {0.0, 0.0, 0.0},
        .lookat = {0.0, 0.0, 1.0},
        .vup = {0.0, 1.0, 0.0},
        .vfov_deg = 90.0,
        .size = 32,
        .t_min = 1e-6,
        /* The k-th segment adds 0.4 (1/2)^(k-1); the rest after D
         * segments is 0.8 2^-D, below 1e-12 from D = 40. */
        .min_depth = 40,
        .n_materials = 1,
        .materials = {{.kind = CF_DIFFUSE_EMITTER, .albedo = 0.5, .radiance = 0.4}},
        .n_shapes = 1,
        .shapes = {{.kind = CF_SPHERE, .center = {0, 0, 0}, .radius = 1.0, .inward = true}},
    },
    {
        .name = "furnace-white",
        .summary = "a white diffuse sphere under a uniform sky of 0.5: every pixel 0.5",
        .lookfrom = {0.0, 0.0, -4.0},
        .lookat = {0.0, 0.0, 0.0},
        .vup = {0.0, 1.0, 0.0},
        .vfov_deg = 40.0,
        .size = 32,
        .background = 0.5,
        .t_min = 1e-6,
        /* A ray leaving a convex surface never meets it again: camera to
         * sphere, sphere to sky. */
        .min_depth = 2,
        .n_materials = 1,
        .materials = {{.kind = CF_DIFFUSE, .albedo = 1.0}},
        .n_shapes = 1,
        .shapes = {{.kind = CF_SPHERE, .center = {0, 0, 0}, .radius = 1.0}},
    },
    {
        .name = "quad-wall",
        .summary = "a floor of albedo 0.5 under a standing quad emitter of 4: Lambert's formula",
        WALL_CAMERA,
        .vfov_deg = WALL_FOV,
        .size = 64,
        .t_min = 1e-6,
        .min_depth = 2,
        .n_materials = 2,
        .materials = {{.kind = CF_DIFFUSE, .albedo = 0.5}, {.kind = CF_EMITTER, .radiance = 4.0}},
        .n_shapes = 2,
        /* The emitter stands in the plane x = 1.05, just outside the view
         * (which ends at x = 1), from 0.02 to 0.62 above the floor, facing
         * -x ((0, 0, 1) x (0, 0.6, 0) = (-0.6, 0, 0)): the floor near
         * x = 1 sees it at grazing angles from its own plane. */
        .shapes = {WALL_FLOOR,
                   {.kind = CF_QUAD, .q = {1.05, 0.02, -0.5}, .u = {0.0, 0.0, 1.0},
                    .v = {0.0, 0.6, 0.0}, .material = 1}},
        .n_regions = 2,
        .regions = {{"within 0.2 of the emitter's plane", 0.9, 0.0, 1.0, 1.0},
                    {"farther than 1 from it", 0.0, 0.0, 0.475, 1.0}},
    },
    {
        .name = "sphere-wall",
        .summary = "a floor of albedo 0.5 under a spherical emitter of 20 beside the view",
        WALL_CAMERA,
        .vfov_deg = WALL_FOV,
        .size = 64,
        .t_min = 1e-6,
        .min_depth = 2,
        .n_materials = 2,
        .materials = {{.kind = CF_DIFFUSE, .albedo = 0.5}, {.kind = CF_EMITTER, .radiance = 20.0}},
        .n_shapes = 2,
        /* Wholly above the floor (0.5 > 0.25) and outside the view (the
         * view is 0.75 wide at its height, the sphere starts at x = 1.25). */
        .shapes = {WALL_FLOOR, {.kind = CF_SPHERE, .center = {1.5, 0.5, 0.0}, .radius = 0.25,
                                .material = 1}},
        SPHERE_REGIONS,
    },
    {
        .name = "sphere-horizon",
        .summary = "the floor under a spherical emitter of 12 that the floor's plane cuts",
        WALL_CAMERA,
        .vfov_deg = WALL_FOV,
        .size = 32,
        .t_min = 1e-6,
        .min_depth = 2,
        .n_materials = 2,
        .materials = {{.kind = CF_DIFFUSE, .albedo = 0.5}, {.kind = CF_EMITTER, .radiance = 12.0}},
        .n_shapes = 2,
        /* The centre 0.1 above the floor, the radius 0.25: the floor hides
         * the lower part of the sphere from every point it sees, more of it
         * the nearer the point. Outside the view: the view is 0.825 wide at
         * the sphere's top, the sphere starts at x = 1.1. */
        .shapes = {WALL_FLOOR, {.kind = CF_SPHERE, .center = {1.35, 0.1, 0.0}, .radius = 0.25,
                                .material = 1}},
        SPHERE_REGIONS,
    },
    {
        .name = "glass-slab",
        .summary = "an emitter of 0.9 seen through a glass slab of index 1.5 (exact Fresnel)",
        .lookfrom = {0.0, 0.0, -3.0},
        .lookat = {0.0, 0.0, 0.0},
        .vup = {0.0, 1.0, 0.0},
        .vfov_deg = 60.0,
        .size = 32,
        .t_min = 1e-6,
        /* Three segments reach the emitter straight through; each pair of
         * inner reflections adds two and a factor R^2 <= 0.06^2 at the
         * view's edge: after 13 segments less than 1e-12 is left. */
        .min_depth = 13,
        .n_materials = 2,
        .materials = {{.kind = CF_GLASS, .ior = 1.5}, {.kind = CF_EMITTER, .radiance = 0.9}},
        .n_shapes = 7,
        /* The slab: |x|, |y| <= 4, -0.25 <= z <= 0.25, six quads facing
         * out. The emitter: the plane z = 1 for |x|, |y| <= 6, facing -z
         * ((0, 12, 0) x (12, 0, 0) = (0, 0, -144)). */
        .shapes = {{.kind = CF_QUAD, .q = {-4, -4, -0.25}, .u = {0, 8, 0}, .v = {8, 0, 0}},
                   {.kind = CF_QUAD, .q = {-4, -4, 0.25}, .u = {8, 0, 0}, .v = {0, 8, 0}},
                   {.kind = CF_QUAD, .q = {-4, -4, -0.25}, .u = {0, 0, 0.5}, .v = {0, 8, 0}},
                   {.kind = CF_QUAD, .q = {4, -4, -0.25}, .u = {0, 8, 0}, .v = {0, 0, 0.5}},
                   {.kind = CF_QUAD, .q = {-4, -4, -0.25}, .u = {8, 0, 0}, .v = {0, 0, 0.5}},
                   {.kind = CF_QUAD, .q = {-4, 4, -0.25}, .u = {0, 0, 0.5}, .v = {8, 0, 0}},
                   {.kind = CF_QUAD, .q = {-6, -6, 1.0}, .u = {0, 12, 0}, .v = {12, 0, 0},
                    .material = 1}},
        .n_regions = 2,
        .regions = {{"the middle", 0.25, 0.25, 0.75, 0.75}, {"the left edge", 0.0, 0.0, 0.125, 1.0}},
    },
};

#define N_SCENES (sizeof scenes / sizeof scenes[0])

const char *const cf_scene_names[] = {"furnace-grey", "furnace-white", "quad-wall", "sphere-wall",
                                      "sphere-horizon", "glass-slab", NULL};

const cf_scene *cf_scene_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; i < N_SCENES; i++)
        if (strcmp(scenes[i].name, name) == 0)
            return &scenes[i];
    return NULL;
}

bool cf_material_emits(const cf_material *m)
{
    return (m->kind == CF_EMITTER || m->kind == CF_DIFFUSE_EMITTER) && m->radiance > 0.0;
}
