/*
 * gf-core-latency: the time one cache line takes to move between two cores.
 *
 * Two threads, pinned to cpu A and cpu B, pass a counter back and forth
 * through one 64-byte line: each waits until the other has written its
 * value, then writes the next. One round trip is two transfers of the line,
 * so half the mean round trip is the one-way latency of a modified line
 * from one core's cache to the other's.
 *
 * Why the DEM benchmarks need it: with two threads the grains near the
 * boundary between the two chunks of the store are read by one core and
 * written by the other at every step (docs/notes/benchmarks.md, "Two cores"), so
 * the parallel efficiency of a small bed depends on this latency as much as
 * on the code. On bare metal two cores of one CCX exchange a line in a few
 * tens of ns; a virtual machine may place its two vCPUs much farther apart,
 * and the placement can change while it runs. parallel_efficiency.sh prints
 * the latency next to each round.
 *
 * usage: gf-core-latency [CPU_A CPU_B [ROUND_TRIPS]]   (defaults 0 1 200000)
 * prints: one-way latency in ns, and the round trip
 */
#define _GNU_SOURCE
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct ping_line {
    _Alignas(64) atomic_long counter; /* alone on its line: nothing else moves with it */
    char pad[64 - sizeof(atomic_long)];
} ping_line;

typedef struct pong_args {
    ping_line *line;
    long round_trips;
    int cpu;
    int pinned;
} pong_args;

static int pin_to(int cpu)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

/* The answering side: waits for the odd values, writes the even ones. */
static void *pong(void *arg)
{
    pong_args *a = arg;
    a->pinned = pin_to(a->cpu);
    for (long k = 0; k < a->round_trips; ++k) {
        while (atomic_load_explicit(&a->line->counter, memory_order_acquire) != 2 * k + 1)
            ;
        atomic_store_explicit(&a->line->counter, 2 * k + 2, memory_order_release);
    }
    return NULL;
}

int main(int argc, char **argv)
{
    int cpu_a = argc > 2 ? atoi(argv[1]) : 0, cpu_b = argc > 2 ? atoi(argv[2]) : 1;
    long round_trips = argc > 3 ? atol(argv[3]) : 200000;
    if (argc == 2 || argc > 4 || cpu_a < 0 || cpu_b < 0 || cpu_a == cpu_b || round_trips < 1) {
        fprintf(stderr, "usage: gf-core-latency [CPU_A CPU_B [ROUND_TRIPS]] (two different cpus)\n");
        return 2;
    }
    static ping_line line; /* static: aligned storage without an allocation */
    atomic_store(&line.counter, 0);
    pong_args a = {&line, round_trips, cpu_b, 0};
    if (!pin_to(cpu_a)) {
        fprintf(stderr, "gf-core-latency: cannot pin to cpu %d\n", cpu_a);
        return 1;
    }
    pthread_t t;
    if (pthread_create(&t, NULL, pong, &a) != 0) {
        fprintf(stderr, "gf-core-latency: cannot start the second thread\n");
        return 1;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (long k = 0; k < round_trips; ++k) {
        atomic_store_explicit(&line.counter, 2 * k + 1, memory_order_release);
        while (atomic_load_explicit(&line.counter, memory_order_acquire) != 2 * k + 2)
            ;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    pthread_join(t, NULL);
    if (!a.pinned) {
        fprintf(stderr, "gf-core-latency: cannot pin to cpu %d\n", cpu_b);
        return 1;
    }
    double ns = ((double)(t1.tv_sec - t0.tv_sec) * 1e9 + (double)(t1.tv_nsec - t0.tv_nsec)) / (double)round_trips;
    printf("cpu %d <-> cpu %d: one-way %.1f ns (round trip %.1f ns, %ld round trips)\n", cpu_a, cpu_b, 0.5 * ns, ns,
           round_trips);
    return 0;
}
