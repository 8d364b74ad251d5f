/* mc/qmc.c - radical inverses, Hammersley, Halton, Sobol and their
 * scrambles; the cursor that hides which source a sample comes from. */
#include "mc/qmc.h"

#include <assert.h>

#include "mc/sobol_table.h"

_Static_assert(MC_SOBOL_MAX_DIM <= MC_SOBOL_TABLE_DIMS, "Sobol table too small");

static const uint16_t primes[MC_HALTON_MAX_DIM] = {
    2,   3,   5,   7,   11,  13,  17,  19,  23,  29,  31,  37,  41,  43,  47,  53,
    59,  61,  67,  71,  73,  79,  83,  89,  97,  101, 103, 107, 109, 113, 127, 131,
    137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193, 197, 199, 211, 223,
    227, 229, 233, 239, 241, 251, 257, 263, 269, 271, 277, 281, 283, 293, 307, 311};

/* The largest double below 1, 1 - 2^-53. */
#define ONE_MINUS_ULP 0x1.fffffffffffffp-1

unsigned mc_qmc_prime(unsigned k)
{
    assert(k < MC_HALTON_MAX_DIM);
    return primes[k];
}

/* MurmurHash3's 64-bit finaliser (Austin Appleby, public domain): a
 * bijection with full avalanche, used to turn (seed, stream, dim) into
 * independent-looking keys. */
static uint64_t mix64(uint64_t x)
{
    x ^= x >> 33;
    x *= UINT64_C(0xff51afd7ed558ccd);
    x ^= x >> 33;
    x *= UINT64_C(0xc4ceb9fe1a85ec53);
    return x ^ (x >> 33);
}

/* Chris Wellons' "lowbias32" [@wellons2018] (2018, "Prospecting for hash functions",
 * nullprogram.com): a cheap 32-bit bijective mix, for the per-digit keys of
 * the Halton permutations. */
static uint32_t mix32(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

/* The two halves of mc_qmc_stream_seed: the seed's mix, which a caller
 * that hashes many streams of one seed can keep, and the stream's. */
static uint64_t seed_mix(uint64_t seed)
{
    return mix64(seed ^ UINT64_C(0x9e3779b97f4a7c15));
}

static uint64_t stream_mix(uint64_t seed_mixed, uint64_t stream)
{
    return mix64(seed_mixed ^ (stream + UINT64_C(0x6a09e667f3bcc909)));
}

uint64_t mc_qmc_stream_seed(uint64_t seed, uint64_t stream)
{
    /* Both inputs pass through a full-avalanche mix, so neighbouring seeds
     * or streams give unrelated scrambles. The constants only keep (0, 0)
     * away from the fixed point mix64(0) = 0. */
    return stream_mix(seed_mix(seed), stream);
}

/* The key of sub-index k (a dimension, or a padded pair's slot) under the
 * stream seed `base`: the high half of a mix of the two. */
static uint32_t index_key(uint64_t base, uint64_t k)
{
    return (uint32_t)(mix64(base + (k + 1u) * UINT64_C(0x9e3779b97f4a7c15)) >> 32);
}

uint32_t mc_qmc_key(uint64_t seed, uint64_t stream, unsigned dim)
{
    return index_key(mc_qmc_stream_seed(seed, stream), dim);
}

/* BEGIN SNIPPET radical_inverse */
/* Mirrors the base-b digits of i about the radix point. Digit j (j = 0 is
 * the lowest digit of i, which becomes the first after the point) is
 * replaced by a random permutation of {0..b-1} keyed by mix32(key + j
 * golden) when `permute` is set, and then at least enough digits are kept
 * that b^m >= 2^32, because the permuted zeros above the top digit of i are
 * no longer zero. rev / b^m is one correctly rounded division while b^m <=
 * 2^53; a longer i spills into a second chunk (i < 2^64 needs at most two:
 * after the first, i < 2^64 b / 2^53 < 2^53 / b).
 */
static double mirror_digits(uint64_t i, unsigned b, int permute, uint32_t key)
{
    const uint64_t limit = UINT64_C(1) << 53, resolution = UINT64_C(1) << 32;
    uint64_t rev[2] = {0u, 0u}, bm[2] = {1u, 1u};
    uint32_t j = 0;
    for (int c = 0; c < 2; c++) {
        while ((i > 0 || (permute && bm[0] < resolution)) && bm[c] <= limit / b) {
            /* 32-bit division where i allows: several times cheaper than
             * 64-bit division on common CPUs, and this is the hot loop. */
            uint32_t d;
            if (i <= UINT32_MAX) {
                d = (uint32_t)i % b;
                i = (uint32_t)i / b;
            } else {
                d = (uint32_t)(i % b);
                i /= b;
            }
            if (permute)
                d = mc_permutation_element(d, b, mix32(key + j * 0x9e3779b9u));
            rev[c] = rev[c] * b + d;
            bm[c] *= b;
            j++;
        }
    }
    assert(i == 0);
    double x = ((double)rev[0] + (double)rev[1] / (double)bm[1]) / (double)bm[0];
    /* Two roundings can carry rev[0] + frac up to b^m: keep the point in
     * [0, 1). */
    return x < 1.0 ? x : ONE_MINUS_ULP;
}

double mc_radical_inverse(uint64_t i, unsigned base)
{
    assert(base >= 2);
    return mirror_digits(i, base, 0, 0u);
}
/* END SNIPPET radical_inverse */

/* BEGIN SNIPPET van_der_corput */
uint32_t mc_van_der_corput_u32(uint32_t i)
{
    /* Reverse by swapping ever smaller halves: 16-bit halves and bytes
     * (one byte swap instruction where the compiler has it), nibbles,
     * pairs, bits. */
#if defined(__GNUC__)
    i = __builtin_bswap32(i);
#else
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i >> 8) & 0x00ff00ffu);
#endif
    i = ((i & 0x0f0f0f0fu) << 4) | ((i >> 4) & 0x0f0f0f0fu);
    i = ((i & 0x33333333u) << 2) | ((i >> 2) & 0x33333333u);
    i = ((i & 0x55555555u) << 1) | ((i >> 1) & 0x55555555u);
    return i;
}
/* END SNIPPET van_der_corput */

