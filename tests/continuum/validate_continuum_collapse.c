/*
 * Dry granular column collapse in the continuum mu(I) solver, two-phase
 * (granular material and a light Newtonian phase, VOF), 2-D, after Lagree,
 * Staron & Popinet (JFM 686, 2011), side by side with this project's DEM
 * figures (docs/notes/validation-dem.md, "Dry collapse": mean (R_inf - R0)/R0 over
 * packing seeds 1-8 of 0.539, 1.383, 2.94 at a = 0.5, 1, 2; R0 = 16 D).
 * Units D = g = rho_s = 1; phi = 0.6; mu_s = 0.280, mu_2 = 0.703 (this DEM's own
 * steady chute, docs/notes/validation-dem.md), I0 = 0.279; air 1/100 of the bulk
 * density, viscosity 1e-3. Back wall at x = 0, no-slip floor and walls, open top.
 * Usage: validate_continuum_collapse a [cell_over_D] [t_end] [out.csv] [dt_over_cell] [gdot_min]
 * Prints the run-out (the front where the solid height falls to D/4, as the
 * DEM scene measures it), the final height, the mass drift and the CPU time; the
 * optional CSV gets the final column height profile h(x).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "continuum/gf_continuum_collapse.h"

static double column_height(const gf_continuum *s, gf_continuum *sm, int i)
{
    const gf_grid *g = gf_continuum_grid(s);
    const double *c = gf_continuum_fraction(sm);
    double h = 0.0;
    for (int j = 0; j < g->n[1]; ++j)
        h += c[gf_grid_cell(g, i, j, 0)] * g->h_m[1];
    return h;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s a [cell_over_D] [t_end] [out.csv]\n", argv[0]);
        return 2;
    }
    double a = atof(argv[1]), h = argc > 2 ? atof(argv[2]) : 0.5, t_end = argc > 3 ? atof(argv[3]) : 0.0;
    double R0 = 16.0, H0 = a * R0, L = R0 * (2.0 + 2.5 * a), Ly = 1.3 * H0 + 2.0;
    if (t_end <= 0.0)
        t_end = 6.0 * sqrt(H0) + 10.0;
    int nx = (int)ceil(L / h), ny = (int)ceil(Ly / h);
    gf_ctx ctx = {0};
    gf_continuum_params p = {
        .n = {nx, ny, 1},
        .length_m = {nx * h, ny * h, 1.0},
        .side = {{GF_SIDE_WALL, GF_SIDE_WALL}, {GF_SIDE_WALL, GF_SIDE_OUTFLOW}, {GF_SIDE_PERIODIC, GF_SIDE_PERIODIC}},
        .density_kg_m3 = 0.6,
        .body_accel_m_s2 = {0.0, -1.0, 0.0},
        .rheology = GF_RHEOLOGY_MU_I,
        .mui = {.law = {.mu_s = 0.280, .mu_2 = 0.703, .I0 = 0.279}, .diameter_m = 1.0, .grain_density_kg_m3 = 1.0,
                .gdot_min_1_s = argc > 6 ? atof(argv[6]) : 1e-4},
        .two_phase = 1,
        .density2_kg_m3 = 0.006,
        .viscosity2_Pa_s = 1e-3,
        .dt_s = (argc > 5 ? atof(argv[5]) : 0.05) * h,
    };
    gf_continuum *s = NULL;
    if (gf_continuum_create(&ctx, &p, &s) != GF_OK) {
        fprintf(stderr, "%s\n", ctx.last_msg);
        return 1;
    }
    const gf_grid *g = gf_continuum_grid(s);
    double *c = gf_continuum_fraction(s), mass0 = 0.0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            double x = (i + 0.5) * h, y = (j + 0.5) * h;
            c[gf_grid_cell(g, i, j, 0)] = (x < R0 && y < H0) ? 1.0 : 0.0;
            mass0 += c[gf_grid_cell(g, i, j, 0)];
        }
    if (gf_continuum_init_pressure(s) != GF_OK) {
        fprintf(stderr, "%s\n", ctx.last_msg);
        return 1;
    }
    clock_t c0 = clock();
    for (double t = 1.0; t <= t_end + 1e-9; t += 1.0) {
        if (gf_continuum_run(s, t, 0.0, NULL) != GF_OK) {
            fprintf(stderr, "%s\n", ctx.last_msg);
            return 1;
        }
        if (fmod(t, 5.0) == 0.0 || t >= t_end - 1e-9) {
            double umax = 0.0; /* over the faces between two cells of the column (c > 1/2) */
            for (int k = 0; k < 2; ++k) {
                const double *u = gf_continuum_velocity(s, k);
                for (int j = 0; j < ny; ++j)
                    for (int i = 0; i < nx; ++i) {
                        int jn = j + (k == 1), in = i + (k == 0);
                        if (in >= nx || jn >= ny || c[gf_grid_cell(g, i, j, 0)] <= 0.5 ||
                            c[gf_grid_cell(g, in, jn, 0)] <= 0.5)
                            continue;
                        umax = fmax(umax, fabs(u[gf_grid_face(g, k, in, jn, 0)]));
                    }
            }
            printf("t = %5.1f sqrt(D/g): front %.2f D, (R - R0)/R0 = %.3f, height at x = 0: %.2f D, max|u| in the column %.3f\n", t,
                   gf_continuum_collapse_front(s, 0.6, 1.0), (gf_continuum_collapse_front(s, 0.6, 1.0) - R0) / R0, column_height(s, s, 0), umax);
        }
    }
    double mass = 0.0;
    for (size_t q = 0; q < g->n_cells; ++q)
        mass += c[q];
    double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC, R = gf_continuum_collapse_front(s, 0.6, 1.0);
    double body = gf_continuum_collapse_extent(s, 2.0);
    printf("a = %.2f, cell %.2f D (%d x %d): (R_inf - R0)/R0 = %.3f, body (x_2D - R0)/R0 = %.3f, H_inf/R0 = %.3f, "
           "mass drift %.2e, %.1f s CPU\n",
           a, h, nx, ny, (R - R0) / R0, (body - R0) / R0, column_height(s, s, 0) / R0, mass / mass0 - 1.0, cpu);
    if (argc > 4) {
        FILE *f = fopen(argv[4], "w");
        if (f) {
            fprintf(f, "x_over_D,height_over_D\n");
            for (int i = 0; i < nx; ++i)
                fprintf(f, "%.4f,%.4f\n", (i + 0.5) * h, column_height(s, s, i));
            fclose(f);
        }
        char field[4200];
        snprintf(field, sizeof field, "%s.c", argv[4]);
        if ((f = fopen(field, "w"))) { /* the volume fraction, one row of cells per line from the floor up */
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i)
                    fprintf(f, "%.4f%c", c[gf_grid_cell(g, i, j, 0)], i == nx - 1 ? '\n' : ' ');
            fclose(f);
        }
    }
    gf_continuum_destroy(&s);
    return 0;
}
