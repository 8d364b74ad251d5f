/* tests/test_catalog_meta.c - the catalog's metadata held against its own
 * densities (catalog/catalog.h): for every row,
 *   - the support edges: the sampler at every corner of its uniforms'
 *     cube, each uniform 0 or the largest double below 1
 *     (nextafter(1, 0), the most mc_rng_uniform returns), gives finite
 *     points inside the row's domain with a finite, non-negative density
 *     (infinite only at the pole of a row that says pole_infinite, or at
 *     the end of a line domain where the density diverges), and an
 *     inner point a positive one;
 *   - the domain's ends: a line row's domain text "[a,b]" is its chart's
 *     [lo, hi], the sampler maps u = 0 to lo and the top uniform to within
 *     1e-6 of hi, the density is 0 one ulp outside either end and
 *     integrates to 1 over [lo, hi]; a direction row's density is 0 just
 *     below its lowest cos theta and integrates to 1 over the cap above
 *     it; a discrete row's probabilities sum to 1;
 *   - the parameters' ends: each numeric parameter at its closed ends is
 *     accepted (and the row then samples finite points with finite
 *     densities), at its open ends and one ulp outside refused;
 *   - the parameter text: cat_param_defaults into every buffer size from 1
 *     to one past the text truncates to a terminated prefix, writes
 *     nothing past the buffer and returns the whole text's length (so a
 *     caller can tell a cut), and the full text parsed back gives the
 *     default densities bit for bit.
 * Negative controls: the catalog's rows with a wrong density
 * (catalog/negatives.c: the cosine without 1/pi, the hemisphere with the
 * sphere's 1/(4 pi)) must fail the normalisation. Compiling with
 * -DMETA_BREAK=k perturbs expectation k (1 support edge, 2 domain ends,
 * 3 parameter ends, 4 parameter text) so that it fails. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "mc/constants.h"
#include "tests/support/negctl.h"

#ifndef META_BREAK
#define META_BREAK 0
#endif

/* The largest double below 1: the top of every uniform the samplers see. */
static double top_uniform(void)
{
#if META_BREAK == 1
    return 1.0; /* outside [0, 1): a closed end no generator gives */
#else
    return nextafter(1.0, 0.0);
#endif
}

/* The lowest cos theta about +z of a direction state's domain: its
 * chart's (a cone's prepare moves it to cos_max), or -1 for a chart that
 * is not a cap about +z. */
static double cap_lo(const cat_state *s)
{
    if (s->chart != CAT_CHART_DIRECTION || s->dir_chart.kind != PDF_CHART_SPHERICAL ||
        s->dir_chart.frame.n.z != 1.0)
        return -1.0;
    return s->dir_chart.cos_lo;
}

/* Whether x, a point of row r's kind, lies in its domain; a direction
 * within 1e-12 of unit length and of the lowest cos theta (rounding of
 * the warps' trigonometry). */
static bool in_domain(const cat_state *s, const double x[3])
{
    const cat_row *r = s->row;
    for (int k = 0; k < cat_point_dims(r); k++)
        if (!isfinite(x[k]))
            return false;
    if (r->in_support && !r->in_support(s, x))
        return false;
    switch (r->point) {
    case CAT_DIRECTION:
        return fabs(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1.0) < 1e-12 &&
               x[2] >= cap_lo(s) - 1e-12;
    case CAT_PLANAR:
        if (r->chart == CAT_CHART_DISC)
            return x[0] * x[0] + x[1] * x[1] <= 1.0 + 1e-12;
        return x[0] >= 0.0 && x[0] <= 1.0 && x[1] >= 0.0 && x[1] <= 1.0;
    case CAT_REAL:
        return x[0] >= r->lo && x[0] <= r->hi;
    case CAT_INDEX:
        return x[0] >= 0.0 && x[0] < (double)s->p.n_weights && x[0] == floor(x[0]);
    case CAT_POINT:
        return true;
    }
    return false;
}

/* Whether the density at x is acceptable: not NaN, >= 0, finite except at
 * the pole of a row whose density is infinite there. */
static bool density_ok(const cat_state *s, const double x[3], double density)
{
    const cat_row *r = s->row;
    if (isnan(density) || density < 0.0)
        return false;
    if (isfinite(density))
        return true;
    if (r->point == CAT_DIRECTION)
        return r->pole_infinite && x[2] > 1.0 - 1e-12;
    /* A line density may diverge at an end of its domain (log-ends:
     * -ln(2 x / pi) / pi); the end itself, where the sampler puts u = 0,
     * is then the one point of infinite density, and one ulp inside it
     * must be finite. */
    if (r->point == CAT_REAL && (x[0] == r->lo || x[0] == r->hi)) {
        double in[3] = {nextafter(x[0], x[0] == r->lo ? r->hi : r->lo), 0.0, 0.0};
        return isfinite(cat_pdf(s, in));
    }
    return false;
}

