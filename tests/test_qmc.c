/* tests/test_qmc.c - quasi-Monte Carlo point sources: known answers against
 * scipy's Sobol generator, the net property of Sobol, Hammersley and Halton
 * (unscrambled and scrambled), unbiasedness of the scrambles, convergence
 * rates, Kensler's permutation, padded pairs and the cursor. */
#include "tests/support/mc_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mc/constants.h"
#include "mc/qmc.h"
#include "mc/rng.h"
#include "mc/stats.h"
#include "mc/testfn.h"
#include "tests/data/sobol_scipy.h"
#include "tests/support/negctl.h"

/* ---- known answers ---------------------------------------------------- */

static void test_qmc_primes(void **state)
{
    (void)state;
    unsigned prev = 1u;
    for (unsigned k = 0; k < MC_HALTON_MAX_DIM; k++) {
        unsigned p = mc_qmc_prime(k);
        assert_true(p > prev);
        for (unsigned q = 2; q * q <= p; q++)
            assert_true(p % q != 0u);
        /* No prime was skipped: nothing between prev and p is prime. */
        for (unsigned c = prev + 1u; c < p; c++) {
            bool composite = false;
            for (unsigned q = 2; q * q <= c && !composite; q++)
                composite = c % q == 0u;
            assert_true(composite);
        }
        prev = p;
    }
    assert_int_equal(mc_qmc_prime(0), 2);
    assert_int_equal(mc_qmc_prime(MC_HALTON_MAX_DIM - 1u), 311);
}

/* Radical inverses worked by hand: 5 = 12_3 -> 0.21_3 = 7/9; 2385 = 6645_7
 * -> 0.5466_7 = 1959/2401; 2^60 -> 2^-61 (past the first 53-digit chunk);
 * 3^40 -> 3^-41. Base 2 equals the bit reversal for every 32-bit i. */
static void test_qmc_radical_inverse(void **state)
{
    (void)state;
    assert_true(mc_radical_inverse(0u, 2u) == 0.0);
    assert_true(mc_radical_inverse(1u, 2u) == 0.5);
    assert_true(mc_radical_inverse(6u, 2u) == 0.375);
    assert_true(mc_radical_inverse(5u, 3u) == 7.0 / 9.0);
    assert_true(mc_radical_inverse(2385u, 7u) == 1959.0 / 2401.0);
    assert_true(mc_radical_inverse(UINT64_C(1) << 60, 2u) == 0x1p-61);
    uint64_t p40 = 1u;
    for (int k = 0; k < 40; k++)
        p40 *= 3u;
    assert_near(mc_radical_inverse(p40, 3u) * pow(3.0, 41.0), 1.0, 1e-14);
    mc_rng rng = mc_rng_derive(11u, 0u);
    for (int k = 0; k < 100000; k++) {
        uint32_t i = mc_rng_u32(&rng);
        assert_true(mc_radical_inverse(i, 2u) == (double)mc_van_der_corput_u32(i) * 0x1p-32);
    }
    assert_int_equal(mc_van_der_corput_u32(1u), 0x80000000u);
    assert_int_equal(mc_van_der_corput_u32(0x0000f00du), 0xb00f0000u);
}

/* scipy's row n is the point of Gray-code index n ^ (n >> 1). */
static void test_qmc_sobol_matches_scipy(void **state)
{
    (void)state;
    for (uint32_t n = 0; n < 1024u; n++)
        for (unsigned d = 0; d < 8u; d++)
            assert_int_equal(mc_sobol_u32(n ^ (n >> 1), d), sobol_scipy_low[n][d]);
    for (uint32_t n = 0; n < 256u; n++)
        for (unsigned k = 0; k < 16u; k++)
            assert_int_equal(mc_sobol_u32(n ^ (n >> 1), sobol_scipy_high_dims[k]),
                             sobol_scipy_high[n][k]);
    /* Dimension 1 (the first) is van der Corput's: bit-reversed indices. */
    for (uint32_t i = 0; i < 65536u; i++)
        assert_int_equal(mc_sobol_u32(i, 0u), mc_van_der_corput_u32(i));
    assert_true(mc_sobol(3u, 0u) == 0.75 && mc_sobol(3u, 1u) == 0.25);
}

/* ---- net property ------------------------------------------------------ */

/* The top `bits` bits of a 32-bit fraction (0 <= bits <= 32). */
static uint32_t top(uint32_t v, unsigned bits)
{
    return (uint32_t)(((uint64_t)v << bits) >> 32);
}

enum source { UNSCRAMBLED, XOR, OWEN, PCG, MULT_SCRAMBLE };

/* The first n points of dimensions (d, d+1) of a source as 32-bit
 * fractions. MULT_SCRAMBLE is a negative control: Owen's scramble with the
 * bit reversals left out, so that low bits change high ones. */
