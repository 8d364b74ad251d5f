/* examples/check_cli/report.c - what mcbox-check says: the human summary,
 * one JSON object (--json), a JUnit suite of one case (--junit), and the
 * error case of each when there is no verdict (exit 2). */
#define _POSIX_C_SOURCE 200809L /* open_memstream, kill, waitpid */

#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

/* Where cli_fail reports besides stderr. It is called from every layer
 * without a context (as app_fail is), so the destination is held here:
 * set once from argv before parsing, then pointed at the parsed options. */
static struct {
    bool json;
    const char *junit, *name;
    cli_app *app;
} where_to;

void cli_report_prescan(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        size_t len = strcspn(s, "=");
        const char **dest = len == 7 && strncmp(s, "--junit", 7) == 0 ? &where_to.junit
                          : len == 6 && strncmp(s, "--name", 6) == 0  ? &where_to.name
                                                                      : NULL;
        if (strcmp(s, "--json") == 0)
            where_to.json = true;
        else if (dest && (s[len] == '=' || (i + 1 < argc && !s[len])))
            *dest = s[len] == '=' ? s + len + 1 : argv[++i];
    }
}

void cli_report_errors_to(cli_app *c)
{
    where_to.app = c;
    where_to.json = c->a.json, where_to.junit = c->a.junit, where_to.name = c->a.name;
}

const char *cli_verdict(const mcbox_check_result *r)
{
    return r->pass ? "pass" : r->undetermined ? "undetermined" : "fail";
}

void cli_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char b = (unsigned char)*s;
        if (b == '"' || b == '\\')
            fprintf(f, "\\%c", b);
        else if (b < 0x20)
            fprintf(f, "\\u%04x", b);
        else
            fputc(b, f);
    }
    fputc('"', f);
}

void cli_json_key_string(FILE *f, const char *key, const char *v)
{
    fprintf(f, ", \"%s\": ", key);
    cli_json_string(f, v);
}

void cli_json_number(FILE *f, const char *key, double v)
{
    if (isfinite(v))
        fprintf(f, ", \"%s\": %.17g", key, v);
    else
        fprintf(f, ", \"%s\": null", key);
}

void cli_json_vector(FILE *f, const char *key, const double *v, int n)
{
    fprintf(f, ", \"%s\": [", key);
    for (int j = 0; j < n; j++)
        fprintf(f, isfinite(v[j]) ? "%s%.17g" : "%snull", j ? ", " : "", v[j]);
    fputc(']', f);
}

/* The options a verdict rests on. */
static void json_options(FILE *f, const cli_app *c)
{
    const mcbox_check_options *o = &c->a.o;
    fprintf(f, ", \"alpha\": %.17g, \"tests\": %d, \"seed\": %llu", o->alpha, o->tests,
            (unsigned long long)o->seed);
    const struct {
        const char *key;
        double v;
    } tol[] = {{"norm_tol", o->norm_tol},   {"pdf_tol", o->pdf_tol},
               {"weight_tol", o->weight_tol}, {"invert_tol", o->invert_tol},
               {"quad_error_max", o->quad_error_max}, {"lobe_width", o->lobe_width}};
    for (size_t k = 0; k < sizeof tol / sizeof tol[0]; k++)
        cli_json_number(f, tol[k].key, tol[k].v);
    fprintf(f, ", \"quad_order\": %d, \"quad_depth\": %d", o->quad_order, o->quad_depth);
    cli_json_vector(f, "lobe_axis", o->lobe_axis, 3);
}

/* The chart and the atoms' cells of the table. */
static void json_table(FILE *f, const cli_app *c, const mcbox_check_table *t)
{
    fprintf(f, ", \"chart\": {\"dims\": %d, \"nx\": %d, \"ny\": %d", t->dims, t->nx, t->ny);
    cli_json_vector(f, "lo", t->lo, t->dims);
    cli_json_vector(f, "hi", t->hi, t->dims);
    fputs("}, \"atoms\": [", f);
    size_t chart = (size_t)t->nx * (size_t)t->ny;
    for (size_t k = 0; k < c->s.n_atoms && chart + k < t->cells; k++) {
        fputs(k ? ", {" : "{", f);
        fputs("\"index\": ", f);
        fprintf(f, "%zu", k);
        cli_json_vector(f, "x", c->atom_x + k * (size_t)c->dims, c->dims);
        cli_json_number(f, "mass", c->atom_mass[k]);
        cli_json_number(f, "observed", t->observed[chart + k]);
        cli_json_number(f, "expected", t->expected[chart + k]);
        fputc('}', f);
    }
    fputc(']', f);
}

