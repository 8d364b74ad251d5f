/* examples/check_cli/options.c - mcbox-check's options, and the sampler
 * (domain, density, atoms) they describe. */
#define _POSIX_C_SOURCE 200809L /* strtok_r */

#include "examples/check_cli/check_cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"

/* Stores the value of a string option given at most once. */
static void once(const char **dest, const char *v, const char *name)
{
    if (*dest)
        cli_fail("%s given twice", name);
    if (!*v)
        cli_fail("%s: empty value", name);
    *dest = v;
}

static void parse_cells(const char *v, int cells[2])
{
    const char *x = strchr(v, 'x');
    char first[64];
    uint64_t a = 0, b = 0;
    size_t len = x ? (size_t)(x - v) : strlen(v);
    bool ok = len < sizeof first;
    if (ok) {
        memcpy(first, v, len);
        first[len] = '\0';
        ok = app_parse_uint(first, 1, 4096, &a) && (!x || app_parse_uint(x + 1, 1, 4096, &b));
    }
    if (!ok)
        cli_fail("--cells: '%s' is not NX or NXxNY with whole numbers from 1 to 4096", v);
    cells[0] = (int)a, cells[1] = (int)b;
}

/* "x,y,z": three finite numbers into v; false otherwise. */
static bool parse_vector(const char *s, double v[3])
{
    char buf[256], *save = NULL, *t;
    int got = 0;
    if (strlen(s) >= sizeof buf)
        return false;
    memcpy(buf, s, strlen(s) + 1);
    for (char *p = buf; (t = strtok_r(p, ",", &save)); p = NULL)
        if (got == 3 || !app_parse_double(t, &v[got++]))
            return false;
    return got == 3 && s[strlen(s) - 1] != ',';
}

/* The options that take a number, in the order of the switch below. */
static const char *const VALUED[] = {
    "--format",   "--uniforms",  "--timeout",    "--n",          "--seed",
    "--alpha",    "--tests",     "--cells",      "--lobe-width", "--lobe-axis",
    "--norm-tol", "--pdf-tol",   "--weight-tol", "--invert-tol", "--quad-order",
    "--quad-depth", "--quad-error-max"};
#define N_VALUED (sizeof VALUED / sizeof VALUED[0])

/* A tolerance: a finite number >= 0. */
static double tolerance(const char *name, const char *v)
{
    double d;
    if (!app_parse_double(v, &d) || !(d >= 0.0))
        cli_fail("%s: '%s' is not a finite number >= 0", name, v);
    return d;
}

