/* xoshiro256** generator; see gf_rng.h. */
#include "core/gf_rng.h"

#include <math.h>

static uint64_t rotl(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

void gf_rng_seed(gf_rng *rng, uint64_t seed)
{
    for (int i = 0; i < 4; ++i)
        rng->s[i] = splitmix64(&seed);
}

uint64_t gf_rng_next(gf_rng *rng)
{
    uint64_t *s = rng->s;
    uint64_t result = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

double gf_rng_uniform(gf_rng *rng)
{
    return (double)(gf_rng_next(rng) >> 11) * 0x1.0p-53;
}

double gf_rng_range(gf_rng *rng, double lo, double hi)
{
    return lo + (hi - lo) * gf_rng_uniform(rng);
}

double gf_rng_normal(gf_rng *rng)
{
    double u1 = gf_rng_uniform(rng);
    double u2 = gf_rng_uniform(rng);
    if (u1 < 1e-300)
        u1 = 1e-300;
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}
