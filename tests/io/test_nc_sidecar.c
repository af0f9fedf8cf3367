/*
 * XDMF sidecars (particles.xmf, fields.xmf). The writers record grains that
 * move ballistically and analytic fluid fields; the test then reads each
 * sidecar as a viewer would: it parses the XML (libxml2), opens every HDF5
 * dataset it names with the HDF5 C API, checks that the dataset exists with
 * the dimensions and number type the sidecar states, that every hyperslab
 * lies inside its dataset, and reads the selections: grid k of the temporal
 * collection must give the grains' positions and velocities, and the fields'
 * values, of record k at the time of record k, and the fluid grid's origin
 * and spacing must be the writer's. A second close of a shorter file must
 * replace the sidecar (fewer steps), leaving no temporary file.
 *
 * With an argument (a pvpython), it also opens both sidecars with ParaView
 * (check_xdmf_paraview.py) and checks point and cell counts, array names,
 * bounds and times; exit code 77 (skipped) when no pvpython was found.
 */
#include <hdf5.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gf_test.h"
#include "nc_check.h"

enum { N = 7, NT = 3, NX = 5, NY = 4, NZ = 3, NV = 5, MAXD = 4 };
static const double times[NT] = {0.0, 0.025, 0.05};
static const double lo[3] = {-0.01, 0.0, 0.002}, h[3] = {0.004, 0.0025, 0.003};

/* grains: trajectory k has id k */
static double grain(int comp, int k, double t)
{
    switch (comp) {
    case 0: return 0.01 * k + 0.1 * k * t;
    case 1: return 0.02 + 0.003 * k + 0.5 * t - 4.905 * t * t;
    case 2: return -0.001 * k;
    case 3: return 0.1 * k;
    case 4: return 0.5 - 9.81 * t;
    default: return 0.002 * k * t;
    }
}
static void start(int k, double x[3])
{
    for (int c = 0; c < 3; ++c)
        x[c] = grain(c, k, 0);
}

static double centre(int axis, int i) { return lo[axis] + (i + 0.5) * h[axis]; }
static double field(int iv, int i, int j, int k, double t)
{
    double x = centre(0, i), y = centre(1, j), z = centre(2, k);
    switch (iv) {
    case 0: return 1.0 - 0.4 * exp(-y / 0.003);
    case 1: return (1 + t) * 40.0 * y * (0.01 - y);
    case 2: return 1e-3 * x;
    case 3: return 1e-3 * z * (1 + t);
    default: return 9.81 * 1000.0 * (0.01 - y) * (1 + 0.1 * t);
    }
}

static void write_particles(const char *path, int n_records)
{
    nc_test_run run;
    nc_test_run_init(&run);
    gf_ctx ctx = {0};
    gf_particles *p = nc_test_particles(&ctx, N, start);
    gf_nc_writer *w = NULL;
    GF_CHECK_OK(gf_nc_particles_open(&ctx, path, &run.meta, p, &w), &ctx);
    for (int it = 0; it < n_records; ++it) {
        for (size_t i = 0; i < p->n_local; ++i) {
            int k = (int)p->id[i];
            double *dst[6] = {p->x_m, p->y_m, p->z_m, p->vx_m_s, p->vy_m_s, p->vz_m_s};
            for (int c = 0; c < 6; ++c)
                dst[c][i] = grain(c, k, times[it]);
        }
        GF_CHECK_OK(gf_nc_particles_append(w, times[it], p), &ctx);
    }
    GF_CHECK_OK(gf_nc_writer_close(&w), &ctx);
    gf_particles_destroy(&p);
}

static double field_of_record(int iv, int i, int j, int k, int it) { return field(iv, i, j, k, times[it]); }

static void write_fields(const char *path)
{
    nc_test_run run;
    nc_test_run_init(&run);
    const int n_cells[3] = {NX, NY, NZ};
    nc_test_write_fluid_fields(path, &run.meta, n_cells, lo, h, NT, times, field_of_record);
}