/* The support edges of a prepared state: every corner of the uniforms'
 * cube, and the point with every uniform 0.3 (inside, with a positive
 * density; not 0.5, which log-ends maps to its density's zero at pi / 2),
 * for a row sampled from uniforms; 64 points from a
 * generator (seed 2501) otherwise. Returns false, naming the point, on
 * the first bad one. */
static bool edges_ok(const cat_state *s, const char *what)
{
    const cat_row *r = s->row;
    double x[3];
    if (r->uniforms == 0) {
        mc_rng rng = mc_rng_derive(mc_test_seed(2501u), 0u);
        for (int k = 0; k < 64; k++) {
            cat_sample(s, &rng, x);
            double p = cat_pdf(s, x);
            if (!in_domain(s, x) || !density_ok(s, x, p) || !(p > 0.0)) {
                printf("%s: drawn point %d (%g, %g, %g), density %g\n", what, k, x[0], x[1], x[2], p);
                return false;
            }
        }
        return true;
    }
    int corners = 1 << r->uniforms;
    for (int c = 0; c <= corners; c++) {
        double u[4];
        for (int k = 0; k < r->uniforms; k++)
            u[k] = c == corners ? 0.3 : (c >> k & 1) ? top_uniform() : 0.0;
        x[0] = x[1] = x[2] = 0.0;
        r->sample_u(s, u, x);
        double p = cat_pdf(s, x);
        bool ok = in_domain(s, x) && density_ok(s, x, p) && (c < corners || p > 0.0);
        if (!ok) {
            printf("%s: corner %d of the uniforms gives (%.17g, %.17g, %.17g), density %g\n", what,
                   c, x[0], x[1], x[2], p);
            return false;
        }
    }
    return true;
}

/* Every row with its defaults at the support edges. */
static void test_support_edges(void **state)
{
    (void)state;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        cat_state s;
        char err[256];
        assert_true(cat_prepare_named(r->name, &s, err, sizeof err));
        if (!edges_ok(&s, r->name))
            fail_msg("row %s: a support edge leaves the domain or has a bad density", r->name);
    }
}

/* --- the domain's ends ------------------------------------------------- */

/* "pi" or a number. */
static double end_value(const char *t, size_t len)
{
    if (len == 2 && strncmp(t, "pi", 2) == 0)
        return MC_PI;
    char buf[32];
    snprintf(buf, sizeof buf, "%.*s", (int)len, t);
    return strtod(buf, NULL);
}

/* The integral of the density of a line row over [lo, hi] (midpoint rule,
 * 200000 cells: the densities are smooth inside, at worst logarithmic at
 * an end, which the rule's open points never touch) and of a direction
 * row over the cap cos theta >= lo (midpoint rule in theta and phi,
 * d omega = sin theta d theta d phi, which also tames a 1 / sin theta at
 * the pole: 800 x 64 cells for the lobes about +z, all symmetric about
 * it). */
static double line_integral(const cat_state *s)
{
    const cat_row *r = s->row;
    enum { N = 200000 };
    double h = (r->hi - r->lo) / N, sum = 0.0;
    for (int k = 0; k < N; k++) {
        double x[3] = {r->lo + (k + 0.5) * h, 0.0, 0.0};
        sum += cat_pdf(s, x);
    }
    return sum * h;
}

