/* exercises/hammersley.c - chapter 13, "Quasi-Monte Carlo" (#ch-qmc): the
 * radical inverse and the Hammersley set.
 *
 * WRITE  radical_inverse2(i): the base-2 radical inverse of i: its binary
 *        digits mirrored about the binary point (i = 6 = 110b gives
 *        0.011b = 0.375), for 0 <= i < 2^32;
 *        hammersley(i, n, x): point i of the n-point Hammersley set,
 *        x = (i / n, radical_inverse2(i)), 0 <= i < n.
 * HINT   Reverse the 32 bits of i (swap halves, then quarters, ... or a
 *        loop over the bits) and multiply by 2^-32 (0x1p-32): that is
 *        exact. A loop that adds digit / 2^k is exact too, if the first
 *        digit is worth 1/2.
 * JUDGED exactly (no statistics):
 *        1. radical_inverse2(i) equals mc_radical_inverse(i, 2) of
 *           mc/qmc.h bit for bit for every i < 2^16 and for 10^4 random
 *           i < 2^32 (rng mc_rng_derive(13101, 0));
 *        2. the coordinates: for n = 1, 7, 1000, 4096 and 65535 and every
 *           i < n, x[0] within 2^-52 of i / n (i * (1.0 / n) rounds twice,
 *           and passes) and x[1] equal to mc_radical_inverse(i, 2) bit for
 *           bit. The net of test 3 alone would pass the two coordinates
 *           swapped, or (i + 1/2) / n: both nets, neither this set;
 *        3. for n = 2^m, m = 2 .. 12, the n points form a (0, m, 2)-net in
 *           base 2: every elementary interval [a 2^-k, (a+1) 2^-k) x
 *           [b 2^-(m-k), (b+1) 2^-(m-k)) of area 1/n, k = 0 .. m, holds
 *           exactly one point.
 *
 * Run:   make exercise NAME=hammersley
 */
#include <math.h>
#include <stdlib.h>

#include "exercises/check_exercise.h"
#include "mc/qmc.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* The base-2 radical inverse of i, in [0, 1). */
static double radical_inverse2(uint64_t i)
{
    (void)i;
    return 0.5; /* TODO */
}

/* Point i of the n-point Hammersley set into x[0], x[1]. */
static void hammersley(uint64_t i, uint64_t n, double x[2])
{
    (void)i, (void)n;
    x[0] = x[1] = 0.5; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/hammersley.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

/* The number of i whose radical inverse differs from the library's in any
 * bit; the first such i into *first. */
static int bit_mismatches(uint64_t seed, uint64_t *first)
{
    int bad = 0;
    mc_rng rng = mc_rng_derive(seed, 0);
    for (uint64_t k = 0; k < 65536 + 10000; k++) {
        uint64_t i = k < 65536 ? k : mc_rng_u32(&rng);
        if (radical_inverse2(i) != mc_radical_inverse(i, 2) && bad++ == 0)
            *first = i;
    }
    return bad;
}

/* Whether the 2^m points form a (0, m, 2)-net: for each split k of the m
 * bits, the k leading bits of x and the m - k leading bits of y index a
 * cell, and each of the 2^m cells must be hit once. */
static bool is_net(int m, int *bad_k)
{
    uint64_t n = (uint64_t)1 << m;
    unsigned char *hits = malloc(n);
    bool ok = hits != NULL;
    for (int k = 0; ok && k <= m; k++) {
        for (uint64_t c = 0; c < n; c++)
            hits[c] = 0;
        for (uint64_t i = 0; ok && i < n; i++) {
            double x[2];
            hammersley(i, n, x);
            if (!(x[0] >= 0.0 && x[0] < 1.0 && x[1] >= 0.0 && x[1] < 1.0)) {
                ok = false;
                break;
            }
            uint64_t a = (uint64_t)(x[0] * (double)((uint64_t)1 << k));
            uint64_t b = (uint64_t)(x[1] * (double)((uint64_t)1 << (m - k)));
            ok = hits[(a << (m - k)) | b]++ == 0;
        }
        if (!ok)
            *bad_k = k;
    }
    free(hits);
    return ok;
}

/* The number of points whose coordinates are not (i / n, the radical
 * inverse of i), over every i < n of a few n, with the first such (i, n)
 * and the number of points looked at.
 * 2^-52: i * (1.0 / n) differs from i / n by two roundings, each at most
 * 2^-53 relative, of numbers below 1. */
static int coordinate_mismatches(uint64_t *first_i, uint64_t *first_n, uint64_t *points)
{
    static const uint64_t ns[] = {1, 7, 1000, 4096, 65535};
    int bad = 0;
    *points = 0;
    for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++)
        for (uint64_t i = 0; i < ns[k]; i++, ++*points) {
            double x[2] = {-1.0, -1.0};
            hammersley(i, ns[k], x);
            bool ok = fabs(x[0] - (double)i / (double)ns[k]) <= 0x1p-52 &&
                      x[1] == mc_radical_inverse(i, 2);
            if (!ok && bad++ == 0)
                *first_i = i, *first_n = ns[k];
        }
    return bad;
}

static void judge(ex_judge *j)
{
    uint64_t first = 0, seed = ex_seed(j, 13101);
    int bad = bit_mismatches(seed, &first);
    const char *name = "radical inverse, bit for bit";
    if (bad)
        ex_check_exact(j, "bits", name, false,
                       "%d of 75536 differ from mc_radical_inverse, first i = %llu", bad,
                       (unsigned long long)first);
    else
        ex_check_exact(j, "bits", name, true, "all 75536 equal mc_radical_inverse(i, 2)");
    uint64_t first_n = 0, points = 0;
    int wrong = coordinate_mismatches(&first, &first_n, &points);
    name = "coordinates (i / n, radical inverse)";
    if (wrong)
        ex_check_exact(j, "coords", name, false,
                       "%d of %llu points wrong, first i = %llu of n = %llu", wrong,
                       (unsigned long long)points, (unsigned long long)first,
                       (unsigned long long)first_n);
    else
        ex_check_exact(j, "coords", name, true, "all %llu points of n = 1, 7, 1000, 4096, 65535",
                       (unsigned long long)points);
    int failed_m = 0, bad_k = -1;
    for (int m = 2; m <= 12 && failed_m == 0; m++)
        if (!is_net(m, &bad_k))
            failed_m = m;
    name = "(0,m,2)-net, m = 2..12";
    if (failed_m)
        ex_check_exact(j, "net", name, false, "m = %d: an interval of 2^-%d x 2^-%d holds 0 or 2+ points",
                       failed_m, bad_k, failed_m - bad_k);
    else
        ex_check_exact(j, "net", name, true, "every elementary interval of area 2^-m holds one point");
}

const ex_exercise ex_this = {"hammersley", "13 (#ch-qmc)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
