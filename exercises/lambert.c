/* exercises/lambert.c - chapter 10, "The Cornell box" (#ch-cornell), with
 * chapter 7's orthonormal bases (#ch-onb): a Lambertian bounce about any
 * surface normal.
 *
 * WRITE  lambert_sample(n, u1, u2): a direction of density cos(theta)/pi
 *        about the unit surface normal n (theta measured from n), from two
 *        uniforms in [0, 1) (any map with that law passes: any cosine
 *        warp, any orthonormal basis about n);
 *        lambert_pdf(n, w): its density at the unit direction w PER UNIT
 *        SOLID ANGLE, 0 below the surface.
 * HINT   Sample about +z (exercise cosine, or smp_cosine_hemisphere_sample
 *        of samplers/hemisphere.h), then carry the direction to n with an
 *        orthonormal basis: onb o = onb_from_w(n); onb_to_world(&o, a)
 *        (mc/onb.h). The density needs cos theta = n . w, not w.z.
 * JUDGED by five statistical tests and two exact ones:
 *        1. the public check (check/check.h) on the catalog's "cosine-pdf"
 *           row for the normal (0.36, -0.48, 0.8), whose chart covers the
 *           whole sphere in (cos theta, phi) about that normal, 5 x 10^5
 *           samples from seed 10101: your directions against YOUR
 *           lambert_pdf (chi-square, integral within 1e-6 of 1); the same
 *           directions against the law asked for, max(0, n . w) / pi (the
 *           chi-square again, and your lambert_pdf at every sample within
 *           1e-6, relative, of it); and, exactly, your lambert_pdf against
 *           that law at the centres of 64 x 128 cells of (cos theta, phi)
 *           about +z, relative 1e-6;
 *        2. the same three on MCBOX_SPHERE (chart about +z) for the normal
 *           (0.48, 0.6, -0.64): seed 10102;
 *        3. a small rendering: a white Lambertian sphere (albedo 1) under a
 *           sky of radiance L(w) = 1 + a . w, seen along -z in 32 x 32
 *           pixels, 128 samples per pixel (streams of seed 10103), each
 *           sample L(w) (n . w / pi) / lambert_pdf(n, w). Exactly, a pixel
 *           whose normal is n has the value 1 + (2/3) a . n. The image is
 *           compared region by region (8 x 8 blocks of 4 x 4 pixels): the
 *           sum of the squared z-scores of the blocks against chi-square.
 *
 * Run:   make exercise NAME=lambert
 */
#include <math.h>

#include "exercises/check_exercise.h"
#include "mc/onb.h"

#ifndef EX_FIXTURE
/* ===== YOUR CODE BEGINS ================================================ */
/* BEGIN SNIPPET your_code */

/* A cosine-weighted direction about the unit normal n. */
static vec3 lambert_sample(vec3 n, double u1, double u2)
{
    (void)n, (void)u1, (void)u2;
    return vec3_make(0.0, 0.0, 1.0); /* TODO */
}

/* The density of lambert_sample() per unit solid angle at the unit w. */
static double lambert_pdf(vec3 n, vec3 w)
{
    (void)n, (void)w;
    return 0.0; /* TODO */
}

/* END SNIPPET your_code */
/* ===== YOUR CODE ENDS ================================================== */
#else
#include "exercises/fixtures/lambert.h" /* the suite's reference and slips */
#endif

/* --- the judge: nothing to change below ----------------------------------- */

static void check_sample(const double *u, mcbox_sample *out, void *ctx)
{
    ex_put3(out->x, lambert_sample(*(const vec3 *)ctx, u[0], u[1]));
}

static double check_pdf(const double *x, void *ctx)
{
    return lambert_pdf(*(const vec3 *)ctx, ex_vec3(x));
}

/* The rendering test: returns the sum of the blocks' squared z-scores and
 * their number in *blocks. */
