/* exercises/check_exercise.c - main() of every exercise: runs its judge,
 * prints each check's figures and one verdict.
 *
 * Usage: EXERCISE [--seed S] [--samples N] [--plot DIR] [--table] [--build B]
 *   --seed S     replace every check's stated seed by a hash of (S, seed)
 *   --samples N  replace every stated sample count by N
 *   --plot DIR   write DIR/NAME-K.dat and DIR/NAME-K.gp (a gnuplot script
 *                drawing NAME-K.png) for the K-th sampler check
 *   --table      print one line, fields separated by tabs: VERDICT, build,
 *                key figure, the number of statistical tests, the ids of
 *                the failed checks (comma-separated, "-" if none), the
 *                build's kind and the id of the check a slip must fail
 *                ("-" for other builds)
 *   --build B    judge the build B (ref, slipK, altK) linked into NAME-all
 *                instead of the reader's (see find_build)
 * Exit status 0 pass, 1 fail, 2 bad usage or a check that could not run.
 */
#include "exercises/check_exercise.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"

struct ex_judge {
    bool has_seed, has_samples, table;
    uint64_t seed, samples;
    const char *plot_dir;
    const ex_exercise *ex; /* the build being judged */
    int checks, failed, errors, stat_tests, plots;
    char key[200];
    bool key_is_failure, key_is_intended;
    char failed_ids[200]; /* the ids of the failed checks, comma-separated */
};

/* The per-test level of the table (Sidak over EX_FAMILY tests). */
static double level(void)
{
    return mc_sidak_alpha(EX_ALPHA, EX_FAMILY);
}

uint64_t ex_seed(const ex_judge *j, uint64_t base)
{
    if (!j->has_seed)
        return base;
    /* MurmurHash3's 64-bit finaliser of the pair: nearby S give unrelated
     * seeds. */
    uint64_t h = j->seed * UINT64_C(0x9e3779b97f4a7c15) ^ base;
    h ^= h >> 33, h *= UINT64_C(0xff51afd7ed558ccd);
    h ^= h >> 33, h *= UINT64_C(0xc4ceb9fe1a85ec53);
    return h ^ (h >> 33);
}

uint64_t ex_samples(const ex_judge *j, uint64_t n)
{
    return j->has_samples ? j->samples : n;
}

/* Appends id to the list of failed checks, once. */
static void add_failed_id(ex_judge *j, const char *id)
{
    size_t len = strlen(id), used = strlen(j->failed_ids);
    for (const char *p = j->failed_ids; (p = strstr(p, id)) != NULL; p += len)
        if ((p == j->failed_ids || p[-1] == ',') && (p[len] == ',' || p[len] == '\0'))
            return;
    if (used + len + 2 <= sizeof j->failed_ids)
        snprintf(j->failed_ids + used, sizeof j->failed_ids - used, "%s%s", used ? "," : "", id);
}

/* Records one check's outcome and prints it (unless --table): `key` is the
 * short figure the table shows, `figure` the full line. The table's key
 * figure is that of the first failing check of the id a slip must fail,
 * else of the first failing check, else of the first check. */
static void report(ex_judge *j, const char *id, const char *what, int status, const char *key,
                   const char *figure, const char *why)
{
    j->checks++;
    if (status != 0)
        j->failed++, add_failed_id(j, id);
    if (status == 2)
        j->errors++;
    bool intended = status != 0 && j->ex->intended && strcmp(j->ex->intended, id) == 0;
    if ((status != 0 && !j->key_is_failure) || (intended && !j->key_is_intended) ||
        j->checks == 1) {
        snprintf(j->key, sizeof j->key, "%.60s: %.130s", what, key); /* fits: 194 < 200 */
        j->key_is_failure = status != 0;
        j->key_is_intended = intended;
    }
    if (j->table)
        return;
    printf("  [%s] %s (%s)\n         %s\n", status == 0 ? "pass" : status == 1 ? "FAIL" : "ERROR",
           what, id, figure);
    if (why && why[0])
        printf("         why: %s\n", why);
}

/* --- the picture ----------------------------------------------------------- */

/* a, b, c and d one after the other as a gnuplot single-quoted string,
 * where a quote is written twice. */
