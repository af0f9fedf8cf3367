/* Private state of gf_continuum, shared by its files (not a public header). */
#ifndef GF_CONTINUUM_INTERNAL_H
#define GF_CONTINUUM_INTERNAL_H

#include "continuum/gf_cont_lu.h"
#include "continuum/gf_cont_poisson.h"
#include "continuum/gf_continuum.h"

/* One unknown velocity face of the implicit system: component a's face q at index idx. */
typedef struct gf_unknown_face {
    int a, idx[3];
    size_t q;
} gf_unknown_face;

struct gf_continuum {
    gf_ctx *ctx;
    gf_continuum_params p;
    gf_grid g;
    int n_comp;            /* velocity components solved: 2 in 2-D, 3 in 3-D */
    double *u[3], *u_old[3];
    double *p_cell, *div_cell, *eta_cell;
    double *strain_cell;   /* |gdot|^2 at cells, from the diagonal and the averaged off-diagonal terms */
    double *diag_cell;     /* 2 sum D_ii^2 at cells */
    double *offsq_cell[3]; /* per edge family, the square of the cell's four-edge average of gdot_ab */
    double *e_edge[3], *eta_edge[3]; /* edges normal to axis k (pair a, b != k): gdot_ab and eta */
    int ne[3][3];          /* edge array sizes per axis */
    size_t n_edges[3];
    int *unknown[3];       /* face -> unknown index, -1 for a boundary (prescribed) or duplicate face */
    int n_unknowns;
    gf_unknown_face *unknown_face; /* unknown index -> face, numbered component by component, x fastest:
                                    * the per-unknown loops (predictor, viscous rows, projection) follow it */
    double *rhs, *x;
    gf_cont_poisson *poisson;
    gf_cont_lu *lu;
    double *c_cell, *c_new;    /* volume fraction of the main phase */
    double *c_start;           /* c at the start of a split advection step (gf_continuum_vof.c) */
    double *rho_face[3];       /* density on the faces (two phases), else NULL */
    gf_cont_lu *lu_p;          /* variable-density pressure (two phases) */
    int factored;          /* a Newtonian matrix is factored once per dt */
    double time_s;
    long steps;
};

/* A face value seen from a stencil: scale * u[a][face] + constant. */
typedef struct gf_face_ref {
    size_t face;
    double scale, constant;
} gf_face_ref;

gf_face_ref gf_continuum_resolve(const gf_continuum *s, int a, const int idx[3]);
double gf_continuum_value(const gf_continuum *s, int a, const int idx[3]);
size_t gf_continuum_cell_clamped(const gf_continuum *s, const int idx[3]);

void gf_continuum_advect(gf_continuum *s, double dt);
void gf_continuum_update_viscosity(gf_continuum *s);
gf_status gf_continuum_viscous(gf_continuum *s, double dt);
void gf_continuum_project(gf_continuum *s, double dt);
/* Two phases: density on the faces from c; the variable-density projection; the VOF advection of c. */
void gf_continuum_face_density(gf_continuum *s);
gf_status gf_continuum_project_variable(gf_continuum *s, double dt);
void gf_continuum_advect_fraction(gf_continuum *s, double dt);
/* Density of component a's face q (rho, or rho_face under two phases). */
static inline double gf_continuum_rho(const gf_continuum *s, int a, size_t q)
{
    return s->rho_face[a] ? s->rho_face[a][q] : s->p.density_kg_m3;
}
/* (p(cell above) - p(cell below))/h_a at face idx of component a, p = 0 on outflow faces. */
double gf_continuum_pressure_gradient(const gf_continuum *s, const double *p, int a, const int idx[3]);
/* Largest |u_a| over component a's faces. */
double gf_continuum_max_speed(const gf_continuum *s, int a);
/* Discrete divergence of u at cell (i,j,k): sum over the components of the face difference over h_a. */
double gf_continuum_cell_divergence(const gf_continuum *s, int i, int j, int k);
/* The projection's correction u -= dt / rho grad phi on every unknown face (rho per face under two phases). */
void gf_continuum_correct_velocity(gf_continuum *s, const double *phi, double dt);

#endif
