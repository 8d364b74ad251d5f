/* tests/test_discrete.c - the CDF-table and alias samplers of
 * samplers/discrete.h, the rows of family "discrete" of the catalog
 * (catalog/catalog.h): chi-square, normalization and domain of their cases
 * through the shared harness (tests/support/warp_check.h); chi-square of
 * every row against the weights with the uniform each table leaves over;
 * zero weights never drawn, exact alias probabilities, input validation,
 * round trip.
 *
 * Statistics (seeds overridable with MC_TEST_SEED): chi-square with 10^6
 * draws per catalog case (one cell per outcome) and 4 x 10^5 draws per
 * row and weight set (4 cells per outcome), rejected at
 * chi2_suite_alpha() ~ 1.6e-4 (Sidak: 1% over the suite's 64 tests). */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/rng.h"
#include "samplers/discrete.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"
#include "tests/support/warp_check.h"

/* The rows of the catalog this program tests. */
static const char *const families[] = {"discrete"};

enum { MAXN = 128 };

/* The eight events of the lecture slides "Solving the Rendering
 * Equation", weights not normalized ("high-entropy" values so that a
 * missing factor cannot hide). */
static const double w8[8] = {1.5, 4.0, 2.385, 0.25, 6.0, 3.1, 0.75, 2.0};

/* A table of either kind over weights w[0..n), for the unit tests of the
 * tables themselves. */
typedef struct table_case {
    const double *w;
    size_t n;
    double total;
    smp_discrete_cdf cdf;
    smp_alias alias;
    double cdf_storage[MAXN];
    smp_alias_cell alias_storage[MAXN];
} table_case;

static void build(table_case *c, const double *w, size_t n)
{
    c->w = w;
    c->n = n;
    c->total = 0.0;
    for (size_t k = 0; k < n; k++)
        c->total += w[k];
    assert_true(smp_discrete_cdf_init(&c->cdf, w, n, c->cdf_storage));
    assert_true(smp_alias_init(&c->alias, w, n, c->alias_storage));
}

/* A catalog row's table over weights w[0..n), as a chi-square case: the
 * sample is k + r, r the uniform the table leaves over (x[1] of the
 * catalog's sample), so each event is a unit interval of the parameter
 * line and the claimed density there is w_k / sum(w) of the claimed
 * weights (not the table's). Cells of width 1/4 test that r is uniform
 * given the event as well. */
typedef struct row_table {
    cat_state s; /* the table drawn from */
    const double *w; /* the weights claimed */
    size_t n;
    double total;
} row_table;

static void row_table_build(row_table *t, const cat_row *r, const double *w_sampled,
                            const double *w_claimed, size_t n)
{
    cat_values v;
    cat_defaults(r, &v);
    for (size_t k = 0; k < n; k++)
        v.weights[k] = w_sampled[k];
    v.n_weights = n;
    char err[256];
    if (!cat_prepare(r, &v, &t->s, err, sizeof err))
        fail_msg("%s", err);
    t->w = w_claimed;
    t->n = n;
    t->total = 0.0;
    for (size_t k = 0; k < n; k++)
        t->total += w_claimed[k];
}

static void sample_table(mc_rng *rng, void *ctx, double out[2])
{
    const row_table *t = ctx;
    double x[3];
    cat_sample(&t->s, rng, x);
    out[0] = x[0] + x[1];
    out[1] = 0.0;
}

static double pdf_table(const double x[2], void *ctx)
{
    const row_table *t = ctx;
    if (!(x[0] >= 0.0 && x[0] < (double)t->n))
        return 0.0;
    return t->w[(size_t)x[0]] / t->total;
}

static chi2_outcome run(row_table *t, const char *name, uint64_t seed)
{
    chi2_spec s = {name, {1, {0.0, 0.0}, {(double)t->n, 1.0}, {(int)(4 * t->n), 1}, sample_table,
                          pdf_table, t}};
    chi2_outcome o = chi2_run(&s, 400000u, seed, chi2_suite_alpha());
    chi2_print(&s, &o);
    return o;
}

/* 40 weights with zeros among them, from a fixed generator. */
static void weights40(double *w)
{
    mc_rng rng = mc_rng_derive(2385u, 0u);
    for (int k = 0; k < 40; k++)
        w[k] = k % 7 == 3 ? 0.0 : 0.1 + 3.0 * mc_rng_uniform(&rng);
}

