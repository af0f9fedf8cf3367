/*
 * XDMF sidecars: "particles.xmf" beside particles.nc and "fields.xmf" beside
 * fields.nc, so that ParaView (or VisIt) opens the grains as points carrying
 * radius and velocity, and the fluid fields on their grid, over time,
 * without a conversion step.
 *
 * Why XDMF over the netCDF files rather than a copy. A netCDF-4 file is an
 * HDF5 file whose variables are HDF5 datasets of the same name, and XDMF
 * (eXtensible Data Model and Format, version 2, xdmf.org) describes a mesh
 * in XML whose arrays are references "file.h5:/dataset" into HDF5. The
 * sidecar therefore holds only the mesh description and the times; the
 * numbers stay in the one file that post-processing reads.
 *
 * particles.nc stores x(trajectory, time): a record is a column of that
 * array, which XDMF selects with a HyperSlab DataItem (start, stride, count
 * per dimension). The velocity vector is the JOIN of the u, v, w columns.
 * Grains form a Polyvertex topology (one point per grain). fields.nc stores
 * f(time, z, y, x) at cell centres of a uniform grid, a 3DCoRectMesh whose
 * node dimensions are one more than the cell counts, listed slowest first
 * (z, y, x), and whose origin and spacing are given in the same order.
 *
 * The sidecar is written from the closed, renamed netCDF file (times and
 * shapes read back from it), as "<name>.xmf.tmp" renamed into place, each
 * time that file is: a sidecar never names a dataset its file lacks.
 */
#include <netcdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/gf_nc_internal.h"

enum { MAX_VARS = 64 };

/* A variable of the file as the sidecar needs it. */
typedef struct nc_var {
    char name[NC_MAX_NAME + 1];
    const char *number_type; /* XDMF NumberType */
    int precision;           /* bytes */
    int ndims;
    size_t dims[4];
} nc_var;

typedef struct sidecar {
    FILE *f;
    const char *file;   /* netCDF file name, relative to the sidecar */
    size_t n_records;
    double *time_s;
    int n_vars;
    nc_var vars[MAX_VARS];
} sidecar;

static int xdmf_type(nc_type t, const char **number_type, int *precision)
{
    switch (t) {
    case NC_DOUBLE: *number_type = "Float", *precision = 8; return 1;
    case NC_FLOAT: *number_type = "Float", *precision = 4; return 1;
    case NC_BYTE: *number_type = "Char", *precision = 1; return 1;
    case NC_INT: *number_type = "Int", *precision = 4; return 1;
    case NC_INT64: *number_type = "Int", *precision = 8; return 1;
    default: return 0;
    }
}

static const nc_var *find_var(const sidecar *s, const char *name)
{
    for (int i = 0; i < s->n_vars; ++i)
        if (strcmp(s->vars[i].name, name) == 0)
            return &s->vars[i];
    return NULL;
}

/* Reads the variables' shapes and the time coordinate of the closed file. */
static gf_status read_layout(gf_ctx *ctx, const char *path, sidecar *s)
{
    int ncid, n_vars, rc = nc_open(path, NC_NOWRITE, &ncid);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "sidecar: cannot reopen %s: %s", path, nc_strerror(rc));
    rc = nc_inq_nvars(ncid, &n_vars);
    for (int iv = 0; rc == NC_NOERR && iv < n_vars && s->n_vars < MAX_VARS; ++iv) {
        nc_var *v = &s->vars[s->n_vars];
        nc_type t;
        int dimids[NC_MAX_VAR_DIMS];
        rc = nc_inq_var(ncid, iv, v->name, &t, &v->ndims, dimids, NULL);
        if (rc != NC_NOERR || v->ndims > 4 || !xdmf_type(t, &v->number_type, &v->precision))
            continue;
        for (int d = 0; d < v->ndims && rc == NC_NOERR; ++d)
            rc = nc_inq_dimlen(ncid, dimids[d], &v->dims[d]);
        s->n_vars++;
    }
    const nc_var *time = find_var(s, "time");
    if (rc == NC_NOERR && time) {
        s->n_records = time->dims[0];
        s->time_s = malloc((s->n_records ? s->n_records : 1) * sizeof *s->time_s);
        int var_time;
        rc = s->time_s ? nc_inq_varid(ncid, "time", &var_time) : NC_ENOMEM;
        if (rc == NC_NOERR && s->n_records > 0)
            rc = nc_get_var_double(ncid, var_time, s->time_s);
    }
    nc_close(ncid);
    if (rc != NC_NOERR)
        return GF_FAIL(ctx, GF_ERR_IO, "sidecar: reading the layout of %s: %s", path, nc_strerror(rc));
    if (!time)
        return GF_FAIL(ctx, GF_ERR_IO, "sidecar: %s has no time coordinate", path);
    return GF_OK;
}

static void put_dims(FILE *f, int n, const size_t *dims)
{
    for (int d = 0; d < n; ++d)
        fprintf(f, d ? " %zu" : "%zu", dims[d]);
}

