/*
 * gf_cont_poisson: the pressure Poisson solve of the continuum solver, for
 * cell-centred unknowns on the MAC grid, with each axis periodic or bounded
 * by zero-flux (Neumann) and fixed-pressure (Dirichlet, p = 0 on the boundary
 * face: an outflow) sides in any combination. Every combination is
 * diagonalised by one FFTW real-to-real transform per axis (Frigo & Johnson,
 * Proc. IEEE 93, 2005):
 *   periodic                 R2HC / HC2R   eigenvalue (2 cos(2 pi k/n) - 2)/h^2
 *   Neumann  - Neumann       REDFT10/01    (2 cos(pi k/n) - 2)/h^2
 *   Neumann  - Dirichlet     REDFT11       (2 cos(pi (k + 1/2)/n) - 2)/h^2
 *   Dirichlet - Neumann      RODFT11       same
 *   Dirichlet - Dirichlet    RODFT10/01    (2 cos(pi (k + 1)/n) - 2)/h^2
 * (the ghost cell across a Neumann face equals the cell, across a Dirichlet
 * face it is minus the cell). The fluid module's gf_poisson covers walls and
 * periodic axes only; the thesis' channel fixes the pressure at its outlet
 * (Djouwe Meffeja 2012, §4.4.2 and Annex A), hence this file.
 * Without a Dirichlet side the constant mode is set to zero (zero-mean p).
 */
#ifndef GF_CONT_POISSON_H
#define GF_CONT_POISSON_H

#include "core/gf_status.h"

typedef enum gf_cont_poisson_side { GF_POISSON_NEUMANN = 0, GF_POISSON_DIRICHLET, GF_POISSON_PERIODIC } gf_cont_poisson_side;

typedef struct gf_cont_poisson gf_cont_poisson;

/* n cells of edge h per axis (x fastest), side[axis][low/high]; periodic on both sides or neither. Returns owned plan. */
gf_status gf_cont_poisson_create(gf_ctx *ctx, const int n[3], const double h_m[3],
                                 const gf_cont_poisson_side side[3][2], gf_cont_poisson **out);
void gf_cont_poisson_destroy(gf_cont_poisson **plan);
/* L p = rhs (cell arrays, may alias). */
void gf_cont_poisson_solve(gf_cont_poisson *plan, const double *rhs, double *p);

#endif
