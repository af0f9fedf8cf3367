/*
 * One settling phase of a packing preparation (particles/gf_packing.h) run
 * by the engine: the container of a gf_packing_spec becomes a
 * packing_preparation scene (gf_scene_packing_preparation.c), its glued
 * obstacles and the grains to settle are added to it, and gf_sim advances
 * until the grains are at rest. The phase states what differs from a run:
 * the contacts (t_c, eps, mu), blocked rotations, and a linear drag
 * F = -m u / tau_drag, the viscous fluid the loose columns of Izard 2014 §5.2
 * settle in, reduced to a fluid at rest.
 */
#ifndef GF_PACKING_SETTLE_H
#define GF_PACKING_SETTLE_H

#include "particles/gf_packing.h"

typedef struct gf_packing_phase {
    double t_contact_s;       /* contact duration of the mean pair */
    double restitution;       /* normal restitution */
    double mu;                /* grain-grain (and grain-obstacle) friction; the plane walls have none */
    double dt_over_tc;        /* DEM step / t_c */
    int rotation_locked;      /* 1: infinite rolling resistance */
    double drag_time_s;       /* tau_drag; INFINITY: no drag */
} gf_packing_phase;

/* Settles the grains of `grains` (mobile, each with its position, velocity
 * and radius, density spec->density_kg_m3) in the container of spec with its
 * obstacles, under phase, until their mean kinetic energy per grain is below
 * 1e-4 m g D (m the mean grain's mass, no sooner than 5 sqrt(D/g)) or
 * 400 sqrt(D/g) have passed; writes the settled positions and velocities
 * back into grains, in their order. Errors: those of gf_sim_create and
 * gf_sim_advance (GF_ERR_PHYSICS for grains overlapping at the start). */
gf_status gf_packing_settle(gf_ctx *ctx, const gf_packing_spec *spec, const gf_packing_phase *phase,
                            gf_particles *grains);

#endif