static void parse_valued(cli_args *a, int which, const char *v)
{
    uint64_t u;
    double d;
    mcbox_check_options *o = &a->o;
    switch (which) {
    case 0:
        if (!app_samples_format_parse(v, &a->format))
            cli_fail("--format: '%s' is not csv, f32 or f64", v);
        a->have_format = true;
        break;
    case 1:
        if (!app_parse_uint(v, 0, MCBOX_MAX_UNIFORMS, &u))
            cli_fail("--uniforms: '%s' is not a whole number from 0 to %d", v, MCBOX_MAX_UNIFORMS);
        a->uniforms = (int)u, a->have_uniforms = true;
        break;
    case 2:
        if (!app_parse_double(v, &a->timeout) || !(a->timeout > 0.0 && a->timeout <= 1e6))
            cli_fail("--timeout: '%s' is not a number of seconds in (0, 1e6]", v);
        a->have_timeout = true;
        break;
    case 3:
        if (!app_parse_count(v, APP_MAX_SAMPLES, &a->n))
            cli_fail("--n: '%s' is not a whole number from 1 to 1e13", v);
        a->have_n = true;
        break;
    case 4:
        if (!app_parse_seed(v, &o->seed))
            cli_fail("--seed: '%s' is not a whole number from 0 to 2^64 - 1", v);
        a->have_seed = true;
        break;
    case 5:
        if (!app_parse_double(v, &o->alpha) || !(o->alpha > 0.0 && o->alpha < 1.0))
            cli_fail("--alpha: '%s' is not a number in (0, 1)", v);
        break;
    case 6:
        if (!app_parse_uint(v, 1, 1000000000, &u))
            cli_fail("--tests: '%s' is not a whole number from 1 to 1e9", v);
        o->tests = (int)u;
        break;
    case 7: parse_cells(v, o->cells); break;
    case 8:
        if (!app_parse_double(v, &d) || !(d > 0.0 && d <= 10.0))
            cli_fail("--lobe-width: '%s' is not a number in (0, 10]", v);
        o->lobe_width = d;
        break;
    case 9:
        if (!parse_vector(v, o->lobe_axis) ||
            (o->lobe_axis[0] == 0.0 && o->lobe_axis[1] == 0.0 && o->lobe_axis[2] == 0.0))
            cli_fail("--lobe-axis: '%s' is not x,y,z: three finite numbers, not all 0", v);
        break;
    case 10: o->norm_tol = tolerance("--norm-tol", v); break;
    case 11: o->pdf_tol = tolerance("--pdf-tol", v); break;
    case 12: o->weight_tol = tolerance("--weight-tol", v); break;
    case 13: o->invert_tol = tolerance("--invert-tol", v); break;
    case 14:
        if (!app_parse_uint(v, 1, 64, &u))
            cli_fail("--quad-order: '%s' is not a whole number from 1 to 64", v);
        o->quad_order = (int)u;
        break;
    case 15:
        if (!app_parse_uint(v, 0, 30, &u))
            cli_fail("--quad-depth: '%s' is not a whole number from 0 to 30", v);
        o->quad_depth = (int)u;
        break;
    default:
        if (!app_parse_double(v, &d) || !(d > 0.0))
            cli_fail("--quad-error-max: '%s' is not a finite number > 0", v);
        o->quad_error_max = d;
        break;
    }
}

static void parse_option(cli_args *a, int argc, char **argv, int *i, bool *seen)
{
    static const char *const strings[] = {"--exec", "--samples", "--pdf", "--pdf-exec", "--domain",
                                          "--interval", "--name", "--junit", "--plot"};
    const char *s = argv[*i];
    size_t len = strcspn(s, "=");
    const char **dest[] = {&a->exec, &a->samples, &a->pdf, &a->pdf_exec, &a->domain,
                           &a->interval, &a->name, &a->junit, &a->plot};
#define IS(name) (len == strlen(name) && strncmp(s, name, len) == 0)
    for (size_t k = 0; k < sizeof strings / sizeof strings[0]; k++)
        if (IS(strings[k])) {
            once(dest[k], app_option_value(CLI_PROG, argc, argv, i, len), strings[k]);
            return;
        }
    if (IS("--invert") || IS("--json")) {
        if (s[len] == '=')
            cli_fail("%.*s takes no value", (int)len, s);
        bool *f = IS("--invert") ? &a->invert : &a->json;
        if (*f)
            cli_fail("%.*s given twice", (int)len, s);
        *f = true;
        return;
    }
    if (IS("--param") || IS("--atom")) {
        bool param = IS("--param");
        const char *v = app_option_value(CLI_PROG, argc, argv, i, len);
        if (!*v)
            cli_fail("%s: empty value", param ? "--param" : "--atom");
        if (param ? a->n_params == CLI_MAX_PARAMS : a->n_atoms == CLI_MAX_ATOMS)
            cli_fail("more than %d %s options", param ? CLI_MAX_PARAMS : CLI_MAX_ATOMS,
                     param ? "--param" : "--atom");
        if (param)
            a->params[a->n_params++] = v;
        else
            a->atoms[a->n_atoms++] = v;
        return;
    }
    size_t which = N_VALUED;
    for (size_t k = 0; k < N_VALUED; k++)
        if (IS(VALUED[k]))
            which = k;
#undef IS
    if (which == N_VALUED) {
        if (s[0] == '-' && s[1] != '\0')
            cli_fail("unknown option '%.*s' (see --help)", (int)len, s);
        cli_fail("unexpected argument '%s' (see --help)", s);
    }
    const char *v = app_option_value(CLI_PROG, argc, argv, i, len);
    if (seen[which])
        cli_fail("%s given twice", VALUED[which]);
    seen[which] = true;
    parse_valued(a, (int)which, v);
}

