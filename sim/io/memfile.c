/* memfile.c - a chip's non-volatile memory kept in a file (memfile.h). */
#include "memfile.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "infile.h"
#include "outfile.h"

/* The file's bytes into mem: 0, or -1 with one line in err. */
static int read_image(const char *path, uint8_t *mem, size_t size, const char *what, char *err, size_t errn)
{
    uint64_t fsize = 0;
    FILE *f = infile_open(path, INFILE_NO_LIMIT, &fsize, err, errn);
    if (!f) return -1;
    int rc = -1;
    if (fsize != size)
        snprintf(err, errn, "%s: %llu bytes, the %s holds %zu (the file is a raw image of all of it)", path,
                 (unsigned long long)fsize, what, size);
    else if (fread(mem, 1, size, f) != size)
        snprintf(err, errn, "%s: cannot read: %s", path, ferror(f) ? strerror(errno) : "shorter than it was");
    else rc = 0;
    fclose(f);
    return rc;
}

int memfile_load(const char *path, uint8_t *mem, size_t size, uint8_t erased, const char *what, char *err,
                 size_t errn)
{
    struct stat st;
    if (stat(path, &st) != 0 && errno == ENOENT) memset(mem, erased, size); /* a blank chip */
    else if (read_image(path, mem, size, what, err, errn) != 0) return -1;
    return outfile_probe(path, err, errn);
}

int memfile_save(const char *path, const uint8_t *mem, size_t size, char *err, size_t errn)
{
    outfile_t o;
    if (outfile_open(&o, path, err, errn) != 0) return -1;
    if (fwrite(mem, 1, size, o.f) != size) {
        snprintf(err, errn, "%s: cannot write: %s", path, strerror(errno));
        outfile_abort(&o);
        return -1;
    }
    return outfile_commit(&o, err, errn);
}
