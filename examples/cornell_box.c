/* examples/cornell_box.c - the Cornell box of Shirley, "Ray Tracing: The
 * Rest of Your Life" (v1.123), rendered with that book's mixture of light
 * and material densities (its chapters 8-10; this book's #ch-cornell) or any of six other strategies that must agree with it:
 * among them light tracing and bidirectional path tracing (render/bdpt.h),
 * and with --strategy bdpt:S,T one bidirectional strategy alone.
 *
 * Build: make; run:
 *   build/bin/cornell_box --scene book --spp 100 -o cornell.png
 *   build/bin/cornell_box --scene lambert --strategy uniform -o uniform.pfm
 *   build/bin/cornell_box --scene book --sampler stratified --reference ref.pfm -o strat.pfm
 *   build/bin/cornell_box --scene book --strategy bdpt --roulette -o bdpt.png
 * Prints the image's mean linear RGB (standard errors from the per-pixel
 * variances), the paths, ray segments and dropped non-finite samples, and
 * the time. --sampler picks where the uniforms come from
 * (render/sampler.h; by default the strategy's best,
 * rt_render_sampler_kind); --reference REF.pfm compares the image with a
 * converged one and prints the error per pixel and channel and the
 * efficiency 1 / (MSE x seconds). Ctrl-C (SIGINT), SIGTERM and SIGHUP write the image rendered so
 * far and exit with 128 + the signal's number (130 for Ctrl-C). The image
 * goes to a temporary file beside the target, renamed over it only when
 * complete: whatever stops the program, the target holds either the
 * previous image or a complete new one.
 *
 * Over MPI (make MPI=1; examples/common/mpi_split.h):
 *   mpirun -q -np 4 build/mpi/bin/cornell_box --spp 1000 -o cornell.png
 * Rank r of K renders the rows r, r + K, ...; each pixel's samples are
 * taken by one rank in sample order, so the image rank 0 gathers and
 * writes is the one-process image, bit for bit, for any K and threads. A
 * stop signal to any rank (mpirun turns Ctrl-C into SIGTERM) stops every
 * rank and the image so far is written, as above.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "conform/build.h"
#include "conform/conform.h"
#include "examples/common/cli.h"
#include "examples/common/mpi_split.h"
#include "examples/common/outfile.h"
#include "render/bdpt.h"
#include "render/lighttrace.h"
#include "render/render.h"
#include "render/scenes.h"

static const char *const prog = "cornell_box";
static atomic_int interrupted; /* the signal that stopped us, polled by the renderer */

/* C17 7.14.1.1 allows a handler to touch only lock-free atomics: an
 * atomic_int that needed a lock could deadlock against the interrupted
 * thread. Require it to be always lock-free, not just sometimes. */
_Static_assert(ATOMIC_INT_LOCK_FREE == 2, "the signal handler needs a lock-free atomic_int");

static void on_stop_signal(int sig)
{
    atomic_store(&interrupted, sig);
}

typedef struct options {
    const char *scene, *strategy, *sampler, *gamma, *out, *reference;
    int width, depth, threads;
    double emit_aim;
    uint64_t spp, seed;
    bool csv, roulette;
} options;

/* The renderer's own scenes, then the conformance scenes
 * (conform/conform.h), in one NULL-terminated table for --scene. */
#define N_SCENE_CHOICES 16
static void scene_choices(const char *out[N_SCENE_CHOICES + 1])
{
    int n = 0;
    for (int i = 0; rt_scene_names[i] && n < N_SCENE_CHOICES; i++)
        out[n++] = rt_scene_names[i];
    for (int i = 0; cf_scene_names[i] && n < N_SCENE_CHOICES; i++)
        out[n++] = cf_scene_names[i];
    out[n] = NULL;
}

