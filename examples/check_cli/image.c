/* examples/check_cli/image.c - the image door of mcbox-check: a renderer's
 * images against the truth (mcbox/image.h), the truth being a conformance
 * scene's closed form (conform/truth.h), an exact image, or a noisy
 * reference with its noise.
 *
 *   mcbox-check --image a.pfm --image b.pfm --scene quad-wall
 *   mcbox-check --image a.png --image b.png --transfer book --scene quad-wall
 *   mcbox-check --image a.exr --image b.exr --truth exact.pfm
 *   mcbox-check --image-mean m.pfm --image-second s.pfm --spp 256 --scene sphere-wall
 *   mcbox-check --image a.pfm --image b.pfm --reference ref.pfm --reference-noise se.pfm
 *   mcbox-check --image a.pfm --image b.pfm --reference ref1.pfm --reference ref2.pfm
 */
#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check/image.h"
#include "imageio/image_io.h"
#include "conform/conform.h"
#include "conform/judge.h"
#include "conform/truth.h"
#include "examples/common/cli.h"

/* The relative rounding of a stored float: half an ulp of a 32-bit float
 * (PFM); an EXR may hold halves, whose half ulp is 2^-11. */
#define F32_ROUNDING 0x1p-24
#define HALF_ROUNDING 0x1p-11

typedef struct image_args {
    const char *renders[64];
    int n_renders;
    const char *references[64];
    int n_references;
    const char *mean, *second, *scene, *truth, *noise, *transfer, *junit, *name, *picture;
    double spp, truth_error;
    bool json;
    mcbox_image_options o;
} image_args;

static double number(const char *opt, const char *v, double lo, double hi)
{
    double x;
    if (!app_parse_double(v, &x) || !(x >= lo && x <= hi))
        cli_fail("%s %s: expected a number in [%g, %g]", opt, v, lo, hi);
    return x;
}

static image_args parse(int argc, char **argv)
{
    image_args a = {.name = "render"};
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (strcmp(o, "--json") == 0) {
            a.json = true;
            continue;
        }
        if (i + 1 >= argc)
            cli_fail("%s: needs a value, or is not an option of the image door (--help)", o);
        const char *v = argv[++i];
        if (strcmp(o, "--image") == 0) {
            if (a.n_renders == 64)
                cli_fail("--image: at most 64 renders");
            a.renders[a.n_renders++] = v;
        } else if (strcmp(o, "--image-mean") == 0)
            a.mean = v;
        else if (strcmp(o, "--image-second") == 0)
            a.second = v;
        else if (strcmp(o, "--spp") == 0)
            a.spp = number(o, v, 2.0, 1e15);
        else if (strcmp(o, "--scene") == 0) {
            if (!cf_scene_find(v))
                cli_fail("--scene %s: not a conformance scene (mcbox-scene list)", v);
            a.scene = v;
        } else if (strcmp(o, "--truth") == 0)
            a.truth = v;
        else if (strcmp(o, "--truth-error") == 0)
            a.truth_error = number(o, v, 0.0, 1.0);
        else if (strcmp(o, "--reference") == 0) {
            if (a.n_references == 64)
                cli_fail("--reference: at most 64 references");
            a.references[a.n_references++] = v;
        }
        else if (strcmp(o, "--reference-noise") == 0)
            a.noise = v;
        else if (strcmp(o, "--transfer") == 0) {
            img_transfer t;
            if (img_transfer_parse(v, &t) != 0)
                cli_fail("--transfer %s: one of linear, gamma2, gamma2.2, srgb, book", v);
            a.transfer = v;
        } else if (strcmp(o, "--alpha") == 0)
            a.o.alpha = number(o, v, 1e-12, 0.25);
        else if (strcmp(o, "--block") == 0)
            a.o.block = (int)number(o, v, 1.0, 65536.0);
        else if (strcmp(o, "--picture") == 0)
            a.picture = v;
        else if (strcmp(o, "--junit") == 0)
            a.junit = v;
        else if (strcmp(o, "--name") == 0)
            a.name = v;
        else
            cli_fail("%s: not an option of the image door (--help)", o);
    }
    int truths = (a.scene != NULL) + (a.truth != NULL) + (a.n_references > 0);
    if (truths != 1)
        cli_fail("the image door needs exactly one of --scene, --truth and --reference");
    if (a.noise && a.n_references != 1)
        cli_fail("--reference-noise goes with one --reference (two or more measure their own noise)");
    if (a.n_references == 1 && !a.noise)
        cli_fail("one --reference needs --reference-noise FILE (its standard error per pixel), "
                 "or give 2 or more independent references");
    bool moments = a.mean || a.second;
    if (moments && (a.n_renders || !a.mean || !a.second || a.spp < 2.0))
        cli_fail("a moment pair is --image-mean FILE --image-second FILE --spp N (N >= 2), "
                 "without --image");
    if (!moments && a.n_renders < 2)
        cli_fail("%d render%s: the noise is measured from 2 or more independent renders "
                 "(different seeds), or from --image-mean and --image-second",
                 a.n_renders, a.n_renders == 1 ? "" : "s");
    return a;
}

