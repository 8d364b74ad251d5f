/* conform/build.h - a conformance scene as a scene of mcbox's renderer.
 *
 * The renderer reads the same tables the exporters write
 * (conform/conform.h): Lambertian materials, one-sided emitters
 * (rt_diffuse_light, or a Lambertian one with emission for a furnace's
 * wall), glass with the exact Fresnel reflectance, quads and spheres, the
 * background; every emitter goes into the light list.
 */
#ifndef CF_BUILD_H
#define CF_BUILD_H

#include "conform/conform.h"
#include "render/camera.h"
#include "render/scene.h"

/* The scene built (rt_scene_build, with the engine's leaf tests) and its
 * camera in *cam; NULL when out of memory. */
rt_scene *cf_build(const cf_scene *s, rt_camera_params *cam);

#endif /* CF_BUILD_H */
