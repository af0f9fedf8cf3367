/* Placeholder until the unresolved tier lands: every fluid request is refused. */
#include "coupling/gf_coupling.h"

#include <stdlib.h>

gf_status gf_coupling_create(gf_ctx *ctx, const gf_run_spec *spec, const gf_coupling_setup *setup,
                             gf_coupling **out)
{
    *out = NULL;
    return GF_FAIL(ctx, GF_ERR_UNSUPPORTED, "fluid model '%s' is not available in this build", spec->fluid.model);
}
void gf_coupling_destroy(gf_coupling **c) { if (c) *c = NULL; }
double gf_coupling_dt_max_s(const gf_coupling *c, const gf_particles *p) { return 1e30; }
gf_status gf_coupling_fluid_step(gf_coupling *c, const gf_particles *p, double dt_s) { return GF_ERR_UNSUPPORTED; }
gf_status gf_coupling_add_forces(gf_coupling *c, gf_particles *p) { return GF_ERR_UNSUPPORTED; }
double gf_coupling_excess_pressure_Pa(const gf_coupling *c, const double x_m[3]) { return 0.0; }
int gf_coupling_fields(const gf_coupling *c, int n_cells[3], double lo_m[3], double cell_m[3],
                       const gf_var_info **vars, const double *const **fields) { return 0; }
double gf_coupling_fluid_flow_rate(const gf_coupling *c) { return 0.0; }
double gf_coupling_fluid_mass_kg(const gf_coupling *c) { return 0.0; }
