/* catalog/catalog.h - the sampler catalog: one row per warp of samplers/
 * and per pdf object of pdf/, with everything a program or a test needs to
 * know about it.
 *
 * A row gives the warp's stable name, its domain and the measure its
 * density is per unit of, its parameters (key, default, valid range), how
 * to sample it (from uniforms, or from a generator), its density, its
 * inverse and support where it has them, the chart in which its goodness
 * of fit is histogrammed, and the named parameter sets the test suite and
 * the benchmark run. `warp`, `sphere_plot`, `plotdata_chi2`,
 * `bench_samplers`, the chapter programs that estimate integrals over
 * directions (cat_integrate) and the tests of the samplers and of the pdf
 * objects all iterate this one table, so adding a sampler is adding a row.
 * Serves this book's #ch-integration to #ch-mixture (every sampler and
 * density they use) and #ch-own-sampler; the layer sits above pdf/ and
 * below the programs.
 *
 * Nothing here prints or allocates; errors come back as messages.
 */
#ifndef CAT_CATALOG_H
#define CAT_CATALOG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mc/gof.h"
#include "mc/rng.h"
#include "pdf/chart.h"
#include "pdf/experiments.h"
#include "pdf/pdf.h"
#include "samplers/discrete.h"

/* At most this many weights for `discrete` and `alias`. */
#define CAT_MAX_WEIGHTS 256
/* At most this many parameters per row and named cases per row. */
#define CAT_MAX_PARAMS 5
#define CAT_MAX_CASES 5

/* How a point is written and read: a direction as x y z, a point of a
 * surface in space as x y z, a planar point as x y, a real as x, a
 * discrete outcome as its index. */
typedef enum cat_point { CAT_DIRECTION, CAT_POINT, CAT_PLANAR, CAT_REAL, CAT_INDEX } cat_point;

/* Every parameter any row takes; a row accepts only its own. */
typedef struct cat_values {
    double n;          /* phong exponent */
    double alpha;      /* ggx roughness */
    double cos_max;    /* cone */
    double w;          /* mixture: weight of the cosine pdf */
    vec3 normal;       /* cosine-pdf and mixture: the cosine lobe's axis (any length > 0) */
    vec3 corner, u, v; /* parallelogram, quad-light, light-list, mixture: the parallelogram */
    vec3 center;       /* sphere-surface, sphere-light, light-list: the sphere */
    double radius;
    double weights[CAT_MAX_WEIGHTS];
    size_t n_weights; /* discrete and alias */
} cat_values;

/* A parameter: a number in a range, a vector x,y,z, or a list of numbers. */
typedef enum cat_param_kind { CAT_NUMBER, CAT_VECTOR, CAT_LIST } cat_param_kind;

typedef struct cat_param {
    const char *key;     /* NULL ends a row's list */
    cat_param_kind kind;
    size_t offset;       /* of the value in cat_values */
    const char *def;     /* the default, as written on a command line */
    double lo, hi;       /* CAT_NUMBER: the valid range ... */
    bool lo_open, hi_open; /* ... with its open ends */
} cat_param;

/* How goodness of fit histograms a row's points: x on [lo, hi]; an index
 * k as k + 1/2 on [0, count]; a planar point as (x, y) on [0, 1]^2; a disc
 * point as (r^2, phi), where d area = d(r^2) d phi / 2; a point of the
 * parallelogram corner + a u + b v as (a, b) on [0, 1]^2, where
 * d area = |u x v| da db; a point of a sphere's surface as (cos theta, phi)
 * about its centre, where d area = r^2 d(cos theta) d phi; a direction in
 * a chart of pdf/chart.h (the state's); for a lobe about an axis (+z by
 * default), as x = theta / (theta + s) and phi over [0, x(theta_max)] x
 * [0, 2 pi], which spreads a lobe of width about s over many cells; or, for
 * the directions toward a triangle or parallelogram seen from the origin,
 * as the polygon's own coordinates (a, b) on [0, 1]^2 (see
 * cat_use_polygon_chart), whose edges are then cell edges. */
typedef enum cat_chart_kind {
    CAT_CHART_LINE,
    CAT_CHART_INDEX,
    CAT_CHART_XY,
    CAT_CHART_DISC,
    CAT_CHART_PARALLELOGRAM,
    CAT_CHART_SURFACE,
    CAT_CHART_DIRECTION,
    CAT_CHART_LOBE,
    CAT_CHART_POLYGON
} cat_chart_kind;

