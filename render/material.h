/* render/material.h - what happens where a ray meets a surface: emission,
 * and scattering described by a scatter record.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123) [@shirley-rotl], chapter 10
 * ("Cleaning Up pdf Management"): a material either scatters diffusely,
 * handing the integrator the pdf object of its scattering density (its
 * chapter 3: the Lambertian scattering pdf is cos(theta) / pi), or
 * specularly, handing it a single ray with the specular flag set (metal and
 * glass, whose delta densities are never evaluated). Emission is the
 * diffuse light of its chapter 7, which shines from its front face only.
 * Refraction, total internal reflection, Schlick's approximation and the
 * exact Fresnel equations follow the project's source notes on path-tracing
 * mathematics (this book's #ch-cornell).
 */
#ifndef RT_MATERIAL_H
#define RT_MATERIAL_H

#include <stdbool.h>

#include "mc/constants.h"
#include "render/sampler.h"
#include "mc/vec3.h"
#include "pdf/pdf.h"
#include "render/ray.h"

typedef enum rt_material_kind {
    RT_MAT_LIGHT,     /* emits, never scatters */
    RT_MAT_LAMBERT,   /* ideal diffuse: BRDF albedo / pi */
    RT_MAT_METAL,     /* mirror plus a fuzz sphere */
    RT_MAT_DIELECTRIC /* glass: reflect or refract by the Fresnel reflectance */
} rt_material_kind;

typedef enum rt_fresnel {
    RT_FRESNEL_SCHLICK, /* R0 + (1 - R0)(1 - cos)^5, cos on the rarer side */
    RT_FRESNEL_EXACT    /* unpolarized (R_s + R_p) / 2 */
} rt_fresnel;

typedef struct rt_material {
    rt_material_kind kind;
    vec3 albedo;        /* Lambert and metal reflectance per channel, in [0, 1] */
    vec3 emission;      /* radiance emitted from the front face (any kind) */
    double fuzz;        /* metal: radius of the perturbing sphere, in [0, 1] */
    double ior;         /* dielectric: index of refraction inside / outside */
    rt_fresnel fresnel; /* dielectric: which reflectance */
    /* Dielectric, set by rt_dielectric (glass is hit at every other
     * segment in the book's scene; these save two divisions a hit):
     * 1 / ior, and Schlick's R0 = ((ior - 1) / (ior + 1))^2, the same
     * number from either side since n1 - n2 = -(n2 - n1) exactly. */
    double inv_ior, schlick_r0;
} rt_material;

/* Ideal diffuse reflector of the given albedo. */
rt_material rt_lambertian(vec3 albedo);
/* Metal: mirror direction plus fuzz times a uniform unit vector. */
rt_material rt_metal(vec3 albedo, double fuzz);
/* Clear dielectric of index ior (> 0) with the chosen reflectance. */
rt_material rt_dielectric(double ior, rt_fresnel fresnel);
/* The diffuse light of v1.123's chapter 7: radiance `emission` from the
 * front face. */
rt_material rt_diffuse_light(vec3 emission);

/* The scatter record. For a diffuse event the material's scattering
 * density is the cosine pdf about `normal` (rt_scatter_pdf builds it as a
 * pdf object); for a specular one, `ray` is the scattered ray and the
 * estimator is simply attenuation times what comes back along it. */
/* BEGIN SNIPPET scatter_record */
typedef struct rt_scatter {
    bool specular;
    vec3 attenuation; /* albedo (diffuse) or the specular colour */
    rt_ray ray;       /* specular only */
    vec3 normal;      /* diffuse only: the unit normal facing the incoming ray */
} rt_scatter;

/* The scattering density of a diffuse record as a pdf object:
 * pdf_cosine(s->normal), per unit solid angle. */
static inline pdf rt_scatter_pdf(const rt_scatter *s) { return pdf_cosine(s->normal); }
/* END SNIPPET scatter_record */

/* Radiance emitted toward the ray that produced h: m->emission on the
 * front face, 0 on the back. */