static void fill(enum source s, uint64_t seed, unsigned d, uint32_t n, uint32_t *x, uint32_t *y)
{
    mc_rng rng = mc_rng_derive(seed, 0u);
    for (uint32_t i = 0; i < n; i++) {
        for (unsigned k = 0; k < 2u; k++) {
            uint32_t *out = k ? y : x;
            switch (s) {
            case UNSCRAMBLED:
                out[i] = (uint32_t)(mc_sobol(i, d + k) * 0x1p32);
                break;
            case XOR:
                out[i] = (uint32_t)(mc_sobol_xor(i, d + k, seed, 7u) * 0x1p32);
                break;
            case OWEN:
                out[i] = (uint32_t)(mc_sobol_owen(i, d + k, seed, 7u) * 0x1p32);
                break;
            case PCG:
                out[i] = mc_rng_u32(&rng);
                break;
            case MULT_SCRAMBLE:
                out[i] = (mc_sobol_u32(i, d + k) ^ 0x2c1b3c6du) * 0x9e3779b9u;
                break;
            }
        }
    }
}

/* For m = 2..12 the first 2^m Sobol points in dimensions (1, 2) are a
 * (0,m,2)-net, unscrambled, with a random digital shift and Owen scrambled
 * (four seeds each); the scrambles permute elementary intervals, so the
 * property must survive exactly. Negative controls: PCG32 points and a
 * scramble that is not nested must fail the same check. */
static void test_qmc_sobol_net_property(void **state)
{
    negctl *t = *state;
    static uint32_t x[1u << 12], y[1u << 12];
    uint64_t seed = mc_test_seed(5001u);
    int nets = 0;
    for (unsigned m = 2; m <= 12u; m++) {
        fill(UNSCRAMBLED, 0u, 0u, 1u << m, x, y);
        assert_true(mc_test_is_02_net(x, y, m));
        nets++;
        for (uint64_t s = 0; s < 4u; s++) {
            fill(XOR, seed + s, 0u, 1u << m, x, y);
            assert_seeded(mc_test_is_02_net(x, y, m), seed + s);
            fill(OWEN, seed + s, 0u, 1u << m, x, y);
            assert_seeded(mc_test_is_02_net(x, y, m), seed + s);
            nets += 2;
        }
    }
    printf("net property: %d point sets (m = 2..12; unscrambled, 4 XOR, 4 Owen) are (0,m,2)-nets\n",
           nets);
    fill(PCG, seed, 0u, 1u << 8, x, y);
    assert_seeded(
        negctl_record(t, "PCG32 points as a net", "(0,m,2)-net check",
                      !mc_test_is_02_net(x, y, 8)),
        seed);
    fill(MULT_SCRAMBLE, seed, 0u, 1u << 8, x, y);
    assert_true(negctl_record(t, "non-nested scramble (XOR then multiply)", "(0,m,2)-net check",
                              !mc_test_is_02_net(x, y, 8)));
}

/* Every one of the 1024 dimensions is a (0,1)-sequence: the first 2^m
 * points hit each interval of length 2^-m once (m = 1..10), unscrambled
 * and Owen scrambled. */
static void test_qmc_sobol_1d_stratified(void **state)
{
    (void)state;
    static uint32_t v[1024];
    uint64_t seed = mc_test_seed(5002u);
    for (unsigned d = 0; d < MC_SOBOL_MAX_DIM; d++) {
        for (unsigned m = 1; m <= 10u; m++) {
            uint32_t n = 1u << m;
            for (int scrambled = 0; scrambled < 2; scrambled++) {
                for (uint32_t i = 0; i < n; i++) {
                    double u = scrambled ? mc_sobol_owen(i, d, seed, 3u) : mc_sobol(i, d);
                    v[i] = (uint32_t)(u * 0x1p32);
                }
                assert_true(mc_test_strata_once(v, m));
            }
        }
    }
}

/* The n-point Hammersley set, n = 2^m, is a (0,m,2)-net (m = 2..12); the
 * 3D set's third coordinate (base 3) hits each of the 3^5 intervals of
 * length 3^-5 once when n = 3^5. */
static void test_qmc_hammersley(void **state)
{
    (void)state;
    static uint32_t x[1u << 12], y[1u << 12];
    for (unsigned m = 2; m <= 12u; m++) {
        uint32_t n = 1u << m;
        for (uint32_t i = 0; i < n; i++) {
            double p[2];
            mc_hammersley2(i, n, p);
            x[i] = (uint32_t)(p[0] * 0x1p32);
            y[i] = (uint32_t)(p[1] * 0x1p32);
        }
        assert_true(mc_test_is_02_net(x, y, m));
    }
    static unsigned char seen[243];
    memset(seen, 0, sizeof seen);
    for (uint32_t i = 0; i < 243u; i++) {
        double p[3];
        mc_hammersley3(i, 243u, p);
        assert_true(p[0] == (double)i / 243.0);
        assert_true(p[1] == mc_radical_inverse(i, 2u));
        /* Points lie on multiples of 3^-5; 1e-9 absorbs the rounding of
         * p[2] * 243 (about 1e-14) and is far below the 1/243 spacing. */
        unsigned cell = (unsigned)floor(p[2] * 243.0 + 1e-9);
        assert_int_equal(seen[cell]++, 0);
    }
}

