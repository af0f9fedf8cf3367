/* Serial stand-in for gf_comm_mpi.c: the world is one rank; see gf_comm.h. */
#ifndef GF_HAVE_MPI
#include "schedule/gf_comm.h"

int gf_comm_init(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    return 0;
}
void gf_comm_finalize(void) {}
int gf_comm_rank(void) { return 0; }
int gf_comm_size(void) { return 1; }
long gf_comm_sum(long value) { return value; }
void gf_comm_barrier(void) {}
#else
typedef int gf_comm_stub_unused; /* ISO C forbids an empty translation unit */
#endif
