/* tests/test_render_values.c - the values that decide a bidirectional
 * render's noise, pinned against numbers the test derives itself
 * (render/bdpt.h; Veach's thesis, 1997, chapters 9 and 10):
 *   - the balance heuristic's weights of hand-built paths (camera - wall -
 *     lamp, camera - wall - wall - lamp, camera - wall - wall - wall -
 *     lamp), from each strategy's density written out here in the area
 *     measure (emitter area, cosine emission, cosine sampling, the film's
 *     density, each turned into area density by cos / distance^2), the
 *     direct light's splat scaled by RT_BDPT_DIRECT_SPLAT_SCALE and longer
 *     paths' by RT_BDPT_SPLAT_SCALE; and the joins' weights from running
 *     sums against the same weights summed over the whole path, on those
 *     paths and on every join of renders;
 *   - the pinhole camera's importance and its density per unit area on a
 *     300 x 200 film, against the closed forms and the normalisation of
 *     the importance over the film's directions;
 *   - a white furnace rendered at RT_BDPT_MAX_DEPTH, the largest depth the
 *     Cornell box program lets the splatting strategies take, against the
 *     furnace's closed form (this also fills every subpath buffer to the
 *     last vertex under the sanitizers);
 *   - the paths estimated apart are those only s = 0 can make: on every
 *     camera subpath that reaches the lamp through the glass ball, the
 *     rule against the balance heuristic's weight of 1;
 *   - the rays traced by the families estimated apart (the lamp seen
 *     through glass and mirrors, the caustic seen through the sphere):
 *     an exact count in a scene where every ray's fate is known, and a
 *     per-sample upper bound from the depth in the book's scene; the
 *     share of the hemisphere the ball covers, which chooses how many
 *     rays the caustic's term sends, against cosine-distributed
 *     directions, and those counts.
 * Every value also has a negative control: the same check against a
 * plausible wrong value (the power heuristic, either splat unscaled, a
 * square film, the lens cosine dropped, one depth short, one split level
 * short) must fail.
 * Compiling with -DVALUES_BREAK=k (1 weights, 2 camera, 3 furnace,
 * 4 segments) perturbs the expected value of check k so that it fails. */
#include "tests/support/mc_test.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"
#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/stats.h"
#include "pdf/pdf.h"
#include "render/bdpt.h"
#include "render/bdpt_internal.h"
#include "render/render.h"
#include "render/scenes.h"
#include "render/splat.h"
#include "tests/support/negctl.h"

#ifndef VALUES_BREAK
#define VALUES_BREAK 0
#endif

/* The film of the weight and camera tests: not square, so that a density
 * that takes the film's area as width^2 or height^2 pixels is caught. */
enum { FILM_W = 300, FILM_H = 200 };

static double rel_err(double a, double b) { return fabs(a - b) / fabs(b); }

/* --- densities written out from first principles ---------------------- */

/* The view axis and the film's area on the plane at distance 1 of a
 * camera with vertical field of view vfov and aspect w / h: the plane's
 * half-height is tan(vfov / 2), its half-width that times w / h. */
static vec3 view_axis(const rt_camera_params *cp)
{
    return vec3_normalize(vec3_sub(cp->lookat, cp->lookfrom));
}

static double film_area(const rt_camera_params *cp, int w, int h)
{
    double half_h = tan(0.5 * cp->vfov_deg * MC_PI / 180.0);
    return (2.0 * half_h) * (2.0 * half_h * (double)w / (double)h);
}

/* The density per unit area at x (normal n) with which the camera ray,
 * uniform over the film of area A at distance 1, lands there: per unit
 * solid angle 1 / (A cos^3 theta) (a patch dA of the plane subtends
 * cos^3 theta dA / 1^2), times cos at x over the squared distance. */
static double camera_area_pdf(const rt_camera_params *cp, double film, vec3 x, vec3 n)
{
    vec3 d = vec3_sub(x, cp->lookfrom);
    double dist = vec3_length(d);
    double cos_theta = vec3_dot(view_axis(cp), d) / dist;
    double cos_x = fabs(vec3_dot(n, d)) / dist;
    return 1.0 / (film * cos_theta * cos_theta * cos_theta) * cos_x / (dist * dist);
}

/* The density per unit area at `to` (normal n_to) of a direction drawn
 * at `from` with density cos / pi about n_from (cosine sampling at a
 * Lambertian vertex, or cosine emission from a lamp): (cos_from / pi) x
 * cos_to / distance^2. */
static double cosine_area_pdf(vec3 from, vec3 n_from, vec3 to, vec3 n_to)
{
    vec3 d = vec3_sub(to, from);
    double dist = vec3_length(d);
    double cos_from = vec3_dot(n_from, d) / dist, cos_to = fabs(vec3_dot(n_to, d)) / dist;
    return cos_from > 0.0 ? cos_from * MC_INV_PI * cos_to / (dist * dist) : 0.0;
}

/* A hand-built path in lambert's room: p[0] on the lamp (normal n[0],
 * facing down), p[1 .. n - 2] on the walls (Lambertian, inward normals),
 * p[n - 1] the camera. */
typedef struct hand_path {
    int n;
    vec3 p[6], nrm[6];
} hand_path;

/* The density p_r with which strategy r (r light vertices, n - r camera
 * vertices) makes the path: the light subpath picks p[0] with density
 * 1 / (emitters x lamp area) and continues by cosine emission, then
 * cosine sampling; the camera subpath makes p[n - 2] through the film and
 * continues by cosine sampling toward the lamp. For n = 3 (camera - wall
 * - lamp), with pL = 1 / A_lamp:
 *   p_0 = pcam(p1) pcos(p1 -> p0)
 *   p_1 = pL pcam(p1)
 *   p_2 = pL pemit(p0 -> p1). */
static double strategy_pdf(const hand_path *x, int r, const rt_camera_params *cp, double film,
                           double light_area_pdf)
{
    int n = x->n;
    double p = r >= 1 ? light_area_pdf : 1.0;
    for (int i = 1; i < r; i++) /* made from p[i - 1] by the light subpath */
        p *= cosine_area_pdf(x->p[i - 1], x->nrm[i - 1], x->p[i], x->nrm[i]);
    for (int i = r; i <= n - 2; i++) /* made from p[i + 1] by the camera subpath */
        p *= i == n - 2 ? camera_area_pdf(cp, film, x->p[i], x->nrm[i])
                        : cosine_area_pdf(x->p[i + 1], x->nrm[i + 1], x->p[i], x->nrm[i]);
    return p;
}

/* The constant strategy r's density is scaled by in the weights: the
 * splat (r = n - 1) of a path of three vertices counts at `direct_splat`,
 * that of a longer path at `splat`. */
static double strategy_scale(const hand_path *x, int r, double direct_splat, double splat)
{
    if (r != x->n - 1)
        return 1.0;
    return x->n == 3 ? direct_splat : splat;
}

/* The weight of strategy s under the heuristic of exponent beta (2: the
 * power heuristic, 1: the balance heuristic the renderer uses), each
 * density scaled as the renderer scales it (RT_BDPT_DIRECT_SPLAT_SCALE and
 * RT_BDPT_SPLAT_SCALE; the controls pass 1 for either): every strategy of
 * a path of Lambertian vertices can make it. */
static double hand_weight_scaled(const hand_path *x, int s, double beta, const rt_camera_params *cp,
                                 double film, double light_area_pdf, double direct_splat,
                                 double splat)
{
    double sum = 0.0;
    double ps = pow(strategy_scale(x, s, direct_splat, splat) *
                        strategy_pdf(x, s, cp, film, light_area_pdf),
                    beta);
    for (int r = 0; r < x->n; r++)
        sum += pow(strategy_scale(x, r, direct_splat, splat) *
                       strategy_pdf(x, r, cp, film, light_area_pdf),
                   beta);
#if VALUES_BREAK == 1
    if (s == 1)
        ps *= 1.001; /* the deliberately broken expectation */
#endif
    return ps / sum;
}