static options parse(int argc, char **argv)
{
    const char *scenes[N_SCENE_CHOICES + 1];
    scene_choices(scenes);
    options o = {.scene = "book", .strategy = "mixture", .sampler = "default", .gamma = "2",
                 .out = "cornell.png", .reference = NULL, .width = 600, .depth = 50, .threads = 0,
                 .spp = 100, .seed = 1, .csv = false, .roulette = false,
                 .emit_aim = RT_EMIT_AIM_DEFAULT};
    const app_opt opts[] = {
        {"--scene", APP_CHOICE, &o.scene,
         "the scene (default book); after lambert, furnace and sphere-light come the conformance scenes of mcbox-scene(1), "
         "whose every pixel is known", scenes, 0, 0},
        {"--width", APP_INT, &o.width, "image width and height in pixels (default 600)", NULL, 1, 65536},
        {"--spp", APP_COUNT, &o.spp, "samples per pixel (default 100)", NULL, 0, 0},
        {"--samples", APP_COUNT, &o.spp, "same as --spp", NULL, 0, 0},
        {"--max-depth", APP_INT, &o.depth, "most ray segments per path (default 50)", NULL, 0, 1e6},
        {"--strategy", APP_STRING, &o.strategy,
         "sampling strategy: uniform, cosine, light, mixture, mis, lighttrace, bdpt, or bdpt:S,T "
         "(one bidirectional strategy, unweighted) (default mixture)", NULL, 0, 0},
        {"--sampler", APP_CHOICE, &o.sampler,
         "where the uniforms come from: stratified (the pixel position jittered over cells, PCG32 "
         "for the rest), independent (PCG32 for all), sobol (Owen-scrambled Sobol points), or "
         "default: the strategy's best at equal error in make bench, sobol for mis, lighttrace "
         "and bdpt, stratified for the others (default default)", rt_sampler_names, 0, 0},
        {"--reference", APP_STRING, &o.reference,
         "a converged .pfm of the same size: print the pixel RMSE, MSE and 1/(MSE x seconds)", NULL, 0, 0},
        {"--threads", APP_INT, &o.threads, "OpenMP threads, 0 for all, at most 64 per processor (default 0)",
         NULL, 0, app_max_threads()},
        {"--seed", APP_SEED, &o.seed, "random seed (default 1)", NULL, 0, 0},
        {"-o", APP_STRING, &o.out, "output image .png, .ppm or .pfm (linear) (default cornell.png)", NULL, 0, 0},
        {"--gamma", APP_CHOICE, &o.gamma, "display encoding of .png and .ppm (default 2)", rt_gamma_names, 0, 0},
        {"--csv", APP_FLAG, &o.csv, "print the mean linear RGB as CSV", NULL, 0, 0},
        {"--roulette", APP_FLAG, &o.roulette, "Russian roulette after 3 segments (default off)", NULL, 0, 0},
        {"--emit-aim", APP_DOUBLE, &o.emit_aim,
         "bdpt: the share of light subpaths whose first direction aims at the light "
         "list's entries that do not emit (the book's glass sphere) instead of following the "
         "cosine; 0 for cosine emission only (default 0.1, the least error on the book scene)",
         NULL, 0, 0.99},
    };
    app_parse(prog, "cornell_box [--scene S] [--width W] [--spp N] [--max-depth D] "
                    "[--strategy S] [--sampler S] [--threads T] [--seed S] [-o FILE] [--gamma G] "
                    "[--roulette] [--emit-aim A] [--reference REF.pfm]",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);
    if (o.spp > UINT64_MAX / ((uint64_t)o.width * (uint64_t)o.width))
        app_fail(prog, "--spp %llu is too many for a %dx%d image", (unsigned long long)o.spp, o.width,
                 o.width);
    rt_path_settings ps = rt_path_settings_default(RT_MIXTURE);
    if (!rt_bdpt_strategy_parse(o.strategy, &ps))
        app_fail(prog, "--strategy %s: not a strategy (uniform, cosine, light, mixture, mis, "
                       "lighttrace, bdpt, bdpt:S,T with S >= 0, T >= 1, S + T >= 2)", o.strategy);
    if (rt_strategy_splats(ps.strategy) && o.depth > RT_BDPT_MAX_DEPTH)
        app_fail(prog, "--max-depth %d: %s takes at most %d", o.depth, o.strategy, RT_BDPT_MAX_DEPTH);
    if (strcmp(o.sampler, "sobol") == 0 && o.spp > UINT32_MAX)
        app_fail(prog, "--spp %llu: the sobol sampler takes fewer than 2^32 samples per pixel",
                 (unsigned long long)o.spp);
    return o;
}

