/* check/image.c - the block tests of mcbox/image.h. */
#include "check/image.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/gsl_quiet.h"

/* z of the one-sided 0.9 power point: a bias of (z_crit + Z90) standard
 * errors beyond the allowance is caught nine times in ten. */
#define Z90 1.2815515655446004

typedef struct job {
    const mcbox_image_set *set;
    int k;      /* renders, 0 for a moment pair */
    size_t n;   /* values per image */
} job;

static void fail_input(mcbox_image_result *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->message, sizeof r->message, fmt, ap);
    va_end(ap);
    r->pass = false;
    r->undetermined = true;
}

/* Render k's value i, and the half-width of what it stands for: the
 * middle of a quantization interval, or the value with its rounding. */
static double value_of(const job *j, int k, size_t i, double *half)
{
    const mcbox_image_set *s = j->set;
    if (s->lo && s->hi && s->lo[k] && s->hi[k]) {
        double lo = s->lo[k][i], hi = s->hi[k][i];
        *half = 0.5 * (hi - lo);
        return 0.5 * (lo + hi);
    }
    double v = s->renders[k][i];
    *half = fabs(v) * s->rel_precision;
    return v;
}

static const char *const channel_name[3] = {"red", "green", "blue"};

/* Rejects what cannot be judged: non-finite or negative values, and a
 * clamped value over a truth that the clamp does not reach. */
static int validate(const job *j, mcbox_image_result *r)
{
    const mcbox_image_set *s = j->set;
    int w = s->width;
    for (size_t i = 0; i < j->n; i++) {
        int x = (int)(i / 3 % (size_t)w), y = (int)(i / 3 / (size_t)w), c = (int)(i % 3);
        if (!isfinite(s->truth[i]) || (s->truth_se && !(s->truth_se[i] >= 0.0))) {
            fail_input(r, "the truth is not finite at pixel (%d, %d) %s", x, y, channel_name[c]);
            return -1;
        }
        for (int k = 0; k < (j->k ? j->k : 2); k++) {
            const double *img = j->k ? s->renders[k] : (k == 0 ? s->mean : s->second_moment);
            double v = img[i];
            if (!isfinite(v) || v < 0.0) {
                fail_input(r, "%s %d: %s value %g at pixel (%d, %d) %s", j->k ? "render" : "moment",
                           k + 1, isfinite(v) ? "a negative" : "a non-finite", v, x, y,
                           channel_name[c]);
                return -1;
            }
            if (j->k && s->hi && s->hi[k] && isinf(s->hi[k][i]) && s->truth[i] < s->lo[k][i]) {
                fail_input(r,
                           "render %d: pixel (%d, %d) %s is clamped at the top code, where the "
                           "truth %.4g lies below it; render more samples or write a float image",
                           k + 1, x, y, channel_name[c], s->truth[i]);
                return -1;
            }
        }
    }
    return 0;
}

/* What a part's test rests on before the inflation. */
typedef struct sums {
    double truth, mean, v_ind, v_blk, v_truth, allowance;
} sums;

static sums part_sums(const job *j, int x0, int y0, int x1, int y1, int c)
{
    const mcbox_image_set *s = j->set;
    sums o = {0};
    int k = j->k;
    double part_mean[64] = {0}; /* per render; K is at most 64 */
    double half_sum = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t i = ((size_t)y * (size_t)s->width + (size_t)x) * 3 + (size_t)c;
            o.truth += s->truth[i];
            if (s->truth_se)
                o.v_truth += s->truth_se[i] * s->truth_se[i];
            if (k == 0) {
                double m = s->mean[i], var = s->second_moment[i] - m * m;
                var = var > 0.0 ? var * s->samples / (s->samples - 1.0) : 0.0;
                o.mean += m;
                o.v_ind += var / s->samples;
                half_sum += fabs(m) * s->rel_precision;
                continue;
            }
            double v[64], sum = 0.0, sq = 0.0, half;
            for (int r = 0; r < k; r++) {
                v[r] = value_of(j, r, i, &half);
                sum += v[r];
                part_mean[r] += v[r];
                half_sum += half / k;
            }
            double m = sum / k;
            for (int r = 0; r < k; r++)
                sq += (v[r] - m) * (v[r] - m);
            o.mean += m;
            o.v_ind += sq / (k - 1) / k;
        }
    int n = (x1 - x0) * (y1 - y0);
    double n2 = (double)n * (double)n;
    o.truth /= n;
    o.mean /= n;
    o.v_ind /= n2;
    o.v_truth /= n2;
    o.allowance = half_sum / n + s->truth_error;
    if (k >= 2) {
        double sq = 0.0;
        for (int r = 0; r < k; r++) {
            double d = part_mean[r] / n - o.mean;
            sq += d * d;
        }
        o.v_blk = sq / (k - 1) / k;
    }
    return o;
}