static double hand_weight(const hand_path *x, int s, double beta, const rt_camera_params *cp,
                          double film, double light_area_pdf)
{
    return hand_weight_scaled(x, s, beta, cp, film, light_area_pdf, RT_BDPT_DIRECT_SPLAT_SCALE,
                              RT_BDPT_SPLAT_SCALE);
}

/* The renderer's vertices of the path: as the weight of the whole path
 * sees it (x[0] the start of a light subpath), and as a camera subpath
 * that reached the lamp sees its last vertex (a surface hit on the
 * emitting side). */
static rt_bdpt_vertex lamp_vertex(const hand_path *x, const rt_scene *s, bool as_hit)
{
    const rt_prim *lamp = &rt_scene_emitter_prims(s)[0];
    return (rt_bdpt_vertex){as_hit ? RT_BDPT_SURFACE : RT_BDPT_LIGHT, x->p[0], x->nrm[0], x->nrm[0],
                            true, false, rt_scene_material(s, lamp->material), 0,
                            vec3_make(1.0, 1.0, 1.0)};
}

static rt_bdpt_vertex wall_vertex(vec3 p, vec3 n, const rt_material *m)
{
    return (rt_bdpt_vertex){RT_BDPT_SURFACE, p, n, n, true, false, m, -1, vec3_make(1.0, 1.0, 1.0)};
}

static rt_bdpt_vertex camera_vertex(const rt_bdpt_ctx *c)
{
    return (rt_bdpt_vertex){RT_BDPT_CAMERA, c->camera->origin, c->forward, c->forward, true, false,
                            NULL, -1, vec3_make(1.0, 1.0, 1.0)};
}

/* The three paths of the weight test, in "high-entropy" coordinates on
 * lambert's room (walls at 0 and 555; the lamp at y = 554, x in
 * [213, 343], z in [227, 332]). */
static hand_path weight_path(int k)
{
    vec3 down = vec3_make(0.0, -1.0, 0.0), up = vec3_make(0.0, 1.0, 0.0);
    vec3 left = vec3_make(1.0, 0.0, 0.0), back = vec3_make(0.0, 0.0, -1.0);
    vec3 lamp = vec3_make(251.37, 554.0, 290.85), cam = vec3_make(278.0, 278.0, -800.0);
    vec3 floor_pt = vec3_make(318.6, 0.0, 201.35), wall_pt = vec3_make(0.0, 161.2, 402.77);
    vec3 back_pt = vec3_make(120.4, 307.9, 555.0);
    if (k == 0)
        return (hand_path){3, {lamp, floor_pt, cam}, {down, up, back}};
    if (k == 1)
        return (hand_path){4, {lamp, wall_pt, floor_pt, cam}, {down, left, up, back}};
    return (hand_path){5, {lamp, back_pt, wall_pt, floor_pt, cam}, {down, back, left, up, back}};
}

/* The renderer's path x[0..n) of hand path h; x[0] as a light start. */
static void renderer_path(const hand_path *h, const rt_scene *s, const rt_bdpt_ctx *c,
                          const rt_material *white, rt_bdpt_vertex *x)
{
    x[0] = lamp_vertex(h, s, false);
    for (int i = 1; i < h->n - 1; i++)
        x[i] = wall_vertex(h->p[i], h->nrm[i], white);
    x[h->n - 1] = camera_vertex(c);
}

/* The weight of the join (s, n - s) through the cached subpath densities
 * (rt_bdpt_join_weight, the weighted render's own way): the light
 * subpath x[0..s), the camera subpath x[n - 1] down to x[s]. */
/* The subpaths of the join (sv, n - sv) of x[0..n): light[0..sv) and
 * cam[0..n - sv), x[n - 1] first. */
static void split_path(const rt_bdpt_vertex *x, int n, int sv, rt_bdpt_vertex *light,
                       rt_bdpt_vertex *cam)
{
    for (int i = 0; i < sv; i++)
        light[i] = x[i];
    for (int j = 0; j < n - sv; j++)
        cam[j] = x[n - 1 - j];
}

static double join_weight_of(const rt_bdpt_ctx *c, const hand_path *h, const rt_scene *s,
                             const rt_bdpt_vertex *x, int sv)
{
    int n = h->n, t = n - sv;
    rt_bdpt_vertex light[6], cam[6];
    split_path(x, n, sv, light, cam);
    if (sv == 0)
        cam[t - 1] = lamp_vertex(h, s, true);
    rt_bdpt_subpath_pdfs sp;
    rt_bdpt_cache_pdfs(c, light, sv, cam, t, &sp);
    double w = rt_bdpt_join_weight(c, &sp, light, sv, cam, t);
    double running = rt_bdpt_join_weight_running(c, &sp, light, sv, cam, t);
    if (rel_err(running, w) > 1e-12)
        fail_msg("path of %d vertices, s = %d: running sums %.17g, over the path %.17g", n, sv,
                 running, w);
    return w;
}

/* The running sums' weight of join (sv, n - sv) of hand path h with the
 * light side's sums (la) zeroed: a running sum that forgets the light
 * subpath, the negative control of the comparison above. */
static double join_weight_light_forgotten(const rt_bdpt_ctx *c, const hand_path *h,
                                          const rt_bdpt_vertex *x, int sv)
{
    int n = h->n, t = n - sv;
    rt_bdpt_vertex light[6], cam[6];
    split_path(x, n, sv, light, cam);
    rt_bdpt_subpath_pdfs sp;
    rt_bdpt_cache_pdfs(c, light, sv, cam, t, &sp);
    for (int i = 0; i < sv; i++)
        sp.la[i] = 0.0;
    return rt_bdpt_join_weight_running(c, &sp, light, sv, cam, t);
}

/* Every strategy's weight of the three paths, from rt_bdpt_mis_weight and
 * from the joins' cached densities, against the balance heuristic over the
 * densities above: relative error < 1e-12 (the two computations share
 * no code; the tolerance is a few hundred roundings). Also the exception
 * of a lamp the camera sees directly (n = 2): all to s = 0. Negative
 * controls: the power heuristic's weights (exponent 2) and the balance
 * heuristic's without the direct light's splat scale, or without the
 * longer paths' splat scale, must each differ from the renderer's by
 * more than 1e-3 somewhere, and the renderer with
 * strategy 1 counted twice (neg.mis_double) from the balance heuristic's. */