static void gp_quoted(FILE *g, const char *a, const char *b, const char *c, const char *d)
{
    const char *parts[4] = {a, b, c, d};
    fputc('\'', g);
    for (int k = 0; k < 4; k++)
        for (const char *p = parts[k]; *p; p++) {
            if (*p == '\'')
                fputc('\'', g);
            fputc(*p, g);
        }
    fputc('\'', g);
}

/* DIR/NAME-K.dat: per chart cell its centre, observed and expected counts
 * and the standardized residual; DIR/NAME-K.gp draws the three maps (or,
 * in 1D, the two histograms and the residuals) into DIR/NAME-K.png. */
static void write_picture(ex_judge *j, const char *what, const mcbox_check_table *t,
                          const mcbox_check_result *r)
{
    char dat[512], gp[512], base[256];
    snprintf(base, sizeof base, "%s-%d", j->ex->name, ++j->plots);
    snprintf(dat, sizeof dat, "%s/%s.dat", j->plot_dir, base);
    snprintf(gp, sizeof gp, "%s/%s.gp", j->plot_dir, base);
    FILE *f = fopen(dat, "w"), *g = f ? fopen(gp, "w") : NULL;
    if (!f || !g) {
        fprintf(stderr, "%s: cannot write %s: %s\n", j->ex->name, f ? gp : dat, strerror(errno));
        if (f)
            fclose(f);
        return;
    }
    double dx = (t->hi[0] - t->lo[0]) / t->nx;
    double dy = t->dims == 2 ? (t->hi[1] - t->lo[1]) / t->ny : 0.0;
    fprintf(f, "# %s: %s\n# x%s observed expected (observed-expected)/sqrt(expected)\n",
            j->ex->name, what, t->dims == 2 ? " y" : "");
    for (int i = 0; i < t->nx; i++) {
        for (int k = 0; k < t->ny; k++) {
            size_t c = (size_t)i * (size_t)t->ny + (size_t)k;
            double o = t->observed[c], e = t->expected[c];
            double res = e > 0.0 ? (o - e) / sqrt(e) : (o > 0.0 ? 10.0 : 0.0);
            if (t->dims == 2)
                fprintf(f, "%.9g %.9g %.0f %.6g %.4g\n", t->lo[0] + (i + 0.5) * dx,
                        t->lo[1] + (k + 0.5) * dy, o, e, res);
            else
                fprintf(f, "%.9g %.0f %.6g %.4g\n", t->lo[0] + (i + 0.5) * dx, o, e, res);
        }
        if (t->dims == 2)
            fputc('\n', f);
    }
    fclose(f);
    char title[400];
    snprintf(title, sizeof title, "%s (%s): %s; chi-square %.5g, %d dof, p = %.3g", j->ex->name,
             j->ex->variant, what, r->statistic, r->dof, r->pvalue);
    fprintf(g, "set terminal pngcairo size %d,460 font 'DejaVu Sans,10'\nset output ",
            t->dims == 2 ? 1500 : 1000);
    gp_quoted(g, j->plot_dir, "/", base, ".png");
    fprintf(g, "\nset multiplot layout 1,%d title ", t->dims == 2 ? 3 : 2);
    gp_quoted(g, title, "", "", "");
    fprintf(g, "\nset xrange [%.9g:%.9g]\nset xlabel ", t->lo[0], t->hi[0]);
    gp_quoted(g, t->xlabel, "", "", "");
    if (t->dims == 2) {
        fprintf(g, "\nset yrange [%.9g:%.9g]\nset ylabel ", t->lo[1], t->hi[1]);
        gp_quoted(g, t->ylabel, "", "", "");
        fputs("\nset palette rgb 33,13,10\nset title 'observed'\nplot ", g);
        gp_quoted(g, dat, "", "", "");
        fputs(" using 1:2:3 with image notitle\nset title 'expected'\nplot ", g);
        gp_quoted(g, dat, "", "", "");
        fputs(" using 1:2:4 with image notitle\nset title '(obs - exp) / sqrt(exp)'\n"
              "set cbrange [-4:4]\nset palette defined (-4 'blue', 0 'white', 4 'red')\nplot ",
              g);
        gp_quoted(g, dat, "", "", "");
        fputs(" using 1:2:5 with image notitle\n", g);
    } else {
        fputs("\nset ylabel 'samples per cell'\nset title 'observed and expected'\nplot ", g);
        gp_quoted(g, dat, "", "", "");
        fputs(" using 1:2 with steps title 'observed', '' using 1:3 with steps title 'expected'\n"
              "set title '(obs - exp) / sqrt(exp)'\nset ylabel 'z'\nplot ",
              g);
        gp_quoted(g, dat, "", "", "");
        fputs(" using 1:4 with impulses notitle\n", g);
    }
    fputs("unset multiplot\n", g);
    fclose(g);
    if (!j->table)
        printf("         picture: gnuplot %s (writes %s/%s.png)\n", gp, j->plot_dir, base);
}

