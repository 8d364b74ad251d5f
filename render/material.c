/* render/material.c - Lambert, metal, glass and light; Snell and Fresnel. */
#include "render/material.h"

#include <math.h>

#include "mc/constants.h"
#include "samplers/sphere.h"

rt_material rt_lambertian(vec3 albedo)
{
    rt_material m = {.kind = RT_MAT_LAMBERT, .albedo = albedo};
    return m;
}

rt_material rt_metal(vec3 albedo, double fuzz)
{
    rt_material m = {.kind = RT_MAT_METAL, .albedo = albedo, .fuzz = fuzz < 1.0 ? fuzz : 1.0};
    return m;
}

static double schlick_r0(double n1, double n2);

rt_material rt_dielectric(double ior, rt_fresnel fresnel)
{
    rt_material m = {.kind = RT_MAT_DIELECTRIC, .albedo = vec3_make(1.0, 1.0, 1.0), .ior = ior,
                     .fresnel = fresnel, .inv_ior = 1.0 / ior, .schlick_r0 = schlick_r0(1.0, ior)};
    return m;
}

rt_material rt_diffuse_light(vec3 emission)
{
    rt_material m = {.kind = RT_MAT_LIGHT, .emission = emission};
    return m;
}

vec3 rt_reflect(vec3 d, vec3 n) { return vec3_madd(d, n, -2.0 * vec3_dot(d, n)); }

/* BEGIN SNIPPET refract */
bool rt_refract(vec3 d, vec3 n, double eta, vec3 *out)
{
    double cos_i = -vec3_dot(d, n);
    /* fmin(cos_i, 1) without the libm call that -O2 makes of fmin: the
     * same result for every input (NaN gives 1 both ways). */
    cos_i = cos_i < 1.0 ? cos_i : 1.0;
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0)
        return false;
    /* The tangential part scales by eta (Snell), the normal part is what
     * is left of a unit vector (Pythagoras). */
    vec3 perp = vec3_scale(vec3_madd(d, n, cos_i), eta);
    *out = vec3_madd(perp, n, -sqrt(1.0 - sin2_t));
    return true;
}
/* END SNIPPET refract */

/* cos theta_t from cos theta_i by Snell's law with eta = n1 / n2; -1
 * under total internal reflection. */
static double transmitted_cos_eta(double cos_i, double eta)
{
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    return sin2_t >= 1.0 ? -1.0 : sqrt(1.0 - sin2_t);
}

static double transmitted_cos(double cos_i, double n1, double n2)
{
    return transmitted_cos_eta(cos_i, n1 / n2);
}

/* BEGIN SNIPPET fresnel_exact */
double rt_fresnel_exact(double cos_i, double n1, double n2)
{
    double cos_t = transmitted_cos(cos_i, n1, n2);
    if (cos_t < 0.0)
        return 1.0;
    /* Continuity of the tangential fields at the boundary, for the two
     * polarizations (s: E perpendicular to the plane of incidence). */
    double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    double rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
    return 0.5 * (rs * rs + rp * rp);
}
/* END SNIPPET fresnel_exact */

/* BEGIN SNIPPET fresnel_schlick */
static double schlick(double r0, double c)
{
    double m = 1.0 - c;
    double m2 = m * m;
    return r0 + (1.0 - r0) * m2 * m2 * m;
}

/* ((n1 - n2) / (n1 + n2))^2: Schlick's reflectance at normal incidence. */
static double schlick_r0(double n1, double n2)
{
    double r0 = (n1 - n2) / (n1 + n2);
    return r0 * r0;
}

/* rt_fresnel_schlick with r0, eta = n1 / n2 and whether the incident side
 * is the rarer one (n1 <= n2) given. */
static double fresnel_schlick_given(double cos_i, double r0, double eta, bool rarer_incident)
{
    if (rarer_incident)
        return schlick(r0, cos_i);
    double cos_t = transmitted_cos_eta(cos_i, eta);
    return cos_t < 0.0 ? 1.0 : schlick(r0, cos_t);
}

double rt_fresnel_schlick(double cos_i, double n1, double n2)
{
    return fresnel_schlick_given(cos_i, schlick_r0(n1, n2), n1 / n2, n1 <= n2);
}

double rt_fresnel_schlick_book(double cos_i, double n1, double n2)
{
    return transmitted_cos(cos_i, n1, n2) < 0.0 ? 1.0 : schlick(schlick_r0(n1, n2), cos_i);
}
/* END SNIPPET fresnel_schlick */

/* Glass: reflect with the probability of the Fresnel reflectance, refract
 * otherwise. Choosing by that probability makes the weight of either
 * branch exactly 1 (R / R and T / T).
 *
 * sin^2 theta_t and cos theta_t = sqrt(1 - sin^2 theta_t) are computed
 * once, by the expressions of transmitted_cos_eta and rt_refract (the
 * same operands in the same order, eta the same n1 / n2 bits), and shared
 * by the reflectance (Schlick from the denser side needs cos theta_t) and
 * the refracted direction: one square root a hit instead of two inside
 * the glass, and the same numbers, so the same uniforms are drawn and the
 * same direction comes out. sin^2 theta_t >= 1 is total internal
 * reflection (transmitted_cos_eta's test); the exactly grazing 1 refracts
 * along the surface in rt_refract (cos theta_t = sqrt(0) = 0), hence the
 * 0 there. */
