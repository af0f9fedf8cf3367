/*
 * gf_packing: preparation of a granular column or bed at a requested
 * packing fraction Phi_i (Izard 2014 §5.2, §5.5).
 *
 * Protocol (deposition with a tuned preparation friction):
 *   1. Grains (radii from gf_psd) are placed on a jittered loose lattice
 *      (solid fraction ~0.35) filling the container footprint, enough of them
 *      for a deposit taller than the target height.
 *   2. They settle under gravity through a linear drag F = -m u / tau_prep
 *      (terminal speed g tau_prep = 2 sqrt(gD)), which plays the part of the
 *      viscous fluid the loose columns of the thesis settle in (Izard 2014 §5.2) and keeps
 *      impacts gentle, with a preparation inter-grain friction mu_prep, a low
 *      restitution 0.3 and rotations blocked (infinite rolling resistance).
 *      Frictionless grains pour dense (Phi = 0.637, random close packing);
 *      friction with free rolling only reaches ~0.59 at mu = 1 under gravity
 *      (measured here; Silbert et al. PRE 65 031304, 2002), while non-rolling
 *      frictional grains stop where they land and reach the random-loose
 *      limit ~0.55 at mu ~ 0.25 (rolling resistance is the usual DEM route to
 *      loose packings; Onoda & Liniger PRL 64 2727, 1990 for the RLP limit).
 *      Grain-wall friction is zero during preparation, so walls hold no arches.
 *   3. The interior packing fraction Phi(mu_prep) decreases monotonically
 *      with mu_prep in [0, 0.4] (up to the sampling noise of a finite
 *      deposit); mu_prep is found by safeguarded regula falsi until the
 *      interior value is within the
 *      tolerance of the target. Once the bracket on mu_prep is narrower than
 *      0.02, across which Phi changes less than a small deposit's scatter
 *      (0.01-0.02 between lattice draws for a control box of a few D), the
 *      next deposits are new draws of the loose lattice (seeds derived from
 *      the spec's) at the mu_prep where the least-squares line through every
 *      deposit meets the target. When the iteration budget is spent first,
 *      the preparation fails (GF_ERR_PHYSICS, naming the closest deposit):
 *      a run never starts from a packing other than the one requested.
 *      With relax.mu > 0, each deposit then relaxes with the run's contacts
 *      (relax: mu_c, t_c, eps_max), rotations still blocked, from zero
 *      tangential history, before it is measured. That is what happens to
 *      it when the run starts: the run's contacts are stiffer than the
 *      preparation's, their springs start unloaded, and a loose packing
 *      held by friction compacts (measured at 48 D, seed 1, 0.55 asked:
 *      0.552 measured, 0.557 at t = 0 after the scene's re-equilibration;
 *      0.553 with the run at the preparation's t_c, 0.552 with mu_c 0.4).
 *      The bisection then tunes the relaxed Phi.
 *   4. The deposit is trimmed: grains whose centre lies above the target
 *      height H are removed, so the column top is at H within one radius.
 *   Targets below what the most frictional deposit reaches are reported as
 *   GF_ERR_PHYSICS (no silent clamp).
 *   Free pour (free_pour = 1, phi_target NaN): one deposit at mu_natural
 *   with free rotations and no drag, the grains falling from the loose
 *   lattice (twice the final height): the thesis' "settling from a taller
 *   box" for its Janssen silo. The packing is what the pour reaches.
 *
 * Measures (both stored in the result, for phi_initial_measured and
 * phi_initial_local of the run's metadata):
 *   phi_global = sum_i V_i / (footprint x H)       (Rondon et al. 2011 estimate)
 *   phi_local  = sampled solid fraction of an interior control box, at
 *                margin m from the walls, the base and the top (Izard 2014 §5.2: the
 *                thesis averages alpha over such a volume).
 *
 * Accuracy and cost (tests/scenes/test_packing.c, 16D x 8D x 3D column,
 * ~400 grains, one core): Phi_i = 0.55 -> 0.551, 0.58 -> 0.585, 0.60 ->
 * 0.597 (interior), in 1-4 deposits of 2-4 s each; the global estimate is
 * 0.02 below the interior one (walls and the trimmed top).
 *
 * The deposits run in the engine (one DEM): each settling phase is a gf_sim
 * of the scene packing_preparation (the container: box, floor, plane walls
 * without friction) holding the grains and the glued obstacles
 * (scenes/gf_packing_settle.h). What the preparation changes is stated as
 * the phase's settings, not as other code: its contacts (linear law, t_c =
 * 0.02 sqrt(D/g), restitution 0.3, friction mu_prep, dt = t_c/15), rotations
 * locked (gf_sim_set_rotation_locked), and the drag F = -m u / tau_prep,
 * applied as the exact decay u exp(-t/tau_prep) once per t_c (operator
 * splitting; t_c/tau_prep = 0.01). The engine has one grain-grain friction,
 * so during the deposition the obstacles take mu_prep too (see
 * mu_obstacles). Its contacts are softer than a run's, so the scene
 * re-equilibrates with the run's contacts before t = 0 and records the Phi
 * it then measures.
 */
