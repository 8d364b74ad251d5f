/* mcbox/check.h - test YOUR sampler against YOUR density: the chi-square
 * goodness-of-fit test, normalization, domain, pdf-consistency and inverse
 * round-trip checks that mcbox runs on its own samplers, as an installed C
 * library (pkg-config --cflags --libs mcbox).
 *
 * A sampler maps uniforms in [0, 1) to points of a domain and claims a
 * density there. mcbox draws the uniforms (PCG32, from a seed), calls the
 * sampler, histograms its points in a chart of the domain (a rectangle in
 * which the measure of the domain is a simple density), integrates the
 * claimed density over every cell by adaptive quadrature, pools cells whose
 * expected count is below 5 and runs Pearson's test. The result carries the
 * verdict and every figure behind it.
 *
 * Three verdicts: pass, fail, and undetermined (never a pass) when the
 * check cannot decide: the quadrature's error on the density's integral
 * is above quad_error_max, a sample lies where the density is positive
 * but the quadrature found nothing, or the test passed on a chart that
 * does not resolve the density (most of the mass in one or two rows or
 * columns of cells; the warning names the lobe width and axis to pass).
 * With every verdict comes what a pass proves: the smallest relative
 * density error over a tenth of the mass that the run detects with
 * probability 0.9 (power_rel_error) and the smallest scale error the
 * normalization catches (scale_detectable).
 *
 * What a pass proves: the points follow the density you GAVE (at this
 * sample count and level, over the chart's cells), it integrates to 1, the
 * densities the sampler reported agree with it and the inverse returns the
 * uniforms. It does not prove that this density is the one you meant: a
 * sampler true to a wrong density of its own (the uniform hemisphere with
 * its own 1/(2 pi), where the cosine lobe was meant) passes. To pin the law
 * you meant, set `pdf` to THAT law and report your own density per sample
 * in `out->pdf`: the histogram is then tested against the intended law and
 * your density is compared with it at every sample (pdf_tol):
 *
 *   static void pinned_sample(const double *u, mcbox_sample *out, void *ctx)
 *   {
 *       my_sample(u, out->x);
 *       out->pdf = my_pdf(out->x);            // your density, compared
 *   }
 *   static double cosine_law(const double *x, void *ctx)
 *   {
 *       return x[2] > 0.0 ? x[2] / 3.14159265358979323846 : 0.0; // the law meant
 *   }
 *   s.sample = pinned_sample, s.pdf = cosine_law;
 *
 * Run it beside the check against your own density: the two verdicts
 * together say "consistent, and the law intended".
 *
 *   #include <mcbox/check.h>
 *   static void sample(const double *u, mcbox_sample *out, void *ctx) { ... }
 *   static double pdf(const double *x, void *ctx) { ... }
 *   mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
 *   s.sample = sample, s.pdf = pdf;
 *   mcbox_check_options o = mcbox_check_defaults();
 *   mcbox_check_result r;
 *   if (mcbox_check_run(&s, &o, &r, NULL) != 0) { puts(r.message); return 2; }
 *   return r.pass ? 0 : 1;
 *
 * Points: an interval point is x[0]; a planar point (square, disc,
 * triangle) is (x[0], x[1]); a direction is the unit vector (x[0], x[1],
 * x[2]). Densities are per unit length, per unit area and per unit solid
 * angle respectively.
 *
 * Nothing here prints. Every call is reentrant; the callbacks of one check
 * are called from the thread that runs it, except `pdf`, which the
 * quadrature calls from several OpenMP threads at once: it must not write
 * shared state.
 */
#ifndef MCBOX_CHECK_H
#define MCBOX_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MCBOX_VERSION_MAJOR 0
#define MCBOX_VERSION_MINOR 2
#define MCBOX_VERSION_PATCH 0

/* The library's version as "MAJOR.MINOR.PATCH" (that of the loaded library,
 * which may be newer than the header a program was compiled with). */
