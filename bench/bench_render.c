/* bench/bench_render.c - throughput of the Cornell box renderer.
 *
 * Renders the book's final scene (chapter 10 of "Ray Tracing: The Rest of
 * Your Life") at 600 x 600, 100 samples per pixel, max depth 50, with the
 * book's mixture strategy, once for each thread count from 1 up to
 * --max-threads T (default 2), and prints wall time, paths/s and ray
 * segments/s for each, the speed-up over the book's own program (68.3 s
 * for this render on one thread of the machine it was measured on, or its
 * time here with --book-program; see below), the dropped non-finite
 * samples and the mean linear RGB of the image.
 *
 * Then, for each converged reference given, an error table at the
 * reference's size. Book references come from --reference PREFIX or the
 * environment variable MC_REF_BOOK, lambert ones from --lambert-reference
 * PREFIX or MC_REF_LAMBERT; each variable may hold several prefixes
 * separated by spaces (`make bench` sets them to the images `make
 * reference` caches, 600 x 600 first, then the quicker 300 x 300). For each
 * strategy the table gives the seconds of a render with --max-threads
 * threads (the median of three, taken in rounds over all the strategies,
 * so that a slow minute of the machine does not fall on one strategy), its
 * pixel mean squared error against the reference, and for the book scene
 * how many times the book's program it is at equal error,
 * (BOOK_ERR_SECONDS x BOOK_MSE) / (seconds x MSE): the book's program
 * averages independent samples (drand48 for every one), so its time to
 * reach an error scales exactly as 1 / MSE, and this is how many times
 * longer than the row it would take to reach the row's error. The book's
 * program does not render lambert, so there the table gives the
 * efficiency 1 / (MSE x seconds) and its ratio to the mixture's. Last,
 * the share of the squared error that sits in the worst 1% of the pixels.
 * Under the book scene's table one more line: the same ratio at the book's
 * own error (equal_error_measured).
 *
 * The book's program is not part of mcbox: its figures are constants
 * measured once on another machine, unless --book-program PATH (or
 * MC_BOOK_PROGRAM, which `make bench` sets when `make book-program` has
 * built it) names the book's own code built for this render
 * (tools/book_program.sh). Then it is run here, three times before
 * anything else, and the median of its wall times replaces the constant
 * seconds in every x_book figure: two programs timed on one machine,
 * since their ratio, not either time, is what moves with the machine.
 *
 * The reference is two independent renders, PREFIX-a.pfm and PREFIX-b.pfm
 * (different seeds). Their mean is the reference; its own noise, per
 * pixel and channel, is a quarter of MSE(a, b) (each has variance
 * MSE(a, b) / 2, the mean half of that), and it is subtracted: the MSE
 * against a noisy reference is the true MSE plus the reference's noise.
 *
 * Build: make bench (or make all); run: build/bench/bench_render
 * A quicker run: MC_BENCH_QUICK=1 (or --quick) renders 10 samples per
 * pixel instead of 100; --spp N and --max-threads T override.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "render/bdpt.h"
#include "render/render.h"
#include "render/scenes.h"

/* The book's program (its final chapter's code at v1.123.0, 600 x 600,
 * 100 spp, one thread of the project's 2-core machine of the day), built
 * and run once for the error table: 68.3 s, and a pixel mean squared error
 * of 1.01e-3 (linear RGB) against a converged reference (two independent
 * 1024-spp `mis` renders of the book scene, their own noise subtracted).
 * The time is the default of the yardstick; --book-program measures it
 * here. The error is the estimator's, not the machine's (mcbox's mixture,
 * the same estimator, has 1.0012e-3), and stays a constant. */
#define BOOK_ERR_SECONDS 68.3
#define BOOK_MSE 1.01e-3

/* Where the x_book figures' time of the book's program comes from. */
typedef struct book_time {
    double seconds; /* 600 x 600, 100 spp, one thread */
    bool measured;  /* timed here by --book-program, not the constant */
} book_time;

