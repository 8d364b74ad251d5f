/* examples/warp.c - the command-line face of samplers/ and pdf/: list the
 * warps, draw samples, evaluate densities, and test one against the other.
 *
 *   warp list                       name domain measure params # what it is
 *   warp sample NAME [--param k=v]... [--n N] [--seed S]   one point per line
 *   warp pdf NAME [--param k=v]...     points on stdin -> one density per line
 *   warp chi2 NAME [--param k=v]... [--n N] [--seed S] [--alpha A]
 *                                   prints a header "chi2 dof p verdict" and
 *                                   one line of the four values
 *   warp serve NAME [--param k=v]...   answers mcbox-check's --exec protocol
 *                                   (docs/check-protocol.md) on stdin/stdout
 *
 * Points are written and read as in `sample`: directions `x y z`, planar
 * points `x y`, reals `x`, discrete outcomes the index; numbers in %.17g.
 * The samplers are the rows of the catalog (catalog/catalog.h).
 * chi2 histograms N samples (default 1e6) in the row's chart, integrates
 * the density over every cell (mc/gof.h) and runs Pearson's test at level
 * alpha (default 0.01); the verdict is `pass` or `fail`, and the exit
 * status 0 or 1 accordingly. Any bad input: one line on stderr, exit 2.
 *
 * Build and run:  make all && build/bin/warp list
 *                 build/bin/warp sample cosine --n 5 --seed 7
 *                 build/bin/warp sample phong --param n=10 --n 3 |
 *                     build/bin/warp pdf phong --param n=10
 *                 build/bin/warp chi2 mixture --param w=0.2
 *                 build/bin/mcbox-check --exec 'build/bin/warp serve cosine' \
 *                     --domain hemisphere
 */
#define _POSIX_C_SOURCE 200809L /* getline, ssize_t */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "examples/common/exec_proto.h"
#include "catalog/catalog.h"
#include "mc/gof.h"

#define PROG "warp"
#define MAX_PARAMS 16

static const char USAGE[] =
    "usage: warp list                         (name domain measure params # density)\n"
    "       warp sample NAME [--param k=v]... [--n N] [--seed S]\n"
    "       warp pdf NAME [--param k=v]...      (points on stdin)\n"
    "       warp chi2 NAME [--param k=v]... [--n N] [--seed S] [--alpha A]\n"
    "       warp serve NAME [--param k=v]...    (mcbox-check --exec: commands on stdin)\n"
    "--samples is a synonym of --n. chi2 exits 0 on pass, 1 on fail; bad input exits 2.\n"
    "--param takes one assignment or several separated by blanks, as list prints them.\n"
    "A command refuses the options it does not take (list takes none, pdf only --param).\n"
    "pdf of discrete and alias reads outcome indices: whole numbers from 0 to k-1.\n"
    APP_NUMBER_GRAMMAR "\n";

typedef struct args {
    const char *command, *name;
    const char *params[MAX_PARAMS];
    int n_params;
    uint64_t n, seed;
    bool have_n, have_seed, have_alpha;
    double alpha;
} args;

static bool is_option(const char *a, const char *name)
{
    size_t len = strlen(name);
    return strncmp(a, name, len) == 0 && (a[len] == '\0' || a[len] == '=');
}

