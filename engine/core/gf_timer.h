/*
 * Wall-clock timers for the step loop, from one X-macro list (handle + name)
 * so that the report and the enum never drift apart.
 */
#ifndef GF_TIMER_H
#define GF_TIMER_H

#define GF_TIMER_LIST(X)            \
    X(GF_T_TOTAL, "total")          \
    X(GF_T_NEIGHBOUR, "neighbour")  \
    X(GF_T_FORCE, "force")          \
    X(GF_T_INTEGRATE, "integrate")  \
    X(GF_T_FLUID, "fluid")          \
    X(GF_T_COUPLING, "coupling")    \
    X(GF_T_OUTPUT, "output")

typedef enum gf_timer_id {
#define GF_TIMER_ENUM(id, name) id,
    GF_TIMER_LIST(GF_TIMER_ENUM)
#undef GF_TIMER_ENUM
    GF_TIMER_COUNT
} gf_timer_id;

typedef struct gf_timers {
    double elapsed_s[GF_TIMER_COUNT];
    double started_s[GF_TIMER_COUNT];
} gf_timers;

/* Monotonic wall clock, seconds. */
double gf_wtime(void);
void gf_timer_start(gf_timers *t, gf_timer_id id);
void gf_timer_stop(gf_timers *t, gf_timer_id id);
const char *gf_timer_name(gf_timer_id id);

#endif