/* --- the checks ------------------------------------------------------------ */

static void direction_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const ex_direction_fns *f = ctx;
    ex_put3(out->x, f->sample(u[0], u[1]));
}

static double direction_pdf(const double *x, void *ctx)
{
    const ex_direction_fns *f = ctx;
    return f->pdf(ex_vec3(x));
}

static void direction_invert(const double *x, double *u, void *ctx)
{
    const ex_direction_fns *f = ctx;
    f->invert(ex_vec3(x), u);
}

mcbox_sampler ex_direction_sampler(mcbox_domain_kind kind, const ex_direction_fns *fns)
{
    mcbox_sampler s = mcbox_sampler_init(kind);
    s.sample = direction_sample, s.pdf = direction_pdf, s.ctx = (void *)fns;
    if (fns->invert)
        s.invert = direction_invert;
    return s;
}

/* One public check of s; fills r (and t, for the picture, when the run was
 * given --plot DIR) and returns its status for report(): 0 pass, 1 fail, 2
 * could not run. `key` (120 bytes) and `fig` (400) receive the table's
 * short figure and the full line; `pinned` says that s is the law check's
 * sampler, whose integral is the law's and whose density at the samples
 * is the reader's. */
static int run_check(ex_judge *j, const mcbox_sampler *s, bool pinned, uint64_t seed,
                     uint64_t samples, mcbox_check_result *r, mcbox_check_table *t, char *key,
                     char *fig)
{
    mcbox_check_options o = mcbox_check_defaults();
    o.samples = ex_samples(j, samples);
    o.seed = ex_seed(j, seed);
    o.alpha = EX_ALPHA;
    o.tests = EX_FAMILY;
    int rc = mcbox_check_run(s, &o, r, j->plot_dir ? t : NULL);
    j->stat_tests++;
    char tail[120] = "no inverse";
    mcbox_check_figure(r, key, 120);
    if (pinned)
        snprintf(tail, sizeof tail, "your density at the samples off the law's by %.3g at most",
                 r->pdf_mismatch);
    else if (!isnan(r->invert_error))
        snprintf(tail, sizeof tail, "integral %.9f; round trip %.2g", r->pdf_integral,
                 r->invert_error);
    else
        snprintf(tail, sizeof tail, "integral %.9f; no inverse", r->pdf_integral);
    snprintf(fig, 400,
             "seed %" PRIu64 ", %" PRIu64 " samples, chi-square %.6g with %d dof, p = %.4g "
             "(level %.2g); %s; outside %" PRIu64,
             o.seed, o.samples, r->statistic, r->dof, r->pvalue, r->level, tail, r->outside);
    if (rc != 0) {
        snprintf(key, 120, "check could not run");
        return 2;
    }
    return r->pass ? 0 : 1;
}

/* The picture of a check that ran, after its report. */
static void picture(ex_judge *j, const char *what, int status, mcbox_check_table *t,
                    const mcbox_check_result *r)
{
    if (status == 2 || !j->plot_dir)
        return;
    write_picture(j, what, t, r);
    mcbox_check_table_free(t);
}

/* BEGIN SNIPPET pinned_law */
/* The law check's sampler: the reader's points, with the reader's density
 * reported at each (mcbox_sample.pdf), and the law's density as the one the
 * points are histogrammed against. */
