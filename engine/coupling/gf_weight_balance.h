/*
 * gf_weight_balance: the mean pressure gradient that carries the grains'
 * excess weight along a periodic gravity axis, for every coupling tier.
 *
 * A periodic axis along which gravity acts has no bottom: without a mean
 * pressure gradient the grains' weight in excess of buoyancy would accelerate
 * the whole mixture. A settling tank's bottom supplies
 *     G_d = -phi_mean (rho_p - rho_f) g_d = -(sum_i (m_i - rho_f V_i) / V_box) g_d
 * on each periodic axis d (Capecelatro & Desjardins, J. Comput. Phys. 238,
 * 2013, for the unresolved form; Uhlmann, J. Comput. Phys. 209, 2005, and
 * Uhlmann & Doychev, J. Fluid Mech. 752, 2014, for periodic sedimentation with
 * resolved grains), which keeps the mixture's momentum constant. While any
 * grain is glued, the glued grains (and the walls) carry the weight: G = 0 on
 * every axis, the "physical tank" form of an avalanche on a periodic incline.
 */
#ifndef GF_WEIGHT_BALANCE_H
#define GF_WEIGHT_BALANCE_H

#include "fluid/gf_grid.h"
#include "particles/gf_particles.h"

/* G (Pa/m) on the periodic axes of grid g (box volume from its cells), 0 elsewhere, 0 everywhere with a glued
 * grain or no grains. */
void gf_weight_balance_gradient(const gf_grid *g, const gf_particles *p, double rho_f_kg_m3,
                                const double gravity_m_s2[3], double G_Pa_m[3]);

#endif
