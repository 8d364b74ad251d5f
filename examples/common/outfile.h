/* examples/common/outfile.h - output files that are either the old file or
 * a complete new one, never a truncated mix.
 *
 * A program that writes its result after a long computation (the Cornell
 * box of chapters 9-11 renders for minutes) must not truncate the target
 * when it starts: a kill, a full disk or an allocation failure in between
 * would leave a 0-byte file where the previous result was. The data goes to
 * a temporary file in the target's directory (so that rename(2) stays on
 * one file system and is atomic), which replaces the target only once it
 * has been written, flushed and closed without error. Program code: POSIX
 * calls are fine here.
 */
#ifndef APP_OUTFILE_H
#define APP_OUTFILE_H

#include <stdbool.h>
#include <stdio.h>

typedef struct app_outfile {
    FILE *f;          /* the temporary file, open for writing */
    const char *path; /* the target, as given */
    char *tmp;        /* the temporary file's path (allocated) */
} app_outfile;

/* Creates the temporary file beside `path` (mode 0666 less the umask,
 * like fopen). False, with errno set, when it cannot: the directory is
 * missing or not writable, or `path` names a directory; nothing is
 * created then. */
bool app_outfile_open(app_outfile *o, const char *path);

/* Flushes, syncs and closes the temporary file, then renames it over the
 * target. False, with errno set, on any error; the temporary file is then
 * removed and the target left as it was. */
bool app_outfile_commit(app_outfile *o);

/* Closes and removes the temporary file; the target is left as it was. */
void app_outfile_abort(app_outfile *o);

#endif /* APP_OUTFILE_H */