/* BEGIN SNIPPET image_judge */
/* The part's test once the inflation, the degrees of freedom and the
 * per-test level are known. */
static mcbox_image_part judge(const sums *o, int x0, int y0, int x1, int y1, int c, double inflation,
                              double dof, double z_crit)
{
    mcbox_image_part p = {.x0 = x0, .y0 = y0, .x1 = x1, .y1 = y1, .channel = c};
    p.truth = o->truth;
    p.mean = o->mean;
    p.allowance = o->allowance;
    double var = o->v_ind * (inflation > 1.0 ? inflation : 1.0) + o->v_truth;
    p.se = sqrt(var);
    double dev = o->mean - o->truth, beyond = fabs(dev) - o->allowance;
    if (beyond <= 0.0)
        p.z = 0.0;
    else
        p.z = p.se > 0.0 ? copysign(beyond / p.se, dev) : copysign((double)INFINITY, dev);
    double az = fabs(p.z);
    if (isinf(az))
        p.p = 0.0;
    else
        p.p = 2.0 * (dof < 30.0 ? gsl_cdf_tdist_Q(az, dof) : gsl_cdf_ugaussian_Q(az));
    p.detectable = o->allowance + (z_crit + Z90) * p.se;
    return p;
}
/* END SNIPPET image_judge */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Keeps the MCBOX_IMAGE_WORST parts of smallest p (largest |z| on ties). */
static void keep_worst(mcbox_image_result *r, const mcbox_image_part *p)
{
    int n = r->n_worst;
    int at = n;
    while (at > 0 && (p->p < r->worst[at - 1].p ||
                      (p->p == r->worst[at - 1].p && fabs(p->z) > fabs(r->worst[at - 1].z))))
        at--;
    if (at >= MCBOX_IMAGE_WORST)
        return;
    int last = n < MCBOX_IMAGE_WORST ? n : MCBOX_IMAGE_WORST - 1;
    memmove(&r->worst[at + 1], &r->worst[at], (size_t)(last - at) * sizeof r->worst[0]);
    r->worst[at] = *p;
    if (n < MCBOX_IMAGE_WORST)
        r->n_worst++;
}

/* The blocks' grid, for the helpers below. */
typedef struct grid {
    int b, nx, ny, width, height;
} grid;

/* Block (bx, by) as pixels [x0, x1) x [y0, y1); the last ones are cut
 * at the image's edge. */
static void block_rect(const grid *g, int bx, int by, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = bx * g->b, *y0 = by * g->b;
    *x1 = *x0 + g->b < g->width ? *x0 + g->b : g->width;
    *y1 = *y0 + g->b < g->height ? *y0 + g->b : g->height;
}

static int block_pixels(const grid *g, int bx, int by)
{
    int x0, y0, x1, y1;
    block_rect(g, bx, by, &x0, &y0, &x1, &y1);
    return (x1 - x0) * (y1 - y0);
}

/* BEGIN SNIPPET image_floor */
/* A block's own variance rests on few samples, and a heavy-tailed
 * renderer (light paths that splat, a lamp found rarely) most often shows
 * less than its expectation: no rare sample landed in it. Its neighbours'
 * relative variance per pixel estimates the same smooth quantity from nine
 * times the samples; the larger of the two estimates is used. A block
 * whose truth is 0 keeps its own. */
static int floor_variances(sums *bs, const grid *g)
{
    size_t nb = (size_t)g->nx * (size_t)g->ny * 3;
    double *rho = malloc(nb * sizeof *rho);
    if (!rho)
        return -1;
    for (size_t i = 0; i < nb; i++) {
        size_t cell = i / 3;
        int n = block_pixels(g, (int)(cell % (size_t)g->nx), (int)(cell / (size_t)g->nx));
        double t = bs[i].truth;
        rho[i] = t > 0.0 ? bs[i].v_ind * n / (t * t) : -1.0;
    }
    for (int by = 0; by < g->ny; by++)
        for (int bx = 0; bx < g->nx; bx++)
            for (int c = 0; c < 3; c++) {
                double sum = 0.0;
                int count = 0;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int x = bx + dx, y = by + dy;
                        if (x < 0 || y < 0 || x >= g->nx || y >= g->ny)
                            continue;
                        double v = rho[((size_t)y * (size_t)g->nx + (size_t)x) * 3 + (size_t)c];
                        if (v >= 0.0)
                            sum += v, count++;
                    }
                sums *o = &bs[((size_t)by * (size_t)g->nx + (size_t)bx) * 3 + (size_t)c];
                if (count && o->truth > 0.0) {
                    double v = o->truth * o->truth * (sum / count) / block_pixels(g, bx, by);
                    o->v_ind = v > o->v_ind ? v : o->v_ind;
                }
            }
    free(rho);
    return 0;
}
/* END SNIPPET image_floor */

