/* mc/qmc.h - quasi-Monte Carlo point sources: radical inverse, Hammersley,
 * Halton, Sobol, and their random scrambles.
 *
 * Serves this book's #ch-qmc, which follows the stratified samples of its
 * #ch-pi: instead of independent uniforms, points of [0,1)^D that fill the
 * cube more evenly than chance does, so that the error of a smooth
 * integrand can fall like N^-1 (or N^-3/2 once scrambled) instead of
 * N^-1/2.
 *
 * Every point is a pure function of its index (and of the seed of its
 * scramble): there is no hidden state, so any thread can draw any sample and
 * results do not depend on the order in which samples are drawn.
 *
 * Scrambled points are random (a random digital shift, random digit
 * permutations, or Owen's nested uniform scramble); each of those is
 * uniformly distributed over the cube, so an estimate averaged over
 * independent scrambles is unbiased and has an honest standard error. The
 * scrambles are seeded by (seed, stream) as the RNG is: the same pair gives
 * the same points, different streams give independent scrambles.
 */
#ifndef MC_QMC_H
#define MC_QMC_H

#include <stdint.h>

#include "mc/rng.h"

/* Largest dimension (exclusive) of the Halton sequence: dimension d uses
 * the (d+1)-th prime as its base (2, 3, 5, ...). */
#define MC_HALTON_MAX_DIM 64
/* Largest dimension (exclusive) of the Sobol table (Joe and Kuo's
 * new-joe-kuo-6.21201 direction numbers, mc/sobol_table.h). */
#define MC_SOBOL_MAX_DIM 1024

/* The (k+1)-th prime: mc_qmc_prime(0) = 2. 0 <= k < MC_HALTON_MAX_DIM. */
unsigned mc_qmc_prime(unsigned k);

/* Radical inverse of i in base `base` (>= 2): the base-b digits of i
 * mirrored about the radix point, a number in [0, 1). Computed as one
 * correctly rounded division rev / base^m while base^m <= 2^53 (every i
 * below 2^53 in base 2, below 3^33 in base 3), within two roundings for
 * longer i; never 1. */
double mc_radical_inverse(uint64_t i, unsigned base);

/* Van der Corput's sequence (the radical inverse in base 2) as a 32-bit
 * fraction: the bits of i reversed; the point is the result times 2^-32. */
uint32_t mc_van_der_corput_u32(uint32_t i);

/* Point i of the n-point Hammersley set in 2D, (i/n, radical inverse of i
 * in base 2), and in 3D (i/n, base 2, base 3). 0 <= i < n. */
void mc_hammersley2(uint64_t i, uint64_t n, double x[2]);
void mc_hammersley3(uint64_t i, uint64_t n, double x[3]);

/* Dimension `dim` of point i of the Halton sequence: the radical inverse of
 * i in base mc_qmc_prime(dim). 0 <= dim < MC_HALTON_MAX_DIM. */
double mc_halton(uint64_t i, unsigned dim);

/* The same with random digit permutations: each digit position of each
 * dimension gets its own uniformly random permutation of {0, ..., b-1}
 * (mc_permutation_element keyed by a hash of mc_qmc_key(seed, stream, dim)
 * and the position), applied to the digits of i before mirroring. The
 * zeros above the top digit of i are permuted too, down to a resolution of
 * b^-m <= 2^-32, so every point is uniform over the multiples of b^-m in
 * [0, 1) (the same resolution as mc_rng_uniform). */
double mc_halton_permuted(uint64_t i, unsigned dim, uint64_t seed, uint64_t stream);

/* Dimension `dim` of point i of the unscrambled Sobol sequence as a 32-bit
 * fraction (the point is the result times 2^-32). Dimension 0 is van der
 * Corput's sequence. 0 <= dim < MC_SOBOL_MAX_DIM, 0 <= i < 2^32. */
uint32_t mc_sobol_u32(uint32_t i, unsigned dim);

/* The 64-bit seed of the scramble (seed, stream): a hash of the two (two
 * rounds of MurmurHash3's finaliser), from which every key of that scramble
 * and the PCG32 streams of MC_QMC_RANDOM derive. */