static args parse(int argc, char **argv)
{
    args a = {NULL, NULL, {NULL}, 0, 1000, 1, false, false, false, 0.01};
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(USAGE, stdout);
            exit(0);
        }
        if (strcmp(s, "--version") == 0) {
            printf("warp (mcbox) %s\n", APP_VERSION);
            exit(0);
        }
        if (is_option(s, "--param")) {
            if (a.n_params == MAX_PARAMS)
                app_fail(PROG, "more than %d --param options", MAX_PARAMS);
            a.params[a.n_params++] = app_option_value(PROG, argc, argv, &i, 7);
        } else if (is_option(s, "--n") || is_option(s, "--samples")) {
            const char *v = app_option_value(PROG, argc, argv, &i, s[3] == 'a' ? 9 : 3);
            if (!app_parse_count(v, APP_MAX_SAMPLES, &a.n))
                app_fail(PROG, "--n: '%s' is not a whole number from 1 to 1e13", v);
            if (a.have_n)
                app_fail(PROG, "--n given twice (or with its synonym --samples)");
            a.have_n = true;
        } else if (is_option(s, "--seed")) {
            const char *v = app_option_value(PROG, argc, argv, &i, 6);
            if (!app_parse_seed(v, &a.seed))
                app_fail(PROG, "--seed: '%s' is not a whole number from 0 to 2^64 - 1", v);
            if (a.have_seed)
                app_fail(PROG, "--seed given twice");
            a.have_seed = true;
        } else if (is_option(s, "--alpha")) {
            const char *v = app_option_value(PROG, argc, argv, &i, 7);
            if (!app_parse_double(v, &a.alpha) || !(a.alpha > 0.0 && a.alpha < 1.0))
                app_fail(PROG, "--alpha: '%s' is not a number in (0, 1)", v);
            if (a.have_alpha)
                app_fail(PROG, "--alpha given twice");
            a.have_alpha = true;
        } else if (s[0] == '-' && s[1] != '\0') {
            app_fail(PROG, "unknown option '%s' (see --help)", s);
        } else if (!a.command) {
            a.command = s;
        } else if (!a.name) {
            a.name = s;
        } else {
            app_fail(PROG, "unexpected argument '%s' (see --help)", s);
        }
    }
    if (!a.command)
        app_fail(PROG, "no command (list, sample, pdf or chi2; see --help)");
    /* Each command refuses what it would ignore: `warp list --n 3` or
     * `warp pdf x --seed 2` is a mistake the user should hear about. */
    bool list = strcmp(a.command, "list") == 0,
         densities_only = strcmp(a.command, "pdf") == 0 || strcmp(a.command, "serve") == 0,
         sample = strcmp(a.command, "sample") == 0;
    const char *extra = list && a.n_params ? "--param"
                        : (list || densities_only) && a.have_n ? "--n"
                        : (list || densities_only) && a.have_seed ? "--seed"
                        : (list || densities_only || sample) && a.have_alpha ? "--alpha"
                                                                  : NULL;
    if (extra)
        app_fail(PROG, "%s does not take %s (see --help)", a.command, extra);
    return a;
}

/* What each row's density is, in one line: the name says which warp, not
 * always which law (quad-light samples the light's area, not its solid
 * angle uniformly). Keyed by row name; tests/test_check_cli.c checks that
 * every row of `warp list` has one. */
static const struct {
    const char *name, *text;
} DESCRIPTIONS[] = {
    {"square", "uniform on the unit square, density 1"},
    {"disc-polar", "uniform on the unit disc by polar coordinates, r = sqrt(u); density 1/pi"},
    {"disc-concentric", "uniform on the unit disc by Shirley-Chiu's concentric map; density 1/pi"},
    {"triangle", "uniform on the triangle (0,0) (1,0) (0,1), the square folded; density 2"},
    {"parallelogram", "uniform on corner + s u + t v (area), density 1 / |u x v|"},
    {"sphere-surface", "uniform on the sphere's surface (area), density 1 / (4 pi radius^2)"},
    {"sphere-inverse", "uniform directions by z = 1 - 2 u2, phi = 2 pi u1; density 1 / (4 pi)"},
    {"sphere-gaussian", "uniform directions: three normal deviates (4 uniforms), normalized"},
    {"sphere-rejection", "uniform directions: points of the cube kept inside the ball, normalized"},
    {"hemisphere", "uniform directions of z >= 0 by z = 1 - u2; density 1 / (2 pi)"},
    {"hemisphere-flip", "uniform sphere directions with z -> |z|; density 1 / (2 pi), no inverse"},
    {"cosine", "cosine-weighted, z = sqrt(1 - u2) (the polar disc lifted); density cos(theta) / pi"},
    {"cosine-malley", "cosine-weighted, the concentric disc lifted (Malley); density cos(theta) / pi"},
    {"cosine-acos", "cosine-weighted, theta = acos(1 - 2 u2) / 2; density cos(theta) / pi"},
    {"theta-phi", "theta and phi uniform (not uniform directions): density 1 / (pi^2 sin theta)"},
    {"phong", "Phong lobe about +z: density (n + 1) cos^n(theta) / (2 pi)"},
    {"ggx", "GGX (Trowbridge-Reitz) normals of roughness alpha: density D(h) cos(theta_h)"},
    {"cone", "uniform directions in the cone cos(theta) >= cos_max about +z"},
    {"linear", "x on [0, 2] with density x / 2 (x = 2 sqrt(u))"},
    {"quadratic", "x on [0, 2] with density 3 x^2 / 8 (x = 2 cbrt(u))"},
    {"sine", "x on [0, pi] with density sin(x) / 2 (x = acos(1 - 2u))"},
    {"log-ends", "x on [0, pi] with density -ln(2 d / pi) / pi, d the distance to an end"},
    {"discrete", "outcome k with probability weight k / sum, by binary search of the CDF"},
    {"alias", "outcome k with probability weight k / sum, by Walker's alias table"},
    {"quad-light", "toward a parallelogram light: uniform over its area (not its solid angle), "
                   "density dist^2 / (|cos| A)"},
    {"sphere-light", "uniform directions in the cone the sphere subtends from the origin"},
    {"mixture", "w x cosine-pdf + (1 - w) x quad-light, one of the two drawn with those weights"},
    {"uniform-pdf", "the uniform pdf object of the whole sphere: density 1 / (4 pi)"},
    {"cosine-pdf", "the cosine pdf object about normal: density max(cos, 0) / pi"},
    {"light-list", "the quad light or the sphere light, each drawn with probability 1/2"},
};