/* The rows of the error table, in order: a strategy (any name of
 * rt_bdpt_strategy_parse), "+rr" for Russian roulette, "+stratified" or
 * "+sobol" for that sampler instead of the strategy's default
 * (rt_render_sampler_kind: what a render gets without --sampler), and the
 * share of the --spp samples per pixel it takes (the slow ones fewer, to
 * keep the bench short; for independent samples the measure does not
 * depend on the sample count, and bench_convergence shows how far the
 * stratified ones depart from that). */
typedef struct error_row {
    const char *name;
    double spp_share;
} error_row;
static const error_row error_rows[] = {
    {"uniform", 1.0},    {"cosine", 1.0},     {"light", 1.0},  {"mixture", 1.0},
    {"mixture+rr", 1.0}, {"mis", 1.0},        {"mis+rr", 1.0}, {"lighttrace", 0.5},
    {"bdpt", 0.25},      {"bdpt+rr", 0.5},    {"bdpt+rr+stratified", 0.5},
};

static const char *const prog = "bench_render";

/* Reads a PFM; NULL (after a line on stderr) when it cannot. */
static rt_image *read_pfm(const char *path)
{
    FILE *f = fopen(path, "rb");
    const char *why = "cannot open";
    rt_image *img = f ? rt_image_read_pfm(f, &why) : NULL;
    if (f)
        fclose(f);
    if (!img)
        fprintf(stderr, "%s: %s: %s\n", prog, path, why);
    return img;
}

/* The reference PREFIX-a.pfm and PREFIX-b.pfm as their mean; *noise
 * receives the mean's own mean squared error, MSE(a, b) / 4. NULL when
 * either cannot be read, is not square or their sizes differ. */
/* BEGIN SNIPPET reference_noise */
static rt_image *load_reference(const char *prefix, double *noise)
{
    char path[4096];
    snprintf(path, sizeof path, "%s-a.pfm", prefix);
    rt_image *a = read_pfm(path);
    snprintf(path, sizeof path, "%s-b.pfm", prefix);
    rt_image *b = a ? read_pfm(path) : NULL;
    rt_image *ref = NULL;
    int width = a ? a->width : 0;
    if (a && b && a->height == width && a->height == width && b->width == width &&
        b->height == width && (ref = rt_image_create(width, width))) {
        *noise = 0.25 * rt_image_mse(a, b);
        for (size_t i = 0; i < (size_t)width * (size_t)width; i++) {
            rt_pixel_add(&ref->px[i], rt_image_get(a, (int)(i % (size_t)width), (int)(i / (size_t)width)));
            rt_pixel_add(&ref->px[i], rt_image_get(b, (int)(i % (size_t)width), (int)(i / (size_t)width)));
        }
    } else if (a && b) {
        fprintf(stderr, "%s: the reference %s-{a,b}.pfm: two square images of one size needed\n",
                prog, prefix);
    }
    rt_image_destroy(a);
    rt_image_destroy(b);
    return ref;
}
/* END SNIPPET reference_noise */

static int cmp_desc(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a < b) - (a > b);
}

/* The share of the squared error (summed over the channels) in the worst
 * 1% of the pixels, against the (noisy) reference as it is. */
/* BEGIN SNIPPET worst_share */
static double worst_share(const rt_image *img, const rt_image *ref)
{
    size_t n = (size_t)img->width * (size_t)img->height, top = n / 100 > 0 ? n / 100 : 1;
    double *e = malloc(n * sizeof *e), all = 0.0, worst = 0.0;
    if (!e)
        return (double)NAN;
    for (size_t i = 0; i < n; i++) {
        int x = (int)(i % (size_t)img->width), y = (int)(i / (size_t)img->width);
        vec3 d = vec3_sub(rt_image_get(img, x, y), rt_image_get(ref, x, y));
        all += e[i] = vec3_dot(d, d);
    }
    qsort(e, n, sizeof *e, cmp_desc);
    for (size_t i = 0; i < top; i++)
        worst += e[i];
    free(e);
    return worst / all;
}
/* END SNIPPET worst_share */

