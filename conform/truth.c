/* conform/truth.c - the closed forms of conform/truth.h and the pixel
 * quadrature. */
#include "conform/truth.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/quad.h"
#include "render/camera.h"
#include "render/material.h"

/* BEGIN SNIPPET quad_irradiance */
double cf_quad_irradiance(vec3 p, vec3 n, vec3 q, vec3 u, vec3 v, double radiance)
{
    vec3 front = vec3_cross(u, v);
    if (vec3_dot(front, vec3_sub(p, q)) <= 0.0)
        return 0.0; /* behind a one-sided emitter */
    vec3 corner[4] = {q, vec3_add(q, u), vec3_add(vec3_add(q, u), v), vec3_add(q, v)};
    vec3 r[4];
    for (int i = 0; i < 4; i++)
        r[i] = vec3_normalize(vec3_sub(corner[i], p));
    /* Each edge adds the angle it subtends, gamma, times the cosine
     * between n and the normal of the plane holding p and the edge; atan2
     * of sine and cosine keeps gamma accurate where the edge looks short. */
    double sum = 0.0;
    for (int i = 0; i < 4; i++) {
        vec3 c = vec3_cross(r[i], r[(i + 1) % 4]);
        double s = vec3_length(c);
        if (s == 0.0)
            continue;
        double gamma = atan2(s, vec3_dot(r[i], r[(i + 1) % 4]));
        sum += gamma * vec3_dot(n, c) / s;
    }
    return 0.5 * radiance * fabs(sum);
}
/* END SNIPPET quad_irradiance */

/* BEGIN SNIPPET sphere_irradiance */
double cf_sphere_irradiance(vec3 p, vec3 n, vec3 center, double radius, double radiance)
{
    vec3 to = vec3_sub(center, p);
    double d2 = vec3_length_sq(to);
    double cos_theta = vec3_dot(n, to) / sqrt(d2);
    return radiance * MC_PI * radius * radius * cos_theta / d2;
}
/* END SNIPPET sphere_irradiance */

/* The inner integral of the clipped cone: over beta in [0, b] of
 * (A cos(beta) + B sin(beta)) sin(beta) (the receiver's cosine times the
 * solid-angle element), in closed form. */
static double cone_strip(double a, double b_coef, double b)
{
    double s = sin(b);
    return 0.5 * a * s * s + b_coef * (0.5 * b - 0.25 * sin(2.0 * b));
}

/* The integrand over the azimuth phi about the cone's axis: the strip of
 * the cone above the horizon, up to alpha or to the horizon, where
 * A cos(beta) + B sin(beta) = 0. */
static double cone_azimuth(double a, double nu, double nv, double alpha, double phi)
{
    double b_coef = cos(phi) * nu + sin(phi) * nv;
    double top = b_coef < 0.0 ? fmin(alpha, atan2(a, -b_coef)) : alpha;
    return cone_strip(a, b_coef, top);
}

double cf_sphere_irradiance_clipped(vec3 p, vec3 n, vec3 center, double radius, double radiance)
{
    vec3 to = vec3_sub(center, p);
    double d = vec3_length(to), h = vec3_dot(n, to);
    if (h >= radius)
        return cf_sphere_irradiance(p, n, center, radius, radiance);
    if (h <= 0.0)
        return (double)NAN; /* the centre below the horizon: not a case of these scenes */
    /* In the frame (u, v, axis) of the cone toward the centre, a direction
     * at angle beta from the axis and azimuth phi has the receiver's
     * cosine A cos(beta) + B(phi) sin(beta), B(phi) = R cos(phi - phi0).
     * The integrand over phi has kinks where the horizon meets the cone's
     * rim (B tan(alpha) = -A); between them it is analytic, and 12
     * Gauss-Legendre points on each half of an arc agree with 24 on each
     * eighth to 1.3e-12 of the value. */
    vec3 axis = vec3_scale(to, 1.0 / d);
    onb f = onb_from_w(axis);
    double a = vec3_dot(n, axis), nu = vec3_dot(n, f.s), nv = vec3_dot(n, f.t);
    double alpha = asin(radius / d), r = hypot(nu, nv), phi0 = atan2(nv, nu);
    double c = -a / (r * tan(alpha));
    double cuts[2] = {phi0, phi0 + 2.0 * MC_PI};
    int ncuts = 1;
    if (c > -1.0 && c < 1.0) {
        double k = acos(c);
        cuts[0] = phi0 - k, cuts[1] = phi0 + k;
        ncuts = 2;
    }
    double x[12], w[12];
    if (mc_quad_gauss_legendre(12, 0.0, 1.0, x, w) != 0)
        return (double)NAN;
    double sum = 0.0;
    for (int arc = 0; arc < ncuts; arc++) {
        double lo = cuts[arc], hi = arc + 1 < ncuts ? cuts[arc + 1] : cuts[0] + 2.0 * MC_PI;
        for (int piece = 0; piece < 2; piece++) {
            double p0 = lo + (hi - lo) * piece / 2.0, len = (hi - lo) / 2.0;
            for (int i = 0; i < 12; i++)
                sum += w[i] * len * cone_azimuth(a, nu, nv, alpha, p0 + len * x[i]);
        }
    }
    return radiance * sum;
}

