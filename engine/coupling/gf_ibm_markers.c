/* Lagrangian-marker direct forcing of the resolved tier; equations and sources in gf_ibm_markers.h. */
#include "coupling/gf_ibm_markers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const gf_ibm_forcing_names[] = {"smoothed", "markers", NULL};

int gf_ibm_forcing_from_name(const char *name, gf_ibm_forcing *out)
{
    for (int i = 0; gf_ibm_forcing_names[i]; ++i)
        if (strcmp(name, gf_ibm_forcing_names[i]) == 0) {
            *out = (gf_ibm_forcing)i;
            return 0;
        }
    return -1;
}

size_t gf_ibm_marker_count(double R_m, double dx_m)
{
    double n = round(4.0 * M_PI * R_m * R_m / (dx_m * dx_m));
    return n >= 1.0 ? (size_t)n : 1;
}

void gf_ibm_marker_direction(size_t l, size_t n, double dir[3])
{
    double z = 1.0 - (2.0 * (double)l + 1.0) / (double)n;
    double rho = sqrt(fmax(0.0, 1.0 - z * z));
    double phi = (double)l * M_PI * (3.0 - sqrt(5.0)); /* the golden angle */
    dir[0] = rho * cos(phi), dir[1] = rho * sin(phi), dir[2] = z;
}

double gf_ibm_roma_kernel(double r)
{
    double x = fabs(r);
    if (x <= 0.5)
        return (1.0 + sqrt(1.0 - 3.0 * x * x)) / 3.0;
    if (x <= 1.5) {
        double y = 1.0 - x;
        return (5.0 - 3.0 * x - sqrt(fmax(0.0, 1.0 - 3.0 * y * y))) / 6.0;
    }
    return 0.0;
}

void gf_ibm_markers_free(gf_ibm_markers *mk)
{
    free(mk->first), free(mk->F), free(mk->slip2);
    int nt = mk->n_threads;
    double rd = mk->retraction_cells;
    memset(mk, 0, sizeof *mk);
    mk->n_threads = nt, mk->retraction_cells = rd;
}

/* The faces of component a that carry a marker at X, and their weights (sum 1; 27 at most). */
typedef struct stencil {
    int n;
    size_t face[27];
    double w[27];
} stencil;

static void marker_stencil(const gf_grid *g, int a, const double X[3], stencil *s)
{
    double w1[3][3];
    int q[3][3];
    for (int d = 0; d < 3; ++d) {
        double x = (X[d] - g->lo_m[d]) / g->h_m[d] - (d == a ? 0.0 : 0.5);
        int m0 = (int)floor(x + 0.5);
        for (int k = 0; k < 3; ++k) {
            w1[d][k] = gf_ibm_roma_kernel(x - (m0 + k - 1));
            q[d][k] = gf_ibm_face_index(g, a, d, m0 + k - 1);
        }
    }
    double sum = 0.0;
    s->n = 0;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                double w = w1[0][i] * w1[1][j] * w1[2][k];
                if (q[0][i] < 0 || q[1][j] < 0 || q[2][k] < 0 || w == 0.0)
                    continue;
                s->face[s->n] = gf_grid_face(g, a, q[0][i], q[1][j], q[2][k]);
                s->w[s->n++] = w;
                sum += w;
            }
    for (int t = 0; t < s->n; ++t)
        s->w[t] /= sum; /* near a wall: the faces left carry the whole kernel (none: a marker past a wall) */
}

/* The markers' sphere of grain i: R_m = R - r_d dx. */
static double marker_radius(const gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p, size_t i)
{
    return p->radius_m[i] - mk->retraction_cells * g->h_m[0];
}

/* Each of n markers' volume on a sphere of radius R_m: dV_l = (pi dx / 3n) (12 R_m^2 + dx^2). */
static double marker_volume(double R_m, double dx_m, size_t n)
{
    return M_PI * dx_m * (12.0 * R_m * R_m + dx_m * dx_m) / (3.0 * (double)n);
}

static gf_status reserve(gf_ctx *ctx, gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p)
{
    size_t n = p->n_local;
    if (n + 1 > mk->cap_grains) {
        size_t cap = n + n / 2 + 8;
        size_t *f = realloc(mk->first, cap * sizeof *f);
        if (f)
            mk->first = f;
        double *s2 = realloc(mk->slip2, cap * sizeof *s2);
        if (s2)
            mk->slip2 = s2;
        if (!f || !s2)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "ibm markers: out of memory for %zu grains", n);
        mk->cap_grains = cap;
    }
    mk->first[0] = 0;
    for (size_t i = 0; i < n; ++i)
        mk->first[i + 1] = mk->first[i] + gf_ibm_marker_count(marker_radius(mk, g, p, i), g->h_m[0]);
    mk->n_grains = n;
    if (3 * mk->first[n] > mk->cap_markers) {
        size_t cap = 3 * mk->first[n] + 3 * mk->first[n] / 2 + 64;
        double *F = realloc(mk->F, cap * sizeof *F);
        if (!F)
            return GF_FAIL(ctx, GF_ERR_NOMEM, "ibm markers: out of memory for %zu markers", mk->first[n]);
        mk->F = F, mk->cap_markers = cap;
    }
    return GF_OK;
}

