/*
 * Lab notebook — stage deposit on prescribed heaps.
 *
 * A heap profile h(x) (back wall at x = 0) is filled with grains: columns
 * every D in x, layers every D in y up to the profile (a grain is placed
 * when its top y + r <= h(x_c) + D/2, i.e. the profile rounded to the
 * nearest layer), two grains across z, positions jittered by ±0.1 D and
 * radii by ±5 % (the seed's polydispersity). Added noise the stage must
 * ignore: one saltating grain 3 D above the top and one grain that rolled
 * 8 D ahead of the toe. A glued floor layer (glued = 1) must not count.
 * Heaps (D = 7.6 mm, R0 = 16 D):
 *   A trapezoid: h = 8 D up to x = 10 D, then linear to 0 at 30 D:
 *     R_inf = 30 D, H_inf = 8 D, flank atan(8/20) = 21.80°;
 *   B triangle: h = 6 D (1 − x / 24 D): flank atan(6/24) = 14.04°;
 *   C triangle at the seed's flank angle 26° (Izard §5.5): H = 8 D,
 *     R = 8 D / tan 26° = 16.40 D.
 * Discreteness: the surface is a staircase of grains of size D. The heap's
 * own toe (front-most grain edge) and top (highest grain top) are known
 * exactly from the construction and must be found exactly. Against the
 * continuum profile, the last grain layer stops where h = D/2, i.e. at
 * R − (D/2)(R − plateau)/H: tolerances R_inf ± 1 D from that, H_inf ± 0.6 D,
 * flank angle ± 2.5° (a fit over ~10–20 bins).
 * Cross-section: the continuum profile's area (A: 8 D x 10 D + 8 D x 20 D / 2
 * = 160 D², B: 72 D², C: 65.6 D²), within R x D/10 (the staircase
 * rounds each column of grains to the nearest layer: a mean bias of a
 * tenth of a grain would be a systematic error of the binning; measured:
 * 0.6, 0.6 and 1.2 D²); and the same
 * over R0 H0 = 128 D² in the stage's row. Heap C, the 26° triangle of
 * H0 = 8 D, holds 0.51 R0 H0: half the grains of a column of a = 0.5 (what
 * mass conservation allows, docs/notes/validation-collapse.md).
 * Front history (heap A): frames x_i(t) = x_i f(t), f = (R0 + (R − R0) S(t))/R,
 * S = (1 + tanh((t − t_c)/τ))/2, so the front grain (centre x_f) moves with
 * maximum speed x_f (R − R0)/(2 τ R); the time to rest (front within D/2 of
 * its end position) solves x_f (R − R0)(1 − S)/R = D/2. Tolerances: speed 1 %
 * (windows of n/100 frames span 0.13 τ: bias (span/τ)²/12 < 0.2 %), rest
 * time one frame; the time the front reaches half its run-out, R0 + (R_inf − R0)/2
 * (two columns' lag read along the front curve, Izard 2014 §5.5), one frame.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/gf_rng.h"
#include "gf_post_synth.h"
#include "gf_test.h"
#include "stages/gf_stage.h"
#include "synth_stage.h"

#define NMAX 4000

typedef struct heap {
    size_t n;
    double x[NMAX], y[NMAX], z[NMAX], r[NMAX];
    unsigned char glued[NMAX];
    double x_front_grain, r_front_grain, top;
} heap;

static double profile(double x, double H, double plateau, double R)
{
    if (x < plateau)
        return H;
    if (x >= R)
        return 0.0;
    return H * (R - x) / (R - plateau);
}

static void build(heap *hp, double D, double H, double plateau, double R, uint64_t seed)
{
    gf_rng rng;
    gf_rng_seed(&rng, seed);
    hp->n = 0;
    hp->x_front_grain = hp->r_front_grain = hp->top = 0.0;
    /* glued floor: half-buried grains over 60 D */
    for (int i = 0; i < 60; ++i) {
        hp->x[hp->n] = (i + 0.5) * D, hp->y[hp->n] = 0.0, hp->z[hp->n] = 0.5 * D, hp->r[hp->n] = 0.5 * D;
        hp->glued[hp->n++] = 1;
    }
    for (int i = 0; (i + 0.5) * D < R + D; ++i) {
        const double xc = (i + 0.5) * D, h = profile(xc, H, plateau, R);
        for (int j = 0; (j + 1.0) * D <= h + 0.5 * D; ++j)
            for (int k = 0; k < 2; ++k) {
                const double jx = gf_rng_range(&rng, -0.1, 0.1) * D;
                double rr = 0.5 * D * (1.0 + gf_rng_range(&rng, -0.05, 0.05));
                hp->x[hp->n] = xc + jx;
                hp->y[hp->n] = (j + 0.5) * D + gf_rng_range(&rng, -0.05, 0.05) * D;
                hp->z[hp->n] = (k + 0.5) * D;
                hp->r[hp->n] = rr;
                hp->glued[hp->n] = 0;
                if (hp->y[hp->n] + rr > hp->top)
                    hp->top = hp->y[hp->n] + rr;
                if (hp->x[hp->n] + rr > hp->x_front_grain + hp->r_front_grain) {
                    hp->x_front_grain = hp->x[hp->n];
                    hp->r_front_grain = rr;
                }
                hp->n++;
            }
    }
    /* a saltating grain above the top, and one that rolled ahead */
    hp->x[hp->n] = 2.5 * D, hp->y[hp->n] = H + 3.5 * D, hp->z[hp->n] = D, hp->r[hp->n] = 0.5 * D;
    hp->glued[hp->n++] = 0;
    hp->x[hp->n] = R + 8 * D, hp->y[hp->n] = D, hp->z[hp->n] = D, hp->r[hp->n] = 0.5 * D;
    hp->glued[hp->n++] = 0;
}