static double cap_integral(const cat_state *s)
{
    enum { NT = 800, NP = 64 };
    double theta_max = acos(cap_lo(s)), ht = theta_max / NT, hp = 2.0 * MC_PI / NP, sum = 0.0;
    for (int i = 0; i < NT; i++) {
        double th = (i + 0.5) * ht;
        for (int j = 0; j < NP; j++) {
            double ph = (j + 0.5) * hp;
            double x[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
            sum += cat_pdf(s, x) * sin(th);
        }
    }
    return sum * ht * hp;
}

/* Whether a density's integral over its domain is 1 within tol, for the
 * rows the normalisation covers (lines, lobes about +z from uniforms,
 * discrete tables); *checked false for any other row. */
static bool normalised(const cat_state *s, double tol, double *integral, bool *checked)
{
    const cat_row *r = s->row;
    *checked = true;
    if (r->point == CAT_REAL) {
        *integral = line_integral(s);
    } else if (r->point == CAT_DIRECTION && r->uniforms > 0) {
        *integral = cap_integral(s);
    } else if (r->point == CAT_INDEX) {
        *integral = 0.0;
        for (size_t k = 0; k < s->p.n_weights; k++) {
            double x[3] = {(double)k, 0.0, 0.0};
            *integral += cat_pdf(s, x);
        }
    } else {
        *checked = false;
        return true;
    }
#if META_BREAK == 2
    *integral *= 1.01;
#endif
    return fabs(*integral - 1.0) < tol;
}

/* The ends of each line row's domain text against its chart, the sampler
 * and the density; each direction row's density below its cap; every
 * covered row's normalisation (tolerance 1e-4: the midpoint rules' error
 * on these densities is below 1e-6, the tolerance leaves room for the
 * peaked lobe at n = 40). Negative controls: the wrong densities of
 * catalog/negatives.c must fail the normalisation. */
static void test_domain_ends(void **state)
{
    negctl *nc = *state;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        cat_state s;
        char err[256];
        assert_true(cat_prepare_named(r->name, &s, err, sizeof err));
        if (r->point == CAT_REAL) {
            const char *comma = strchr(r->domain, ',');
            size_t n = strlen(r->domain);
            assert_true(r->domain[0] == '[' && comma && r->domain[n - 1] == ']');
            double a = end_value(r->domain + 1, (size_t)(comma - r->domain - 1));
            double b = end_value(comma + 1, (size_t)(r->domain + n - 1 - comma - 1));
            assert_near(a, r->lo, 0.0);
            assert_near(b, r->hi, 0.0);
            double u0[1] = {0.0}, u1[1] = {top_uniform()}, x0[3] = {0}, x1[3] = {0};
            r->sample_u(&s, u0, x0);
            r->sample_u(&s, u1, x1);
            double below[3] = {nextafter(r->lo, -HUGE_VAL), 0.0, 0.0};
            double above[3] = {nextafter(r->hi, HUGE_VAL), 0.0, 0.0};
            printf("%s: domain %s, u = 0 -> %.17g, top u -> %.17g, density outside %g, %g\n", r->name,
                   r->domain, x0[0], x1[0], cat_pdf(&s, below), cat_pdf(&s, above));
            assert_near(x0[0], r->lo, 1e-12 * (r->hi - r->lo));
            assert_true(x1[0] <= r->hi && x1[0] >= r->hi - 1e-6 * (r->hi - r->lo));
            assert_true(cat_pdf(&s, below) == 0.0 && cat_pdf(&s, above) == 0.0);
        }
        if (r->point == CAT_DIRECTION && cap_lo(&s) > -1.0) {
            double c = cap_lo(&s) - 1e-3, x[3] = {sqrt(1.0 - c * c), 0.0, c};
            assert_true(cat_pdf(&s, x) == 0.0);
        }
        double integral = 0.0;
        bool checked;
        bool ok = normalised(&s, 1e-4, &integral, &checked);
        if (checked)
            printf("%s: density integrates to %.8f over its domain\n", r->name, integral);
        if (!ok)
            fail_msg("row %s: density integrates to %.8f over its domain", r->name, integral);
    }
    static const char *const wrong[2] = {"wrong-cosine-no-pi", "wrong-hemisphere-4pi"};
    for (int k = 0; k < 2; k++) {
        cat_state s;
        char err[256];
        assert_true(cat_prepare_named(wrong[k], &s, err, sizeof err));
        double integral = 0.0;
        bool checked;
        bool caught = !normalised(&s, 1e-4, &integral, &checked) && checked;
        printf("negative row %s integrates to %.6f\n", wrong[k], integral);
        if (!negctl_record(nc, wrong[k], "normalisation over the domain", caught))
            fail_msg("%s was not caught", wrong[k]);
    }
}

/* --- the parameters' ends ---------------------------------------------- */

/* Row r with its defaults and parameter key set to value through its
 * text form ("key=%.17g", which reads back to the same double), prepared
 * into *s; false if refused at either step. */
static bool prepare_with(const cat_row *r, const char *key, double value, cat_state *s)
{
    cat_values v;
    char text[96], err[256];
    cat_defaults(r, &v);
    snprintf(text, sizeof text, "%s=%.17g", key, value);
    return cat_set_param(r, &v, text, err, sizeof err) && cat_prepare(r, &v, s, err, sizeof err);
}

/* Each numeric parameter at its ends: a closed finite end accepted (and
 * the row sampling finite points with finite densities there), an open
 * one refused, one ulp outside either refused; an infinite end refused
 * (the text parser takes finite numbers only). */
