/*
 * Lab notebook — stages profiles and energy on a synthetic avalanche.
 *
 * Grains on a simple cubic lattice of spacing D = 5 mm: 10 columns in x,
 * 4 in z (L = 10 D, W = 4 D periodic cell), layers at y = (j + 0.5) D,
 * j = 0..9; layer 0 glued (the rough base, not counted). Mobile grains move
 * with the linear profile u = U0 y / h, U0 = 0.2 m/s, h = 10 D.
 * Known answers per slab j of thickness D (eq. 4.7, solid-volume weighted):
 *   ⟨U⟩_g = U0 (j + 0.5)/10 exactly (all grains of the slab share y);
 *   φ_g = 40 (π D³/6)/(L W D) = π/6 = 0.523599 for j >= 1 (L and W are
 *     estimated from the grain extents: 9 D + D = 10 D exactly here);
 *   φ_g = 0 in slab 0 (glued).
 * Tolerances 1e-9 relative (no approximation in this construction).
 * Steady window: grain_flow_rate ramps to a constant at t = 5 s, so frames
 * before ~5 s are excluded (MSER-5; the profile is the same in every frame,
 * so only the frame count depends on it: 14 to 16 of the 20 frames).
 * Fluid (fields.nc, cells of D/4 over the same 10 D × 10 D × 4 D box, 20
 * records at the particle times): fluid fraction ε = 0.4 + 0.02 y/D and
 * u_f = 0.1 y/h + 0.05 sin(2π x/L). Per slab j, the ε-weighted average over
 * its 4 cell rows y_m = (4j + m + 0.5) D/4 is Σ ε_m u_m / Σ ε_m (the sine
 * averages out over whole periods in x): computed in closed form by the test,
 * 1e-9 relative.
 * Mean particle Stokes number (eq. 4.17): the mobile grains' mean |u| D is
 * U0 D (1/9) Σ_{j=1..9} (j + 0.5)/10 = 0.55 U0 D, so
 * St̄ = ρ_p 0.55 U0 D / (9 η) = 2500 × 0.55 × 0.2 × 0.005 / 0.09 = 15.278
 * and R̄e* = St̄ / r with r = sqrt(5 × 2.5 / 3) = 2.0412: 7.4848 (1e-9).
 * Energy: ecx_per_grain = E0 exp(−(t − 3)²), E0 = 0.082 m g D (the seed's
 * case D value, Table 5.1) with m = ρ_p π D³/6 -> E_cx^max/(m g D) = 0.082 at
 * t = 3 s (sampled exactly), 1e-9 relative.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_ncread.h"
#include "gf_post_synth.h"
#include "gf_test.h"
#include "stages/gf_stage.h"
#include "synth_stage.h"

int main(void)
{
    synth_meta m;
    synth_meta_default(&m, "prof1", "avalanche");
    m.incline_deg = 25.0;
    const double D = m.D, U0 = 0.2, h = 10 * D;
    const size_t N = 10 * 4 * 10, NTF = 20, NTD = 200;
    double *rad = malloc(N * sizeof *rad), *X = malloc(N * NTF * sizeof *X), *Y = malloc(N * NTF * sizeof *Y);
    double *Z = malloc(N * NTF * sizeof *Z), *U = malloc(N * NTF * sizeof *U), tf[20];
    unsigned char *glued = calloc(N, 1);
    size_t i = 0;
    for (int j = 0; j < 10; ++j)
        for (int a = 0; a < 10; ++a)
            for (int c = 0; c < 4; ++c, ++i) {
                rad[i] = 0.5 * D;
                glued[i] = j == 0;
                for (size_t k = 0; k < NTF; ++k) {
                    X[i * NTF + k] = (a + 0.5) * D;
                    Y[i * NTF + k] = (j + 0.5) * D;
                    Z[i * NTF + k] = (c + 0.5) * D;
                    U[i * NTF + k] = j == 0 ? 0.0 : U0 * (j + 0.5) * D / h;
                }
            }
    for (size_t k = 0; k < NTF; ++k)
        tf[k] = (double)k;
    char dir[1024];
    synth_scratch(dir, sizeof dir, "profiles");
    GF_CHECK(synth_particles(dir, &m, N, NTF, tf, rad, glued, X, Y, Z, U) == 0);
    const double mass = m.rho_p * M_PI / 6.0 * D * D * D, E0 = 0.082 * mass * m.g * D;
    double *t = malloc(NTD * sizeof *t), *q = malloc(NTD * sizeof *q), *e = malloc(NTD * sizeof *e);
    for (size_t k = 0; k < NTD; ++k) {
        t[k] = 0.1 * (double)k;
        q[k] = 1e-4 * (t[k] < 5.0 ? t[k] / 5.0 : 1.0) * (1.0 + 0.01 * sin(7.0 * t[k]));
        e[k] = E0 * exp(-(t[k] - 3.0) * (t[k] - 3.0));
    }
    const char *names[] = {"grain_flow_rate", "ecx_per_grain"};
    const char *units[] = {"m3 s-1", "J"};
    const double *vals[] = {q, e};
    GF_CHECK(synth_diagnostics(dir, &m, NTD, t, 2, names, units, vals) == 0);

    /* fluid fields: 40 x 40 x 16 cells of D/4 */
    const size_t nx = 40, ny = 40, nz = 16, nc = nx * ny * nz;
    double *eps = malloc(NTF * nc * sizeof *eps), *uf = malloc(NTF * nc * sizeof *uf);
    for (size_t k = 0; k < NTF; ++k)
        for (size_t c = 0; c < nc; ++c) {
            const double yy = ((double)((c / nx) % ny) + 0.5) * 0.25 * D, xx = ((double)(c % nx) + 0.5) * 0.25 * D;
            eps[k * nc + c] = 0.4 + 0.02 * yy / D;
            uf[k * nc + c] = 0.1 * yy / h + 0.05 * sin(2.0 * M_PI * xx / (10 * D));
        }
    GF_CHECK(synth_fields(dir, &m, nx, ny, nz, 0.25 * D, NTF, tf, eps, uf) == 0);
    free(eps), free(uf);

    gf_ctx ctx = {0};
    gf_post_row row;
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_profiles, dir, "avalanche", 1, &row), &ctx);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_energy, dir, "avalanche", 1, &row), &ctx);
    const double nf = gf_post_row_get(&row, "n_profile_frames");
    printf("profiles: %g frames, Ug_max = %.6f m/s (true %.6f), phi_max = %.6f (true %.6f), h_g = %.4f m (true %.4f)\n",
           nf, gf_post_row_get(&row, "Ug_max_m_s"), U0 * 0.95, gf_post_row_get(&row, "phi_g_max"), M_PI / 6,
           gf_post_row_get(&row, "h_g_m"), h);
    GF_CHECK(nf >= 14 && nf <= 16);
    GF_CHECK_REL(gf_post_row_get(&row, "Ug_max_m_s"), U0 * 0.95, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "phi_g_max"), M_PI / 6.0, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "h_g_m"), h, 1e-9);
    printf("St_bar = %.4f (true %.4f), Re_bar = %.4f (true %.4f)\n", gf_post_row_get(&row, "St_bar"),
           2500 * 0.55 * U0 * D / 0.09, gf_post_row_get(&row, "Re_bar"), 2500 * 0.55 * U0 * D / 0.09 / sqrt(12.5 / 3));
    GF_CHECK_REL(gf_post_row_get(&row, "St_bar"), 2500 * 0.55 * U0 * D / 0.09, 1e-9);
    GF_CHECK_REL(gf_post_row_get(&row, "Re_bar"), 2500 * 0.55 * U0 * D / 0.09 / sqrt(12.5 / 3), 1e-9);
    printf("energy: Ecx_max/(m g D) = %.6f (true 0.082) at %.3f s (true 3)\n",
           gf_post_row_get(&row, "Ecx_max_over_mgD"), gf_post_row_get(&row, "t_Ecx_max_s"));
    GF_CHECK_REL(gf_post_row_get(&row, "Ecx_max_over_mgD"), 0.082, 1e-9);
    GF_CHECK_ABS(gf_post_row_get(&row, "t_Ecx_max_s"), 3.0, 1e-9);

    /* the full profile in post_profiles.nc, slab by slab */
    char p[1100];
    snprintf(p, sizeof p, "%s/post_profiles.nc", dir);
    gf_ncr f;
    GF_CHECK_OK(gf_ncr_open(&ctx, p, &f), &ctx);
    double *ug = NULL, *phi = NULL, *ufl = NULL;
    size_t n1 = 0, n2 = 0, n3 = 0;
    GF_CHECK_OK(gf_ncr_var_1d(&ctx, &f, "u_fluid", &ufl, &n3), &ctx);
    double worst = 0.0;
    for (size_t j = 0; j < n3 && j < 10; ++j) {
        double num = 0, den = 0;
        for (int mm = 0; mm < 4; ++mm) {
            const double yy = (4.0 * j + mm + 0.5) * 0.25 * D, e = 0.4 + 0.02 * yy / D;
            num += e * 0.1 * yy / h;
            den += e;
        }
        GF_CHECK_REL(ufl[j], num / den, 1e-9);
        worst = fmax(worst, fabs(ufl[j] / (num / den) - 1.0));
    }
    printf("fluid profile: %zu slabs, worst relative error %.2g\n", n3, worst);
    free(ufl);
    GF_CHECK_OK(gf_ncr_var_1d(&ctx, &f, "u_grain", &ug, &n1), &ctx);
    GF_CHECK_OK(gf_ncr_var_1d(&ctx, &f, "phi_grain", &phi, &n2), &ctx);
    GF_CHECK(n1 == 10 && n2 == 10);
    for (size_t j = 1; j < n1 && j < 10; ++j) {
        GF_CHECK_REL(ug[j], U0 * (j + 0.5) / 10.0, 1e-9);
        GF_CHECK_REL(phi[j], M_PI / 6.0, 1e-9);
    }
    if (n2 > 0)
        GF_CHECK_ABS(phi[0], 0.0, 1e-12);
    char stage[64];
    GF_CHECK_OK(gf_ncr_att_text(&ctx, &f, "post_stage", stage, sizeof stage), &ctx);
    GF_CHECK(strcmp(stage, "profiles") == 0);
    gf_ncr_close(&f);
    free(ug), free(phi), free(rad), free(X), free(Y), free(Z), free(U), free(glued), free(t), free(q), free(e);
    return gf_test_finish();
}
