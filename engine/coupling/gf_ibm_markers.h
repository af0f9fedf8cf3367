/*
 * gf_ibm_markers: the Lagrangian-marker direct forcing of the resolved tier
 * (fluid.ibm_forcing: markers), the alternative to the smoothed solid
 * fraction of gf_ibm.h (fluid.ibm_forcing: smoothed, Izard 2014).
 *
 * Why. The smoothed forcing drags a shell of about three cells a fraction
 * alpha toward the grain's velocity at every forcing: the more forcings per
 * unit time, the bigger the grain the flow sees, and the terminal velocity
 * depends on the fluid step. The forcing below acts at the grain's surface
 * only, with the force that makes the interpolated velocity there the grain's
 * own, whatever the step.
 *
 * Markers (Uhlmann, J. Comput. Phys. 209, 2005). N_i markers on a sphere
 * of radius R_m = R_i - r_d dx, concentric with grain i, r_d = fluid.ibm_retraction_dx
 * (Breugem, J. Comput. Phys. 231, 2012, retracts them by 0.3 dx so that
 * the diffuse interface makes the grain hydrodynamically R_i, not R_i + ~dx/3).
 * N_i = round(4 pi R_m^2 / dx^2), about one marker per cell face of surface,
 * placed on the golden-angle (Fibonacci) spiral,
 *     z_l = 1 - (2l + 1)/N,  rho_l = sqrt(1 - z_l^2),  phi_l = l pi (3 - sqrt 5),
 * fixed in the lab frame (a sphere: no orientation to follow). Each marker
 * carries the volume of a shell one cell thick (Breugem 2012):
 *     dV_l = (pi dx / 3N) (12 R_m^2 + dx^2).
 *
 * Kernel. The regularised three-point delta of Roma, Peskin & Berger
 * (J. Comput. Phys. 153, 1999), a product over the axes of
 *     phi(r) = (1 + sqrt(1 - 3 r^2)) / 3                          |r| <= 1/2,
 *              (5 - 3|r| - sqrt(1 - 3 (1 - |r|)^2)) / 6          1/2 <= |r| <= 3/2,
 * r the distance to the face in cells, on each staggered velocity component's
 * own faces (3 x 3 x 3 faces a marker and component). Near a wall the faces
 * that are not unknowns (outside the grid, or the wall's normal faces) are
 * dropped and the remaining weights rescaled to sum to one: the stencil never
 * reads outside the grid, and the momentum the markers give the fluid is
 * still exactly the momentum they take from the grain. On a periodic axis the
 * stencil wraps.
 *
 * Forcing, per substep of the fluid step, with multi-direct forcing (Luo et
 * al., Phys. Rev. E 76, 2007; Breugem 2012): from u^0 = u~ (the predictor),
 * for s = 1..GF_IBM_MARKER_SWEEPS,
 *     U_l = sum_faces u^{s-1} delta(x - X_l) dx^3                (interpolation)
 *     F_l^s = (U_i + w_i x (X_l - x_i) - U_l) / dt
 *     f^s(x) = sum_l F_l^s delta(x - X_l) dV_l,   u^s = u^{s-1} + dt f^s   (spreading)
 * and f = sum_s f^s enters the Crank-Nicolson step as the smoothed forcing
 * does. The sweeps correct the overlap of neighbouring markers' kernels, which
 * otherwise leaves the interpolated slip at a fraction of its start.
 *
 * Force and torque (Uhlmann 2005; Kempe & Froehlich, J. Comput. Phys.
 * 231, 2012; Breugem 2012): the momentum balance of the fluid
 * inside grain i, rigid or not, gives the surface force
 *     F_i = -rho sum_l F_l dV_l + rho d/dt int_{V_i} u dV - rho V_i g,
 *     T_i = -rho sum_l (X_l - x_i) x F_l dV_l + rho d/dt int_{V_i} (x - x_i) x u dV,
 * the last term of F_i the buoyancy the excess pressure leaves out (the step
 * loop adds m g, as for the smoothed forcing). The mean pressure gradient of a
 * periodic gravity axis cancels from F_i as it does there (gf_coupling_resolved.c).
 * The internal momentum is the sum over the faces of the smoothed fraction
 * alpha_i of gf_ibm.h centred on R_i (its retraction 0), at the end of each
 * fluid step (grain frozen at x_i^n); its rate is the difference from the last
 * step's value, taken where the grain then was, over dt, added once a step: the
 * derivative that follows the moving volume (Breugem 2012). A rate over a
 * volume held still (both values at x_i^n) misses the flux of the fluid the
 * smoothed weights count outside R_i and biases the terminal velocity (+3.5 %
 * at D/dx 8; docs/notes/resolved-settling.md). This term removes the rho_p/(rho_p - rho) factor of Izard's formula; with it
 * explicit, the grain's acceleration feeds back through rho V_i/m_i = rho/rho_p
 * per step, stable for rho_p/rho > 1 (the tier requires 1.7).
 *
 * Threads. Interpolation and each grain's sums are per grain (its own markers
 * in order); the spreading runs one velocity component per thread, grains and
 * markers in order: the forcing and the forces are bitwise the same on any
 * number of threads.
 */
