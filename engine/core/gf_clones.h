/*
 * GF_AVX512_CLONES: a function compiled twice, for x86-64-v4 (AVX-512) and
 * for the baseline, the clone chosen at load time by the machine it runs on
 * (GCC target_clones, an ifunc of glibc). The hot loops that GCC vectorises
 * only with masked AVX-512 stores use it (pair loop, grain-cell transfers,
 * integrator, preparation contacts). The project builds in ISO C mode
 * (-ffp-contract=off), so neither clone fuses multiply-adds and both give
 * the same bits. Elsewhere (other compilers, other libcs) it is empty.
 */
#ifndef GF_CLONES_H
#define GF_CLONES_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__GLIBC__)
#define GF_AVX512_CLONES __attribute__((target_clones("arch=x86-64-v4", "default")))
#else
#define GF_AVX512_CLONES
#endif

#endif
