/* tests/test_check.c - the public check (check/check.h) through its C door:
 * every sampler of the catalog passes it, with the very statistic the
 * suite's own harness computes (bit for bit, same seed); every negative
 * control of the catalog fails it; and each check that chi-square alone
 * cannot make (the sampler's reported pdf, weights, inverse, atoms, a
 * density that goes negative, samples that are not finite) catches its
 * deliberate error.
 *
 * Statistics: the catalog sweep uses each case's own seed
 * (warp_case_seed(case seed, position)) and 10^6 samples, the harness's
 * numbers, at chi2_suite_alpha() = 1.57e-4: the same draws as the sampler
 * groups, so it adds no false alarm of its own beyond theirs. The other
 * tests state their seed, sample count and level where they run; the
 * correct samplers of those run at the Sidak level 1.57e-4 (alpha 0.01
 * over 64 tests).
 */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "check/stream.h"
#include "mc/chi2.h"
#include "mc/constants.h"
#include "samplers/hemisphere.h"
#include "samplers/planar.h"
#include "samplers/sphere.h"
#include "samplers/warp1d.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

enum { N_CHI2 = 1000000, N_SMALL = 200000 };

/* --- a catalog row as a user's sampler ------------------------------------ */

static void row_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const cat_state *s = ctx;
    s->row->sample_u(s, u, out->x);
}

static void row_sample_stream(mcbox_stream *st, mcbox_sample *out, void *ctx)
{
    const cat_state *s = ctx;
    s->row->sample_rng(s, chk_stream_rng(st), out->x);
}

static double row_pdf(const double *x, void *ctx)
{
    return cat_pdf(ctx, x);
}

static void row_invert(const double *x, double *u, void *ctx)
{
    const cat_state *s = ctx;
    double v[2] = {0.0, 0.0};
    s->row->invert(s, x, v);
    u[0] = v[0];
    if (s->row->uniforms == 2)
        u[1] = v[1];
}

/* The sampler of the prepared row s with the case's parameters. */
static mcbox_sampler row_sampler(const cat_state *s, const char *params)
{
    mcbox_sampler m = mcbox_sampler_init(MCBOX_CATALOG);
    m.domain.row = s->row->name;
    m.domain.params = params;
    m.uniforms = s->row->uniforms;
    m.sample = s->row->uniforms ? row_sample : NULL;
    m.sample_stream = s->row->uniforms ? NULL : row_sample_stream;
    m.pdf = row_pdf;
    m.invert = s->row->invert && s->row->uniforms <= 2 ? row_invert : NULL;
    m.ctx = (void *)s;
    return m;
}

static mcbox_check_options suite_options(uint64_t n, uint64_t seed)
{
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = n;
    o.seed = seed;
    o.alpha = CHI2_SUITE_ALPHA;
    o.tests = CHI2_SUITE_TESTS;
    return o;
}

/* Every case of every catalog row: the C API passes it, and its statistic,
 * degrees of freedom and p-value are the harness's to the bit, except
 * where the check's own refinement of a cell disagreed with the harness's
 * GSL value beyond its error estimate (the mixtures' cells that the
 * light's edge cuts): there the check keeps the refinement's value and
 * adds the difference to its error, and the statistic may differ from the
 * harness's by a relative 1e-4 at most (those cells hold under one
 * expected sample each). */
