/* render/lights.c - the light constants, and the one-shot forms of the
 * inline densities of render/lights.h. */
#include "render/lights.h"

#include <math.h>

rt_light rt_light_make(const rt_prim *p)
{
    rt_light l = {.kind = p->kind};
    if (p->kind == RT_PRIM_QUAD) {
        l.q = p->as.quad.q;
        l.u = p->as.quad.u;
        l.v = p->as.quad.v;
        pdf_quad_constants(l.u, l.v, &l.normal, &l.w, &l.inv_area);
    } else {
        l.center = p->as.sphere.center;
        l.radius = p->as.sphere.radius;
    }
    return l;
}

vec3 rt_lights_generate(const rt_light *lights, int n, vec3 origin, rt_sampler *sampler)
{
    rt_lights_at at;
    rt_lights_prepare(&at, lights, n, origin);
    return rt_lights_at_generate(&at, sampler);
}

double rt_lights_value(const rt_light *lights, int n, vec3 origin, vec3 d)
{
    rt_lights_at at;
    rt_lights_prepare(&at, lights, n, origin);
    return rt_lights_at_value(&at, d);
}