typedef struct law_pin {
    const mcbox_sampler *yours;
    const ex_law *law;
} law_pin;

static void pinned_sample(const double *u, mcbox_sample *out, void *ctx)
{
    const law_pin *p = ctx;
    p->yours->sample(u, out, p->yours->ctx);
    out->pdf = p->yours->pdf(out->x, p->yours->ctx);
}

static double pinned_pdf(const double *x, void *ctx)
{
    const law_pin *p = ctx;
    return p->law->pdf(x, p->law->ctx);
}
/* END SNIPPET pinned_law */

/* The point at the centre of grid cell k of the domain of s, into x; the
 * number of cells by *cells (k is ignored then). 64 x 128 cells of
 * (cos theta, phi) on the whole sphere for directions (so a density that
 * should vanish somewhere is seen there too), 128 x 128 of [-1, 1]^2, the
 * square about the disc, for the disc, 1024 of an interval. */
static void grid_point(const mcbox_sampler *s, int k, double *x, int *cells)
{
    int dims = mcbox_domain_dims(&s->domain);
    *cells = dims == 3 ? 64 * 128 : dims == 2 ? 128 * 128 : 1024;
    if (dims == 3) {
        double z = -1.0 + (k / 128 + 0.5) / 32.0, phi = MC_2PI * (k % 128 + 0.5) / 128.0;
        double r = sqrt(1.0 - z * z);
        x[0] = r * cos(phi), x[1] = r * sin(phi), x[2] = z;
    } else if (dims == 2) {
        x[0] = -1.0 + (k / 128 + 0.5) / 64.0, x[1] = -1.0 + (k % 128 + 0.5) / 64.0;
    } else {
        double a = s->domain.a, b = s->domain.b;
        x[0] = a + (b - a) * (k + 0.5) / 1024.0;
    }
}

/* The reader's density against the law's on the grid of grid_point:
 * relative 1e-6 (the public check's own tolerance for a reported pdf),
 * exactly 0 where the law's is 0. */
static void check_density_grid(ex_judge *j, const char *what, const mcbox_sampler *s,
                               const ex_law *law)
{
    int cells, bad = 0;
    double first[3] = {0}, yours_first = 0.0, law_first = 0.0;
    grid_point(s, 0, first, &cells);
    for (int k = 0; k < cells; k++) {
        double x[3] = {0};
        grid_point(s, k, x, &cells);
        double yours = s->pdf(x, s->ctx), ref = law->pdf(x, law->ctx);
        if (!(fabs(yours - ref) <= 1e-6 * ref) && bad++ == 0) {
            memcpy(first, x, sizeof first);
            yours_first = yours, law_first = ref;
        }
    }
    char name[160], key[120], fig[400], at[100], why[400] = "";
    snprintf(name, sizeof name, "%.100s: your density on a grid", what);
    snprintf(key, sizeof key, "%d of %d grid points differ", bad, cells);
    snprintf(fig, sizeof fig, "%d of %d grid points where your density differs from %s's by "
             "more than 1e-6 relative", bad, cells, law->name);
    int dims = mcbox_domain_dims(&s->domain);
    if (dims == 3)
        snprintf(at, sizeof at, "(%.4g, %.4g, %.4g)", first[0], first[1], first[2]);
    else if (dims == 2)
        snprintf(at, sizeof at, "(%.4g, %.4g)", first[0], first[1]);
    else
        snprintf(at, sizeof at, "x = %.6g", first[0]);
    if (bad)
        snprintf(why, sizeof why, "your density is not %s: at %s yours is %.6g, the law's %.6g",
                 law->name, at, yours_first, law_first);
    report(j, "density", name, bad ? 1 : 0, key, fig, why);
}