static void test_mis_weights_by_hand(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    assert_non_null(s);
    assert_int_equal(rt_scene_emitter_count(s), 1);
    rt_camera cam = rt_camera_make(cp, FILM_W, FILM_H);
    rt_path_settings ps = rt_path_settings_default(RT_BDPT);
    rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
    rt_material white = rt_lambertian(vec3_make(0.73, 0.73, 0.73));
    double film = film_area(&cp, FILM_W, FILM_H);
    double light_pdf = 1.0 / (130.0 * 105.0); /* the lamp is 130 x 105 */
    double worst = 0.0, power_gap = 0.0, unscaled_gap = 0.0, long_unscaled_gap = 0.0;
    for (int k = 0; k < 3; k++) {
        hand_path h = weight_path(k);
        rt_bdpt_vertex x[6];
        renderer_path(&h, s, &c, &white, x);
        for (int sv = 0; sv < h.n; sv++) {
            double want = hand_weight(&h, sv, 1.0, &cp, film, light_pdf);
            double got = rt_bdpt_mis_weight(&c, x, h.n, sv);
            double got_join = join_weight_of(&c, &h, s, x, sv);
            printf("path of %d vertices, s = %d: weight %.15f, joins' %.15f, by hand %.15f\n", h.n,
                   sv, got, got_join, want);
            worst = fmax(worst, fmax(rel_err(got, want), rel_err(got_join, want)));
            power_gap = fmax(power_gap, fabs(got - hand_weight(&h, sv, 2.0, &cp, film, light_pdf)));
            unscaled_gap = fmax(unscaled_gap, fabs(got - hand_weight_scaled(&h, sv, 1.0, &cp, film,
                                                                            light_pdf, 1.0,
                                                                            RT_BDPT_SPLAT_SCALE)));
            long_unscaled_gap =
                fmax(long_unscaled_gap, fabs(got - hand_weight_scaled(&h, sv, 1.0, &cp, film, light_pdf,
                                                                      RT_BDPT_DIRECT_SPLAT_SCALE, 1.0)));
        }
    }
    printf("largest relative error of a weight: %.2e\n", worst);
    assert_true(worst < 1e-12);
    /* The running sums (compared with the path's in join_weight_of) must
     * see the light side: forgetting it moves the weight of s = 3 on the
     * path of five vertices. */
    {
        hand_path h5 = weight_path(2);
        rt_bdpt_vertex x5[6];
        renderer_path(&h5, s, &c, &white, x5);
        double forgot = fabs(join_weight_light_forgotten(&c, &h5, x5, 3) -
                             hand_weight(&h5, 3, 1.0, &cp, film, light_pdf));
        if (!negctl_record(nc, "running sums without the light side", "weights by hand",
                           forgot > 1e-3))
            fail_msg("a running sum without the light subpath was not caught: gap %.2e", forgot);
    }
    if (!negctl_record(nc, "the power heuristic's weights", "weights by hand", power_gap > 1e-3))
        fail_msg("the power heuristic is not told from the balance heuristic: gap %.2e", power_gap);
    if (!negctl_record(nc, "the direct light's splat unscaled", "weights by hand", unscaled_gap > 1e-3))
        fail_msg("the splat's scale on direct light is not seen: gap %.2e", unscaled_gap);
    if (!negctl_record(nc, "the longer paths' splats unscaled", "weights by hand",
                       long_unscaled_gap > 1e-3))
        fail_msg("the splat's scale on longer paths is not seen: gap %.2e", long_unscaled_gap);
    /* The renderer's own hook: strategy 1 counted twice in the sum. */
    rt_path_settings twice = ps;
    twice.neg.mis_double = 2;
    rt_bdpt_ctx cb = rt_bdpt_ctx_make(s, &twice, &cam);
    hand_path h3 = weight_path(1);
    rt_bdpt_vertex x3[6];
    renderer_path(&h3, s, &cb, &white, x3);
    double gap = fabs(rt_bdpt_mis_weight(&cb, x3, h3.n, 2) -
                      hand_weight(&h3, 2, 1.0, &cp, film, light_pdf));
    if (!negctl_record(nc, "a renderer counting strategy 1 twice", "weights by hand", gap > 1e-6))
        fail_msg("the double-counted strategy was not caught: gap %.2e", gap);
    /* The lamp seen directly: both strategies could make it, but the
     * render gives it wholly to the camera ray (render/bdpt.h). */
    hand_path d = {2, {weight_path(0).p[0]}, {vec3_make(0.0, -1.0, 0.0)}};
    rt_bdpt_vertex x2[2] = {lamp_vertex(&d, s, false), camera_vertex(&c)};
    assert_near(rt_bdpt_mis_weight(&c, x2, 2, 0), 1.0, 0.0);
    assert_near(rt_bdpt_mis_weight(&c, x2, 2, 1), 0.0, 0.0);
    rt_scene_destroy(s);
}

/* --- the camera ------------------------------------------------------- */

/* The point at distance `dist` from the camera through the image-plane
 * point (px, py) in pixel units, from the book's basis written out: w
 * back toward the viewer, u = vup x w to the right, v = w x u up; the
 * top-left corner of the plane at distance 1 is -w - half_w u + half_h v. */
static vec3 through_film(const rt_camera_params *cp, int w, int h, double px, double py,
                         double dist, double *cos_theta)
{
    double half_h = tan(0.5 * cp->vfov_deg * MC_PI / 180.0), half_w = half_h * w / (double)h;
    vec3 ww = vec3_normalize(vec3_sub(cp->lookfrom, cp->lookat));
    vec3 u = vec3_normalize(vec3_cross(cp->vup, ww)), v = vec3_cross(ww, u);
    double a = -half_w + 2.0 * half_w * px / w, b = half_h - 2.0 * half_h * py / h;
    vec3 q = vec3_add(vec3_neg(ww), vec3_add(vec3_scale(u, a), vec3_scale(v, b)));
    *cos_theta = 1.0 / vec3_length(q);
    return vec3_add(cp->lookfrom, vec3_scale(vec3_normalize(q), dist));
}

/* The importance W_j of a pixel per unit solid angle: Veach's (and
 * pbrt's) pinhole importance is 1 / (A cos^4 theta) per unit solid angle
 * per unit area of the lens, A the pixel's area at distance 1; the join
 * to a pinhole counts the lens cosine cos theta (the geometry term's
 * factor at the camera), so what the splat carries is
 * cos theta / (A_pix cos^4 theta). */
static double importance_closed_form(double pixel_area, double cos_theta)
{
    double c4 = cos_theta * cos_theta * cos_theta * cos_theta;
#if VALUES_BREAK == 2
    return 1.0 / (pixel_area * c4); /* the lens cosine dropped */
#else
    return cos_theta / (pixel_area * c4);
#endif
}

/* On the 300 x 200 film of lambert's camera: the pixel area, the
 * importance at the centre and at the centres of the four corner pixels
 * (with their pixel indices) against the closed form (relative error <
 * 1e-12), also with the renderer's hook that drops the 1 / cos^3
 * (neg.splat_drop_cos3), which must not match; a point just outside the
 * film has none. Then the normalisation:
 * each pixel's importance integrates to 1 over its directions, so over the
 * whole film to W x H. Estimated from N = 400000 directions uniform in the
 * cone about the view axis that holds the film (seed 2101), statistic
 * z = (mean / (W H) - 1) / stderr, threshold 4 (two-sided false alarm
 * 6.3e-5). Negative control: the same integral of 1 / (A_pix cos^4)
 * (the lens cosine dropped) must give |z| > 4. And the camera's density
 * per unit area, which only the weights use: recovered from the weights
 * of the path camera - floor - lamp as pemit(lamp -> floor) x
 * sqrt(w_1 / w_2) (p_1 / p_2 = pcam / pemit, the lamp's start density
 * cancelling), against 1 / (A_film cos^3) cos_x / d^2 with A_film the
 * 300 x 200 film; negative control: the same with a square film of the
 * height's field of view must differ. */
