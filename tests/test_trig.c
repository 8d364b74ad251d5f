/* tests/test_trig.c - mc_sincos_turn of mc/trig.h, the azimuth's sin and cos
 * of every direction sampler (this book's #ch-sphere, #ch-directions and
 * #ch-onb), against long double sinl/cosl of 2 pi u: at most 4e-16 absolute
 * (about 2 ulps of values near
 * 1) over a dense grid of u in [0, 1), 10^6 random u, the neighbours of
 * every octant boundary and a few turns outside [0, 1); exact at the
 * quarter turns. Truncating the series one term early, or reducing the
 * rounded product 2 pi u instead of u itself, must fail the same check.
 */
#include "tests/support/mc_test.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mc/rng.h"
#include "mc/trig.h"
#include "tests/support/negctl.h"

/* The bound, 4e-16: the reduction of u is exact, so the error is the
 * rounding of x = f pi / 2 and of the two Horner sums, about 1.5 ulps of a
 * result below 1 (ulp 1.1e-16 on [1/2, 1)) in the worst case. */
#define TRIG_TOL 4e-16

/* 2 pi to long double precision: the reference must be far more accurate
 * than the function under test. x86-64's long double carries 64 bits, so
 * sinl(2 pi u) for a double u is good to about 1e-19 absolute. Where long
 * double is only a double the test would compare against the same rounding
 * it is meant to beat, hence the static check below. */
#define TWO_PI_L 6.283185307179586476925286766559005768L
_Static_assert(LDBL_MANT_DIG >= 64, "test_trig needs an extended long double reference");

typedef void (*sincos_fn)(double u, double *s, double *c);

static double error_at(sincos_fn f, double u)
{
    double s, c;
    f(u, &s, &c);
    long double a = TWO_PI_L * (long double)u;
    double es = (double)fabsl((long double)s - sinl(a));
    double ec = (double)fabsl((long double)c - cosl(a));
    return fmax(es, ec);
}

/* The worst error of f over: u = i / 2^20 for every i < 2^20 (every
 * quadrant boundary and the octant midpoints among them), 10^6 uniform u
 * (seed 7301), the 8 doubles either side of each k / 8, and u in [-3, 3]
 * at steps of 1/1000 + 1e-7 (negative u and whole extra turns). */
static double worst_error(sincos_fn f, uint64_t seed)
{
    double worst = 0.0;
#pragma omp parallel for reduction(max : worst)
    for (int i = 0; i < (1 << 20); i++)
        worst = fmax(worst, error_at(f, ldexp((double)i, -20)));
#pragma omp parallel for reduction(max : worst)
    for (int i = 0; i < 1000000; i++) {
        mc_rng r = mc_rng_derive(seed, (uint64_t)i);
        /* 53 random bits, not the 32 of mc_rng_uniform, so that u's low
         * bits (which the exact reduction keeps) are exercised. */
        double u = ldexp((double)(mc_rng_u32(&r) >> 11), -21) + ldexp((double)mc_rng_u32(&r), -53);
        worst = fmax(worst, error_at(f, u));
    }
    for (int k = 0; k <= 8; k++) {
        double up = k / 8.0, down = k / 8.0;
        for (int j = 0; j < 8; j++) {
            up = nextafter(up, 2.0);
            down = nextafter(down, -2.0);
            worst = fmax(worst, fmax(error_at(f, up), error_at(f, down)));
        }
    }
    for (int i = -3000; i <= 3000; i++)
        worst = fmax(worst, error_at(f, i * (1e-3 + 1e-7)));
    return worst;
}

static void test_trig_sincos_turn_accuracy(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(7301u);
    double worst = worst_error(mc_sincos_turn, seed);
    printf("sincos_turn: worst absolute error %.3g (bound %g)\n", worst, TRIG_TOL);
    if (!(worst < TRIG_TOL))
        fail_msg("worst error %.3g >= %g (seed %llu)", worst, TRIG_TOL, (unsigned long long)seed);
}

/* Quarter turns land on the axes exactly: the samplers' directions along
 * +-x and +-y have no stray 1e-16 component. */
static void test_trig_sincos_turn_quarter_turns_exact(void **state)
{
    (void)state;
    static const double u[] = {0.0, 0.25, 0.5, 0.75, 1.0, -0.25, 2.5};
    static const double want_s[] = {0.0, 1.0, 0.0, -1.0, 0.0, -1.0, 0.0};
    static const double want_c[] = {1.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0};
    for (size_t i = 0; i < sizeof u / sizeof u[0]; i++) {
        double s, c;
        mc_sincos_turn(u[i], &s, &c);
        assert_true(s == want_s[i]);
        assert_true(c == want_c[i]);
    }
}

/* Negative control 1: each series cut one term short, sin to x^15 / 15!
 * and cos to x^14 / 14!. At pi / 4 the omitted cos term x^16 / 16! is
 * 1.0e-15, which the bound must see (the omitted sin term, 4.6e-17, is
 * below it: the sin series is one term longer than it strictly needs). */
static void sincos_short_series(double u, double *s, double *c)
{
    double t = 4.0 * u;
    long long k = (long long)(t + copysign(0.5, t));
    double x = (t - (double)k) * MC_PI_2, z = x * x;
    double sx = x * (1 - z / 6 * (1 - z / 20 * (1 - z / 42 * (1 - z / 72 * (1 - z / 110 * (1 - z / 156 * (1 - z / 210)))))));
    double cx = 1 - z / 2 * (1 - z / 12 * (1 - z / 30 * (1 - z / 56 * (1 - z / 90 * (1 - z / 132 * (1 - z / 182))))));
    unsigned q = (unsigned)k & 3u;
    double a = (q & 1u) ? cx : sx, b = (q & 1u) ? sx : cx;
    *s = (q & 2u) ? -a : a;
    *c = ((q + 1u) & 2u) ? -b : b;
}

/* Negative control 2: libm's sin and cos of the rounded product 2 pi u,
 * the code this function replaces; the product's rounding (up to 4.4e-16
 * near 2 pi, more for the extra turns) is what the exact reduction avoids. */
static void sincos_libm_product(double u, double *s, double *c)
{
    *s = sin(MC_2PI * u);
    *c = cos(MC_2PI * u);
}

static void test_trig_negative_controls(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(7301u);
    double e1 = worst_error(sincos_short_series, seed);
    double e2 = worst_error(sincos_libm_product, seed);
    printf("negative controls: short series %.3g, libm of 2 pi u %.3g\n", e1, e2);
    bool ok = negctl_record(t, "sincos series one term short", "4e-16 accuracy", !(e1 < TRIG_TOL));
    ok &= negctl_record(t, "sincos of rounded 2 pi u", "4e-16 accuracy", !(e2 < TRIG_TOL));
    assert_true(ok);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trig_sincos_turn_accuracy),
        cmocka_unit_test(test_trig_sincos_turn_quarter_turns_exact),
        cmocka_unit_test(test_trig_negative_controls),
    };
    return cmocka_run_group_tests_name("test_trig", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