static inline vec3 rt_material_emitted(const rt_material *m, const rt_hit *h)
{
    return h->front_face ? m->emission : vec3_make(0.0, 0.0, 0.0);
}

/* rt_material_scatter for metal and glass (the specular kinds). */
bool rt_material_scatter_specular(const rt_material *m, const rt_ray *in, const rt_hit *h,
                                  rt_sampler *sampler, rt_scatter *s);

/* Fills *s for the ray *in scattered at h; returns false when the
 * material absorbs it (a light, or fuzzed metal sent below the surface).
 * Draws uniforms from sampler only for specular events. Inline, with the
 * diffuse case first: it follows every hit, and most hits in the Cornell
 * box are diffuse. The ray goes by pointer (docs/performance.md says
 * why). */
static inline bool rt_material_scatter(const rt_material *m, const rt_ray *in, const rt_hit *h,
                                       rt_sampler *sampler, rt_scatter *s)
{
    if (m->kind == RT_MAT_LAMBERT) {
        s->specular = false;
        s->attenuation = m->albedo;
        s->normal = h->normal;
        return true;
    }
    if (m->kind == RT_MAT_LIGHT)
        return false;
    return rt_material_scatter_specular(m, in, h, sampler, s);
}

/* The chapter-3 scattering pdf s(direction) of a diffuse material at h for
 * the unit direction d: max(0, cos theta) / pi with theta measured from the
 * normal facing the incoming ray (BRDF = albedo s / cos). 0 for specular
 * materials. */
static inline double rt_material_scattering_pdf(const rt_material *m, const rt_hit *h, vec3 d)
{
    if (m->kind != RT_MAT_LAMBERT)
        return 0.0;
    double c = vec3_dot(h->normal, d);
    return c > 0.0 ? c * MC_INV_PI : 0.0;
}

/* Both branches of the ray *in meeting glass m at h, for a caller that
 * follows both instead of drawing one (splitting): returns the Fresnel
 * reflectance R in [0, 1], the probability with which
 * rt_material_scatter reflects, and sets *reflected and, when R < 1,
 * *refracted to the rays it would send (the same bits). Each branch's
 * weight is then the material's albedo times R or 1 - R. */
double rt_glass_branches(const rt_material *m, const rt_ray *in, const rt_hit *h, rt_ray *reflected,
                         rt_ray *refracted);

/* Mirror direction of d about the unit normal n: d - 2 (d . n) n. */
vec3 rt_reflect(vec3 d, vec3 n);

/* Snell's law for the unit direction d meeting the unit normal n (facing
 * against d) with eta = n_incident / n_transmitted. Returns false on total
 * internal reflection (eta sin theta_i > 1); else *out is the unit
 * refracted direction. */
bool rt_refract(vec3 d, vec3 n, double eta, vec3 *out);

/* Unpolarized Fresnel reflectance (R_s + R_p) / 2 for light arriving at
 * cos_i in [0, 1] from the medium of index n1 into the one of index n2;
 * 1 under total internal reflection. */
double rt_fresnel_exact(double cos_i, double n1, double n2);

/* Schlick's approximation [@schlick1994] of the same reflectance. The cosine used is that
 * on the rarer side of the interface (the incident one when n1 <= n2, the
 * transmitted one otherwise): the reflectance is symmetric in the two
 * angles, and only on the rarer side does the approximation hold. The
 * book's code uses the incident cosine in both directions, which is far off
 * near total internal reflection (rt_fresnel_schlick_book). 1 under total
 * internal reflection. */
double rt_fresnel_schlick(double cos_i, double n1, double n2);

/* The book's variant, for comparison and negative controls:
 * R0 + (1 - R0)(1 - cos_i)^5 with the incident cosine whichever side it is
 * on; 1 under total internal reflection. */
double rt_fresnel_schlick_book(double cos_i, double n1, double n2);

#endif /* RT_MATERIAL_H */
