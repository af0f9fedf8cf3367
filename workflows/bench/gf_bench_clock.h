/*
 * The benchmarks' clock: CPU seconds of the whole process (all its threads),
 * the measure of cost the side-by-side comparisons use (a wall clock on a
 * shared machine times the other tenants too).
 */
#ifndef GF_BENCH_CLOCK_H
#define GF_BENCH_CLOCK_H

#include <time.h>

static inline double gf_bench_cpu_time_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

#endif
