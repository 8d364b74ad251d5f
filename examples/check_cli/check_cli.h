/* examples/check_cli/check_cli.h - the parts of `mcbox-check`, the
 * command-line door of mcbox/check.h (chapter 5, Generating Random
 * Directions, and chapter 16, Testing your own sampler): the options and
 * the sampler they describe (options.c), the child process that speaks the
 * protocol (child.c), the --exec door (exec.c), the --samples door
 * (samples.c), the reports (report.c) and the picture (plot.c).
 * examples/mcbox-check.c is the program: usage and main.
 *
 * Every bad input ends in cli_fail: one line "mcbox-check: ..." on stderr
 * and exit 2, and, when --json or --junit was asked for, the error case
 * written there too (CI reads a missing report as "no report").
 */
#ifndef CHECK_CLI_H
#define CHECK_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "catalog/catalog.h"
#include "check/check.h"
#include "examples/common/exec_proto.h"
#include "examples/common/outfile.h"
#include "examples/common/sample_reader.h"

#define CLI_PROG "mcbox-check"
/* --param options, and "k=v" assignments over all of them. */
#define CLI_MAX_PARAMS 32
#define CLI_MAX_ATOMS 64
#define CLI_BATCH APP_PROTO_MAX_BATCH
/* Bytes of a program's stderr kept for the message when it fails. */
#define CLI_TAIL 1024

typedef struct cli_args {
    const char *exec, *samples, *pdf, *pdf_exec, *domain, *interval, *name, *junit, *plot;
    const char *params[CLI_MAX_PARAMS], *atoms[CLI_MAX_ATOMS];
    int n_params, n_atoms;
    app_samples_format format;
    int uniforms;
    bool have_uniforms, have_n, have_seed, have_format, have_timeout, invert, json;
    uint64_t n;
    double timeout;
    mcbox_check_options o;
} cli_args;

/* The child process that speaks the protocol. */
typedef struct cli_child {
    const char *cmd;
    pid_t pid;             /* 0: none, or reaped */
    int in, out, err;      /* our ends of its stdin, stdout, stderr (-1: closed) */
    char rbuf[1 << 16];    /* its stdout, read but not yet split into lines */
    size_t rpos, rlen;
    char line[APP_PROTO_MAX_LINE + 1];
    size_t line_len;
    char tail[CLI_TAIL];   /* the end of its stderr */
    size_t tail_len;
    int status;            /* waitpid's, once reaped */
    bool reaped;
} cli_child;

typedef struct cli_app {
    cli_args a;
    mcbox_sampler s;
    int dims;
    char domain_word[64]; /* DOMAIN of hello */
    char params[1024];    /* the --param assignments of a catalog row, "k=v k=v" */
    char param_store[2048]; /* the assignments of every --param, NUL-separated ... */
    const char *assign[CLI_MAX_PARAMS]; /* ... one each */
    int n_assign;
    bool uniforms_from_row; /* UNIFORMS is the catalog row's, not --uniforms */
    cli_child ch;
    bool have_child;
    app_outfile junit;
    bool junit_open;
    char *text;           /* a command's text */
    size_t text_cap;
    uint64_t batch;       /* commands sent after hello */
    uint64_t sample_batches; /* of them, sample or draw commands */
    char where[160];      /* the command being answered, for messages */
    /* invert answers of the current batch, looked up by point */
    double inv_x[CLI_BATCH * 3], inv_u[CLI_BATCH * MCBOX_MAX_UNIFORMS];
    size_t inv_n, inv_at;
    double atom_x[CLI_MAX_ATOMS * 3], atom_mass[CLI_MAX_ATOMS];
    cat_state *row_state; /* --pdf: the row's density */
    /* where the answers of the exchange under way go */
    mcbox_sample *ans_smp;
    double *ans_vals;
    int ans_count;
    /* --samples: the file's points */
    mcbox_sample *points;
    uint64_t n_points;
    double t0;            /* when the check started, for JUnit's time */
    char note[320];       /* said on stderr and in the reports: the program was slow to exit */
} cli_app;

/* --- options.c ------------------------------------------------------------ */

/* The options of argv, checked for what each door takes; exits 2 (through
 * cli_fail) on anything malformed. */
cli_args cli_parse(int argc, char **argv);

/* The sampler the options describe (callbacks included) into c->s. */
void cli_setup(cli_app *c);

/* --- report.c ------------------------------------------------------------- */

/* From now on, cli_fail writes the error case in c's --json and --junit. */
void cli_report_errors_to(cli_app *c);