const char *mcbox_version(void);

/* The domain of a sampler's points, and the measure its density is per
 * unit of. */
typedef enum mcbox_domain_kind {
    MCBOX_INTERVAL,   /* x in [a, b]; per unit length */
    MCBOX_SQUARE,     /* (x, y) in [0, 1]^2; per unit area */
    MCBOX_DISC,       /* (x, y) with x^2 + y^2 <= 1; per unit area */
    MCBOX_TRIANGLE,   /* (x, y) with x, y >= 0 and x + y <= 1; per unit area */
    MCBOX_SPHERE,     /* unit (x, y, z); per unit solid angle */
    MCBOX_HEMISPHERE, /* unit (x, y, z) with z >= 0; per unit solid angle */
    MCBOX_CATALOG,    /* the domain, measure and chart of a row of mcbox's sampler
                         catalog (`mcbox warp list`), e.g. "quad-light" */
    MCBOX_CAP,        /* unit (x, y, z) with cos(angle to axis) >= cos_max: a cone of
                         directions about any axis; per unit solid angle */
    MCBOX_SPHERICAL_TRIANGLE, /* the unit directions toward the triangle with vertices
                         vertex[0..3) (seen from the origin); per unit solid angle */
    MCBOX_SPHERICAL_QUAD /* the unit directions toward the parallelogram
                         vertex[0] + a vertex[1] + b vertex[2], a, b in [0, 1] (a corner
                         and two edges, seen from the origin); per unit solid angle */
} mcbox_domain_kind;

typedef struct mcbox_domain {
    mcbox_domain_kind kind;
    double a, b;        /* MCBOX_INTERVAL: finite ends, a < b */
    const char *row;    /* MCBOX_CATALOG: the row's name */
    const char *params; /* MCBOX_CATALOG: "key=value ..." (the row's parameters), or NULL */
    double axis[3];     /* MCBOX_CAP: the cone's axis, any length > 0 */
    double cos_max;     /* MCBOX_CAP: cos of the cone's half angle, in [-1, 1) */
    double vertex[3][3];/* MCBOX_SPHERICAL_TRIANGLE: the triangle's corners; MCBOX_SPHERICAL_QUAD:
                           corner, edge u, edge v; the plane they span must miss the origin */
} mcbox_domain;

/* The number of coordinates of a point of the domain (1, 2 or 3), or 0 for
 * an unknown kind or catalog row. */
int mcbox_domain_dims(const mcbox_domain *d);

/* The domain's name as the command line spells it: "interval", "square",
 * "disc", "triangle", "sphere", "hemisphere", "catalog", "cap",
 * "spherical-triangle", "spherical-quad"; NULL for an unknown kind.
 * mcbox_domain_parse is the inverse (false when unknown). */
const char *mcbox_domain_name(mcbox_domain_kind k);
bool mcbox_domain_parse(const char *name, mcbox_domain_kind *k);

/* One sample as the sampler returns it. mcbox presets pdf and weight to
 * NaN ("not reported") and atom to -1 before every call. */
typedef struct mcbox_sample {
    double x[3];   /* the point; unused coordinates ignored */
    double pdf;    /* optional: the density at x as the sampler computed it (set it,
                      with the sampler's pdf callback set to the law you meant, to
                      pin that law: see the opening comment) */
    double weight; /* optional: the sample's weight, f(x) / pdf(x) (see eval) */
    int atom;      /* optional: k when the point is the discrete atom k (see atoms) */
} mcbox_sample;

/* A stream of uniforms, for samplers that take a variable number of them
 * (rejection sampling): mcbox_uniform returns the next, in [0, 1). */
typedef struct mcbox_stream mcbox_stream;
double mcbox_uniform(mcbox_stream *s);

/* The largest number of uniforms per sample. */
#define MCBOX_MAX_UNIFORMS 16