void cli_print_json(FILE *f, const cli_app *c, const mcbox_check_result *r,
                    const mcbox_check_table *t)
{
    fputs("{\"name\": ", f);
    cli_json_string(f, c->a.name);
    cli_json_key_string(f, "verdict", cli_verdict(r));
    fprintf(f, ", \"pass\": %s, \"undetermined\": %s", r->pass ? "true" : "false",
            r->undetermined ? "true" : "false");
    cli_json_key_string(f, "message", r->message);
    cli_json_key_string(f, "warning", r->warning);
    cli_json_key_string(f, "note", c->note);
    cli_json_number(f, "statistic", r->statistic);
    fprintf(f, ", \"dof\": %d", r->dof);
    cli_json_number(f, "pvalue", r->pvalue);
    cli_json_number(f, "level", r->level);
    const struct {
        const char *key;
        uint64_t v;
    } counts[] = {{"samples", r->samples},       {"cells", r->cells},
                  {"cells_pooled", r->cells_pooled}, {"outside", r->outside},
                  {"nonfinite", r->nonfinite},   {"in_zero_cells", r->in_zero_cells},
                  {"bad_atoms", r->bad_atoms},   {"bad_pdf", r->bad_pdf},
                  {"pdf_reported", r->pdf_reported}, {"weight_reported", r->weight_reported},
                  {"cells_90", r->cells_90}};
    for (size_t k = 0; k < sizeof counts / sizeof counts[0]; k++)
        fprintf(f, ", \"%s\": %llu", counts[k].key, (unsigned long long)counts[k].v);
    const struct {
        const char *key;
        double v;
    } figures[] = {{"pdf_integral", r->pdf_integral},   {"pdf_integral_error", r->pdf_integral_error},
                   {"pdf_mismatch", r->pdf_mismatch},   {"weight_mean", r->weight_mean},
                   {"weight_mismatch", r->weight_mismatch}, {"invert_error", r->invert_error},
                   {"power_share", r->power_share},     {"power_rel_error", r->power_rel_error},
                   {"scale_detectable", r->scale_detectable},
                   {"lobe_hint_width", r->lobe_hint_width}};
    for (size_t k = 0; k < sizeof figures / sizeof figures[0]; k++)
        cli_json_number(f, figures[k].key, figures[k].v);
    cli_json_vector(f, "lobe_hint_axis", r->lobe_hint_axis, 3);
    if (t)
        json_table(f, c, t);
    json_options(f, c);
    fputs("}\n", f);
}

/* What a pass proves: the smallest error of the density over a share of
 * the mass that the run catches, and the scale error normalization
 * catches. Silent when the check did not compute it. */
static void print_power(FILE *f, const mcbox_check_result *r)
{
    if (!(r->power_share > 0.0))
        return;
    fputs("  power: ", f);
    if (isfinite(r->power_rel_error))
        fprintf(f, "a density %.3g%% off over a region holding %.3g%% of the mass would be caught "
                   "(probability 0.9)", 100.0 * r->power_rel_error, 100.0 * r->power_share);
    else
        fprintf(f, "no error over a region holding %.3g%% of the mass is sure to be caught",
                100.0 * r->power_share);
    if (isfinite(r->scale_detectable) && r->scale_detectable > 0.0)
        fprintf(f, "; a scale error above %.3g%% fails normalization", 100.0 * r->scale_detectable);
    fprintf(f, "; %llu cells hold 90%% of the expected count\n", (unsigned long long)r->cells_90);
}

void cli_print_summary(FILE *f, const cli_app *c, const mcbox_check_result *r)
{
    fprintf(f, "%s: %s\n", c->a.name, r->pass ? "pass" : r->undetermined ? "UNDETERMINED" : "FAIL");
    fprintf(f, "  chi-square %.6g, %d dof, p = %.4g (level %.4g)\n", r->statistic, r->dof,
            r->pvalue, r->level);
    fprintf(f, "  samples %llu: %llu outside, %llu non-finite, %llu in zero cells\n",
            (unsigned long long)r->samples, (unsigned long long)r->outside,
            (unsigned long long)r->nonfinite, (unsigned long long)r->in_zero_cells);
    fprintf(f, "  pdf integral %.9g", r->pdf_integral);
    if (r->pdf_integral_error > 0.0)
        fprintf(f, " (quadrature error %.2g)", r->pdf_integral_error);
    fprintf(f, "; pdf mismatch %.3g (%llu reported); bad pdf %llu\n", r->pdf_mismatch,
            (unsigned long long)r->pdf_reported, (unsigned long long)r->bad_pdf);
    if (!isnan(r->invert_error))
        fprintf(f, "  inverse error %.3g\n", r->invert_error);
    print_power(f, r);
    if (r->warning[0])
        fprintf(f, "  warning: %s\n", r->warning);
    if (c->note[0])
        fprintf(f, "  note: %s\n", c->note);
    if (!r->pass)
        fprintf(f, "  why: %s\n", r->message);
}