static void test_camera_importance_and_density(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("lambert", &cp);
    rt_camera cam = rt_camera_make(cp, FILM_W, FILM_H);
    rt_path_settings ps = rt_path_settings_default(RT_BDPT);
    rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
    double film = film_area(&cp, FILM_W, FILM_H), a_pix = film / (FILM_W * FILM_H);
    assert_true(rel_err(c.pixel_area, a_pix) < 1e-12);
    /* The centre, then the four corner pixels' centres. */
    static const double at[5][2] = {{150.0, 100.0}, {0.5, 0.5}, {299.5, 0.5}, {0.5, 199.5},
                                    {299.5, 199.5}};
    static const size_t want_px[5] = {100 * FILM_W + 150, 0, FILM_W - 1, (FILM_H - 1) * FILM_W,
                                      FILM_W * FILM_H - 1};
    for (int i = 0; i < 5; i++) {
        double cos_theta, we;
        size_t px;
        vec3 p = through_film(&cp, FILM_W, FILM_H, at[i][0], at[i][1], 3.7 + i, &cos_theta);
        assert_true(rt_bdpt_camera_importance(&c, p, &px, &we));
        double want = importance_closed_form(a_pix, cos_theta);
        printf("film point (%.1f, %.1f): cos %.6f, importance %.10g, closed form %.10g, pixel %zu\n",
               at[i][0], at[i][1], cos_theta, we, want, px);
        /* The axis meets the film on a pixel corner: any of four. */
        assert_true(i == 0 || px == want_px[i]);
        assert_true(rel_err(we, want) < 1e-12);
    }
    /* The renderer's own hook: the splat's importance without 1 / cos^3. */
    rt_path_settings flat = ps;
    flat.neg.splat_drop_cos3 = true;
    rt_bdpt_ctx cf = rt_bdpt_ctx_make(s, &flat, &cam);
    double cos_c, we_c;
    size_t px_c;
    vec3 pc = through_film(&cp, FILM_W, FILM_H, 0.5, 0.5, 4.1, &cos_c);
    bool seen_c = rt_bdpt_camera_importance(&cf, pc, &px_c, &we_c);
    if (!negctl_record(nc, "importance without 1/cos^3", "importance closed form",
                       seen_c && rel_err(we_c, importance_closed_form(a_pix, cos_c)) > 1e-3))
        fail_msg("the importance without 1/cos^3 was not caught");
    double cos_out, we_out;
    size_t px_out;
    assert_false(rt_bdpt_camera_importance(
        &c, through_film(&cp, FILM_W, FILM_H, -0.01, 50.0, 2.0, &cos_out), &px_out, &we_out));

    /* The cone about the view axis through the film's corners. */
    double half_h = tan(0.5 * cp.vfov_deg * MC_PI / 180.0), half_w = half_h * FILM_W / FILM_H;
    double cos_max = 1.0 / sqrt(1.0 + half_w * half_w + half_h * half_h) - 1e-3;
    double cone = 2.0 * MC_PI * (1.0 - cos_max); /* its solid angle */
    onb frame = onb_from_w(view_axis(&cp));
    uint64_t seed = mc_test_seed(2101u);
    mc_rng rng = mc_rng_derive(seed, 0u);
    mc_welford good = mc_welford_init(), bad = mc_welford_init();
    for (int k = 0; k < 400000; k++) {
        double ct = 1.0 - mc_rng_uniform(&rng) * (1.0 - cos_max), phi = 2.0 * MC_PI * mc_rng_uniform(&rng);
        double st = sqrt(fmax(0.0, 1.0 - ct * ct));
        vec3 d = onb_to_world(&frame, vec3_make(st * cos(phi), st * sin(phi), ct));
        size_t px;
        double we = 0.0;
        bool in = rt_bdpt_camera_importance(&c, vec3_add(cp.lookfrom, vec3_scale(d, 5.0)), &px, &we);
        double norm = cone / (double)(FILM_W * FILM_H);
        mc_welford_add(&good, in ? we * norm : 0.0);
        mc_welford_add(&bad, in ? norm / (a_pix * ct * ct * ct * ct) : 0.0);
    }
    mc_estimate eg = mc_welford_estimate(&good), eb = mc_welford_estimate(&bad);
    printf("importance over the film's directions / (W H): %.6f +- %.6f; without the lens "
           "cosine %.6f +- %.6f\n", eg.value, eg.std_error, eb.value, eb.std_error);
    assert_z_below("importance integrates to 1 per pixel", eg.value, 1.0, eg.std_error, 4.0, seed);
    if (!negctl_record(nc, "importance without the lens cosine", "normalisation z-test",
                       fabs(eb.value - 1.0) / eb.std_error > 4.0))
        fail_msg("the importance without the lens cosine was not caught");

    /* The density per unit area through the weights. */
    hand_path h = weight_path(0);
    rt_material white = rt_lambertian(vec3_make(0.73, 0.73, 0.73));
    rt_bdpt_vertex x[3];
    renderer_path(&h, s, &c, &white, x);
    double w1 = rt_bdpt_mis_weight(&c, x, 3, 1), w2 = rt_bdpt_mis_weight(&c, x, 3, 2);
    /* w1 / w2 = p_1 / (c p_2) with c the splat's scale (render/bdpt.h),
     * p_1 = pL pcam and p_2 = pL pemit. */
    double recovered = cosine_area_pdf(h.p[0], h.nrm[0], h.p[1], h.nrm[1]) *
                       RT_BDPT_DIRECT_SPLAT_SCALE * (w1 / w2);
    double want = camera_area_pdf(&cp, film, h.p[1], h.nrm[1]);
#if VALUES_BREAK == 2
    want = camera_area_pdf(&cp, 4.0 * half_h * half_h, h.p[1], h.nrm[1]);
#endif
    double square = camera_area_pdf(&cp, 4.0 * half_h * half_h, h.p[1], h.nrm[1]);
    printf("camera density per unit area at the floor point: %.10g, closed form %.10g "
           "(square film: %.10g)\n", recovered, want, square);
    assert_true(rel_err(recovered, want) < 1e-10);
    if (!negctl_record(nc, "the camera density of a square film", "density per unit area",
                       rel_err(recovered, square) > 1e-3))
        fail_msg("the square film's density was not told apart");
    rt_scene_destroy(s);
}

/* --- the furnace at the largest depth --------------------------------- */

/* The furnace of these tests: albedo 0.9, so that paths of every length
 * up to the deepest matter (0.9^63 = 1.3e-3 of the first bounce's). */
#define FURNACE_E 0.5
#define FURNACE_RHO 0.9
enum { FURN_W = 8, FURN_H = 6, FURN_BATCHES = 8 };

/* The radiance of paths of exactly k segments, E rho^(k - 1), and of all
 * paths of at most D, the partial geometric sum E (1 - rho^D) / (1 - rho):
 * every bounce inside the closed furnace reflects rho of what arrives. */
static double furnace_exact_length(int k) { return FURNACE_E * pow(FURNACE_RHO, k - 1); }

static double furnace_exact_upto(int depth)
{
    return FURNACE_E * (1.0 - pow(FURNACE_RHO, depth)) / (1.0 - FURNACE_RHO);
}

/* The mean over the image of one render of the furnace. */
static double furnace_render(const rt_scene *f, rt_camera_params cp, rt_path_settings ps,
                             uint64_t spp, uint64_t seed, rt_image *img)
{
    rt_render_job job = rt_render_job_default(f, rt_camera_make(cp, FURN_W, FURN_H));
    job.path = ps;
    job.spp = spp;
    job.seed = seed;
    job.threads = 2;
    rt_render_stats st;
    assert_int_equal(rt_render(&job, img, &st), 0);
    assert_true(st.dropped == 0);
    double sum = 0.0;
    for (int k = 0; k < FURN_W * FURN_H; k++)
        sum += img->px[k].mean[1];
    return sum / (FURN_W * FURN_H);
}

/* max_depth = RT_BDPT_MAX_DEPTH (64), which the program's --max-depth
 * allows the splatting strategies and no more (rt_bdpt_strategy_parse
 * refuses a subpath past it). The strategies (s, t) with t >= 2 join two
 * points of the sphere, whose geometry term cos cos / d^2 is 1 / (4 R^2)
 * for every chord: each such estimate is exactly E rho^(s + t - 2), so
 * (0, 65), (1, 64) and (32, 33) must give E rho^63 in every pixel to a
 * relative 1e-9 (rounding only). The weighted sum, light tracing and
 * (64, 1) (a splat of the 64th light vertex) are random: FURN_BATCHES
 * renders of 8 x 6 pixels (4 spp weighted, 16 otherwise; seeds 2201 and
 * on), statistic t = (mean of the image means - exact) / their standard
 * error against Student's t with 7 degrees of freedom, Sidak-corrected
 * over the 3 tests at a family false-alarm level of 1e-3 (|t| < 6.50).
 * Negative control: the deterministic strategies against the closed form
 * one depth short (E rho^62) must fail. */