void ex_check_sampler_law(ex_judge *j, const char *what, const mcbox_sampler *s,
                          const ex_law *law, uint64_t seed, uint64_t samples)
{
    char name[160], key[120], fig[400], why[800];
    mcbox_check_result mine, pinned;
    mcbox_check_table table;
    snprintf(name, sizeof name, "%.100s: your points, your density", what);
    int st = run_check(j, s, false, seed, samples, &mine, &table, key, fig);
    report(j, "consistent", name, st, key, fig, mine.message);
    picture(j, name, st, &table, &mine);

    law_pin pin = {s, law};
    mcbox_sampler p = *s;
    p.sample = pinned_sample, p.pdf = pinned_pdf, p.pdf_batch = NULL, p.invert = NULL;
    p.ctx = &pin;
    snprintf(name, sizeof name, "%.100s: the law asked for", what);
    int sl = run_check(j, &p, true, seed, samples, &pinned, &table, key, fig);
    why[0] = '\0';
    if (sl == 1) {
        /* Say it in the reader's terms: "the pdf function" of the check's
         * own message is the law here, "the reported pdf" the reader's. */
        char cause[400];
        bool chi2_failed = !(pinned.pvalue >= pinned.level);
        bool mismatch = !(pinned.pdf_mismatch <= 1e-6);
        if (pinned.outside || pinned.nonfinite || pinned.in_zero_cells)
            snprintf(cause, sizeof cause, "%s", pinned.message);
        else if (chi2_failed && strncmp(pinned.message, "chi-square", 10) == 0)
            snprintf(cause, sizeof cause, "against it, %s", pinned.message); /* names the cell */
        else if (chi2_failed)
            snprintf(cause, sizeof cause, "against it, chi-square %.6g with %d dof, p = %.3g",
                     pinned.statistic, pinned.dof, pinned.pvalue);
        else
            snprintf(cause, sizeof cause, "%s", pinned.message);
        if (chi2_failed)
            snprintf(key, 120, "chi2 %.5g/%d dof against the law, p = %.3g", pinned.statistic,
                     pinned.dof, pinned.pvalue);
        if (!chi2_failed && mismatch && !pinned.outside && !pinned.nonfinite)
            snprintf(why, sizeof why,
                     "your points follow %s, but your density is not that law's at the "
                     "samples (largest relative difference %.3g)",
                     law->name, pinned.pdf_mismatch);
        else if (st == 0)
            snprintf(why, sizeof why,
                     "your sampler and your density agree with each other, but the points do "
                     "not follow %s the exercise asks for: %s",
                     law->name, cause);
        else
            snprintf(why, sizeof why, "the points do not follow %s the exercise asks for: %s",
                     law->name, cause);
    } else if (sl == 2) {
        snprintf(why, sizeof why, "%s", pinned.message);
    }
    report(j, "law", name, sl, key, fig, why);
    picture(j, name, sl, &table, &pinned);

    check_density_grid(j, what, s, law);
}

void ex_check_estimate(ex_judge *j, const char *id, const char *what, mc_estimate e,
                       double exact, uint64_t seed)
{
    j->stat_tests++;
    double z = mc_z_score(e.value, exact, e.std_error);
    double p = mc_z_pvalue(z);
    bool finite = isfinite(e.value) && isfinite(e.std_error) && e.std_error >= 0.0;
    bool ok = finite && p >= level();
    char key[120], fig[400];
    snprintf(key, sizeof key, "z = %.3g", z);
    snprintf(fig, sizeof fig,
             "seed %" PRIu64 ", %" PRIu64 " samples: %.9g +- %.3g against %.9g, z = %.3g, "
             "p = %.4g (level %.2g)",
             seed, e.n, e.value, e.std_error, exact, z, p, level());
    report(j, id, what, ok ? 0 : 1, key, fig,
           ok ? NULL : !finite ? "the estimate or its error bar is not a finite number"
                               : "the estimate is further from the exact value than its error "
                                 "bar allows");
}

void ex_check_variance(ex_judge *j, const char *id, const char *what, mc_estimate e,
                       double sigma2, double mu4, const char *scheme, uint64_t seed)
{
    j->stat_tests++;
    double sd = sqrt((mu4 - sigma2 * sigma2) / (double)e.n);
    double z = (e.variance - sigma2) / sd, p = isfinite(z) ? mc_z_pvalue(z) : 0.0;
    bool ok = p >= level();
    char key[120], fig[400], why[400] = "";
    snprintf(key, sizeof key, "variance %.4g where %.4g is due, z = %.3g", e.variance, sigma2, z);
    snprintf(fig, sizeof fig,
             "seed %" PRIu64 ", %" PRIu64 " samples: variance of one sample %.6g +- %.3g against "
             "%.6g (%s), z = %.3g, p = %.4g (level %.2g)",
             seed, e.n, e.variance, sd, sigma2, scheme, z, p, level());
    if (!ok)
        snprintf(why, sizeof why,
                 "the variance of one sample is not that of %s: the samples come from another "
                 "scheme, or the variance is not computed per sample",
                 scheme);
    report(j, id, what, ok ? 0 : 1, key, fig, why);
}