/* i / n, which for n beyond 2^53 can round up to 1: kept in [0, 1). */
static double fraction(uint64_t i, uint64_t n)
{
    assert(i < n);
    double x = (double)i / (double)n;
    return x < 1.0 ? x : ONE_MINUS_ULP;
}

void mc_hammersley2(uint64_t i, uint64_t n, double x[2])
{
    x[0] = fraction(i, n);
    x[1] = mc_radical_inverse(i, 2u);
}

void mc_hammersley3(uint64_t i, uint64_t n, double x[3])
{
    x[0] = fraction(i, n);
    x[1] = mc_radical_inverse(i, 2u);
    x[2] = mc_radical_inverse(i, 3u);
}

/* BEGIN SNIPPET halton */
double mc_halton(uint64_t i, unsigned dim)
{
    return mirror_digits(i, mc_qmc_prime(dim), 0, 0u);
}

double mc_halton_permuted(uint64_t i, unsigned dim, uint64_t seed, uint64_t stream)
{
    return mirror_digits(i, mc_qmc_prime(dim), 1, mc_qmc_key(seed, stream, dim));
}
/* END SNIPPET halton */

/* The index of the lowest set bit of i != 0. */
static unsigned lowest_bit(uint32_t i)
{
#if defined(__GNUC__)
    return (unsigned)__builtin_ctz(i);
#else
    unsigned k = 0;
    for (; (i & 1u) == 0u; i >>= 1)
        k++;
    return k;
#endif
}

/* BEGIN SNIPPET sobol_u32 */
uint32_t mc_sobol_u32(uint32_t i, unsigned dim)
{
    /* Point i is the generator matrix times the bits of i over GF(2): the
     * XOR of the direction numbers v_k of the bits k set in i, visited
     * lowest first (one step per set bit: half the cost of a loop over all
     * bits up to the highest). */
    assert(dim < MC_SOBOL_MAX_DIM);
    const uint32_t *v = mc_sobol_matrix[dim];
    uint32_t x = 0u;
    for (; i != 0u; i &= i - 1u)
        x ^= v[lowest_bit(i)];
    return x;
}
/* END SNIPPET sobol_u32 */

/* BEGIN SNIPPET owen_scramble */
/* Owen's nested uniform scramble flips each bit by a random function of the
 * bits above it. Reversed, "above" becomes "below", and every step of
 * Laine and Karras's permutation (2011, "Stratified sampling for stochastic
 * transparency") [@laine-karras2011] changes bit k only by a function of bits 0..k: adding the
 * key, multiplying by an odd number, XOR with a multiple by an even one.
 * Burley (2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)) [@burley2020] uses this
 * to scramble by hashing; the constants are Vegdahl's improved ones (2021,
 * "Building a better LK hash", psychopath.io) [@vegdahl2021]. The lowest reversed bit (the
 * first digit) is flipped by key bit 0. For k <= 16 the low k reversed bits
 * after `x += key` are uniform in the key's low bits, and the multiplier
 * depends only on its high half, so a uniform key makes the top 16 bits of
 * every point exactly uniform. */