#ifndef GF_PACKING_H
#define GF_PACKING_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"
#include "particles/gf_particles.h"
#include "particles/gf_psd.h"

/* The run's contact law for the relaxation of step 3 (mu = 0: no relaxation). */
typedef struct gf_packing_relax {
    double mu;                    /* grain-grain friction mu_c (grain-obstacle too, unless mu_obstacles is set) */
    double t_contact_s;           /* contact duration t_c of the mean pair */
    double restitution;           /* eps_max */
} gf_packing_relax;

typedef struct gf_packing_spec {
    double lo_m[3], hi_m[3];      /* container; hi_m[1] is the target height H (top of the column) */
    int periodic[3];              /* x and z may be periodic; y never */
    int walls_x, walls_z;         /* plane walls at lo/hi on non-periodic x / z (1) or none (0: obstacles close it) */
    double wall_setback_m;        /* those planes sit this far outside lo/hi (behind a wall of glued obstacles,
                                     so that no grain squeezed through the obstacles' gaps leaves the box) */
    double phi_target;            /* requested interior Phi; NaN: one deposit at mu_prep = mu_natural */
    double mu_natural;            /* friction used when phi_target is NaN (the run's mu_c) */
    int free_pour;                /* 1 (phi_target NaN only): the grains fall from the loose lattice with free
                                     rotations and no preparation drag, at mu_natural, i.e. they settle "from a
                                     taller box" with the run's own friction and restitution 0.3 (Izard 2014
                                     §2.1.3.2, the Janssen silo); 0: the tuned protocol above */
    gf_packing_relax relax;       /* the run's contacts, to relax each deposit with before it is measured */
    double tolerance;             /* |phi_local - target| accepted; 0: 0.005 */
    int max_iterations;           /* deposits in the search; 0: 16 (columns of a few D need the draws) */
    double interior_margin_m;     /* margin of the control box; 0: 1.5 D */
    gf_psd psd;
    double density_kg_m3;
    double gravity_m_s2;          /* |g|, along -y */
    const gf_particles *obstacles;/* glued grains present during the deposition (rough base, walls); may be NULL */
    double mu_obstacles;          /* grain-obstacle friction the scene asks for the deposition; the engine's
                                     one grain-grain friction gives the obstacles mu_prep (or mu_natural, or
                                     relax.mu) whatever this says: it only keys the cache (gf_packing_cache.h) */
    uint64_t seed;
} gf_packing_spec;

typedef struct gf_packing_result {
    double phi_global;            /* solid volume / (footprint x H) */
    double phi_local;             /* sampled interior control box */
    double mu_prep;               /* preparation friction of the kept deposit */
    int iterations;               /* deposits run */
    size_t n_grains;              /* grains kept */
    double top_m;                 /* highest grain top after trimming */
    double cpu_s;                 /* wall time of the preparation */
    int reused;                   /* 1: read back from a campaign's preparations (gf_packing_cache.h) */
} gf_packing_result;

/* Prepares the packing and appends its (mobile) grains at rest to out.
 * Errors: bad container or psd (GF_ERR_CONFIG), unreachable target
 * (GF_ERR_PHYSICS, naming the reachable range), GF_ERR_NOMEM. */
gf_status gf_packing_build(gf_ctx *ctx, const gf_packing_spec *spec, gf_particles *out, gf_packing_result *res);

/* One deposit at a given mu_prep (no trimming, no bisection): appends the
 * settled grains to out and returns the interior Phi of [lo, hi] (margin as in
 * spec) in *phi_local. For calibration tests. */
gf_status gf_packing_deposit(gf_ctx *ctx, const gf_packing_spec *spec, double mu_prep, gf_particles *out,
                             double *phi_local);

/* Rough base (Izard 2014 §1.5, §4.1.2.2): glued grains of radii drawn from
 * psd with their centres on the plane y = y_m ("half-grains"), placed by
 * random sequential adsorption over x in [x0, x1), z in [z0, z1) (touching
 * allowed, no overlap, periodic images on the periodic axes) until 500
 * successive rejections, i.e. close to the RSA jamming coverage (0.547 of
 * the plane for equal discs; Feder, J. Theor. Biol. 1980). A random base is
 * statistically the same whatever the domain size, which a lattice fitted
 * to the box length is not. Appends GF_P_GLUED grains to out. */
gf_status gf_packing_rough_base(gf_ctx *ctx, gf_particles *out, const gf_psd *psd, double density_kg_m3, double y_m,
                                double x0_m, double x1_m, double z0_m, double z1_m, const int periodic_xz[2],
                                uint64_t seed);

/* Solid fraction of the box [lo, hi] by sampling the grain indicator on a
 * cell-centred lattice of spacing h_m, periodic images of the domain
 * [dom_lo, dom_hi] included on periodic axes; glued grains count when
 * include_glued. NaN for a box thinner than h. */
double gf_packing_solid_fraction_box(const gf_particles *p, const double dom_lo_m[3], const double dom_hi_m[3],
                                     const int periodic[3], const double lo_m[3], const double hi_m[3], double h_m,
                                     int include_glued);

#endif
