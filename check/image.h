/* mcbox/image.h - judge YOUR renderer's images against the truth: a mean
 * per block and per channel, tested against the exact pixel values with a
 * stated family-wise false-alarm rate, the bias reported as a number with
 * its error bar.
 *
 * The noise is estimated from the renders, never from the truth: from
 * K >= 2 independent renders (different seeds) of the same scene, or from
 * the per-pixel mean and second moment of one render. With K renders two
 * variances are measured for every block: the one pixels would give if
 * they were independent (each pixel's spread over the renders, K - 1
 * degrees of freedom per pixel), and the spread of the block's mean itself
 * over the renders. Their ratio, pooled over all blocks, measures how
 * strongly a renderer's pixels move together (light paths that splat onto
 * several pixels, a sampler shared between pixels); it multiplies every
 * variance when above 1, so that correlated noise never passes for bias.
 * A mean and second-moment pair cannot show that correlation: the result
 * says so. A block's own variance rests on few samples, and a
 * heavy-tailed renderer's most often comes out low (the rare large sample
 * missed the block in every render): each block's variance is at least
 * the mean relative variance per pixel of its 3 x 3 neighbourhood of
 * blocks, scaled to it. Without that floor, 8 in 40 correct light-tracing
 * and bidirectional renders at 16 samples per pixel failed; with it none
 * did.
 *
 * What a stored value stands for is modelled, not ignored. An 8- or 16-bit
 * value stands for an interval of linear values (its transfer curve and
 * quantizer; mcbox-check's readers, imageio/image_io.h in mcbox's sources, say
 * how), a float for an interval of its rounding;
 * the truth has an error bound of its own. A block is wrong only when its
 * mean lies farther from the truth than those bounds allow, by more than
 * its noise explains: the deviation beyond the allowance, over the
 * standard error, is the statistic z.
 *
 * The family of tests: the whole image per channel, every named region per
 * channel, every block per channel. Each is two-sided at alpha / (number of
 * tests) (Bonferroni), so that a correct renderer fails with probability at
 * most alpha whatever the tests' dependence. Student's t is used where the
 * variance rests on fewer than 30 degrees of freedom.
 */
#ifndef MCBOX_IMAGE_H
#define MCBOX_IMAGE_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The images to judge; every array holds width * height * 3 linear RGB
 * values, row-major, top row first. */
typedef struct mcbox_image_set {
    int width, height; /* >= 1 */
    const double *truth;      /* the exact pixel values */
    const double *truth_se;   /* a noisy reference's standard error per value, or NULL */
    double truth_error;       /* a bound on |truth - exact| per value (>= 0) */
    /* K independent renders ... */
    int n_renders;
    const double *const *renders;
    /* ... and, per render, the interval of linear values each stored value
     * stands for (an 8- or 16-bit file); NULL for float files. hi may be
     * +INFINITY: a clamped value. */
    const double *const *lo, *const *hi;
    double rel_precision; /* float files: the relative rounding of a stored value */
    /* Or, with n_renders = 0: one render's per-value mean and mean of
     * squares over `samples` samples per pixel (>= 2). */
    const double *mean, *second_moment;
    double samples;
} mcbox_image_set;

/* A named part of the image in fractions of its size, [x0, x1) x [y0, y1). */
typedef struct mcbox_image_region {
    const char *name;
    double x0, y0, x1, y1;
} mcbox_image_region;

typedef struct mcbox_image_options {
    double alpha; /* family-wise false-alarm rate, in (0, 0.5); 0: 0.01 */
    int block;    /* block side in pixels; 0: the image's larger side / 8, at least 1 */
    const mcbox_image_region *regions;
    int n_regions;
} mcbox_image_options;

/* One tested part for one channel. */
typedef struct mcbox_image_part {
    int x0, y0, x1, y1, channel;
    double truth, mean;   /* their means over the part */
    double se;            /* the mean's standard error */
    double allowance;     /* the bound the stored values and the truth allow */
    double z, p;          /* beyond-allowance deviation / se; two-sided p-value */
    double detectable;    /* the bias this test catches with probability 0.9 */
} mcbox_image_part;

#define MCBOX_IMAGE_WORST 5
#define MCBOX_IMAGE_MAX_REGIONS 8

typedef struct mcbox_image_result {
    bool pass, undetermined;
    char message[512];          /* why it failed or could not decide, "" on a pass */
    char note[256];             /* a caveat that does not decide the verdict */
    double alpha, per_test_alpha, min_p;
    double z_crit;              /* |z| above which one test rejects */
    int tests;                  /* in the family */
    int block, blocks_x, blocks_y;
    double inflation;           /* the measured variance ratio (1 when not measurable) */
    double dof;                 /* degrees of freedom of the variances */
    mcbox_image_part image[3];  /* the whole image per channel */
    mcbox_image_part regions[MCBOX_IMAGE_MAX_REGIONS][3];
    const char *region_names[MCBOX_IMAGE_MAX_REGIONS]; /* the options' names */
    int n_regions;
    mcbox_image_part worst[MCBOX_IMAGE_WORST]; /* blocks by smallest p */
    int n_worst;
    double block_detectable;    /* median over blocks of detectable / truth */
    double *z;                  /* blocks_y * blocks_x * 3 block z values, freed by
                                   mcbox_image_result_free */
} mcbox_image_result;

/* Runs the tests. Returns 0 when they ran (the verdict in r->pass), -1
 * when the input cannot be judged, with r->undetermined set and the
 * reason in r->message: fewer than 2 renders, a non-finite or negative
 * value, a clamped value where the truth lies below the clamp, a moment
 * pair with fewer than 2 samples, bad sizes or options, out of memory. */
int mcbox_image_check(const mcbox_image_set *set, const mcbox_image_options *opt,
                      mcbox_image_result *r);

/* Frees what a result holds; the result may be zeroed or checked. */
void mcbox_image_result_free(mcbox_image_result *r);

#ifdef __cplusplus
}
#endif

#endif /* MCBOX_IMAGE_H */