/* Whether the n = 2^i 3^j Halton points (bases 2 and 3) put exactly one
 * point in every box [a/2^i, (a+1)/2^i) x [b/3^j, (b+1)/3^j). Coordinates
 * are multiples of b^-m >= 3^-21 (about 1e-10) apart from box edges by at
 * least that much, so 1e-12 absorbs the rounding of y 3^j (1e-14). */
static bool halton_boxes_ok(const double *x, const double *y, unsigned i2, unsigned j3)
{
    static unsigned char count[32u * 81u];
    unsigned nx = 1u << i2, ny = (unsigned)lround(pow(3.0, j3)), n = nx * ny;
    memset(count, 0, n);
    for (unsigned k = 0; k < n; k++) {
        unsigned a = (unsigned)(x[k] * nx), b = (unsigned)floor(y[k] * ny + 1e-12);
        if (a >= nx || b >= ny || count[a * ny + b]++ != 0u)
            return false;
    }
    return true;
}

/* For i = 1..5, j = 1..4 the first 2^i 3^j Halton points (dimensions 1 and
 * 2) fill every (2^i, 3^j) box once, plain and with random digit
 * permutations (four scrambles). Negative control: PCG32 points fail. */
static void test_qmc_halton_boxes(void **state)
{
    negctl *t = *state;
    static double x[32 * 81], y[32 * 81];
    uint64_t seed = mc_test_seed(5003u);
    int sets = 0;
    for (unsigned i2 = 1; i2 <= 5u; i2++) {
        for (unsigned j3 = 1; j3 <= 4u; j3++) {
            unsigned n = (1u << i2) * (unsigned)lround(pow(3.0, j3));
            for (int s = -1; s < 4; s++) {
                for (unsigned k = 0; k < n; k++) {
                    x[k] = s < 0 ? mc_halton(k, 0u) : mc_halton_permuted(k, 0u, seed, (uint64_t)s);
                    y[k] = s < 0 ? mc_halton(k, 1u) : mc_halton_permuted(k, 1u, seed, (uint64_t)s);
                }
                assert_seeded(halton_boxes_ok(x, y, i2, j3), seed);
                sets++;
            }
        }
    }
    printf("Halton boxes: %d point sets (2^i 3^j points, i = 1..5, j = 1..4; plain and 4 "
           "permuted) fill every box once\n",
           sets);
    mc_rng rng = mc_rng_derive(seed, 1u);
    for (unsigned k = 0; k < 72u; k++) {
        x[k] = mc_rng_uniform(&rng);
        y[k] = mc_rng_uniform(&rng);
    }
    assert_seeded(negctl_record(t, "PCG32 points as Halton boxes", "(2^i, 3^j) box check",
                                !halton_boxes_ok(x, y, 3u, 2u)),
                  seed);
}

/* ---- unbiasedness -------------------------------------------------------- */

/* Smooth test integrands over [0,1]^dim with closed-form integrals: three
 * of mc/testfn.h (the ones the `qmc` program of this book's #ch-qmc uses)
 * and 1 / (1 + x + y), whose mixed derivative never vanishes. */
typedef struct integrand {
    const char *name;
    unsigned dim;
    double (*f)(const double *x); /* or NULL: fn */
    const mc_testfn *fn;
    double exact;
} integrand;

static double f_inv_sum(const double *x)
{
    return 1.0 / (1.0 + x[0] + x[1]);
}

static double integrand_eval(const integrand *g, const double *x)
{
    return g->f ? g->f(x) : mc_testfn_eval(g->fn, x);
}

/* int int 1 / (1 + x + y) = 3 ln 3 - 4 ln 2 (integrate ln(2 + y) - ln(1 + y)). */
static integrand integrands[4];
static mc_testfn smooth2, peak5, gauss4;

static bool init_integrands(void)
{
    if (!mc_testfn_init(&smooth2, MC_TESTFN_SMOOTH, 2u) ||
        !mc_testfn_init(&peak5, MC_TESTFN_PEAK, 5u) || !mc_testfn_init(&gauss4, MC_TESTFN_GAUSS, 4u))
        return false;
    integrands[0] = (integrand){"exp(x + y)", 2u, NULL, &smooth2, mc_testfn_exact(&smooth2)};
    integrands[1] = (integrand){"1 / (1 + x + y)", 2u, f_inv_sum, NULL,
                                3.0 * log(3.0) - 4.0 * log(2.0)};
    integrands[2] = (integrand){"Genz product peak 5D", 5u, NULL, &peak5, mc_testfn_exact(&peak5)};
    integrands[3] = (integrand){"Genz Gaussian 4D", 4u, NULL, &gauss4, mc_testfn_exact(&gauss4)};
    return true;
}