/* The whole dataset v. */
static void put_dataset(const sidecar *s, const nc_var *v, const char *indent)
{
    fprintf(s->f, "%s<DataItem Dimensions=\"", indent);
    put_dims(s->f, v->ndims, v->dims);
    fprintf(s->f, "\" NumberType=\"%s\" Precision=\"%d\" Format=\"HDF\">%s:/%s</DataItem>\n", v->number_type,
            v->precision, s->file, v->name);
}

/* Record `record` of v, whose time dimension is `time_axis`: the other
 * dimensions whole. The result's Dimensions leave out the time axis. */
static void put_record(const sidecar *s, const nc_var *v, int time_axis, size_t record, const char *indent)
{
    size_t start[4] = {0}, stride[4] = {1, 1, 1, 1}, count[4], out[4];
    int n_out = 0;
    for (int d = 0; d < v->ndims; ++d) {
        count[d] = d == time_axis ? 1 : v->dims[d];
        start[d] = d == time_axis ? record : 0;
        if (d != time_axis)
            out[n_out++] = v->dims[d];
    }
    FILE *f = s->f;
    fprintf(f, "%s<DataItem ItemType=\"HyperSlab\" Dimensions=\"", indent);
    put_dims(f, n_out, out);
    fprintf(f, "\" Type=\"HyperSlab\">\n%s  <DataItem Dimensions=\"3 %d\" Format=\"XML\">", indent, v->ndims);
    put_dims(f, v->ndims, start);
    fputc(' ', f);
    put_dims(f, v->ndims, stride);
    fputc(' ', f);
    put_dims(f, v->ndims, count);
    fprintf(f, "</DataItem>\n");
    char deeper[64];
    snprintf(deeper, sizeof deeper, "%s  ", indent);
    put_dataset(s, v, deeper);
    fprintf(f, "%s</DataItem>\n", indent);
}

/* A vector attribute joined from three per-record components, when all
 * three exist. The JOIN's Dimensions are the record's shape with the three
 * components last (ParaView's XDMF reader fills only part of a flattened one). */
static void put_vector(const sidecar *s, const char *name, const char *const comp[3], int time_axis, size_t record,
                       const char *center)
{
    const nc_var *v[3] = {find_var(s, comp[0]), find_var(s, comp[1]), find_var(s, comp[2])};
    if (!v[0] || !v[1] || !v[2])
        return;
    fprintf(s->f,
            "      <Attribute Name=\"%s\" AttributeType=\"Vector\" Center=\"%s\">\n"
            "        <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1, $2)\" Dimensions=\"",
            name, center);
    for (int d = 0; d < v[0]->ndims; ++d)
        if (d != time_axis)
            fprintf(s->f, "%zu ", v[0]->dims[d]);
    fprintf(s->f, "3\">\n");
    for (int k = 0; k < 3; ++k)
        put_record(s, v[k], time_axis, record, "          ");
    fprintf(s->f, "        </DataItem>\n      </Attribute>\n");
}

static void put_header(FILE *f, const char *collection)
{
    fprintf(f, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n"
               "  <Domain>\n    <Grid Name=\"%s\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
            collection);
}

static void put_footer(FILE *f) { fprintf(f, "    </Grid>\n  </Domain>\n</Xdmf>\n"); }

/* The file's x, y, z variables into xyz; 0 when one is missing. */
static int find_xyz(const sidecar *s, const nc_var *xyz[3])
{
    static const char *const names[3] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c)
        if (!(xyz[c] = find_var(s, names[c])))
            return 0;
    return 1;
}

/* Writes the body of record k's grid (topology, geometry, attributes). */
typedef void record_writer(const sidecar *s, size_t k, const void *arg);

/* The temporal collection: one uniform grid "<collection>_<k>" at time_s[k]
 * per record, its body from put. */
static void put_collection(const sidecar *s, const char *collection, record_writer *put, const void *arg)
{
    put_header(s->f, collection);
    for (size_t k = 0; k < s->n_records; ++k) {
        fprintf(s->f, "    <Grid Name=\"%s_%zu\" GridType=\"Uniform\">\n      <Time Value=\"%.17g\"/>\n", collection,
                k, s->time_s[k]);
        put(s, k, arg);
        fprintf(s->f, "    </Grid>\n");
    }
    put_footer(s->f);
}

/* Record k of the grains: a Polyvertex of x, y, z (trajectory, time), the
 * velocity and the per-grain variables. arg: the x, y, z variables. */
static void put_grains_record(const sidecar *s, size_t k, const void *arg)
{
    const nc_var *const *xyz = arg;
    static const char *const vel[3] = {"u", "v", "w"};
    static const char *const per_grain[3] = {"radius", "glued", "trajectory_id"};
    fprintf(s->f,
            "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%zu\" NodesPerElement=\"1\"/>\n"
            "      <Geometry GeometryType=\"X_Y_Z\">\n",
            xyz[0]->dims[0]);
    for (int c = 0; c < 3; ++c)
        put_record(s, xyz[c], 1, k, "        ");
    fprintf(s->f, "      </Geometry>\n");
    put_vector(s, "velocity", vel, 1, k, "Node");
    for (int i = 0; i < 3; ++i) {
        const nc_var *v = find_var(s, per_grain[i]);
        if (!v || v->ndims != 1)
            continue;
        fprintf(s->f, "      <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n", v->name);
        put_dataset(s, v, "        ");
        fprintf(s->f, "      </Attribute>\n");
    }
}