#ifndef GF_IBM_MARKERS_H
#define GF_IBM_MARKERS_H

#include "coupling/gf_ibm.h"

/* Multi-direct forcing sweeps per substep. Each sweep halves the markers' slip (the kernel's overlap with itself,
 * int phi^2 dr ~ 1/2): four leave 1/16 of it, and the terminal velocity's spread over a factor 4 in the fluid
 * step falls from 0.27 % (two) to 0.03 %, at no measurable cost (docs/notes/resolved-settling.md). */
#define GF_IBM_MARKER_SWEEPS 4

/* The names of fluid.ibm_forcing, NULL-terminated: "smoothed" (gf_ibm.h), "markers". */
extern const char *const gf_ibm_forcing_names[];
typedef enum gf_ibm_forcing { GF_IBM_SMOOTHED, GF_IBM_MARKERS } gf_ibm_forcing;
/* name -> forcing; 0 when the name is known, -1 otherwise. */
int gf_ibm_forcing_from_name(const char *name, gf_ibm_forcing *out);

typedef struct gf_ibm_markers {
    int n_threads;          /* as gf_ibm_map's */
    double retraction_cells; /* r_d: markers on R - r_d dx */
    size_t n_grains, cap_grains;
    size_t *first;          /* grain i's markers are first[i] .. first[i+1]-1 (n_grains + 1 entries) */
    double *F;              /* 3 per marker: this sweep's F_l (m/s^2) */
    size_t cap_markers;
    double *slip2;          /* per grain: the sum of its markers' squared slip at the last sweep (m2/s2) */
    double last_slip[GF_IBM_MARKER_SWEEPS]; /* rms slip per component before each sweep of the last forcing, m/s */
} gf_ibm_markers;

/* The number of markers on a sphere of radius R_m on a grid of step dx (at least 1). */
size_t gf_ibm_marker_count(double R_m, double dx_m);
/* Direction of marker l of n on the golden-angle spiral (unit vector). */
void gf_ibm_marker_direction(size_t l, size_t n, double dir[3]);
/* The 1-D three-point kernel of Roma, Peskin & Berger (1999) at r cells. */
double gf_ibm_roma_kernel(double r);

/* Marker forcing of the local grains. u_pred: the predictor u~ (face arrays); u_work: face scratch arrays;
 * force_out: receives f = sum_s f^s (m/s^2); F_N, T_Nm: n_local x 3, receive -rho sum_l F_l dV_l and its torque
 * (the internal-momentum and buoyancy terms are the caller's, gf_ibm_momentum). */
gf_status gf_ibm_markers_force(gf_ctx *ctx, gf_ibm_markers *mk, const gf_grid *g, const gf_particles *p,
                               const double *const u_pred[3], double dt_s, double rho_f, double *const u_work[3],
                               double *const force_out[3], double *F_N, double *T_Nm);
void gf_ibm_markers_free(gf_ibm_markers *mk);

#endif