/* The floor of a wall scene (shape 0) reflecting the irradiance of its
 * emitter (shape 1) where the ray from lookfrom along d meets it. */
static double wall_radiance(const cf_scene *s, vec3 d)
{
    const cf_shape *floor = &s->shapes[0], *lamp = &s->shapes[1];
    vec3 n = vec3_normalize(vec3_cross(floor->u, floor->v));
    double t = vec3_dot(n, vec3_sub(floor->q, s->lookfrom)) / vec3_dot(n, d);
    vec3 p = vec3_madd(s->lookfrom, d, t);
    double radiance = s->materials[lamp->material].radiance;
    double e = lamp->kind == CF_QUAD
                   ? cf_quad_irradiance(p, n, lamp->q, lamp->u, lamp->v, radiance)
                   : cf_sphere_irradiance_clipped(p, n, lamp->center, lamp->radius, radiance);
    return s->materials[floor->material].albedo * MC_INV_PI * e;
}

/* The slab's faces are parallel to z = 0 and its index is material 0's;
 * the emitter is material 1. */
static double slab_radiance(const cf_scene *s, vec3 d)
{
    double r = rt_fresnel_exact(fabs(d.z), 1.0, s->materials[0].ior);
    return s->materials[1].radiance * (1.0 - r) / (1.0 + r);
}

double cf_radiance_along(const cf_scene *s, vec3 d)
{
    if (strcmp(s->name, "furnace-grey") == 0)
        return s->materials[0].radiance / (1.0 - s->materials[0].albedo);
    if (strcmp(s->name, "furnace-white") == 0)
        return s->background;
    if (strcmp(s->name, "glass-slab") == 0)
        return slab_radiance(s, d);
    return wall_radiance(s, d);
}

/* Gauss-Legendre rules of two orders on [0, 1]: the pixel's mean by the
 * lower, checked against the higher. */
enum { LO = 6, HI = 10, MAX_SPLIT = 6 };
typedef struct rules {
    double xl[LO], wl[LO], xh[HI], wh[HI];
} rules;

/* The integral over [x, x + h] x [y, y + h] of the radiance along the
 * camera's rays by both rules; halved in both directions where they
 * differ by more than tol (absolute, per unit area); *err collects the
 * differences left. */
static double square(const cf_scene *s, const rt_camera *cam, const rules *g, double x, double y,
                     double h, double tol, int depth, double *err)
{
    double lo = 0.0, hi = 0.0;
    for (int a = 0; a < HI; a++)
        for (int b = 0; b < HI; b++)
            hi += g->wh[a] * g->wh[b] *
                  cf_radiance_along(s, rt_camera_ray(cam, x + h * g->xh[a], y + h * g->xh[b]).dir);
    for (int a = 0; a < LO; a++)
        for (int b = 0; b < LO; b++)
            lo += g->wl[a] * g->wl[b] *
                  cf_radiance_along(s, rt_camera_ray(cam, x + h * g->xl[a], y + h * g->xl[b]).dir);
    double diff = fabs(hi - lo);
    if (diff <= tol || depth >= MAX_SPLIT) {
        *err += diff * h * h;
        return hi * h * h;
    }
    double k = 0.5 * h, sum = 0.0;
    for (int q = 0; q < 4; q++)
        sum += square(s, cam, g, x + k * (q & 1), y + k * (q >> 1), k, tol, depth + 1, err);
    return sum;
}

int cf_truth_image(const cf_scene *s, int width, int height, double *value, double *max_error)
{
    if (!s || width < 1 || height < 1 || !value)
        return -1;
    rules g;
    if (mc_quad_gauss_legendre(LO, 0.0, 1.0, g.xl, g.wl) != 0 ||
        mc_quad_gauss_legendre(HI, 0.0, 1.0, g.xh, g.wh) != 0)
        return -1;
    rt_camera_params p = {s->lookfrom, s->lookat, s->vup, s->vfov_deg};
    rt_camera cam = rt_camera_make(p, width, height);
    double worst = 0.0;
    for (int j = 0; j < height; j++)
        for (int i = 0; i < width; i++) {
            double err = 0.0;
            value[(size_t)j * (size_t)width + (size_t)i] =
                square(s, &cam, &g, (double)i, (double)j, 1.0, 1e-11, 0, &err);
            worst = err > worst ? err : worst;
        }
    if (max_error)
        *max_error = worst;
    return 0;
}
