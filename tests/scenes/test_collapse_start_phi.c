/*
 * The column a collapse starts from has the Phi_i asked (issue #2: Phi_i within +-0.005; Rondon et al.
 * 2011 and Izard 2014 ch. 5 compare columns at 0.55 and 0.60 from t = 0).
 *
 * The loose column of the immersed validation (validate_collapse: R0 = 48 D, a = 0.5, W = 3 D, the
 * seed's grains, D = 7.6 mm, rho_p = 8000, mu_c = 0.25, the default t_c = 0.01 sqrt(D/g)), 0.55 asked,
 * rotations blocked until t = 0 (settle_rotation_locked = 1), packing seed 1, built twice:
 *   - relax_preparation = 0: the preparation measures its deposit as built at mu_prep ~ 0.27, and the
 *     scene's re-equilibration, with the run's stiffer contacts and unloaded tangential springs, compacts
 *     it: measured 0.557 at t = 0, beyond the +-0.005 the preparation was tuned to;
 *   - relax_preparation = 1: each deposit relaxes with the run's contacts before it is measured, so the
 *     column starts within 0.005 of 0.55 (measured 0.550).
 * Claims: the relaxed column starts within 0.005 of 0.55 (the tolerance the issue asks for), and the
 * unrelaxed one at least 0.003 denser (the compaction the relaxation is there to absorb). The build
 * only (preparation and re-equilibration, dry): about 30 s per column on one core.
 */
#include <math.h>
#include <stdio.h>

#include "scene_runner.h"

static double start_phi(int relax, double *build_s)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    runner_dry_spec(&spec, "column_collapse");
    spec.grains = (gf_grains_spec){.diameter_m = 7.6e-3, .polydispersity = 0.05, .density_kg_m3 = 8000.0};
    spec.phi_initial = 0.55;
    spec.aspect_ratio_a = 0.5;
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "column_length_over_D", 48.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "settle_rotation_locked", 1.0), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "relax_preparation", relax), &ctx);
    double t0 = runner_now_s();
    gf_sim *sim = runner_create(&ctx, &spec);
    if (!sim)
        return NAN;
    double phi_global, phi_local;
    GF_CHECK_OK(gf_scene_find("column_collapse")->initial_packing(sim, &phi_global, &phi_local), &ctx);
    *build_s = runner_now_s() - t0;
    gf_sim_destroy(&sim);
    return phi_local;
}

int main(void)
{
    double s0, s1;
    double plain = start_phi(0, &s0), relaxed = start_phi(1, &s1);
    printf("loose column, 0.55 asked, Phi_i at t = 0: preparation measured as built %.4f (%.0f s), "
           "relaxed with the run's contacts %.4f (%.0f s)\n", plain, s0, relaxed, s1);
    GF_CHECK_ABS(relaxed, 0.55, 0.005);
    GF_CHECK(plain > relaxed + 0.003);
    return gf_test_finish();
}