/* The pixel-independent variance of the mean over [x0, x1) x [y0, y1)
 * from the blocks' (floored) variances: a block holding m of the part's
 * N pixels adds m n V / N^2, its n pixels being alike. */
static double part_variance(const sums *bs, const grid *g, int x0, int y0, int x1, int y1, int c)
{
    double v = 0.0, total = (double)(x1 - x0) * (double)(y1 - y0);
    for (int by = y0 / g->b; by * g->b < y1; by++)
        for (int bx = x0 / g->b; bx * g->b < x1; bx++) {
            int ox0 = bx * g->b > x0 ? bx * g->b : x0, oy0 = by * g->b > y0 ? by * g->b : y0;
            int ox1 = (bx + 1) * g->b < x1 ? (bx + 1) * g->b : x1;
            int oy1 = (by + 1) * g->b < y1 ? (by + 1) * g->b : y1;
            double m = (double)(ox1 - ox0) * (double)(oy1 - oy0);
            const sums *o = &bs[((size_t)by * (size_t)g->nx + (size_t)bx) * 3 + (size_t)c];
            v += m * block_pixels(g, bx, by) * o->v_ind;
        }
    return v / (total * total);
}

int mcbox_image_check(const mcbox_image_set *set, const mcbox_image_options *opt,
                      mcbox_image_result *r)
{
    memset(r, 0, sizeof *r);
    mcbox_image_options o = opt ? *opt : (mcbox_image_options){0};
    double alpha = o.alpha > 0.0 ? o.alpha : 0.01;
    if (!set || set->width < 1 || set->height < 1 || !set->truth || !(alpha < 0.5) ||
        o.block < 0 || o.n_regions < 0 || o.n_regions > MCBOX_IMAGE_MAX_REGIONS ||
        !(set->truth_error >= 0.0) || !(set->rel_precision >= 0.0)) {
        fail_input(r, "bad arguments");
        return -1;
    }
    job j = {set, set->n_renders, (size_t)set->width * (size_t)set->height * 3};
    if (j.k == 0 && (!set->mean || !set->second_moment || !(set->samples >= 2.0))) {
        fail_input(r, "%s", set->mean ? "a mean and second-moment pair needs at least 2 samples"
                                      : "no renders: the noise needs 2 or more independent renders");
        return -1;
    }
    if (j.k == 1 || j.k > 64 || j.k < 0) {
        fail_input(r, "%d render%s: the noise needs 2 to 64 independent renders (different seeds)",
                   j.k, j.k == 1 ? "" : "s");
        return -1;
    }
    for (int k = 0; k < j.k; k++)
        if (!set->renders || !set->renders[k]) {
            fail_input(r, "bad arguments");
            return -1;
        }
    if (validate(&j, r) != 0)
        return -1;
    mc_gsl_quiet();

    int side = set->width > set->height ? set->width : set->height;
    int b = o.block > 0 ? o.block : (side / 8 > 0 ? side / 8 : 1);
    r->block = b;
    r->blocks_x = (set->width + b - 1) / b;
    r->blocks_y = (set->height + b - 1) / b;
    size_t nb = (size_t)r->blocks_x * (size_t)r->blocks_y * 3;
    sums *bs = malloc(nb * sizeof *bs);
    double *det = malloc(nb * sizeof *det);
    r->z = malloc(nb * sizeof *r->z);
    if (!bs || !det || !r->z) {
        free(bs);
        free(det);
        mcbox_image_result_free(r);
        fail_input(r, "out of memory");
        return -1;
    }

    /* The inflation: block-mean variance over pixel-independent variance,
     * as a ratio of sums over every block, with (K - 1) degrees of freedom
     * per block behind it. */
    grid gr = {b, r->blocks_x, r->blocks_y, set->width, set->height};
    double sum_blk = 0.0, sum_ind = 0.0;
    for (int by = 0; by < r->blocks_y; by++)
        for (int bx = 0; bx < r->blocks_x; bx++)
            for (int c = 0; c < 3; c++) {
                int x0, y0, x1, y1;
                block_rect(&gr, bx, by, &x0, &y0, &x1, &y1);
                sums *s = &bs[((size_t)by * (size_t)r->blocks_x + (size_t)bx) * 3 + (size_t)c];
                *s = part_sums(&j, x0, y0, x1, y1, c);
                sum_blk += s->v_blk;
                sum_ind += s->v_ind;
            }
    double pixels_per_block = (double)b * (double)b;
    if (j.k >= 2) {
        r->inflation = sum_ind > 0.0 ? sum_blk / sum_ind : 1.0;
        /* Pixel variances rest on (K - 1) per pixel of the block; the
         * inflation, when it is used, on (K - 1) per block. */
        r->dof = r->inflation > 1.0 ? (double)(j.k - 1) * (double)(r->blocks_x * r->blocks_y)
                                    : (double)(j.k - 1) * pixels_per_block;
    } else {
        r->inflation = 1.0;
        r->dof = set->samples - 1.0;
        snprintf(r->note, sizeof r->note,
                 "from a mean and second-moment pair the pixels are taken as independent: "
                 "renders that splat light paths need 2 or more separate renders");
    }

    if (floor_variances(bs, &gr) != 0) {
        free(bs);
        free(det);
        mcbox_image_result_free(r);
        fail_input(r, "out of memory");
        return -1;
    }

    r->n_regions = o.n_regions;
    r->tests = 3 * (1 + o.n_regions) + (int)nb;
    r->alpha = alpha;
    r->per_test_alpha = alpha / r->tests;
    double z_crit = r->dof < 30.0 ? gsl_cdf_tdist_Qinv(0.5 * r->per_test_alpha, r->dof)
                                  : gsl_cdf_ugaussian_Qinv(0.5 * r->per_test_alpha);
    r->z_crit = z_crit;
    r->min_p = 1.0;

    for (int c = 0; c < 3; c++) {
        sums s = part_sums(&j, 0, 0, set->width, set->height, c);
        s.v_ind = part_variance(bs, &gr, 0, 0, set->width, set->height, c);
        r->image[c] = judge(&s, 0, 0, set->width, set->height, c, r->inflation, r->dof, z_crit);
        r->min_p = fmin(r->min_p, r->image[c].p);
    }
    for (int g = 0; g < o.n_regions; g++) {
        const mcbox_image_region *rg = &o.regions[g];
        int x0 = (int)floor(rg->x0 * set->width), x1 = (int)ceil(rg->x1 * set->width);
        int y0 = (int)floor(rg->y0 * set->height), y1 = (int)ceil(rg->y1 * set->height);
        x0 = x0 < 0 ? 0 : x0;
        y0 = y0 < 0 ? 0 : y0;
        x1 = x1 > set->width ? set->width : x1;
        y1 = y1 > set->height ? set->height : y1;
        if (x1 <= x0 || y1 <= y0) {
            free(bs);
            free(det);
            mcbox_image_result_free(r);
            fail_input(r, "region %d (%s) is empty", g + 1, rg->name ? rg->name : "unnamed");
            return -1;
        }
        r->region_names[g] = rg->name;
        for (int c = 0; c < 3; c++) {
            sums s = part_sums(&j, x0, y0, x1, y1, c);
            s.v_ind = part_variance(bs, &gr, x0, y0, x1, y1, c);
            r->regions[g][c] = judge(&s, x0, y0, x1, y1, c, r->inflation, r->dof, z_crit);
            r->min_p = fmin(r->min_p, r->regions[g][c].p);
        }
    }
    for (size_t i = 0; i < nb; i++) {
        size_t cell = i / 3;
        int bx = (int)(cell % (size_t)r->blocks_x), by = (int)(cell / (size_t)r->blocks_x);
        int x0, y0, x1, y1;
        block_rect(&gr, bx, by, &x0, &y0, &x1, &y1);
        mcbox_image_part p = judge(&bs[i], x0, y0, x1, y1, (int)(i % 3), r->inflation, r->dof, z_crit);
        r->z[i] = p.z;
        det[i] = p.truth > 0.0 ? p.detectable / p.truth : (double)INFINITY;
        r->min_p = fmin(r->min_p, p.p);
        keep_worst(r, &p);
    }
    qsort(det, nb, sizeof *det, cmp_double);
    r->block_detectable = det[nb / 2];
    free(det);
    free(bs);

    r->pass = r->min_p >= r->per_test_alpha;
    if (!r->pass) {
        const mcbox_image_part *w = &r->worst[0];
        for (int c = 0; c < 3; c++)
            if (r->image[c].p < w->p)
                w = &r->image[c];
        double rel = w->truth > 0.0 ? (w->mean - w->truth) / w->truth : 0.0;
        snprintf(r->message, sizeof r->message,
                 "pixels [%d, %d) x [%d, %d) %s: mean %.6g against the truth %.6g (%+.2f%% +- "
                 "%.2f%%), z = %.2f, p = %.3g below %.3g = %.3g / %d tests",
                 w->x0, w->x1, w->y0, w->y1, channel_name[w->channel], w->mean, w->truth,
                 100.0 * rel, w->truth > 0.0 ? 100.0 * w->se / w->truth : 0.0, w->z, w->p,
                 r->per_test_alpha, alpha, r->tests);
    }
    return 0;
}

void mcbox_image_result_free(mcbox_image_result *r)
{
    if (!r)
        return;
    free(r->z);
    r->z = NULL;
}
