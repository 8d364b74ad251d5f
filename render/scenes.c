/* render/scenes.c - Cornell box variants and the analytic test scenes. */
#include "render/scenes.h"

#include <math.h>

#include "mc/constants.h"
#include "render/engine.h"
#include "render/names.h"

/* The scenes of rt_scene_named, each bound to its name here. */
enum { SCENE_BOOK, SCENE_BOOK_METAL, SCENE_LAMBERT, SCENE_FURNACE, SCENE_SPHERE_LIGHT, SCENE_COUNT };

const char *const rt_scene_names[] = {
    [SCENE_BOOK] = "book",       [SCENE_BOOK_METAL] = "book-metal",     [SCENE_LAMBERT] = "lambert",
    [SCENE_FURNACE] = "furnace", [SCENE_SPHERE_LIGHT] = "sphere-light", [SCENE_COUNT] = NULL,
};

static vec3 v3(double x, double y, double z) { return vec3_make(x, y, z); }

/* s built, with the engine's leaf tests (the same bits as none, sooner);
 * NULL, and s freed, when the build fails. */
static rt_scene *built(rt_scene *s)
{
    if (rt_scene_build(s) != 0) {
        rt_scene_destroy(s);
        return NULL;
    }
    rt_scene_use_leaf_tests(s, rt_engine_get()->leaf);
    return s;
}

/* BEGIN SNIPPET cornell_room */
int rt_scene_cornell_room(rt_scene *s, rt_camera_params *cam)
{
    int red = rt_scene_add_material(s, rt_lambertian(v3(0.65, 0.05, 0.05)));
    int white = rt_scene_add_material(s, rt_lambertian(v3(0.73, 0.73, 0.73)));
    int green = rt_scene_add_material(s, rt_lambertian(v3(0.12, 0.45, 0.15)));
    int light = rt_scene_add_material(s, rt_diffuse_light(v3(15.0, 15.0, 15.0)));
    rt_scene_add(s, rt_scene_quad(s, v3(555, 0, 0), v3(0, 0, 555), v3(0, 555, 0), green));
    rt_scene_add(s, rt_scene_quad(s, v3(0, 0, 555), v3(0, 0, -555), v3(0, 555, 0), red));
    rt_scene_add(s, rt_scene_quad(s, v3(0, 555, 0), v3(555, 0, 0), v3(0, 0, 555), white));
    rt_scene_add(s, rt_scene_quad(s, v3(0, 0, 555), v3(555, 0, 0), v3(0, 0, -555), white));
    rt_scene_add(s, rt_scene_quad(s, v3(555, 0, 555), v3(-555, 0, 0), v3(0, 555, 0), white));
    /* (130, 0, 0) x (0, 0, 105) points to -y: the light faces down. */
    rt_object lamp = rt_scene_quad(s, v3(213, 554, 227), v3(130, 0, 0), v3(0, 0, 105), light);
    rt_scene_add(s, lamp);
    rt_scene_add_light(s, lamp);
    cam->lookfrom = v3(278, 278, -800);
    cam->lookat = v3(278, 278, 0);
    cam->vup = v3(0, 1, 0);
    cam->vfov_deg = 40.0;
    return white;
}
/* END SNIPPET cornell_room */

/* A box [0, size] turned about y, then moved. */
static rt_object placed_box(rt_scene *s, vec3 size, double degrees, vec3 offset, int material)
{
    rt_object box = rt_scene_box(s, v3(0, 0, 0), size, material);
    return rt_scene_translate(s, rt_scene_rotate_y(s, box, degrees), offset);
}

