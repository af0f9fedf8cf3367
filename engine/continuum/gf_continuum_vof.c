/*
 * The volume fraction c of the main phase, advected by the divergence-free
 * velocity of the step (two phases; see gf_continuum.h).
 *
 * THINC (Xiao, Honma & Kono, Int. J. Numer. Meth. Fluids 48, 2005): in a
 * donor cell that holds the interface (eps < c < 1 - eps, c monotone across
 * it) c is reconstructed as 0.5 (1 + g tanh(beta (xi - xi0))), g the sign of
 * the slope, xi0 from the cell average, and the flux is the integral of that
 * profile over the part of the cell that crosses the face; elsewhere donor
 * cell. A step is split by direction, the order alternating from step to step,
 * with the dilatation term of Weymouth & Yue (J. Comput. Phys. 229, 2010):
 *     c <- c - (F_hi - F_lo) + c_c (alpha_hi - alpha_lo),
 * alpha = u dt/h the face Courant number and c_c = 1 where c > 1/2 at the
 * start of the step, 0 elsewhere, so that a sweep of a divergence-free field
 * conserves c exactly and stays within [0, 1] at Courant numbers below 1/2
 * per sweep (sub-steps of 0.2 here). What enters through an open side is the
 * second phase (c = 0).
 *
 * It replaces a MUSCL scheme limited by minmod, whose diffusion spread the
 * column of the collapse into a mist of c ~ 0.01-0.2 over the whole domain
 * (docs/continuum.md, "Column collapse").
 */
#include <math.h>

#include "continuum/gf_continuum_internal.h"

static const double thinc_beta = 3.5;       /* interface thickness ~ 2-3 cells (Xiao et al. 2005) */
static const double thinc_eps = 1e-8;
static const double max_sweep_courant = 0.2;

/* ln cosh x without overflow. */
static double log_cosh(double x)
{
    double a = fabs(x);
    return a + log1p(exp(-2.0 * a)) - M_LN2;
}

/* Fraction of a cell volume carried through its face by a THINC profile: the integral of
 * 0.5 (1 + g tanh(beta (xi - xi0))) over [x0, x1] within the cell [0, 1], the cell average being c. */
static double thinc_integral(double c, double g, double x0, double x1)
{
    double b = thinc_beta;
    double t = (cosh(b) - exp(g * b * (2.0 * c - 1.0))) / sinh(b);  /* tanh(b xi0) */
    t = fmin(fmax(t, -1.0 + 1e-15), 1.0 - 1e-15);
    double xi0 = atanh(t) / b;
    return 0.5 * (x1 - x0) + 0.5 * g / b * (log_cosh(b * (x1 - xi0)) - log_cosh(b * (x0 - xi0)));
}

/* c at cell index m along a (others from idx), or -1 outside a non-periodic axis. */
static double cell_c(const gf_continuum *s, const int idx[3], int a, int m)
{
    int t[3] = {idx[0], idx[1], idx[2]};
    t[a] = m;
    if (!s->g.periodic[a] && (m < 0 || m >= s->g.n[a]))
        return -1.0;
    return s->c_cell[gf_continuum_cell_clamped(s, t)];
}

/* Volume fraction (of a cell) crossing face idx of axis a at Courant number alpha (signed). */
static double face_flux(const gf_continuum *s, const int idx[3], int a, double alpha)
{
    int m = idx[a], donor = alpha > 0.0 ? m - 1 : m;
    double cd = cell_c(s, idx, a, donor);
    if (cd < 0.0)
        return 0.0;  /* entering through an open side: the second phase */
    double cu = cell_c(s, idx, a, donor - 1), cn = cell_c(s, idx, a, donor + 1), w = fabs(alpha);
    int interface = cd > thinc_eps && cd < 1.0 - thinc_eps && cu >= 0.0 && cn >= 0.0 && (cn - cd) * (cd - cu) > 0.0;
    if (!interface)
        return alpha * cd;
    double g = cn > cu ? 1.0 : -1.0;
    double part = alpha > 0.0 ? thinc_integral(cd, g, 1.0 - w, 1.0) : thinc_integral(cd, g, 0.0, w);
    return alpha > 0.0 ? part : -part;
}

static void sweep(gf_continuum *s, int a, double dt)
{
    const gf_grid *g = &s->g;
    double *c = s->c_cell, *cn = s->c_new;
    for (size_t q = 0; q < g->n_cells; ++q)
        cn[q] = c[q];
    for (int k = 0; k < g->nf[a][2]; ++k)
        for (int j = 0; j < g->nf[a][1]; ++j)
            for (int i = 0; i < g->nf[a][0]; ++i) {
                int idx[3] = {i, j, k};
                if (g->periodic[a] && idx[a] == g->n[a])
                    continue;  /* the duplicate of face 0 */
                double alpha = dt / g->h_m[a] * s->u[a][gf_grid_face(g, a, i, j, k)];
                double f = alpha == 0.0 ? 0.0 : face_flux(s, idx, a, alpha);
                int lo[3] = {i, j, k};
                lo[a] -= 1;
                /* c_c alpha: the dilatation term of the split sweep, c_c from the step's start (c_start) */
                if (g->periodic[a] || idx[a] < g->n[a]) {
                    size_t q = gf_continuum_cell_clamped(s, idx);
                    cn[q] += f - (s->c_start[q] > 0.5 ? alpha : 0.0);
                }
                if (g->periodic[a] || idx[a] > 0) {
                    size_t q = gf_continuum_cell_clamped(s, lo);
                    cn[q] -= f - (s->c_start[q] > 0.5 ? alpha : 0.0);
                }
            }
    for (size_t q = 0; q < g->n_cells; ++q)
        c[q] = fmin(fmax(cn[q], 0.0), 1.0);
}

void gf_continuum_advect_fraction(gf_continuum *s, double dt)
{
    const gf_grid *g = &s->g;
    double courant = 0.0;
    for (int a = 0; a < s->n_comp; ++a)
        courant = fmax(courant, dt * gf_continuum_max_speed(s, a) / g->h_m[a]);
    int n_sub = (int)ceil(courant / max_sweep_courant);
    if (n_sub < 1)
        n_sub = 1;
    for (int k = 0; k < n_sub; ++k) {
        for (size_t q = 0; q < g->n_cells; ++q)
            s->c_start[q] = s->c_cell[q];
        int first = (int)((s->steps + k) % s->n_comp);  /* alternate the sweep order */
        for (int b = 0; b < s->n_comp; ++b)
            sweep(s, (first + b) % s->n_comp, dt / n_sub);
    }
}
