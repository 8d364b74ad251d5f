/* pdf/pdf.h - the book's pdf objects: densities of directions that can be
 * evaluated (value) and sampled (generate).
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapters 8
 * ("Mixture Densities") and 10 ("Cleaning Up pdf Management"), give every
 * density the renderer samples from the same two-function interface; its
 * chapter 7 ("Sampling Lights Directly") supplies the density toward a
 * parallelogram light, and its chapter 10 also the density toward a sphere
 * (a cone of directions) and the list of lights. This book introduces the
 * interface in #ch-scattering and builds the mixture in #ch-mixture.
 *
 * C has no class hierarchy, so a pdf is a tagged union passed by pointer.
 * Nothing here allocates: constructors return by value, and a mixture or a
 * list only points at a caller-owned array of component pointers (and
 * weights), which is typically on the caller's stack for one bounce. The
 * caller keeps those arrays and the pdfs they point to alive while the
 * composite is used.
 *
 * Every density is per unit solid angle on the unit sphere of directions.
 * Every direction passed to pdf_value must be unit length (within rounding;
 * the parallelogram and sphere densities rely on it for distances), and
 * every direction pdf_generate returns is unit length. Densities are 0 where
 * the pdf cannot generate, never NaN.
 */
#ifndef PDF_PDF_H
#define PDF_PDF_H

#include <stdbool.h>
#include <stddef.h>

#include "mc/constants.h"
#include "mc/onb.h"
#include "mc/rng.h"
#include "mc/vec3.h"
#include "samplers/cone.h"
#include "samplers/hemisphere.h"
#include "samplers/measure.h"
#include "samplers/planar.h"

typedef enum pdf_kind {
    PDF_UNIFORM_SPHERE, /* 1 / (4 pi) everywhere */
    PDF_COSINE,         /* cos(theta) / pi about a normal, 0 below it */
    PDF_TOWARD_QUAD,    /* uniform points of a parallelogram seen from a point */
    PDF_TOWARD_SPHERE,  /* uniform directions in the cone that holds a sphere */
    PDF_MIXTURE,        /* sum of weights[i] * components[i] */
    PDF_LIST            /* mixture with equal weights 1 / n */
} pdf_kind;

typedef struct pdf pdf;

/* Build pdfs with the constructors below, never by hand: they precompute
 * the fields (frames, normals, the cone's cosine and 1 - cosine). Reading
 * a field, as the tests and the chart tools do, is fine. */
struct pdf {
    pdf_kind kind;
    union {
        struct {
            onb frame; /* frame.n is the normal */
        } cosine;
        struct {
            vec3 origin, corner, u, v;
            vec3 normal;     /* unit (u x v) / |u x v| */
            vec3 w;          /* (u x v) / |u x v|^2: gives the edge coordinates */
            double inv_area; /* 1 / |u x v| */
        } quad;
        struct {
            vec3 origin, center;
            double radius;
            onb frame;            /* frame.n points from origin to center */
            double cos_theta_max; /* -1 when origin is inside or on the sphere */
            double one_minus_cos; /* 1 - cos theta_max to full relative accuracy
                                     (smp_sphere_cone_one_minus_cos); 2 inside */
        } sphere;
        struct {
            const pdf *const *components;
            const double *weights;
            size_t n;
        } mixture;
        struct {
            const pdf *const *items;
            size_t n;
        } list;
    } as;
};

/* Uniform directions over the whole sphere: value 1 / (4 pi). */
pdf pdf_uniform_sphere(void);

/* Cosine-weighted directions about `normal` (unit length): value
 * max(0, cos theta) / pi, theta measured from normal. Generated with the
 * book's mapping (samplers/hemisphere.h) carried to normal by an ONB. */
pdf pdf_cosine(vec3 normal);