/* ------------------------------------------------------------ reading the sidecar */

static int is(const xmlNode *n, const char *name) { return n->type == XML_ELEMENT_NODE && !strcmp((const char *)n->name, name); }

static char *attr(const xmlNode *n, const char *name) { return (char *)xmlGetProp(n, (const xmlChar *)name); }

static int parse_sizes(const char *text, size_t *out, int max)
{
    int n = 0;
    char *end;
    for (const char *s = text; n < max; s = end) {
        unsigned long long v = strtoull(s, &end, 10);
        if (end == s)
            break;
        out[n++] = (size_t)v;
    }
    return n;
}

static xmlNode *child(const xmlNode *n, const char *name, int index)
{
    for (xmlNode *c = n->children; c; c = c->next)
        if (is(c, name) && index-- == 0)
            return c;
    return NULL;
}

static size_t product(const size_t *d, int n)
{
    size_t p = 1;
    for (int i = 0; i < n; ++i)
        p *= d[i];
    return p;
}

/* An HDF DataItem: "file:/dataset", opened relative to dir. Checks that the
 * dataset exists with the stated Dimensions, NumberType and Precision. On
 * success returns the open dataset and its dimensions. */
static hid_t open_hdf_item(const xmlNode *item, const char *dir, hid_t *file, hsize_t *dims, int *rank)
{
    char *text = (char *)xmlNodeGetContent(item), *stated = attr(item, "Dimensions");
    char *type = attr(item, "NumberType"), *prec = attr(item, "Precision");
    char *colon = text ? strstr(text, ":/") : NULL;
    hid_t ds = H5I_INVALID_HID;
    *file = H5I_INVALID_HID;
    if (!colon || !stated || !type || !prec) {
        gf_test_check(0, __FILE__, __LINE__, "HDF DataItem without file:/dataset, Dimensions or type: %s",
                      text ? text : "(none)");
        goto done;
    }
    *colon = '\0';
    char *name = text + strspn(text, " \n\t");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    *file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    ds = *file >= 0 ? H5Dopen2(*file, colon + 1, H5P_DEFAULT) : H5I_INVALID_HID;
    gf_test_check(ds >= 0, __FILE__, __LINE__, "dataset %s:%s named by the sidecar opens", path, colon + 1);
    if (ds < 0)
        goto done;
    hid_t space = H5Dget_space(ds), dtype = H5Dget_type(ds);
    *rank = H5Sget_simple_extent_ndims(space);
    H5Sget_simple_extent_dims(space, dims, NULL);
    size_t want[MAXD];
    int n_want = parse_sizes(stated, want, MAXD);
    int same = n_want == *rank;
    for (int d = 0; same && d < *rank; ++d)
        same = want[d] == dims[d];
    gf_test_check(same, __FILE__, __LINE__, "%s: stated Dimensions \"%s\", dataset rank %d dims[0] %llu",
                  colon + 1, stated, *rank, (unsigned long long)dims[0]);
    H5T_class_t cls = H5Tget_class(dtype);
    int want_float = !strcmp(type, "Float");
    gf_test_check((cls == H5T_FLOAT) == want_float && (cls == H5T_INTEGER) == !want_float, __FILE__, __LINE__,
                  "%s: NumberType %s matches the dataset's class", colon + 1, type);
    gf_test_check(H5Tget_size(dtype) == (size_t)atoi(prec), __FILE__, __LINE__, "%s: Precision %s, size %zu",
                  colon + 1, prec, H5Tget_size(dtype));
    H5Tclose(dtype);
    H5Sclose(space);
done:
    xmlFree(text), xmlFree(stated), xmlFree(type), xmlFree(prec);
    return ds;
}

