/* render/sampler.h - where the uniforms of a path come from.
 *
 * Every random number the renderer draws for one sample of one pixel goes
 * through a sampler: "the next 1D" or "the next 2D" of this sample. Three
 * kinds:
 *   RT_SAMPLER_STRATIFIED  the pixel position jittered over a grid of cells
 *                          (render/jitter.h, this book's #ch-cornell),
 *                          every other draw from the pixel's PCG32 stream
 *   RT_SAMPLER_INDEPENDENT every draw, the pixel position too, from the
 *                          pixel's PCG32 stream
 *   RT_SAMPLER_SOBOL       Owen-scrambled Sobol points, padded as pbrt-v4's
 *                          PaddedSobolSampler [@pharr2023] pads them: each 1D or 2D
 *                          request of sample k of pixel p is the first or
 *                          the first two dimensions of Sobol point
 *                          perm(k), with the index permutation perm and the
 *                          Owen scrambles keyed by a hash of (seed, p,
 *                          dimension) (mc_sobol_padded1_sized and
 *                          mc_sobol_padded2_sized, the pixel's part of the
 *                          hash computed once per pixel,
 *                          mc_sobol_padded_key, and its sample count
 *                          made once, mc_permutation_size_make). Each
 *                          request is a stratified set over the pixel's
 *                          samples; requests differ in
 *                          their permutations and scrambles, which makes
 *                          them independent of one another, so the
 *                          estimate stays unbiased.
 * The two PCG32 kinds draw one PCG32 output per uniform, in the order of
 * the requests, from a stream continued over the passes (render/drive.c).
 *
 * Dimensions of a Sobol sample: the pixel position takes 0 and 1; the
 * draws made for the vertex after segment d (the scattering there, the
 * next direction, a shadow ray, Russian roulette) take the block of
 * RT_SAMPLER_SEGMENT_DIMS dimensions from 2 + d RT_SAMPLER_SEGMENT_DIMS
 * on, in the order they are made. Aligning the blocks with the segments
 * keeps the same dimension for the same decision in most samples (the
 * first bounce's light choice is the same dimension in every sample),
 * which is where a low-discrepancy set can beat independent points.
 *
 * A fourth kind, RT_SAMPLER_DEFAULT, names no source of its own: it is
 * the strategy's best measured one (render/render.h).
 */
#ifndef RT_SAMPLER_H
#define RT_SAMPLER_H

#include <stdbool.h>
#include <stdint.h>

#include "mc/qmc.h"
#include "mc/rng.h"

typedef enum rt_sampler_kind {
    RT_SAMPLER_STRATIFIED, /* 0: a zeroed job is stratified */
    RT_SAMPLER_INDEPENDENT,
    RT_SAMPLER_SOBOL,
    /* The strategy's own, the one `make bench` measures best for it
     * (rt_render_sampler_kind, render/render.h); what
     * rt_render_job_default and the programs' --sampler default give. */
    RT_SAMPLER_DEFAULT
} rt_sampler_kind;

/* The names "stratified", "independent", "sobol", "default" in
 * rt_sampler_kind order, NULL-terminated (for option tables and help
 * text). */
extern const char *const rt_sampler_names[];

/* The kind named `name`; false for anything else. */
bool rt_sampler_parse(const char *name, rt_sampler_kind *out);

/* The name of a kind. */
const char *rt_sampler_name(rt_sampler_kind kind);

/* Most dimensions the draws at one path vertex can take: 8 covers the
 * most any vertex draws (next-event estimation: light choice 1, point on
 * the light 2, material direction 2, roulette 1; the book's mixture:
 * component 1, light choice 1, direction 2, roulette 1; glass 1; metal
 * fuzz 2 and roulette 1). */
#define RT_SAMPLER_SEGMENT_DIMS 8u

/* Most dimensions of a point of the image's sequence
 * (rt_sampler_image_point). */
#define RT_SAMPLER_IMAGE_DIMS 5u

/* The sampler of one pixel while it takes one sample. */
typedef struct rt_sampler {
    mc_rng rng;   /* the pixel's PCG32 stream: every draw unless sobol */
    bool sobol;   /* draws come from the padded Sobol points */
    /* Negative-control hook: a 1D request leaves the dimension where it
     * was, so that the request after it gets the same point (a dimension
     * dropped). False in a correct renderer; rt_render_sampler sets it
     * from the job's path.neg.sampler_reuse_dim (render/integrator.h). */
    bool reuse_dim;
    uint32_t dim; /* sobol: the next dimension of this sample */
    uint32_t k;    /* sobol: this sample's index */
    mc_permutation_size n; /* sobol: the pixel's sample count, made once */
    uint64_t base; /* sobol: mc_sobol_padded_key(mc_qmc_stream_seed(seed, pixel)) */
    /* sobol, the image's sequence (rt_sampler_image_point): the index of
     * the pixel's sample 0 in it, pixel x spp; the render's seed; and the
     * scramble keys of its dimensions for the block of 2^32 indices that
     * holds `first`, hashed once per pixel. */
    uint64_t first, seed;
    uint32_t image_key[RT_SAMPLER_IMAGE_DIMS];
} rt_sampler;

