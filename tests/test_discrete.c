/* tests/test_discrete.c - the CDF-table and alias samplers of
 * samplers/discrete.h: chi-square against the weights, zero weights never
 * drawn, exact alias probabilities, input validation, round trip. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>

#include "mc/rng.h"
#include "samplers/discrete.h"
#include "tests/support/chi2_harness.h"
#include "tests/support/negctl.h"

enum { MAXN = 128 };

/* The lecture's eight events, weights not normalized ("high-entropy"
 * values so that a missing factor cannot hide). */
static const double w8[8] = {1.5, 4.0, 2.385, 0.25, 6.0, 3.1, 0.75, 2.0};

/* A table of either kind over weights w[0..n), as a chi-square case: the
 * sample is k + u_remapped, so each event is a unit interval of the
 * parameter line and the claimed density there is w_k / sum(w). Cells of
 * width 1/4 test that the remapped u is uniform given the event as well. */
typedef struct table_case {
    const double *w;     /* the weights the pdf claims */
    size_t n;
    double total;
    smp_discrete_cdf cdf;
    smp_alias alias;
    bool use_alias;
    double cdf_storage[MAXN];
    smp_alias_cell alias_storage[MAXN];
} table_case;

static void build(table_case *c, const double *w_sampled, const double *w_claimed, size_t n, bool use_alias)
{
    c->w = w_claimed;
    c->n = n;
    c->total = 0.0;
    for (size_t k = 0; k < n; k++)
        c->total += w_claimed[k];
    c->use_alias = use_alias;
    assert_true(smp_discrete_cdf_init(&c->cdf, w_sampled, n, c->cdf_storage));
    assert_true(smp_alias_init(&c->alias, w_sampled, n, c->alias_storage));
}

static void sample_table(mc_rng *rng, void *ctx, double out[2])
{
    const table_case *c = ctx;
    double u = mc_rng_uniform(rng), r;
    size_t k = c->use_alias ? smp_alias_sample(&c->alias, u, &r) : smp_discrete_cdf_sample(&c->cdf, u, &r);
    out[0] = (double)k + r;
    out[1] = 0.0;
}

static double pdf_table(const double x[2], void *ctx)
{
    const table_case *c = ctx;
    if (!(x[0] >= 0.0 && x[0] < (double)c->n))
        return 0.0;
    return c->w[(size_t)x[0]] / c->total;
}

static chi2_outcome run(table_case *c, const char *name, uint64_t seed)
{
    chi2_spec s = {name, 1, {0.0, 0.0}, {(double)c->n, 1.0}, {(int)(4 * c->n), 1},
                   sample_table, pdf_table, c};
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

/* Chi-square of both samplers on the 8 events and on 40 events with
 * zeros: 4 x 10^5 draws, 4 cells per event (expected from the weights, not
 * from the tables), level chi2_suite_alpha() ~ 1.6e-4, seeds 5001..5004. */
static void test_discrete_chi2(void **state)
{
    (void)state;
    static table_case c;
    double w40[40];
    weights40(w40);
    for (int alias = 0; alias < 2; alias++) {
        build(&c, w8, w8, 8, alias);
        uint64_t seed = mc_test_seed(5001u + (uint64_t)alias);
        chi2_outcome o = run(&c, alias ? "alias-8" : "cdf-8", seed);
        if (o.reject)
            fail_msg("%s on 8 events: p %.3g (seed %llu)", alias ? "alias" : "cdf", o.r.pvalue,
                     (unsigned long long)seed);
        build(&c, w40, w40, 40, alias);
        seed = mc_test_seed(5003u + (uint64_t)alias);
        o = run(&c, alias ? "alias-40" : "cdf-40", seed);
        if (o.reject)
            fail_msg("%s on 40 events: p %.3g (seed %llu)", alias ? "alias" : "cdf", o.r.pvalue,
                     (unsigned long long)seed);
    }
}

/* Negative controls: tables built from the weights with events 2 and 5
 * swapped, tested against the true weights, must be rejected. */
static void test_discrete_chi2_negative_controls(void **state)
{
    negctl *t = *state;
    static table_case c;
    double swapped[8];
    for (int k = 0; k < 8; k++)
        swapped[k] = w8[k];
    swapped[2] = w8[5];
    swapped[5] = w8[2];
    bool all = true;
    for (int alias = 0; alias < 2; alias++) {
        build(&c, swapped, w8, 8, alias);
        chi2_outcome o = run(&c, alias ? "negctl-alias-swapped" : "negctl-cdf-swapped", mc_test_seed(5011u));
        all &= negctl_record(t, alias ? "alias table of swapped weights" : "cdf table of swapped weights",
                             "chi-square", o.reject);
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
    build(&c, w, w, 7, false);
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
    build(&c, w40, w40, 40, true);
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
    build(&c, w8, w8, 8, false);
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
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_discrete_chi2),
        cmocka_unit_test(test_discrete_chi2_negative_controls),
        cmocka_unit_test(test_discrete_zero_weights_never_drawn),
        cmocka_unit_test(test_discrete_pmf_and_alias_exact),
        cmocka_unit_test(test_discrete_input_validation),
        cmocka_unit_test(test_discrete_cdf_roundtrip),
    };
    return cmocka_run_group_tests_name("test_discrete", tests, negctl_group_setup, negctl_group_teardown);
}
