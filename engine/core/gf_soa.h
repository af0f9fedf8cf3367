/*
 * Per-grain arrays of a struct of arrays in one allocation, each array
 * starting one cache line further from a page boundary than the one before.
 *
 * Why: separate large allocations come from mmap and all start at the same
 * offset in their page (16 bytes past it with glibc), so element i of every
 * array falls in the same set of a 4 KiB-indexed L1 cache (48 KiB, 12 ways,
 * 64 sets on Zen 5; 32 KiB, 8 ways on most others). A kernel that touches
 * element i of more arrays than the cache has ways (the integrator reads
 * and writes 15-20 per grain; the contact force reads 10 of each partner)
 * then evicts its own lines, and loads that follow stores 4 KiB apart may
 * stall on a false store-forwarding match ("4K aliasing" in the x86 vendors'
 * optimisation manuals). Staggering the arrays by one line each puts
 * element i of up to 64 arrays in distinct sets (docs/notes/benchmarks.md, "Per-grain
 * arrays staggered by a cache line": about +5 % on a bed of 1e5 grains).
 */
#ifndef GF_SOA_H
#define GF_SOA_H

#include <stddef.h>

/* Lines of shift of the first array of each block: the particle store's 19
 * arrays take lines 0-18, the simulation's own ten per-grain arrays
 * (predicted velocities, inverse masses...) lines 20-29 and the force
 * buffers of the second and later threads six lines each from 30 on, so
 * that the blocks do not share sets either. */
enum { GF_SOA_LINE_PARTICLES = 0, GF_SOA_LINE_SIM = 20 };

/* The block for n arrays of cap elements of elem_size bytes (elem_size a
 * divisor of 64): sets ptrs[a] to array a, each 64-byte aligned and starting
 * (first_line + a) mod 64 cache lines past the start of a page. Copies
 * the first n_keep elements of each array from old[a] when old is not NULL
 * (old[a] pointers into an earlier block), zeroes the rest. Returns the
 * block (free it with gf_soa_free), NULL when out of memory (ptrs unchanged). */
void *gf_soa_alloc(size_t n, size_t elem_size, size_t cap, size_t first_line, void **ptrs, void *const *old,
                   size_t n_keep);
/* Accepts NULL. */
void gf_soa_free(void *block);

#endif
