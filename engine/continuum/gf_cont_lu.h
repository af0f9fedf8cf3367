/*
 * gf_cont_lu: sparse LU solve of the implicit viscous step, through UMFPACK
 * (Davis, ACM TOMS 30, 2004). The variable mu(I) viscosity makes the matrix
 * non-symmetric and changes it every step, as in Djouwe Meffeja 2012,
 * §4.4.3 (Matlab's sparse LU there): the symbolic analysis is done once for
 * the fixed pattern, the numeric factorisation whenever the values change.
 * This file pair is the only UMFPACK caller.
 */
#ifndef GF_CONT_LU_H
#define GF_CONT_LU_H

#include "core/gf_status.h"

typedef struct gf_cont_lu gf_cont_lu;

/* n x n matrix with at most max_nz triplets per assembly. Returns owned solver. */
gf_status gf_cont_lu_create(gf_ctx *ctx, int n, long max_nz, gf_cont_lu **out);
void gf_cont_lu_destroy(gf_cont_lu **lu);
/* Assembly: clear, then add (duplicates are summed), then factor. */
void gf_cont_lu_clear(gf_cont_lu *lu);
void gf_cont_lu_add(gf_cont_lu *lu, int row, int col, double value);
/* GF_ERR_NUMERIC on a singular matrix; GF_ERR_CAPACITY if more than max_nz were added. */
gf_status gf_cont_lu_factor(gf_ctx *ctx, gf_cont_lu *lu);
/* x = A^{-1} b with the last factorisation. */
gf_status gf_cont_lu_solve(gf_ctx *ctx, gf_cont_lu *lu, const double *b, double *x);

#endif