void ex_check_coverage(ex_judge *j, const char *id, const char *what, uint64_t covered,
                       uint64_t runs, double nominal, uint64_t seed)
{
    j->stat_tests++;
    double mean = (double)runs * nominal, sd = sqrt(mean * (1.0 - nominal));
    double z = ((double)covered - mean) / sd, p = mc_z_pvalue(z);
    bool ok = p >= level();
    char key[120], fig[400];
    snprintf(key, sizeof key, "covered %.3f, z = %.3g", (double)covered / (double)runs, z);
    snprintf(fig, sizeof fig,
             "seeds %" PRIu64 "+i: %" PRIu64 " of %" PRIu64 " error bars (%.4f) hold the exact "
             "value, nominal %.4f; z = %.3g, p = %.4g (level %.2g)",
             seed, covered, runs, (double)covered / (double)runs, nominal, z, p, level());
    report(j, id, what, ok ? 0 : 1, key, fig,
           ok ? NULL : z > 0 ? "the error bar is too wide" : "the error bar is too narrow");
}

void ex_check_z_family(ex_judge *j, const char *id, const char *what, double sum_sq, int k,
                       uint64_t seed)
{
    j->stat_tests++;
    double p = isfinite(sum_sq) ? mc_chi2_pvalue(sum_sq, k) : 0.0;
    bool ok = p >= level();
    char key[120], fig[400];
    snprintf(key, sizeof key, "chi2 %.5g/%d, p = %.3g", sum_sq, k, p);
    snprintf(fig, sizeof fig,
             "seed %" PRIu64 ": sum of %d squared z-scores %.6g, p = %.4g (level %.2g)", seed, k,
             sum_sq, p, level());
    report(j, id, what, ok ? 0 : 1, key, fig,
           ok ? NULL : "some regions differ from their exact value beyond their error bars");
}

void ex_check_exact(ex_judge *j, const char *id, const char *what, bool ok, const char *figure,
                    ...)
{
    char fig[400];
    va_list ap;
    va_start(ap, figure);
    vsnprintf(fig, sizeof fig, figure, ap);
    va_end(ap);
    report(j, id, what, ok ? 0 : 1, fig, fig, NULL);
}

/* --- main ------------------------------------------------------------------ */

/* The fixtures' builds. `make exercises` compiles the reference, each slip
 * and each alternative with ex_this renamed (-Dex_this=ex_build_ref,
 * ex_build_slipK, ex_build_altK) and
 * links them beside the reader's build into one program per exercise,
 * NAME-all, which --build selects from: one link instead of one per
 * build. Weak, so that the reader's program, which has none of them,
 * links all the same (an absent one is a null address). */
#define EX_MAX_SLIPS 8
#define EX_MAX_ALTS 4
#define WEAK __attribute__((weak))
extern const ex_exercise ex_build_ref WEAK, ex_build_slip1 WEAK, ex_build_slip2 WEAK,
    ex_build_slip3 WEAK, ex_build_slip4 WEAK, ex_build_slip5 WEAK, ex_build_slip6 WEAK,
    ex_build_slip7 WEAK, ex_build_slip8 WEAK, ex_build_alt1 WEAK, ex_build_alt2 WEAK,
    ex_build_alt3 WEAK, ex_build_alt4 WEAK;

/* The build called `name` ("ref", "slip1", "alt1" ...), or NULL when it is
 * not in this program. */
