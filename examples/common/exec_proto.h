/* examples/common/exec_proto.h - the text protocol between `mcbox-check
 * --exec CMD` and a sampler in another process, in any language (chapter
 * 5, Generating Random Directions: every warp, tested from outside).
 * docs/check-protocol.md is the user's description; this is its one
 * implementation, for both ends: mcbox-check formats commands and parses
 * answers, `warp serve` parses commands and formats answers.
 *
 * mcbox-check writes commands to the program's stdin and reads one answer
 * line per item from its stdout:
 *
 *   hello 1 DOMAIN DIMS UNIFORMS SEED   -> ok
 *   sample K, then K lines of UNIFORMS numbers
 *                                       -> K lines: DIMS coordinates
 *                                          [pdf [weight]], or "atom J"
 *   draw K                              -> K lines as for sample
 *   pdf K, then K lines of DIMS numbers -> K lines of one density
 *   invert K, then K lines of DIMS numbers -> K lines of UNIFORMS numbers
 *
 * Instead of an answer a program may write "error MESSAGE" and stop. K is
 * 1 .. APP_PROTO_MAX_BATCH. Numbers are decimal text (written with %.17g,
 * read with strtod: "nan" and "inf" are numbers here; what a non-finite
 * coordinate means is the check's business), separated by spaces, tabs or
 * commas; a line may end in CR LF.
 *
 * Nothing here does I/O: every function takes a line in memory (not
 * NUL-terminated, without its '\n') or fills a buffer, so that a fuzzer can
 * drive it. Errors come back as one line (no newline) in err.
 */
#ifndef APP_EXEC_PROTO_H
#define APP_EXEC_PROTO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "check/check.h"

#define APP_PROTO_VERSION 1
/* The most items of one command: a batch's text stays within a pipe's
 * few hundred kilobytes and a program's reply to one command is bounded. */
#define APP_PROTO_MAX_BATCH 4096
/* Longer answer lines are garbage, not numbers: five %.17g numbers take
 * under 130 characters. */
#define APP_PROTO_MAX_LINE 4096

typedef enum app_proto_cmd {
    APP_PROTO_HELLO,
    APP_PROTO_SAMPLE,
    APP_PROTO_DRAW,
    APP_PROTO_PDF,
    APP_PROTO_INVERT
} app_proto_cmd;

/* The command's word ("hello", "sample", ...). */
const char *app_proto_cmd_name(app_proto_cmd c);

/* --- mcbox-check's side --------------------------------------------------- */

/* "hello 1 DOMAIN DIMS UNIFORMS SEED\n" into buf. DOMAIN is one word (a
 * domain name or a catalog row: no blanks, at most 63 bytes); dims 1 .. 3,
 * uniforms 0 .. MCBOX_MAX_UNIFORMS. Returns the length, or 0 when an
 * argument is out of range or the text does not fit. */
size_t app_proto_format_hello(char *buf, size_t size, const char *domain, int dims, int uniforms,
                              uint64_t seed);

/* "sample K\n" (or draw, pdf, invert) into buf, K in 1 .. APP_PROTO_MAX_BATCH;
 * the length, or 0. */
size_t app_proto_format_command(char *buf, size_t size, app_proto_cmd c, size_t k);

/* v[0 .. n) as one line of %.17g numbers separated by spaces, ending in
 * '\n'; the length, or 0 when it does not fit (n * 25 + 1 bytes always do). */
size_t app_proto_format_numbers(char *buf, size_t size, const double *v, int n);

/* The answer to hello: "ok". False with the reason otherwise. */
bool app_proto_parse_ok(const char *line, size_t len, char *err, size_t errlen);

/* The answer to one sample or draw item into *out: dims coordinates, then
 * optionally the pdf, then optionally the weight (those not given are NaN),
 * atom -1; or "atom J" (J a whole number from 0 to 2^31 - 1), which sets
 * out->atom = J and leaves the rest to the caller. False with the reason
 * for anything else. */
bool app_proto_parse_sample(const char *line, size_t len, int dims, mcbox_sample *out, char *err,
                            size_t errlen);

/* Exactly `count` (1 .. 16) numbers into out: an answer to pdf (count 1)
 * or invert (count UNIFORMS), or one item line of a command (warp serve's
 * side). False with the reason otherwise. */
bool app_proto_parse_numbers(const char *line, size_t len, int count, double *out, char *err,
                             size_t errlen);

/* --- the program's side --------------------------------------------------- */

typedef struct app_proto_request {
    app_proto_cmd cmd;
    size_t k;              /* items to follow (1 .. APP_PROTO_MAX_BATCH); 0 for hello */
    int version;           /* hello: the protocol version */
    char domain[64];       /* hello */
    int dims, uniforms;    /* hello */
    uint64_t seed;         /* hello */
} app_proto_request;

/* One command line into *r. False with the reason for an unknown command,
 * a count out of range, or a hello with missing, extra or malformed
 * fields (dims 1 .. 3, uniforms 0 .. MCBOX_MAX_UNIFORMS, the seed in
 * 0 .. 2^64 - 1 as digits). The version is not checked: the program
 * decides which it speaks. */
bool app_proto_parse_command(const char *line, size_t len, app_proto_request *r, char *err,
                             size_t errlen);

#endif /* APP_EXEC_PROTO_H */
