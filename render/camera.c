/* render/camera.c - the pinhole camera. */
#include "render/camera.h"

#include <math.h>

#include "mc/constants.h"

rt_camera rt_camera_make(rt_camera_params p, int width, int height)
{
    rt_camera c;
    /* The image plane at distance 1 has half-height tan(vfov / 2); the
     * basis is the book's: w back toward the viewer, u to the right, v
     * up. */
    double half_h = tan(0.5 * p.vfov_deg * (MC_PI / 180.0));
    double half_w = half_h * (double)width / (double)height;
    vec3 w = vec3_normalize(vec3_sub(p.lookfrom, p.lookat));
    vec3 u = vec3_normalize(vec3_cross(p.vup, w));
    vec3 v = vec3_cross(w, u);
    c.origin = p.lookfrom;
    c.du = vec3_scale(u, 2.0 * half_w / (double)width);
    c.dv = vec3_scale(v, -2.0 * half_h / (double)height);
    c.corner = vec3_add(vec3_sub(vec3_scale(v, half_h), vec3_scale(u, half_w)), vec3_neg(w));
    c.width = width;
    c.height = height;
    return c;
}

rt_ray rt_camera_ray(const rt_camera *c, double x, double y)
{
    vec3 d = vec3_add(c->corner, vec3_add(vec3_scale(c->du, x), vec3_scale(c->dv, y)));
    return rt_ray_make(c->origin, vec3_normalize(d));
}