/* Each door refuses what it would ignore. */
static void check_doors(const cli_args *a)
{
    if (!a->exec == !a->samples)
        cli_fail("%s (see --help)", a->exec ? "--exec and --samples exclude each other"
                                            : "no sampler: give --exec CMD or --samples FILE");
    const char *extra = NULL;
    if (a->exec)
        extra = a->pdf ? "--pdf" : a->pdf_exec ? "--pdf-exec" : a->have_format ? "--format" : NULL;
    else
        extra = a->have_uniforms ? "--uniforms" : a->invert ? "--invert" : a->n_atoms ? "--atom"
              : a->have_seed ? "--seed" : NULL;
    if (extra)
        cli_fail("%s does not take %s (see --help)", a->exec ? "--exec" : "--samples", extra);
    if (a->samples && !a->pdf == !a->pdf_exec)
        cli_fail("--samples needs %s", a->pdf ? "--pdf or --pdf-exec, not both"
                                              : "a density: --pdf NAME or --pdf-exec CMD");
    if (a->pdf && a->domain)
        cli_fail("--pdf NAME gives the domain: drop --domain %s", a->domain);
    if (!a->pdf && !a->domain)
        cli_fail("%s needs --domain D (see --help)", a->exec ? "--exec" : "--pdf-exec");
    if (a->pdf && a->have_timeout)
        cli_fail("--timeout applies to --exec and --pdf-exec only");
}

cli_args cli_parse(int argc, char **argv)
{
    cli_args a;
    memset(&a, 0, sizeof a);
    a.o = mcbox_check_defaults();
    a.timeout = 60.0;
    bool seen[N_VALUED] = {false};
    for (int i = 1; i < argc; i++)
        parse_option(&a, argc, argv, &i, seen);
    check_doors(&a);
    if (a.name) {
        for (const char *p = a.name; *p; p++)
            if (!(('a' <= *p && *p <= 'z') || ('A' <= *p && *p <= 'Z') || ('0' <= *p && *p <= '9') ||
                  strchr("._-", *p)) || (p == a.name && *p == '.'))
                cli_fail("--name: '%s' is not letters, digits, '.', '_' and '-'", a.name);
        if (strlen(a.name) > 100)
            cli_fail("--name: longer than 100 characters");
    }
    return a;
}

/* --- the domain and the density of the options ------------------------------ */

/* Every --param's assignments into c->assign. */
static void split_all_params(cli_app *c)
{
    size_t used = 0;
    char err[200];
    for (int i = 0; i < c->a.n_params; i++) {
        int k = app_split_assignments(c->a.params[i], c->param_store + used,
                                      sizeof c->param_store - used, c->assign + c->n_assign,
                                      CLI_MAX_PARAMS - c->n_assign, err, sizeof err);
        if (k < 0)
            cli_fail("--param '%s': %s", c->a.params[i], err);
        for (int j = 0; j < k; j++)
            used += strlen(c->assign[c->n_assign + j]) + 1;
        c->n_assign += k;
    }
}

static void parse_atom(cli_app *c, int k)
{
    const char *v = c->a.atoms[k], *colon = strrchr(v, ':');
    char coords[256];
    double x[3] = {0.0, 0.0, 0.0}, mass;
    int got = 0;
    bool ok = colon && (size_t)(colon - v) < sizeof coords && app_parse_double(colon + 1, &mass) &&
              mass >= 0.0 && mass <= 1.0;
    if (ok) {
        memcpy(coords, v, (size_t)(colon - v));
        coords[colon - v] = '\0';
        for (char *p = coords, *save = NULL, *t; ok && (t = strtok_r(p, ",", &save)); p = NULL)
            ok = got < 3 && app_parse_double(t, &x[got++]);
    }
    if (!ok || got != c->dims)
        cli_fail("--atom: '%s' is not %d coordinate%s, a colon and a mass in [0, 1]", v, c->dims,
                 c->dims > 1 ? "s separated by commas" : "");
    memcpy(c->atom_x + (size_t)k * (size_t)c->dims, x, (size_t)c->dims * sizeof *x);
    c->atom_mass[k] = mass;
}