/* A sampler and its density. Start from mcbox_sampler_init, then set what
 * applies. */
typedef struct mcbox_sampler {
    mcbox_domain domain;
    /* Uniforms per sample, 1 .. MCBOX_MAX_UNIFORMS (default 2; 1 for an
     * interval), passed to sample; 0 to use sample_stream instead. */
    int uniforms;
    void (*sample)(const double *u, mcbox_sample *out, void *ctx);
    void (*sample_stream)(mcbox_stream *s, mcbox_sample *out, void *ctx);
    /* Required: the density of the continuous part at a point of the
     * domain, >= 0, per unit of the domain's measure. Every cell gets the
     * fixed rules described at pdf_integral_error (thread-safe, as above);
     * where they agree (a smooth cell) its probability is GSL's adaptive
     * integral, as the suite's own harness computes it. */
    double (*pdf)(const double *x, void *ctx);
    /* Alternative to pdf: the densities of n points (x: n * dims doubles)
     * into out[0 .. n). Used when pdf is NULL; then the cells' expected
     * counts come from the fixed rules alone, asked for in batches (one
     * per round of halving), and the densities at the samples in batches:
     * for a density behind a pipe, a GPU or another language. Called from
     * one thread. */
    void (*pdf_batch)(const double *x, size_t n, double *out, void *ctx);
    /* Optional: the uniforms (u[0 .. uniforms)) that sample maps to x. */
    void (*invert)(const double *x, double *u, void *ctx);
    /* Optional: f(x), the function whose ratio f / pdf the sampler reports
     * as its weight (a BSDF times the cosine, say); mcbox then compares every
     * reported weight with eval(x) / pdf(x). */
    double (*eval)(const double *x, void *ctx);
    /* Optional discrete part: n_atoms points atom_x[k * dims ...] (a mirror
     * or glass direction) drawn with probabilities atom_mass[k]; the
     * density then integrates to 1 - sum of the masses. The sampler marks
     * such a sample with out->atom = k. */
    size_t n_atoms;
    const double *atom_x;
    const double *atom_mass;
    void *ctx;
} mcbox_sampler;

/* A sampler of the domain `kind` with every callback NULL, two uniforms
 * (one for an interval, whose ends are then [0, 1]). */
mcbox_sampler mcbox_sampler_init(mcbox_domain_kind kind);

typedef struct mcbox_check_options {
    uint64_t samples;    /* >= 1; default 1,000,000 */
    uint64_t seed;       /* of the uniforms (PCG32); default 1 */
    int cells[2];        /* histogram resolution; {0, 0}: the chart's own (see below) */
    double lobe_width;   /* sphere, hemisphere, cap: > 0 histograms the angle theta to
                            lobe_axis as theta / (theta + w) and phi about it, spreading a
                            peaked lobe of width ~w (radians) over many cells; 0 (default):
                            (cos theta, phi) */
    double lobe_axis[3]; /* the lobe chart's axis, any length; {0, 0, 0} (default): +z, or
                            the cap's axis */
    double alpha;        /* family-wise significance level, in (0, 1); default 0.01 */
    int tests;           /* tests the level is shared over (Sidak): each test runs at
                            1 - (1 - alpha)^(1 / tests); default 1 */
    double norm_tol;     /* |integral of the density (plus atoms) - 1| allowed; default 1e-6 */
    double pdf_tol;      /* largest relative |reported pdf - pdf(x)| allowed; default 1e-6 */
    double weight_tol;   /* largest relative |weight - eval(x) / pdf(x)|; default 1e-6 */
    double invert_tol;   /* largest |invert(sample(u)) - u| allowed; default 1e-6 */
    int quad_order;      /* Gauss-Legendre points per axis of the fixed rules; default 8 */
    int quad_depth;      /* how many times a chart cell may be halved (per axis) where two
                            rules disagree, 0 .. 30; default 12 */
    double quad_error_max; /* the largest error estimate of the density's integral that a
                            verdict may rest on, > 0; above it the check is undetermined
                            (never a pass); default 1e-3 */
} mcbox_check_options;

