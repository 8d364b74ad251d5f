/* tests/support/real_samplers.h - light and lobe samplers as a renderer
 * writes them, written here from the published mathematics, to try the
 * public check (check/check.h) where real sampling code lives: densities
 * with jumps (spherical triangles and rectangles, cones) and narrow lobes
 * (von Mises-Fisher, Beckmann). Serves chapter 15, Testing Your Own Sampler.
 *
 * Every sampler maps two uniforms in [0, 1) to a unit direction and claims
 * a density per unit solid angle, as mcbox_sampler callbacks; it reports
 * that claimed density as the sample's pdf. Each correct one has wrong
 * twins (a density 0.5% too high, a lobe drawn with the wrong width, the
 * classic slips) that the check must reject.
 *
 * The same samplers answer mcbox-check's --exec protocol
 * (docs/check-protocol.md) through rs_serve, and write sample files for
 * --samples through rs_write_samples, so that one sampler meets all three
 * doors.
 */
#ifndef RS_REAL_SAMPLERS_H
#define RS_REAL_SAMPLERS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "check/check.h"
#include "mc/vec3.h"

/* The shapes behind the samplers; the wrong twins share the shape of the
 * sampler they imitate, so they meet the same charts. */
typedef enum rs_shape_kind {
    RS_TRIANGLE, /* the triangle v[0], v[1], v[2] seen from 0 (any lengths) */
    RS_RECT,     /* a rectangle corner v[0], edges v[1], v[2] (orthogonal), seen from 0 */
    RS_CONE,     /* directions within acos(cos_max) of axis */
    RS_VMF,      /* von Mises-Fisher about axis, concentration kappa */
    RS_BECKMANN  /* Beckmann microfacet normals about +z, roughness alpha */
} rs_shape_kind;

typedef struct rs_shape {
    rs_shape_kind kind;
    vec3 v[3];
    vec3 axis;      /* any length */
    double cos_max; /* RS_CONE */
    double kappa;   /* RS_VMF */
    double alpha;   /* RS_BECKMANN */
} rs_shape;

/* The charts a sampler is checked on. */
typedef enum rs_chart {
    RS_CHART_SPHERE,     /* MCBOX_SPHERE, the default (cos theta, phi) chart */
    RS_CHART_HEMISPHERE, /* MCBOX_HEMISPHERE, default chart */
    RS_CHART_POLYGON,    /* MCBOX_SPHERICAL_TRIANGLE or MCBOX_SPHERICAL_QUAD of the shape */
    RS_CHART_CAP,        /* MCBOX_CAP of the cone */
    RS_CHART_LOBE        /* the sphere (hemisphere for Beckmann) with a lobe chart about
                            the shape's axis, of the shape's width */
} rs_chart;

#define RS_MAX_CHARTS 3

typedef struct rs_sampler {
    const char *name;  /* one word: the --exec server's argument */
    const char *what;  /* the algorithm and its source */
    const char *wrong; /* NULL for a correct sampler; else its error */
    const rs_shape *shape;
    /* ctx is the rs_sampler itself. */
    void (*sample)(const double *u, mcbox_sample *out, void *ctx);
    double (*pdf)(const double *x, void *ctx); /* the claimed density, per unit solid angle */
    double pdf_scale; /* the claimed density is the true one times this (1: correct) */
    double draw;      /* the lobe's kappa or alpha the sampler draws with (0: the shape's) */
    int slip;         /* 0: none; 1: the second coordinate uniform in angle, not in cos */
    int n_charts;
    rs_chart charts[RS_MAX_CHARTS]; /* charts[0] is the natural one */
} rs_sampler;

size_t rs_count(void);
const rs_sampler *rs_at(size_t i);
const rs_sampler *rs_find(const char *name); /* NULL when unknown */

/* The chart's name for tables: "sphere", "polygon", "cap", "lobe", ... */
const char *rs_chart_name(rs_chart c);

/* s as an mcbox_sampler on chart c; *o gets the chart's lobe options (the
 * other options are left as they are). */
mcbox_sampler rs_mcbox_sampler(const rs_sampler *s, rs_chart c, mcbox_check_options *o);

/* The mcbox-check options that select chart c for s ("--domain cap
 * --param axis=x,y,z --param cos_max=c", "--domain sphere --lobe-width w
 * --lobe-axis x,y,z", ...). The length written (truncated to size). */
size_t rs_cli_args(const rs_sampler *s, rs_chart c, char *buf, size_t size);

/* --- the shapes' own mathematics, for their tests ------------------------ */

/* The solid angle of the spherical triangle with unit vertices a, b, c by
 * Van Oosterom and Strackee (1983) [@vanoosterom1983]: tan(Omega / 2) = |a . (b x c)| /
 * (1 + a.b + b.c + c.a). */
double rs_triangle_solid_angle(vec3 a, vec3 b, vec3 c);

/* The solid angle of the shape's support: the triangle's or rectangle's
 * (as Urena et al. compute it), the cone's 2 pi (1 - cos_max); 4 pi for
 * the lobes. */
double rs_shape_solid_angle(const rs_shape *sh);

/* Whether the unit direction w lies in the triangle or rectangle (as seen
 * from the origin) or the cone; true for the lobes. */
bool rs_shape_contains(const rs_shape *sh, vec3 w);

/* --- the doors ------------------------------------------------------------ */

/* Answers mcbox-check's --exec protocol for s on `in` and `out` until EOF:
 * hello, sample (two uniforms a line: the point and its claimed pdf) and
 * pdf (the claimed density at a direction, normalized first). Returns 0 at
 * EOF, 2 (with "error ..." written and a line on stderr) on a command it
 * does not serve or a malformed line. */
int rs_serve(const rs_sampler *s, FILE *in, FILE *out);

/* Writes n samples of s to f, from the uniforms mcbox_check_run draws
 * with `seed` (so a file checked with --samples holds the points the C
 * door and --exec get): as text lines "x y z" (%.17g) or, with f64, as
 * raw little-endian doubles. Returns 0, or -1 when writing fails. */
int rs_write_samples(const rs_sampler *s, uint64_t n, uint64_t seed, bool f64, FILE *f);

/* The command-line modes every program holding these samplers offers:
 *   PROG serve NAME                 the --exec protocol for NAME
 *   PROG sample NAME N SEED [f64]   a sample file on stdout
 * Returns the exit status when argv is one of these, -1 when it is not. */
int rs_main(int argc, char **argv);

#endif /* RS_REAL_SAMPLERS_H */