typedef struct cat_state cat_state;

/* A named parameter set the test suite and the benchmark run: the
 * parameters as on a command line ("n=40", NULL for the defaults), the
 * test's histogram resolution ({0, 0}: the chart's) and lobe width (0: the
 * row's chart), and the fixed seed of its checks: the base seed of its
 * test group and its position there (tests/support/warp_check.h hashes
 * the two). */
typedef struct cat_case {
    const char *name; /* NULL ends a row's list */
    const char *params;
    int cells[2];
    double lobe_width;
    uint64_t seed;
    int seq;
} cat_case;

typedef struct cat_row {
    const char *name, *domain, *measure;
    const char *family; /* the samplers/ or pdf/ module, which test program runs its cases */
    cat_point point;
    cat_param params[CAT_MAX_PARAMS + 1];
    /* Builds what the parameters imply (tables, pdf objects, the chart)
     * after the ranges are checked, or NULL; false with a message. */
    bool (*prepare)(cat_state *s, char *err, size_t errlen);
    /* Sampling: `uniforms` (1, 2 or 4) uniforms per point through
     * sample_u, or, when uniforms is 0, sample_rng. */
    int uniforms;
    void (*sample_u)(const cat_state *s, const double *u, double x[3]);
    void (*sample_rng)(const cat_state *s, mc_rng *rng, double x[3]);
    /* The density at x per unit of the measure (0 outside the support). */
    double (*pdf)(const cat_state *s, const double x[3]);
    /* The (u1, u2) that sample_u maps to x, or NULL. */
    void (*invert)(const cat_state *s, const double x[3], double u[2]);
    /* Whether x lies in the support, or NULL for the chart's rectangle
     * (a direction: cos theta >= its lower end). */
    bool (*in_support)(const cat_state *s, const double x[3]);
    /* The density may be exactly 0 on the horizon z = 0 (cosine lobes), and
     * infinite on the polar axis (uniform in theta, 1 / sin theta). */
    bool rim_zero, pole_infinite;
    cat_chart_kind chart;
    double lo, hi; /* LINE: the interval; DIRECTION: cos theta from lo about +z by default */
    /* A negative control (catalog/negatives.c): what is wrong with it;
     * NULL for every real sampler. */
    const char *wrong;
    cat_case cases[CAT_MAX_CASES + 1];
} cat_row;

/* What cat_prepare builds. It holds pointers into itself (the mixture's
 * components, the tables' storage): do not copy it after cat_prepare. */
struct cat_state {
    const cat_row *row;
    cat_values p;
    pdf uniform, cosine, quad, sphere, mixture, list;
    const pdf *object; /* the pdf object a pdf row samples */
    const pdf *parts[2]; /* the mixture's components, or the list's items */
    double mix_weights[2];
    smp_discrete_cdf cdf;
    double cdf_storage[CAT_MAX_WEIGHTS];
    smp_alias alias;
    smp_alias_cell alias_storage[CAT_MAX_WEIGHTS];
    cat_chart_kind chart;
    pdf_chart dir_chart; /* DIRECTION */
    double lobe_width;   /* LOBE */
    double lobe_theta_max; /* LOBE: the largest angle to the axis covered, pi/2 or pi */
    bool lobe_rotated;   /* LOBE: about lobe_frame.n rather than +z */
    onb lobe_frame;
    bool poly_triangle;  /* POLYGON: a triangle (else a parallelogram) ... */
    vec3 poly_corner, poly_e1, poly_e2; /* ... corner + a e1 + a b e2, or corner + a e1 + b e2 */
};

/* The number of rows and the i-th (0 <= i < count), in `warp list` order. */
size_t cat_count(void);
const cat_row *cat_at(size_t i);

/* The negative controls: rows wrong on purpose (their `wrong` says how),
 * which every check must reject. Not among cat_count's rows. */
size_t cat_negative_count(void);
const cat_row *cat_negative_at(size_t i);

/* The row called `name` (a negative control's too), or NULL; the case called `name` of any row, or
 * NULL (its row in *row). */
const cat_row *cat_find(const char *name);
const cat_case *cat_find_case(const char *name, const cat_row **row);

/* The number of coordinates of a point: 3, 3, 2, 1 or 1. */
int cat_point_dims(const cat_row *r);

/* "key=default ..." into buf, "-" for a row without parameters; as
 * snprintf, at most size bytes with the terminator (buf may be NULL when
 * size is 0), and the length of the whole text is returned: a result
 * >= size says the text was cut. */
