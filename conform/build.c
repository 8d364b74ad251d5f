/* conform/build.c - the renderer's scene from a conformance table. */
#include "conform/build.h"

#include "render/engine.h"
#include "render/material.h"

static vec3 grey(double x) { return vec3_make(x, x, x); }

static rt_material material(const cf_material *m)
{
    switch (m->kind) {
    case CF_DIFFUSE:
        return rt_lambertian(grey(m->albedo));
    case CF_EMITTER:
        return rt_diffuse_light(grey(m->radiance));
    case CF_DIFFUSE_EMITTER: {
        rt_material r = rt_lambertian(grey(m->albedo));
        r.emission = grey(m->radiance);
        return r;
    }
    case CF_GLASS:
    default:
        return rt_dielectric(m->ior, RT_FRESNEL_EXACT);
    }
}

rt_scene *cf_build(const cf_scene *s, rt_camera_params *cam)
{
    rt_scene *rs = rt_scene_create();
    if (!rs)
        return NULL;
    int ids[CF_MAX_MATERIALS];
    for (int i = 0; i < s->n_materials; i++)
        ids[i] = rt_scene_add_material(rs, material(&s->materials[i]));
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        rt_object o = sh->kind == CF_QUAD
                          ? rt_scene_quad(rs, sh->q, sh->u, sh->v, ids[sh->material])
                          : rt_scene_sphere(rs, sh->center, sh->radius, ids[sh->material]);
        if (sh->kind == CF_SPHERE && sh->inward)
            o = rt_scene_flip(rs, o);
        rt_scene_add(rs, o);
        if (cf_material_emits(&s->materials[sh->material]))
            rt_scene_add_light(rs, o);
    }
    rt_scene_set_t_min(rs, s->t_min);
    rt_scene_set_background(rs, grey(s->background));
    *cam = (rt_camera_params){s->lookfrom, s->lookat, s->vup, s->vfov_deg};
    if (rt_scene_build(rs) != 0) {
        rt_scene_destroy(rs);
        return NULL;
    }
    rt_scene_use_leaf_tests(rs, rt_engine_get()->leaf);
    return rs;
}
