#ifndef fsgmpm_parallel_distributed_points_h
#define fsgmpm_parallel_distributed_points_h

#include <fsgmpm/parallel/domain_partition.h>
#include <fsgmpm/particles/particle_store.h>

namespace fsgmpm
{
  /**
   * Moving material points between MPI processes with their whole state
   * (DomainPartition describes who owns what). Between steps a process
   * holds only the points of its own cells; during a step also the ghost
   * copies of the points around them.
   */
  namespace DistributedPoints
  {
    /**
     * Send copies of this process's points to the processes that hold
     * their cells as ghost cells (point to point, no collective), and
     * receive theirs (flagged in
     * particles.ghost). The copies are appended cell by cell, not sorted
     * in: the cell ranges and occupied_cells include them, which is all
     * the stages read (relocate sorts everything again).
     */
    template <int dim>
    void
    add_ghosts(const DomainPartition<dim> &partition,
               ParticleStore<dim>         &particles);

    /**
     * Drop the ghost copies that add_ghosts() appended, before the
     * positions are updated (the copies have served every nodal sum; their
     * motion is their owners'). The arrays are cut back, as no stage
     * reorders points before relocate: no copying.
     */
    template <int dim>
    void
    drop_ghosts(ParticleStore<dim> &particles);

    /**
     * After a step (or a new partition): send the points that moved into
     * another process's cells to it with their whole state, and receive
     * those that moved into ours. Sorted afterwards. Points go to the
     * point neighbours (DomainPartition::point_neighbours()) point to
     * point, with one all-reduce to find out whether any process has
     * points for others (after a repartition), which then go through
     * Utilities::MPI::some_to_some(). Returns the largest @p value over
     * the processes, taken in that all-reduce (the step's displacement
     * ratio: one collective less per step).
     */
    template <int dim>
    double
    migrate(const DomainPartition<dim> &partition,
            ParticleStore<dim>         &particles,
            const double                value = 0.);

    /**
     * migrate() for points whose cells are numbers in the whole grid (as a
     * checkpoint has them, or as they were before the process's grid
     * changed to a new window): send them to their owners in @p partition
     * and number the cells of those kept and received in its grid.
     * Collective.
     */
    template <int dim>
    void
    move_to_owners(const DomainPartition<dim> &partition,
                   ParticleStore<dim>         &particles);

    /**
     * The points of every cell of the whole grid, summed over the
     * processes, on process 0 (for METIS; empty elsewhere). Each process
     * sends the counts of its occupied cells only, so none but process 0
     * holds a whole-grid-sized array. The cells of @p particles are
     * numbers in the whole grid if @p whole_numbers (a checkpoint's, or
     * before a new window), else in @p grid. Collective.
     */
    template <int dim>
    std::vector<unsigned int>
    points_per_cell_on_root(const BackgroundGrid<dim> &grid,
                            const ParticleStore<dim>  &particles,
                            const bool                 whole_numbers,
                            const MPI_Comm            &comm);

    /// The number of points over all processes.
    template <int dim>
    unsigned int
    global_size(const DomainPartition<dim> &partition,
                const ParticleStore<dim>   &particles);
  } // namespace DistributedPoints
} // namespace fsgmpm

#endif
