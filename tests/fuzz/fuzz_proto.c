/* tests/fuzz/fuzz_proto.c - libFuzzer target of the --exec protocol's
 * parsers (examples/common/exec_proto.h): the answers mcbox-check reads
 * from another program (ok, sample lines, numbers) and the commands `warp
 * serve` reads from mcbox-check.
 *
 * The first byte chooses the parser and its width (coordinates 1 to 3, or
 * 1 to 16 numbers); the rest is one line. Every parser must return, never
 * reading past the line (AddressSanitizer watches: the line is copied
 * without a terminating NUL), with either a result or a one-line message.
 * Built and run by `make fuzz`.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "examples/common/exec_proto.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void one_line(bool ok, const char *err)
{
    if (!ok && (err[0] == '\0' || memchr(err, '\n', strlen(err))))
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    /* mcbox-check splits the child's output at '\n', so a line holds none. */
    const uint8_t *nl = memchr(data + 1, '\n', size - 1);
    size_t len = nl ? (size_t)(nl - (data + 1)) : size - 1;
    char *line = malloc(len ? len : 1);
    if (!line)
        return 0;
    memcpy(line, data + 1, len);
    char err[256];
    err[0] = '\0';
    int which = data[0] % 4, width = data[0] / 4;
    switch (which) {
    case 0: one_line(app_proto_parse_ok(line, len, err, sizeof err), err); break;
    case 1: {
        mcbox_sample s;
        int dims = 1 + width % 3;
        bool ok = app_proto_parse_sample(line, len, dims, &s, err, sizeof err);
        if (ok && s.atom < -1)
            abort();
        one_line(ok, err);
        break;
    }
    case 2: {
        double v[16];
        one_line(app_proto_parse_numbers(line, len, 1 + width % 16, v, err, sizeof err), err);
        break;
    }
    default: {
        app_proto_request r;
        bool ok = app_proto_parse_command(line, len, &r, err, sizeof err);
        if (ok && r.cmd != APP_PROTO_HELLO && (r.k < 1 || r.k > APP_PROTO_MAX_BATCH))
            abort();
        if (ok && r.cmd == APP_PROTO_HELLO &&
            (r.dims < 1 || r.dims > 3 || r.uniforms < 0 || r.uniforms > MCBOX_MAX_UNIFORMS ||
             memchr(r.domain, '\0', sizeof r.domain) == NULL))
            abort();
        one_line(ok, err);
        break;
    }
    }
    free(line);
    return 0;
}