/* A sampler drawing every uniform from rng (independent and stratified,
 * and the tests' way to call the integrator with a stream). */
static inline rt_sampler rt_sampler_from_rng(mc_rng rng)
{
    rt_sampler s = {rng, false, false, 0, 0, {1, 0, 0}, 0, 0, 0, {0}};
    return s;
}

/* The sampler of pixel `pixel` of a render of kind `kind` (not
 * RT_SAMPLER_DEFAULT, which the job resolves first) with `seed` and spp
 * samples per pixel (sobol: 1 <= spp < 2^32), continuing the pixel's
 * PCG32 stream rng. */
rt_sampler rt_sampler_pixel(rt_sampler_kind kind, uint64_t seed, uint64_t spp, mc_rng rng,
                            uint64_t pixel);

/* Begins sample k (< spp) of the pixel: sobol starts again at dimension
 * 0; the PCG32 kinds go on in their stream. */
static inline void rt_sampler_start(rt_sampler *s, uint64_t k)
{
    if (s->sobol) {
        s->k = (uint32_t)k;
        s->dim = 0;
    }
}

/* Moves to the dimensions of the vertex after segment `depth` (>= 0) of
 * the current path (see the top of this file); nothing for PCG32. */
static inline void rt_sampler_segment(rt_sampler *s, int depth)
{
    if (s->sobol)
        s->dim = 2u + (uint32_t)depth * RT_SAMPLER_SEGMENT_DIMS;
}

/* For the draws below and the functions that make them at every path
 * vertex (the camera ray, the cosine direction, the light list's
 * direction): inline even where the compiler's size heuristics would not.
 * The sampler's branch grew them past gcc's limit, and the calls then
 * cost the default sampler instructions in the book render that inlining
 * saves (docs/performance.md records the counts). */
#if defined(__GNUC__)
#define RT_HOT_INLINE static inline __attribute__((always_inline))
#else
#define RT_HOT_INLINE static inline
#endif

/* The Sobol requests, out of line: they hash and scramble. */
double rt_sampler_sobol_1d(rt_sampler *s);
void rt_sampler_sobol_2d(rt_sampler *s, double *u1, double *u2);

/* The next uniform in [0, 1) of the sample. */
RT_HOT_INLINE double rt_sampler_1d(rt_sampler *s)
{
    if (!s->sobol)
        return mc_rng_uniform(&s->rng);
    return rt_sampler_sobol_1d(s);
}

/* The next two uniforms in [0, 1) of the sample; for PCG32, *u1 is drawn
 * first. */
RT_HOT_INLINE void rt_sampler_2d(rt_sampler *s, double *u1, double *u2)
{
    if (!s->sobol) {
        *u1 = mc_rng_uniform(&s->rng);
        *u2 = mc_rng_uniform(&s->rng);
        return;
    }
    rt_sampler_sobol_2d(s, u1, u2);
}

/* The integer in [0, n), n >= 1, that a uniform u in [0, 1) picks:
 * floor(n u), kept below n. */
static inline uint32_t rt_sampler_index_of(double u, uint32_t n)
{
    uint32_t i = (uint32_t)(u * (double)n);
    return i < n ? i : n - 1u;
}

/* A uniformly chosen integer in [0, n), n >= 1: PCG32's unbiased bounded
 * draw (mc_rng_bounded), or rt_sampler_index_of the next 1D (u one of the
 * 2^32 equally likely multiples of 2^-32: each integer's probability is
 * off from 1 / n by less than 2^-32, far below any error bar). */
RT_HOT_INLINE uint32_t rt_sampler_index(rt_sampler *s, uint32_t n)
{
    if (!s->sobol)
        return mc_rng_bounded(&s->rng, n);
    return rt_sampler_index_of(rt_sampler_sobol_1d(s), n);
}

/* Dimensions 0 .. n - 1 (n <= RT_SAMPLER_IMAGE_DIMS) of this sample's
 * point in the image's sequence, into u[0 .. n): for a sobol sampler
 * only. The padded points of a pixel (rt_sampler_1d, rt_sampler_2d) are
 * stratified over that pixel's samples, and the pixels' sets are
 * independent. The image's sequence is one Owen-scrambled Sobol sequence
 * (its dimensions 0 .. n - 1 together, not padded) over every sample of
 * the image: sample k of pixel p is its point p x spp + k, scrambled with
 * keys of the render's seed (a fresh scramble for each block of 2^32
 * indices). So the samples of the whole image fill the n-dimensional cube
 * as one low-discrepancy set, and a pixel's samples, consecutive points,
 * fill it evenly too. Meant for draws whose result lands in any pixel, not
 * only the sample's own: the start of a light subpath, whose splats
 * spread over the image. Each point alone is uniform, so an estimate
 * from it stays unbiased. */
void rt_sampler_image_point(const rt_sampler *s, unsigned n, double *u);

#endif /* RT_SAMPLER_H */