uint64_t mc_qmc_stream_seed(uint64_t seed, uint64_t stream);

/* The 32-bit scramble key of dimension `dim` for the scramble (seed,
 * stream): a hash of mc_qmc_stream_seed(seed, stream) and dim, so that keys
 * of different dimensions and streams are independent. */
uint32_t mc_qmc_key(uint64_t seed, uint64_t stream, unsigned dim);

/* Owen's nested uniform scramble of a 32-bit fraction v under `key`: each
 * bit is flipped or not according to a hash of key and the bits above it,
 * so that every elementary interval is permuted at random (Burley's
 * hash-based scramble: a Laine-Karras style hash of the reversed bits).
 * A bijection of the 32-bit fractions for every key; the top bit is
 * flipped by key bit 0, and for a uniform key the top 16 bits of the
 * result are exactly uniform (the lower ones to the quality of the hash). */
uint32_t mc_owen_scramble_u32(uint32_t v, uint32_t key);

/* Sobol point i, dimension dim, as a double in [0, 1): unscrambled, with a
 * random digital shift (XOR by the key of (seed, stream, dim)), or Owen
 * scrambled with that key. */
double mc_sobol(uint32_t i, unsigned dim);
double mc_sobol_xor(uint32_t i, unsigned dim, uint64_t seed, uint64_t stream);
double mc_sobol_owen(uint32_t i, unsigned dim, uint64_t seed, uint64_t stream);

/* mc_sobol_owen with the key of its dimension given, key =
 * mc_qmc_key(seed, stream, dim): the same bits, for a caller that draws
 * many points of one dimension and hashes the key once. */
double mc_sobol_owen_keyed(uint32_t i, unsigned dim, uint32_t key);

/* Element i of a random permutation of {0, ..., n-1} chosen by `key`
 * (Kensler's cycle-walking hash, "Correlated Multi-Jittered Sampling",
 * 2013): a way to visit the samples of a pixel in an order that differs
 * from one dimension to the next. 1 <= n, 0 <= i < n; i -> result is a
 * bijection of {0, ..., n-1} for every key. */
uint32_t mc_permutation_element(uint32_t i, uint32_t n, uint32_t key);

/* The size n of mc_permutation_element made once for the many requests
 * of a pixel: the mask of the bits of n - 1, which the cycle walk (and,
 * for a power of two, the remainder) needs, and Lemire's multiplier for
 * the remainder key mod n otherwise (ceil(2^64 / n);
 * Lemire, Kaser and Kurz, "Faster remainder by direct computation",
 * 2019), which replaces a division by two multiplications. */
typedef struct mc_permutation_size {
    uint32_t n;       /* >= 1 */
    uint32_t mask;    /* 2^w - 1, w the bits of n - 1 */
    uint64_t inverse; /* ceil(2^64 / n); 0 for a power of two, which the mask serves */
} mc_permutation_size;

mc_permutation_size mc_permutation_size_make(uint32_t n);

/* a mod size.n by the multiplier: a % size.n, exactly, for every a. */
uint32_t mc_permutation_remainder(uint32_t a, mc_permutation_size size);

/* mc_permutation_element(i, size.n, key), the same bits. */
uint32_t mc_permutation_element_sized(uint32_t i, mc_permutation_size size, uint32_t key);

/* Padded Owen-scrambled Sobol, for a path tracer that asks for its
 * dimensions one or two at a time (pbrt-v4's PaddedSobolSampler). `base`
 * names the pixel's sequence: mc_qmc_stream_seed(seed, pixel), hashed once
 * per pixel by the caller. The request at dimension `dim` of sample k (of
 * n) is Sobol point perm(k), where the index permutation perm
 * (mc_permutation_element) and the Owen scrambles are keyed by hashes of
 * (base, dim): a 1D request is its dimension 0, a 2D request its
 * dimensions 0 and 1. Every request is a stratified (0,2)-sequence on its
 * own (for n a power of 2 the n samples of a pixel form a (0,m,2)-net);
 * requests are decorrelated by their independent permutations. A caller
 * hands each dimension out once per sample: a 1D request takes one, a 2D
 * request two (dim and dim + 1), so no two requests share a key.
 * 1 <= n, 0 <= k < n. */
