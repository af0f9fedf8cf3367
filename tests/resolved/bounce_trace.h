/*
 * A sampled trace of a bounce harness: one growing array per quantity, so that
 * the columns go straight to gf_bounce_measure (postproc/stages/gf_bounce_measure.h).
 */
#ifndef BOUNCE_TRACE_H
#define BOUNCE_TRACE_H

#include <stdlib.h>

#define BOUNCE_TRACE_MAX_COLS 8

typedef struct bounce_trace {
    int n_cols;
    double *col[BOUNCE_TRACE_MAX_COLS];
    size_t n, cap;
} bounce_trace;

/* Appends one sample of n_cols values; -1 when out of memory. */
static inline int bounce_trace_push(bounce_trace *s, const double *x)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 4096;
        for (int c = 0; c < s->n_cols; ++c) {
            double *grown = realloc(s->col[c], s->cap * sizeof *grown);
            if (!grown)
                return -1;
            s->col[c] = grown;
        }
    }
    for (int c = 0; c < s->n_cols; ++c)
        s->col[c][s->n] = x[c];
    s->n++;
    return 0;
}

static inline void bounce_trace_free(bounce_trace *s)
{
    for (int c = 0; c < s->n_cols; ++c)
        free(s->col[c]);
    *s = (bounce_trace){0};
}

#endif