/* Reads a DataItem (HDF, HyperSlab over HDF, or XML) as doubles. */
static double *read_item(const xmlNode *item, const char *dir, size_t *n)
{
    char *itype = attr(item, "ItemType"), *format = attr(item, "Format");
    double *out = NULL;
    *n = 0;
    if (format && !strcmp(format, "XML")) {
        char *text = (char *)xmlNodeGetContent(item);
        out = malloc(64 * sizeof *out);
        char *end;
        for (const char *s = text; *n < 64; s = end) {
            double v = strtod(s, &end);
            if (end == s)
                break;
            out[(*n)++] = v;
        }
        xmlFree(text);
    } else {
        int slab = itype && !strcmp(itype, "HyperSlab");
        const xmlNode *hdf = slab ? child(item, "DataItem", 1) : item;
        hid_t file, ds;
        hsize_t dims[MAXD];
        int rank = 0;
        if (hdf && (ds = open_hdf_item(hdf, dir, &file, dims, &rank)) >= 0) {
            hid_t space = H5Dget_space(ds);
            hsize_t count[MAXD];
            for (int d = 0; d < rank; ++d)
                count[d] = dims[d];
            if (slab) {
                size_t sel[3 * MAXD], outer[MAXD];
                char *text = (char *)xmlNodeGetContent(child(item, "DataItem", 0));
                char *od = attr(item, "Dimensions");
                int n_sel = parse_sizes(text, sel, 3 * MAXD), n_outer = parse_sizes(od, outer, MAXD);
                xmlFree(text), xmlFree(od);
                GF_CHECK(n_sel == 3 * rank);
                hsize_t start[MAXD], stride[MAXD];
                int inside = 1;
                for (int d = 0; d < rank && n_sel == 3 * rank; ++d) {
                    start[d] = sel[d], stride[d] = sel[rank + d], count[d] = sel[2 * rank + d];
                    inside &= count[d] >= 1 && start[d] + (count[d] - 1) * stride[d] < dims[d];
                }
                gf_test_check(inside, __FILE__, __LINE__, "hyperslab inside its dataset");
                gf_test_check(product(outer, n_outer) == product((size_t *)count, rank), __FILE__, __LINE__,
                              "hyperslab result Dimensions hold the selected count");
                if (inside)
                    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, stride, count, NULL);
            }
            *n = product((size_t *)count, rank);
            out = malloc((*n ? *n : 1) * sizeof *out);
            hid_t mem = H5Screate_simple(1, (hsize_t[]){*n}, NULL);
            GF_CHECK(H5Dread(ds, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, out) >= 0);
            H5Sclose(mem);
            H5Sclose(space);
            H5Dclose(ds);
            H5Fclose(file);
        }
    }
    xmlFree(itype), xmlFree(format);
    return out;
}

/* The attribute of grid g named name: its values (the JOIN of its items for a vector, interlaced). */
static double *read_attribute(const xmlNode *grid, const char *name, const char *dir, size_t *n)
{
    *n = 0;
    for (xmlNode *a = grid->children; a; a = a->next) {
        if (!is(a, "Attribute"))
            continue;
        char *an = attr(a, "Name");
        int match = an && !strcmp(an, name);
        xmlFree(an);
        if (!match)
            continue;
        xmlNode *item = child(a, "DataItem", 0);
        char *itype = attr(item, "ItemType");
        int join = itype && !strcmp(itype, "Function");
        xmlFree(itype);
        if (!join)
            return read_item(item, dir, n);
        size_t nc[3];
        double *c[3];
        for (int k = 0; k < 3; ++k)
            c[k] = read_item(child(item, "DataItem", k), dir, &nc[k]);
        double *out = NULL;
        if (c[0] && c[1] && c[2] && nc[0] == nc[1] && nc[1] == nc[2]) {
            *n = 3 * nc[0];
            out = malloc(*n * sizeof *out);
            for (size_t i = 0; i < nc[0]; ++i)
                for (int k = 0; k < 3; ++k)
                    out[3 * i + (size_t)k] = c[k][i];
        }
        free(c[0]), free(c[1]), free(c[2]);
        return out;
    }
    return NULL;
}

