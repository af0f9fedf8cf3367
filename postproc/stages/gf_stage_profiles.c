/*
 * Stage profiles: x–z averaged grain (and fluid) profiles of an avalanche
 * over the steady window (Izard 2014 eqs. 4.7–4.8).
 *
 * Slabs of thickness D (grain_diameter_m) from the plane y = 0, not
 * overlapping. Grains are counted whole in the slab holding their centre
 * (the coarse-graining of Izard 2014 (2.16)-(2.20) would spread them; at slab width D the
 * difference is a smoothing over one D):
 *   ⟨U⟩_g(y_j) = Σ V_i u_i / Σ V_i      (solid-volume weighted, eq. 4.7)
 *   φ_g(y_j)   = Σ V_i / (L W D)        per frame, then averaged in time
 * over the mobile grains of every particles.nc frame at t >= t_steady (MSER-5
 * on diagnostics grain_flow_rate, as stage flow_rate; the second half of the
 * frames if there is no flow-rate series). L and W are the fields.nc grid
 * extents when that file exists, otherwise the grain extents
 * max − min + mean D in x and z of the first window frame (a periodic cell
 * full of grains; error of order D/L).
 * Fluid: ⟨U⟩_f(y_j) = Σ ε u_f / Σ ε over the cells of fields.nc
 * (fluid_fraction ε = 1 − α, u_fluid) in the same slabs and frames (eq. 4.7).
 * Mean particle Stokes number (Izard 2014 eq. 4.17):
 *   St̄ = (ρ_p / (9 η_f)) (1/N_g) Σ_i |u_i| D_i over the mobile grains,
 * averaged over the same frames, and R̄e* = St̄ / r (§4.2: St̄_c ≈ 40,
 * R̄e*_c ≈ 10). NaN for a dry run.
 * Writes post_profiles.nc (y_slab, u_grain, phi_grain, u_fluid).
 * Scene silo: the velocity profiles across the orifice (stages/gf_silo_flow.h).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stages/gf_post_stats.h"
#include "stages/gf_silo_flow.h"
#include "stages/gf_stage_util.h"

#define NSLAB_MAX 4096

/* Fluid slab averages from fields.nc over records with time >= t0. */
static gf_status fluid_profile(gf_ctx *ctx, const gf_stage_in *in, double t0, double D, size_t ns, double *uf,
                               double *L, double *W)
{
    gf_ncr f;
    GF_TRY(gf_stage_open(ctx, in, "fields.nc", &f));
    double *t = NULL, *xc = NULL, *yc = NULL, *zc = NULL, *eps = NULL, *u = NULL, *num = NULL, *den = NULL;
    size_t nt, nx, ny, nz;
    gf_status st = gf_ncr_var_1d(ctx, &f, "time", &t, &nt);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &f, "x", &xc, &nx);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &f, "y", &yc, &ny);
    if (st == GF_OK) st = gf_ncr_var_1d(ctx, &f, "z", &zc, &nz);
    const size_t nc = nx * ny * nz;
    if (st == GF_OK) {
        eps = malloc(nc * sizeof *eps + 1), u = malloc(nc * sizeof *u + 1);
        num = calloc(ns, sizeof *num), den = calloc(ns, sizeof *den);
        if (!eps || !u || !num || !den)
            st = GF_FAIL(ctx, GF_ERR_NOMEM, "profiles: out of memory");
    }
    if (st == GF_OK && nx > 1 && nz > 1) {
        *L = (xc[nx - 1] - xc[0]) * (double)nx / (double)(nx - 1);
        *W = (zc[nz - 1] - zc[0]) * (double)nz / (double)(nz - 1);
    }
    for (size_t k = 0; st == GF_OK && k < nt; ++k) {
        if (!(t[k] >= t0))
            continue;
        st = gf_ncr_var_record(ctx, &f, "fluid_fraction", k, eps, nc);
        if (st == GF_OK)
            st = gf_ncr_var_record(ctx, &f, "u_fluid", k, u, nc);
        for (size_t c = 0; st == GF_OK && c < nc; ++c) {
            const size_t j = (c / nx) % ny;   /* dims (z, y, x), x fastest */
            const long s = (long)floor(yc[j] / D);
            if (s < 0 || (size_t)s >= ns || !isfinite(eps[c]) || !isfinite(u[c]))
                continue;
            num[s] += eps[c] * u[c];
            den[s] += eps[c];
        }
    }
    for (size_t s = 0; st == GF_OK && s < ns; ++s)
        uf[s] = den[s] > 0.0 ? num[s] / den[s] : NAN;
    free(t), free(xc), free(yc), free(zc), free(eps), free(u), free(num), free(den);
    gf_ncr_close(&f);
    return st;
}