/* Whether the chosen strategy splats light paths onto the image (light
 * tracing, bidirectional); the option was checked by main. */
static bool strategy_splats(const options *o)
{
    rt_path_settings ps = rt_path_settings_default(RT_MIXTURE);
    return rt_bdpt_strategy_parse(o->strategy, &ps) && rt_strategy_splats(ps.strategy);
}

/* Refuses (exit 2) an image whose buffers would not fit: the pixels
 * (Welford sums), one generator per pixel, the 8-bit rows of a PNG, and
 * 64 MB for the scene, the threads and the libraries. The limit is the
 * physical memory, or the address-space limit when that is lower: past
 * either, calloc fails late or the machine swaps for hours. */
static void check_memory(const options *o)
{
    double pixels = (double)o->width * (double)o->width;
    double need = pixels * (double)(sizeof(rt_pixel) + sizeof(mc_rng) + 3) + 64e6;
    if (strategy_splats(o)) /* a set of exact sums per thread (render/splat.h) */
        need += pixels * 3.0 * sizeof(rt_splat_sum) * rt_splat_sets(app_threads_used(o->threads));
    double have = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGE_SIZE);
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && (double)rl.rlim_cur < have)
        have = (double)rl.rlim_cur;
    if (have > 0.0 && need > have)
        app_fail(prog, "--width %d needs about %.2f GB of memory, more than the %.2f GB available",
                 o->width, need * 1e-9, have * 1e-9);
}

/* The reference image of --reference, read before the render so that a
 * bad one costs no rendering time: exit 2 if it cannot be read or is not
 * a width x width PFM. */
static rt_image *load_reference(const options *o)
{
    if (!o->reference)
        return NULL;
    FILE *f = fopen(o->reference, "rb");
    if (!f)
        app_fail(prog, "--reference %s: %s", o->reference, strerror(errno));
    const char *why = "";
    rt_image *ref = rt_image_read_pfm(f, &why);
    fclose(f);
    if (!ref)
        app_fail(prog, "--reference %s: %s", o->reference, why);
    if (ref->width != o->width || ref->height != o->width) {
        int w = ref->width, h = ref->height;
        rt_image_destroy(ref);
        app_fail(prog, "--reference %s is %dx%d, the image %dx%d", o->reference, w, h, o->width,
                 o->width);
    }
    return ref;
}

/* The error against the reference, per pixel and channel of linear RGB,
 * and the efficiency 1 / (MSE x seconds) of the render: the larger, the
 * less time to a given error (halving the MSE takes twice the samples).
 * On stderr with --csv, so that stdout stays one table. */
/* BEGIN SNIPPET report_error */
static void report_error(const options *o, const rt_image *img, const rt_image *ref, double seconds)
{
    double mse = rt_image_mse(img, ref);
    fprintf(o->csv ? stderr : stdout,
            "against %s: pixel RMSE %.6e, MSE %.6e (linear RGB, over all %dx%d pixels and 3 "
            "channels); efficiency 1/(MSE x %.3f s) = %.6g\n",
            o->reference, sqrt(mse), mse, img->width, img->height, seconds, 1.0 / (mse * seconds));
}
/* END SNIPPET report_error */