/* The defaults above. */
mcbox_check_options mcbox_check_defaults(void);

/* Everything a verdict rests on. Counts are of samples. */
typedef struct mcbox_check_result {
    bool pass;
    bool undetermined;     /* the check could not decide (the quadrature's error above
                              quad_error_max, or part of the density's support it could not
                              find): never a pass; programs exit 2 */
    char message[512];     /* why it failed or is undetermined (the first failing check, with
                              the sample or cell concerned), or why the call could not run;
                              "" on pass */
    char warning[256];     /* a doubt that does not decide the verdict, "" if none: the chart
                              does not resolve the density (most of the mass in a few cells),
                              with the lobe width and axis to pass */
    double statistic;      /* Pearson's chi-square over the pooled cells */
    int dof;               /* degrees of freedom: cells in the test - 1 */
    double pvalue;         /* P(chi-square(dof) >= statistic) */
    double level;          /* the per-test level the p-value is held to (Sidak) */
    uint64_t samples;      /* samples drawn */
    uint64_t cells;        /* chart cells, plus one per atom */
    uint64_t cells_pooled; /* cells with expected count < 5 merged into one */
    uint64_t outside;      /* samples outside the domain (or its chart) */
    uint64_t nonfinite;    /* samples with a NaN or infinite coordinate */
    uint64_t in_zero_cells;/* samples in cells whose density integrates to 0 */
    uint64_t bad_atoms;    /* samples marked with an atom index out of range, or whose
                              point is not the atom's */
    uint64_t bad_pdf;      /* samples where pdf(x) is negative, NaN or infinite */
    double pdf_integral;   /* the density's integral over the domain, plus the atoms' mass */
    double pdf_integral_error; /* the quadrature's error estimate for pdf_integral, allowed on
                              top of norm_tol. Every chart cell gets the Gauss-Legendre rule
                              of quad_order points per axis and, as a check, the rule of half
                              that order on the cell cut (at 0.618 of each side) in two or
                              four, and the density is probed just inside every side; where
                              the two rules disagree or a side jumps, the cell is halved,
                              worst parts first, up to quad_depth times, until the estimate
                              falls below 1e-5 or 2^23 densities were asked for. A part's
                              estimate is 3 |its two rules' difference| plus 3 |its
                              siblings' sum - their parent's rule| shared among them, plus
                              0.03 times its measure times the larger density at each side
                              where the density drops to 0 (or by 1000x) between the
                              outermost node and the edge; with pdf, GSL's estimate on
                              smooth cells. Above quad_error_max the verdict is
                              undetermined */
    uint64_t pdf_reported; /* samples that reported their own pdf */
    double pdf_mismatch;   /* largest |reported - pdf(x)| / pdf(x) over them (0 if none) */
    uint64_t weight_reported;
    double weight_mean;    /* mean reported weight (NaN if none): E[f / pdf] = integral of f */
    double weight_mismatch;/* largest relative |weight - eval(x) / pdf(x)| (NaN without eval) */
    double invert_error;   /* largest |invert(sample(u)) - u| (NaN without invert) */
    /* What a pass proves (power). */
    double power_share;    /* the mass share s of the region in power_rel_error: 0.1 */
    double power_rel_error;/* the smallest relative error e of the density over a region
                              holding a share s of the mass (the rest rescaled to keep the
                              total) that this run's chi-square test detects with
                              probability 0.9: its noncentrality n e^2 s / (1 - s) */
    double scale_detectable; /* a density off by a constant factor 1 + e everywhere fails the
                              normalization when |e| exceeds this: norm_tol plus the
                              quadrature's error */
    uint64_t cells_90;     /* the fewest chart cells holding 90% of the expected count */
    double lobe_hint_width;/* with a warning about resolution, the lobe width (radians) to
                              pass, from the samples' spread about lobe_hint_axis; 0 if none */
    double lobe_hint_axis[3]; /* the samples' mean direction (directions only) */
} mcbox_check_result;