gf_status gf_stage_profiles(gf_ctx *ctx, const gf_stage_in *in, const gf_stage_opts *opts, gf_stage_out *out)
{
    if (!gf_stage_has_file(in, "particles.nc"))
        return GF_ERR_UNSUPPORTED;   /* only when trajectories were written */
    if (gf_stage_has_var(in, "diagnostics.nc", "discharge_rate"))
        return gf_silo_profiles(ctx, in, out);   /* a discharge through an orifice */
    if (!gf_stage_has_var(in, "diagnostics.nc", "grain_flow_rate"))
        return GF_ERR_UNSUPPORTED;   /* a flowing layer (its steady window) */
    /* steady window start */
    double t0 = NAN;
    if (gf_stage_has_file(in, "diagnostics.nc")) {
        gf_ncr d;
        GF_TRY(gf_stage_open(ctx, in, "diagnostics.nc", &d));
        double *t = NULL, *q = NULL;
        size_t nt = 0, nq = 0;
        if (gf_ncr_has_var(&d, "grain_flow_rate") && gf_ncr_var_1d(ctx, &d, "time", &t, &nt) == GF_OK &&
            gf_ncr_var_1d(ctx, &d, "grain_flow_rate", &q, &nq) == GF_OK && nq == nt) {
            gf_steady s;
            gf_stats_steady(t, q, nt, &s);
            if (s.ok)
                t0 = s.t_start_s;
        }
        free(t), free(q);
        gf_ncr_close(&d);
    }
    gf_ncr p;
    gf_grains_info g;
    double D;
    GF_TRY(gf_stage_open_grains(ctx, in, &p, &g, &D));
    gf_status st = GF_OK;
    const double rho_p = gf_ncr_att_double_or(&p, "grain_density_kg_m3", NAN);
    const double eta = gf_ncr_att_double_or(&p, "fluid_viscosity_Pa_s", 0.0);
    gf_groups_input gi;
    gf_scales sc;
    const double r_dens = gf_stage_scales(NULL, &p, in, &gi, &sc) == GF_OK ? sc.density_ratio_r : NAN;
    const size_t n = g.n_all;
    double *t = NULL, *x = malloc(n * sizeof *x + 1), *y = malloc(n * sizeof *y + 1), *z = malloc(n * sizeof *z + 1),
           *u = malloc(n * sizeof *u + 1), *v = malloc(n * sizeof *v + 1), *w = malloc(n * sizeof *w + 1);
    double speed_d = 0.0;   /* sum over frames of (1/N) sum |u| D */
    double *vol = calloc(NSLAB_MAX, sizeof *vol), *mom = calloc(NSLAB_MAX, sizeof *mom);
    size_t nt = 0, nframes = 0, ns = 0;
    if (!x || !y || !z || !u || !v || !w || !vol || !mom)
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "profiles: out of memory");
    if (st == GF_OK)
        st = gf_ncr_var_1d(ctx, &p, "time", &t, &nt);
    if (st == GF_OK && !isfinite(t0) && nt > 0)
        t0 = t[nt / 2];
    double L = NAN, W = NAN;
    for (size_t k = 0; st == GF_OK && k < nt; ++k) {
        if (!(t[k] >= t0))
            continue;
        st = gf_ncr_var_2d_col(ctx, &p, "x", k, x, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, &p, "y", k, y, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, &p, "z", k, z, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, &p, "u", k, u, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, &p, "v", k, v, n);
        if (st == GF_OK) st = gf_ncr_var_2d_col(ctx, &p, "w", k, w, n);
        if (st != GF_OK)
            break;
        double sd = 0.0;
        size_t nm = 0;
        for (size_t i = 0; i < n; ++i)
            if (g.mobile[i] && isfinite(u[i]) && isfinite(v[i]) && isfinite(w[i])) {
                sd += sqrt(u[i] * u[i] + v[i] * v[i] + w[i] * w[i]) * 2.0 * g.radius[i];
                ++nm;
            }
        speed_d += nm ? sd / (double)nm : 0.0;
        if (nframes == 0) {
            double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
            for (size_t i = 0; i < n; ++i)
                if (isfinite(x[i]) && isfinite(z[i])) {
                    x0 = fmin(x0, x[i]), x1 = fmax(x1, x[i]), z0 = fmin(z0, z[i]), z1 = fmax(z1, z[i]);
                }
            L = x1 - x0 + g.mean_diameter_m;
            W = z1 - z0 + g.mean_diameter_m;
        }
        for (size_t i = 0; i < n; ++i) {
            if (!g.mobile[i] || !isfinite(y[i]) || !isfinite(u[i]))
                continue;
            const long s = (long)floor(y[i] / D);
            if (s < 0 || s >= NSLAB_MAX)
                continue;
            const double v = 4.0 / 3.0 * M_PI * g.radius[i] * g.radius[i] * g.radius[i];
            vol[s] += v;
            mom[s] += v * u[i];
            if ((size_t)s + 1 > ns)
                ns = (size_t)s + 1;
        }
        ++nframes;
    }
    gf_ncr_close(&p);
    if (st == GF_OK && nframes == 0)
        st = GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "not determined: %s/particles.nc: no frame in the steady window (t >= %g s)", in->run_dir, t0);
    double *ug = calloc(ns + 1, sizeof *ug), *phi = calloc(ns + 1, sizeof *phi), *uf = malloc((ns + 1) * sizeof *uf);
    double *yc = malloc((ns + 1) * sizeof *yc);
    if (st == GF_OK && (!ug || !phi || !uf || !yc))
        st = GF_FAIL(ctx, GF_ERR_NOMEM, "profiles: out of memory");
    int have_fluid = 0;
    if (st == GF_OK) {
        for (size_t s = 0; s < ns; ++s)
            uf[s] = NAN;
        if (gf_stage_has_file(in, "fields.nc")) {
            st = fluid_profile(ctx, in, t0, D, ns, uf, &L, &W);
            have_fluid = st == GF_OK;
        }
    }
    if (st == GF_OK) {
        double ugmax = NAN, phimax = 0.0, ufmax = NAN;
        for (size_t s = 0; s < ns; ++s) {
            yc[s] = (s + 0.5) * D;
            ug[s] = vol[s] > 0.0 ? mom[s] / vol[s] : NAN;
            phi[s] = vol[s] / ((double)nframes * L * W * D);
            if (isfinite(ug[s]) && !(ug[s] <= ugmax))
                ugmax = ug[s];
            if (phi[s] > phimax)
                phimax = phi[s];
            if (isfinite(uf[s]) && !(uf[s] <= ufmax))
                ufmax = uf[s];
        }
        double h = 0.0;
        for (size_t s = 0; s < ns; ++s)
            if (phi[s] >= 0.5 * phimax)
                h = (s + 1) * D;
        gf_post_row_set(out->row, "Ug_max_m_s", ugmax);
        gf_post_row_set(out->row, "phi_g_max", phimax);
        gf_post_row_set(out->row, "h_g_m", h);
        if (have_fluid)
            gf_post_row_set(out->row, "Uf_max_m_s", ufmax);
        gf_post_row_set(out->row, "n_profile_frames", (double)nframes);
        gf_post_row_set(out->row, "St_bar", eta > 0.0 ? rho_p * (speed_d / (double)nframes) / (9.0 * eta) : NAN);
        gf_post_row_set(out->row, "Re_bar",
                        eta > 0.0 && r_dens > 0.0 ? rho_p * (speed_d / (double)nframes) / (9.0 * eta) / r_dens : NAN);
    }
    if (st == GF_OK && opts && opts->write_series) {
        const gf_postnc_dimension dims[] = {{"y_slab", ns}};
        const gf_postnc_series vars[] = {
            {"y_slab", 1, {0}, "m", "slab centre above the plane", NULL, yc},
            {"u_grain", 1, {0}, "m s-1", "grain-phase averaged downslope velocity", NULL, ug},
            {"phi_grain", 1, {0}, "1", "grain volume fraction", NULL, phi},
            {"u_fluid", 1, {0}, "m s-1", "fluid-phase averaged downslope velocity", NULL, uf},
        };
        st = gf_postnc_write(ctx, in, "profiles", 1, dims, GF_POSTNC_COUNT(dims), vars, GF_POSTNC_COUNT(vars));
    }
    gf_stage_grains_free(&g);
    free(t), free(x), free(y), free(z), free(u), free(v), free(w), free(vol), free(mom), free(ug), free(phi), free(uf), free(yc);
    return st;
}
