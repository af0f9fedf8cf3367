/*
 * Files for tests: a whole netCDF variable as doubles, and a count of the
 * files a shell pattern matches (run directories, kept deposits).
 */
#ifndef GF_TEST_FILES_H
#define GF_TEST_FILES_H

#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>

/* Variable name of the netCDF file path, all its values; NULL when unreadable
 * (*n then undefined). Owner: the caller (free). */
static inline double *gf_test_nc_read(const char *path, const char *name, size_t *n)
{
    int nc, var, ndims, dims[NC_MAX_VAR_DIMS];
    double *v = NULL;
    *n = 1;
    if (nc_open(path, NC_NOWRITE, &nc) != NC_NOERR)
        return NULL;
    if (nc_inq_varid(nc, name, &var) == NC_NOERR && nc_inq_varndims(nc, var, &ndims) == NC_NOERR &&
        nc_inq_vardimid(nc, var, dims) == NC_NOERR) {
        for (int d = 0; d < ndims; ++d) {
            size_t len = 0;
            nc_inq_dimlen(nc, dims[d], &len);
            *n *= len;
        }
        v = malloc(*n * sizeof *v);
        if (v && nc_get_var_double(nc, var, v) != NC_NOERR) {
            free(v);
            v = NULL;
        }
    }
    nc_close(nc);
    return v;
}

/* Number of files matching the shell pattern (e.g. "DIR/packing-*.h5"). */
static inline size_t gf_test_count_files(const char *pattern)
{
    char cmd[4500];
    snprintf(cmd, sizeof cmd, "ls %s 2>/dev/null | wc -l", pattern);
    FILE *f = popen(cmd, "r");
    size_t n = 0;
    if (f) {
        if (fscanf(f, "%zu", &n) != 1)
            n = 0;
        pclose(f);
    }
    return n;
}

#endif
