/* tests/test_onb.c - the orthonormal basis of mc/onb.h (Duff et al. 2017)
 * on 10^6 normals: orthonormal, right-handed (s x t = n; the book's ONB
 * code was once left-handed), exact near both poles where the classic
 * constructions lose precision or divide by zero, and to_world / to_local
 * inverse to each other. A left-handed basis must fail the same check.
 * Also vec3_max_component (mc/vec3.h), which roulette takes at every
 * path vertex, against fmax on every order of values with ties, zeros of
 * both signs, infinities and NaNs.
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 6
 * "Ortho-normal Bases"; this book's #ch-onb.
 */
#include "tests/support/mc_test.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "mc/onb.h"
#include "mc/rng.h"
#include "samplers/sphere.h"
#include "tests/support/negctl.h"

/* The worst deviation of a basis from orthonormal and right-handed: unit
 * lengths, pairwise dot products, and |s x t - n|. For Duff's construction
 * every entry is a few ulps; 1e-14 (about 45 ulps) leaves room for the
 * normal's own rounding and nothing for a real error. */
#define ONB_TOL 1e-14

static double basis_error(const onb *o)
{
    double e = 0.0;
    e = fmax(e, fabs(vec3_length(o->s) - 1.0));
    e = fmax(e, fabs(vec3_length(o->t) - 1.0));
    e = fmax(e, fabs(vec3_length(o->n) - 1.0));
    e = fmax(e, fabs(vec3_dot(o->s, o->t)));
    e = fmax(e, fabs(vec3_dot(o->s, o->n)));
    e = fmax(e, fabs(vec3_dot(o->t, o->n)));
    e = fmax(e, vec3_length(vec3_sub(vec3_cross(o->s, o->t), o->n)));
    return e;
}

/* The normals to check: 10^6 uniform directions (seed 7001), then every
 * sign combination of (eps x, eps y, +-sqrt(1 - eps^2 ...)) for eps from
 * 1e-12 down to 0 and subnormal, and the signed zeros of z. */
enum { N_RANDOM = 1000000 };

static vec3 special_normal(int k)
{
    static const double eps[] = {1e-12, 3e-13, 1e-15, 1e-100, DBL_TRUE_MIN, 0.0};
    int e = k / 8, sx = k & 1, sy = (k >> 1) & 1, sz = (k >> 2) & 1;
    double x = (sx ? -0.6 : 0.6) * eps[e], y = (sy ? -0.8 : 0.8) * eps[e];
    double z = sqrt(1.0 - (x * x + y * y));
    return vec3_make(x, y, sz ? -z : z);
}

enum { N_SPECIAL = 6 * 8 };

static void test_onb_orthonormal_right_handed(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(7001u);
    double worst = 0.0;
    long bad = 0;
#pragma omp parallel for reduction(max : worst) reduction(+ : bad)
    for (int i = 0; i < N_RANDOM + N_SPECIAL + 4; i++) {
        vec3 n;
        if (i < N_RANDOM) {
            mc_rng r = mc_rng_derive(seed, (uint64_t)i);
            n = smp_uniform_sphere_sample(mc_rng_uniform(&r), mc_rng_uniform(&r));
        } else if (i < N_RANDOM + N_SPECIAL) {
            n = special_normal(i - N_RANDOM);
        } else {
            /* The equator with both zero signs, where the sign switch is. */
            static const vec3 eq[4] = {
                {1.0, 0.0, 0.0}, {0.0, 1.0, -0.0}, {0.6, -0.8, 0.0}, {-0.8, 0.6, -0.0}};
            n = eq[i - N_RANDOM - N_SPECIAL];
        }
        onb o = onb_from_w(n);
        double e = vec3_is_finite(o.s) && vec3_is_finite(o.t) ? basis_error(&o) : (double)INFINITY;
        worst = fmax(worst, e);
        bad += !(e <= ONB_TOL);
    }
    printf("onb: %d normals, worst orthonormality / handedness error %.3g\n",
           N_RANDOM + N_SPECIAL + 4, worst);
    if (bad)
        fail_msg("%ld bases off by more than %g (worst %.3g, seed %llu)", bad, ONB_TOL, worst,
                 (unsigned long long)seed);
}

/* to_local(to_world(a)) == a and to_world(to_local(v)) == v to 1e-14 for
 * 10^5 random bases and vectors (seed 7002), near-pole normals included:
 * the basis is orthonormal, so each map is the other's transpose. */
static void test_onb_round_trip(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(7002u);
    mc_rng r = mc_rng_derive(seed, 0u);
    double worst = 0.0;
    for (int i = 0; i < 100000; i++) {
        vec3 n = i < N_SPECIAL ? special_normal(i)
                               : smp_uniform_sphere_sample(mc_rng_uniform(&r), mc_rng_uniform(&r));
        onb o = onb_from_w(n);
        vec3 a = vec3_make(2.385 * mc_rng_uniform(&r) - 1.2, mc_rng_uniform(&r) - 0.5,
                           1.7 * mc_rng_uniform(&r));
        worst = fmax(worst, vec3_length(vec3_sub(onb_to_local(&o, onb_to_world(&o, a)), a)));
        worst = fmax(worst, vec3_length(vec3_sub(onb_to_world(&o, onb_to_local(&o, a)), a)));
        /* The third local axis is the normal. */
        worst = fmax(worst, vec3_length(vec3_sub(onb_to_world(&o, vec3_make(0.0, 0.0, 1.0)), n)));
    }
    printf("onb: round-trip worst error %.3g\n", worst);
    assert_true(worst < 1e-14);
}

/* Negative control: the same check on left-handed bases (s and t swapped,
 * or t negated, the book's one-time slip) must fail for every normal. */
static void test_onb_negative_control(void **state)
{
    negctl *t = *state;
    int caught = 0, tried = 0;
    for (int i = 0; i < N_SPECIAL; i++) {
        onb o = onb_from_w(special_normal(i));
        onb swapped = {o.t, o.s, o.n};
        onb flipped = {o.s, vec3_neg(o.t), o.n};
        caught += basis_error(&swapped) > ONB_TOL;
        caught += basis_error(&flipped) > ONB_TOL;
        tried += 2;
    }
    printf("onb: left-handed bases flagged %d/%d\n", caught, tried);
    assert_true(negctl_record(t, "ONB left-handed", "orthonormality/handedness", caught == tried));
}

/* vec3_max_component(v) = fmax(v.x, fmax(v.y, v.z)) for every triple of
 * 8 values (512 triples), NaN where fmax gives NaN and equal otherwise (a
 * zero's sign aside, which fmax leaves open). */
static void test_vec3_max_component_is_fmax(void **state)
{
    (void)state;
    const double vals[8] = {0.25, -0.0, 0.0, 0.75, 0.25, -3.5, HUGE_VAL, (double)NAN};
    for (int i = 0; i < 512; i++) {
        vec3 v = vec3_make(vals[i & 7], vals[(i >> 3) & 7], vals[i >> 6]);
        double want = fmax(v.x, fmax(v.y, v.z)), got = vec3_max_component(v);
        if (isnan(want) ? !isnan(got) : got != want)
            fail_msg("(%g, %g, %g): %g, fmax %g", v.x, v.y, v.z, got, want);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_onb_orthonormal_right_handed),
        cmocka_unit_test(test_onb_round_trip),
        cmocka_unit_test(test_onb_negative_control),
        cmocka_unit_test(test_vec3_max_component_is_fmax),
    };
    return cmocka_run_group_tests_name("test_onb", tests, negctl_group_setup,
                                       negctl_group_teardown);
}