/* Marker l of grain i: its offset r from the centre and its position X. */
static void marker_position(const gf_particles *p, size_t i, double R_m, size_t l, size_t n, double r[3],
                            double X[3])
{
    gf_ibm_marker_direction(l, n, r);
    const double xc[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
    for (int d = 0; d < 3; ++d) {
        r[d] *= R_m;
        X[d] = xc[d] + r[d];
    }
}

/* One sweep's interpolation for grain i: F_l = (U_i + w_i x r_l - u(X_l))/dt into mk->F, and the grain's
 * -rho sum_l F_l dV_l and its torque added to F_N, T_Nm; the squared slip summed into mk->slip2[i]. */
static void interpolate_grain(gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p, size_t i,
                              const double *const u[3], double dt_s, double rho_f, double *F_N, double *T_Nm)
{
    const double h = g->h_m[0], R_m = marker_radius(mk, g, p, i);
    const size_t n = mk->first[i + 1] - mk->first[i];
    const double dV = marker_volume(R_m, h, n);
    const double v[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]};
    const double w[3] = {p->wx_rad_s[i], p->wy_rad_s[i], p->wz_rad_s[i]};
    double F[3] = {0, 0, 0}, T[3] = {0, 0, 0}, slip2 = 0.0;
    for (size_t l = 0; l < n; ++l) {
        double r[3], X[3], Fl[3];
        marker_position(p, i, R_m, l, n, r, X);
        for (int a = 0; a < 3; ++a) {
            stencil s;
            marker_stencil(g, a, X, &s);
            double ul = 0.0;
            for (int t = 0; t < s.n; ++t)
                ul += s.w[t] * u[a][s.face[t]];
            int b = (a + 1) % 3, c = (a + 2) % 3;
            double target = s.n ? v[a] + w[b] * r[c] - w[c] * r[b] : ul; /* a marker with no face forces nothing */
            Fl[a] = (target - ul) / dt_s;
            slip2 += (target - ul) * (target - ul);
            mk->F[3 * (mk->first[i] + l) + a] = Fl[a];
        }
        for (int a = 0; a < 3; ++a) {
            int b = (a + 1) % 3, c = (a + 2) % 3;
            F[a] += Fl[a] * dV;
            T[a] += (r[b] * Fl[c] - r[c] * Fl[b]) * dV;
        }
    }
    for (int a = 0; a < 3; ++a)
        F_N[3 * i + a] -= rho_f * F[a], T_Nm[3 * i + a] -= rho_f * T[a];
    mk->slip2[i] = slip2;
}

/* One sweep's spreading of component a, grains and markers in order: f += F_l delta dV_l, u += dt F_l delta dV_l. */
static void spread_component(const gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p, int a, double dt_s,
                             double *u, double *force)
{
    const double h = g->h_m[0], cell = g->h_m[0] * g->h_m[1] * g->h_m[2];
    for (size_t i = 0; i < mk->n_grains; ++i) {
        const double R_m = marker_radius(mk, g, p, i);
        const size_t n = mk->first[i + 1] - mk->first[i];
        const double dV = marker_volume(R_m, h, n);
        for (size_t l = 0; l < n; ++l) {
            double r[3], X[3];
            marker_position(p, i, R_m, l, n, r, X);
            stencil s;
            marker_stencil(g, a, X, &s);
            double f = mk->F[3 * (mk->first[i] + l) + a] * dV / cell;
            for (int t = 0; t < s.n; ++t) {
                force[s.face[t]] += s.w[t] * f;
                u[s.face[t]] += dt_s * s.w[t] * f;
            }
        }
    }
}

gf_status gf_ibm_markers_force(gf_ctx *ctx, gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p,
                               const double *const u_pred[3], double dt_s, double rho_f, double *const u_work[3],
                               double *const force_out[3], double *F_N, double *T_Nm)
{
    GF_TRY(reserve(ctx, mk, g, p));
    const int nt = mk->n_threads > 1 ? mk->n_threads : 1, nc = nt >= 3 ? 3 : nt;
    for (int a = 0; a < 3; ++a) {
        memcpy(u_work[a], u_pred[a], g->n_faces[a] * sizeof(double));
        memset(force_out[a], 0, g->n_faces[a] * sizeof(double));
    }
    const long n = (long)mk->n_grains;
    memset(F_N, 0, 3 * (size_t)n * sizeof *F_N);
    memset(T_Nm, 0, 3 * (size_t)n * sizeof *T_Nm);
    const double *const uw[3] = {u_work[0], u_work[1], u_work[2]};
    for (int sweep = 0; sweep < GF_IBM_MARKER_SWEEPS; ++sweep) {
#pragma omp parallel for num_threads(nt) if (nt > 1 && n > 1) schedule(dynamic, 1)
        for (long i = 0; i < n; ++i)
            interpolate_grain(mk, g, p, (size_t)i, uw, dt_s, rho_f, F_N, T_Nm);
        double s2 = 0.0;
        for (long i = 0; i < n; ++i)
            s2 += mk->slip2[i];
        mk->last_slip[sweep] = mk->first[n] ? sqrt(s2 / (3.0 * (double)mk->first[n])) : 0.0;
#pragma omp parallel for num_threads(nc) if (nc > 1) schedule(static, 1)
        for (int a = 0; a < 3; ++a)
            spread_component(mk, g, p, a, dt_s, u_work[a], force_out[a]);
    }
    for (int a = 0; a < 3; ++a)
        gf_grid_sync_periodic(g, a, force_out[a]);
    return GF_OK;
}
