/* tests/support/picture_files.c - see picture_files.h. */
#define _XOPEN_SOURCE 700 /* mkdtemp */
#include "tests/support/mc_test.h"

#include "tests/support/picture_files.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];

/* A path in this run's temporary directory. */
const char *path_of(const char *name)
{
    static char p[sizeof dir + 1 + 256]; /* 256: a directory entry's longest name */
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return p;
}

const char *write_bytes(const char *name, const void *b, size_t n)
{
    const char *p = path_of(name);
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(b, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
    return p;
}

/* The first n bytes (at most 4096) of a file written before, cut. */
const char *cut_copy(const char *from, const char *to, size_t cut)
{
    unsigned char b[4096];
    FILE *f = fopen(path_of(from), "rb");
    assert_non_null(f);
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    return write_bytes(to, b, n - cut);
}

/* The 4 bytes of the float whose IEEE bits are u, in either order. */
void put_bits(unsigned char *q, uint32_t u, int little)
{
    for (int j = 0; j < 4; j++)
        q[j] = (unsigned char)(u >> 8 * (little ? j : 3 - j));
}

/* Reads path, which must fail with a reason starting with want and
 * leave the picture empty. */
void refused(const char *path, img_transfer t, const char *want)
{
    img_picture p;
    char why[256] = "";
    assert_int_equal(img_picture_read(path, t, &p, why, sizeof why), -1);
    if (strncmp(why, want, strlen(want)) != 0)
        fail_msg("reason '%s', expected '%s...'", why, want);
    assert_true(!p.value && !p.lo && !p.hi && p.width == 0 && p.height == 0);
}

void read_ok(const char *path, img_transfer t, img_picture *p)
{
    char why[256] = "";
    if (img_picture_read(path, t, p, why, sizeof why) != 0)
        fail_msg("%s: %s", path, why);
}

int make_dir(void **state)
{
    (void)state;
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/mcbox_image_io_XXXXXX", tmp && strlen(tmp) < 32 ? tmp : "/tmp");
    return mkdtemp(dir) ? 0 : -1;
}

int remove_dir(void **state)
{
    (void)state;
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d));)
        if (e->d_name[0] != '.')
            remove(path_of(e->d_name));
    if (d)
        closedir(d);
    return rmdir(dir);
}

