/* The coupling tiers' shared checkpoint steps; see gf_coupling_restart.h. */
#include "coupling/gf_coupling_restart.h"

gf_status gf_coupling_put_arrays(gf_restart *r, const gf_restart_array *arrays, int n_arrays)
{
    for (int i = 0; i < n_arrays; ++i)
        GF_TRY(gf_restart_put_f64(r, arrays[i].name, arrays[i].n, arrays[i].values));
    return GF_OK;
}

gf_status gf_coupling_get_arrays(gf_restart *r, const gf_restart_array *arrays, int n_arrays)
{
    for (int i = 0; i < n_arrays; ++i)
        GF_TRY(gf_restart_get_f64(r, arrays[i].name, arrays[i].n, arrays[i].values));
    return GF_OK;
}

gf_status gf_coupling_check_grid(gf_ctx *ctx, const int64_t saved_n_cells[3], const gf_grid *g)
{
    for (int d = 0; d < 3; ++d)
        if (saved_n_cells[d] != g->n[d])
            return GF_FAIL(ctx, GF_ERR_CONFIG,
                           "restart: the checkpoint's fluid grid is %lldx%lldx%lld cells, this spec builds %dx%dx%d",
                           (long long)saved_n_cells[0], (long long)saved_n_cells[1], (long long)saved_n_cells[2],
                           g->n[0], g->n[1], g->n[2]);
    return GF_OK;
}
