/* UMFPACK wrapper; see gf_cont_lu.h. */
#include "continuum/gf_cont_lu.h"

#include <stdlib.h>
#include <umfpack.h>

struct gf_cont_lu {
    int n;
    long max_nz, nz;
    int *Ti, *Tj, *Ap, *Ai;
    double *Tx, *Ax;
    void *symbolic, *numeric;
    int overflow;
};

gf_status gf_cont_lu_create(gf_ctx *ctx, int n, long max_nz, gf_cont_lu **out)
{
    *out = NULL;
    gf_cont_lu *lu = calloc(1, sizeof *lu);
    if (!lu)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "continuum LU");
    lu->n = n;
    lu->max_nz = max_nz;
    lu->Ti = malloc(max_nz * sizeof(int));
    lu->Tj = malloc(max_nz * sizeof(int));
    lu->Tx = malloc(max_nz * sizeof(double));
    lu->Ai = malloc(max_nz * sizeof(int));
    lu->Ax = malloc(max_nz * sizeof(double));
    lu->Ap = malloc((n + 1) * sizeof(int));
    if (!lu->Ti || !lu->Tj || !lu->Tx || !lu->Ai || !lu->Ax || !lu->Ap) {
        gf_cont_lu_destroy(&lu);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "continuum LU: %ld entries", max_nz);
    }
    *out = lu;
    return GF_OK;
}

void gf_cont_lu_destroy(gf_cont_lu **plu)
{
    if (!plu || !*plu)
        return;
    gf_cont_lu *lu = *plu;
    if (lu->numeric)
        umfpack_di_free_numeric(&lu->numeric);
    if (lu->symbolic)
        umfpack_di_free_symbolic(&lu->symbolic);
    free(lu->Ti), free(lu->Tj), free(lu->Tx), free(lu->Ai), free(lu->Ax), free(lu->Ap);
    free(lu);
    *plu = NULL;
}

void gf_cont_lu_clear(gf_cont_lu *lu)
{
    lu->nz = 0;
    lu->overflow = 0;
}

void gf_cont_lu_add(gf_cont_lu *lu, int row, int col, double value)
{
    if (lu->nz >= lu->max_nz) {
        lu->overflow = 1;
        return;
    }
    lu->Ti[lu->nz] = row;
    lu->Tj[lu->nz] = col;
    lu->Tx[lu->nz] = value;
    ++lu->nz;
}

gf_status gf_cont_lu_factor(gf_ctx *ctx, gf_cont_lu *lu)
{
    if (lu->overflow)
        return GF_FAIL(ctx, GF_ERR_CAPACITY, "continuum LU: more than %ld matrix entries", lu->max_nz);
    int st = umfpack_di_triplet_to_col(lu->n, lu->n, (int)lu->nz, lu->Ti, lu->Tj, lu->Tx, lu->Ap, lu->Ai, lu->Ax, NULL);
    if (st != UMFPACK_OK)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "continuum LU: triplet conversion failed (UMFPACK status %d)", st);
    if (!lu->symbolic) {
        st = umfpack_di_symbolic(lu->n, lu->n, lu->Ap, lu->Ai, lu->Ax, &lu->symbolic, NULL, NULL);
        if (st != UMFPACK_OK)
            return GF_FAIL(ctx, GF_ERR_NUMERIC, "continuum LU: symbolic analysis failed (UMFPACK status %d)", st);
    }
    if (lu->numeric)
        umfpack_di_free_numeric(&lu->numeric);
    st = umfpack_di_numeric(lu->Ap, lu->Ai, lu->Ax, lu->symbolic, &lu->numeric, NULL, NULL);
    if (st != UMFPACK_OK)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "continuum LU: factorisation failed (UMFPACK status %d)", st);
    return GF_OK;
}

gf_status gf_cont_lu_solve(gf_ctx *ctx, gf_cont_lu *lu, const double *b, double *x)
{
    int st = umfpack_di_solve(UMFPACK_A, lu->Ap, lu->Ai, lu->Ax, x, b, lu->numeric, NULL, NULL);
    if (st != UMFPACK_OK)
        return GF_FAIL(ctx, GF_ERR_NUMERIC, "continuum LU: solve failed (UMFPACK status %d)", st);
    return GF_OK;
}