/* The estimate of f from points 0..n-1 of scramble `stream` of a method. */
static double qmc_estimate(const integrand *g, mc_qmc_method method, uint64_t seed,
                           uint64_t stream, uint32_t n)
{
    double sum = 0.0, x[8];
    for (uint32_t i = 0; i < n; i++) {
        mc_qmc_cursor c = mc_qmc_begin(method, seed, stream, i);
        for (unsigned d = 0; d < g->dim; d++)
            x[d] = mc_qmc_next(&c);
        sum += integrand_eval(g, x);
    }
    return sum / n;
}

/* Each scramble is uniform over the cube, so the mean over R = 64
 * independent scrambles (streams 0..63) of the N = 1024-point estimate is
 * unbiased and its standard error is the spread of the 64 estimates over
 * sqrt 64. For Owen, XOR and permuted Halton and each of four integrands
 * |z| < 4: the statistic is Student's t with 63 degrees of freedom, false
 * alarm 1.7e-4 per test (seed 5004). */
static void test_qmc_scrambles_unbiased(void **state)
{
    (void)state;
    enum { R = 64, N = 1024 };
    static const mc_qmc_method methods[3] = {MC_QMC_SOBOL_OWEN, MC_QMC_SOBOL_XOR, MC_QMC_HALTON};
    static const char *names[3] = {"Owen", "XOR", "Halton permuted"};
    uint64_t seed = mc_test_seed(5004u);
    for (int m = 0; m < 3; m++) {
        for (int k = 0; k < 4; k++) {
            mc_welford w = mc_welford_init();
            for (uint64_t r = 0; r < R; r++)
                mc_welford_add(&w, qmc_estimate(&integrands[k], methods[m], seed, r, N));
            char label[96];
            snprintf(label, sizeof label, "%s, %s, R = %d, N = %d", names[m], integrands[k].name,
                     R, N);
            assert_z_below(label, w.mean, integrands[k].exact, mc_welford_std_error(&w), 4.0, seed);
        }
    }
}

/* Broken scrambles that the z-test above must reject, on 1 / (1 + x + y):
 * output bit 29 stuck at 1 (every point moved up by 1/8 in the cells where
 * it was 0: a bias of about 4% of the integral) and all R scrambles drawn
 * from one seed (identical estimates: the spread, and so the error bar,
 * collapses to 0 while the error does not). */
static void test_qmc_broken_scrambles_caught(void **state)
{
    negctl *t = *state;
    enum { R = 64, N = 1024 };
    uint64_t seed = mc_test_seed(5005u);
    const integrand *g = &integrands[1];
    mc_welford stuck = mc_welford_init(), shared = mc_welford_init();
    for (uint64_t r = 0; r < R; r++) {
        double sum = 0.0, x[2];
        for (uint32_t i = 0; i < N; i++) {
            for (unsigned d = 0; d < 2u; d++) {
                uint32_t v = mc_owen_scramble_u32(mc_sobol_u32(i, d), mc_qmc_key(seed, r, d));
                x[d] = (double)(v | (1u << 29)) * 0x1p-32;
            }
            sum += integrand_eval(g, x);
        }
        mc_welford_add(&stuck, sum / N);
        mc_welford_add(&shared, qmc_estimate(g, MC_QMC_SOBOL_OWEN, seed, 0u, N));
    }
    double z_stuck = mc_z_score(stuck.mean, g->exact, mc_welford_std_error(&stuck));
    double z_shared = mc_z_score(shared.mean, g->exact, mc_welford_std_error(&shared));
    printf("broken scrambles: bit 29 stuck z = %.3g, shared seed z = %.3g\n", z_stuck, z_shared);
    assert_seeded(negctl_record(t, "Owen scramble with output bit 29 stuck at 1", "z-test",
                                !(fabs(z_stuck) < 4.0)),
                  seed);
    assert_seeded(negctl_record(t, "one seed shared by all R scrambles", "z-test",
                                !(fabs(z_shared) < 4.0)),
                  seed);
}

/* Every single point of a scramble is uniform: the mean of point 0 and of
 * point 5 over 20000 scrambles (streams) is 1/2 within |z| < 4 (variance
 * 1/12), in dimensions 0, 1, 5 and 63 of Owen, XOR and permuted Halton
 * (seed 5006; 24 tests, false alarm 6.3e-5 each). */
