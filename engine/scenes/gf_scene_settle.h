/*
 * Rest of a granular scene: the settling with the run's contacts that a
 * scene does before t = 0 (after its preparation, behind a closed gate or
 * orifice), and the rest test that ends a run once the grains have stopped.
 * Both in the grain time scale sqrt(D/g) and the grain energy m g D.
 */
#ifndef GF_SCENE_SETTLE_H
#define GF_SCENE_SETTLE_H

#include "gf_sim.h"

/* Advances the sim by settle_time_nd sqrt(D/g), rounded up to whole steps of
 * the spec's dt (none when <= 0). Errors: gf_sim_advance's. */
gf_status gf_scene_settle(gf_sim *sim, const gf_run_spec *spec, double settle_time_nd);

/* Non-zero when the kinetic energy (translation and rotation) per mobile
 * grain is below rest_energy_nd m g D, m the mean mass of the mobile grains
 * and D the spec's diameter; non-zero too when no grain is mobile. */
int gf_scene_at_rest(gf_sim *sim, double rest_energy_nd);

#endif