static void test_catalog_through_api(void **state)
{
    (void)state;
    int cases = 0, failures = 0, refined = 0;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *row = cat_at(i);
        for (const cat_case *tc = row->cases; tc->name; tc++, cases++) {
            static cat_state s; /* large; self-referencing */
            warp_case wc = warp_case_of(row, tc, &s);
            uint64_t seed = warp_case_seed(mc_test_seed(tc->seed), tc->seq);
            chi2_outcome h = warp_chi2(&wc, N_CHI2, seed);
            mc_gof_spec g = cat_gof_spec(&s, tc->cells);
            mcbox_check_options o = suite_options(N_CHI2, seed);
            o.cells[0] = g.cells[0];
            o.cells[1] = g.dims == 2 ? g.cells[1] : 1;
            o.lobe_width = tc->lobe_width;
            mcbox_sampler m = row_sampler(&s, tc->params);
            mcbox_check_result r;
            assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
            bool bits = memcmp(&r.statistic, &h.r.stat, sizeof(double)) == 0 &&
                        r.dof == h.r.dof && memcmp(&r.pvalue, &h.r.pvalue, sizeof(double)) == 0;
            bool near = r.dof == h.r.dof && fabs(r.statistic - h.r.stat) <= 1e-4 * h.r.stat;
            bool same = bits || near;
            refined += !bits && near;
            printf("check %-22s stat %12.4f dof %5d p %.4g | harness %12.4f %5d %.4g %s %s%s\n",
                   tc->name, r.statistic, r.dof, r.pvalue, h.r.stat, h.r.dof, h.r.pvalue,
                   bits ? "same" : near ? "near" : "DIFFERENT", r.pass ? "pass" : "FAIL ", r.message);
            if (!same || !r.pass || h.reject) {
                failures++;
                print_error("%s: seed %llu\n", tc->name, (unsigned long long)seed);
            }
        }
    }
    printf("catalog through the C API: %d cases, %d failures, %d within 1e-4 (refined cells)\n",
           cases, failures, refined);
    assert_int_equal(failures, 0);
    /* Only the two mixtures' light edges may take the refinement's value. */
    assert_true(refined <= 2);
}

/* Every negative control of the catalog is rejected by the C API, each
 * with 10^6 samples at the suite's level. */
static void test_negatives_through_api(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(9101);
    for (size_t i = 0; i < cat_negative_count(); i++) {
        const cat_row *row = cat_negative_at(i);
        static cat_state s;
        char err[256];
        assert_true(cat_prepare_named(row->name, &s, err, sizeof err));
        mcbox_sampler m = row_sampler(&s, NULL);
        mcbox_check_options o = suite_options(N_CHI2, seed + i);
        mcbox_check_result r;
        assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
        printf("  %s (%s): %s\n", row->name, row->wrong, r.message);
        char name[96];
        snprintf(name, sizeof name, "catalog %s", row->name);
        assert_seeded(negctl_record(t, name, "the C API (mcbox_check_run)", !r.pass), seed + i);
    }
}

/* --- a user's own sampler, written here as a user would ------------------- */

/* Cosine-weighted hemisphere by Malley's method, with an optional slip. */
typedef struct cosine_ctx {
    bool report_pdf;
    bool swap_reported; /* reports pdf at (y, x, z): the argument-order slip */
    bool weight;        /* reports weight = f / pdf for f = cos theta / pi (albedo 1) */
    double weight_scale;
    bool wrong_invert;
} cosine_ctx;

static void my_cosine_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const cosine_ctx *c = ctx;
    vec3 w = smp_cosine_hemisphere_sample_malley(u[0], u[1]);
    out->x[0] = w.x, out->x[1] = w.y, out->x[2] = w.z;
    if (c && c->report_pdf)
        out->pdf = c->swap_reported ? smp_cosine_hemisphere_pdf(vec3_make(w.z, w.y, w.x))
                                    : smp_cosine_hemisphere_pdf(w);
    if (c && c->weight)
        out->weight = c->weight_scale;
}

static double my_cosine_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] > 0.0 ? x[2] * MC_INV_PI : 0.0;
}

static double my_cosine_eval(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] > 0.0 ? x[2] * MC_INV_PI : 0.0;
}

static void my_cosine_invert(const double *x, double *u, void *ctx)
{
    const cosine_ctx *c = ctx;
    vec2 v = smp_cosine_hemisphere_invert_malley(vec3_make(x[0], x[1], x[2]));
    u[0] = v.x, u[1] = c && c->wrong_invert ? 1.0 - v.y : v.y;
}

static mcbox_sampler my_cosine(cosine_ctx *c)
{
    mcbox_sampler m = mcbox_sampler_init(MCBOX_HEMISPHERE);
    m.sample = my_cosine_sample;
    m.pdf = my_cosine_pdf;
    m.invert = my_cosine_invert;
    m.ctx = c;
    return m;
}

/* A basic domain gives the catalog row's chart: the user's cosine sampler
 * on MCBOX_HEMISPHERE has the statistic of the catalog's cosine-malley row
 * under the harness (same uniforms, same chart, same cells). */