/* The row's line of description, or NULL when it has none. */
static const char *description(const char *name)
{
    for (size_t k = 0; k < sizeof DESCRIPTIONS / sizeof DESCRIPTIONS[0]; k++)
        if (strcmp(DESCRIPTIONS[k].name, name) == 0)
            return DESCRIPTIONS[k].text;
    return NULL;
}

/* name, domain, measure, the parameters as --param takes them (one
 * quoted --param 'k=v k=v' or one option each), then after '#' what the
 * density is; a negative control says what is wrong with it. */
static void list(void)
{
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        char defaults[256];
        cat_param_defaults(r, defaults, sizeof defaults);
        const char *d = r->wrong ? r->wrong : description(r->name);
        printf("%-17s %-24s %-12s %s  # %s\n", r->name, r->domain, r->measure, defaults,
               d ? d : "(no description)");
    }
}

static void sample(const cat_state *s, const args *a)
{
    mc_rng rng = mc_rng_derive(a->seed, 0u);
    int dims = cat_point_dims(s->row);
    for (uint64_t k = 0; k < a->n; k++) {
        double x[3];
        cat_sample(s, &rng, x);
        if (s->row->point == CAT_INDEX)
            printf("%.0f\n", x[0]);
        else
            for (int j = 0; j < dims; j++)
                printf("%.17g%c", x[j], j + 1 < dims ? ' ' : '\n');
    }
}

/* Densities are collected first and printed only when every input line
 * has parsed, so that bad input leaves stdout empty. */
static void densities(const cat_state *s)
{
    int dims = cat_point_dims(s->row);
    size_t n = 0, cap = 1024;
    double *out = malloc(cap * sizeof *out);
    char line[4096];
    for (long lineno = 1; out && fgets(line, sizeof line, stdin); lineno++) {
        double x[3] = {0.0, 0.0, 0.0};
        char *p = line, *end;
        for (int j = 0; j < dims; j++, p = end) {
            x[j] = strtod(p, &end);
            if (end == p || !isfinite(x[j]))
                app_fail(PROG, "stdin line %ld: expected %d number%s", lineno, dims,
                         dims > 1 ? "s" : "");
        }
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')
            p++;
        if (*p)
            app_fail(PROG, "stdin line %ld: expected %d number%s", lineno, dims,
                     dims > 1 ? "s" : "");
        /* An outcome is an index: 2.5 or -1 is a mistake in the input, not
         * an outcome of probability 0. */
        if (s->row->point == CAT_INDEX &&
            (x[0] != floor(x[0]) || x[0] < 0.0 || x[0] >= (double)s->p.n_weights))
            app_fail(PROG, "stdin line %ld: '%g' is not an outcome index from 0 to %zu", lineno, x[0],
                     s->p.n_weights - 1);
        if (s->row->point == CAT_DIRECTION) { /* normalized; (0, 0, 0) is none */
            double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
            if (!(len > 0.0))
                app_fail(PROG, "stdin line %ld: the zero vector is not a direction", lineno);
            x[0] /= len, x[1] /= len, x[2] /= len;
        }
        if (n == cap)
            out = realloc(out, (cap *= 2) * sizeof *out);
        if (out)
            out[n++] = cat_pdf(s, x);
    }
    if (!out)
        app_fail(PROG, "out of memory");
    for (size_t i = 0; i < n; i++)
        printf("%.17g\n", out[i]);
    free(out);
}