/* BEGIN SNIPPET cornell_book_scene */
static rt_scene *cornell(bool metal, bool lambert, rt_camera_params *cam)
{
    rt_scene *s = rt_scene_create();
    if (!s)
        return NULL;
    int white = rt_scene_cornell_room(s, cam);
    int tall = metal ? rt_scene_add_material(s, rt_metal(v3(0.8, 0.85, 0.88), 0.0)) : white;
    rt_scene_add(s, placed_box(s, v3(165, 330, 165), 15.0, v3(265, 0, 295), tall));
    if (lambert) {
        rt_scene_add(s, placed_box(s, v3(165, 165, 165), -18.0, v3(130, 0, 65), white));
    } else {
        int glass = rt_scene_add_material(s, rt_dielectric(1.5, RT_FRESNEL_SCHLICK));
        rt_object ball = rt_scene_sphere(s, v3(190, 90, 190), 90.0, glass);
        rt_scene_add(s, ball);
        rt_scene_add_light(s, ball);
    }
    return built(s);
}
/* END SNIPPET cornell_book_scene */

double rt_scene_furnace_radiance(double emission, double rho, int max_depth)
{
    /* Segment k (k = 1 .. max_depth) ends on the sphere and adds rho^(k-1) E. */
    return emission * (1.0 - pow(rho, (double)max_depth)) / (1.0 - rho);
}

/* BEGIN SNIPPET furnace_scene */
rt_scene *rt_scene_furnace(double emission, double rho, rt_camera_params *cam)
{
    rt_scene *s = rt_scene_create();
    if (!s)
        return NULL;
    rt_material m = rt_lambertian(v3(rho, rho, rho));
    m.emission = v3(emission, emission, emission);
    int mat = rt_scene_add_material(s, m);
    /* Flipped: the inside is the front face, which emits. */
    rt_object ball = rt_scene_flip(s, rt_scene_sphere(s, v3(0, 0, 0), 1.0, mat));
    rt_scene_add(s, ball);
    rt_scene_add_light(s, ball);
    /* The room is 555 times smaller than the book's: so is the offset. */
    rt_scene_set_t_min(s, 1e-6);
    cam->lookfrom = v3(0, 0, 0);
    cam->lookat = v3(0, 0, 1);
    cam->vup = v3(0, 1, 0);
    cam->vfov_deg = 90.0;
    return built(s);
}
/* END SNIPPET furnace_scene */

rt_scene *rt_scene_sphere_light(double phi, double r, double h, double half, double rho,
                                rt_camera_params *cam)
{
    rt_scene *s = rt_scene_create();
    if (!s)
        return NULL;
    /* BEGIN SNIPPET sphere_light_scene */
    /* Flux of a sphere of uniform radiance L: each point emits pi L per
     * unit area (the cosine integrated over the hemisphere), so
     * Phi = 4 pi r^2 pi L. */
    double radiance = phi / (4.0 * MC_PI * MC_PI * r * r);
    int floor_mat = rt_scene_add_material(s, rt_lambertian(v3(rho, rho, rho)));
    int lamp_mat = rt_scene_add_material(s, rt_diffuse_light(v3(radiance, radiance, radiance)));
    /* (0, 0, 2 half) x (2 half, 0, 0) points to +y: the front faces up. */
    rt_scene_add(s, rt_scene_quad(s, v3(-half, 0, -half), v3(0, 0, 2 * half), v3(2 * half, 0, 0),
                                  floor_mat));
    rt_object lamp = rt_scene_sphere(s, v3(0, h, 0), r, lamp_mat);
    rt_scene_add(s, lamp);
    rt_scene_add_light(s, lamp);
    /* END SNIPPET sphere_light_scene */
    cam->lookfrom = v3(0, 500, -700);
    cam->lookat = v3(0, 0, 0);
    cam->vup = v3(0, 1, 0);
    cam->vfov_deg = 60.0;
    return built(s);
}

rt_scene *rt_scene_named(const char *name, rt_camera_params *cam)
{
    switch (rt_name_index(rt_scene_names, name)) {
    case SCENE_BOOK:
        return cornell(false, false, cam);
    case SCENE_BOOK_METAL:
        return cornell(true, false, cam);
    case SCENE_LAMBERT:
        return cornell(false, true, cam);
    case SCENE_FURNACE:
        return rt_scene_furnace(RT_FURNACE_EMISSION, RT_FURNACE_RHO, cam);
    case SCENE_SPHERE_LIGHT:
        return rt_scene_sphere_light(4e5, 20.0, 100.0, 400.0, 0.8, cam);
    default:
        return NULL;
    }
}
