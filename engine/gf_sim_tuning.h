/*
 * Performance knobs of a simulation: how the step is computed, never what it
 * computes. Each zero is the default a run gets; the other values exist for
 * the benchmarks (workflows/bench/) and for the tests that hold the fast
 * paths to the plain ones (bitwise, or at round-off where stated). A user
 * running a campaign never sets them: they are not part of the YAML schema.
 */
#ifndef GF_SIM_TUNING_H
#define GF_SIM_TUNING_H

typedef struct gf_sim_tuning {
    /* 1: skip nothing (engine/sim/gf_skips.c; workflows/bench/skips.sh
     * measures what each skip saves). The results do not depend on it. */
    int keep_all_work;
    /* Spatial sort of the particle store (engine/sim/gf_sort.c): every
     * sort_every-th neighbour-list rebuild reorders the grains by the Morton
     * index of their cell, so that neighbours are close in memory (ids, and so
     * outputs, are unchanged). 0: every 20 rebuilds from 2048 grains on
     * (smaller stores fit in the caches: never); > 0: every that many
     * rebuilds, any grain count; < 0: never. The results depend on it at
     * round-off (summation order): a restart must use the same value. */
    int sort_every;
    /* Steps per call of gf_sim_advance in gf_sim_run. 0: adaptive, about 0.1 s
     * of wall time each (progress, interrupts). The outputs do not depend on
     * it: output, checkpoint and done() instants are steps of the clock
     * (engine/sim/gf_run.c); > 0 fixes it (tests/pipeline/test_run_chunking.c). */
    int chunk_steps;
    /* 1: the linear law (with or without lubrication) runs in the scalar pair
     * loop (engine/sim/gf_forces.c) instead of the blocked, vectorised one
     * (engine/sim/gf_pairs_blocked.c), which must give the same bits
     * (tests/engine/test_pair_loops.c). */
    int generic_pair_loop;
    /* Near list (engine/sim/gf_near_list.c): the blocked pair loop scans the
     * neighbour pairs within this fraction of the skin of contact, rebuilt
     * when a grain has moved half of it. 0: GF_SIM_NEAR_SKIN_DEFAULT; < 0:
     * scan the whole list. The results do not depend on it (bitwise). */
    double near_skin;
    /* 1: every step is the reference step, the velocity-Verlet method as
     * written (engine/sim/gf_step.c: kick, drift, neighbour upkeep, forces
     * over the whole list, kick), instead of the fused step that defers and
     * merges the kicks and scans the near list. The results do not depend on
     * it (bitwise, tests/engine/test_reference_step.c). */
    int reference_step;
} gf_sim_tuning;

#endif
