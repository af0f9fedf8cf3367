/*
 * The granular deposit of a scene: built by gf_packing once per set of
 * packing parameters and read back from the run's preparations directory by
 * every later run that asks for the same one (gf_packing_cache.h).
 */
#ifndef GF_SCENE_DEPOSIT_H
#define GF_SCENE_DEPOSIT_H

#include "gf_sim.h"
#include "particles/gf_packing.h"

/* Adds the deposit ps describes to the sim's grains, read back from the
 * sim's preparations directory or built and stored there, and logs its size,
 * packing fractions and cost under the scene's name. Borrows ps; *pr the
 * preparation's result. Errors: gf_packing_build_cached's. */
gf_status gf_scene_deposit(gf_sim *sim, const gf_packing_spec *ps, gf_packing_result *pr);

#endif