/* Chi-square of every row on the 8 events and on 40 events with zeros:
 * 4 x 10^5 draws, 4 cells per event (expected from the weights, not from
 * the tables), seeds 5001 + i (8 events) and 5003 + i (40), i the row's
 * position in the family. */
static void test_discrete_chi2(void **state)
{
    (void)state;
    static row_table t;
    double w40[40];
    weights40(w40);
    for (size_t i = 0, seq = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        if (strcmp(r->family, families[0]) != 0)
            continue;
        char name[64];
        row_table_build(&t, r, w8, w8, 8);
        uint64_t seed = mc_test_seed(5001u + seq);
        snprintf(name, sizeof name, "%s-8", r->name);
        chi2_outcome o = run(&t, name, seed);
        if (o.reject)
            fail_msg("%s on 8 events: p %.3g (seed %llu)", r->name, o.r.pvalue,
                     (unsigned long long)seed);
        row_table_build(&t, r, w40, w40, 40);
        seed = mc_test_seed(5003u + seq);
        snprintf(name, sizeof name, "%s-40", r->name);
        o = run(&t, name, seed);
        if (o.reject)
            fail_msg("%s on 40 events: p %.3g (seed %llu)", r->name, o.r.pvalue,
                     (unsigned long long)seed);
        seq++;
    }
}

/* Negative controls: tables built from the weights with events 2 and 5
 * swapped, tested against the true weights, must be rejected (seed
 * 5011). */
static void test_discrete_chi2_negative_controls(void **state)
{
    negctl *t = *state;
    static row_table c;
    double swapped[8];
    for (int k = 0; k < 8; k++)
        swapped[k] = w8[k];
    swapped[2] = w8[5];
    swapped[5] = w8[2];
    bool all = true;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        if (strcmp(r->family, families[0]) != 0)
            continue;
        char name[64], label[96];
        row_table_build(&c, r, swapped, w8, 8);
        snprintf(name, sizeof name, "negctl-%s-swapped", r->name);
        snprintf(label, sizeof label, "%s table of swapped weights", r->name);
        chi2_outcome o = run(&c, name, mc_test_seed(5011u));
        all &= negctl_record(t, label, "chi-square", o.reject);
    }
    assert_true(all);
}

/* Events of weight 0 are never drawn, whatever u: a grid of 10^5 u plus
 * every table boundary and its neighbours. */
static void test_discrete_zero_weights_never_drawn(void **state)
{
    (void)state;
    static const double w[7] = {0.0, 1.0, 0.0, 0.0, 2.385, 0.0, 0.0};
    static table_case c;
    build(&c, w, 7);
    double us[100000 + 3 * 7];
    size_t m = 0;
    for (int i = 0; i < 100000; i++)
        us[m++] = i / 100000.0;
    for (size_t k = 0; k < 7; k++) {
        us[m++] = c.cdf.cdf[k] < 1.0 ? c.cdf.cdf[k] : 0.5;
        us[m++] = nextafter(c.cdf.cdf[k], 0.0);
        us[m++] = c.cdf.cdf[k] < 1.0 ? nextafter(c.cdf.cdf[k], 1.0) : 0.25;
    }
    us[0] = 0.0;
    us[1] = 1.0 - 0x1p-53;
    for (size_t i = 0; i < m; i++) {
        size_t a = smp_discrete_cdf_sample(&c.cdf, us[i], NULL);
        size_t b = smp_alias_sample(&c.alias, us[i], NULL);
        if (w[a] == 0.0 || w[b] == 0.0)
            fail_msg("u = %.17g draws cdf %zu, alias %zu", us[i], a, b);
    }
}

/* pmf equals the normalized weights (1e-15) and both tables agree; the
 * alias table's implied probabilities, (threshold_k + sum of 1 - threshold_j
 * over columns j aliased to k) / n, equal the pmf to 1e-13: the
 * construction is exact up to rounding, so no statistics are needed. */