static uint32_t lk_hash(uint32_t x, uint32_t key)
{
    x ^= x * 0x3d20adeau;
    x += key;
    x *= (key >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

uint32_t mc_owen_scramble_u32(uint32_t v, uint32_t key)
{
    return mc_van_der_corput_u32(lk_hash(mc_van_der_corput_u32(v), key));
}

double mc_sobol(uint32_t i, unsigned dim)
{
    return (double)mc_sobol_u32(i, dim) * 0x1p-32;
}

/* The two scrambles of point i, dimension dim, under its key: the digital
 * shift and the nested uniform scramble. */
static double sobol_xor_keyed(uint32_t i, unsigned dim, uint32_t key)
{
    return (double)(mc_sobol_u32(i, dim) ^ key) * 0x1p-32;
}

/* Dimension 1's point, reversed (bit r is the point's digit r + 1): its
 * direction numbers are the rows of Pascal's triangle mod 2 (primitive
 * polynomial x + 1), so digit r is the XOR over the bits c of i of
 * C(c, r) mod 2. As polynomials over GF(2) that is i(z) taken to
 * i(z + 1), a Taylor shift by 1: split into halves i = a + z^h b, with h a
 * power of two (z + 1)^h = z^h + 1, so the shift adds each block's high
 * half into its low half, at every block size (the five steps commute).
 * Five masked XORs for the loop over i's bits in mc_sobol_u32, the same
 * bits (tests/test_qmc.c compares them). */
static uint32_t sobol_dim1_reversed(uint32_t i)
{
    i ^= (i & 0xffff0000u) >> 16;
    i ^= (i & 0xff00ff00u) >> 8;
    i ^= (i & 0xf0f0f0f0u) >> 4;
    i ^= (i & 0xccccccccu) >> 2;
    i ^= (i & 0xaaaaaaaau) >> 1;
    return i;
}

double mc_sobol_owen_keyed(uint32_t i, unsigned dim, uint32_t key)
{
    /* Dimension 0's generator matrix is the identity read from the top
     * bit down, so its point is i reversed, and the scramble's first
     * reversal gives back i: the same bits without the matrix product.
     * Dimension 1's reversed point has a closed form. */
    if (dim == 0u)
        return (double)mc_van_der_corput_u32(lk_hash(i, key)) * 0x1p-32;
    if (dim == 1u)
        return (double)mc_van_der_corput_u32(lk_hash(sobol_dim1_reversed(i), key)) * 0x1p-32;
    return (double)mc_owen_scramble_u32(mc_sobol_u32(i, dim), key) * 0x1p-32;
}

double mc_sobol_xor(uint32_t i, unsigned dim, uint64_t seed, uint64_t stream)
{
    return sobol_xor_keyed(i, dim, mc_qmc_key(seed, stream, dim));
}

double mc_sobol_owen(uint32_t i, unsigned dim, uint64_t seed, uint64_t stream)
{
    return mc_sobol_owen_keyed(i, dim, mc_qmc_key(seed, stream, dim));
}
/* END SNIPPET owen_scramble */

mc_permutation_size mc_permutation_size_make(uint32_t n)
{
    assert(n >= 1u);
    uint32_t w = n - 1u;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    /* A power of two takes its remainder by the mask: no division. */
    return (mc_permutation_size){n, w, (n & w) == 0u ? 0u : UINT64_MAX / n + 1u};
}

/* a mod n for a 32-bit a: the mask when n is a power of two (n = 1
 * included, whose mask is 0); else, with c = ceil(2^64 / n), (c a mod 2^64) / 2^64
 * approximates the fractional part of a / n closely enough that its
 * product with n, floored, is the remainder, for every a and n below 2^32
 * (Lemire, Kaser and Kurz 2019, theorem 1: a multiplier of 64 bits
 * suffices for 32-bit operands). The product's high 64 bits come from
 * the two 32-bit halves of c a: (hi n 2^32 + lo n) / 2^64 floors to
 * (hi n + floor(lo n / 2^32)) / 2^32, whose sum cannot overflow. */
uint32_t mc_permutation_remainder(uint32_t a, mc_permutation_size s)
{
    if ((s.n & s.mask) == 0u)
        return a & s.mask;
    uint64_t frac = s.inverse * a;
    uint64_t hi = frac >> 32, lo = frac & 0xffffffffu;
    return (uint32_t)((hi * s.n + ((lo * s.n) >> 32)) >> 32);
}

uint32_t mc_permutation_element(uint32_t i, uint32_t n, uint32_t key)
{
    return mc_permutation_element_sized(i, mc_permutation_size_make(n), key);
}

/* Kensler (2013, "Correlated Multi-Jittered Sampling", Pixar technical memo
 * 13-01) [@kensler2013], section 3: a hash that is a bijection on the w-bit integers
 * (w = the bits of n - 1): XOR with key bits, multiplication by odd
 * constants and xorshifts of the masked value are each invertible modulo
 * 2^w. Values >= n are walked along their cycle until they fall back into
 * [0, n) ("cycle walking"), which keeps the bijection; the final rotation by
 * the key makes the image of any i uniform over the keys. */
uint32_t mc_permutation_element_sized(uint32_t i, mc_permutation_size size, uint32_t key)
{
    uint32_t n = size.n, w = size.mask;
    assert(i < n);
    do {
        i ^= key;
        i *= 0xe170893du;
        i ^= key >> 16;
        i ^= (i & w) >> 4;
        i ^= key >> 8;
        i *= 0x0929eb3fu;
        i ^= key >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | key >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= n);
    /* (i + key) mod n without the 32-bit overflow of i + key; key mod n
     * without a division (a mask, or two multiplications). */
    uint64_t r = (uint64_t)i + mc_permutation_remainder(key, size);
    return (uint32_t)(r >= n ? r - n : r);
}

/* The keys of the request at dimension d: the index permutation and the
 * first scramble take the two halves of the hash of (base, 2d), a second
 * scramble half of that of (base, 2d + 1). Each is a full-avalanche hash
 * (mc_qmc_stream_seed), so keys of different requests, pixels and seeds
 * are independent. The hash's first half depends on base alone and is
 * kept in the pixel key. */
uint64_t mc_sobol_padded_key(uint64_t base)
{
    return seed_mix(base);
}

double mc_sobol_padded1_sized(uint64_t pixel_key, uint32_t dim, uint32_t k, mc_permutation_size n)
{
    uint64_t h = stream_mix(pixel_key, 2u * (uint64_t)dim);
    uint32_t index = mc_permutation_element_sized(k, n, (uint32_t)h);
    return mc_sobol_owen_keyed(index, 0u, (uint32_t)(h >> 32));
}

void mc_sobol_padded2_sized(uint64_t pixel_key, uint32_t dim, uint32_t k, mc_permutation_size n,
                            double u[2])
{
    uint64_t h = stream_mix(pixel_key, 2u * (uint64_t)dim);
    uint64_t h2 = stream_mix(pixel_key, 2u * (uint64_t)dim + 1u);
    uint32_t index = mc_permutation_element_sized(k, n, (uint32_t)h);
    u[0] = mc_sobol_owen_keyed(index, 0u, (uint32_t)(h >> 32));
    u[1] = mc_sobol_owen_keyed(index, 1u, (uint32_t)h2);
}

double mc_sobol_padded1_keyed(uint64_t pixel_key, uint32_t dim, uint32_t k, uint32_t n)
{
    return mc_sobol_padded1_sized(pixel_key, dim, k, mc_permutation_size_make(n));
}

void mc_sobol_padded2_keyed(uint64_t pixel_key, uint32_t dim, uint32_t k, uint32_t n, double u[2])
{
    mc_sobol_padded2_sized(pixel_key, dim, k, mc_permutation_size_make(n), u);
}

double mc_sobol_padded1(uint64_t base, uint32_t dim, uint32_t k, uint32_t n)
{
    return mc_sobol_padded1_keyed(mc_sobol_padded_key(base), dim, k, n);
}

void mc_sobol_padded2(uint64_t base, uint32_t dim, uint32_t k, uint32_t n, double u[2])
{
    mc_sobol_padded2_keyed(mc_sobol_padded_key(base), dim, k, n, u);
}

unsigned mc_qmc_max_dim(mc_qmc_method method)
{
    switch (method) {
    case MC_QMC_RANDOM:
        return UINT32_MAX;
    case MC_QMC_HALTON:
        return MC_HALTON_MAX_DIM;
    case MC_QMC_SOBOL:
    case MC_QMC_SOBOL_XOR:
    case MC_QMC_SOBOL_OWEN:
        return MC_SOBOL_MAX_DIM;
    }
    return 0u;
}

mc_qmc_cursor mc_qmc_begin(mc_qmc_method method, uint64_t seed, uint64_t stream, uint64_t i)
{
    mc_qmc_cursor c = {.method = method, .seed = seed, .stream = stream, .index = i, .dim = 0u};
    c.base = mc_qmc_stream_seed(seed, stream);
    if (method == MC_QMC_RANDOM)
        c.rng = mc_rng_derive(c.base, i);
    else if (method != MC_QMC_HALTON)
        assert(i <= UINT32_MAX);
    return c;
}

/* BEGIN SNIPPET qmc_next */
double mc_qmc_next(mc_qmc_cursor *c)
{
    unsigned d = c->dim++;
    assert(d < mc_qmc_max_dim(c->method));
    uint32_t i = (uint32_t)c->index;
    switch (c->method) {
    case MC_QMC_RANDOM:
        return mc_rng_uniform(&c->rng);
    case MC_QMC_HALTON:
        return mirror_digits(c->index, primes[d], 1, index_key(c->base, d));
    case MC_QMC_SOBOL:
        return mc_sobol(i, d);
    case MC_QMC_SOBOL_XOR:
        return sobol_xor_keyed(i, d, index_key(c->base, d));
    case MC_QMC_SOBOL_OWEN:
        return mc_sobol_owen_keyed(i, d, index_key(c->base, d));
    }
    return 0.0;
}
/* END SNIPPET qmc_next */

/* Sobol dimension d of indices i0 .. i0+n-1, as 32-bit fractions. Going
 * from i to i+1 flips bits 0..t of i, t = the lowest set bit of i+1, so
 * x(i+1) = x(i) ^ (v_0 ^ ... ^ v_t): one XOR per point after the first
 * (the natural-order counterpart of Antonov and Saleev's Gray-code step). */
static void sobol_run(uint32_t i0, uint32_t n, unsigned d, int reversed, uint32_t *out)
{
    /* With `reversed` every value is produced bit-reversed (reversal
     * commutes with XOR), which saves the Owen scramble its first
     * reversal. */
    const uint32_t *v = mc_sobol_matrix[d];
    uint32_t prefix[32], acc = 0u;
    for (unsigned k = 0; k < 32u; k++) {
        acc ^= v[k];
        prefix[k] = reversed ? mc_van_der_corput_u32(acc) : acc;
    }
    uint32_t x = mc_sobol_u32(i0, d);
    if (reversed)
        x = mc_van_der_corput_u32(x);
    for (uint32_t k = 0; k < n; k++) {
        out[k] = x;
        uint32_t next = i0 + k + 1u;
        if (next != 0u)
            x ^= prefix[lowest_bit(next)];
    }
}

void mc_qmc_fill(mc_qmc_method method, uint64_t seed, uint64_t stream, uint64_t i0, uint32_t n,
                 unsigned dim, double *out)
{
    assert(dim < mc_qmc_max_dim(method));
    uint64_t base = mc_qmc_stream_seed(seed, stream);
    uint32_t key = index_key(base, dim);
    if (method == MC_QMC_RANDOM || method == MC_QMC_HALTON) {
        for (uint32_t k = 0; k < n; k++) {
            if (method == MC_QMC_HALTON) {
                out[k] = mirror_digits(i0 + k, primes[dim], 1, key);
            } else {
                mc_rng rng = mc_rng_derive(base, i0 + k);
                mc_rng_advance(&rng, dim);
                out[k] = mc_rng_uniform(&rng);
            }
        }
        return;
    }
    assert(i0 + n <= UINT64_C(1) << 32);
    /* Chunks of 256 keep the integer buffer on the stack. */
    uint32_t buf[256];
    for (uint32_t done = 0; done < n;) {
        uint32_t m = n - done < 256u ? n - done : 256u;
        sobol_run((uint32_t)(i0 + done), m, dim, method == MC_QMC_SOBOL_OWEN, buf);
        if (method == MC_QMC_SOBOL_OWEN) {
            for (uint32_t k = 0; k < m; k++)
                out[done + k] = (double)mc_van_der_corput_u32(lk_hash(buf[k], key)) * 0x1p-32;
        } else {
            uint32_t shift = method == MC_QMC_SOBOL_XOR ? key : 0u;
            for (uint32_t k = 0; k < m; k++)
                out[done + k] = (double)(buf[k] ^ shift) * 0x1p-32;
        }
        done += m;
    }
}