static void test_basic_domain_matches_harness(void **state)
{
    (void)state;
    const cat_row *row = NULL;
    const cat_case *tc = cat_find_case("cosine-malley", &row);
    assert_non_null(tc);
    static cat_state s;
    warp_case wc = warp_case_of(row, tc, &s);
    uint64_t seed = mc_test_seed(9102);
    chi2_outcome h = warp_chi2(&wc, N_SMALL, seed);
    cosine_ctx c = {0};
    mcbox_sampler m = my_cosine(&c);
    mcbox_check_options o = suite_options(N_SMALL, seed);
    o.cells[0] = 50, o.cells[1] = 100;
    mcbox_check_result r;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("user cosine: stat %.17g dof %d p %.6g; harness %.17g %d %.6g\n", r.statistic, r.dof,
           r.pvalue, h.r.stat, h.r.dof, h.r.pvalue);
    assert_true(memcmp(&r.statistic, &h.r.stat, sizeof(double)) == 0);
    assert_int_equal(r.dof, h.r.dof);
    assert_seeded(r.pass, seed);
    assert_near(r.pdf_integral, 1.0, 1e-9);
    assert_true(r.invert_error < 1e-9);
    assert_true(isnan(r.weight_mismatch)); /* no eval given */
    assert_true(r.outside == 0 && r.nonfinite == 0 && r.in_zero_cells == 0);
    /* The level is Sidak's for 64 tests at 0.01, computed here directly. */
    assert_near(r.level, 1.0 - pow(0.99, 1.0 / 64.0), 1e-15);
}

/* The checks beyond chi-square, each with a correct case that passes and
 * its slip that must be caught (1e5 samples, seed 9103; chi-square at the
 * suite's level). */
static void test_reported_pdf_weight_invert(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(9103);
    mcbox_check_options o = suite_options(100000, seed);
    mcbox_check_result r;

    cosine_ctx good = {.report_pdf = true, .weight = true, .weight_scale = 1.0};
    mcbox_sampler m = my_cosine(&good);
    m.eval = my_cosine_eval;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    assert_seeded(r.pass, seed);
    assert_true(r.pdf_reported == 100000 && r.pdf_mismatch < 1e-12);
    assert_true(r.weight_reported == 100000 && r.weight_mismatch < 1e-12);
    assert_near(r.weight_mean, 1.0, 0.0);

    /* The reported pdf with its arguments swapped: chi-square passes (the
     * points are right), the comparison with the pdf function does not. */
    cosine_ctx swapped = {.report_pdf = true, .swap_reported = true};
    m = my_cosine(&swapped);
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  swapped pdf: p = %.3g, %s\n", r.pvalue, r.message);
    assert_true(r.pvalue >= r.level);
    assert_seeded(negctl_record(t, "reported pdf with swapped arguments", "pdf consistency",
                                !r.pass && r.pdf_mismatch > 0.1),
                  seed);

    cosine_ctx heavy = {.weight = true, .weight_scale = 1.25};
    m = my_cosine(&heavy);
    m.eval = my_cosine_eval;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  weight off by 1.25: %s\n", r.message);
    assert_seeded(negctl_record(t, "weight 1.25 x f / pdf", "weight consistency",
                                !r.pass && fabs(r.weight_mismatch - 0.25) < 1e-9),
                  seed);

    cosine_ctx inv = {.wrong_invert = true};
    m = my_cosine(&inv);
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  inverse 1 - u2: %s\n", r.message);
    assert_seeded(negctl_record(t, "inverse returning 1 - u2", "round trip",
                                !r.pass && r.invert_error > 0.1),
                  seed);
}

/* A lobe with a discrete part, as glass or a coated mirror has: with
 * probability 0.3 the mirror direction +z (an atom), otherwise a cosine
 * direction; the continuous density is then 0.7 cos theta / pi. */
typedef struct glassy {
    double mass_drawn; /* the probability the sampler really uses */
} glassy;

static void glassy_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const glassy *g = ctx;
    if (u[0] < g->mass_drawn) {
        out->x[0] = 0.0, out->x[1] = 0.0, out->x[2] = 1.0;
        out->atom = 0;
        return;
    }
    double v = (u[0] - g->mass_drawn) / (1.0 - g->mass_drawn);
    vec3 w = smp_cosine_hemisphere_sample_malley(v, u[1]);
    out->x[0] = w.x, out->x[1] = w.y, out->x[2] = w.z;
}

