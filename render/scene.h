/* render/scene.h - scenes: a tree of shapes, lists and instances, the
 * materials, the lights, and the closest-hit query.
 *
 * The Cornell box of "Ray Tracing: The Rest of Your Life" (chapters 4-10)
 * is built the book's way: quads, a sphere, boxes made of six quads, and
 * boxes moved by rotate-about-y and translate instances; the lights that
 * the mixture density aims at are a separate list (v1.123's chapter 10;
 * this book's #ch-cornell).
 *
 * Instances. The book intersects an instance by moving every ray into the
 * child's frame and the hit back out. A rigid motion maps a parallelogram
 * to a parallelogram and a sphere to a sphere, so rt_scene_build instead
 * applies each instance's composed transform to the shapes once
 * ("flattening") and builds the BVH over the resulting world-space
 * primitives. The book's per-ray evaluation is kept as rt_scene_hit_tree,
 * the reference the tests compare the flattened BVH against.
 *
 * Ownership: the scene owns everything created through it
 * (rt_scene_create / rt_scene_destroy). Errors (out of memory, an invalid
 * handle) are sticky: the constructors return -1 and rt_scene_build fails.
 */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>

#include "mc/vec3.h"
#include "pdf/pdf.h"
#include "render/bvh.h"
#include "render/leaf4.h"
#include "render/lights.h"
#include "render/material.h"
#include "render/ray.h"

/* A handle to a node of the scene's object tree; -1 is "none/invalid". */
typedef int rt_object;

/* Most lights a scene may have (the pdf list is built on the stack). */
#define RT_MAX_LIGHTS 16

typedef struct rt_scene rt_scene;

/* An empty scene: no objects, black background, t_min 1e-3. NULL when out
 * of memory. */
rt_scene *rt_scene_create(void);

/* Frees the scene and everything in it; NULL is a no-op. */
void rt_scene_destroy(rt_scene *s);

/* Adds a material; returns its id (>= 0) or -1. */
int rt_scene_add_material(rt_scene *s, rt_material m);

/* A sphere (radius > 0) / the quad q + a u + b v, (a, b) in [0, 1]^2
 * (front face toward u x v), with the given material id. */
rt_object rt_scene_sphere(rt_scene *s, vec3 center, double radius, int material);
rt_object rt_scene_quad(rt_scene *s, vec3 q, vec3 u, vec3 v, int material);

/* A list of n >= 1 objects (the array is copied). */
rt_object rt_scene_list(rt_scene *s, const rt_object *items, int n);

/* The box [a, b] (componentwise a < b) as a list of six quads with
 * outward front faces. */
rt_object rt_scene_box(rt_scene *s, vec3 a, vec3 b, int material);

/* Instances: the child moved by offset; rotated by `degrees` about the y
 * axis (right-handed: +90 takes +x to -z); with its faces flipped (front
 * becomes back; for a sphere seen from inside). */
rt_object rt_scene_translate(rt_scene *s, rt_object child, vec3 offset);
rt_object rt_scene_rotate_y(rt_scene *s, rt_object child, double degrees);
rt_object rt_scene_flip(rt_scene *s, rt_object child);

/* Puts an object in the world (what rays hit). */
void rt_scene_add(rt_scene *s, rt_object o);

/* Puts an object in the light list (what the light pdfs aim at). It must
 * flatten to a single quad or sphere; at most RT_MAX_LIGHTS. Being in the
 * list does not put it in the world. */
void rt_scene_add_light(rt_scene *s, rt_object o);

/* The shadow-acne offset: hits closer than t_min are ignored (the book's
 * 0.001 for its 555-unit room). */
void rt_scene_set_t_min(rt_scene *s, double t_min);

/* Radiance of rays that leave the scene (the book's black background). */
void rt_scene_set_background(rt_scene *s, vec3 radiance);

/* Flattens the world, builds the BVH and the lights. Returns 0, or -1 on
 * any earlier or present error (out of memory, invalid handle or material,
 * a light that is not one quad or sphere, an empty world). Call once,
 * after every object was added and before any query. */
int rt_scene_build(rt_scene *s);

/* The four-wide tests of the root leaf (render/leaf4.h) that the queries
 * below use from now on; a built scene starts with none (the BVH alone,
 * the reference), and the engine's (render/engine.h) give the same bits
 * sooner. render/scenes.c gives its scenes the engine's. Call after a
 * successful build, before any query runs. */