/* The renders of one error table, in rounds: every strategy once per
 * round, NROUNDS rounds, each time's median kept. */
#define NROUNDS 3
#define NROWS (sizeof error_rows / sizeof error_rows[0])

/* The render job of the row named `row` (error_rows' syntax) at width x
 * width, spp samples per pixel; false for a strategy the renderer does not
 * know. */
static bool row_job(const char *row, const rt_scene *scene, rt_camera_params cp, int width,
                    uint64_t spp, uint64_t seed, int threads, rt_render_job *job)
{
    *job = rt_render_job_default(scene, rt_camera_make(cp, width, width));
    job->spp = spp;
    job->seed = seed;
    job->threads = threads;
    char name[32];
    snprintf(name, sizeof name, "%s", row);
    job->path.russian_roulette = strstr(name, "+rr") != NULL;
    job->sampler = strstr(name, "+sobol")        ? RT_SAMPLER_SOBOL
                   : strstr(name, "+stratified") ? RT_SAMPLER_STRATIFIED
                                                 : RT_SAMPLER_DEFAULT;
    name[strcspn(name, "+")] = '\0';
    return rt_bdpt_strategy_parse(name, &job->path);
}

/* Renders job into img: *seconds its time, *mse its MSE against ref less
 * the reference's noise. False (after a line on stderr) when it fails. */
static bool render_error(const rt_render_job *job, const rt_image *ref, double noise, rt_image *img,
                         double *seconds, double *mse)
{
    rt_render_stats st;
    if (rt_render(job, img, &st) != 0) {
        fprintf(stderr, "%s: render failed\n", prog);
        return false;
    }
    *seconds = st.seconds;
    *mse = rt_image_mse(img, ref) - noise;
    return true;
}

/* A fixed seed gives the same image at any thread count, so a render
 * repeated gives the same MSE: false (after a line on stderr) when it did
 * not. */
static bool same_image(const char *what, double first, double again)
{
    if (again == first)
        return true;
    fprintf(stderr, "%s: %s: the same render gave another image (MSE %.17g, then %.17g)\n", prog,
            what, first, again);
    return false;
}

/* Renders every row of error_rows NROUNDS times into img and fills, per
 * row, the median seconds, the MSE against ref less its noise, the worst
 * 1% share and the samples per pixel (0 for a row the renderer does not
 * know). The image of a row is the same bits every round (a fixed seed,
 * any thread count), which is checked: the MSE of a later round must equal
 * the first's. False when a render fails or an MSE differs. */
static bool error_rows_measure(const rt_scene *scene, rt_camera_params cp, uint64_t spp,
                               uint64_t seed, int threads, const rt_image *ref, double noise,
                               rt_image *img, double seconds[NROWS], double mse[NROWS],
                               double worst[NROWS], uint64_t used_spp[NROWS])
{
    double times[NROWS][NROUNDS];
    for (int round = 0; round < NROUNDS; round++) {
        for (size_t i = 0; i < NROWS; i++) {
            rt_render_job job;
            uint64_t n = (uint64_t)((double)spp * error_rows[i].spp_share);
            used_spp[i] = 0;
            if (!row_job(error_rows[i].name, scene, cp, img->width, n > 0 ? n : 1, seed, threads,
                         &job))
                continue;
            double e;
            if (!render_error(&job, ref, noise, img, &times[i][round], &e))
                return false;
            used_spp[i] = job.spp;
            if (round == 0) {
                mse[i] = e;
                worst[i] = worst_share(img, ref);
            } else if (!same_image(error_rows[i].name, mse[i], e)) {
                return false;
            }
        }
    }
    for (size_t i = 0; i < NROWS; i++)
        seconds[i] = app_median(times[i], NROUNDS);
    return true;
}