/* The progress line: percent, elapsed, estimated time left, throughput. */
static void show_progress(void *ctx, const rt_progress *p)
{
    double *t = ctx, now = omp_get_wtime(), el = now - t[0];
    if (now - t[1] < 0.25 && p->paths_done < p->paths_total)
        return;
    t[1] = now;
    double f = (double)p->paths_done / (double)p->paths_total;
    fprintf(stderr, "\r%s: %5.1f%%  elapsed %.1f s  ETA %.1f s  %.2f Mpaths/s   ", prog, 100.0 * f, el,
            f > 0.0 ? el * (1.0 - f) / f : 0.0, el > 0.0 ? (double)p->paths_done / el * 1e-6 : 0.0);
    fflush(stderr);
}

/* The renderer's per-row callback: shares stop signals between the ranks
 * of an MPI run, and draws the progress line on a terminal. */
typedef struct row_watch {
    double clock[2];
    app_mpi *mpi;
    bool tty;
} row_watch;

static void on_row(void *ctx, const rt_progress *p)
{
    row_watch *w = ctx;
    app_mpi_poll_stop(w->mpi, &interrupted);
    if (w->tty)
        show_progress(w->clock, p);
}

/* The ranks' counts summed, the rows gathered on rank 0 and, for the
 * strategies that splat, the splat sums added there and divided by every
 * rank's light paths together (the sums are exact, so neither the order
 * nor the split of the rows shows in the bits); the returned signal
 * stopped some rank (0: none). */
static int combine(app_mpi *mpi, rt_image *img, rt_splats *splats, rt_render_stats *st)
{
    int sig = app_mpi_settle_stop(mpi, &interrupted);
    uint64_t sums[4] = {st->paths, st->segments, st->dropped, st->cancelled};
    app_mpi_sum_u64(mpi, sums, 4);
    *st = (rt_render_stats){sums[0], sums[1], sums[2], st->seconds, sums[3] > 0};
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    _Static_assert(sizeof(rt_splat_sum) == 2 * sizeof(uint64_t), "a sum is two words, low first");
    if (!app_mpi_gather_rows(mpi, img->px, sizeof(rt_pixel) * (size_t)img->width, img->height) ||
        (splats && !app_mpi_sum_u128(mpi, (uint64_t *)(void *)splats->sum, n))) {
        fprintf(stderr, "%s: rank %d: gathering the image failed\n", prog, mpi->rank);
        exit(1);
    }
    if (splats && mpi->rank == 0) /* every pixel sample traced one light path */
        rt_splats_add_to_image(splats, st->paths, img);
    return sig;
}

static void report(const options *o, const rt_image *img, const rt_render_stats *st)
{
    mc_estimate rgb[3];
    rt_image_region_stats(img, 0, 0, img->width, img->height, rgb);
    /* region_stats counts a pixel of fewer than 2 samples as variance 0;
     * with such pixels (--spp 1, or a render stopped in its first pass) the
     * image's standard error cannot be estimated at all. */
    uint64_t fewest = UINT64_MAX;
    for (size_t i = 0; i < (size_t)img->width * (size_t)img->height; i++)
        fewest = img->px[i].n < fewest ? img->px[i].n : fewest;
    /* Nor for the strategies that splat: a pixel's splats come from the
     * light paths of every pixel, and their variance is not tracked. */
    if (fewest < 2 || strategy_splats(o))
        for (int c = 0; c < 3; c++)
            rgb[c].std_error = (double)NAN;
    app_table t = {stdout, o->csv, NULL, 0, "cornell_box"};
    app_table_begin(&t);
    static const char *const channel[3] = {"mean_linear_r", "mean_linear_g", "mean_linear_b"};
    /* The furnace has one exact value for every pixel, so for the image
     * mean too; the other scenes' image means have no closed form (the
     * sphere light's irradiance is exact point by point, which
     * test_render_integrator checks). */
    double exact = strcmp(o->scene, "furnace") == 0
                       ? rt_scene_furnace_radiance(RT_FURNACE_EMISSION, RT_FURNACE_RHO, o->depth)
                       : (double)NAN;
    for (int c = 0; c < 3; c++)
        app_table_row(&t, channel[c], rgb[c], exact, NULL);
    if (!o->csv)
        printf("%s %dx%d, %s, max depth %d: %llu paths, %llu ray segments, %llu dropped, %.2f s "
               "(%.2f Mpaths/s, %.2f Msegments/s); wrote %s\n",
               o->scene, o->width, o->width, o->strategy, o->depth, (unsigned long long)st->paths,
               (unsigned long long)st->segments, (unsigned long long)st->dropped, st->seconds,
               (double)st->paths / st->seconds * 1e-6, (double)st->segments / st->seconds * 1e-6, o->out);
}