void rt_scene_use_leaf_tests(rt_scene *s, rt_leaf_tests t);

/* The closest hit of r with t in (t_min, tmax), through the BVH: for a
 * root leaf, the scene's one-ray test if it has one (rt_leaf_lanes_hit1),
 * the same bits as the reference. */
bool rt_scene_hit(const rt_scene *s, rt_ray r, double tmax, rt_hit *h);

/* rt_scene_hit for RT_LANES rays at once, through rt_leaf_lanes_hit and
 * the scene's four-ray test if it has one: bit k of the result says
 * whether r[k] hit, and then h[k] is its record. */
unsigned rt_scene_hit4(const rt_scene *s, const rt_ray r[RT_LANES], double tmax,
                       rt_hit h[RT_LANES]);

/* Whether each of RT_LANES shadow rays r[k] meets anything with t in
 * (t_min, tmax[k]): bit k of the result, through rt_leaf_lanes_occluded
 * and the scene's shadow-ray test if it has one; the same answers as
 * rt_scene_hit4 out to the largest tmax[k], compared lane by lane. */
unsigned rt_scene_occluded4(const rt_scene *s, const rt_ray r[RT_LANES],
                            const double tmax[RT_LANES]);

/* The same by testing every flattened primitive (reference). */
bool rt_scene_hit_brute(const rt_scene *s, rt_ray r, double tmax, rt_hit *h);

/* The same through the object tree, instances moving the ray as in the
 * book (reference; h->prim is -1). */
bool rt_scene_hit_tree(const rt_scene *s, rt_ray r, double tmax, rt_hit *h);

/* The material with id m (valid after a successful build). */
const rt_material *rt_scene_material(const rt_scene *s, int m);

/* Number of lights in the light list. */
int rt_scene_light_count(const rt_scene *s);

/* The chapter-10 list pdf over the lights seen from `origin`: items[i] is
 * the pdf toward light i (pdf_toward_quad or pdf_toward_sphere) and
 * ptrs[i] = &items[i]; both arrays need rt_scene_light_count entries and
 * must outlive the returned pdf. The scene must have at least one light. */
pdf rt_scene_lights_pdf(const rt_scene *s, vec3 origin, pdf *items, const pdf **ptrs);

/* The lights with their precomputed constants (rt_scene_light_count of
 * them), for the fast densities of render/lights.h. */
const rt_light *rt_scene_lights(const rt_scene *s);

/* The emitters: the entries of the light list whose material emits
 * (nonzero emission), in light-list order, as primitives and with the
 * constants of render/lights.h. Next-event estimation aims its shadow rays
 * at these only (a shadow ray toward the book's glass sphere, which is in
 * the light list for the mixture's sake, brings back nothing), and light
 * paths start on them. */
int rt_scene_emitter_count(const rt_scene *s);
const rt_prim *rt_scene_emitter_prims(const rt_scene *s);
const rt_light *rt_scene_emitters(const rt_scene *s);

/* The other entries of the light list, those that do not emit (the
 * book's glass sphere), in light-list order with the constants of
 * render/lights.h: what bidirectional light subpaths may aim their first
 * direction at (rt_path_settings.emit_aim), since light through them is
 * what only a light subpath finds. */
int rt_scene_target_count(const rt_scene *s);
const rt_light *rt_scene_targets(const rt_scene *s);

/* rt_scene_lights_pdf over the emitters only (at least one). */
pdf rt_scene_emitters_pdf(const rt_scene *s, vec3 origin, pdf *items, const pdf **ptrs);

/* t_min and background as set. */
double rt_scene_t_min(const rt_scene *s);
vec3 rt_scene_background(const rt_scene *s);

/* The flattened primitives and the BVH over them (after build). */
int rt_scene_prim_count(const rt_scene *s);
const rt_prim *rt_scene_prims(const rt_scene *s);
const rt_bvh *rt_scene_bvh(const rt_scene *s);

/* The root leaf laid out in lanes (render/leaf4.h), NULL when the root is
 * not a leaf. */
const rt_leaf_lanes *rt_scene_leaf_lanes(const rt_scene *s);

#endif /* RT_SCENE_H */