/* The ratio at the book's own error. x_book_equal_err compares the two at
 * the row's error, far below the book's; mcbox's error cannot be carried
 * up to the book's by the same 1 / N, since a render of a few samples per
 * pixel does worse than that law: a Sobol set of one or two points per
 * pixel has little or none of the stratification across a pixel's samples
 * that fifty have, and part of a render's time does not grow with the
 * sample count (the first pass's edge test is in it). So the row `row`
 * (the default, bdpt+rr) is rendered at 1, 2, 3, ... samples per pixel
 * until its MSE is at most the book's, and that render is timed (median of
 * NROUNDS): the book's seconds over those is how many times faster it
 * gives an image as good as the book's. At most MEASURED_MAX_SPP samples.
 * False when a render fails. */
#define MEASURED_MAX_SPP 64
static bool equal_error_measured(const char *row, const rt_scene *scene, rt_camera_params cp,
                                 uint64_t seed, int threads, const rt_image *ref, double noise,
                                 rt_image *img, double book_s)
{
    for (uint64_t n = 1; n <= MEASURED_MAX_SPP; n++) {
        double t[NROUNDS], e = 0.0;
        rt_render_job job;
        if (!row_job(row, scene, cp, img->width, n, seed, threads, &job))
            return false;
        for (int round = 0; round < NROUNDS; round++) {
            double er;
            if (!render_error(&job, ref, noise, img, &t[round], &er) ||
                (round > 0 && !same_image(row, e, er)))
                return false;
            e = er;
            if (e > BOOK_MSE)
                break; /* not yet the book's error: no need of the other rounds */
        }
        if (e > BOOK_MSE)
            continue;
        double sec = app_median(t, NROUNDS);
        printf("%s at the book's error, measured: %llu spp, MSE %.4e, %.2f s (median of %d): "
               "%.1fx the book's program\n",
               row, (unsigned long long)n, e, sec, NROUNDS, book_s / sec);
        return true;
    }
    printf("%s: the book's error not reached within %d samples per pixel\n", row, MEASURED_MAX_SPP);
    return true;
}

/* The book's program's time: the median of NROUNDS runs of path, or the
 * constant BOOK_ERR_SECONDS when path is NULL or empty. False when a run
 * fails. */
static bool book_time_get(const char *path, book_time *bt)
{
    *bt = (book_time){BOOK_ERR_SECONDS, false};
    if (!path || !*path)
        return true;
    double t = app_time_program(prog, "the book's program", path, NROUNDS);
    if (isnan(t))
        return false;
    *bt = (book_time){t, true};
    return true;
}

/* The error table of scene "book" or "lambert" (see the top of the file)
 * at the size of the reference PREFIX-{a,b}.pfm. The book's time is for
 * 600 x 600 pixels; for another size it is scaled by the pixel count (its
 * cost is per path), while the pixel MSE at a given spp hardly depends on
 * the pixel size (a pixel's mean is over spp samples either way). False
 * when the reference cannot be read or a render fails. */