/* The catalog row `name` with the --param assignments, prepared into st. */
static void prepare_row(cli_app *c, const char *name, cat_state *st, bool from_domain)
{
    const cat_row *r = cat_find(name);
    if (!r && from_domain) {
        char names[256] = "";
        size_t used = 0;
        for (int k = 0; mcbox_domain_name((mcbox_domain_kind)k); k++)
            if (k != MCBOX_CATALOG)
                used += (size_t)snprintf(names + used, sizeof names - used, "%s%s", used ? ", " : "",
                                         mcbox_domain_name((mcbox_domain_kind)k));
        cli_fail("--domain: '%s' is neither a domain (%s) nor a catalog row (see warp list)", name,
                 names);
    }
    if (!r)
        cli_fail("unknown catalog row '%s' (see warp list)", name);
    cat_values p;
    cat_defaults(r, &p);
    char err[256];
    size_t used = 0;
    for (int i = 0; i < c->n_assign; i++) {
        if (!cat_set_param(r, &p, c->assign[i], err, sizeof err))
            cli_fail("--param: %s", err);
        if (used + strlen(c->assign[i]) + 2 > sizeof c->params)
            cli_fail("--param: the assignments are longer than %zu bytes", sizeof c->params);
        used += (size_t)snprintf(c->params + used, sizeof c->params - used, "%s%s", used ? " " : "",
                                 c->assign[i]);
    }
    if (!cat_prepare(r, &p, st, err, sizeof err))
        cli_fail("--param: %s", err);
}

/* The parameters of a spherical domain: cap (axis, cos_max), spherical
 * triangle (a, b, c) or quad (corner, u, v), each key once and every
 * required one given. */
static void spherical_params(cli_app *c, mcbox_domain_kind kind)
{
    static const char *const keys[3][3] = {
        {"axis", "cos_max", NULL}, {"a", "b", "c"}, {"corner", "u", "v"}};
    const char *const *k = keys[kind == MCBOX_CAP ? 0 : kind == MCBOX_SPHERICAL_TRIANGLE ? 1 : 2];
    const char *dom = mcbox_domain_name(kind);
    bool got[3] = {kind == MCBOX_CAP, false, false}; /* a cap's axis defaults to +z */
    mcbox_domain *d = &c->s.domain;
    if (kind == MCBOX_CAP)
        d->axis[0] = d->axis[1] = 0.0, d->axis[2] = 1.0;
    for (int i = 0; i < c->n_assign; i++) {
        const char *as = c->assign[i], *eq = strchr(as, '=');
        int j = 0;
        while (j < 3 && !(k[j] && strlen(k[j]) == (size_t)(eq - as) && strncmp(as, k[j], (size_t)(eq - as)) == 0))
            j++;
        if (j == 3)
            cli_fail("--param: %s takes %s=x,y,z %s=%s (not '%.*s')", dom, k[0], k[1],
                     kind == MCBOX_CAP ? "COS" : "x,y,z", (int)(eq - as), as);
        bool vec = !(kind == MCBOX_CAP && j == 1);
        double v[3];
        if (vec ? !parse_vector(eq + 1, v) : !app_parse_double(eq + 1, &v[0]))
            cli_fail("--param %s: '%s' is not %s", as, eq + 1,
                     vec ? "x,y,z: three finite numbers" : "a number");
        if (kind == MCBOX_CAP && j == 0)
            memcpy(d->axis, v, sizeof v);
        else if (kind == MCBOX_CAP)
            d->cos_max = v[0];
        else
            memcpy(d->vertex[j], v, sizeof v);
        got[j] = true;
    }
    for (int j = 0; j < 3; j++)
        if (k[j] && !got[j])
            cli_fail("--domain %s needs --param %s=%s", dom, k[j],
                     kind == MCBOX_CAP ? "COS (the cosine of the half angle)" : "x,y,z");
}