/* Before the options are parsed: what argv asks of the reports (--json,
 * --junit FILE, --name NAME), so that an error in the options is reported
 * there too. */
void cli_report_prescan(int argc, char **argv);

/* One line "mcbox-check: message" on stderr, the error case in --json and
 * --junit, exit 2. */
_Noreturn void cli_fail(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* The verdict's word: "pass", "fail" or "undetermined". */
const char *cli_verdict(const mcbox_check_result *r);

void cli_print_json(FILE *f, const cli_app *c, const mcbox_check_result *r,
                    const mcbox_check_table *t);
void cli_print_summary(FILE *f, const cli_app *c, const mcbox_check_result *r);
/* The result as a JUnit suite of one case into the open --junit file. */
bool cli_write_junit(cli_app *c, const mcbox_check_result *r, double seconds);

/* The pieces of the reports the image door shares: a JSON string, a
 * ", key: value" member (null for a non-finite number), and a JUnit suite
 * of one case (<failure> for "fail", <error> for any verdict but "pass";
 * summary and err_text may be NULL). */
void cli_json_string(FILE *f, const char *s);
void cli_json_key_string(FILE *f, const char *key, const char *v);
void cli_json_number(FILE *f, const char *key, double v);
void cli_json_vector(FILE *f, const char *key, const double *v, int n);
void cli_junit_suite(FILE *f, const char *name, const char *verdict, const char *message,
                     const char *summary, const char *err_text, double seconds);

/* --- image.c: the image door (mcbox/image.h) --------------------------------- */

/* mcbox-check --image ...: reads the renders and the truth, runs
 * mcbox_image_check, reports; returns the exit status (0 pass, 1 fail; every
 * error exits 2 through cli_fail). */
int cli_image_main(int argc, char **argv);

/* What the image reports say besides the result. */
typedef struct cli_image_info {
    const char *name, *truth; /* the render's name; the scene or truth file */
    int renders, width, height; /* renders: 0 for a moment pair */
    double truth_error;
    double seconds;
} cli_image_info;

/* --- image_report.c ---------------------------------------------------------- */

/* The summary on stdout (or the JSON object with json), the JUnit suite
 * in junit and the picture of the block z values in picture (.png or
 * .ppm), each when asked for; a file that cannot be written is a
 * warning on stderr. */
struct mcbox_image_result;
void cli_image_report(const cli_image_info *info, const struct mcbox_image_result *r, bool json,
                      const char *junit, const char *picture);

/* --- plot.c ---------------------------------------------------------------- */

/* DIR/NAME.dat and DIR/NAME.png (gnuplot); a failure is a warning. */
void cli_plot(const cli_app *c, const mcbox_check_table *t, const mcbox_check_result *r);

/* --- child.c ---------------------------------------------------------------- */

double cli_now(void);

/* Starts /bin/sh -c cmd in its own process group, pipes on its stdio. */
void cli_child_start(cli_app *c, const char *cmd);

/* The program broke the protocol: kill and reap it, one line naming the
 * command, where it was and what went wrong, exit 2. `grace` seconds let
 * a program that is ending anyway report its own status. */
_Noreturn void cli_child_fail(cli_app *c, double grace, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Called with each answer line (i from 0); false with the reason. */
typedef bool (*cli_answer_fn)(cli_app *c, size_t i, const char *line, size_t len, char *err,
                              size_t errlen);

/* Writes text[0 .. n) to the child while reading k answer lines. */
void cli_exchange(cli_app *c, const char *text, size_t n, size_t k, cli_answer_fn fn);

/* "cmd K" and K lines of m numbers of v (stride apart) into c->text; the
 * length. */
size_t cli_format_batch(cli_app *c, app_proto_cmd cmd, const double *v, size_t k, int m,
                        size_t stride);

/* Closes the program's stdin and waits for it to exit 0 without writing
 * more. With verdict_reached, a program still running after --timeout is
 * killed and the verdict kept (c->note says so); otherwise that is an
 * error. */
void cli_child_end(cli_app *c, bool verdict_reached);

/* --- exec.c and samples.c ---------------------------------------------------- */

void cli_hello(cli_app *c, int uniforms);
/* The density over the pipe (mcbox_sampler.pdf_batch). */
void cli_pdf_batch(const double *x, size_t n, double *out, void *ctx);
void cli_invert_cached(const double *x, double *u, void *ctx);
int cli_run_exec(cli_app *c, mcbox_check_result *r, mcbox_check_table *t);

void cli_load_samples(cli_app *c);
int cli_run_samples(cli_app *c, mcbox_check_result *r, mcbox_check_table *t);

#endif /* CHECK_CLI_H */
