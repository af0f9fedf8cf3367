/*
 * Random numbers: xoshiro256** (Blackman & Vigna 2018), seeded by splitmix64.
 * The whole state is four 64-bit words, so a checkpoint stores it and a
 * restarted run draws exactly the same sequence.
 */
#ifndef GF_RNG_H
#define GF_RNG_H

#include <stdint.h>

typedef struct gf_rng {
    uint64_t s[4];
} gf_rng;

void gf_rng_seed(gf_rng *rng, uint64_t seed);
uint64_t gf_rng_next(gf_rng *rng);
/* Uniform in [0, 1). */
double gf_rng_uniform(gf_rng *rng);
/* Uniform in [lo, hi). */
double gf_rng_range(gf_rng *rng, double lo, double hi);
/* Standard normal (Box–Muller). */
double gf_rng_normal(gf_rng *rng);

#endif