/* The temporal collection's steps; checks their count and times. */
static int steps(xmlDoc *doc, xmlNode **grids, int max, int n_expect)
{
    xmlNode *root = xmlDocGetRootElement(doc), *domain = root ? child(root, "Domain", 0) : NULL;
    xmlNode *coll = domain ? child(domain, "Grid", 0) : NULL;
    char *ct = coll ? attr(coll, "CollectionType") : NULL;
    GF_CHECK(ct && !strcmp(ct, "Temporal"));
    xmlFree(ct);
    int n = 0;
    for (xmlNode *g = coll ? coll->children : NULL; g && n < max; g = g->next) {
        if (!is(g, "Grid"))
            continue;
        char *tv = attr(child(g, "Time", 0), "Value");
        gf_test_check(tv && n < NT && strtod(tv, NULL) == times[n], __FILE__, __LINE__, "step %d time %s", n,
                      tv ? tv : "(none)");
        xmlFree(tv);
        grids[n++] = g;
    }
    gf_test_check(n == n_expect, __FILE__, __LINE__, "%d steps in the sidecar, %d records written", n, n_expect);
    return n;
}

/* dir/name parsed as XML (checked); NULL when it does not parse. Owner: the caller (xmlFreeDoc). */
static xmlDoc *read_sidecar(const char *dir, const char *name)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    xmlDoc *doc = xmlReadFile(path, NULL, XML_PARSE_NONET);
    gf_test_check(doc != NULL, __FILE__, __LINE__, "%s parses as XML", path);
    return doc;
}

/* The values read through one step of a sidecar (grid, record time t) that
 * are the record's: *n_exact of *n_values (both incremented). */
typedef void (*step_check_fn)(xmlNode *grid, const char *dir, double t, int *n_exact, int *n_values);

/* Every step of dir/name (n_records of them, checked), each holding
 * values_per_step values (what: their kind in the printed line). */
static void check_sidecar(const char *dir, const char *name, int n_records, step_check_fn check_step,
                          int values_per_step, const char *what)
{
    xmlDoc *doc = read_sidecar(dir, name);
    if (!doc)
        return;
    xmlNode *grids[NT];
    int n = steps(doc, grids, NT, n_records);
    int n_exact = 0, n_values = 0;
    for (int it = 0; it < n; ++it)
        check_step(grids[it], dir, times[it], &n_exact, &n_values);
    gf_test_check(n_exact == n_values && n_values == n * values_per_step, __FILE__, __LINE__,
                  "%s: %d of %d %s values read through the sidecar are the record's", name, n_exact, n_values, what);
    xmlFreeDoc(doc);
}

/* A particles step: N grains, positions, velocities, radii, the glued flag. */
static void check_grain_step(xmlNode *grid, const char *dir, double t, int *n_exact, int *n_values)
{
    xmlNode *topo = child(grid, "Topology", 0), *geom = child(grid, "Geometry", 0);
    char *ne = attr(topo, "NumberOfElements"), *tt = attr(topo, "TopologyType");
    GF_CHECK(ne && atoi(ne) == N && tt && !strcmp(tt, "Polyvertex"));
    xmlFree(ne), xmlFree(tt);
    for (int c = 0; c < 3; ++c) {
        size_t m;
        double *v = read_item(child(geom, "DataItem", c), dir, &m);
        GF_CHECK(v && m == N);
        for (int k = 0; v && m == N && k < N; ++k, ++*n_values)
            *n_exact += v[k] == grain(c, k, t);
        free(v);
    }
    size_t m;
    double *vel = read_attribute(grid, "velocity", dir, &m);
    GF_CHECK(vel && m == 3 * N);
    for (int k = 0; vel && m == 3 * N && k < N; ++k)
        for (int c = 0; c < 3; ++c, ++*n_values)
            *n_exact += vel[3 * k + c] == grain(3 + c, k, t);
    free(vel);
    double *r = read_attribute(grid, "radius", dir, &m);
    GF_CHECK(r && m == N);
    for (int k = 0; r && m == N && k < N; ++k, ++*n_values)
        *n_exact += r[k] == nc_test_radius(k);
    free(r);
    double *glued = read_attribute(grid, "glued", dir, &m);
    GF_CHECK(glued && m == N && glued[0] == 1.0 && glued[1] == 0.0);
    free(glued);
}