static void test_furnace_at_largest_depth(void **state)
{
    negctl *nc = *state;
    int depth = RT_BDPT_MAX_DEPTH;
    rt_path_settings probe = rt_path_settings_default(RT_MIXTURE);
    assert_true(rt_bdpt_strategy_parse("bdpt:64,1", &probe));
    assert_true(rt_bdpt_strategy_parse("bdpt:0,65", &probe));
    assert_false(rt_bdpt_strategy_parse("bdpt:65,1", &probe));
    assert_false(rt_bdpt_strategy_parse("bdpt:0,66", &probe));
    rt_camera_params cp;
    rt_scene *f = rt_scene_furnace(FURNACE_E, FURNACE_RHO, &cp);
    assert_non_null(f);
    rt_image *img = rt_image_create(FURN_W, FURN_H);
    double exact_k = furnace_exact_length(depth), short_k = furnace_exact_length(depth - 1);
#if VALUES_BREAK == 3
    exact_k = short_k;
#endif
    static const int st_pairs[3][2] = {{0, 65}, {1, 64}, {32, 33}};
    bool short_caught = true;
    for (int i = 0; i < 3; i++) {
        rt_path_settings ps = rt_path_settings_default(RT_BDPT);
        ps.max_depth = depth;
        ps.bdpt_s = st_pairs[i][0];
        ps.bdpt_t = st_pairs[i][1];
        furnace_render(f, cp, ps, 2, 2200u, img);
        double worst = 0.0;
        for (int k = 0; k < FURN_W * FURN_H; k++)
            worst = fmax(worst, rel_err(img->px[k].mean[1], exact_k));
        short_caught = short_caught && rel_err(img->px[0].mean[1], short_k) > 1e-9;
        printf("furnace bdpt:%d,%d at depth %d: pixel 0 %.15g, E rho^63 %.15g, largest relative "
               "error %.2e\n", ps.bdpt_s, ps.bdpt_t, depth, img->px[0].mean[1], exact_k, worst);
        assert_true(worst < 1e-9);
    }
    if (!negctl_record(nc, "furnace closed form one depth short", "deterministic strategies",
                       short_caught))
        fail_msg("E rho^62 was not told from E rho^63");

    uint64_t seed = mc_test_seed(2201u);
    double thr = gsl_cdf_tdist_Qinv(0.5 * mc_sidak_alpha(1e-3, 3), FURN_BATCHES - 1);
    for (int i = 0; i < 3; i++) {
        rt_path_settings ps = rt_path_settings_default(i == 1 ? RT_LIGHTTRACE : RT_BDPT);
        ps.max_depth = depth;
        double exact = furnace_exact_upto(depth);
        if (i == 2) {
            ps.bdpt_s = 64;
            ps.bdpt_t = 1;
            exact = furnace_exact_length(depth);
        }
#if VALUES_BREAK == 3
        exact = i == 2 ? furnace_exact_length(depth - 1) : furnace_exact_upto(depth) * 1.05;
#endif
        mc_welford acc = mc_welford_init();
        for (int b = 0; b < FURN_BATCHES; b++)
            mc_welford_add(&acc, furnace_render(f, cp, ps, i == 0 ? 4 : 16,
                                                seed + 10u * (uint64_t)i + (uint64_t)b, img));
        mc_estimate e = mc_welford_estimate(&acc);
        double t = (e.value - exact) / e.std_error;
        printf("furnace %s at depth %d: %.6g +- %.2g, exact %.6g, |t| %.2f (threshold %.2f)\n",
               i == 0 ? "bdpt" : i == 1 ? "lighttrace" : "bdpt:64,1", depth, e.value, e.std_error,
               exact, fabs(t), thr);
        assert_seeded(fabs(t) < thr, seed);
    }
    rt_image_destroy(img);
    rt_scene_destroy(f);
}

/* --- the rays of the families estimated apart ------------------------- */

/* The most rays one call of rt_bdpt_seen_emission with `left` segments
 * and `splits` splits can trace: a ray, then at glass both branches
 * while splits last (one fewer for each), else one branch:
 *   f(L, 0) = L,  f(L, S) = 1 + 2 f(L - 1, S - 1),
 * i.e. f(L, S) = 2^S (L - S + 1) - 1 for L >= S (2^L - 1 below): the
 * first S levels a full binary tree of 2^S - 1 rays, then 2^S chains of
 * L - S rays. A mirror (1 + f(L - 1, S)) traces fewer: 2^S - 1 fewer. */
static uint64_t seen_max(int left, int splits)
{
    if (left < 1)
        return 0;
    if (left < splits)
        return ((uint64_t)1 << left) - 1u;
    return ((uint64_t)1 << splits) * (uint64_t)(left - splits + 1) - 1u;
}

/* The scene where every ray's fate is known: a glass ball of radius 1
 * (index 1.5) inside a perfect mirror sphere of radius 2, both about the
 * origin, the camera at the origin. Every ray from the centre is radial
 * and stays radial: a radial ray meets the glass or the mirror at normal
 * incidence, where the glass's Fresnel reflectance is
 * ((1.5 - 1) / (1.5 + 1))^2 = 0.04 (in (0, 1): both branches exist) and
 * the mirror sends it straight back. Nothing is ever missed or absorbed. */
static rt_scene *radial_scene(rt_camera_params *cp)
{
    rt_scene *s = rt_scene_create();
    int glass = rt_scene_add_material(s, rt_dielectric(1.5, RT_FRESNEL_SCHLICK));
    int mirror = rt_scene_add_material(s, rt_metal(vec3_make(0.9, 0.9, 0.9), 0.0));
    vec3 o = vec3_make(0.0, 0.0, 0.0);
    rt_scene_add(s, rt_scene_sphere(s, o, 1.0, glass));
    rt_scene_add(s, rt_scene_sphere(s, o, 2.0, mirror));
    assert_int_equal(rt_scene_build(s), 0);
    *cp = (rt_camera_params){o, vec3_make(0.0, 0.0, 1.0), vec3_make(0.0, 1.0, 0.0), 60.0};
    return s;
}

/* Where a radial ray is in the radial scene: inside the glass (it meets
 * the glass from inside next), outside going out (the mirror next),
 * outside coming in (the glass from outside next). */
typedef enum radial { IN_GLASS, OUT_GOING, OUT_COMING } radial;

/* The rays rt_bdpt_seen_emission traces for a radial ray in state r with
 * `left` segments and `splits` splits to go: one for this segment, then
 * at glass both branches (reflection keeps the side, refraction crosses
 * it) while splits last, else one of them (either: every branch goes on
 * to the end); at the mirror the ray comes back. */
static uint64_t radial_rays(radial r, int left, int splits)
{
    if (left < 1)
        return 0;
    if (r == OUT_GOING)
        return 1u + radial_rays(OUT_COMING, left - 1, splits);
    radial refl = r == IN_GLASS ? IN_GLASS : OUT_GOING, refr = r == IN_GLASS ? OUT_GOING : IN_GLASS;
    if (splits == 0)
        return (uint64_t)left; /* one ray per segment to the end */
    return 1u + radial_rays(refl, left - 1, splits - 1) + radial_rays(refr, left - 1, splits - 1);
}

/* The exact ray count of a weighted render of the radial scene: W x H
 * pixels, spp samples, depth D <= RT_BDPT_MAX_DEPTH. Per pixel, the edge test traces the
 * seen term of 9 rays, c = radial_rays(IN_GLASS, D, S) each (no pixel is
 * an edge: nothing emits). Per sample: the camera subpath, D rays (it
 * never ends early), and the seen term from its first hit, c - 1 (the
 * hit itself is the subpath's); no light subpath (no emitter), no join,
 * no split rays at a Lambertian vertex (there is none). */
static uint64_t radial_render_rays(int w, int h, uint64_t spp, int depth, int splits)
{
    int d = depth;
    uint64_t c = radial_rays(IN_GLASS, d, splits), pixels = (uint64_t)w * (uint64_t)h;
    return pixels * 9u * c + pixels * spp * ((uint64_t)d + c - 1u);
}

/* The radial scene: one seen term from the centre traces exactly
 * radial_rays(IN_GLASS, D, RT_BDPT_SPLITS) rays (D = 64 and 7), and a
 * weighted render of 6 x 4 pixels, 3 spp, at depth 64 and 7 traces
 * exactly radial_render_rays; at depth 65 the render is refused (its
 * subpaths would not fit RT_BDPT_MAX_DEPTH). Negative controls:
 * the counts with one split level fewer, and without splitting, must
 * differ from the measured ones. */