static double glassy_pdf(const double *x, void *ctx)
{
    (void)ctx;
    return 0.7 * my_cosine_pdf(x, NULL);
}

static void test_atoms(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(9104);
    static const double atom_x[3] = {0.0, 0.0, 1.0}, atom_mass[1] = {0.3};
    glassy g = {0.3};
    mcbox_sampler m = mcbox_sampler_init(MCBOX_HEMISPHERE);
    m.sample = glassy_sample, m.pdf = glassy_pdf, m.ctx = &g;
    m.n_atoms = 1, m.atom_x = atom_x, m.atom_mass = atom_mass;
    mcbox_check_options o = suite_options(200000, seed);
    mcbox_check_result r;
    mcbox_check_table tab;
    assert_int_equal(mcbox_check_run(&m, &o, &r, &tab), 0);
    printf("  atoms, correct: stat %.2f dof %d p %.3g integral %.9f %s\n", r.statistic, r.dof,
           r.pvalue, r.pdf_integral, r.message);
    assert_seeded(r.pass, seed);
    assert_near(r.pdf_integral, 1.0, 1e-9);
    assert_int_equal(tab.cells, (size_t)tab.nx * (size_t)tab.ny + 1);
    /* The atom's cell holds the atom's draws: about 0.3 n. */
    assert_true(fabs(tab.observed[tab.cells - 1] - 60000.0) < 5.0 * sqrt(200000 * 0.21));
    assert_near(tab.expected[tab.cells - 1], 60000.0, 1e-6);
    mcbox_check_table_free(&tab);

    /* The sampler picks the mirror 35% of the time but declares 30%. */
    g.mass_drawn = 0.35;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  atoms, mass 0.35 declared 0.3: %s\n", r.message);
    assert_seeded(negctl_record(t, "atom drawn at 0.35, declared 0.3", "chi-square with atoms",
                                !r.pass),
                  seed);

    /* Declaring no atom while drawing one: the mark is caught. */
    g.mass_drawn = 0.3;
    m.n_atoms = 0;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    assert_seeded(negctl_record(t, "undeclared atom", "atom marks", !r.pass && r.bad_atoms > 0),
                  seed);
}

/* The batch form of the density (as behind a pipe): a correct density
 * passes and one without 1/pi fails, on Gauss-Legendre expected counts. */
static void batch_cosine(const double *x, size_t n, double *out, void *ctx)
{
    const double *scale = ctx;
    for (size_t i = 0; i < n; i++)
        out[i] = x[3 * i + 2] > 0.0 ? *scale * x[3 * i + 2] : 0.0;
}

static void batch_sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    my_cosine_sample(u, out, NULL);
}

static void test_pdf_batch(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(9105);
    double scale = MC_INV_PI;
    mcbox_sampler m = mcbox_sampler_init(MCBOX_HEMISPHERE);
    m.sample = batch_sample, m.pdf_batch = batch_cosine, m.ctx = &scale;
    mcbox_check_options o = suite_options(200000, seed);
    mcbox_check_result r;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  batch cosine: stat %.2f dof %d p %.3g integral %.12f\n", r.statistic, r.dof,
           r.pvalue, r.pdf_integral);
    assert_seeded(r.pass, seed);
    assert_near(r.pdf_integral, 1.0, 1e-9);
    scale = 1.0;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    assert_seeded(negctl_record(t, "batch density without 1/pi", "normalization (batch rule)",
                                !r.pass && fabs(r.pdf_integral - MC_PI) < 1e-6),
                  seed);
}

/* Each basic domain with a sampler of the library written against the
 * public API: passes (2 x 10^5 samples, seed 9106 + k, suite level). */
