/*
 * Deposit envelope of a collapsed column from grain positions (used by stage
 * deposit; public so that a test can feed it a prescribed heap).
 *
 * Surface: grains are binned in x with bins of one mean diameter D starting
 * at the back wall x = 0 (the seed's convention: the column rests against the
 * wall at x = 0, Izard §5.2). In each bin the grain tops y + r are sorted
 * downwards and grains separated from the next one below by a vertical gap
 * larger than D are discarded (saltating or bouncing grains); the bin height
 * is the highest remaining top. The heap is the chain of grains from the
 * wall: grains sorted by their left edge x − r are taken while each starts
 * within D/2 of the furthest right edge x + r reached so far; the first gap
 * wider than D/2 ends it, so grains that rolled or bounced ahead of the toe
 * are not part of the deposit.
 *   R_inf  = the furthest right edge of the chain (from the back wall)
 *   H_inf  = largest bin height (the thesis's "maximum height")
 *   H_back = largest height of the two bins against the wall (x < 2 D): over
 *            the initial H0 it tells whether the column's top survived (~1,
 *            Rondon et al. 2011's dense columns) or the whole column flowed
 *            and sank (below ~0.9; validate_collapse's deposit criterion)
 *   flank  = least-squares line through the bins beyond the highest one with
 *            0.2 H_inf <= h <= 0.8 H_inf; flank angle = atan(-slope)
 *   area   = cross-section of the heap under its surface, sum of the bin
 *            heights times the bin width (the last bin ends at the toe),
 *            above the floor plane y = 0 (the plane H0 is measured from).
 *            Times the width, it is the volume the grains fill: area
 *            / (R0 H0) = Phi_i / Phi_deposit for a column of packing Phi_i
 *            (mass conservation), the bulk dilation or compaction of the
 *            collapse, and it bounds the shapes the heap can take (a
 *            straight-flanked triangle no higher than H0 holding it has a
 *            flank no steeper than atan(H0^2 / (2 area)): 14 deg at a = 0.5,
 *            docs/notes/validation-collapse.md, "What mass conservation allows")
 *   shape  = trapezoid when the flank line reaches H_inf at a distance
 *            L_top from the wall with L_top >= max(2 D, 0.1 R_inf), i.e. a
 *            plateau of the full height extends over a finite length at the
 *            back (Rondon et al. 2011; Izard §5.5); triangle otherwise.
 */
#ifndef GF_DEPOSIT_H
#define GF_DEPOSIT_H

#include <stddef.h>

#include "core/gf_status.h"

typedef struct gf_deposit {
    double runout_m, height_m, back_height_m, flank_angle_deg, plateau_length_m, area_m2;
    int trapezoid;        /* 1 trapezoid, 0 triangle, -1 undetermined (too few flank bins) */
    size_t n_bins;        /* bins of the heap */
    double bin_m;
    double *bin_height_m; /* n_bins heights (malloc'ed; free with gf_deposit_free) */
} gf_deposit;

/* Envelope of grains (x, y, r) with mask (NULL: all); bin = D. */
gf_status gf_deposit_envelope(gf_ctx *ctx, const double *x, const double *y, const double *r,
                              const unsigned char *mask, size_t n, double bin_m, gf_deposit *out);
/* Front only (R_inf of the heap), no allocation kept. */
double gf_deposit_front(const double *x, const double *y, const double *r, const unsigned char *mask, size_t n,
                        double bin_m);
void gf_deposit_free(gf_deposit *d);

#endif