static void test_seen_rays_exact(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = radial_scene(&cp);
    enum { RW = 6, RH = 4, RSPP = 3 };
    rt_camera cam = rt_camera_make(cp, RW, RH);
    int splits = RT_BDPT_SPLITS;
#if VALUES_BREAK == 4
    splits = RT_BDPT_SPLITS - 1;
#endif
    bool caught = true;
    static const int depths[2] = {RT_BDPT_MAX_DEPTH, 7};
    for (int i = 0; i < 2; i++) {
        rt_path_settings ps = rt_path_settings_default(RT_BDPT);
        ps.max_depth = depths[i];
        rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
        mc_rng rng = mc_rng_derive(2301u, (uint64_t)i);
        uint64_t seg = 0;
        vec3 L = rt_bdpt_seen_emission(&c, rt_camera_ray(&cam, 1.3, 2.6), &rng, &seg);
        uint64_t want = radial_rays(IN_GLASS, depths[i], splits);
        printf("radial scene, depth %d: one seen term traced %llu rays, model %llu, bound %llu\n",
               depths[i], (unsigned long long)seg, (unsigned long long)want,
               (unsigned long long)seen_max(depths[i], RT_BDPT_SPLITS));
        assert_true(L.x == 0.0 && seg == want && seg <= seen_max(depths[i], RT_BDPT_SPLITS));
        caught = caught && seg != radial_rays(IN_GLASS, depths[i], RT_BDPT_SPLITS - 1) &&
                 seg != (uint64_t)depths[i];
    }
    static const int render_depths[2] = {RT_BDPT_MAX_DEPTH, 7};
    rt_image *img = rt_image_create(RW, RH);
    for (int i = 0; i < 3; i++) {
        rt_render_job job = rt_render_job_default(s, cam);
        job.path = rt_path_settings_default(RT_BDPT);
        job.path.max_depth = i < 2 ? render_depths[i] : RT_BDPT_MAX_DEPTH + 1;
        job.spp = RSPP;
        job.threads = 2;
        rt_render_stats st;
        if (i == 2) { /* past the subpath buffers: refused */
            assert_int_equal(rt_render(&job, img, &st), -1);
            break;
        }
        assert_int_equal(rt_render(&job, img, &st), 0);
        uint64_t want = radial_render_rays(RW, RH, RSPP, render_depths[i], splits);
        printf("radial scene render at depth %d: %llu rays, exact %llu\n", render_depths[i],
               (unsigned long long)st.segments, (unsigned long long)want);
        assert_true(st.paths == (uint64_t)RW * RH * RSPP);
        assert_true(st.segments == want);
        caught = caught && st.segments != radial_render_rays(RW, RH, RSPP, render_depths[i],
                                                              RT_BDPT_SPLITS - 1);
    }
    if (!negctl_record(nc, "seen-term ray counts one split level short or unsplit",
                       "exact ray count", caught))
        fail_msg("a ray count with the wrong number of splits was not told apart");
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

/* The most rays of one sample of rt_bdpt_sample (weighted, seen_here) at
 * depth D (S = RT_BDPT_SPLITS): the camera subpath D, the light subpath
 * D - 1 (its start is drawn, not traced), one shadow ray per join
 * (s >= 1, t >= 2, s + t - 1 <= D: D (D - 1) / 2 of them), one per splat
 * (s = 2 .. D; (1, 1) is left out), the seen term from the first hit
 * (at most 2 f(D - 1, S - 1) = f(D, S) - 1), and the split rays at each
 * through vertex (rt_bdpt_through_vertices: Lambertian vertices with glass
 * or mirrors on both sides, so at indices 2, 4, 6, ... at the most):
 * RT_BDPT_THROUGH_RAYS_NEAR f(D - jd, S) at jd, the count near the
 * ball (RT_BDPT_THROUGH_RAYS elsewhere). */
static uint64_t sample_core(int d)
{
    uint64_t D = (uint64_t)d;
    return D + (D - 1u) + D * (D - 1u) / 2u + (D - 1u);
}

static uint64_t sample_max(int d)
{
#if VALUES_BREAK == 4
    return sample_core(d); /* the families' rays left out */
#else
    uint64_t through = 0;
    for (int jd = 2; jd < d; jd += 2)
        through += (uint64_t)RT_BDPT_THROUGH_RAYS_NEAR * seen_max(d - jd, RT_BDPT_SPLITS);
    return sample_core(d) + seen_max(d, RT_BDPT_SPLITS) - 1u + through;
#endif
}

/* The book's scene (glass sphere, lamp) at depth 64 and 6: every sample
 * of rt_bdpt_sample traces at most sample_max(D) rays, every edge term
 * rt_bdpt_seen_sample at most RT_BDPT_EDGE_SUBSAMPLES f(D, S) and every
 * edge test rt_bdpt_seen_edge at most 9 f(D, S); and a weighted render
 * (12 x 12 pixels, 2 spp) at most paths x (sample_max + 64 f(D, S)) +
 * pixels x 9 f(D, S) in its stats. 12 x 12 x 2 direct samples per depth
 * from pixel streams derived from seed 2401. Negative control: at depth
 * 6 some sample traces more rays than the subpaths, joins and splats
 * alone may (the families' rays are not negligible), and some edge term
 * more than 64 unsplit chains of D rays. */
static void test_seen_rays_bounded(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    enum { BW = 12, BSPP = 2 };
    rt_camera cam = rt_camera_make(cp, BW, BW);
    uint64_t seed = mc_test_seed(2401u);
    static const int depths[2] = {RT_BDPT_MAX_DEPTH, 6};
    rt_splats *splat = rt_splats_create(BW, BW);
    assert_non_null(splat);
    for (int i = 0; i < 2; i++) {
        int d = depths[i];
        rt_path_settings ps = rt_path_settings_default(RT_BDPT);
        ps.max_depth = d;
        rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
        uint64_t f = seen_max(d, RT_BDPT_SPLITS), most = 0, most_edge = 0, most_test = 0;
        for (int y = 0; y < BW; y++)
            for (int x = 0; x < BW; x++) {
                uint64_t idx = (uint64_t)y * BW + (uint64_t)x, seg = 0;
                rt_sampler sampler = rt_sampler_from_rng(mc_rng_derive(seed, idx));
                (void)rt_bdpt_seen_edge(&c, x, y, seed, &seg);
                most_test = seg > most_test ? seg : most_test;
                for (uint64_t k = 0; k < BSPP; k++) {
                    mc_rng aux = rt_bdpt_aux_stream(seed, idx * BSPP + k);
                    rt_ray r = rt_camera_ray(&cam, x + mc_rng_uniform(&sampler.rng),
                                             y + mc_rng_uniform(&sampler.rng));
                    seg = 0;
                    rt_bdpt_sample(&c, r, &sampler, &aux, true, splat, &seg);
                    most = seg > most ? seg : most;
                    seg = 0;
                    rt_bdpt_seen_sample(&c, x, y, seed, k, &aux, &seg);
                    most_edge = seg > most_edge ? seg : most_edge;
                }
            }
        printf("book, depth %d: most rays of a sample %llu (bound %llu), of an edge term %llu "
               "(bound %llu), of an edge test %llu (bound %llu)\n", d, (unsigned long long)most,
               (unsigned long long)sample_max(d), (unsigned long long)most_edge,
               (unsigned long long)(RT_BDPT_EDGE_SUBSAMPLES * f), (unsigned long long)most_test,
               (unsigned long long)(9u * f));
        assert_true(most <= sample_max(d));
        assert_true(most_edge <= RT_BDPT_EDGE_SUBSAMPLES * f);
        assert_true(most_test <= 9u * f);

        rt_render_job job = rt_render_job_default(s, cam);
        job.path = ps;
        job.spp = BSPP;
        job.seed = seed;
        job.threads = 2;
        rt_image *img = rt_image_create(BW, BW);
        rt_render_stats st;
        assert_int_equal(rt_render(&job, img, &st), 0);
        uint64_t bound = st.paths * (sample_max(d) + RT_BDPT_EDGE_SUBSAMPLES * f) +
                         (uint64_t)BW * BW * 9u * f;
        printf("book render, depth %d: %llu rays for %llu samples, bound %llu\n", d,
               (unsigned long long)st.segments, (unsigned long long)st.paths,
               (unsigned long long)bound);
        assert_true(st.segments <= bound);
        if (d == 6 && !negctl_record(nc, "ray bound without the families or without splits",
                                     "per-sample ray bound",
                                     most > sample_core(d) &&
                                         most_edge > (uint64_t)RT_BDPT_EDGE_SUBSAMPLES * (uint64_t)d))
            fail_msg("a bound that leaves out the families' rays was not exceeded");
        rt_image_destroy(img);
    }
    rt_splats_destroy(splat);
    rt_scene_destroy(s);
}

/* The through rays' count near the ball. First the share that chooses
 * it, rt_bdpt_target_share, at two points of the book's floor (normal up;
 * the ball stands on the floor, so it is wholly above the horizon from
 * any floor point, where (r / d)^2 cos alpha is exact): under the ball
 * beside its foot and 200 units off in x and z, against the share of
 * 2^20 cosine-distributed directions (PCG32, seed 2701) that meet the
 * ball, z = (share - hits / N) / sqrt(share (1 - share) / N), |z| < 4.42
 * each (two-sided false alarm 1e-5). Negative control: the share without
 * the cosine, (r / d)^2, must miss by more at the far point. Then the
 * count itself: with max depth jd + 1 every ray traces its first segment
 * alone, so a through term at vertex jd = 2 traces exactly its count of
 * rays: RT_BDPT_THROUGH_RAYS_NEAR at the point under the ball,
 * RT_BDPT_THROUGH_RAYS at the far one. */
static void test_through_rays_near_the_ball(void **state)
{
    negctl *nc = *state;
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_true(rt_scene_target_count(s) == 1 && rt_scene_targets(s)[0].kind == RT_PRIM_SPHERE);
    rt_light ball = rt_scene_targets(s)[0];
    vec3 up = vec3_make(0.0, 1.0, 0.0);
    vec3 pts[2] = {vec3_make(ball.center.x + 10.0, 0.0, ball.center.z + 10.0),
                   vec3_make(ball.center.x + 200.0, 0.0, ball.center.z + 200.0)};
    enum { N = 1 << 20 };
    const double thr = 4.42;
    double z_nocos = 0.0;
    mc_rng rng = mc_rng_derive(mc_test_seed(2701u), 0u);
    onb frame = onb_from_w(up);
    for (int k = 0; k < 2; k++) {
        uint64_t hits = 0;
        for (int i = 0; i < N; i++) {
            double u1 = mc_rng_uniform(&rng), u2 = mc_rng_uniform(&rng);
            vec3 dir = pdf_cosine_direction(&frame, u1, u2);
            vec3 to = vec3_sub(ball.center, pts[k]);
            double along = vec3_dot(to, dir);
            hits += along > 0.0 && vec3_length_sq(to) - along * along < ball.radius * ball.radius;
        }
        double share = rt_bdpt_target_share(s, pts[k], up), p = (double)hits / N;
        double se = sqrt(share * (1.0 - share) / N), z = (share - p) / se;
        vec3 to = vec3_sub(ball.center, pts[k]);
        double nocos = ball.radius * ball.radius / vec3_length_sq(to);
        double zn = (nocos - p) / sqrt(nocos * (1.0 - nocos) / N);
        printf("floor point %d: share %.6f, cosine directions meeting the ball %.6f, |z| %.2f "
               "(threshold %.2f); without the cosine %.6f, |z| %.1f\n",
               k, share, p, fabs(z), thr, nocos, fabs(zn));
        assert_true(fabs(z) < thr);
        if (k == 1)
            z_nocos = fabs(zn);
    }
    if (!negctl_record(nc, "the ball's share without the cosine", "cosine-weighted share z-test",
                       z_nocos >= thr))
        fail_msg("the share without the cosine was not told apart: |z| %.2f", z_nocos);

    rt_path_settings ps = rt_path_settings_default(RT_BDPT);
    ps.max_depth = 3;
    rt_camera cam = rt_camera_make(cp, 8, 8);
    rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
    const rt_material *floor_m = NULL;
    rt_hit h;
    assert_true(rt_scene_hit(s, rt_ray_make(vec3_make(pts[1].x, 100.0, pts[1].z), vec3_neg(up)),
                             HUGE_VAL, &h));
    floor_m = rt_scene_material(s, h.material);
    static const int want[2] = {RT_BDPT_THROUGH_RAYS_NEAR, RT_BDPT_THROUGH_RAYS};
    for (int k = 0; k < 2; k++) {
        rt_bdpt_vertex d = wall_vertex(pts[k], up, floor_m);
        mc_rng aux = rt_bdpt_aux_stream(2701u, (uint64_t)k);
        uint64_t seg = 0;
        (void)rt_bdpt_through_estimate(&c, &d, 2, &aux, &seg);
        printf("through term at floor point %d: %llu rays (want %d)\n", k, (unsigned long long)seg,
               want[k]);
        assert_true(seg == (uint64_t)want[k]);
    }
    rt_scene_destroy(s);
}

/* Every join of weighted renders, the joins' weights from running sums
 * (rt_bdpt_join_weight_running, what the render uses) against the same
 * weights summed over the whole path (rt_bdpt_join_weight): relative
 * difference < 1e-12 (a few hundred roundings on paths of up to 64
 * vertices). Both scenes (book: glass, its specular rules), 16 x 16
 * pixels, 4 samples each from pixel streams of seed 2501, with and without
 * Russian roulette, at depths 50 and 4 (the splat's scale on paths of three
 * vertices is in both). At least 10^3 joins each (the running sums weigh
 * paths of three vertices or more). */
static void test_running_weights_every_join(void **state)
{
    (void)state;
    static const char *const scenes[2] = {"lambert", "book"};
    enum { RW = 16, RSPP = 4 };
    uint64_t seed = mc_test_seed(2501u);
    rt_splats *splat = rt_splats_create(RW, RW);
    assert_non_null(splat);
    for (int k = 0; k < 8; k++) {
        rt_camera_params cp;
        rt_scene *s = rt_scene_named(scenes[k % 2], &cp);
        rt_camera cam = rt_camera_make(cp, RW, RW);
        rt_path_settings ps = rt_path_settings_default(RT_BDPT);
        ps.russian_roulette = (k / 2) % 2 == 1;
        ps.max_depth = k < 4 ? 50 : 4;
        rt_bdpt_weight_audit audit = {0, 0.0};
        rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
        c.audit = &audit;
        for (uint64_t idx = 0; idx < RW * RW; idx++) {
            rt_sampler sampler = rt_sampler_from_rng(mc_rng_derive(seed, idx));
            for (uint64_t j = 0; j < RSPP; j++) {
                mc_rng aux = rt_bdpt_aux_stream(seed, idx * RSPP + j);
                rt_ray r = rt_camera_ray(&cam, (double)(idx % RW) + mc_rng_uniform(&sampler.rng),
                                         (double)(idx / RW) + mc_rng_uniform(&sampler.rng));
                uint64_t seg = 0;
                rt_bdpt_sample(&c, r, &sampler, &aux, true, splat, &seg);
            }
        }
        printf("%s, roulette %s, depth %d: %llu joins weighed from running sums, largest relative "
               "difference %.2e\n",
               scenes[k % 2], ps.russian_roulette ? "on" : "off", ps.max_depth,
               (unsigned long long)audit.joins, audit.worst);
        assert_true(audit.joins >= 1000);
        assert_true(audit.worst < 1e-12);
        rt_scene_destroy(s);
    }
    rt_splats_destroy(splat);
}

/* The paths the weighted render estimates apart are exactly those only
 * s = 0 can make. For every camera subpath of the book scene that ends on
 * the lamp's emitting side (the camera aimed at the glass ball, which
 * fills the view; 64 x 64 pixels, 64 samples each from pixel streams of
 * seed 2601, depth 50, roulette off and on), the path with
 * s = 0 is estimated apart (rt_bdpt_estimated_apart over the subpath's
 * through vertices) if and only if its balance-heuristic weight
 * (rt_bdpt_join_weight) is exactly 1: dropped with any other strategy
 * able to make it, the render would lose that strategy's share; kept
 * although no other can, the split rays would add it twice. At least 10
 * of those paths must have two Lambertian vertices or more (E S+ D S+ D
 * S+ L: the ball's view of a floor that sees the lamp through the ball).
 * Negative control: the rule that knows the first through vertex alone
 * must disagree with the weights on some path. */
static void test_estimated_apart_only_s0(void **state)
{
    negctl *nc = *state;
    enum { PW = 64, PSPP = 64 };
    uint64_t seed = mc_test_seed(2601u);
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    /* The glass ball filling the view (centre (190, 90, 190), radius 90). */
    cp.lookat = vec3_make(190.0, 90.0, 190.0);
    cp.vfov_deg = 11.0;
    rt_camera cam = rt_camera_make(cp, PW, PW);
    uint64_t ends = 0, apart = 0, longer = 0, first_only_wrong = 0;
    for (int rr = 0; rr < 2; rr++) {
        rt_path_settings ps = rt_path_settings_default(RT_BDPT);
        ps.russian_roulette = rr == 1;
        rt_bdpt_ctx c = rt_bdpt_ctx_make(s, &ps, &cam);
        for (uint64_t idx = 0; idx < PW * PW; idx++) {
            rt_sampler sampler = rt_sampler_from_rng(mc_rng_derive(seed, idx));
            for (uint64_t j = 0; j < PSPP; j++) {
                rt_bdpt_vertex v[RT_BDPT_MAX_DEPTH + 1], light[RT_BDPT_MAX_DEPTH];
                v[0] = camera_vertex(&c);
                rt_ray r = rt_camera_ray(&cam, (double)(idx % PW) + mc_rng_uniform(&sampler.rng),
                                         (double)(idx / PW) + mc_rng_uniform(&sampler.rng));
                uint64_t seg = 0;
                int n = rt_bdpt_walk(&c, r, v[0].beta, v, 1, ps.max_depth + 1, 0,
                                             RT_BDPT_RR_GAIN_CAMERA, &sampler, &seg);
                int nl = rt_bdpt_light_walk(&c, &sampler, light, ps.max_depth, &seg);
                rt_bdpt_subpath_pdfs sp;
                rt_bdpt_cache_pdfs(&c, light, nl, v, n, &sp);
                int jd[RT_BDPT_MAX_DEPTH + 1];
                int njd = rt_bdpt_through_vertices(v, n, jd);
                for (int t = 2; t <= n; t++) {
                    const rt_bdpt_vertex *z = &v[t - 1];
                    if (!z->m || z->m->kind != RT_MAT_LIGHT || !z->front_face)
                        continue;
                    ends++;
                    bool only_s0 = rt_bdpt_join_weight(&c, &sp, light, 0, v, t) == 1.0;
                    bool is_apart = rt_bdpt_estimated_apart(&ps, v, t, jd, njd);
                    if (is_apart != only_s0)
                        fail_msg("pixel %llu sample %llu, t = %d: estimated apart %d, weight 1 %d",
                                 (unsigned long long)idx, (unsigned long long)j, t, is_apart,
                                 only_s0);
                    apart += is_apart;
                    longer += is_apart && njd >= 2 && jd[1] < t - 1;
                    first_only_wrong +=
                        rt_bdpt_estimated_apart(&ps, v, t, jd, njd < 1 ? njd : 1) != only_s0;
                }
            }
        }
    }
    printf("book, %d x %d pixels x %d samples, twice: %llu camera subpaths on the lamp, %llu of them "
           "estimated apart, %llu with two Lambertian vertices or more; the first through vertex alone "
           "disagrees on %llu\n",
           PW, PW, PSPP, (unsigned long long)ends, (unsigned long long)apart,
           (unsigned long long)longer, (unsigned long long)first_only_wrong);
    assert_true(longer >= 10);
    if (!negctl_record(nc, "the first through vertex alone", "estimated apart iff only s = 0",
                       first_only_wrong > 0))
        fail_msg("the rule of the first through vertex alone agreed with the weights");
    rt_scene_destroy(s);
}

/* The segment shared by a join's readers (rt_bdpt_segment) against each
 * reader computing its own, bit for bit, over 10^5 point pairs from PCG32
 * stream (seed 77, stream 1): coordinates uniform in [-600, 600] times a
 * power of two from 2^-8 to 2^8, normals uniform on the sphere. Made from
 * either end, the lengths are the same bits, the directions negatives of
 * each other and vec3_normalize's, and a normal's |cos| against d the
 * same: what lets one segment serve the densities at both ends. Control:
 * the direction as d divided by the length component by component, not
 * times its reciprocal, must differ from vec3_normalize in some pair. */
static bool same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static void test_segment_both_ends_same_bits(void **state)
{
    negctl *nc = *state;
    mc_rng rng;
    mc_rng_seed(&rng, 77u, 1u);
    long bad = 0, control_differs = 0;
    for (int k = 0; k < 100000; k++) {
        vec3 p[2], n;
        for (int e = 0; e < 2; e++) {
            double scale = ldexp(1.0, (int)(mc_rng_uniform(&rng) * 17.0) - 8);
            p[e] = vec3_make((2.0 * mc_rng_uniform(&rng) - 1.0) * 600.0 * scale,
                             (2.0 * mc_rng_uniform(&rng) - 1.0) * 600.0 * scale,
                             (2.0 * mc_rng_uniform(&rng) - 1.0) * 600.0 * scale);
        }
        double z = 2.0 * mc_rng_uniform(&rng) - 1.0, phi = 2.0 * MC_PI * mc_rng_uniform(&rng);
        double r = sqrt(1.0 - z * z);
        n = vec3_make(r * cos(phi), r * sin(phi), z);
        rt_bdpt_segment ab = rt_bdpt_segment_make(p[0], p[1]), ba = rt_bdpt_segment_make(p[1], p[0]);
        vec3 alone = vec3_normalize(vec3_sub(p[1], p[0]));
        vec3 back = vec3_normalize(vec3_sub(p[0], p[1]));
        double dist = vec3_length(vec3_sub(p[1], p[0]));
        bool ok = same_bits(ab.dist, ba.dist) && same_bits(ab.dist, dist) &&
                  same_bits(ab.dist_sq, ba.dist_sq) && same_bits(ab.dir.x, alone.x) &&
                  same_bits(ab.dir.y, alone.y) && same_bits(ab.dir.z, alone.z) &&
                  same_bits(-ab.dir.x, back.x) && same_bits(-ab.dir.y, back.y) &&
                  same_bits(-ab.dir.z, back.z) &&
                  same_bits(fabs(vec3_dot(n, ab.d)), fabs(vec3_dot(n, vec3_sub(p[0], p[1])))) &&
                  same_bits(vec3_dot(n, vec3_neg(ab.dir)), vec3_dot(n, back));
        bad += !ok;
        vec3 divided = vec3_make(ab.d.x / ab.dist, ab.d.y / ab.dist, ab.d.z / ab.dist);
        control_differs += !(same_bits(divided.x, alone.x) && same_bits(divided.y, alone.y) &&
                             same_bits(divided.z, alone.z));
    }
    printf("segment from either end: %ld of 100000 pairs differ from each end alone; "
           "dividing by the length differs in %ld\n",
           bad, control_differs);
    assert_int_equal(bad, 0);
    if (!negctl_record(nc, "the direction divided by the length", "segment bits",
                       control_differs > 0))
        fail_msg("dividing by the length gave vec3_normalize's bits in every pair");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mis_weights_by_hand),
        cmocka_unit_test(test_running_weights_every_join),
        cmocka_unit_test(test_segment_both_ends_same_bits),
        cmocka_unit_test(test_estimated_apart_only_s0),
        cmocka_unit_test(test_camera_importance_and_density),
        cmocka_unit_test(test_furnace_at_largest_depth),
        cmocka_unit_test(test_seen_rays_exact),
        cmocka_unit_test(test_seen_rays_bounded),
        cmocka_unit_test(test_through_rays_near_the_ball),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_render_values", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
