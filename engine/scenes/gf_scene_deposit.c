/*
 * A scene's deposit through the preparations cache (gf_scene_deposit.h),
 * with one log line that says whether it was built or read back.
 */
#include "scenes/gf_scene_deposit.h"

#include "io/gf_packing_cache.h"

gf_status gf_scene_deposit(gf_sim *sim, const gf_packing_spec *ps, gf_packing_result *pr)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    GF_TRY(gf_packing_build_cached(ctx, ps, gf_sim_preparation_dir(sim), gf_sim_particles(sim), pr));
    gf_log(ctx, GF_LOG_INFO, "%s: %zu grains at Phi %.4f (preparation interior; global %.4f), %d deposits, %.1f s%s",
           gf_sim_spec(sim)->scene, pr->n_grains, pr->phi_local, pr->phi_global, pr->iterations, pr->cpu_s,
           pr->reused ? " (read back from the preparations)" : "");
    return GF_OK;
}
