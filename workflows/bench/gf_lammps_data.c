/* The grains of a sim as a LAMMPS data file; see gf_lammps_data.h. */
#include "gf_lammps_data.h"

#include <math.h>
#include <stdio.h>

#include "contact/gf_contact.h"

double gf_bench_tsuji_input(double zeta)
{
    /* alpha(e) falls monotonically from 1.27 at e = 0 to 3e-4 at e = 1: bisect */
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 80; ++k) {
        double e = 0.5 * (lo + hi);
        double a = 1.2728 + e * (-4.2783 + e * (11.087 + e * (-22.348 + e * (27.467 + e * (-18.022 + e * 4.8218)))));
        if (a > 2.0 * zeta)
            lo = e;
        else
            hi = e;
    }
    return 0.5 * (lo + hi);
}

/* LAMMPS drops atoms whose centre lies outside a non-periodic side of the box:
 * widen those sides to hold every sphere (the glued base grains are centred
 * on the floor, half below it). Periodic sides stay the period. */
static void data_box(gf_sim *sim, double lo[3], double hi[3], int per[3])
{
    const gf_particles *p = gf_sim_particles(sim);
    gf_sim_box(sim, lo, hi, per);
    const double *c[3] = {p->x_m, p->y_m, p->z_m};
    for (int a = 0; a < 3; ++a) {
        if (per[a])
            continue;
        double bottom = lo[a], top = lo[a], ext = hi[a] - lo[a];
        for (size_t i = 0; i < p->n_local; ++i) {
            bottom = fmin(bottom, c[a][i] - p->radius_m[i]);
            top = fmax(top, c[a][i] + p->radius_m[i]);
        }
        if (bottom < lo[a])
            lo[a] = bottom - 0.01 * ext;
        hi[a] = fmax(hi[a], top + 0.01 * ext);
    }
}

static double wrap(double x, double lo, double hi, int periodic)
{
    return periodic ? x - (hi - lo) * floor((x - lo) / (hi - lo)) : x;
}

static int write_atoms(gf_sim *sim, const char *path)
{
    const gf_particles *p = gf_sim_particles(sim);
    const gf_run_spec *s = gf_sim_spec(sim);
    double lo[3], hi[3];
    int per[3];
    data_box(sim, lo, hi, per);
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f, "grainflow %s, %zu grains (SI units)\n\n%zu atoms\n2 atom types\n\n", s->scene, p->n_local,
            p->n_local);
    fprintf(f, "%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\nAtoms # sphere\n\n", lo[0], hi[0],
            lo[1], hi[1], lo[2], hi[2]);
    for (size_t i = 0; i < p->n_local; ++i)
        fprintf(f, "%zu %d %.17g %.17g %.17g %.17g %.17g\n", i + 1, (p->flags[i] & GF_P_GLUED) ? 2 : 1,
                2.0 * p->radius_m[i], s->grains.density_kg_m3, wrap(p->x_m[i], lo[0], hi[0], per[0]),
                wrap(p->y_m[i], lo[1], hi[1], per[1]), wrap(p->z_m[i], lo[2], hi[2], per[2]));
    fprintf(f, "\nVelocities\n\n");
    for (size_t i = 0; i < p->n_local; ++i) {
        int g = (p->flags[i] & GF_P_GLUED) != 0; /* glued: at rest whatever the store holds */
        fprintf(f, "%zu %.17g %.17g %.17g %.17g %.17g %.17g\n", i + 1, g ? 0.0 : p->vx_m_s[i],
                g ? 0.0 : p->vy_m_s[i], g ? 0.0 : p->vz_m_s[i], g ? 0.0 : p->wx_rad_s[i], g ? 0.0 : p->wy_rad_s[i],
                g ? 0.0 : p->wz_rad_s[i]);
    }
    return fclose(f) == 0;
}

int gf_bench_write_lammps(gf_sim *sim, const char *path)
{
    if (!write_atoms(sim, path))
        return 0;
    const gf_particles *p = gf_sim_particles(sim);
    const gf_run_spec *s = gf_sim_spec(sim);
    double lo[3], hi[3];
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    size_t n_glued = 0;
    for (size_t i = 0; i < p->n_local; ++i)
        n_glued += (p->flags[i] & GF_P_GLUED) != 0;
    /* the law's constants for the mean pair, in LAMMPS gran/hooke/history terms */
    gf_contact_params cp;
    gf_ctx ctx = {0};
    gf_contact_params_from_spec(&ctx, s, &cp);
    double gamma_n = 2.0 * cp.zeta * sqrt(cp.m_eff_mean_kg * cp.k_n_N_m);
    char pp[600];
    snprintf(pp, sizeof pp, "%s.params", path);
    FILE *f = fopen(pp, "w");
    if (!f)
        return 0;
    /* gran/hooke/history: F_n = k_n delta - m_eff gamma_n v_n, gamma_n in 1/s (exact for the mean pair only);
     * granular ... damping tsuji TSUJI: 2 zeta sqrt(m_eff k_n) for every pair and wall, as grainflow */
    fprintf(f, "KN=%.17g\nGAMMAN=%.17g\nKT=%.17g\nGAMMAT=0\nMU=%.17g\nDT=%.17g\nSKIN=%.17g\nG=%.17g\nN=%zu\n",
            cp.k_n_N_m, gamma_n / cp.m_eff_mean_kg, cp.kt_over_kn * cp.k_n_N_m, cp.mu_grain, gf_sim_dt_s(sim),
            s->contact.skin_over_D * s->grains.diameter_m, s->gravity_m_s2, p->n_local);
    fprintf(f, "LX=%.17g\nLZ=%.17g\nD=%.17g\n", hi[0] - lo[0], hi[2] - lo[2], s->grains.diameter_m);
    fprintf(f, "MUW=%.17g\nZETA=%.17g\nTSUJI=%.17g\nN_GLUED=%zu\n", cp.mu_wall, cp.zeta,
            gf_bench_tsuji_input(cp.zeta), n_glued);
    return fclose(f) == 0;
}

int gf_bench_export_lammps(gf_sim *sim, const char *path, gf_bench_params_fn *append, const void *args,
                           const char *program)
{
    int ok = gf_bench_write_lammps(sim, path);
    if (ok && append) {
        char pp[600];
        double lo[3], hi[3];
        int per[3];
        gf_sim_box(sim, lo, hi, per);
        snprintf(pp, sizeof pp, "%s.params", path);
        FILE *f = fopen(pp, "a");
        if (f)
            append(f, sim, lo, hi, args);
        ok = f && fclose(f) == 0;
    }
    if (!ok)
        fprintf(stderr, "%s: cannot write %s\n", program, path);
    return ok;
}

int gf_bench_write_dump(gf_sim *sim, const char *path, int with_type)
{
    const gf_particles *p = gf_sim_particles(sim);
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    for (size_t i = 0; i < p->n_local; ++i) {
        fprintf(f, "%.17g %.17g %.17g %.17g", p->x_m[i], p->y_m[i], p->z_m[i], p->radius_m[i]);
        if (with_type)
            fprintf(f, " %d", (p->flags[i] & GF_P_GLUED) ? 2 : 1);
        fputc('\n', f);
    }
    return fclose(f) == 0;
}
