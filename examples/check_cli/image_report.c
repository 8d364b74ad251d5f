/* examples/check_cli/image_report.c - what the image door says: the
 * summary, one JSON object (--json), a JUnit suite of one case (--junit),
 * and the picture of the standardized bias block by block (--picture). */
#define _POSIX_C_SOURCE 200809L /* open_memstream */

#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check/image.h"
#include "render/image.h"

static const char *const channel[3] = {"red", "green", "blue"};

/* "darker by 3.1% +- 0.4%" for a part (relative to its truth). */
static void bias_words(FILE *f, const mcbox_image_part *p)
{
    if (!(p->truth > 0.0)) {
        fprintf(f, "%+.3g +- %.3g (absolute; the truth is 0)", p->mean - p->truth, p->se);
        return;
    }
    double rel = (p->mean - p->truth) / p->truth, se = p->se / p->truth;
    fprintf(f, "%s by %.3g%% +- %.3g%%", rel < 0.0 ? "darker" : "brighter", 100.0 * fabs(rel),
            100.0 * se);
}

/* True when the three channels of a part say the same (a grey scene
 * rendered grey): one line says it for all. */
static bool alike(const mcbox_image_part p[3])
{
    return p[0].mean == p[1].mean && p[1].mean == p[2].mean && p[0].truth == p[1].truth &&
           p[1].truth == p[2].truth && p[0].se == p[1].se && p[1].se == p[2].se;
}

static void part_line(FILE *f, const char *label, const mcbox_image_part *p, bool all)
{
    fprintf(f, "  %s, %s: ", label, all ? "every channel" : channel[p->channel]);
    bias_words(f, p);
    fprintf(f, " (mean %.6g, truth %.6g, z %.2f, p %.3g)\n", p->mean, p->truth, p->z, p->p);
}

/* The part's three channels, one line for all when they agree, else the
 * least likely channel's. */
static void parts_line(FILE *f, const char *label, const mcbox_image_part p[3])
{
    if (alike(p)) {
        part_line(f, label, &p[0], true);
        return;
    }
    const mcbox_image_part *w = &p[0];
    for (int c = 1; c < 3; c++)
        if (p[c].p < w->p)
            w = &p[c];
    part_line(f, label, w, false);
}

static void summary(FILE *f, const cli_image_info *in, const mcbox_image_result *r)
{
    fprintf(f, "%s: %s\n", in->name, r->pass ? "pass" : "FAIL");
    fprintf(f, "  against %s, %dx%d, ", in->truth, in->width, in->height);
    if (in->renders)
        fprintf(f, "%d renders", in->renders);
    else
        fputs("a mean and second-moment pair", f);
    fprintf(f, "; the truth within %.2g\n", in->truth_error);
    if (alike(r->image))
        part_line(f, "whole image", &r->image[0], true);
    else
        for (int c = 0; c < 3; c++)
            part_line(f, "whole image", &r->image[c], false);
    for (int g = 0; g < r->n_regions; g++) {
        const mcbox_image_part *p = &r->regions[g][0];
        char label[160];
        snprintf(label, sizeof label, "%s (pixels [%d, %d) x [%d, %d))",
                 r->region_names[g] ? r->region_names[g] : "region", p->x0, p->x1, p->y0, p->y1);
        parts_line(f, label, r->regions[g]);
    }
    /* The worst blocks, each once whatever its channels. */
    for (int i = 0, shown = 0; i < r->n_worst && shown < 3; i++) {
        const mcbox_image_part *p = &r->worst[i];
        bool seen = false;
        for (int j = 0; j < i; j++)
            seen |= r->worst[j].x0 == p->x0 && r->worst[j].y0 == p->y0;
        if (seen)
            continue;
        char label[96];
        snprintf(label, sizeof label, "block [%d, %d) x [%d, %d)", p->x0, p->x1, p->y0, p->y1);
        part_line(f, label, p, false);
        shown++;
    }
    fprintf(f, "  family: %d tests (whole image, regions and %dx%d blocks of %d px, per channel), "
               "each at %.3g, alpha %.3g; |z| > %.2f rejects\n",
            r->tests, r->blocks_x, r->blocks_y, r->block, r->per_test_alpha, r->alpha, r->z_crit);
    fprintf(f, "  noise: measured from the renders, %.0f degrees of freedom; block variance %.3g "
               "times the independent pixels'%s\n",
            r->dof, r->inflation, r->inflation > 1.0 ? " (used)" : " (1 used)");
    double det = r->image[0].truth > 0.0 ? r->image[0].detectable / r->image[0].truth
                                         : (double)INFINITY;
    fprintf(f, "  power: a bias of %.3g%% over the whole image, or %.3g%% in a typical block, "
               "would be caught (probability 0.9)\n",
            100.0 * det, 100.0 * r->block_detectable);
    if (r->note[0])
        fprintf(f, "  note: %s\n", r->note);
    if (!r->pass)
        fprintf(f, "  why: %s\n", r->message);
}

static void json_part(FILE *f, const mcbox_image_part *p)
{
    fprintf(f, "{\"x0\": %d, \"y0\": %d, \"x1\": %d, \"y1\": %d, \"channel\": %d", p->x0, p->y0,
            p->x1, p->y1, p->channel);
    cli_json_number(f, "truth", p->truth);
    cli_json_number(f, "mean", p->mean);
    cli_json_number(f, "se", p->se);
    cli_json_number(f, "allowance", p->allowance);
    cli_json_number(f, "z", p->z);
    cli_json_number(f, "p", p->p);
    cli_json_number(f, "detectable", p->detectable);
    fputc('}', f);
}

