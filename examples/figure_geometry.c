/* examples/figure_geometry.c - the points and curves of the book's
 * geometric figures (`make plots`), computed by the library's own
 * functions, so that a figure shows what the code does:
 *   sphere-patch  a patch of the unit sphere in (theta, phi) and the
 *                 angles that place it (smp_spherical_direction; #ch-sphere)
 *   area          a parallelogram light seen from a point, its edges and
 *                 sampled points projected onto the unit sphere
 *                 (smp_parallelogram_sample, pdf_quad_direction,
 *                 smp_area_to_solid_angle; #ch-lights)
 *   onb           the bases onb_from_w builds from five normals (#ch-onb)
 *   disc          a grid of the unit square under the polar and the
 *                 concentric disc mappings (#ch-directions)
 *   hemisphere    the same uniforms warped uniformly and cosine-weighted
 *                 (#ch-scattering)
 *   cone          the cone toward a sphere light and directions drawn from
 *                 pdf_toward_sphere (#ch-lights)
 *   cap           the cap of a cone on the unit sphere and points of
 *                 smp_uniform_cone_sample (#ch-directions)
 *   mixture       the densities of examples/mixture.c's cosine, light and
 *                 mixture pdfs along one plane (#ch-mixture)
 * Each prints CSV: curve,x,y,z rows (a curve is a polyline of consecutive
 * rows with one label; a row labelled "break" ends one, and gnuplot draws
 * no line through it; a label "value:NAME" carries a number in x), or for
 * mixture curve,angle_deg,density.
 * Build and run:  make all && build/bin/figure_geometry disc
 *                 build/bin/figure_geometry hemisphere --points 500 --seed 3
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "examples/common/cli.h"
#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/rng.h"
#include "pdf/pdf.h"
#include "render/shapes.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/measure.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/spherical.h"

#define PROG "figure_geometry"
#define DEG (MC_PI / 180.0)

static void row(const char *curve, vec3 p) { printf("%s,%.6f,%.6f,%.6f\n", curve, p.x, p.y, p.z); }
static void brk(void) { printf("break,0,0,0\n"); }
static void value(const char *name, double x) { printf("value:%s,%.9g,0,0\n", name, x); }
static void segment(const char *curve, vec3 a, vec3 b)
{
    row(curve, a);
    row(curve, b);
    brk();
}

/* The arc of directions (theta, phi) from (t0, p0) to (t1, p1), in degrees,
 * scaled by radius, as a polyline of 60 steps. */
static void arc(const char *curve, double t0, double p0, double t1, double p1, double radius)
{
    for (int k = 0; k <= 60; k++) {
        double f = k / 60.0, theta = (t0 + f * (t1 - t0)) * DEG, phi = (p0 + f * (p1 - p0)) * DEG;
        row(curve, vec3_scale(smp_spherical_direction(cos(theta), phi), radius));
    }
    brk();
}

/* Meridians every 30 degrees and parallels every 15 of the unit sphere
 * (the upper half only when upper). */
static void wire_sphere(const char *curve, bool upper)
{
    for (int m = 0; m < 12; m++)
        arc(curve, 0.0, 30.0 * m, upper ? 90.0 : 180.0, 30.0 * m, 1.0);
    for (int t = 15; t < (upper ? 90 : 180); t += 15)
        arc(curve, t, 0.0, t, 360.0, 1.0);
    if (upper)
        arc(curve, 90.0, 0.0, 90.0, 360.0, 1.0);
}

