/* examples/common/warp_table.h - the table of samplers and pdf objects
 * behind the `warp` program: stable names, domains, measures, parameters
 * with their defaults, and for each one how to sample, how to evaluate its
 * density, and in which chart its goodness of fit is tested.
 *
 * Serves chapters 2 and 5-10: it is the command-line face of samplers/
 * and pdf/ (the plots and the book draw their points through it). Program
 * code, not a library: it still prints nothing; errors come back as messages.
 */
#ifndef APP_WARP_TABLE_H
#define APP_WARP_TABLE_H

#include <stdbool.h>
#include <stddef.h>

#include "mc/gof.h"
#include "mc/rng.h"
#include "pdf/chart.h"
#include "pdf/pdf.h"
#include "samplers/discrete.h"

/* At most this many weights for `discrete` and `alias`. */
#define WARP_MAX_WEIGHTS 256

/* How a point is written and read: a direction as x y z, a planar point as
 * x y, a real as x, a discrete outcome as its index. */
typedef enum warp_point { WARP_DIRECTION, WARP_PLANAR, WARP_REAL, WARP_INDEX } warp_point;

/* Every parameter any entry takes; an entry accepts only its own. */
typedef struct warp_params {
    double n;          /* phong exponent */
    double alpha;      /* ggx roughness */
    double cos_max;    /* cone */
    double w;          /* mixture: weight of the cosine pdf */
    vec3 corner, u, v; /* quad-light and mixture: the parallelogram */
    vec3 center;       /* sphere-light */
    double radius;     /* sphere-light */
    double weights[WARP_MAX_WEIGHTS];
    size_t n_weights; /* discrete and alias */
} warp_params;

/* What warp_prepare builds from the parameters. It holds pointers into
 * itself (the mixture's components, the tables' storage): do not copy it
 * after warp_prepare. */
typedef struct warp_state {
    warp_params p;
    pdf cosine, quad, sphere, mixture;
    const pdf *parts[2];
    double mix_weights[2];
    smp_discrete_cdf cdf;
    double cdf_storage[WARP_MAX_WEIGHTS];
    smp_alias alias;
    smp_alias_cell alias_storage[WARP_MAX_WEIGHTS];
    pdf_chart chart; /* where directions are histogrammed */
} warp_state;

typedef struct warp_entry warp_entry;

/* The number of entries and the i-th (0 <= i < count), in `list` order. */
size_t warp_count(void);
const warp_entry *warp_at(size_t i);

/* The entry called `name`, or NULL. */
const warp_entry *warp_find(const char *name);

/* The entry's name, domain, measure and "key=default ..." ("-" for none). */
const char *warp_name(const warp_entry *e);
const char *warp_domain(const warp_entry *e);
const char *warp_measure(const warp_entry *e);
const char *warp_param_defaults(const warp_entry *e);
warp_point warp_point_kind(const warp_entry *e);

/* The number of coordinates of a point: 3, 2, 1 or 1. */
int warp_point_dims(const warp_entry *e);

/* Sets every parameter of *p to the entry's defaults. */
void warp_defaults(const warp_entry *e, warp_params *p);

/* Applies one "key=value" assignment (a number, a comma triple, or a comma
 * list for weights). Returns false and writes a message to err (size
 * errlen) for an unknown key or a malformed value. */
bool warp_set_param(const warp_entry *e, warp_params *p, const char *assignment, char *err,
                    size_t errlen);

/* Checks the parameters (ranges, a non-degenerate light, a usable weight
 * array) and builds *s. Returns false with a message in err otherwise. */
bool warp_prepare(const warp_entry *e, const warp_params *p, warp_state *s, char *err,
                  size_t errlen);

/* One sample written as the point's coordinates into out[0..dims). */
void warp_sample(const warp_entry *e, const warp_state *s, mc_rng *rng, double out[3]);

/* The density at the point x[0..dims) with respect to the entry's measure
 * (for an index, its probability). Directions must be unit length. */
double warp_density(const warp_entry *e, const warp_state *s, const double x[3]);

/* The goodness-of-fit experiment of the entry: its chart, rectangle,
 * cells, sampler and density. ctx must outlive the spec. */
typedef struct warp_gof_ctx {
    const warp_entry *e;
    const warp_state *s;
} warp_gof_ctx;
/* Samples per cell, on average, that the resolution is reduced to keep
 * when n is small (the full resolution suits 10^6 samples). */
#define WARP_GOF_PER_CELL 200.0
mc_gof_spec warp_gof_spec(warp_gof_ctx *ctx, uint64_t n);

#endif /* APP_WARP_TABLE_H */
