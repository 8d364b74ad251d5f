/* conform/conform.h - the conformance scenes: small scenes whose every
 * pixel is known exactly, defined once, for any renderer to be judged by.
 *
 * A scene is data: a pinhole camera, grey materials, quads and spheres, a
 * background radiance. mcbox's renderer builds its scenes from these
 * tables (render/scenes.h), the exporters write them as pbrt-v4, Mitsuba 3,
 * Blender and plain-table files (conform/export.h), and the truth of every
 * pixel comes from the same tables (conform/truth.h). Every scene is grey
 * (the three channels equal) and every pixel's value lies in [0, 1), so
 * that an 8-bit output need not clamp.
 *
 * Conventions every exporter pins (conform/export.h says how per format):
 * - Right-handed world; the camera looks from `lookfrom` at `lookat`,
 *   `vup` is the image's up; the field of view is vertical, and the images
 *   are square, so it is the horizontal one too.
 * - A pixel's value is the mean of the radiance over the pixel's square
 *   (a box filter one pixel wide): pixel (i, j) covers [i, i + 1) x
 *   [j, j + 1) of the image plane in pixel units, rows from the top.
 * - Radiance in W/(m^2 sr) with no exposure or tone curve: the linear value
 *   is the pixel.
 * - Emitters are one-sided: they emit from their front face only, with the
 *   same radiance in every direction (a Lambertian emitter). A quad
 *   q + a u + b v, (a, b) in [0, 1]^2, faces toward u x v; a sphere's front
 *   face is its outside unless it is `inward`.
 * - Diffuse surfaces are Lambertian (BRDF albedo / pi) on both faces.
 * - Glass is a smooth dielectric with the exact unpolarized Fresnel
 *   reflectance (not Schlick's approximation) and no absorption.
 */
#ifndef CF_CONFORM_H
#define CF_CONFORM_H

#include <stdbool.h>

#include "mc/vec3.h"

typedef enum cf_material_kind {
    CF_DIFFUSE, /* Lambertian reflector of `albedo` */
    CF_EMITTER, /* emits `radiance` from the front face, reflects nothing */
    CF_DIFFUSE_EMITTER, /* both: emits `radiance`, reflects with `albedo` */
    CF_GLASS    /* smooth dielectric of index `ior` (outside: 1) */
} cf_material_kind;

typedef struct cf_material {
    cf_material_kind kind;
    double albedo;   /* CF_DIFFUSE, CF_DIFFUSE_EMITTER: in [0, 1] */
    double radiance; /* CF_EMITTER, CF_DIFFUSE_EMITTER: >= 0 */
    double ior;      /* CF_GLASS: > 1 */
} cf_material;

typedef enum cf_shape_kind { CF_QUAD, CF_SPHERE } cf_shape_kind;

typedef struct cf_shape {
    cf_shape_kind kind;
    vec3 q, u, v;  /* CF_QUAD: the parallelogram q + a u + b v, front toward u x v */
    vec3 center;   /* CF_SPHERE */
    double radius; /* CF_SPHERE, > 0 */
    bool inward;   /* CF_SPHERE: the front face is the inside (a furnace's wall) */
    int material;  /* index into the scene's materials */
} cf_shape;

/* A named part of the image, in fractions of its width and height:
 * [x0, x1) x [y0, y1), rows from the top. The image check reports the
 * bias over each region (conform/truth.h says why each is there). */
typedef struct cf_region {
    const char *name;
    double x0, y0, x1, y1;
} cf_region;

/* How close to the truth a renderer at min_depth segments comes: the
 * part of the truth's error bound that is not quadrature. */
#define CF_DEPTH_PROMISE 1e-12

#define CF_MAX_SHAPES 8
#define CF_MAX_MATERIALS 4
#define CF_MAX_REGIONS 4

typedef struct cf_scene {
    const char *name;    /* what --scene takes */
    const char *summary; /* one line */
    vec3 lookfrom, lookat, vup;
    double vfov_deg;     /* vertical field of view, degrees */
    int size;            /* suggested width = height in pixels */
    double background;   /* radiance of rays that leave the scene */
    double t_min;        /* a renderer's self-intersection offset that suits the scale */
    /* The truth is the limit of infinitely long paths; a renderer that
     * stops at max_depth segments is within CF_DEPTH_PROMISE of it for
     * max_depth >= min_depth. */
    int min_depth;
    int n_materials, n_shapes, n_regions;
    cf_material materials[CF_MAX_MATERIALS];
    cf_shape shapes[CF_MAX_SHAPES];
    cf_region regions[CF_MAX_REGIONS];
} cf_scene;

/* The scene names, NULL-terminated, in a fixed order. */
extern const char *const cf_scene_names[];

/* The scene of that name, or NULL. */
const cf_scene *cf_scene_find(const char *name);

/* True when the material emits (CF_EMITTER, CF_DIFFUSE_EMITTER with
 * radiance > 0): what a renderer puts in its light list. */
bool cf_material_emits(const cf_material *m);

#endif /* CF_CONFORM_H */