static void square_s(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    vec2 p = smp_unit_square_sample(u[0], u[1]);
    o->x[0] = p.x, o->x[1] = p.y;
}
static double square_p(const double *x, void *c)
{
    (void)c;
    return smp_unit_square_pdf(vec2_make(x[0], x[1]));
}
static void disc_s(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    vec2 p = smp_disc_concentric_sample(u[0], u[1]);
    o->x[0] = p.x, o->x[1] = p.y;
}
static double disc_p(const double *x, void *c)
{
    (void)c;
    return smp_disc_concentric_pdf(vec2_make(x[0], x[1]));
}
static void tri_s(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    vec2 p = smp_triangle_sample(u[0], u[1]);
    o->x[0] = p.x, o->x[1] = p.y;
}
static double tri_p(const double *x, void *c)
{
    (void)c, (void)x;
    return 2.0; /* the triangle's density; the check masks the square's other half */
}
static void lin_s(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    o->x[0] = smp_linear_sample(u[0]);
}
static double lin_p(const double *x, void *c)
{
    (void)c;
    return smp_linear_pdf(x[0]);
}
static void sph_s(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    vec3 w = smp_uniform_sphere_sample(u[0], u[1]);
    o->x[0] = w.x, o->x[1] = w.y, o->x[2] = w.z;
}
static double sph_p(const double *x, void *c)
{
    (void)c, (void)x;
    return MC_INV_4PI;
}

static void test_basic_domains(void **state)
{
    (void)state;
    struct {
        mcbox_domain_kind k;
        void (*s)(const double *, mcbox_sample *, void *);
        double (*p)(const double *, void *);
    } cases[] = {{MCBOX_SQUARE, square_s, square_p},   {MCBOX_DISC, disc_s, disc_p},
                 {MCBOX_TRIANGLE, tri_s, tri_p},       {MCBOX_INTERVAL, lin_s, lin_p},
                 {MCBOX_SPHERE, sph_s, sph_p}};
    for (int k = 0; k < 5; k++) {
        uint64_t seed = mc_test_seed(9106 + (uint64_t)k);
        mcbox_sampler m = mcbox_sampler_init(cases[k].k);
        m.sample = cases[k].s, m.pdf = cases[k].p;
        if (cases[k].k == MCBOX_INTERVAL)
            m.domain.a = 0.0, m.domain.b = 2.0;
        mcbox_check_options o = suite_options(N_SMALL, seed);
        mcbox_check_result r;
        assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
        printf("  %-10s stat %10.2f dof %5d p %.3g integral %.9f %s\n",
               mcbox_domain_name(cases[k].k), r.statistic, r.dof, r.pvalue, r.pdf_integral,
               r.message);
        assert_seeded(r.pass, seed);
    }
}

/* Samples that are not points and densities that are not densities: a
 * NaN coordinate, a point off the domain, a pdf that goes negative. Each
 * is a failed verdict with the sample named, never a pass. */
static void nan_sample(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    my_cosine_sample(u, o, NULL);
    if (u[0] < 1e-3)
        o->x[2] = (double)NAN;
}
static void long_sample(const double *u, mcbox_sample *o, void *c)
{
    (void)c;
    my_cosine_sample(u, o, NULL);
    if (u[0] > 0.999)
        o->x[0] *= 2.0;
}
static double negative_pdf(const double *x, void *c)
{
    (void)c;
    return x[2] > 0.9 ? -0.1 : my_cosine_pdf(x, NULL);
}

static void test_bad_samples_and_densities(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(9111);
    mcbox_check_options o = suite_options(50000, seed);
    mcbox_check_result r;
    mcbox_sampler m = my_cosine(NULL);
    m.invert = NULL;
    m.sample = nan_sample;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  NaN samples: %s\n", r.message);
    assert_seeded(negctl_record(t, "NaN coordinates", "finite samples",
                                !r.pass && r.nonfinite > 0 && strstr(r.message, "sample")),
                  seed);
    m.sample = long_sample;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  off the sphere: %s\n", r.message);
    assert_seeded(negctl_record(t, "directions of length != 1", "domain",
                                !r.pass && r.outside > 0),
                  seed);
    m.sample = my_cosine_sample, m.pdf = negative_pdf;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), 0);
    printf("  negative pdf: %s\n", r.message);
    assert_seeded(negctl_record(t, "pdf negative near the pole", "density values",
                                !r.pass && r.bad_pdf > 0),
                  seed);
}

/* Points drawn elsewhere (a file, a GPU): the same statistic as drawing
 * them through mcbox_check_run from the same uniforms. */