size_t cat_param_defaults(const cat_row *r, char *buf, size_t size);

/* Sets every parameter of *p to the row's defaults. */
void cat_defaults(const cat_row *r, cat_values *p);

/* Applies one "key=value" assignment (a number, a comma triple, or a comma
 * list of weights). False with a message in err for an unknown key or a
 * malformed value. */
bool cat_set_param(const cat_row *r, cat_values *p, const char *assignment, char *err,
                   size_t errlen);

/* Checks the parameters against their ranges, then builds *s. False with
 * a message in err otherwise. */
bool cat_prepare(const cat_row *r, const cat_values *p, cat_state *s, char *err, size_t errlen);

/* The row called `name` with its defaults, prepared into *s. False with a
 * message in err for an unknown name. */
bool cat_prepare_named(const char *name, cat_state *s, char *err, size_t errlen);

/* cat_defaults, the case's assignments and cat_prepare in one call. */
bool cat_prepare_case(const cat_row *r, const cat_case *c, cat_state *s, char *err,
                      size_t errlen);

/* One sample into x[0..dims) (x[dims..3) are set to 0, except that an
 * index row leaves in x[1] the uniform in [0, 1) its table had left over,
 * samplers/discrete.h). */
void cat_sample(const cat_state *s, mc_rng *rng, double x[3]);

/* The density at x[0..dims) with respect to the row's measure (for an
 * index, its probability). Directions must be unit length. */
double cat_pdf(const cat_state *s, const double x[3]);

/* The estimate of the integral of f over the directions of a direction
 * row (per unit solid angle) from n >= 1 directions drawn from s: the mean
 * of f(d) / cat_pdf(d), its variance per sample and its standard error.
 * A direction of density 0 contributes 0 (unbiased only if f vanishes
 * wherever the density does: the caller's contract). */
mc_estimate cat_integrate(pdf_fn f, const cat_state *s, mc_rng *rng, uint64_t n);

/* Uses the lobe chart of width `width` (> 0) for a direction row about +z
 * over the hemisphere z >= 0. */
void cat_use_lobe_chart(cat_state *s, double width);

/* The lobe chart of width `width` (> 0) about the unit vector `axis`,
 * covering the angles to it up to theta_max (in (0, pi]). */
void cat_use_lobe_chart_about(cat_state *s, double width, vec3 axis, double theta_max);

/* The chart of the directions from the origin toward a polygon: the
 * triangle with corners a, a + e1, a + e1 + e2 (triangle true; the point
 * of chart point (x, y) is a + x e1 + x y e2, so that d area =
 * x |e1 x e2| dx dy) or the parallelogram a + x e1 + y e2 (d area =
 * |e1 x e2| dx dy). A direction's solid angle element is d area times
 * |cos| / r^2 at the polygon's point. The plane must miss the origin. */
void cat_use_polygon_chart(cat_state *s, bool triangle, vec3 a, vec3 e1, vec3 e2);

/* The chart point of x, and the density of the chart's rectangle at a
 * chart point (the row's density times the chart's Jacobian). */
void cat_chart_point(const cat_state *s, const double x[3], double out[2]);
double cat_chart_density(const cat_state *s, const double c[2]);

/* The same with any density f of the row's points in place of the row's
 * own (read only, ctx passed through): the chart's Jacobian times f at the
 * point of chart point c, 0 where the chart point has no point. f is not
 * called there. */
typedef double (*cat_density_fn)(const double x[3], void *ctx);
double cat_chart_density_of(const cat_state *s, const double c[2], cat_density_fn f, void *ctx);

/* The goodness-of-fit experiment of the state: its chart's rectangle,
 * `cells` cells ({0, 0}: 50 x 100 for a 2D chart, 120 x 90 for a light's
 * plane chart; an index has one cell per outcome, a line 100), sampler
 * and density; ctx is s, which must outlive the spec. */
mc_gof_spec cat_gof_spec(const cat_state *s, const int cells[2]);

/* The same with a resolution that follows n: coarser cells keep about
 * CAT_GOF_PER_CELL samples per cell on average when n is small (the full
 * resolution suits 10^6 samples). */
#define CAT_GOF_PER_CELL 200.0
mc_gof_spec cat_gof_spec_for(const cat_state *s, uint64_t n);

#endif /* CAT_CATALOG_H */