/* --- serve: the --exec protocol (examples/common/exec_proto.h) ------------ */

/* A command the row cannot answer, or a malformed one: "error ..." for
 * mcbox-check, which reports it, and the same on stderr for a person
 * typing at the program; exit 2. */
_Noreturn static void serve_fail(long lineno, const char *fmt, const char *detail)
{
    char msg[400];
    snprintf(msg, sizeof msg, fmt, detail);
    printf("error line %ld: %s\n", lineno, msg);
    fflush(stdout);
    app_fail(PROG, "serve: stdin line %ld: %s", lineno, msg);
}

/* The next line of stdin without its line end, or NULL at EOF. */
static const char *next_line(char **buf, size_t *cap, size_t *len, long *lineno)
{
    ssize_t k = getline(buf, cap, stdin);
    if (k < 0)
        return NULL;
    ++*lineno;
    *len = (size_t)k;
    while (*len > 0 && ((*buf)[*len - 1] == '\n' || (*buf)[*len - 1] == '\r'))
        --*len;
    return *buf;
}

/* A point of the row, as `sample` prints it. */
static void print_point(const cat_state *s, const double *x, int n)
{
    char line[128];
    if (s->row->point == CAT_INDEX)
        printf("%.0f\n", x[0]);
    else if (app_proto_format_numbers(line, sizeof line, x, n))
        fputs(line, stdout);
}

/* One batch after its command line: K item lines in, K answer lines out. */
static void serve_batch(const cat_state *s, const app_proto_request *q, int uniforms, mc_rng *rng,
                        char **buf, size_t *cap, long *lineno)
{
    const cat_row *row = s->row;
    int dims = cat_point_dims(row);
    int in = q->cmd == APP_PROTO_SAMPLE ? uniforms : q->cmd == APP_PROTO_DRAW ? 0 : dims;
    char err[200];
    for (size_t i = 0; i < q->k; i++) {
        double v[MCBOX_MAX_UNIFORMS] = {0.0}, x[3] = {0.0, 0.0, 0.0}, u[2] = {0.0, 0.0};
        size_t len;
        if (in > 0) {
            if (!next_line(buf, cap, &len, lineno))
                serve_fail(*lineno + 1, "%s", "end of input inside a batch");
            if (!app_proto_parse_numbers(*buf, len, in, v, err, sizeof err))
                serve_fail(*lineno, "%s", err);
        }
        switch (q->cmd) {
        case APP_PROTO_SAMPLE:
            row->sample_u(s, v, x);
            print_point(s, x, dims);
            break;
        case APP_PROTO_DRAW:
            cat_sample(s, rng, x);
            print_point(s, x, dims);
            break;
        case APP_PROTO_PDF:
            /* Directions as `warp pdf` reads them: normalized, and the zero
             * vector, which is none, of density 0. */
            if (row->point == CAT_DIRECTION) {
                double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                v[0] /= l, v[1] /= l, v[2] /= l;
            }
            printf("%.17g\n", isfinite(v[0]) ? cat_pdf(s, v) : 0.0);
            break;
        default:
            row->invert(s, v, u);
            print_point(s, u, uniforms);
            break;
        }
    }
    fflush(stdout);
}