/* A fields step: the grid's nodes, origin and spacing, every field, the last cell's velocity. */
static void check_field_step(xmlNode *grid, const char *dir, double t, int *n_exact, int *n_values)
{
    xmlNode *topo = child(grid, "Topology", 0), *geom = child(grid, "Geometry", 0);
    char *dims = attr(topo, "Dimensions");
    size_t nodes[3];
    GF_CHECK(dims && parse_sizes(dims, nodes, 3) == 3 && nodes[0] == NZ + 1 && nodes[1] == NY + 1 &&
             nodes[2] == NX + 1);
    xmlFree(dims);
    size_t m0, m1;
    double *origin = read_item(child(geom, "DataItem", 0), dir, &m0);
    double *spacing = read_item(child(geom, "DataItem", 1), dir, &m1);
    GF_CHECK(m0 == 3 && m1 == 3);
    for (int a = 0; m0 == 3 && m1 == 3 && a < 3; ++a)   /* listed z, y, x */
        GF_CHECK(origin[2 - a] == lo[a] && spacing[2 - a] == h[a]);
    free(origin), free(spacing);
    for (int iv = 0; iv < NV; ++iv) {
        size_t m;
        double *v = read_attribute(grid, nc_test_fluid_fields[iv].name, dir, &m);
        GF_CHECK(v && m == NX * NY * NZ);
        for (int k = 0; v && m == NX * NY * NZ && k < NZ; ++k)
            for (int j = 0; j < NY; ++j)
                for (int i = 0; i < NX; ++i, ++*n_values)
                    *n_exact += v[(k * NY + j) * NX + i] == field(iv, i, j, k, t);
        free(v);
    }
    size_t m;
    double *vel = read_attribute(grid, "fluid_velocity", dir, &m);
    GF_CHECK(vel && m == 3 * NX * NY * NZ);
    for (int c = 0; vel && m == 3 * NX * NY * NZ && c < 3; ++c, ++*n_values)
        *n_exact += vel[3 * (NX * NY * NZ - 1) + c] == field(1 + c, NX - 1, NY - 1, NZ - 1, t);
    free(vel);
}

static int run_paraview(const char *pvpython, const char *dir)
{
    const char *src = getenv("GF_SOURCE_DIR");
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' '%s/tests/io/check_xdmf_paraview.py' '%s' %d %d %d %d %d", pvpython,
             src ? src : ".", dir, N, NT, NX, NY, NZ);
    int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "ParaView reads the sidecars: %s (status %d)", cmd, rc);
    return gf_test_finish();
}

int main(int argc, char **argv)
{
    const char *pvpython = argc > 1 ? argv[1] : NULL;
    if (pvpython && (!*pvpython || strstr(pvpython, "NOTFOUND"))) {
        printf("no pvpython: skipped\n");
        return 77;
    }
    const char *dir = nc_test_dir(pvpython ? "sidecar-paraview" : "sidecar");
    char path[2048];
    snprintf(path, sizeof path, "%s/particles.nc", dir);
    write_particles(path, NT);
    snprintf(path, sizeof path, "%s/fields.nc", dir);
    write_fields(path);
    if (pvpython)
        return run_paraview(pvpython, dir);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    check_sidecar(dir, "particles.xmf", NT, check_grain_step, N * 7, "grain");
    check_sidecar(dir, "fields.xmf", NT, check_field_step, NV * NX * NY * NZ + 3, "field");
    /* the file rewritten with fewer records: the sidecar follows it */
    snprintf(path, sizeof path, "%s/particles.nc", dir);
    write_particles(path, 2);
    check_sidecar(dir, "particles.xmf", 2, check_grain_step, N * 7, "grain");
    snprintf(path, sizeof path, "%s/particles.xmf.tmp", dir);
    GF_CHECK(access(path, F_OK) != 0);
    return gf_test_finish();
}