static void test_points_equal_run(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(9112);
    enum { N = 100000 };
    static mcbox_sample pts[N];
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (int i = 0; i < N; i++) {
        double u[2] = {mc_rng_uniform(&rng), mc_rng_uniform(&rng)};
        pts[i].pdf = pts[i].weight = (double)NAN;
        pts[i].atom = -1;
        my_cosine_sample(u, &pts[i], NULL);
    }
    mcbox_sampler m = my_cosine(NULL);
    m.invert = NULL;
    mcbox_check_options o = suite_options(N, seed);
    mcbox_check_result a, b;
    assert_int_equal(mcbox_check_run(&m, &o, &a, NULL), 0);
    assert_int_equal(mcbox_check_points(&m, pts, N, &o, &b, NULL), 0);
    assert_true(memcmp(&a.statistic, &b.statistic, sizeof(double)) == 0);
    assert_int_equal(a.dof, b.dof);
    assert_seeded(b.pass, seed);
}

/* Frequency tables made elsewhere: a fair table passes, a table with one
 * cell 20 sigma off fails, invalid tables are refused. */
static void test_counts(void **state)
{
    negctl *t = *state;
    enum { CELLS = 100 };
    double obs[CELLS], expct[CELLS];
    for (int k = 0; k < CELLS; k++) {
        expct[k] = 1000.0;
        obs[k] = 1000.0 + (k % 2 ? 20.0 : -20.0); /* chi-square 40 on 99 dof */
    }
    mcbox_check_options o = mcbox_check_defaults();
    mcbox_check_result r;
    assert_int_equal(mcbox_check_counts(obs, expct, CELLS, &o, &r), 0);
    assert_near(r.statistic, 40.0, 1e-9);
    assert_int_equal(r.dof, 99);
    assert_near(r.pvalue, mc_chi2_pvalue(40.0, 99), 0.0);
    assert_true(r.pass);
    obs[7] += 20.0 * sqrt(1000.0);
    obs[8] -= 20.0 * sqrt(1000.0);
    assert_int_equal(mcbox_check_counts(obs, expct, CELLS, &o, &r), 0);
    assert_true(negctl_record(t, "table with two cells 20 sigma off", "mcbox_check_counts",
                              !r.pass));
    expct[3] = -1.0;
    assert_int_equal(mcbox_check_counts(obs, expct, CELLS, &o, &r), -1);
    assert_non_null(strstr(r.message, "expected[3]"));
}

/* Invalid calls come back as -1 with a message, never a crash. */
static void test_invalid_calls(void **state)
{
    (void)state;
    mcbox_check_options o = mcbox_check_defaults();
    mcbox_check_result r;
    mcbox_sampler m = my_cosine(NULL);
    m.pdf = NULL;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "pdf"));
    m = my_cosine(NULL);
    o.alpha = 1.5;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "alpha"));
    o = mcbox_check_defaults();
    m.domain.kind = MCBOX_CATALOG, m.domain.row = "no-such-row";
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "no-such-row"));
    m = mcbox_sampler_init(MCBOX_INTERVAL);
    m.sample = lin_s, m.pdf = lin_p, m.domain.a = 2.0, m.domain.b = 1.0;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "interval"));
    mcbox_domain_kind k;
    assert_true(mcbox_domain_parse("hemisphere", &k) && k == MCBOX_HEMISPHERE);
    assert_false(mcbox_domain_parse("hemisfear", &k));
    assert_string_equal(mcbox_version(), "0.2.0");
    o = mcbox_check_defaults();
    o.quad_depth = 31;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "quad_depth"));
    o = mcbox_check_defaults();
    o.quad_error_max = 0.0;
    assert_int_equal(mcbox_check_run(&m, &o, &r, NULL), -1);
    assert_non_null(strstr(r.message, "quad_error_max"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_catalog_through_api),
        cmocka_unit_test(test_negatives_through_api),
        cmocka_unit_test(test_basic_domain_matches_harness),
        cmocka_unit_test(test_reported_pdf_weight_invert),
        cmocka_unit_test(test_atoms),
        cmocka_unit_test(test_pdf_batch),
        cmocka_unit_test(test_basic_domains),
        cmocka_unit_test(test_bad_samples_and_densities),
        cmocka_unit_test(test_points_equal_run),
        cmocka_unit_test(test_counts),
        cmocka_unit_test(test_invalid_calls),
    };
    mc_test_select();
    return cmocka_run_group_tests(tests, negctl_group_setup, negctl_group_teardown);
}