static void test_discrete_pmf_and_alias_exact(void **state)
{
    (void)state;
    static table_case c;
    double w40[40];
    weights40(w40);
    build(&c, w40, 40);
    double implied[40] = {0}, sum = 0.0;
    for (size_t j = 0; j < 40; j++) {
        const smp_alias_cell *cell = &c.alias.cells[j];
        assert_true(cell->threshold >= 0.0 && cell->threshold <= 1.0 && cell->alias < 40);
        implied[j] += cell->threshold / 40.0;
        implied[cell->alias] += (1.0 - cell->threshold) / 40.0;
    }
    for (size_t k = 0; k < 40; k++) {
        double p = w40[k] / c.total;
        assert_near(smp_discrete_cdf_pmf(&c.cdf, k), p, 1e-15);
        assert_near(smp_alias_pmf(&c.alias, k), p, 1e-15);
        assert_near(implied[k], p, 1e-13);
        sum += smp_alias_pmf(&c.alias, k);
    }
    assert_near(sum, 1.0, 1e-14);
    assert_true(smp_alias_pmf(&c.alias, 40) == 0.0 && smp_discrete_cdf_pmf(&c.cdf, 40) == 0.0);
}

/* Invalid weights are refused; one event is always drawn. */
static void test_discrete_input_validation(void **state)
{
    (void)state;
    double storage[4];
    smp_alias_cell cells[4];
    smp_discrete_cdf d;
    smp_alias a;
    const double bad[][4] = {{1.0, -0.5, 1.0, 1.0}, {1.0, nan(""), 1.0, 1.0}, {1.0, HUGE_VAL, 1.0, 1.0},
                             {0.0, 0.0, 0.0, 0.0}, {1e308, 1e308, 1e308, 1.0}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_false(smp_discrete_cdf_init(&d, bad[i], 4, storage));
        assert_false(smp_alias_init(&a, bad[i], 4, cells));
    }
    assert_false(smp_discrete_cdf_init(&d, w8, 0, storage));
    assert_false(smp_alias_init(&a, w8, 0, cells));
    const double one = 2.385;
    assert_true(smp_discrete_cdf_init(&d, &one, 1, storage) && smp_alias_init(&a, &one, 1, cells));
    for (int i = 0; i <= 10; i++) {
        double u = i < 10 ? i / 10.0 : 1.0 - 0x1p-53;
        assert_int_equal(smp_discrete_cdf_sample(&d, u, NULL), 0);
        assert_int_equal(smp_alias_sample(&a, u, NULL), 0);
    }
}

/* The CDF table: ties u == cdf[k] go to k + 1; sample(invert(k, r)) gives
 * back k and r (to 1e-12); remapped values lie in [0, 1). */
static void test_discrete_cdf_roundtrip(void **state)
{
    (void)state;
    static table_case c;
    build(&c, w8, 8);
    for (size_t k = 0; k + 1 < 8; k++)
        assert_int_equal(smp_discrete_cdf_sample(&c.cdf, c.cdf.cdf[k], NULL), k + 1);
    for (size_t k = 0; k < 8; k++) {
        for (int i = 0; i < 100; i++) {
            double r = (i + 0.5) / 100.0, back;
            size_t got = smp_discrete_cdf_sample(&c.cdf, smp_discrete_cdf_invert(&c.cdf, k, r), &back);
            assert_int_equal(got, k);
            assert_near(back, r, 1e-12);
        }
    }
    mc_rng rng = mc_rng_derive(mc_test_seed(5021u), 0u);
    for (int i = 0; i < 100000; i++) {
        double r1, r2, u = mc_rng_uniform(&rng);
        (void)smp_discrete_cdf_sample(&c.cdf, u, &r1);
        (void)smp_alias_sample(&c.alias, u, &r2);
        assert_true(r1 >= 0.0 && r1 < 1.0 && r2 >= 0.0 && r2 < 1.0);
    }
}

int main(void)
{
    struct CMUnitTest tests[32];
    size_t n = 0;
    warp_catalog_tests(families, 1, tests, &n, 24);
    const struct CMUnitTest own[] = {
        cmocka_unit_test(test_discrete_chi2),
        cmocka_unit_test(test_discrete_chi2_negative_controls),
        cmocka_unit_test(test_discrete_zero_weights_never_drawn),
        cmocka_unit_test(test_discrete_pmf_and_alias_exact),
        cmocka_unit_test(test_discrete_input_validation),
        cmocka_unit_test(test_discrete_cdf_roundtrip),
    };
    for (size_t k = 0; k < sizeof own / sizeof own[0]; k++)
        tests[n++] = own[k];
    return _cmocka_run_group_tests("test_discrete", tests, n, negctl_group_setup,
                                   negctl_group_teardown);
}
