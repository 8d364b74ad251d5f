/* render/scenes.h - the scenes of the Cornell box program and its tests.
 *
 * "book" is the final scene of Shirley's "Ray Tracing: The Rest of Your
 * Life" (v1.123, chapter 10), with the values of cornell_box() in main.cc
 * of release v1.123.0: the room of
 * five quads, the light (213, 554, 227) + (130, 0, 0) + (0, 0, 105) of
 * radiance 15 facing down, a white box 165 x 330 x 165 turned 15 degrees
 * and moved to (265, 0, 295), a glass sphere (index 1.5) of radius 90 at
 * (190, 90, 190); the light list holds the light quad and the sphere.
 * "book-metal" makes the tall box aluminium (metal (0.8, 0.85, 0.88),
 * fuzz 0) as v1.123's chapter 10 describes. "lambert" is v1.123's chapter 4 room
 * with the classic two white boxes, all Lambertian; its light list is the
 * light quad. "furnace" and "sphere-light" are test scenes with analytic
 * answers (see their builders below).
 */
#ifndef RT_SCENES_H
#define RT_SCENES_H

#include "render/camera.h"
#include "render/material.h"
#include "render/scene.h"

/* Names accepted by rt_scene_named, NULL-terminated. */
extern const char *const rt_scene_names[];

/* Builds the named scene and sets *cam to its camera. NULL for an unknown
 * name or when out of memory. The result is built (rt_scene_build), with
 * the engine's leaf tests (render/engine.h), as is every built scene this
 * header returns. */
rt_scene *rt_scene_named(const char *name, rt_camera_params *cam);

/* The Cornell room: the five walls, the light and its light-list entry,
 * the camera from (278, 278, -800) at (278, 278, 0), up +y, 40 degrees.
 * Returns the material id of white, or -1. */
int rt_scene_cornell_room(rt_scene *s, rt_camera_params *cam);

/* The white furnace: the inside of the sphere of radius 1 about the
 * origin, which emits radiance `emission` and reflects diffusely with
 * albedo rho (0 <= rho < 1), camera at the centre looking along +z with a
 * 90 degree field of view. The sphere is also the light. Every ray sees
 * E + rho E + rho^2 E + ... = E / (1 - rho). The named scene has E = 0.5,
 * rho = 0.5. */
rt_scene *rt_scene_furnace(double emission, double rho, rt_camera_params *cam);

/* The named "furnace" scene's emission and albedo. */
#define RT_FURNACE_EMISSION 0.5
#define RT_FURNACE_RHO 0.5

/* The radiance every pixel of the furnace sees when a path has at most
 * max_depth segments (max_depth >= 1): the first max_depth terms of the
 * series above, E (1 - rho^max_depth) / (1 - rho). */
double rt_scene_furnace_radiance(double emission, double rho, int max_depth);

/* A Lambertian square of albedo rho in the plane y = 0 (corners at +-half
 * in x and z), lit by one sphere of radius r centred at (0, h, 0), h > r,
 * emitting radiance Phi / (4 pi^2 r^2) so that its flux is Phi; the sphere
 * is the light. The irradiance at (x, 0, z) is that of a point source,
 * Phi cos(theta) / (4 pi d^2) with d the distance to the centre and
 * cos(theta) = h / d, because the sphere is wholly above the plane; the
 * square reflects rho E / pi. The named scene has Phi = 4e5, r = 20,
 * h = 100, half = 400, rho = 0.8, seen from (0, 500, -700). */
rt_scene *rt_scene_sphere_light(double phi, double r, double h, double half, double rho,
                                rt_camera_params *cam);

#endif /* RT_SCENES_H */