double mc_sobol_padded1(uint64_t base, uint32_t dim, uint32_t k, uint32_t n);
void mc_sobol_padded2(uint64_t base, uint32_t dim, uint32_t k, uint32_t n, double u[2]);

/* The same requests for a caller that makes many of one pixel: the part
 * of every request's hash that depends on base alone, computed once
 * (mc_sobol_padded_key(base)), then the requests from it, the same bits
 * as mc_sobol_padded1 and mc_sobol_padded2 of base. */
uint64_t mc_sobol_padded_key(uint64_t base);
double mc_sobol_padded1_keyed(uint64_t pixel_key, uint32_t dim, uint32_t k, uint32_t n);
void mc_sobol_padded2_keyed(uint64_t pixel_key, uint32_t dim, uint32_t k, uint32_t n, double u[2]);

/* The keyed requests with the pixel's sample count made once
 * (mc_permutation_size_make(n)): the same bits. */
double mc_sobol_padded1_sized(uint64_t pixel_key, uint32_t dim, uint32_t k, mc_permutation_size n);
void mc_sobol_padded2_sized(uint64_t pixel_key, uint32_t dim, uint32_t k, mc_permutation_size n,
                            double u[2]);

/* Where the dimensions of a sample come from. */
typedef enum mc_qmc_method {
    MC_QMC_RANDOM,     /* PCG32: mc_rng_derive(mc_qmc_stream_seed(seed, stream), i) */
    MC_QMC_HALTON,     /* Halton with random digit permutations */
    MC_QMC_SOBOL,      /* Sobol, unscrambled (deterministic: no error bar) */
    MC_QMC_SOBOL_XOR,  /* Sobol with a random digital shift */
    MC_QMC_SOBOL_OWEN, /* Sobol, Owen scrambled */
} mc_qmc_method;

/* Largest number of dimensions the method can give (exclusive); for
 * MC_QMC_RANDOM, UINT32_MAX. */
unsigned mc_qmc_max_dim(mc_qmc_method method);

/* A cursor over the dimensions of sample i: the caller asks for the next
 * dimension without knowing whether it comes from PCG32 or a sequence.
 * Dimensions are handed out in order 0, 1, 2, ...; dimension d of sample i
 * is exactly mc_halton_permuted(i, d, seed, stream), mc_sobol(i, d),
 * mc_sobol_xor(...) or mc_sobol_owen(...), and for MC_QMC_RANDOM the d-th
 * mc_rng_uniform of its stream. Asking for dimension
 * mc_qmc_max_dim(method) or beyond, or for a Sobol sample i >= 2^32, is the
 * caller's error (checked by an assertion). */
typedef struct mc_qmc_cursor {
    mc_qmc_method method;
    uint64_t seed, stream, index;
    unsigned dim;
    mc_rng rng;    /* used by MC_QMC_RANDOM only */
    uint64_t base; /* mc_qmc_stream_seed(seed, stream), computed once */
} mc_qmc_cursor;

/* A cursor at dimension 0 of sample i of the point source (method, seed,
 * stream). */
mc_qmc_cursor mc_qmc_begin(mc_qmc_method method, uint64_t seed, uint64_t stream, uint64_t i);

/* The next dimension of the cursor's sample, in [0, 1). */
double mc_qmc_next(mc_qmc_cursor *c);

/* Dimension `dim` of the consecutive samples i0, ..., i0 + n - 1 of the
 * point source (method, seed, stream) into out[0 .. n): exactly the values
 * cursors of those samples give as their dimension dim, computed faster
 * for a run (the Sobol methods step from one index to the next with one
 * XOR and hash the key once). dim < mc_qmc_max_dim(method); for the Sobol
 * methods i0 + n <= 2^32. */
void mc_qmc_fill(mc_qmc_method method, uint64_t seed, uint64_t stream, uint64_t i0, uint32_t n,
                 unsigned dim, double *out);

#endif /* MC_QMC_H */
