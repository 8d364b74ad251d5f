/* examples/check_cli/exec.c - the --exec door: the protocol's commands
 * (docs/check-protocol.md) driving the incremental check, one batch at a
 * time, with the uniforms mcbox_check_run would give a C sampler. */
#include "examples/check_cli/check_cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static bool answer_ok(cli_app *c, size_t i, const char *line, size_t len, char *err, size_t errlen)
{
    (void)c, (void)i;
    return app_proto_parse_ok(line, len, err, errlen);
}

void cli_hello(cli_app *c, int uniforms)
{
    char line[160];
    size_t n = app_proto_format_hello(line, sizeof line, c->domain_word, c->dims, uniforms,
                                      c->a.o.seed);
    snprintf(c->where, sizeof c->where, "hello");
    if (!n)
        cli_fail("--domain: '%s' is not one word of at most 63 bytes", c->domain_word);
    cli_exchange(c, line, n, 1, answer_ok);
}

/* A sample answer; "atom J" is the J-th --atom, so the point is that
 * atom's (an index out of range keeps NaN and counts as a bad atom). */
static bool answer_sample(cli_app *c, size_t i, const char *line, size_t len, char *err,
                          size_t errlen)
{
    mcbox_sample *q = &c->ans_smp[i];
    q->x[0] = q->x[1] = q->x[2] = 0.0;
    if (!app_proto_parse_sample(line, len, c->dims, q, err, errlen))
        return false;
    if (q->atom >= 0) {
        size_t k = (size_t)q->atom;
        for (int j = 0; j < c->dims; j++)
            q->x[j] = k < c->s.n_atoms ? c->atom_x[k * (size_t)c->dims + (size_t)j] : (double)NAN;
    }
    return true;
}

static bool answer_numbers(cli_app *c, size_t i, const char *line, size_t len, char *err,
                           size_t errlen)
{
    return app_proto_parse_numbers(line, len, c->ans_count, c->ans_vals + i * (size_t)c->ans_count,
                                   err, errlen);
}

/* The density over the pipe, in batches of the protocol's size. */
void cli_pdf_batch(const double *x, size_t n, double *out, void *ctx)
{
    cli_app *c = ctx;
    for (size_t done = 0; done < n;) {
        size_t k = n - done < CLI_BATCH ? n - done : CLI_BATCH;
        size_t len = cli_format_batch(c, APP_PROTO_PDF, x + done * (size_t)c->dims, k, c->dims,
                                      (size_t)c->dims);
        c->ans_vals = out + done, c->ans_count = 1;
        cli_exchange(c, c->text, len, k, answer_numbers);
        done += k;
    }
}

/* The check asks for invert(x) one point at a time; the answers of the
 * batch's points came in one command, so it looks them up by value (in
 * the order asked, so the search is one step), and asks the program
 * directly for a point it was not given. */
void cli_invert_cached(const double *x, double *u, void *ctx)
{
    cli_app *c = ctx;
    int nu = c->s.uniforms, d = c->dims;
    for (size_t step = 0; step < c->inv_n; step++) {
        size_t i = (c->inv_at + step) % c->inv_n;
        if (memcmp(c->inv_x + i * 3, x, (size_t)d * sizeof *x) == 0) {
            memcpy(u, c->inv_u + i * (size_t)nu, (size_t)nu * sizeof *u);
            c->inv_at = i + 1;
            return;
        }
    }
    size_t len = cli_format_batch(c, APP_PROTO_INVERT, x, 1, d, 3);
    c->ans_vals = u, c->ans_count = nu;
    cli_exchange(c, c->text, len, 1, answer_numbers);
}

/* The inverses of a batch's finite non-atom points, before the check asks. */
static void invert_batch(cli_app *c, const mcbox_sample *smp, size_t k)
{
    c->inv_n = c->inv_at = 0;
    for (size_t i = 0; i < k; i++) {
        bool finite = smp[i].atom == -1;
        for (int j = 0; j < c->dims; j++)
            finite = finite && isfinite(smp[i].x[j]);
        if (finite) {
            double *x = c->inv_x + c->inv_n * 3;
            x[0] = smp[i].x[0], x[1] = c->dims > 1 ? smp[i].x[1] : 0.0;
            x[2] = c->dims > 2 ? smp[i].x[2] : 0.0;
            c->inv_n++;
        }
    }
    if (c->inv_n == 0)
        return;
    size_t len = cli_format_batch(c, APP_PROTO_INVERT, c->inv_x, c->inv_n, c->dims, 3);
    c->ans_vals = c->inv_u, c->ans_count = c->s.uniforms;
    cli_exchange(c, c->text, len, c->inv_n, answer_numbers);
}

int cli_run_exec(cli_app *c, mcbox_check_result *r, mcbox_check_table *t)
{
    int nu = c->s.uniforms;
    mcbox_check *chk = mcbox_check_begin(&c->s, &c->a.o, r);
    if (!chk)
        cli_fail("the check could not run: %s", r->message);
    cli_child_start(c, c->a.exec);
    cli_hello(c, nu);
    mcbox_sample *smp = malloc(CLI_BATCH * sizeof *smp);
    double *u = malloc(CLI_BATCH * (size_t)(nu ? nu : 1) * sizeof *u);
    if (!smp || !u)
        cli_child_fail(c, 0.0, "out of memory");
    for (uint64_t done = 0; done < c->a.o.samples;) {
        size_t k = (size_t)(c->a.o.samples - done < CLI_BATCH ? c->a.o.samples - done : CLI_BATCH), len;
        for (size_t i = 0; nu && i < k; i++)
            mcbox_check_uniforms(chk, u + i * (size_t)nu);
        if (nu)
            len = cli_format_batch(c, APP_PROTO_SAMPLE, u, k, nu, (size_t)nu);
        else
            len = cli_format_batch(c, APP_PROTO_DRAW, NULL, k, 0, 0);
        c->ans_smp = smp;
        cli_exchange(c, c->text, len, k, answer_sample);
        if (c->a.invert)
            invert_batch(c, smp, k);
        mcbox_check_add(chk, smp, nu ? u : NULL, k);
        done += k;
    }
    int rc = mcbox_check_finish(chk, r, t);
    cli_child_end(c, rc == 0);
    free(smp);
    free(u);
    return rc;
}