/* Directions from `origin` toward uniformly distributed points of the
 * parallelogram corner + s u + t v, s, t in [0, 1] (u, v not parallel).
 * value(d) is the area density 1 / A converted to solid angle,
 * dist^2 / (|cos| A), at the point where the ray origin + r d (r > 0) meets
 * the parallelogram, and 0 when it misses. The light is two-sided (|cos|).
 * `origin` must not lie in the parallelogram's plane (every direction to
 * the light would be grazing: no density exists, and value returns 0). */
pdf pdf_toward_quad(vec3 origin, vec3 corner, vec3 u, vec3 v);

/* Directions from `origin` uniformly distributed in the cone that holds
 * the sphere (center, radius > 0): cos theta_max = sqrt(1 - R^2 / d^2)
 * about the direction to center, value 1 / (2 pi (1 - cos theta_max))
 * inside the cone and 0 outside. Every such direction hits the sphere.
 * 1 - cos theta_max is computed without cancellation (samplers/cone.h), so
 * the value stays accurate to a few ulps for arbitrarily small or distant
 * spheres (tested down to R / d = 1e-150).
 * From inside or on the sphere (d <= R) every direction hits it and the
 * pdf is uniform over the whole sphere, 1 / (4 pi) (the formula
 * cos theta_max = sqrt(1 - R^2 / d^2) of v1.123's chapter 10, and
 * sphere::pdf_value of release v1.123.0, take the square root of a
 * negative number there: NaN). */
pdf pdf_toward_sphere(vec3 origin, vec3 center, double radius);

/* BEGIN SNIPPET pdf_mixture_decl */
/* The mixture sum_i weights[i] * components[i] of n >= 1 pdfs. Weights
 * must be finite, >= 0 and sum to 1 (check with pdf_mixture_weights_valid
 * or pdf_valid): otherwise value() no longer integrates to 1 and every
 * estimate divided by it is biased by the same factor. generate() picks
 * component i with probability weights[i] and samples it; value() sums
 * over ALL components, because any component may have produced a given
 * direction (the "very important detail" of chapter 8 of Shirley's
 * v1.123; this book's #ch-mixture). The arrays are borrowed, not copied.
 * n == 0 is invalid (pdf_valid says so); such a pdf's value is 0
 * everywhere and generate() returns +z. */
pdf pdf_mixture(const pdf *const *components, const double *weights, size_t n);
/* END SNIPPET pdf_mixture_decl */

/* The equal-weight mixture of 1 <= n <= UINT32_MAX pdfs (one per light):
 * generate() picks an item uniformly, value() is the average of the
 * items' values. The array is borrowed, not copied. n == 0 is invalid
 * (pdf_valid says so); such a pdf's value is 0 everywhere and generate()
 * returns +z. */
pdf pdf_list(const pdf *const *items, size_t n);

/* BEGIN SNIPPET pdf_interface */
/* The density of direction d (unit length) per unit solid angle, >= 0 and
 * finite. */
double pdf_value(const pdf *p, vec3 d);

/* A unit direction distributed according to p, drawing uniforms from rng. */
vec3 pdf_generate(const pdf *p, mc_rng *rng);
/* END SNIPPET pdf_interface */

/* How far outside [0, 1] an edge coordinate of the parallelogram may fall
 * and still count as a hit in pdf_toward_quad's value. A direction
 * generated toward a point of the edge, normalized, and intersected with
 * the plane again comes back with a rounding error of a few ulps times
 * dist / |edge| (about 1e-12 for a light 10^4 edge lengths away); without
 * slack such a sample would get density 0. The band this admits changes
 * the density's integral by at most 4e-9 relative, invisible next to any
 * Monte Carlo error bar. render/lights.h and pdf/chart.c use the same
 * value: the renderer's densities must be the same bits as these, and the
 * chart must classify a direction as on the light exactly when value()
 * does. */
#define PDF_QUAD_EDGE_TOL 1e-9

