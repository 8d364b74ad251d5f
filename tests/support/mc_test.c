/* tests/support/mc_test.c - seeds, near-equality and z-test assertions. */
#include "tests/support/mc_test.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/stats.h"

/* Clang's OpenMP runtime (libomp) keeps thread descriptors it never frees
 * when a program changes its team size, as the thread-count tests do;
 * LeakSanitizer would report them at exit. They are the runtime's, not
 * ours: tell LSan (the hook it looks up) to ignore leaks from libomp. */
#if defined(__clang__) && defined(__has_feature)
#if __has_feature(address_sanitizer)
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libomp.so\n";
}
#endif
#endif

uint64_t mc_test_seed(uint64_t default_seed)
{
    const char *s = getenv("MC_TEST_SEED");
    if (!s || !*s)
        return default_seed;
    /* The rule of the programs' --seed: decimal or 0x hex, digits first. */
    bool hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    char *end = NULL;
    errno = 0;
    unsigned long long v = strtoull(s, &end, hex ? 16 : 10);
    if (!isdigit((unsigned char)*s) || errno || *end) {
        fprintf(stderr, "MC_TEST_SEED=%s is not an unsigned integer; using defaults\n", s);
        return default_seed;
    }
    /* SplitMix64 of the pair keeps tests with different defaults apart. */
    uint64_t x = (uint64_t)v * UINT64_C(0x9e3779b97f4a7c15) ^ default_seed;
    x = (x ^ (x >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    x = (x ^ (x >> 27)) * UINT64_C(0x94d049bb133111eb);
    return x ^ (x >> 31);
}

void mc_assert_near_impl(double a, double b, double tol, const char *sa, const char *sb,
                         const char *file, int line)
{
    if (fabs(a - b) <= tol)
        return;
    print_error("%s = %.17g and %s = %.17g differ by %.3g > %.3g\n", sa, a, sb, b, fabs(a - b), tol);
    _fail(file, line);
}

void mc_assert_z_impl(const char *label, double estimate, double exact, double std_error,
                      double threshold, uint64_t seed, const char *file, int line)
{
    double z = mc_z_score(estimate, exact, std_error);
    if (fabs(z) < threshold) {
        /* The statistic of a passing test is part of the evidence: the log
         * (and the book, which quotes it) shows how far inside the bound
         * each estimate landed. */
        printf("z-test %s: estimate %.10g, exact %.10g, stderr %.3g, z = %.3f (|z| < %g), seed %llu\n",
               label, estimate, exact, std_error, z, threshold, (unsigned long long)seed);
        return;
    }
    print_error("%s: estimate %.12g, exact %.12g, stderr %.3g, z = %.3g (|z| must be < %g), seed %llu\n",
                label, estimate, exact, std_error, z, threshold, (unsigned long long)seed);
    _fail(file, line);
}

void mc_assert_seeded_impl(bool cond, const char *scond, uint64_t seed, const char *file, int line)
{
    if (cond)
        return;
    print_error("%s is false, seed %llu\n", scond, (unsigned long long)seed);
    _fail(file, line);
}

size_t mc_test_read_text(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
    return n;
}

const char *mc_test_build_dir(void)
{
    const char *b = getenv("MC_BUILD");
    return b && *b ? b : "build";
}

const char *mc_test_source_dir(void)
{
    const char *s = getenv("MC_SOURCE");
    return s && *s ? s : ".";
}

void mc_test_select(void)
{
    const char *only = getenv("MC_TEST_ONLY");
    if (only && *only)
        cmocka_set_test_filter(only);
}

/* The top `bits` bits of a 32-bit fraction (0 <= bits <= 32). */
static uint32_t top_bits(uint32_t v, unsigned bits)
{
    return (uint32_t)(((uint64_t)v << bits) >> 32);
}

bool mc_test_is_02_net(const uint32_t *x, const uint32_t *y, unsigned m)
{
    static _Thread_local unsigned char count[1u << 12];
    if (m > 12u)
        return false;
    uint32_t n = 1u << m;
    for (unsigned a = 0; a <= m; a++) {
        memset(count, 0, n);
        for (uint32_t i = 0; i < n; i++) {
            uint32_t cell = (top_bits(x[i], a) << (m - a)) | top_bits(y[i], m - a);
            if (count[cell]++ != 0u)
                return false;
        }
    }
    return true;
}

bool mc_test_strata_once(const uint32_t *v, unsigned m)
{
    static _Thread_local unsigned char hit[1u << 12];
    if (m > 12u)
        return false;
    uint32_t n = 1u << m;
    memset(hit, 0, n);
    for (uint32_t i = 0; i < n; i++)
        if (hit[top_bits(v[i], m)]++ != 0u)
            return false;
    return true;
}