int main(int argc, char **argv)
{
    /* First of all, so that a Ctrl-C at any moment, even before the render
     * starts, ends in the documented way: the image so far (possibly no
     * samples), a line saying so, exit status 130. sigaction rather than
     * signal(): under _POSIX_C_SOURCE, signal() may reset the handler after
     * one delivery, and a second Ctrl-C would then kill us mid-write.
     * SA_RESTART keeps a write(2) in progress from failing with EINTR.
     * (Under mpirun, MPI starts just before: handlers it may install are
     * then replaced by ours for these three signals.) */
    app_mpi mpi = app_mpi_start(&argc, &argv);
    struct sigaction sa = {0};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    /* SIGTERM is what timeout(1) and batch schedulers send, SIGHUP what a
     * closed terminal sends: both deserve the image so far, like Ctrl-C. */
    static const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof stop_signals / sizeof stop_signals[0]; i++)
        sigaction(stop_signals[i], &sa, NULL);
    options o = parse(argc, argv);
    rt_format format = rt_format_from_path(o.out);
    if (format == RT_FORMAT_UNKNOWN)
        app_fail(prog, "-o %s: the extension must be .png, .ppm or .pfm", o.out);
    check_memory(&o);
    rt_image *ref = load_reference(&o);
    if (mpi.size > o.width)
        app_fail(prog, "%d ranks are more than the %d image rows", mpi.size, o.width);
    /* The file is created only once the image is there (a job killed on
     * the way leaves nothing), but whether it can be is checked now. */
    app_outfile out;
    if (mpi.rank == 0 && !app_outfile_open(&out, o.out))
        app_fail(prog, "cannot write '%s': %s", o.out, strerror(errno));
    if (mpi.rank == 0)
        app_outfile_abort(&out);
    rt_camera_params cp;
    const cf_scene *conformance = cf_scene_find(o.scene);
    rt_scene *scene = conformance ? cf_build(conformance, &cp) : rt_scene_named(o.scene, &cp);
    if (scene && strategy_splats(&o) && rt_scene_emitter_count(scene) == 0) {
        rt_scene_destroy(scene);
        rt_image_destroy(ref);
        app_outfile_abort(&out);
        app_fail(prog, "--strategy %s starts light paths on emitters, and scene %s has none "
                       "(its light is the sky)", o.strategy, o.scene);
    }
    rt_image *img = rt_image_create(o.width, o.width);
    if (!scene || !img) {
        rt_image_destroy(img);
        rt_image_destroy(ref);
        rt_scene_destroy(scene);
        app_outfile_abort(&out);
        fprintf(stderr, "%s: out of memory\n", prog);
        return 1;
    }
    rt_render_job job = rt_render_job_default(scene, rt_camera_make(cp, o.width, o.width));
    rt_gamma gamma = RT_GAMMA_2;
    (void)rt_bdpt_strategy_parse(o.strategy, &job.path);
    (void)rt_sampler_parse(o.sampler, &job.sampler);
    (void)rt_gamma_parse(o.gamma, &gamma);
    job.path.max_depth = o.depth;
    job.path.russian_roulette = o.roulette;
    job.path.emit_aim = o.emit_aim;
    job.spp = o.spp;
    job.seed = o.seed;
    job.threads = o.threads;
    job.cancel = &interrupted;
    double clock[2] = {omp_get_wtime(), 0.0};
    bool tty = isatty(fileno(stderr));
    /* Without a terminal for the progress line, a long render says once,
     * at the start, how long it will take, from the paths per second per
     * thread that make bench's error table measures on the book's scene
     * (rounded; deeper paths go slower): 2 M for the one-ray strategies,
     * 1 M for those that add shadow rays or light paths, 0.5 M for bdpt
     * with roulette and 0.2 M for bdpt without. */
    if (!tty) {
        double paths = (double)o.width * (double)o.width * (double)o.spp;
        rt_strategy st = job.path.strategy;
        double rate = st == RT_BDPT ? (o.roulette ? 0.5e6 : 0.2e6)
                      : st == RT_MIS || st == RT_LIGHT || st == RT_LIGHTTRACE ? 1e6
                                                                              : 2e6;
        int nt = app_threads_used(o.threads);
        char what[192];
        snprintf(what, sizeof what,
                 "%.3g paths on %d thread(s), at about %.1f Mpaths/s each; SIGINT or SIGTERM "
                 "writes the image so far",
                 paths, nt, rate * 1e-6);
        app_announce(prog, paths / (rate * nt * mpi.size), what);
    }
    app_mpi_setup_done(&mpi);
    row_watch watch = {{clock[0], 0.0}, &mpi, tty};
    job.progress = tty || mpi.active ? on_row : NULL;
    job.progress_ctx = &watch;
    rt_render_stats st;
    rt_splats *splats = strategy_splats(&o) ? rt_splats_create(o.width, o.width) : NULL;
    if ((strategy_splats(&o) && !splats) ||
        rt_render_part(&job, img, mpi.rank, mpi.size, splats, &st) < 0) {
        rt_splats_destroy(splats);
        rt_image_destroy(img);
        rt_image_destroy(ref);
        rt_scene_destroy(scene);
        fprintf(stderr, "%s: out of memory\n", prog);
        return 1;
    }
    int sig = combine(&mpi, img, splats, &st);
    rt_splats_destroy(splats);
    if (mpi.active) /* the whole job's time, the gathering included */
        st.seconds = omp_get_wtime() - clock[0];
    if (tty)
        fputc('\n', stderr);
    if (mpi.rank > 0) {
        rt_image_destroy(img);
        rt_image_destroy(ref);
        rt_scene_destroy(scene);
        app_mpi_end(&mpi);
        return st.cancelled ? 128 + sig : 0;
    }
    errno = 0;
    if (!app_outfile_open(&out, o.out) || rt_image_write(img, out.f, format, gamma) != 0 ||
        !app_outfile_commit(&out)) {
        int e = errno;
        rt_image_destroy(img);
        rt_image_destroy(ref);
        rt_scene_destroy(scene);
        app_outfile_abort(&out);
        fprintf(stderr, "%s: error writing '%s'%s%s; it was left as it was\n", prog, o.out,
                e ? ": " : "", e ? strerror(e) : "");
        return 1;
    }
    report(&o, img, &st);
    if (ref)
        report_error(&o, img, ref, st.seconds);
    if (st.cancelled)
        fprintf(stderr, "%s: %s: %s holds %llu samples (%.2f per pixel of the %llu asked)\n",
                prog, sig == SIGTERM ? "terminated" : sig == SIGHUP ? "hung up" : "interrupted", o.out,
                (unsigned long long)st.paths, (double)st.paths / ((double)o.width * o.width),
                (unsigned long long)o.spp);
    rt_image_destroy(img);
    rt_image_destroy(ref);
    rt_scene_destroy(scene);
    app_mpi_end(&mpi);
    return st.cancelled ? 128 + sig : 0;
}