static void sphere_patch(void)
{
    const double t0 = 50.0, dt = 15.0, p0 = 20.0, dp = 30.0;
    wire_sphere("sphere", true);
    arc("patch", t0, p0, t0, p0 + dp, 1.0);
    arc("patch", t0, p0 + dp, t0 + dt, p0 + dp, 1.0);
    arc("patch", t0 + dt, p0 + dp, t0 + dt, p0, 1.0);
    arc("patch", t0 + dt, p0, t0, p0, 1.0);
    for (int k = 1; k < 10; k++) /* hatching: parallels inside the patch */
        arc("fill", t0 + dt * k / 10.0, p0, t0 + dt * k / 10.0, p0 + dp, 1.0);
    vec3 o = vec3_make(0.0, 0.0, 0.0), c = smp_spherical_direction(cos(t0 * DEG), p0 * DEG);
    segment("ray", o, c);
    segment("ray", o, vec3_normalize(vec3_make(c.x, c.y, 0.0)));
    segment("axis", o, vec3_make(1.3, 0, 0));
    segment("axis", o, vec3_make(0, 1.3, 0));
    segment("axis", o, vec3_make(0, 0, 1.3));
    arc("angle", 0.0, p0, t0, p0, 0.35);
    arc("angle", 90.0, 0.0, 90.0, p0, 0.45);
    /* The radius of the parallel: the sin theta of d omega. */
    segment("sin", vec3_make(0, 0, c.z), c);
    /* Where the labels go: the edge d theta (a meridian) and the edge
     * sin theta d phi (a parallel), and the patch's solid angle through
     * the inverse of the uniform sphere warp, whose (u1, u2) have
     * d omega = 4 pi du1 du2. */
    row("label:dtheta", vec3_scale(smp_spherical_direction(cos((t0 + dt / 2) * DEG), (p0 + dp) * DEG), 1.08));
    row("label:dphi", vec3_scale(smp_spherical_direction(cos((t0 - 6.0) * DEG), (p0 + dp / 2) * DEG), 1.08));
    vec2 a = smp_uniform_sphere_invert(smp_spherical_direction(cos(t0 * DEG), p0 * DEG));
    vec2 b = smp_uniform_sphere_invert(smp_spherical_direction(cos((t0 + dt) * DEG), (p0 + dp) * DEG));
    value("omega", MC_4PI * fabs(b.x - a.x) * fabs(b.y - a.y));
    value("approx", sin(t0 * DEG) * dt * DEG * dp * DEG);
}