/* The observed and expected counts of every cell, for a picture of where
 * a sampler is wrong. Chart cell (i, j) is entry i * ny + j, with x in
 * [lo[0], hi[0]] cut into nx cells and y likewise (ny = 1 in 1D); the
 * atoms' cells follow. Filled by a check when passed non-NULL; release
 * with mcbox_check_table_free. */
typedef struct mcbox_check_table {
    int dims, nx, ny;
    double lo[2], hi[2];
    char xlabel[32], ylabel[32]; /* the chart's coordinates, "cos theta", "phi", ... */
    size_t cells;                /* nx * ny + atoms */
    double *observed, *expected;
} mcbox_check_table;
void mcbox_check_table_free(mcbox_check_table *t);

/* The short figure of a result r in buf (size bytes, always terminated),
 * in the order the check judges: non-finite samples, samples outside, bad
 * pdf values, the integral when it is off 1 by more than 1e-6, the
 * reported pdf's or the round trip's largest error when above 1e-6, else
 * the statistic, e.g. "chi2 452.29/464 dof, p = 0.643". */
void mcbox_check_figure(const mcbox_check_result *r, char *buf, size_t size);

/* Draws o->samples samples from s, checks them and fills r (and t). Returns
 * 0 when the check ran (the verdict is r->pass), -1 when it could not: an
 * invalid sampler or option, an unknown catalog row, no memory; then
 * r->message says which and r->pass is false. */
int mcbox_check_run(const mcbox_sampler *s, const mcbox_check_options *o,
                    mcbox_check_result *r, mcbox_check_table *t);

/* The same checks on points someone else drew (a GPU's buffer, a file):
 * samples[0 .. n) against s's domain, density and atoms (s->sample and
 * s->invert are not used; a sample's pdf, weight and atom fields count as
 * reported unless NaN and -1). */
int mcbox_check_points(const mcbox_sampler *s, const mcbox_sample *samples, uint64_t n,
                       const mcbox_check_options *o, mcbox_check_result *r,
                       mcbox_check_table *t);

/* The incremental form behind both, for samples that arrive in batches (a
 * pipe to another process): begin, then mcbox_check_uniforms for the next
 * sample's uniforms (the stream mcbox_check_run uses, so the statistic is
 * the same) and mcbox_check_add for the samples, then finish, which fills r
 * and t and frees c. mcbox_check_begin returns NULL with the reason in
 * r->message. mcbox_check_add returns -1 (message in r at finish) on
 * invalid input and 0 otherwise; u may be NULL (no round trip). */
typedef struct mcbox_check mcbox_check;
mcbox_check *mcbox_check_begin(const mcbox_sampler *s, const mcbox_check_options *o,
                               mcbox_check_result *r);
void mcbox_check_uniforms(mcbox_check *c, double *u);
int mcbox_check_add(mcbox_check *c, const mcbox_sample *samples, const double *u, size_t n);
int mcbox_check_finish(mcbox_check *c, mcbox_check_result *r, mcbox_check_table *t);

/* The statistics alone, for frequency tables made elsewhere (a GPU
 * histogram): observed[0 .. cells) against expected[0 .. cells) (counts,
 * expected >= 0 and finite). Pools cells below 5, runs Pearson's test at
 * the Sidak level of o, and fails on observations in cells expected to be
 * empty beyond 1e-6 of the total. Returns -1 (message in r) for invalid
 * tables. */
int mcbox_check_counts(const double *observed, const double *expected, size_t cells,
                       const mcbox_check_options *o, mcbox_check_result *r);

#ifdef __cplusplus
}
#endif

#endif /* MCBOX_CHECK_H */