static double row_pdf(const double *x, void *ctx)
{
    const cli_app *c = ctx;
    return cat_pdf(c->row_state, x);
}

static void set_interval(cli_app *c, mcbox_domain_kind kind)
{
    const char *v = c->a.interval;
    char *end;
    double lo = strtod(v, &end), hi = (double)NAN;
    if (kind != MCBOX_INTERVAL)
        cli_fail("--interval applies to --domain interval only");
    if (!(*end == ',' && app_parse_double(end + 1, &hi) && end != v && isfinite(lo) && lo < hi))
        cli_fail("--interval: '%s' is not A,B with finite A < B", v);
    c->s.domain.a = lo, c->s.domain.b = hi;
}

/* A catalog row's program takes what the row's own sampler takes (`warp
 * serve ROW` refuses any other count) unless --uniforms says otherwise;
 * a count that is not the usual 2 is said, since a program that expects
 * another would wait for input that never comes. */
static void set_uniforms(cli_app *c, const cat_state *st)
{
    if (st) {
        c->s.uniforms = st->row->uniforms;
        c->uniforms_from_row = !c->a.have_uniforms;
        if (c->uniforms_from_row && c->a.exec && st->row->uniforms != 2)
            fprintf(stderr, "%s: note: --domain %s: the program gets UNIFORMS %d, as the row's own "
                            "sampler takes%s; give --uniforms K for one that maps K uniforms\n",
                    CLI_PROG, st->row->name, st->row->uniforms,
                    st->row->uniforms ? "" : " ('draw K': it samples from its own generator)");
    }
    if (c->a.have_uniforms)
        c->s.uniforms = c->a.uniforms;
    if (c->a.invert && c->s.uniforms == 0)
        cli_fail("--invert needs uniforms: it compares invert(sample(u)) with u");
}

void cli_setup(cli_app *c)
{
    cli_args *a = &c->a;
    const char *dom = a->pdf ? a->pdf : a->domain;
    mcbox_domain_kind kind;
    static cat_state st; /* large and self-referencing: not on the stack */
    split_all_params(c);
    /* --pdf always names a catalog row, even one called like a domain
     * ("hemisphere", "square"): the row is the density. */
    bool row = a->pdf || !mcbox_domain_parse(dom, &kind) || kind == MCBOX_CATALOG;
    if (row) {
        kind = MCBOX_CATALOG;
        prepare_row(c, dom, &st, !a->pdf);
        c->row_state = &st;
    }
    c->s = mcbox_sampler_init(kind);
    if (kind == MCBOX_CAP || kind == MCBOX_SPHERICAL_TRIANGLE || kind == MCBOX_SPHERICAL_QUAD)
        spherical_params(c, kind);
    else if (!row && c->n_assign)
        cli_fail("--param applies to a catalog row or to the domains cap, spherical-triangle and "
                 "spherical-quad, not to %s", dom);
    snprintf(c->domain_word, sizeof c->domain_word, "%s", dom);
    if (row)
        c->s.domain.row = st.row->name, c->s.domain.params = c->params[0] ? c->params : NULL;
    if (a->interval)
        set_interval(c, kind);
    c->dims = mcbox_domain_dims(&c->s.domain);
    set_uniforms(c, row ? &st : NULL);
    for (int k = 0; k < a->n_atoms; k++)
        parse_atom(c, k);
    c->s.n_atoms = (size_t)a->n_atoms;
    c->s.atom_x = c->atom_x, c->s.atom_mass = c->atom_mass;
    if (a->pdf)
        c->s.pdf = row_pdf;
    else
        c->s.pdf_batch = cli_pdf_batch;
    if (a->invert)
        c->s.invert = cli_invert_cached;
    c->s.ctx = c;
    a->o.samples = a->have_n ? a->n : a->o.samples;
    if (!a->name)
        a->name = a->pdf ? a->pdf : "sampler";
}