/* BEGIN SNIPPET scatter_glass */
/* What both branches at a glass hit need: the incident direction and
 * normal, d . n, cos theta_i, eta, sin^2 theta_t, cos theta_t, and the
 * reflectance r. */
typedef struct glass_hit {
    vec3 d, n;
    double d_n, cos_i, eta, sin2_t, cos_t, r;
} glass_hit;

static glass_hit glass_at(const rt_material *m, const rt_ray *in, const rt_hit *h)
{
    glass_hit g;
    double n1 = h->front_face ? 1.0 : m->ior, n2 = h->front_face ? m->ior : 1.0;
    g.eta = h->front_face ? m->inv_ior : m->ior; /* n1 / n2 exactly (ior / 1 = ior) */
    g.d = in->dir;
    g.n = h->normal;
    g.d_n = vec3_dot(g.d, g.n);
    g.cos_i = -g.d_n;
    g.cos_i = g.cos_i < 1.0 ? g.cos_i : 1.0; /* fmin, as in rt_refract */
    g.sin2_t = g.eta * g.eta * (1.0 - g.cos_i * g.cos_i);
    g.cos_t = g.sin2_t >= 1.0 ? 0.0 : sqrt(1.0 - g.sin2_t);
    if (m->fresnel == RT_FRESNEL_EXACT)
        g.r = rt_fresnel_exact(g.cos_i, n1, n2);
    else if (n1 <= n2)
        g.r = schlick(m->schlick_r0, g.cos_i);
    else
        g.r = g.sin2_t >= 1.0 ? 1.0 : schlick(m->schlick_r0, g.cos_t);
    return g;
}

/* The reflected or the refracted ray of a glass hit at p. */
static rt_ray glass_ray(const glass_hit *g, vec3 p, bool reflect)
{
    vec3 dir;
    if (reflect)
        dir = vec3_madd(g->d, g->n, -2.0 * g->d_n); /* rt_reflect */
    else /* rt_refract: Snell for the tangential part, Pythagoras for the normal one */
        dir = vec3_madd(vec3_scale(vec3_madd(g->d, g->n, g->cos_i), g->eta), g->n, -g->cos_t);
    /* Both directions are unit but for rounding, |dir|^2 = 1 + e with e of
     * a few ulps: one Newton step for 1 / |dir|, x (3 - |x|^2) / 2, leaves
     * |dir|^2 = 1 - 3e^2/4 + rounding, as unit as a division by the square
     * root would, without a square root and a division in the chain of a
     * path that is inside glass every few segments. */
    return rt_ray_make(p, vec3_scale(dir, 1.5 - 0.5 * vec3_length_sq(dir)));
}

/* Total internal reflection (sin^2 theta_t > 1) or a reflectance of 1
 * leaves only the reflected branch. */
static bool glass_reflects_only(const glass_hit *g) { return g->r >= 1.0 || g->sin2_t > 1.0; }

static void scatter_glass(const rt_material *m, const rt_ray *in, const rt_hit *h,
                          rt_sampler *sampler, rt_scatter *s)
{
    glass_hit g = glass_at(m, in, h);
    bool reflect = g.r >= 1.0 || rt_sampler_1d(sampler) < g.r || g.sin2_t > 1.0;
    s->specular = true;
    s->attenuation = m->albedo;
    s->ray = glass_ray(&g, h->p, reflect);
}
/* END SNIPPET scatter_glass */

double rt_glass_branches(const rt_material *m, const rt_ray *in, const rt_hit *h, rt_ray *reflected,
                         rt_ray *refracted)
{
    glass_hit g = glass_at(m, in, h);
    *reflected = glass_ray(&g, h->p, true);
    if (glass_reflects_only(&g))
        return 1.0;
    *refracted = glass_ray(&g, h->p, false);
    return g.r;
}

bool rt_material_scatter_specular(const rt_material *m, const rt_ray *in, const rt_hit *h,
                                  rt_sampler *sampler, rt_scatter *s)
{
    if (m->kind == RT_MAT_DIELECTRIC) {
        scatter_glass(m, in, h, sampler, s);
        return true;
    }
    if (m->kind != RT_MAT_METAL)
        return rt_material_scatter(m, in, h, sampler, s); /* light, Lambert */
    vec3 dir = rt_reflect(in->dir, h->normal);
    if (m->fuzz > 0.0) {
        double u1, u2;
        rt_sampler_2d(sampler, &u1, &u2);
        dir = vec3_add(dir, vec3_scale(smp_uniform_sphere_sample(u1, u2), m->fuzz));
        /* Fuzz may push the ray under the surface: absorbed, as in the
         * first book. */
        if (!(vec3_dot(dir, h->normal) > 0.0))
            return false;
    }
    s->specular = true;
    s->attenuation = m->albedo;
    s->ray = rt_ray_make(h->p, vec3_normalize(dir));
    return true;
}