/* The pictures, read under the transfer; the first one's size is the
 * size every other must have. */
static void read_picture(const char *what, const char *path, const image_args *a,
                         img_picture *p, int width, int height)
{
    img_transfer t = IMG_TRANSFER_LINEAR;
    if (a->transfer)
        img_transfer_parse(a->transfer, &t);
    char why[256];
    if (img_picture_read(path, t, p, why, sizeof why) != 0)
        cli_fail("%s %s: %s", what, path, why);
    if (p->bits && !a->transfer)
        cli_fail("%s %s is a %d-bit %s: say how its values were encoded with --transfer "
                 "(book for the write_color of Shirley's books)", what, path, p->bits, p->format);
    if (width && (p->width != width || p->height != height))
        cli_fail("%s %s is %dx%d, the first render %dx%d", what, path, p->width, p->height, width,
                 height);
}

/* The three channels of a grey value per pixel. */
static double *grey_to_rgb(const double *g, size_t n)
{
    double *rgb = malloc(n * 3 * sizeof *rgb);
    if (!rgb)
        cli_fail("out of memory");
    for (size_t i = 0; i < n; i++)
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = g[i];
    return rgb;
}

/* Two or more independent float references: their mean is the truth, and
 * its standard error per value their spread over sqrt(K) (K - 1 degrees
 * of freedom per pixel; the image check pools them over each block). */
static double *reference_mean(const image_args *a, int w, int h, double **se)
{
    size_t n = (size_t)w * (size_t)h * 3;
    double *sum = calloc(n, sizeof *sum), *sq = calloc(n, sizeof *sq);
    if (!sum || !sq)
        cli_fail("out of memory");
    image_args lin = *a;
    lin.transfer = NULL;
    int k = a->n_references;
    for (int r = 0; r < k; r++) {
        img_picture p;
        char what[32];
        snprintf(what, sizeof what, "reference %d", r + 1);
        read_picture(what, a->references[r], &lin, &p, w, h);
        if (p.bits)
            cli_fail("reference %d (%s) is a %d-bit file: references must be float images",
                     r + 1, a->references[r], p.bits);
        for (size_t i = 0; i < n; i++)
            sum[i] += p.value[i], sq[i] += p.value[i] * p.value[i];
        img_picture_free(&p);
    }
    for (size_t i = 0; i < n; i++) {
        double m = sum[i] / k, var = (sq[i] - k * m * m) / (k - 1);
        sum[i] = m;
        sq[i] = var > 0.0 ? sqrt(var / k) : 0.0;
    }
    *se = sq;
    return sum;
}

