/*
 * The table of post-processing stages (docs/architecture.md): a new stage is one file
 * and one row here. The order is that of the runs' stages and of their columns in the summary
 * (gf_summary_columns.c).
 * A stage applies to a run when the run's files hold what its `reads` names (the
 * first variable or attribute listed selects): never by the scene's name, so a
 * new scene that writes those variables is post-processed as it stands.
 */
#include "stages/gf_stage.h"

#include <string.h>

const gf_stage_info gf_stage_table[] = {
    {"flow_rate", 2, gf_stage_flow_rate,
     "diagnostics.nc: grain_flow_rate (a flowing layer), time, fluid_flow_rate; or discharge_rate (a discharge "
     "through an orifice), discharge_mass_rate, orifice_packing_fraction, fill_height",
     "summary row"},
    {"regime", 1, gf_stage_regime,
     "attributes (grains, fluid, geometry, scene_param_*); diagnostics.nc: grain_flow_rate, bed_height, "
     "bed_packing_fraction or front_position; particles.nc: "
     "radius, glued",
     "summary row"},
    {"deposit", 3, gf_stage_deposit,
     "attribute column_length_m > 0 (a released column); particles.nc: x, y, radius, glued (all frames); "
     "diagnostics.nc: front_position, deposit_height (continuum runs: stages = continuum), "
     "deposit_extent_1D, deposit_extent_2D (both methods, when written)",
     "summary row, post_deposit.nc"},
    {"pore_pressure", 1, gf_stage_pore_pressure,
     "probes.nc: excess_pore_pressure, station_name, x, y; attribute column_length_m (the gauge at 13/16 R0)",
     "summary row, post_pore_pressure.nc"},
    {"profiles", 2, gf_stage_profiles,
     "particles.nc: x, y, z, u, v, w, radius, glued; diagnostics.nc: grain_flow_rate (or discharge_rate); "
     "fields.nc: x, y, z, fluid_fraction, u_fluid; attributes: grains, fluid (silo: scene_param_width_*)",
     "summary row, post_profiles.nc"},
    {"energy", 1, gf_stage_energy, "diagnostics.nc: ecx_per_grain; particles.nc: radius, glued",
     "summary row, post_energy.nc"},
    {"bounce", 1, gf_stage_bounce,
     "diagnostics.nc: gap_over_D and sphere_velocity_y (a sphere above a wall), time; attributes: grains, fluid, "
     "restitution, t_contact_s",
     "summary row"},
};
const int gf_stage_count = (int)(sizeof gf_stage_table / sizeof gf_stage_table[0]);

const gf_stage_info *gf_stage_find(const char *name)
{
    for (int i = 0; name && i < gf_stage_count; ++i)
        if (strcmp(gf_stage_table[i].name, name) == 0)
            return &gf_stage_table[i];
    return NULL;
}