static const ex_exercise *find_build(const char *name)
{
    const ex_exercise *slips[EX_MAX_SLIPS] = {&ex_build_slip1, &ex_build_slip2, &ex_build_slip3,
                                              &ex_build_slip4, &ex_build_slip5, &ex_build_slip6,
                                              &ex_build_slip7, &ex_build_slip8};
    const ex_exercise *alts[EX_MAX_ALTS] = {&ex_build_alt1, &ex_build_alt2, &ex_build_alt3,
                                            &ex_build_alt4};
    if (strcmp(name, "ref") == 0)
        return &ex_build_ref;
    if (strncmp(name, "slip", 4) == 0 && name[4] >= '1' && name[4] <= '0' + EX_MAX_SLIPS &&
        name[5] == '\0')
        return slips[name[4] - '1'];
    if (strncmp(name, "alt", 3) == 0 && name[3] >= '1' && name[3] <= '0' + EX_MAX_ALTS &&
        name[4] == '\0')
        return alts[name[3] - '1'];
    return NULL;
}

static int usage(const char *msg)
{
    if (msg)
        fprintf(stderr, "%s: %s\n", ex_this.name, msg);
    else
        printf("usage: %s [--seed S] [--samples N] [--plot DIR] [--table] [--build B]\n"
               "The exercise '%s' (chapter %s): runs its checks on your code, prints\n"
               "their figures and a verdict. Exit status 0 pass, 1 fail, 2 error.\n"
               "--build ref|slipK|altK judges the reference, slip K or alternative K\n"
               "instead (NAME-all only).\n",
               ex_this.name, ex_this.name, ex_this.chapter);
    return msg ? 2 : 0;
}

static bool parse_u64(const char *s, uint64_t *out)
{
    char *end;
    errno = 0;
    double v = s && *s != '-' ? strtod(s, &end) : -1.0; /* accepts 1e6 */
    if (!s || errno || *end || !(v >= 1.0 && v <= 1.8e19) || v != floor(v))
        return false;
    *out = (uint64_t)v;
    return true;
}

int main(int argc, char **argv)
{
    ex_judge j;
    memset(&j, 0, sizeof j);
    j.ex = &ex_this;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0)
            return usage(NULL);
        if (strcmp(a, "--version") == 0) {
            printf("%s (mcbox %s)\n", ex_this.name, mcbox_version());
            return 0;
        }
        if (strcmp(a, "--table") == 0) {
            j.table = true;
        } else if (strcmp(a, "--seed") == 0) {
            if (!parse_u64(v, &j.seed))
                return usage("--seed needs a whole number >= 1");
            j.has_seed = true, i++;
        } else if (strcmp(a, "--samples") == 0) {
            if (!parse_u64(v, &j.samples))
                return usage("--samples needs a whole number >= 1");
            j.has_samples = true, i++;
        } else if (strcmp(a, "--plot") == 0) {
            if (!v)
                return usage("--plot needs a directory");
            j.plot_dir = v, i++;
        } else if (strcmp(a, "--build") == 0) {
            j.ex = v ? find_build(v) : NULL;
            if (!j.ex)
                return usage("--build: no such build in this program (ref, slip1, alt1 ...)");
            i++;
        } else {
            char msg[160];
            snprintf(msg, sizeof msg, "unknown option '%s' (--help lists them)", a);
            return usage(msg);
        }
    }
    if (!j.table)
        printf("exercise %s (chapter %s), build: %s\n", j.ex->name, j.ex->chapter, j.ex->variant);
    j.ex->judge(&j);
    const char *verdict = j.errors ? "ERROR" : j.failed ? "FAIL" : "PASS";
    if (j.table)
        printf("%s\t%s\t%s\t%d\t%s\t%s\t%s\n", verdict, j.ex->variant, j.key, j.stat_tests,
               j.failed_ids[0] ? j.failed_ids : "-", j.ex->kind ? j.ex->kind : "yours",
               j.ex->intended ? j.ex->intended : "-");
    else
        printf("verdict: %s (%d of %d checks failed; %d statistical tests, each at level %.2g: "
               "false-alarm rate %.2g over the %d of the whole table)\n",
               verdict, j.failed, j.checks, j.stat_tests, level(), EX_ALPHA, EX_FAMILY);
    return j.errors ? 2 : j.failed ? 1 : 0;
}