enum { RES = 32, BLOCK = 4, SPP = 128 };
static double render_sky(uint64_t seed, int *blocks)
{
    const vec3 a = vec3_make(0.3, -0.5, 0.6); /* |a| < 1: L > 0 */
    double sum[RES / BLOCK][RES / BLOCK] = {{0}}, var[RES / BLOCK][RES / BLOCK] = {{0}},
           exact[RES / BLOCK][RES / BLOCK] = {{0}};
    int px[RES / BLOCK][RES / BLOCK] = {{0}};
    for (int i = 0; i < RES; i++)
        for (int k = 0; k < RES; k++) {
            double x = (i + 0.5) / RES * 2.0 - 1.0, y = (k + 0.5) / RES * 2.0 - 1.0;
            if (x * x + y * y >= 1.0)
                continue;
            vec3 n = vec3_make(x, y, sqrt(1.0 - x * x - y * y));
            mc_rng rng = mc_rng_derive(seed, (uint64_t)(i * RES + k));
            mc_welford w = mc_welford_init();
            for (int s = 0; s < SPP; s++) {
                vec3 d = lambert_sample(n, mc_rng_uniform(&rng), mc_rng_uniform(&rng));
                double cos_n = fmax(0.0, vec3_dot(n, d)), p = lambert_pdf(n, d);
                /* A direction the pdf calls impossible adds 0, as in an
                 * estimator that skips it; the bias then shows. */
                mc_welford_add(&w, p > 0.0 ? (1.0 + vec3_dot(a, d)) * cos_n * MC_INV_PI / p : 0.0);
            }
            int bi = i / BLOCK, bk = k / BLOCK;
            sum[bi][bk] += w.mean;
            var[bi][bk] += mc_welford_variance(&w) / SPP;
            exact[bi][bk] += 1.0 + 2.0 / 3.0 * vec3_dot(a, n);
            px[bi][bk]++;
        }
    double chi2 = 0.0;
    *blocks = 0;
    for (int bi = 0; bi < RES / BLOCK; bi++)
        for (int bk = 0; bk < RES / BLOCK; bk++)
            if (px[bi][bk] > 0) {
                /* Means of px pixels: the block mean and its variance. */
                double m = px[bi][bk];
                double z = (sum[bi][bk] - exact[bi][bk]) / m / (sqrt(var[bi][bk]) / m);
                chi2 += z * z;
                ++*blocks;
            }
    return chi2;
}

/* The law the exercise asks for: max(0, n . w) / pi; ctx points to n. */
static double lambert_law(const double *x, void *ctx)
{
    double c = vec3_dot(*(const vec3 *)ctx, ex_vec3(x));
    return c > 0.0 ? c / MC_PI : 0.0;
}

static void judge(ex_judge *j)
{
    static const vec3 tilted = {0.36, -0.48, 0.8}, down = {0.48, 0.6, -0.64};
    static const ex_law tilted_law = {"the cosine law about the normal", lambert_law,
                                      (void *)&tilted};
    static const ex_law down_law = {"the cosine law about the normal", lambert_law, (void *)&down};
    mcbox_sampler s = mcbox_sampler_init(MCBOX_CATALOG);
    s.domain.row = "cosine-pdf", s.domain.params = "normal=0.36,-0.48,0.8";
    s.sample = check_sample, s.pdf = check_pdf, s.ctx = (void *)&tilted;
    ex_check_sampler_law(j, "normal (0.36,-0.48,0.8)", &s, &tilted_law, 10101, 500000);
    mcbox_sampler t = mcbox_sampler_init(MCBOX_SPHERE);
    t.sample = check_sample, t.pdf = check_pdf, t.ctx = (void *)&down;
    ex_check_sampler_law(j, "normal (0.48,0.6,-0.64)", &t, &down_law, 10102, 500000);
    int blocks;
    uint64_t seed = ex_seed(j, 10103);
    double chi2 = render_sky(seed, &blocks);
    ex_check_z_family(j, "render", "sky-lit sphere, by region", chi2, blocks, seed);
}

const ex_exercise ex_this = {"lambert", "10 (#ch-cornell)", EX_VARIANT, judge, EX_KIND, EX_INTENDED};