/* The same slack for the rim of a sphere's cone, in cos theta: generated
 * directions lie at least 2^-32 (1 - cos theta_max) inside the rim, but
 * after the round trip through the ONB their cosine carries an error of
 * a few 1e-16, which is larger for cones thinner than 1 - cos = 1e-6 (a
 * sphere seen at R / d < 1.4e-3). 1e-15 covers it; the band adds at most
 * 1e-15 / (1 - cos theta_max) to the integral, so it is kept as small as
 * the round trip allows. It cannot be much smaller: a unit direction in
 * doubles carries an absolute error of ~1e-16 per component, so no test
 * in world coordinates resolves the rim more finely. (For cones with
 * 1 - cos theta_max below 1e-15, R / d below ~4.5e-8, the band is wider
 * than the cone itself: directions up to ~4.5e-8 rad off the axis get the
 * cone's density. Only another pdf of a mixture draws such a direction,
 * with a probability of at most its density times the band's solid angle
 * 2 pi 1e-15.) render/lights.h uses the
 * same value (same bits); pdf/chart.c deliberately uses a looser one for
 * classifying samples (see there). */
#define PDF_CONE_RIM_TOL 1e-15

/* The formulas of the densities, each written once. pdf_value and
 * pdf_generate use them; so does the renderer (render/lights.h), which
 * keeps the hit-point-independent constants of its lights and the
 * direction-independent ones of each hit point instead of building pdf
 * objects, and must get the same bits. Inline: the renderer calls them at
 * every diffuse hit. */

/* The constants of the parallelogram with edges u, v: its unit normal
 * (u x v) / |u x v|, w = (u x v) / |u x v|^2 (which gives the edge
 * coordinates) and 1 / area = 1 / |u x v|. A degenerate parallelogram
 * keeps zero vectors and a zero density rather than dividing by zero. */
static inline void pdf_quad_constants(vec3 u, vec3 v, vec3 *normal, vec3 *w, double *inv_area)
{
    vec3 n = vec3_cross(u, v);
    double len_sq = vec3_length_sq(n);
    *normal = len_sq > 0.0 ? vec3_scale(n, 1.0 / sqrt(len_sq)) : n;
    *w = len_sq > 0.0 ? vec3_scale(n, 1.0 / len_sq) : n;
    *inv_area = len_sq > 0.0 ? 1.0 / sqrt(len_sq) : 0.0;
}

/* BEGIN SNIPPET toward_quad */
/* The density toward the parallelogram corner + s u + t v (constants as
 * above) from origin, per unit solid angle, at the unit direction d;
 * num = normal . (corner - origin), which does not depend on d. Where the
 * ray origin + r d (r > 0) meets the parallelogram, the density 1 / A per
 * unit area becomes dist^2 / (|cos| A) per unit solid angle, because a
 * patch dA at distance dist, tilted by the angle whose cosine is cos,
 * subtends d omega = |cos| dA / dist^2 (v1.123's chapter 7; #ch-lights). */
static inline double pdf_quad_density(vec3 origin, double num, vec3 corner, vec3 u, vec3 v,
                                      vec3 normal, vec3 w, double inv_area, vec3 d)
{
    double denom = vec3_dot(normal, d);
    if (denom == 0.0)
        return 0.0;
    double r = num / denom;
    if (!(r > 0.0))
        return 0.0;
    vec3 q = vec3_sub(vec3_madd(origin, d, r), corner);
    /* With q = s u + t v and w = (u x v) / |u x v|^2: q x v = s (u x v) and
     * u x q = t (u x v), so dotting with w isolates s and t. */
    double s = vec3_dot(w, vec3_cross(q, v));
    double t = vec3_dot(w, vec3_cross(u, q));
    if (!(s >= -PDF_QUAD_EDGE_TOL && s <= 1.0 + PDF_QUAD_EDGE_TOL && t >= -PDF_QUAD_EDGE_TOL &&
          t <= 1.0 + PDF_QUAD_EDGE_TOL))
        return 0.0;
    return smp_area_to_solid_angle(inv_area, r * r, denom);
}

/* The direction from origin toward the point of the parallelogram that
 * the uniforms u1, u2 select (uniform in area). */