static void test_parameter_ends(void **state)
{
    (void)state;
    int ends = 0;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        for (const cat_param *p = r->params; p->key; p++) {
            if (p->kind != CAT_NUMBER)
                continue;
            for (int side = 0; side < 2; side++) {
                double end = side ? p->hi : p->lo;
                bool open = side ? p->hi_open : p->lo_open;
#if META_BREAK == 3
                open = !open;
#endif
                double outside = nextafter(end, side ? HUGE_VAL : -HUGE_VAL);
                cat_state s;
                char what[96];
                snprintf(what, sizeof what, "%s %s=%.17g", r->name, p->key, end);
                if (!isfinite(end)) {
                    assert_false(prepare_with(r, p->key, end, &s));
                    continue;
                }
                bool accepted = prepare_with(r, p->key, end, &s);
                printf("%s: %s end %s, %s\n", what, side ? "upper" : "lower", open ? "open" : "closed",
                       accepted ? "accepted" : "refused");
                if (accepted != !open)
                    fail_msg("%s: the %s end is %s but was %s", what, side ? "upper" : "lower",
                             open ? "open" : "closed", accepted ? "accepted" : "refused");
                if (accepted && !edges_ok(&s, what))
                    fail_msg("%s: bad sample or density at the parameter's end", what);
                assert_false(prepare_with(r, p->key, outside, &s));
                ends++;
            }
        }
    }
    assert_true(ends > 0);
}

/* --- the parameter text ------------------------------------------------ */

/* Every row's default text into buffers of 1 .. length + 1 bytes (with
 * guard bytes after each): always terminated inside the buffer, a prefix
 * of the full text, nothing written past the buffer, the whole text once
 * it fits; and the full text parsed back prepares the default densities,
 * bit for bit at the centre of the uniforms' cube (or at a drawn point). */
static void test_parameter_text(void **state)
{
    (void)state;
    for (size_t i = 0; i < cat_count(); i++) {
        const cat_row *r = cat_at(i);
        char full[1024];
        size_t len = cat_param_defaults(r, full, sizeof full);
        assert_true(len == strlen(full));
        assert_true(len > 0 && len + 1 < sizeof full);
        /* Counting alone, as snprintf(NULL, 0, ...) does. */
        assert_true(cat_param_defaults(r, NULL, 0) == len);
        for (size_t size = 1; size <= len + 1; size++) {
            enum { GUARD = 8 };
            char buf[1024 + GUARD];
            memset(buf, 0x5a, sizeof buf);
            /* The whole text's length, whatever fits: a caller can tell a cut. */
            if (cat_param_defaults(r, buf, size) != len)
                fail_msg("row %s: cat_param_defaults into %zu bytes did not return %zu", r->name,
                         size, len);
            size_t got = (size_t)((char *)memchr(buf, '\0', size) ? (char *)memchr(buf, '\0', size) - buf : (ptrdiff_t)size);
            bool ok = got < size && strncmp(buf, full, got) == 0;
            for (size_t g = size; g < size + GUARD; g++)
                ok = ok && buf[g] == 0x5a;
            size_t want_len = size > len ? len : got;
#if META_BREAK == 4
            want_len = size >= len ? len : got; /* the terminator forgotten */
#endif
            ok = ok && got == want_len;
            if (!ok)
                fail_msg("row %s: text \"%s\" into %zu bytes gave \"%.*s\"", r->name, full, size,
                         (int)got, buf);
        }
        cat_values v;
        char err[256], copy[1024];
        cat_defaults(r, &v);
        snprintf(copy, sizeof copy, "%s", full);
        if (strcmp(copy, "-") != 0)
            for (char *tok = strtok(copy, " "); tok; tok = strtok(NULL, " "))
                assert_true(cat_set_param(r, &v, tok, err, sizeof err));
        cat_state a, b;
        assert_true(cat_prepare_named(r->name, &a, err, sizeof err));
        assert_true(cat_prepare(r, &v, &b, err, sizeof err));
        double x[3] = {0.0, 0.0, 0.0}, u[4] = {0.5, 0.5, 0.5, 0.5};
        if (r->uniforms > 0) {
            r->sample_u(&a, u, x);
        } else {
            mc_rng rng = mc_rng_derive(2601u, i);
            cat_sample(&a, &rng, x);
        }
        assert_true(cat_pdf(&a, x) == cat_pdf(&b, x));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_support_edges),
        cmocka_unit_test(test_domain_ends),
        cmocka_unit_test(test_parameter_ends),
        cmocka_unit_test(test_parameter_text),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_catalog_meta", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