static bool error_table(const char *scene_name, uint64_t spp, uint64_t seed, int threads,
                        const char *prefix, book_time bt)
{
    double noise = 0.0;
    rt_camera_params cp;
    rt_scene *scene = rt_scene_named(scene_name, &cp);
    rt_image *ref = scene ? load_reference(prefix, &noise) : NULL;
    int width = ref ? ref->width : 1;
    rt_image *img = rt_image_create(width, width);
    double seconds[NROWS], mse[NROWS], worst[NROWS];
    uint64_t used_spp[NROWS];
    bool ok = scene && ref && img &&
              error_rows_measure(scene, cp, spp, seed, threads, ref, noise, img, seconds, mse, worst,
                                 used_spp);
    bool book = strcmp(scene_name, "book") == 0;
    double book_s = bt.seconds * (double)width * (double)width / (600.0 * 600.0);
    if (ok && book) {
        printf("\nerror at %dx%d against %s-{a,b}.pfm (their noise, %.3e, subtracted), %d threads, "
               "median of %d rounds; the book's program: %.1f s for 600x600 (%s; %.2f s for "
               "%dx%d), MSE %.3g\n",
               width, width, prefix, noise, threads, NROUNDS, bt.seconds,
               bt.measured ? "timed here" : "a constant from another machine", book_s, width, width,
               BOOK_MSE);
        printf("%-18s %6s %9s %12s %16s %13s\n", "strategy", "spp", "seconds", "MSE",
               "x_book_equal_err", "worst1%_share");
    } else if (ok) {
        printf("\nerror of %s at %dx%d against %s-{a,b}.pfm (their noise, %.3e, subtracted), %d "
               "threads, median of %d rounds; efficiency = 1 / (MSE x seconds), x_mixture = its "
               "ratio to mixture's\n",
               scene_name, width, width, prefix, noise, threads, NROUNDS);
        printf("%-18s %6s %9s %12s %11s %10s %13s\n", "strategy", "spp", "seconds", "MSE",
               "efficiency", "x_mixture", "worst1%_share");
    }
    double mixture_eff = 0.0;
    for (size_t i = 0; ok && i < NROWS; i++)
        if (strcmp(error_rows[i].name, "mixture") == 0)
            mixture_eff = 1.0 / (mse[i] * seconds[i]);
    for (size_t i = 0; ok && i < NROWS; i++) {
        if (used_spp[i] == 0)
            continue;
        double eff = 1.0 / (mse[i] * seconds[i]);
        if (book)
            printf("%-18s %6llu %9.2f %12.4e %15.1fx %12.1f%%\n", error_rows[i].name,
                   (unsigned long long)used_spp[i], seconds[i], mse[i], book_s * BOOK_MSE * eff,
                   100.0 * worst[i]);
        else
            printf("%-18s %6llu %9.2f %12.4e %11.4g %9.2fx %12.1f%%\n", error_rows[i].name,
                   (unsigned long long)used_spp[i], seconds[i], mse[i], eff, eff / mixture_eff,
                   100.0 * worst[i]);
    }
    if (ok && book)
        ok = equal_error_measured("bdpt+rr", scene, cp, seed, threads, ref, noise, img, book_s);
    fflush(stdout);
    rt_image_destroy(ref);
    rt_image_destroy(img);
    rt_scene_destroy(scene);
    return ok;
}

/* The error tables of scene_name for every prefix in the space-separated
 * list; false when any fails. */
static bool error_tables(const char *scene_name, uint64_t spp, uint64_t seed, int threads,
                         const char *prefixes, book_time bt)
{
    bool ok = true;
    /* Room for the longest prefix in load_reference's 4096-byte paths. */
    char prefix[4096 - sizeof "-a.pfm"];
    for (const char *p = prefixes; p && *p;) {
        size_t n = strcspn(p, " ");
        if (n > 0 && n < sizeof prefix) {
            memcpy(prefix, p, n);
            prefix[n] = '\0';
            ok = error_table(scene_name, spp, seed, threads, prefix, bt) && ok;
        } else if (n > 0) {
            fprintf(stderr, "%s: a reference prefix of %zu characters is too long\n", prog, n);
            ok = false;
        }
        p += n + (p[n] == ' ');
    }
    return ok;
}