static void xml_text(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default:
            /* XML 1.0 has no control characters but tab and line ends. */
            fputc((unsigned char)*s < 0x20 && !strchr("\t\n\r", *s) ? '?' : *s, f);
        }
}

/* A suite of one case: <failure> for a failed verdict, <error> when there
 * is none (undetermined, bad input, a broken protocol). summary may be
 * NULL. */
void cli_junit_suite(FILE *f, const char *name, const char *verdict, const char *message,
                        const char *summary, const char *err_text, double seconds)
{
    bool failure = strcmp(verdict, "fail") == 0, error = !failure && strcmp(verdict, "pass") != 0;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<testsuite name=\"mcbox-check\" tests=\"1\" failures=\"%d\" errors=\"%d\" "
               "time=\"%.3f\">\n  <testcase classname=\"mcbox-check\" name=\"",
            failure, error, seconds);
    xml_text(f, name);
    fprintf(f, "\" time=\"%.3f\">\n", seconds);
    if (failure || error) {
        fprintf(f, "    <%s type=\"%s\" message=\"", failure ? "failure" : "error", verdict);
        xml_text(f, message);
        fputs("\">", f);
        xml_text(f, message);
        fprintf(f, "</%s>\n", failure ? "failure" : "error");
    }
    if (summary) {
        fputs("    <system-out>", f);
        xml_text(f, summary);
        fputs("</system-out>\n", f);
    }
    if (err_text && err_text[0]) {
        fputs("    <system-err>", f);
        xml_text(f, err_text);
        fputs("</system-err>\n", f);
    }
    fputs("  </testcase>\n</testsuite>\n", f);
}

bool cli_write_junit(cli_app *c, const mcbox_check_result *r, double seconds)
{
    char *text = NULL, err_text[700];
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (m) {
        cli_print_summary(m, c, r);
        fclose(m);
    }
    snprintf(err_text, sizeof err_text, "%s%s%s%s", r->warning[0] ? "warning: " : "", r->warning,
             r->warning[0] && c->note[0] ? "\n" : "", c->note[0] ? c->note : "");
    cli_junit_suite(c->junit.f, c->a.name, cli_verdict(r), r->message, text, err_text, seconds);
    free(text);
    c->junit_open = false;
    return app_outfile_commit(&c->junit);
}

/* The error case of --json and --junit, as far as they can be written. */
static void report_error(const char *msg)
{
    cli_app *c = where_to.app;
    const char *name = where_to.name ? where_to.name : "sampler";
    if (where_to.json) {
        fputs("{\"name\": ", stdout);
        cli_json_string(stdout, name);
        fputs(", \"verdict\": \"error\", \"pass\": false, \"undetermined\": false", stdout);
        cli_json_key_string(stdout, "message", msg);
        fputs("}\n", stdout);
        fflush(stdout);
    }
    if (!where_to.junit)
        return;
    app_outfile out;
    app_outfile *o = c && c->junit_open ? &c->junit : &out;
    if (o == &out && !app_outfile_open(o, where_to.junit))
        return;
    if (c)
        c->junit_open = false;
    double seconds = c && c->t0 > 0.0 ? cli_now() - c->t0 : 0.0;
    cli_junit_suite(o->f, name, "error", msg, NULL, NULL, seconds);
    app_outfile_commit(o);
}

_Noreturn void cli_fail(const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cli_app *c = where_to.app;
    if (c && c->have_child) { /* never leave a program running behind us */
        kill(-c->ch.pid, SIGKILL);
        kill(c->ch.pid, SIGKILL);
        while (!c->ch.reaped && waitpid(c->ch.pid, NULL, 0) < 0 && errno == EINTR) {
        }
    }
    fflush(stdout);
    fprintf(stderr, "%s: %s\n", CLI_PROG, msg);
    report_error(msg);
    exit(2);
}