static void test_qmc_scrambled_points_uniform(void **state)
{
    (void)state;
    enum { K = 20000 };
    static const unsigned dims[4] = {0u, 1u, 5u, 63u};
    uint64_t seed = mc_test_seed(5006u);
    for (unsigned d = 0; d < 4u; d++) {
        for (uint32_t i = 0; i <= 5u; i += 5u) {
            double s[3] = {0.0, 0.0, 0.0};
            for (uint64_t r = 0; r < K; r++) {
                s[0] += mc_sobol_owen(i, dims[d], seed, r);
                s[1] += mc_sobol_xor(i, dims[d], seed, r);
                s[2] += mc_halton_permuted(i, dims[d], seed, r);
            }
            for (int m = 0; m < 3; m++) {
                char label[64];
                snprintf(label, sizeof label, "point %u dim %u method %d", (unsigned)i, dims[d], m);
                assert_z_below(label, s[m] / K, 0.5, sqrt(1.0 / 12.0 / K), 4.0, seed);
            }
        }
    }
}

/* ---- convergence rates ---------------------------------------------------- */

/* The least-squares slope of log err against log n over k points. */
static double loglog_slope(const double *n, const double *err, int k)
{
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (int j = 0; j < k; j++) {
        double x = log(n[j]), y = log(err[j]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

/* The fitted slope of the RMS error (over R scrambles, streams k 2^32 + r
 * so that each N has its own) of the N-point estimate of g, for
 * N = 2^lo .. 2^hi. */
static double rms_slope(const integrand *g, mc_qmc_method method, uint64_t seed, int R, unsigned lo,
                        unsigned hi)
{
    double n[24], rms[24];
    int k = 0;
    for (unsigned m = lo; m <= hi; m++, k++) {
        double se = 0.0;
        for (int r = 0; r < R; r++) {
            uint64_t stream = ((uint64_t)m << 32) | (uint64_t)r;
            double e = qmc_estimate(g, method, seed, stream, 1u << m) - g->exact;
            se += e * e;
        }
        n[k] = (double)(1u << m);
        rms[k] = sqrt(se / R);
    }
    return loglog_slope(n, rms, k);
}

/* Fitted log-log slopes of the RMS error for f = 1 / (1 + x + y):
 * - Owen-scrambled Sobol, N = 2^6..2^16, R = 64: theory (Owen 1997) [@owen1997] gives
 *   variance O(N^-3 log N) for a smooth 2D integrand, so the local slope
 *   is -3/2 + 1 / (2 ln N), about -1.43 in the middle of the range; the
 *   bound -1.3 leaves 0.13. The RMS of 64 squared errors has a relative
 *   spread of about 1/sqrt(128) = 9%, 0.09 in log per point, so about
 *   0.09 / sqrt(sum (ln N - mean)^2) = 0.012 on the slope over these
 *   eleven N: the bound is ten such spreads away.
 * - unscrambled Sobol, N = 2^4..2^16 (one deterministic error per N):
 *   Koksma-Hlawka gives O((log N)^2 / N); for this integrand the measured
 *   slope is within 0.25 of -1.
 * - PCG32, N = 2^4..2^14, R = 256: the RMS error is exactly sigma / sqrt N,
 *   slope -1/2; the RMS over 256 replicates has a 4.4% spread, 0.006 on
 *   the slope over eleven N, so |slope + 1/2| < 0.05 is eight spreads.
 * Negative control: a random digital shift alone (XOR) does not reach the
 *   nested scramble's rate, its slope is about -1 and must fail <= -1.3.
 * Seed 5007. */
static void test_qmc_convergence_rates(void **state)
{
    negctl *t = *state;
    uint64_t seed = mc_test_seed(5007u);
    const integrand *g = &integrands[1];
    double owen = rms_slope(g, MC_QMC_SOBOL_OWEN, seed, 64, 6u, 16u);
    double plain = rms_slope(g, MC_QMC_SOBOL, seed, 1, 4u, 16u);
    double mc = rms_slope(g, MC_QMC_RANDOM, seed, 256, 4u, 14u);
    double xor = rms_slope(g, MC_QMC_SOBOL_XOR, seed, 64, 6u, 16u);
    printf("fitted slopes of RMS error, 1 / (1 + x + y): Owen %.3f, unscrambled Sobol %.3f, "
           "PCG32 %.3f, XOR %.3f (seed %llu)\n",
           owen, plain, mc, xor, (unsigned long long)seed);
    assert_seeded(owen <= -1.3, seed);
    assert_true(fabs(plain + 1.0) < 0.25);
    assert_seeded(fabs(mc + 0.5) < 0.05, seed);
    assert_seeded(negctl_record(t, "XOR-only scramble held to Owen's rate", "slope <= -1.3",
                                !(xor <= -1.3)),
                  seed);
}

/* ---- permutation, padded pairs, Owen's nesting ----------------------------- */

/* The scrambled points of dimensions 0 and 1, which mc/qmc.c computes
 * without the generator matrix (dimension 0 from i itself, dimension 1
 * from a closed form of its Pascal matrix), equal the matrix product
 * scrambled, bit for bit: 2 x 10^5 indices (every one below 2^16, then
 * spread over 32 bits, 0xffffffff among them) under keys of 4 streams. */
static void test_qmc_first_dimensions_closed_form(void **state)
{
    (void)state;
    uint64_t seed = mc_test_seed(5012u);
    for (uint64_t stream = 0; stream < 4u; stream++)
        for (uint32_t k = 0; k < 50000u; k++) {
            uint32_t i = k < 65536u ? k : k * 2654435761u;
            if (k == 49999u)
                i = 0xffffffffu;
            for (unsigned d = 0; d < 2u; d++) {
                double fast = mc_sobol_owen(i, d, seed, stream);
                uint32_t v = mc_owen_scramble_u32(mc_sobol_u32(i, d), mc_qmc_key(seed, stream, d));
                if (fast != (double)v * 0x1p-32)
                    fail_msg("index %u, dimension %u, stream %llu: %.17g, the matrix's %.17g", i,
                             d, (unsigned long long)stream, fast, (double)v * 0x1p-32);
            }
        }
}

/* mc_permutation_element is a bijection of {0..n-1} for every key tried,
 * for n powers of 2 and not; and the image of i = 0 is uniform over keys:
 * for n = 5, 50000 keys put 10000 +- 4 sqrt(10000 * 4/5) in each value
 * (|z| < 4 per value, 5 tests at 6.3e-5). */
static void test_qmc_permutation_element(void **state)
{
    (void)state;
    static const uint32_t sizes[9] = {1u, 2u, 3u, 5u, 8u, 13u, 100u, 1000u, 4096u};
    static unsigned char seen[4096];
    mc_rng rng = mc_rng_derive(mc_test_seed(5008u), 0u);
    for (int s = 0; s < 9; s++) {
        for (int k = 0; k < 20; k++) {
            uint32_t key = mc_rng_u32(&rng), n = sizes[s];
            memset(seen, 0, n);
            for (uint32_t i = 0; i < n; i++) {
                uint32_t p = mc_permutation_element(i, n, key);
                assert_true(p < n);
                assert_int_equal(seen[p]++, 0);
            }
        }
    }
    double count[5] = {0};
    for (int k = 0; k < 50000; k++)
        count[mc_permutation_element(0u, 5u, mc_rng_u32(&rng))] += 1.0;
    for (int v = 0; v < 5; v++)
        assert_z_below("permutation image of 0, n = 5", count[v], 10000.0, sqrt(10000.0 * 0.8), 4.0,
                       mc_test_seed(5008u));
}

/* mc_permutation_remainder is a % n: for 2 x 10^6 random pairs (a, n),
 * half of them with n < 2^16, and at the edges (n = 1, 2, 3, 2^k - 1,
 * 2^k, 2^k + 1, 2^32 - 1 against a = 0, 1, n - 1, n, n + 1, 2n - 1, 2^32 - 2,
 * 2^32 - 1). Exact comparisons: any difference fails. */
static void test_qmc_permutation_remainder(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(5011u), 0u);
    long bad = 0;
    for (int k = 0; k < 2000000; k++) {
        uint32_t a = mc_rng_u32(&rng), n = mc_rng_u32(&rng);
        if (k % 2)
            n >>= 16;
        n += n == 0u;
        bad += mc_permutation_remainder(a, mc_permutation_size_make(n)) != a % n;
    }
    static const uint32_t edges_n[] = {1u,          2u,          3u,          5u,     7u,     50u,
                                       64u,         100u,        255u,        257u,   65535u, 65537u,
                                       0x7fffffffu, 0x80000000u, 0x80000001u, 0xfffffffeu,
                                       0xffffffffu};
    for (size_t j = 0; j < sizeof edges_n / sizeof edges_n[0]; j++) {
        uint32_t n = edges_n[j];
        mc_permutation_size s = mc_permutation_size_make(n);
        const uint32_t as[] = {0u, 1u, n - 1u, n, n + 1u, 2u * n - 1u, 0xfffffffeu, 0xffffffffu};
        for (size_t i = 0; i < sizeof as / sizeof as[0]; i++)
            bad += mc_permutation_remainder(as[i], s) != as[i] % n;
    }
    printf("remainder by multiplication against %%: %ld differences\n", bad);
    assert_int_equal(bad, 0);
}

/* For n = 2^m (m = 0..10) the n samples of a pixel in every pair form a
 * (0,m,2)-net, for several pixels and pairs; different pairs of one pixel
 * visit the Sobol indices in different orders; points are in [0,1). */
static void test_qmc_padded_pairs(void **state)
{
    (void)state;
    static uint32_t x[1024], y[1024];
    uint64_t seed = mc_test_seed(5009u);
    for (unsigned m = 0; m <= 10u; m++) {
        uint32_t n = 1u << m;
        for (uint64_t pixel = 0; pixel < 5u; pixel++) {
            for (uint32_t pair = 0; pair < 6u; pair++) {
                for (uint32_t k = 0; k < n; k++) {
                    double u[2];
                    mc_sobol_padded2(mc_qmc_stream_seed(seed, pixel * 7919u), 2u * pair, k, n, u);
                    assert_true(u[0] >= 0.0 && u[0] < 1.0 && u[1] >= 0.0 && u[1] < 1.0);
                    x[k] = (uint32_t)(u[0] * 0x1p32);
                    y[k] = (uint32_t)(u[1] * 0x1p32);
                }
                assert_seeded(m == 0u || mc_test_is_02_net(x, y, m), seed);
            }
        }
    }
    /* Pair 0 and pair 1 of one pixel: the same sample k lands in different
     * strata of the first coordinate for some k (the orders are
     * independent; equal orders over 64 samples have probability 1/64!). */
    int differ = 0;
    for (uint32_t k = 0; k < 64u; k++) {
        double a[2], b[2];
        mc_sobol_padded2(mc_qmc_stream_seed(seed, 3u), 0u, k, 64u, a);
        mc_sobol_padded2(mc_qmc_stream_seed(seed, 3u), 2u, k, 64u, b);
        differ += (int)(a[0] * 64.0) != (int)(b[0] * 64.0);
    }
    assert_seeded(differ > 0, seed);
}

/* Owen's scramble is nested: two fractions that share their top b bits
 * keep sharing them (and only those: the next bit differs iff it did), and
 * it is a bijection on the top 16 bits for any key. */
static void test_qmc_owen_nested(void **state)
{
    (void)state;
    mc_rng rng = mc_rng_derive(mc_test_seed(5010u), 0u);
    for (int k = 0; k < 100000; k++) {
        uint32_t key = mc_rng_u32(&rng), a = mc_rng_u32(&rng);
        unsigned b = mc_rng_bounded(&rng, 32u);
        /* b takes the top b bits of a and flips bit 31 - b. */
        uint32_t c = (a ^ (0x80000000u >> b)) ^ (mc_rng_u32(&rng) & (0x7fffffffu >> b));
        uint32_t sa = mc_owen_scramble_u32(a, key), sc = mc_owen_scramble_u32(c, key);
        assert_int_equal(top(sa ^ sc, b), 0);
        assert_int_equal(top(sa ^ sc, b + 1u), 1);
    }
    static unsigned char seen[65536];
    uint32_t key = mc_rng_u32(&rng);
    for (uint32_t v = 0; v < 65536u; v++)
        assert_int_equal(seen[mc_owen_scramble_u32(v << 16, key) >> 16]++, 0);
}

/* ---- cursor and domain ----------------------------------------------------- */

/* The cursor gives exactly the functions it stands for. */
static void test_qmc_cursor(void **state)
{
    (void)state;
    uint64_t seed = 2385u, stream = 17u;
    for (uint32_t i = 0; i < 300u; i += 7u) {
        mc_qmc_cursor r = mc_qmc_begin(MC_QMC_RANDOM, seed, stream, i);
        mc_rng rng = mc_rng_derive(mc_qmc_stream_seed(seed, stream), i);
        mc_qmc_cursor h = mc_qmc_begin(MC_QMC_HALTON, seed, stream, i);
        mc_qmc_cursor s = mc_qmc_begin(MC_QMC_SOBOL, seed, stream, i);
        mc_qmc_cursor x = mc_qmc_begin(MC_QMC_SOBOL_XOR, seed, stream, i);
        mc_qmc_cursor o = mc_qmc_begin(MC_QMC_SOBOL_OWEN, seed, stream, i);
        for (unsigned d = 0; d < MC_HALTON_MAX_DIM; d++) {
            assert_true(mc_qmc_next(&r) == mc_rng_uniform(&rng));
            assert_true(mc_qmc_next(&h) == mc_halton_permuted(i, d, seed, stream));
            assert_true(mc_qmc_next(&s) == mc_sobol(i, d));
            assert_true(mc_qmc_next(&x) == mc_sobol_xor(i, d, seed, stream));
            assert_true(mc_qmc_next(&o) == mc_sobol_owen(i, d, seed, stream));
        }
    }
    assert_int_equal(mc_qmc_max_dim(MC_QMC_RANDOM), UINT32_MAX);
    assert_int_equal(mc_qmc_max_dim(MC_QMC_HALTON), MC_HALTON_MAX_DIM);
    assert_int_equal(mc_qmc_max_dim(MC_QMC_SOBOL_OWEN), MC_SOBOL_MAX_DIM);
    /* Scrambles differ between streams and between seeds. */
    assert_true(mc_qmc_key(1u, 0u, 0u) != mc_qmc_key(1u, 1u, 0u));
    assert_true(mc_qmc_key(1u, 0u, 0u) != mc_qmc_key(2u, 0u, 0u));
    assert_true(mc_qmc_key(1u, 0u, 0u) != mc_qmc_key(1u, 0u, 1u));
}

/* mc_qmc_fill gives what the cursors give, for runs that start anywhere,
 * cross the 256-point chunks, cross 2^31 and end at the last index 2^32 - 1. */
static void test_qmc_fill_matches_cursor(void **state)
{
    (void)state;
    static const mc_qmc_method methods[5] = {MC_QMC_RANDOM, MC_QMC_HALTON, MC_QMC_SOBOL,
                                             MC_QMC_SOBOL_XOR, MC_QMC_SOBOL_OWEN};
    static const uint64_t starts[4] = {0u, 37u, (UINT64_C(1) << 31) - 300u,
                                       (UINT64_C(1) << 32) - 700u};
    static const unsigned dims[3] = {0u, 5u, 63u};
    static double out[700];
    for (int m = 0; m < 5; m++) {
        for (int s = 0; s < 4; s++) {
            for (int d = 0; d < 3; d++) {
                mc_qmc_fill(methods[m], 2385u, 11u, starts[s], 700u, dims[d], out);
                for (uint32_t k = 0; k < 700u; k++) {
                    mc_qmc_cursor c = mc_qmc_begin(methods[m], 2385u, 11u, starts[s] + k);
                    double v = 0.0;
                    for (unsigned j = 0; j <= dims[d]; j++)
                        v = mc_qmc_next(&c);
                    assert_true(out[k] == v);
                }
            }
        }
    }
}

/* Every source stays in [0, 1) at the extremes of its inputs. */
static void test_qmc_domain(void **state)
{
    (void)state;
    for (unsigned b = 0; b < MC_HALTON_MAX_DIM; b++) {
        double v = mc_radical_inverse(UINT64_MAX, mc_qmc_prime(b));
        assert_true(v >= 0.0 && v < 1.0);
        v = mc_halton_permuted(UINT64_MAX, b, 1u, 2u);
        assert_true(v >= 0.0 && v < 1.0);
        v = mc_halton(UINT64_MAX - 1u, b);
        assert_true(v >= 0.0 && v < 1.0);
    }
    assert_true(mc_radical_inverse(UINT64_MAX, 2u) < 1.0);
    static const uint32_t idx[4] = {0u, 1u, 0x7fffffffu, 0xffffffffu};
    for (unsigned d = 0; d < MC_SOBOL_MAX_DIM; d += 31u) {
        for (int k = 0; k < 4; k++) {
            for (uint64_t key = 0; key < 16u; key++) {
                double a = mc_sobol(idx[k], d), b = mc_sobol_xor(idx[k], d, key, 9u),
                       c = mc_sobol_owen(idx[k], d, key, 9u);
                assert_true(a >= 0.0 && a < 1.0 && b >= 0.0 && b < 1.0 && c >= 0.0 && c < 1.0);
            }
        }
    }
    double h[3];
    mc_hammersley3(UINT64_MAX - 1u, UINT64_MAX, h);
    assert_true(h[0] < 1.0 && h[1] < 1.0 && h[2] < 1.0);
}

static int group_setup(void **state)
{
    if (!init_integrands())
        return -1;
    return negctl_group_setup(state);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_qmc_primes),
        cmocka_unit_test(test_qmc_radical_inverse),
        cmocka_unit_test(test_qmc_sobol_matches_scipy),
        cmocka_unit_test(test_qmc_sobol_net_property),
        cmocka_unit_test(test_qmc_sobol_1d_stratified),
        cmocka_unit_test(test_qmc_hammersley),
        cmocka_unit_test(test_qmc_halton_boxes),
        cmocka_unit_test(test_qmc_scrambles_unbiased),
        cmocka_unit_test(test_qmc_broken_scrambles_caught),
        cmocka_unit_test(test_qmc_scrambled_points_uniform),
        cmocka_unit_test(test_qmc_convergence_rates),
        cmocka_unit_test(test_qmc_permutation_element),
        cmocka_unit_test(test_qmc_permutation_remainder),
        cmocka_unit_test(test_qmc_first_dimensions_closed_form),
        cmocka_unit_test(test_qmc_padded_pairs),
        cmocka_unit_test(test_qmc_owen_nested),
        cmocka_unit_test(test_qmc_cursor),
        cmocka_unit_test(test_qmc_fill_matches_cursor),
        cmocka_unit_test(test_qmc_domain),
    };
    return cmocka_run_group_tests_name("test_qmc", tests, group_setup, negctl_group_teardown);
}
