/* examples/common/outfile.c - write beside the target, rename when done. */
#define _POSIX_C_SOURCE 200809L

#include "examples/common/outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

bool app_outfile_open(app_outfile *o, const char *path)
{
    o->f = NULL;
    o->path = path;
    o->tmp = NULL;
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        errno = EISDIR;
        return false;
    }
    /* "dir/.name.XXXXXX": same directory, hidden, and unique (mkstemp). */
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    size_t size = strlen(path) + sizeof "/..XXXXXX";
    o->tmp = malloc(size);
    if (!o->tmp)
        return false;
    snprintf(o->tmp, size, "%.*s.%s.XXXXXX", (int)dir_len, path, path + dir_len);
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        int e = errno;
        free(o->tmp);
        o->tmp = NULL;
        errno = e;
        return false;
    }
    /* mkstemp makes the file 0600; give it the mode fopen would. */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || !(o->f = fdopen(fd, "wb"))) {
        int e = errno;
        close(fd);
        unlink(o->tmp);
        free(o->tmp);
        o->tmp = NULL;
        errno = e;
        return false;
    }
    return true;
}

void app_outfile_abort(app_outfile *o)
{
    int e = errno;
    if (o->f)
        fclose(o->f);
    if (o->tmp)
        unlink(o->tmp);
    free(o->tmp);
    o->f = NULL;
    o->tmp = NULL;
    errno = e;
}

bool app_outfile_commit(app_outfile *o)
{
    /* fsync before rename: otherwise a crash soon after could leave the new
     * name pointing at blocks the disk never received. */
    if (fflush(o->f) != 0 || ferror(o->f) || fsync(fileno(o->f)) != 0) {
        app_outfile_abort(o);
        return false;
    }
    int rc = fclose(o->f);
    o->f = NULL;
    if (rc != 0 || rename(o->tmp, o->path) != 0) {
        app_outfile_abort(o);
        return false;
    }
    free(o->tmp);
    o->tmp = NULL;
    return true;
}