int cli_image_main(int argc, char **argv)
{
    image_args a = parse(argc, argv);
    double t0 = cli_now();
    int k = a.n_renders;
    img_picture pics[64] = {{0}}, mean = {0}, second = {0}, truth_pic = {0}, noise = {0};
    const double *values[64], *lo[64], *hi[64];
    bool quantized = false;
    double rel = 0.0;
    int w = 0, h = 0;
    for (int i = 0; i < k; i++) {
        char what[32];
        snprintf(what, sizeof what, "render %d", i + 1);
        read_picture(what, a.renders[i], &a, &pics[i], w, h);
        w = pics[i].width, h = pics[i].height;
        values[i] = pics[i].value, lo[i] = pics[i].lo, hi[i] = pics[i].hi;
        quantized |= pics[i].lo != NULL;
        double r = pics[i].bits ? 0.0 : strcmp(pics[i].format, "exr") == 0 ? HALF_ROUNDING
                                                                          : F32_ROUNDING;
        rel = r > rel ? r : rel;
    }
    if (!k) {
        read_picture("--image-mean", a.mean, &a, &mean, 0, 0);
        w = mean.width, h = mean.height;
        read_picture("--image-second", a.second, &a, &second, w, h);
        if (mean.bits || second.bits)
            cli_fail("a moment pair must be float images (PFM or EXR)");
        rel = strcmp(mean.format, "exr") == 0 ? HALF_ROUNDING : F32_ROUNDING;
    }
    size_t n = (size_t)w * (size_t)h;
    mcbox_image_set set = {.width = w, .height = h, .n_renders = k, .renders = values,
                           .rel_precision = rel, .mean = mean.value,
                           .second_moment = second.value, .samples = a.spp};
    if (quantized) {
        set.lo = lo;
        set.hi = hi;
    }
    double *truth = NULL, *truth_se = NULL;
    mcbox_image_region regions[CF_MAX_REGIONS];
    const cf_scene *scene = a.scene ? cf_scene_find(a.scene) : NULL;
    if (scene) {
        double *g = malloc(n * sizeof *g), err = 0.0;
        if (!g || cf_truth_image(scene, w, h, g, &err) != 0)
            cli_fail("out of memory");
        truth = grey_to_rgb(g, n);
        free(g);
        set.truth_error = err + CF_DEPTH_PROMISE;
        a.o.regions = regions;
        a.o.n_regions = cf_image_regions(scene, regions);
    } else if (a.truth || a.noise) {
        image_args lin = a;
        lin.transfer = NULL;
        read_picture(a.truth ? "--truth" : "--reference", a.truth ? a.truth : a.references[0],
                     &lin, &truth_pic, w, h);
        /* The truth file's own rounding, at its largest value. */
        double top = 0.0;
        for (size_t i = 0; i < 3 * n; i++)
            top = truth_pic.value[i] > top ? truth_pic.value[i] : top;
        double ulp = strcmp(truth_pic.format, "exr") == 0 ? HALF_ROUNDING : F32_ROUNDING;
        set.truth_error = a.truth_error + top * ulp;
        if (a.noise) {
            read_picture("--reference-noise", a.noise, &lin, &noise, w, h);
            set.truth_se = noise.value;
        }
    } else {
        truth = reference_mean(&a, w, h, &truth_se);
        set.truth_se = truth_se;
    }
    set.truth = truth ? truth : truth_pic.value;

    mcbox_image_result r;
    if (mcbox_image_check(&set, &a.o, &r) != 0)
        cli_fail("%s", r.message);
    char refs[64];
    snprintf(refs, sizeof refs, "the mean of %d references", a.n_references);
    cli_image_info info = {a.name,
                           scene       ? scene->name
                           : a.truth   ? a.truth
                           : a.noise   ? a.references[0]
                                       : refs,
                           k, w, h, set.truth_error, cli_now() - t0};
    cli_image_report(&info, &r, a.json, a.junit, a.picture);
    int status = r.pass ? 0 : 1;
    mcbox_image_result_free(&r);
    for (int i = 0; i < k; i++)
        img_picture_free(&pics[i]);
    img_picture_free(&mean);
    img_picture_free(&second);
    img_picture_free(&truth_pic);
    img_picture_free(&noise);
    free(truth);
    free(truth_se);
    return status;
}