/* Grains: one Polyvertex grid per record, x, y, z (trajectory, time). */
static gf_status put_particles(gf_ctx *ctx, const char *path, const sidecar *s)
{
    const nc_var *xyz[3];
    if (!find_xyz(s, xyz) || xyz[0]->ndims != 2)
        return GF_FAIL(ctx, GF_ERR_IO, "sidecar: %s has no x, y, z (trajectory, time)", path);
    put_collection(s, "grains", put_grains_record, xyz);
    return GF_OK;
}

typedef struct fluid_grid {
    const nc_var *xyz[3];           /* cell centres */
    const double *lo_m, *cell_m;    /* corner and cell size (x, y, z) */
} fluid_grid;

/* Record k of the fluid: a 3DCoRectMesh, every (time, z, y, x) variable a
 * cell attribute, the velocity joined. arg: the fluid_grid. */
static void put_fluid_record(const sidecar *s, size_t k, const void *arg)
{
    const fluid_grid *g = arg;
    static const char *const vel[3] = {"u_fluid", "v_fluid", "w_fluid"};
    fprintf(s->f,
            "      <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"%zu %zu %zu\"/>\n"
            "      <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
            "        <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
            "%.17g %.17g %.17g</DataItem>\n"
            "        <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
            "%.17g %.17g %.17g</DataItem>\n      </Geometry>\n",
            g->xyz[2]->dims[0] + 1, g->xyz[1]->dims[0] + 1, g->xyz[0]->dims[0] + 1, g->lo_m[2], g->lo_m[1],
            g->lo_m[0], g->cell_m[2], g->cell_m[1], g->cell_m[0]);
    for (int i = 0; i < s->n_vars; ++i) {
        const nc_var *v = &s->vars[i];
        if (v->ndims != 4)
            continue;
        fprintf(s->f, "      <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Cell\">\n", v->name);
        put_record(s, v, 0, k, "        ");
        fprintf(s->f, "      </Attribute>\n");
    }
    put_vector(s, "fluid_velocity", vel, 0, k, "Cell");
}

/* Fluid: one 3DCoRectMesh grid per record, every (time, z, y, x) variable
 * a cell attribute, and the velocity joined from u_fluid, v_fluid, w_fluid. */
static gf_status put_fields(gf_ctx *ctx, const char *path, const sidecar *s, const double lo_m[3],
                            const double cell_m[3])
{
    fluid_grid g = {.lo_m = lo_m, .cell_m = cell_m};
    if (!find_xyz(s, g.xyz))
        return GF_FAIL(ctx, GF_ERR_IO, "sidecar: %s has no x, y, z cell centres", path);
    put_collection(s, "fluid", put_fluid_record, &g);
    return GF_OK;
}

/* "<dir>/particles.nc" -> "<dir>/particles.xmf" (malloc'd). */
static char *sidecar_path(const char *path)
{
    size_t n = strlen(path);
    size_t stem = n > 3 && strcmp(path + n - 3, ".nc") == 0 ? n - 3 : n;
    char *out = malloc(stem + 5);
    if (out) {
        memcpy(out, path, stem);
        memcpy(out + stem, ".xmf", 5);
    }
    return out;
}

gf_status gf_nc_sidecar_write(gf_nc_writer *w)
{
    if (w->kind != GF_NC_PARTICLES && w->kind != GF_NC_FIELDS)
        return GF_OK;
    sidecar s = {0};
    const char *slash = strrchr(w->path, '/');
    s.file = slash ? slash + 1 : w->path;
    gf_status st = read_layout(w->ctx, w->path, &s);
    char *xmf = sidecar_path(w->path), *tmp = xmf ? malloc(strlen(xmf) + 5) : NULL;
    if (st == GF_OK && !tmp)
        st = GF_FAIL(w->ctx, GF_ERR_NOMEM, "sidecar for %s: out of memory", w->path);
    if (st == GF_OK) {
        sprintf(tmp, "%s.tmp", xmf);
        s.f = fopen(tmp, "w");
        if (!s.f)
            st = GF_FAIL(w->ctx, GF_ERR_IO, "sidecar: cannot create %s", tmp);
    }
    if (st == GF_OK) {
        st = w->kind == GF_NC_PARTICLES ? put_particles(w->ctx, w->path, &s)
                                        : put_fields(w->ctx, w->path, &s, w->grid_lo_m, w->grid_cell_m);
        int bad = ferror(s.f);
        if (fclose(s.f) != 0 || bad)
            st = st != GF_OK ? st : GF_FAIL(w->ctx, GF_ERR_IO, "sidecar: cannot write %s", tmp);
        if (st == GF_OK && rename(tmp, xmf) != 0)
            st = GF_FAIL(w->ctx, GF_ERR_IO, "sidecar: cannot rename %s to %s", tmp, xmf);
        if (st != GF_OK)
            remove(tmp);
    }
    free(s.time_s);
    free(tmp);
    free(xmf);
    return st;
}
