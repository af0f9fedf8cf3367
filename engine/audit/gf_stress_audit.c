/* Granular stress tensor in horizontal slabs; see gf_sim.h (gf_sim_stress_tensor_slabs). Read
 * through the public API alone: the contacts of the neighbour list with their stored springs
 * (gf_sim_foreach_contact), the law's kernel from the contact table. */
#include "contact/gf_contact.h"
#include "contact/gf_nlist.h"
#include "gf_sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Adds w * f (x) b to the 6 components of S. */
static void add_dyad(double *S, double w, const double f[3], const double b[3])
{
    S[0] += w * f[0] * b[0], S[1] += w * f[1] * b[1], S[2] += w * f[2] * b[2];
    S[3] += w * 0.5 * (f[0] * b[1] + f[1] * b[0]);
    S[4] += w * 0.5 * (f[0] * b[2] + f[2] * b[0]);
    S[5] += w * 0.5 * (f[1] * b[2] + f[2] * b[1]);
}

/* Parameter interval [*t0, *t1] (narrowed) of the segment c0 + t dc, t in [0, 1], inside [lo, hi]. */
static void clip_axis(double c0, double dc, double lo, double hi, double *t0, double *t1)
{
    if (dc == 0.0) {
        if (c0 < lo || c0 > hi)
            *t1 = *t0 - 1.0; /* empty */
        return;
    }
    double ta = (lo - c0) / dc, tb = (hi - c0) / dc;
    double a = ta < tb ? ta : tb, b = ta < tb ? tb : ta;
    *t0 = a > *t0 ? a : *t0, *t1 = b < *t1 ? b : *t1;
}

static gf_status stress_slabs(gf_sim *s, const double *fp, double y0, double dy, int n, double *S);

gf_status gf_sim_stress_tensor_slabs(gf_sim *s, double y0, double dy, int n, double *S)
{
    return stress_slabs(s, NULL, y0, dy, n, S);
}

gf_status gf_sim_stress_tensor_slabs_in(gf_sim *s, const double footprint_m[4], double y0, double dy, int n, double *S)
{
    if (!(footprint_m[1] > footprint_m[0]) || !(footprint_m[3] > footprint_m[2]))
        return GF_FAIL(gf_sim_ctx(s), GF_ERR_ARG, "measure: stress footprint needs x_lo < x_hi and z_lo < z_hi");
    return stress_slabs(s, footprint_m, y0, dy, n, S);
}

/* What the contact walk needs to add each pair's f (x) b to the slabs. */
typedef struct slab_sums {
    const gf_particles *p;
    const double *fp;
    double y0, dy, vol;
    int n;
    double *S;
    double lo[3], hi[3];
    int periodic[3];
    const gf_contact_params *cp;
    gf_contact_kernel *kernel;
} slab_sums;

/* Contact c's force from the law at the current state and its stored spring, into the slabs its
 * branch segment crosses (glued-glued pairs and walls excluded). */
static int add_contact(void *user, const gf_sim_contact *c)
{
    const slab_sums *ss = user;
    const gf_particles *p = ss->p;
    const double *fp = ss->fp, y0 = ss->y0, dy = ss->dy, vol = ss->vol;
    const int n = ss->n;
    double *S = ss->S;
    if (c->wall >= 0)
        return 0;
    const size_t i = c->i, j = c->j;
    if ((p->flags[i] & GF_P_GLUED) && (p->flags[j] & GF_P_GLUED))
        return 0;
    const double *d = c->branch_m; /* with the pair's image: a narrow period may hold two */
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), rsum = p->radius_m[i] + p->radius_m[j];
    if (!(r < rsum) || r <= 0.0)
        return 0;
    gf_contact_geom g;
    for (int a = 0; a < 3; ++a)
        g.n[a] = d[a] / r;
    g.overlap_m = rsum - r;
    double vt[3] = {p->vx_m_s[i] - p->vx_m_s[j], p->vy_m_s[i] - p->vy_m_s[j], p->vz_m_s[i] - p->vz_m_s[j]};
    double ri = p->radius_m[i], rj = p->radius_m[j];
    double rw[3] = {ri * p->wx_rad_s[i] + rj * p->wx_rad_s[j], ri * p->wy_rad_s[i] + rj * p->wy_rad_s[j],
                    ri * p->wz_rad_s[i] + rj * p->wz_rad_s[j]};
    double rwn[3] = {rw[1] * g.n[2] - rw[2] * g.n[1], rw[2] * g.n[0] - rw[0] * g.n[2],
                     rw[0] * g.n[1] - rw[1] * g.n[0]};
    for (int a = 0; a < 3; ++a)
        g.v_rel_m_s[a] = vt[a] - rwn[a];
    g.v_n_m_s = vt[0] * g.n[0] + vt[1] * g.n[1] + vt[2] * g.n[2];
    g.m_eff_kg = c->m_eff_kg;
    g.sqrt_mk = sqrt(c->m_eff_kg * ss->cp->k_n_N_m); /* as the neighbour build derives it */
    g.mu = ss->cp->mu_grain;
    gf_contact_params cp = *ss->cp;
    double h[3] = {c->history[0], c->history[1], c->history[2]}, f_n, f_t[3];
    ss->kernel(&cp, &g, 0.0, h, &f_n, f_t); /* dt = 0: the stored spring, no increment */
    double f[3] = {f_n * g.n[0] + f_t[0], f_n * g.n[1] + f_t[1], f_n * g.n[2] + f_t[2]};
    if (fp) { /* the part of the branch segment inside the footprint, shared among the slabs */
        double t0 = 0.0, t1 = 1.0;
        clip_axis(p->x_m[j], d[0], fp[0], fp[1], &t0, &t1);
        clip_axis(p->z_m[j], d[2], fp[2], fp[3], &t0, &t1);
        for (int q = 0; t1 > t0 && q < n; ++q) {
            double u0 = t0, u1 = t1;
            clip_axis(p->y_m[j], d[1], y0 + q * dy, y0 + (q + 1) * dy, &u0, &u1);
            if (u1 > u0)
                add_dyad(&S[6 * q], (u1 - u0) / vol, f, d);
        }
        return 0;
    }
    /* share f (x) b among the slabs the branch segment crosses */
    double ya = p->y_m[j], yb = p->y_m[j] + d[1];
    double lo = ya < yb ? ya : yb, hi = ya < yb ? yb : ya, len = hi - lo;
    int k0 = (int)floor((lo - y0) / dy), k1 = (int)floor((hi - y0) / dy);
    for (int q = k0 < 0 ? 0 : k0; q <= k1 && q < n; ++q) {
        double w = 1.0;
        if (len > 0.0) {
            double a0 = y0 + q * dy, a1 = a0 + dy;
            double c0 = lo > a0 ? lo : a0, c1 = hi < a1 ? hi : a1;
            w = c1 > c0 ? (c1 - c0) / len : 0.0;
        }
        add_dyad(&S[6 * q], w / vol, f, d);
    }
    return 0;
}