int main(int argc, char **argv)
{
    uint64_t spp = 100, seed = 1;
    bool quick = app_bench_quick();
    int max_threads = 2, width = 600;
    const char *reference = getenv("MC_REF_BOOK"), *lambert = getenv("MC_REF_LAMBERT");
    const char *book_program = getenv("MC_BOOK_PROGRAM");
    const app_opt opts[] = {
        {"--spp", APP_COUNT, &spp, "samples per pixel (100)", NULL, 0, 0},
        {"--quick", APP_FLAG, &quick, "10 samples per pixel (also MC_BENCH_QUICK=1)", NULL, 0, 0},
        {"--max-threads", APP_INT, &max_threads, "run 1, 2, ... up to this many threads (2)", NULL, 1, 256},
        {"--width", APP_INT, &width, "image width and height (600)", NULL, 1, 65536},
        {"--seed", APP_SEED, &seed, "random seed (1)", NULL, 0, 0},
        {"--reference", APP_STRING, &reference,
         "PREFIX of the book scene's converged PREFIX-a.pfm and PREFIX-b.pfm: print the error "
         "table (default $MC_REF_BOOK, which may list several prefixes separated by spaces)",
         NULL, 0, 0},
        {"--lambert-reference", APP_STRING, &lambert,
         "the same for the lambert scene (default $MC_REF_LAMBERT)", NULL, 0, 0},
        {"--book-program", APP_STRING, &book_program,
         "the book's program built for 600x600, 100 spp (make book-program): time it here, the "
         "median of 3 runs, instead of the constant 68.3 s (default $MC_BOOK_PROGRAM)",
         NULL, 0, 0},
    };
    app_parse(prog,
              "bench_render [--spp N] [--quick] [--max-threads T] [--reference PREFIX] "
              "[--lambert-reference PREFIX] [--book-program PATH]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    if (quick && spp == 100)
        spp = 10;
    book_time bt;
    if (!book_time_get(book_program, &bt))
        return 2; /* a bad --book-program: bad input */
    rt_camera_params cp;
    rt_scene *scene = rt_scene_named("book", &cp);
    rt_image *img = rt_image_create(width, width);
    if (!scene || !img) {
        fprintf(stderr, "%s: out of memory\n", prog);
        return 1;
    }
    double book_paths_per_s = 600.0 * 600.0 * 100.0 / bt.seconds;
    char source[64];
    snprintf(source, sizeof source, "timed here, median of %d runs", NROUNDS);
    printf("book scene %dx%d, %llu spp, max depth 50, mixture; the book's program: %.1f s (%s), "
           "%.2f Mpaths/s\n"
           "(x_book: paths per second as a multiple of the book's program, not a thread speed-up)\n",
           width, width, (unsigned long long)spp, bt.seconds,
           bt.measured ? source : "a constant from another machine", book_paths_per_s * 1e-6);
    printf("%7s %10s %12s %15s %10s %9s\n", "threads", "wall_s", "Mpaths/s", "Msegments/s", "x_book", "dropped");
    for (int t = 1; t <= max_threads; t++) {
        rt_render_job job = rt_render_job_default(scene, rt_camera_make(cp, width, width));
        job.spp = spp;
        job.seed = seed;
        job.threads = t;
        rt_render_stats st;
        if (rt_render(&job, img, &st) != 0) {
            fprintf(stderr, "%s: render failed\n", prog);
            return 1;
        }
        double pps = (double)st.paths / st.seconds;
        printf("%7d %10.3f %12.3f %15.3f %9.1fx %9llu\n", t, st.seconds, pps * 1e-6,
               (double)st.segments / st.seconds * 1e-6, pps / book_paths_per_s,
               (unsigned long long)st.dropped);
    }
    mc_estimate rgb[3];
    rt_image_region_stats(img, 0, 0, width, width, rgb);
    printf("mean linear RGB: %.6f %.6f %.6f (standard errors %.1e %.1e %.1e)\n", rgb[0].value,
           rgb[1].value, rgb[2].value, rgb[0].std_error, rgb[1].std_error, rgb[2].std_error);
    rt_image_destroy(img);
    bool ok = true;
    if (reference && *reference)
        ok = error_tables("book", spp, seed, max_threads, reference, bt);
    else
        printf("no reference (make reference, then MC_REF_BOOK=PREFIX or --reference PREFIX): "
               "no error table\n");
    if (lambert && *lambert)
        ok = error_tables("lambert", spp, seed, max_threads, lambert, bt) && ok;
    rt_scene_destroy(scene);
    return ok ? 0 : 1;
}
