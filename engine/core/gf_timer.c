/* Wall-clock timers; see gf_timer.h. */
#include "core/gf_timer.h"

#include <time.h>

double gf_wtime(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void gf_timer_start(gf_timers *t, gf_timer_id id)
{
    t->started_s[id] = gf_wtime();
}

void gf_timer_stop(gf_timers *t, gf_timer_id id)
{
    t->elapsed_s[id] += gf_wtime() - t->started_s[id];
}

const char *gf_timer_name(gf_timer_id id)
{
    static const char *const names[] = {
#define GF_TIMER_NAME(id, name) name,
        GF_TIMER_LIST(GF_TIMER_NAME)
#undef GF_TIMER_NAME
    };
    return (id >= 0 && id < GF_TIMER_COUNT) ? names[id] : "?";
}