/* fp: NULL for the whole x-z footprint of the domain, else {x_lo, x_hi, z_lo, z_hi}: branch segments
 * clipped to it, grains counted by centre. */
static gf_status stress_slabs(gf_sim *s, const double *fp, double y0, double dy, int n, double *S)
{
    gf_ctx *ctx = gf_sim_ctx(s);
    if (n < 1 || !(dy > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "measure: stress tensor needs n >= 1 and dy > 0 (got %d, %g m)", n, dy);
    const gf_particles *p = gf_sim_particles(s);
    const gf_nlist *nl = gf_sim_neighbour_list(s);
    if (!nl || nl->n != p->n_local)
        return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "measure: stress tensor needs a current neighbour list");
    const gf_contact_info *law = gf_contact_find(gf_sim_spec(s)->contact.law);
    if (!law)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "measure: unknown contact law '%s'", gf_sim_spec(s)->contact.law);
    slab_sums ss = {.p = p, .fp = fp, .y0 = y0, .dy = dy, .n = n, .S = S, .cp = gf_sim_contact_params(s),
                    .kernel = law->kernel};
    gf_sim_box(s, ss.lo, ss.hi, ss.periodic);
    double area = fp ? (fp[1] - fp[0]) * (fp[3] - fp[2]) : (ss.hi[0] - ss.lo[0]) * (ss.hi[2] - ss.lo[2]);
    double vol = area * dy;
    ss.vol = vol;
    memset(S, 0, (size_t)n * 6 * sizeof *S);
    GF_TRY(gf_sim_foreach_contact(s, add_contact, &ss)); /* contact part */
    /* kinetic part about each slab's mass-weighted mean velocity */
    double *m = calloc((size_t)n * 10, sizeof *m);
    if (!m)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "measure: cannot allocate %d slabs", n);
    for (size_t i = 0; i < p->n_local; ++i) {
        if (p->flags[i] & GF_P_GLUED)
            continue;
        if (fp && (p->x_m[i] < fp[0] || p->x_m[i] > fp[1] || p->z_m[i] < fp[2] || p->z_m[i] > fp[3]))
            continue;
        int k = (int)floor((p->y_m[i] - y0) / dy);
        if (k < 0 || k >= n)
            continue;
        double mi = p->mass_kg[i], u[3] = {p->vx_m_s[i], p->vy_m_s[i], p->vz_m_s[i]}, *q = &m[10 * k];
        q[0] += mi, q[1] += mi * u[0], q[2] += mi * u[1], q[3] += mi * u[2];
        add_dyad(q + 4, mi, u, u);
    }
    for (int k = 0; k < n; ++k) {
        double *q = &m[10 * k];
        if (!(q[0] > 0.0))
            continue;
        double ub[3] = {q[1] / q[0], q[2] / q[0], q[3] / q[0]};
        double c[6];
        memset(c, 0, sizeof c);
        add_dyad(c, q[0], ub, ub); /* sum m u u - M ub ub = sum m u' u' */
        for (int a = 0; a < 6; ++a)
            S[6 * k + a] += (q[4 + a] - c[a]) / vol;
    }
    free(m);
    return GF_OK;
}