static heap hp;

static void run_heap(const char *name, double H, double plateau, double R, const char *shape, double angle, int frames)
{
    const double D = 7.6e-3, R0 = 16 * D;
    build(&hp, D, H * D, plateau * D, R * D, 11);
    char dir[1024];
    synth_scratch(dir, sizeof dir, name);
    synth_meta m;
    synth_meta_default(&m, name, "column_collapse");
    m.D = D, m.rho_p = 8000, m.rho_f = 1000, m.eta = 1.0, m.R0 = R0, m.H0 = 8 * D, m.a = 0.5, m.phi = 0.6;
    const size_t n = hp.n, nt = frames;
    double *t = malloc(nt * sizeof *t), *X = malloc(n * nt * sizeof *X), *Y = malloc(n * nt * sizeof *Y);
    double *Z = malloc(n * nt * sizeof *Z);
    const double tau = 0.3, tc = 1.5, Rl = R * D;
    for (size_t k = 0; k < nt; ++k) {
        t[k] = nt > 1 ? 4.0 * (double)k / (double)(nt - 1) : 0.0;
        const double S = (nt > 1 && k + 1 < nt) ? 0.5 * (1.0 + tanh((t[k] - tc) / tau)) : 1.0;
        const double f = (R0 + (Rl - R0) * S) / Rl;
        for (size_t i = 0; i < n; ++i) {
            X[i * nt + k] = hp.glued[i] ? hp.x[i] : hp.x[i] * f;
            Y[i * nt + k] = hp.y[i];
            Z[i * nt + k] = hp.z[i];
        }
    }
    GF_CHECK(synth_particles(dir, &m, n, nt, t, hp.r, hp.glued, X, Y, Z, NULL) == 0);
    gf_ctx ctx = {0};
    gf_post_row row;
    gf_post_row_init(&row, dir);
    GF_CHECK_OK(synth_stage(&ctx, gf_stage_deposit, dir, "column_collapse", 1, &row), &ctx);
    const double Rinf = gf_post_row_get(&row, "R_inf_m"), Hinf = gf_post_row_get(&row, "H_inf_m");
    const double ang = gf_post_row_get(&row, "flank_angle_deg");
    const char *sh = gf_post_row_get_text(&row, "deposit_shape");
    printf("%s: R_inf = %.2f D (prescribed %.2f), H_inf = %.2f D (%.2f), flank %.2f deg (%.2f), plateau %.2f D, "
           "shape %s (%s)\n",
           name, Rinf / D, R, Hinf / D, H, ang, angle, gf_post_row_get(&row, "plateau_length_m") / D, sh, shape);
    /* the heap's own toe and top: exact (the rolled and saltating grains excluded) */
    GF_CHECK_REL(Rinf, hp.x_front_grain + hp.r_front_grain, 1e-12);
    GF_CHECK_REL(Hinf, hp.top, 1e-12);
    /* against the continuum profile: the staircase of grains */
    GF_CHECK_ABS(Rinf / D, R - 0.5 * (R - plateau) / H, 1.0);
    GF_CHECK_ABS(Hinf / D, H, 0.6);
    GF_CHECK_ABS(ang, angle, 2.5);
    GF_CHECK(sh && strcmp(sh, shape) == 0);
    GF_CHECK_REL(gf_post_row_get(&row, "runout_norm"), (Rinf - R0) / R0, 1e-12);
    GF_CHECK_REL(gf_post_row_get(&row, "H_inf_over_R0"), Hinf / R0, 1e-12);
    /* height at the back wall (x < 2 D) over H0 = 8 D: the profile there, to the staircase's D/2 */
    const double h_back = fmax(profile(0.5, H, plateau, R), profile(1.5, H, plateau, R));
    printf("  back height %.3f H0 (profile %.3f)\n", gf_post_row_get(&row, "H_back_over_H0"), h_back / 8.0);
    GF_CHECK_ABS(gf_post_row_get(&row, "H_back_over_H0"), h_back / 8.0, 0.6 / 8.0);
    /* cross-section: the continuum profile's (plateau H x p, then the triangle H (R - p) / 2) */
    const double area = gf_post_row_get(&row, "deposit_area_m2"), area_prof = H * (plateau + 0.5 * (R - plateau)) * D * D;
    printf("  cross-section %.2f D^2 (profile %.2f), over R0 H0 %.4f\n", area / (D * D), area_prof / (D * D),
           gf_post_row_get(&row, "deposit_area_over_column"));
    GF_CHECK_ABS(area / (D * D), area_prof / (D * D), 0.1 * R);
    GF_CHECK_REL(gf_post_row_get(&row, "deposit_area_over_column"), area / (R0 * 8 * D), 1e-12);
    if (frames > 1) {
        const double xf = hp.x_front_grain, vmax = xf * (Rl - R0) / (2.0 * tau * Rl);
        const double onems = 1.0 - 0.5 * D * Rl / (xf * (Rl - R0));   /* 1 - (1 - S) scaled */
        const double t_rest = tc + tau * atanh(2.0 * onems - 1.0);
        printf("  front: max speed %.5f m/s (true %.5f), at %.3f s (true %.3f); rest at %.4f s (true %.4f)\n",
               gf_post_row_get(&row, "Ufront_particles_max_m_s"), vmax, gf_post_row_get(&row, "t_front_max_speed_s"),
               tc, gf_post_row_get(&row, "t_rest_s"), t_rest);
        GF_CHECK_REL(gf_post_row_get(&row, "Ufront_particles_max_m_s"), vmax, 0.01);
        GF_CHECK_ABS(gf_post_row_get(&row, "t_front_max_speed_s"), tc, 0.05);
        GF_CHECK_ABS(gf_post_row_get(&row, "t_rest_s"), t_rest, 4.0 / (nt - 1) + 1e-9);
        /* half run-out: the front edge x_f f + r_f reaches R0 + (R_inf - R0)/2 where S solves
         * f(S) = (level - r_f)/x_f; the frames are interpolated linearly, so within one frame */
        const double level = R0 + 0.5 * (Rinf - R0), f_half = (level - hp.r_front_grain) / xf;
        const double t_half = tc + tau * atanh(2.0 * (f_half * Rl - R0) / (Rl - R0) - 1.0);
        printf("  half run-out at %.4f s (true %.4f)\n", gf_post_row_get(&row, "t_half_runout_s"), t_half);
        GF_CHECK_ABS(gf_post_row_get(&row, "t_half_runout_s"), t_half, 4.0 / (nt - 1));
        char p[1100];
        snprintf(p, sizeof p, "%s/post_deposit.nc", dir);
        FILE *f = fopen(p, "rb");
        GF_CHECK(f != NULL);
        if (f)
            fclose(f);
    }
    free(t), free(X), free(Y), free(Z);
}

int main(void)
{
    run_heap("deposit_trapezoid", 8.0, 10.0, 30.0, "trapezoid", atan(8.0 / 20.0) * 180 / M_PI, 401);
    run_heap("deposit_triangle", 6.0, 0.0, 24.0, "triangle", atan(6.0 / 24.0) * 180 / M_PI, 1);
    run_heap("deposit_triangle26", 8.0, 0.0, 8.0 / tan(26.0 * M_PI / 180.0), "triangle", 26.0, 1);
    /* a dry-run without column_collapse scene: not applicable, no error */
    gf_ctx ctx = {0};
    gf_post_row row;
    gf_post_row_init(&row, "/nonexistent");
    GF_CHECK(synth_stage(&ctx, gf_stage_deposit, "/nonexistent", "avalanche", 0, &row) == GF_ERR_UNSUPPORTED);
    return gf_test_finish();
}