static inline vec3 pdf_quad_direction(vec3 origin, vec3 corner, vec3 u, vec3 v, double u1, double u2)
{
    vec3 x = smp_parallelogram_sample(u1, u2, corner, u, v);
    return vec3_normalize(vec3_sub(x, origin));
}
/* END SNIPPET toward_quad */

/* BEGIN SNIPPET toward_sphere */
/* The cone from origin that holds the sphere (center, radius): its unit
 * axis (returned; +z from the centre itself, where the cone is the whole
 * sphere and any axis will do), cos theta_max and 1 - cos theta_max
 * carried without cancellation (samplers/cone.h). */
static inline vec3 pdf_sphere_cone(vec3 origin, vec3 center, double radius, double *cos_max,
                                   double *one_minus_cos)
{
    vec3 axis = vec3_sub(center, origin);
    double dist_sq = vec3_length_sq(axis);
    *one_minus_cos = smp_sphere_cone_cap(dist_sq, radius, cos_max);
    return dist_sq > 0.0 ? vec3_scale(axis, 1.0 / sqrt(dist_sq)) : vec3_make(0.0, 0.0, 1.0);
}

/* The density of uniform directions in that cone, per unit solid angle,
 * inside it: the cap sampler's constant density (taken at its axis, which
 * is always inside). From 1 - cos theta_max carried without cancellation,
 * a far sphere's density is finite and accurate where
 * 1 / (2 pi (1 - cos theta_max)) would be +inf. */
static inline double pdf_cone_density(double one_minus_cos)
{
    return smp_uniform_cap_pdf(vec3_make(0.0, 0.0, 1.0), one_minus_cos);
}

/* Whether the unit direction d is inside the cone (unit axis, cos
 * theta_max): d . axis is its cosine in the cone's frame, and the rim gets
 * the slack PDF_CONE_RIM_TOL. */
static inline bool pdf_cone_contains(vec3 axis, double cos_max, vec3 d)
{
    return !(vec3_dot(d, axis) < cos_max - PDF_CONE_RIM_TOL);
}

/* The direction of the cone (frame.n its axis) that the uniforms u1, u2
 * select, uniform in solid angle. */
static inline vec3 pdf_cone_direction(const onb *frame, double one_minus_cos, double u1, double u2)
{
    return onb_to_world(frame, smp_uniform_cap_sample(u1, u2, one_minus_cos));
}
/* END SNIPPET toward_sphere */

/* The cosine density about the unit normal n, per unit solid angle:
 * max(0, cos theta) / pi. */
static inline double pdf_cosine_density(vec3 n, vec3 d)
{
    double cos_theta = vec3_dot(d, n);
    return cos_theta > 0.0 ? cos_theta * MC_INV_PI : 0.0;
}

/* The cosine-weighted direction about frame.n that the uniforms u1, u2
 * select (the book's mapping, samplers/hemisphere.h). */
static inline vec3 pdf_cosine_direction(const onb *frame, double u1, double u2)
{
    return onb_to_world(frame, smp_cosine_hemisphere_sample(u1, u2));
}

/* Tolerance on |sum of weights - 1| accepted by the checks below. A
 * weight sum off by 1e-9 biases an estimate by at most 1e-9 relative, far
 * below any Monte Carlo error bar, while still admitting sums such as ten
 * times 0.1 that rounding leaves at 1 - 1.1e-16. */
#define PDF_WEIGHT_SUM_TOL 1e-9

/* True when n >= 1 and the weights are finite, >= 0 and sum to 1 within
 * PDF_WEIGHT_SUM_TOL. */
bool pdf_mixture_weights_valid(const double *weights, size_t n);

/* True when p is well formed: a unit normal (1e-9), a parallelogram of
 * nonzero area whose plane does not hold the origin, a finite positive
 * radius and a cone whose density 1 / (2 pi (1 - cos theta_max)) is
 * finite, non-NULL components with valid weights, recursively (nesting
 * deeper than 16 levels, which a cycle would produce, is invalid). For
 * debug assertions in callers; pdf_value and pdf_generate do not check. */
bool pdf_valid(const pdf *p);

#endif /* PDF_PDF_H */
