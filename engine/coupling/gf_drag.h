/*
 * gf_drag: the drag closures of the unresolved tier, a registry selected by
 * spec.fluid.drag (docs/fast-tier.md). A closure is one file
 * (gf_drag_<name>.c, its formula and source in that file's header) and one
 * row in gf_drag_table.c; the schema's allowed names are the registry's.
 *
 * Every closure gives the coefficient K (kg/s) of the drag on one grain,
 *   F_d = K (u_f - v),
 * with u_f the (undisturbed, interstitial) fluid velocity at the grain, v a
 * grain velocity, eps the local fluid fraction (phi = 1 - eps), W = |u_f - v|
 * and the superficial (particle) Reynolds number Re = rho_f eps W D / eta_f.
 * F_d is the drag WITHOUT the mean pressure gradient: the pressure-gradient
 * (buoyancy) force -V grad p is added separately by the coupling (the
 * Anderson–Jackson "model A" split).
 *
 * Two kinds of closure:
 *  - per-grain slip (fluctuation == NULL): v is the grain's own velocity
 *    (di_felice, beetstra, tenneti: laws for the mean slip of a suspension or
 *    of a fixed bed, applied to each grain);
 *  - mean slip (fluctuation != NULL): the law K acts on the slip between the
 *    fluid and the LOCAL MEAN grain velocity <v> (the kernel average of the
 *    grains' velocities at the grain), and the grain's own motion about that
 *    mean, v - <v>, is resisted by the separate coefficient `fluctuation`:
 *      F_d = K (u_f - <v>) + K' (<v> - v).
 *    Resistance to the relative motion of touching neighbours is the
 *    lubrication force of the DEM pair loop (spec.fluid.lubrication).
 *
 * Which to use. The default in gf_run_spec.c is di_felice: it reproduces
 * Richardson–Zaki hindered settling (test_hindered_settling), the state of a
 * collapsing or avalanching column, and it is well-behaved from eps -> 1 to
 * packed beds. Its weakness is the fixed dense bed (Carman–Kozeny drag
 * underestimated by ~30 % at phi = 0.4): beetstra and tenneti are fits to
 * fixed arrays and give the Carman–Kozeny/Ergun pressure drop
 * (test_fixed_bed) but hinder a settling suspension about twice too much at
 * phi = 0.4. For a quasi-static dense column whose pore pressure is set by the
 * permeability, beetstra is the better choice. mean_slip is di_felice on the
 * mean slip with an isolated-sphere resistance to the grain-scale motion
 * (dense sheared beds, docs/fast-tier.md for what it changes and what not).
 */
#ifndef GF_DRAG_H
#define GF_DRAG_H

#include "core/gf_status.h"

/* K in kg/s for a grain of diameter D in a fluid of density rho and viscosity mu; eps in [0.2, 1], slip >= 0. */
typedef double (*gf_drag_fn)(double diameter_m, double eps, double slip_m_s, double rho_kg_m3, double viscosity_Pa_s);

typedef struct gf_drag_info {
    const char *name;        /* the value of fluid.drag */
    const char *summary;     /* one line, with the source */
    gf_drag_fn coefficient;  /* K on the slip u_f - v (per-grain closures) or u_f - <v> (mean-slip closures) */
    gf_drag_fn fluctuation;  /* NULL: per-grain slip; else K' on <v> - v, slip argument |<v> - v| */
} gf_drag_info;

/* The closure named name, or NULL. */
const gf_drag_info *gf_drag_lookup(const char *name);
/* The same, GF_ERR_CONFIG naming the known closures if there is none. */
gf_status gf_drag_find(gf_ctx *ctx, const char *name, const gf_drag_info **law);
/* NULL-terminated list of the registered names (the schema's allowed values). */
const char *const *gf_drag_names(void);

/* K in kg/s of law's coefficient, eps clipped to [0.2, 1]. */
double gf_drag_coefficient(const gf_drag_info *law, double diameter_m, double eps, double slip_m_s, double rho_kg_m3,
                           double viscosity_Pa_s);
/* K' in kg/s of law's fluctuation resistance (law->coefficient's K for a per-grain closure). */
double gf_drag_fluctuation_coefficient(const gf_drag_info *law, double diameter_m, double eps, double slip_m_s,
                                       double rho_kg_m3, double viscosity_Pa_s);

extern const gf_drag_info gf_drag_law_di_felice;
extern const gf_drag_info gf_drag_law_beetstra;
extern const gf_drag_info gf_drag_law_tenneti;
extern const gf_drag_info gf_drag_law_mean_slip;

#endif