/* Answers hello, sample, draw, pdf and invert until EOF on stdin. */
static void serve(const cat_state *s)
{
    const cat_row *row = s->row;
    static char outbuf[1 << 16];
    setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);
    char *buf = NULL, err[200];
    size_t cap = 0, len;
    long lineno = 0;
    bool hello = false;
    int uniforms = row->uniforms;
    mc_rng rng = mc_rng_derive(1u, 0u);
    while (next_line(&buf, &cap, &len, &lineno)) {
        app_proto_request q;
        if (!app_proto_parse_command(buf, len, &q, err, sizeof err))
            serve_fail(lineno, "%s", err);
        if (q.cmd == APP_PROTO_HELLO) {
            char want[80];
            snprintf(want, sizeof want, "%d %d", cat_point_dims(row), row->uniforms);
            if (q.version != APP_PROTO_VERSION)
                serve_fail(lineno, "%s", "this program speaks protocol version 1");
            if (q.dims != cat_point_dims(row) || (q.uniforms != row->uniforms && q.uniforms != 0))
                serve_fail(lineno, "hello: the row's points have DIMS UNIFORMS = %s "
                                   "(or UNIFORMS 0 for draw)", want);
            rng = mc_rng_derive(q.seed, 0u);
            hello = true;
            puts("ok");
            fflush(stdout);
            continue;
        }
        if (!hello)
            serve_fail(lineno, "%s", "the first command must be hello");
        if (q.cmd == APP_PROTO_SAMPLE && !row->sample_u)
            serve_fail(lineno, "%s has no sampler from uniforms: use draw (UNIFORMS 0)", row->name);
        if (q.cmd == APP_PROTO_INVERT && (!row->invert || row->uniforms > 2))
            serve_fail(lineno, "%s has no inverse", row->name);
        serve_batch(s, &q, uniforms, &rng, &buf, &cap, &lineno);
    }
    free(buf);
}

/* BEGIN SNIPPET warp_chi2 */
static int chi2(const cat_state *s, const args *a)
{
    uint64_t n = a->have_n ? a->n : 1000000u;
    mc_gof_spec spec = cat_gof_spec_for(s, n);
    int cells = mc_gof_cell_count(&spec);
    double *obs = malloc((size_t)cells * sizeof *obs),
           *expct = malloc((size_t)cells * sizeof *expct);
    if (!obs || !expct)
        app_fail(PROG, "out of memory");
    mc_rng rng = mc_rng_derive(a->seed, 0u);
    mc_gof_result r = mc_gof_test(&spec, n, &rng, a->alpha, obs, expct);
    if (r.r.dof < 1) {
        free(obs);
        free(expct);
        app_fail(PROG, "--n %llu is too few samples for a chi-square test of '%s' (no degrees of freedom)",
                 (unsigned long long)n, a->name);
    }
    printf("chi2 dof p verdict\n%.6f %d %.6g %s\n", r.r.stat, r.r.dof, r.r.pvalue,
           r.reject ? "fail" : "pass");
    free(obs);
    free(expct);
    return r.reject ? 1 : 0;
}
/* END SNIPPET warp_chi2 */

int main(int argc, char **argv)
{
    args a = parse(argc, argv);
    if (strcmp(a.command, "list") == 0) {
        if (a.name || a.n_params)
            app_fail(PROG, "list takes no arguments");
        list();
        return 0;
    }
    if (strcmp(a.command, "sample") && strcmp(a.command, "pdf") && strcmp(a.command, "chi2") &&
        strcmp(a.command, "serve"))
        app_fail(PROG, "unknown command '%s' (list, sample, pdf or chi2)", a.command);
    if (!a.name)
        app_fail(PROG, "%s needs a sampler name (see warp list)", a.command);
    const cat_row *r = cat_find(a.name);
    if (!r)
        app_fail(PROG, "unknown sampler '%s' (see warp list)", a.name);
    cat_values p;
    cat_defaults(r, &p);
    char err[256], storage[2048];
    const char *assign[MAX_PARAMS];
    int n_assign = 0;
    size_t used = 0;
    /* One --param may hold several assignments, as `warp list` prints
     * them: "corner=0,0,1 u=1,0,0 v=0,1,0". */
    for (int i = 0; i < a.n_params; i++) {
        int k = app_split_assignments(a.params[i], storage + used, sizeof storage - used,
                                      assign + n_assign, MAX_PARAMS - n_assign, err, sizeof err);
        if (k < 0)
            app_fail(PROG, "--param '%s': %s", a.params[i], err);
        for (int j = 0; j < k; j++, n_assign++)
            used += strlen(assign[n_assign]) + 1;
    }
    for (int i = 0; i < n_assign; i++)
        if (!cat_set_param(r, &p, assign[i], err, sizeof err))
            app_fail(PROG, "%s", err);
    static cat_state s; /* large (the tables' storage) and self-referencing */
    if (!cat_prepare(r, &p, &s, err, sizeof err))
        app_fail(PROG, "%s", err);
    if (strcmp(a.command, "sample") == 0)
        sample(&s, &a);
    else if (strcmp(a.command, "pdf") == 0)
        densities(&s);
    else if (strcmp(a.command, "serve") == 0)
        serve(&s);
    else
        return chi2(&s, &a);
    return 0;
}
