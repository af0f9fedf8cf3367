/*
 * Izard (2014) Table 4.2, the immersed-avalanche campaign at 25°: the ends of
 * each printed (St, T) range, paired as (St_min, T_max) and (St_max, T_min)
 * (slower flows at lower St), with ρ_p/ρ from the table (r = sqrt(5 ρ_p/3ρ):
 * 12.91 for ρ_p/ρ = 100, where the table prints 11.2). The label the
 * thesis' boundaries give (§4.1.4.2): r >= 4, viscous below St = 1 and free
 * fall above; r < 4, viscous below the line r = 4 St and inertial above.
 * workflows/regime_score.py carries the same 24 points.
 */
#ifndef GF_TEST_TABLE42_H
#define GF_TEST_TABLE42_H

#include <math.h>

#include "stages/gf_regime.h"

typedef struct table_pt {
    double ratio, St, T_ms;
    int ambiguous;   /* 1 boundary, 2 r ~ 4, 3 pairing (tests/post/test_post_regime.c) */
} table_pt;

static const table_pt table42[] = {
    {2.7, 0.03, 130, 3}, {2.7, 95, 25, 0},   {3, 28, 24, 0},     {4, 0.05, 605, 0},  {4, 155, 24, 0},
    {5, 0.05, 589, 0},   {5, 51, 21, 0},     {6, 62, 21, 0},     {7, 0.15, 182, 0},  {7, 23, 23, 0},
    {7.5, 79, 21, 2},    {10, 0.4, 71, 0},   {10, 107, 18, 2},   {15, 10, 28, 0},    {16, 0.7, 43, 1},
    {16, 0.75, 28, 1},   {20, 220, 32, 0},   {30, 20, 32, 0},    {30, 330, 28, 0},   {40, 0.2, 243, 0},
    {40, 177, 33, 0},    {75, 843, 31, 0},   {100, 0.04, 1200, 0}, {100, 111, 38, 0}};

enum { TABLE42_N = (int)(sizeof table42 / sizeof table42[0]) };

/* 1 when a run's (St, r) is table point pt (r = sqrt(5 ratio / 3), St to 0.1 %, r to 0.02). */
static inline int table42_is(const table_pt *pt, double St, double r)
{
    return fabs(St / pt->St - 1.0) < 1e-3 && fabs(sqrt(5.0 * pt->ratio / 3.0) - r) < 0.02;
}

static inline gf_regime_label table42_expected(double St, double r)
{
    if (r >= 4.0)
        return St < 1.0 ? GF_REGIME_VISCOUS : GF_REGIME_FREE_FALL;
    return St < r / 4.0 ? GF_REGIME_VISCOUS : GF_REGIME_INERTIAL;
}

#endif
