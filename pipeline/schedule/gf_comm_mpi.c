/* MPI for the campaign task farm; see gf_comm.h. Compiled only with MPI. */
#ifdef GF_HAVE_MPI
#include "schedule/gf_comm.h"

#include <mpi.h>
#include <stdlib.h>

static int active;

static int launched_by_mpi(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK") || getenv("MPI_LOCALNRANKS");
}

int gf_comm_init(int *argc, char ***argv)
{
    if (!launched_by_mpi())
        return 0;
    if (MPI_Init(argc, argv) != MPI_SUCCESS)
        return 1;
    active = 1;
    return 0;
}

void gf_comm_finalize(void)
{
    if (active)
        MPI_Finalize();
    active = 0;
}

int gf_comm_rank(void)
{
    int r = 0;
    if (active)
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int gf_comm_size(void)
{
    int n = 1;
    if (active)
        MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
}

long gf_comm_sum(long value)
{
    long sum = value;
    if (active)
        MPI_Allreduce(&value, &sum, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    return sum;
}

void gf_comm_barrier(void)
{
    if (active)
        MPI_Barrier(MPI_COMM_WORLD);
}
#else
typedef int gf_comm_mpi_unused; /* ISO C forbids an empty translation unit */
#endif
