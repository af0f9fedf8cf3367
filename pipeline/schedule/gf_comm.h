/*
 * The campaign's view of MPI: a rank, a size, a sum. The only MPI caller is
 * gf_comm_mpi.c; serial builds (no MPI found, or GF_WITH_MPI=OFF) compile
 * gf_comm_stub.c instead, where the world is one rank.
 *
 * MPI is initialised only when the process was started by an MPI launcher
 * (mpirun/mpiexec/srun set OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK), so
 * a plain `grainflow campaign` on a laptop never pays for, or depends on, an
 * MPI runtime.
 */
#ifndef GF_COMM_H
#define GF_COMM_H

/* Initialises MPI when launched under an MPI launcher. Returns non-zero on failure. */
int gf_comm_init(int *argc, char ***argv);
void gf_comm_finalize(void);
int gf_comm_rank(void);
int gf_comm_size(void);
/* Sum of a non-negative integer over ranks. collective */
long gf_comm_sum(long value);
/* collective */
void gf_comm_barrier(void);

#endif