static void area(mc_rng *rng, int n)
{
    /* The shading point at the origin and a light tilted away from it. */
    vec3 p = vec3_make(0, 0, 0), corner = vec3_make(-0.45, 0.6, 1.9);
    vec3 u = vec3_make(0.0, 0.55, 0.45), v = vec3_make(0.9, 0.0, 0.0); /* u x v faces p */
    vec3 normal, w, centre = smp_parallelogram_sample(0.5, 0.5, corner, u, v);
    double inv_area;
    pdf_quad_constants(u, v, &normal, &w, &inv_area);
    const double e[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    for (int k = 0; k < 4; k++)
        for (int j = 0; j <= 20; j++) {
            double s = e[k][0] + (e[k + 1][0] - e[k][0]) * j / 20.0;
            double t = e[k][1] + (e[k + 1][1] - e[k][1]) * j / 20.0;
            row("quad", smp_parallelogram_sample(s, t, corner, u, v));
        }
    brk();
    for (int k = 0; k < 4; k++) /* its image on the unit sphere about p */
        for (int j = 0; j <= 20; j++)
            row("image", pdf_quad_direction(p, corner, u, v, e[k][0] + (e[k + 1][0] - e[k][0]) * j / 20.0,
                                            e[k][1] + (e[k + 1][1] - e[k][1]) * j / 20.0));
    brk();
    for (int k = 0; k < 4; k++)
        segment("cone", p, smp_parallelogram_sample(e[k][0], e[k][1], corner, u, v));
    segment("axis", p, centre);
    segment("normal", centre, vec3_madd(centre, normal, 0.5));
    for (int m = 0; m < 12; m++) /* the upper unit hemisphere, for scale */
        arc("sphere", 0.0, 30.0 * m, 90.0, 30.0 * m, 1.0);
    for (int i = 0; i < n; i++) {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        row("point", smp_parallelogram_sample(u1, u2, corner, u, v));
        row("direction", pdf_quad_direction(p, corner, u, v, u1, u2));
    }
    vec3 to = vec3_sub(centre, p);
    double dist_sq = vec3_length_sq(to), cos_light = fabs(vec3_dot(normal, vec3_normalize(to)));
    value("area", 1.0 / inv_area);
    value("r", sqrt(dist_sq));
    value("cos_light", cos_light);
    /* The solid angle the whole light would subtend if every point sat
     * at the centre's distance and tilt: 1 / (density per unit solid
     * angle of a point drawn with density 1 / A). */
    value("omega", 1.0 / smp_area_to_solid_angle(inv_area, dist_sq, cos_light));
}

static void onb_frames(void)
{
    const vec3 normals[5] = {{0, 0, 1}, {0.8, -0.2, 0.55}, {-0.75, -0.45, 0.5}, {0.3, 0.85, 0.4},
                             {-0.2, 0.6, -0.75}};
    wire_sphere("sphere", false);
    for (int i = 0; i < 5; i++) {
        vec3 n = vec3_normalize(normals[i]);
        onb o = onb_from_w(n);
        segment("w", n, vec3_madd(n, o.n, 0.45));
        segment("u", n, vec3_madd(n, o.s, 0.35));
        segment("v", n, vec3_madd(n, o.t, 0.35));
    }
}

/* The grid lines u1 = i / 8 and u2 = j / 8 of the unit square, and the
 * boundary of one cell, through `map`. */
static void disc_grid(const char *name, vec2 (*map)(double, double))
{
    char label[40];
    for (int fam = 0; fam < 2; fam++) {
        snprintf(label, sizeof label, "%s-u%d", name, fam + 1);
        for (int i = 0; i <= 8; i++) {
            for (int k = 0; k <= 96; k++) {
                double a = i / 8.0, b = fmin(k / 96.0, 1.0 - 1e-12); /* u < 1: the warps' domain */
                vec2 q = fam == 0 ? map(fmin(a, 1.0 - 1e-12), b) : map(b, fmin(a, 1.0 - 1e-12));
                row(label, vec3_make(q.x, q.y, 0.0));
            }
            brk();
        }
    }
    snprintf(label, sizeof label, "%s-cell", name);
    const double c[5][2] = {{0.5, 0.75}, {0.625, 0.75}, {0.625, 0.875}, {0.5, 0.875}, {0.5, 0.75}};
    for (int e = 0; e < 4; e++)
        for (int k = 0; k <= 24; k++) {
            double f = k / 24.0;
            vec2 q = map(c[e][0] + f * (c[e + 1][0] - c[e][0]), c[e][1] + f * (c[e + 1][1] - c[e][1]));
            row(label, vec3_make(q.x, q.y, 0.0));
        }
    brk();
}

static vec2 square(double u1, double u2) { return smp_unit_square_sample(u1, u2); }

static void hemisphere(mc_rng *rng, int n)
{
    for (int i = 0; i < n; i++) {
        double u1 = mc_rng_uniform(rng), u2 = mc_rng_uniform(rng);
        row("uniform", smp_uniform_hemisphere_sample(u1, u2));
        row("cosine", smp_cosine_hemisphere_sample(u1, u2));
    }
    value("uniform_pdf", smp_uniform_hemisphere_pdf(vec3_make(0, 0, 1)));
    value("cosine_pdf_pole", smp_cosine_hemisphere_pdf(vec3_make(0, 0, 1)));
}

static void cone(mc_rng *rng, int n)
{
    vec3 p = vec3_make(0, 0, 0), c = vec3_make(0.9, 0.0, 2.2);
    double radius = 1.0;
    pdf light = pdf_toward_sphere(p, c, radius);
    rt_sphere s = rt_sphere_make(c, radius, 1.0);
    /* The sphere's outline and the cone's two edges in the plane y = 0:
     * the directions at theta_max from the axis with azimuth 0 and pi in
     * a frame whose first axis lies in that plane. */
    vec3 axis = light.as.sphere.frame.n;
    onb plane = {vec3_make(axis.z, 0.0, -axis.x), vec3_make(0, -1, 0), axis};
    for (int k = 0; k <= 120; k++)
        row("sphere", vec3_madd(c, onb_to_world(&plane, smp_spherical_direction(cos(k * 1.5 * DEG), 0.0)),
                                radius));
    brk();
    for (int k = 0; k <= 120; k++)
        row("sphere", vec3_madd(c, onb_to_world(&plane, smp_spherical_direction(cos(k * 1.5 * DEG), MC_PI)),
                                radius));
    brk();
    double cos_max = light.as.sphere.cos_theta_max;
    for (int side = 0; side < 2; side++) {
        vec3 d = onb_to_world(&plane, smp_spherical_direction(cos_max, side * MC_PI));
        segment("edge", p, vec3_madd(p, d, 3.3));
    }
    segment("axis", p, c);
    for (int i = 0; i < n; i++) {
        vec3 d = pdf_generate(&light, rng);
        double t = rt_sphere_hit_distance(&s, rt_ray_make(p, d), 0.0, HUGE_VAL);
        if (i < 40)
            segment("ray", p, vec3_madd(p, d, t));
        row("direction", d);
    }
    value("cos_theta_max", cos_max);
    value("density", pdf_value(&light, axis));
}

static void cap(mc_rng *rng, int n)
{
    const double cos_max = cos(50.0 * DEG);
    for (int k = 0; k <= 180; k++)
        row("circle", smp_spherical_direction(cos(k * DEG), 0.0));
    brk();
    for (int k = 0; k <= 180; k++)
        row("circle", smp_spherical_direction(cos(k * DEG), MC_PI));
    brk();
    for (int side = 0; side < 2; side++) {
        segment("edge", vec3_make(0, 0, 0), smp_spherical_direction(cos_max, side * MC_PI));
        for (int k = 0; k <= 50; k++)
            row("cap", smp_spherical_direction(cos(k * DEG), side * MC_PI));
        brk();
    }
    for (int i = 0; i < n; i++)
        row("point", smp_uniform_cone_sample(mc_rng_uniform(rng), mc_rng_uniform(rng), cos_max));
    value("cos_theta_max", cos_max);
    value("omega", 1.0 / smp_uniform_cone_pdf(vec3_make(0, 0, 1), cos_max));
}

static void mixture(void)
{
    /* The scene of examples/mixture.c: normal +z, the parallelogram light. */
    vec3 origin = vec3_make(0, 0, 0), up = vec3_make(0, 0, 1);
    vec3 corner = vec3_make(-0.3, 0.2, 1.0), u = vec3_make(0.8, 0.0, 0.2), v = vec3_make(0.0, 0.6, 0.1);
    pdf cosine = pdf_cosine(up), light = pdf_toward_quad(origin, corner, u, v);
    const pdf *parts[2] = {&cosine, &light};
    const double weights[2] = {0.5, 0.5};
    pdf mix = pdf_mixture(parts, weights, 2);
    /* The plane of the normal and the direction to the light's centre:
     * angle 0 is the normal, positive angles lean toward the light. */
    vec3 centre = smp_parallelogram_sample(0.5, 0.5, corner, u, v);
    vec3 h = vec3_normalize(vec3_make(centre.x, centre.y, 0.0));
    onb plane = {h, vec3_cross(up, h), up};
    printf("curve,angle_deg,density\n");
    const pdf *show[3] = {&cosine, &light, &mix};
    const char *names[3] = {"cosine", "light", "mixture"};
    for (int c = 0; c < 3; c++)
        for (int k = 0; k <= 3600; k++) {
            double a = -180.0 + 0.1 * k;
            vec3 d = onb_to_world(&plane, smp_spherical_direction(cos(fabs(a) * DEG), a < 0 ? MC_PI : 0.0));
            printf("%s,%.2f,%.9g\n", names[c], a, pdf_value(show[c], d));
        }
}

static const char *const figures[] = {"sphere-patch", "area", "onb", "disc", "hemisphere",
                                      "cone",         "cap",  "mixture", NULL};

int main(int argc, char **argv)
{
    uint64_t seed = 1;
    int points = 400;
    const app_opt opts[] = {
        APP_OPT_SEED(&seed),
        {"--points", APP_INT, &points, "sampled points of area, hemisphere, cone, cap (default 400)", NULL, 1,
         100000},
    };
    const char *cmd[1] = {NULL};
    int npos = app_parse(PROG,
                         PROG " sphere-patch|area|onb|disc|hemisphere|cone|cap|mixture [--points N] [--seed S]",
                         argc, argv, opts, 2, cmd, 1);
    int which = -1;
    for (int i = 0; npos == 1 && figures[i]; i++)
        if (strcmp(cmd[0], figures[i]) == 0)
            which = i;
    if (which < 0)
        app_fail(PROG, "expected one of sphere-patch, area, onb, disc, hemisphere, cone, cap, mixture (see --help)");
    mc_rng rng = mc_rng_derive(seed, 0);
    if (which != 7)
        printf("curve,x,y,z\n");
    switch (which) {
    case 0: sphere_patch(); break;
    case 1: area(&rng, points); break;
    case 2: onb_frames(); break;
    case 3:
        disc_grid("square", square);
        disc_grid("polar", smp_disc_polar_sample);
        disc_grid("concentric", smp_disc_concentric_sample);
        break;
    case 4: hemisphere(&rng, points); break;
    case 5: cone(&rng, points); break;
    case 6: cap(&rng, points); break;
    default: mixture(); break;
    }
    return 0;
}