static void json(FILE *f, const cli_image_info *in, const mcbox_image_result *r)
{
    fputs("{\"name\": ", f);
    cli_json_string(f, in->name);
    cli_json_key_string(f, "verdict", r->pass ? "pass" : "fail");
    fprintf(f, ", \"pass\": %s, \"undetermined\": false", r->pass ? "true" : "false");
    cli_json_key_string(f, "message", r->message);
    cli_json_key_string(f, "note", r->note);
    cli_json_key_string(f, "truth", in->truth);
    fprintf(f, ", \"width\": %d, \"height\": %d, \"renders\": %d", in->width, in->height,
            in->renders);
    cli_json_number(f, "truth_error", in->truth_error);
    cli_json_number(f, "alpha", r->alpha);
    cli_json_number(f, "per_test_alpha", r->per_test_alpha);
    cli_json_number(f, "z_crit", r->z_crit);
    cli_json_number(f, "min_p", r->min_p);
    cli_json_number(f, "inflation", r->inflation);
    cli_json_number(f, "dof", r->dof);
    cli_json_number(f, "block_detectable", r->block_detectable);
    fprintf(f, ", \"tests\": %d, \"block\": %d, \"blocks_x\": %d, \"blocks_y\": %d", r->tests,
            r->block, r->blocks_x, r->blocks_y);
    fputs(", \"image\": [", f);
    for (int c = 0; c < 3; c++) {
        fputs(c ? ", " : "", f);
        json_part(f, &r->image[c]);
    }
    fputs("], \"regions\": [", f);
    for (int g = 0; g < r->n_regions; g++)
        for (int c = 0; c < 3; c++) {
            fputs(g || c ? ", " : "", f);
            json_part(f, &r->regions[g][c]);
        }
    fputs("], \"worst\": [", f);
    for (int i = 0; i < r->n_worst; i++) {
        fputs(i ? ", " : "", f);
        json_part(f, &r->worst[i]);
    }
    fputs("]", f);
    size_t nz = (size_t)r->blocks_x * (size_t)r->blocks_y * 3;
    fputs(", \"block_z\": [", f);
    for (size_t i = 0; i < nz; i++)
        fprintf(f, isfinite(r->z[i]) ? "%s%.6g" : "%snull", i ? ", " : "", r->z[i]);
    fputs("]}\n", f);
}

/* Each pixel shows its block's z of the channel farthest out: grey at 0,
 * toward red where the render is brighter than the truth, blue where it
 * is darker, full colour at the rejection threshold; rejected blocks get
 * a black frame. */
static bool picture(const char *path, const mcbox_image_result *r, int w, int h)
{
    rt_image *img = rt_image_create(w, h);
    if (!img)
        return false;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int bx = x / r->block, by = y / r->block;
            const double *z = &r->z[((size_t)by * (size_t)r->blocks_x + (size_t)bx) * 3];
            double zz = z[0];
            for (int c = 1; c < 3; c++)
                zz = fabs(z[c]) > fabs(zz) ? z[c] : zz;
            double t = fmax(-1.0, fmin(1.0, zz / r->z_crit));
            double e[3] = {0.5, 0.5, 0.5};
            if (t > 0.0)
                e[0] = 0.5 + 0.5 * t, e[1] = e[2] = 0.5 - 0.5 * t;
            else if (t < 0.0)
                e[2] = 0.5 - 0.5 * t, e[0] = e[1] = 0.5 + 0.5 * t;
            bool edge = x % r->block == 0 || y % r->block == 0;
            if (fabs(zz) > r->z_crit && edge)
                e[0] = e[1] = e[2] = 0.0;
            /* Linear values that the gamma-2 writer encodes back to e. */
            rt_pixel_add(&img->px[(size_t)y * (size_t)w + (size_t)x],
                         vec3_make(e[0] * e[0], e[1] * e[1], e[2] * e[2]));
        }
    int rc = rt_image_save(img, path, RT_GAMMA_2);
    rt_image_destroy(img);
    return rc == 0;
}

void cli_image_report(const cli_image_info *in, const mcbox_image_result *r, bool as_json,
                      const char *junit, const char *pic)
{
    if (as_json)
        json(stdout, in, r);
    else
        summary(stdout, in, r);
    fflush(stdout);
    if (junit) {
        char *text = NULL;
        size_t len = 0;
        FILE *m = open_memstream(&text, &len);
        if (m) {
            summary(m, in, r);
            fclose(m);
        }
        app_outfile out;
        if (!app_outfile_open(&out, junit)) {
            fprintf(stderr, "%s: warning: cannot write %s: %s\n", CLI_PROG, junit, strerror(errno));
        } else {
            cli_junit_suite(out.f, in->name, r->pass ? "pass" : "fail", r->message, text, r->note,
                            in->seconds);
            if (!app_outfile_commit(&out))
                fprintf(stderr, "%s: warning: cannot write %s: %s\n", CLI_PROG, junit,
                        strerror(errno));
        }
        free(text);
    }
    if (pic && !picture(pic, r, in->width, in->height))
        fprintf(stderr, "%s: warning: cannot write the picture %s (the name must end in .png or "
                        ".ppm)\n", CLI_PROG, pic);
}
