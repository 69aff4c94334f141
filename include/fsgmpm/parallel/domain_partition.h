#ifndef fsgmpm_parallel_domain_partition_h
#define fsgmpm_parallel_domain_partition_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/parallel/gather_to_root.h>
#include <fsgmpm/parallel/values_of_owners.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Which MPI process owns which cell of the background grid, and the halo
   * that makes every process's nodal values exact.
   *
   * The cells are split by METIS on the face graph of the grid's blocks of
   * cells (as deal.II's GridTools::partition_triangulation does for
   * cells), weighted by the points they hold, so work follows the
   * material. A process holds the points of its own
   * cells and, during a step, copies ("ghosts") of the points of every cell
   * that shares a vertex with one of its cells: the same layer that
   * parallel::fullydistributed::Triangulation keeps as ghost cells. Then
   * every node of an owned cell receives all its contributions, in the
   * serial order (cells by colour and index, points by id), so its value
   * is the serial one bit for bit. The nodes on the outer rim of the ghost
   * layer miss contributions; update_ghost_nodes() overwrites them with the
   * values of a process that owns a cell around them, after each stage
   * whose nodal values the ghost points read back. With that, ghost points
   * evolve exactly as their originals, and an MPI run repeats the serial
   * run's arithmetic.
   *
   * The partition works on a whole grid or on a process's window of it
   * (BackgroundGrid::window(), window_cells()): the owners stay an array
   * over the whole grid (4 B per cell), the rest comes from the cells the
   * grid holds, and a rim node is asked of one of its owners once per
   * partition (doc/mpi.md, "Grid windows"). An MPI run holds its window
   * after the first partition; process 0 keeps the whole grid
   * besides, for METIS and the grid's output.
   * With multi-field contact the copies of a cell in the
   * other velocity fields belong to the base cell's owner; a membrane is
   * held whole by every process (MembraneCoupling).
   */
  template <int dim>
  class DomainPartition
  {
  public:
    DomainPartition(const MPI_Comm &comm, const BackgroundGrid<dim> &grid);

    /**
     * Split the cells over the processes, weighted by @p points_per_cell
     * (the points of each cell over all processes). METIS runs on rank 0
     * and the result is broadcast, so all processes agree.
     */
    void
    partition(const std::vector<unsigned int> &points_per_cell);

    /**
     * The owners partition() would choose, without taking them: METIS on
     * rank 0's @p grid, which must be whole there (on the other processes
     * @p grid may be a window or empty: it is not read); @p points_per_cell
     * has one entry per cell of the whole grid on rank 0 and is not read
     * elsewhere.
     */
    static std::vector<unsigned int>
    split(const BackgroundGrid<dim>       &grid,
          const std::vector<unsigned int> &points_per_cell,
          const MPI_Comm                  &comm);

    /**
     * METIS's split of the cells of field 0 of the whole @p grid into
     * @p n_parts parts of about equal sums of @p weights (one per cell of
     * field 0), on this process alone. METIS splits the grid's blocks of
     * cells (BackgroundGrid::cell_block()), each going whole to one part,
     * on the graph GridTools::partition_triangulation() would build of
     * them: a graph 32 times smaller than the cells' (METIS's memory on
     * process 0). A grid of fewer than 16 blocks per part is split by
     * cells, as partition_triangulation() would split it.
     */
    static std::vector<unsigned int>
    metis_split(const BackgroundGrid<dim>       &grid,
                const std::vector<unsigned int> &weights,
                const unsigned int               n_parts);

    /// Take @p owners (the owning process of every cell, the same on all
    /// processes) as the partition: a checkpoint's, so that a restarted
    /// run splits the cells as the interrupted one did.
    void
    set_owners(const std::vector<unsigned int> &owners);

    /// Throw, with a message, unless @p owners has a process below
    /// @p n_processes for every cell of the whole grid of @p grid (a whole
    /// grid or a window), the same for the copies of a cell in every
    /// velocity field.
    static void
    check_owners(const BackgroundGrid<dim>       &grid,
                 const std::vector<unsigned int> &owners,
                 const unsigned int               n_processes);

    /// The owning process of every cell of the whole grid.
    const std::vector<unsigned int> &
    owners() const
    {
      return cell_owner;
    }

    unsigned int
    n_ranks() const
    {
      return n_processes;
    }

    unsigned int
    rank() const
    {
      return this_process;
    }

    const MPI_Comm &
    get_communicator() const
    {
      return comm;
    }

    /// The grid (whole, or this process's window) whose cell and node
    /// numbers the partition's lists use.
    const BackgroundGrid<dim> &
    get_grid() const
    {
      return grid;
    }

    /// The process that owns cell c (of the grid this partition was made
    /// with: a window's number).
    unsigned int
    owner(const unsigned int c) const
    {
      return cell_owner[grid.global_cell(c)];
    }

    /// The processes that hold cell c as a ghost cell (not its owner).
    /// All of them for our own cells; in a window, a ghost cell's may miss
    /// those that own no cell of the window.
    ArrayView<const unsigned int>
    ghost_holders(const unsigned int c) const
    {
      return ArrayView<const unsigned int>(ghost_list.data() + ghost_start[c],
                                           ghost_start[c + 1] - ghost_start[c]);
    }

    /**
     * The processes that own a cell sharing a vertex with one of ours,
     * ascending: they hold our cells as ghost cells and we theirs (a
     * symmetric relation, so each side knows whom to expect messages
     * from).
     */
    const std::vector<unsigned int> &
    point_neighbours() const
    {
      return point_neighbour_ranks;
    }

    /**
     * 1 for the nodes whose sums (energies, work, norms) this process adds
     * up: those whose lowest-ranked adjacent owner it is, so that every
     * node is counted once over all processes.
     */
    const std::vector<std::uint8_t> &
    counted_nodes() const
    {
      return counted;
    }

    /**
     * Overwrite this process's values on the outer rim of its ghost layer
     * by those of the process that computed them exactly. Only the entries
     * of active nodes (active_stamp[i] == stamp) are written: a node is
     * active here only if it is active at the sender too.
     */
    template <typename T>
    void
    update_ghost_nodes(std::vector<T>                  &values,
                       const std::vector<std::uint8_t> &active_stamp,
                       const std::uint8_t               stamp) const;

    /**
     * Every node's value as the process that counts it has it (exact
     * there), on every process: a sum over the processes in which the
     * others give -0, the exact neutral element of IEEE addition. For
     * output of nodal fields; @p T is double or a Tensor of doubles. On a
     * window the result has an entry for every node of the whole grid, by
     * its number there, and only process 0 (which writes the grid) gets
     * it: the others get an empty vector.
     */
    template <typename T>
    std::vector<T>
    counted_values(const std::vector<T> &values) const;

    /// Number of (send + receive) rim nodes: the halo exchanged per field.
    unsigned int
    n_halo_nodes() const;

    /// Number of cells this process owns.
    unsigned int
    n_owned_cells() const;

    /**
     * The base cells (field 0) this process needs, ascending: those it owns
     * and every cell that shares a vertex with one of them (its ghost
     * layer). BackgroundGrid::window() of these holds every node whose sums
     * this process computes exactly.
     */
    std::vector<unsigned int>
    window_cells() const;

    /// window_cells() of process @p process (of a whole grid).
    std::vector<unsigned int>
    window_cells(const unsigned int process) const;

    /// window_cells() of process @p process for the owners @p owners of
    /// the cells of the whole grid @p grid, without a partition (no
    /// collective: process 0 cuts every process's window).
    static std::vector<unsigned int>
    window_cells(const BackgroundGrid<dim>       &grid,
                 const std::vector<unsigned int> &owners,
                 const unsigned int               process);

    /// window_cells() of every one of @p n_processes processes, in one
    /// pass over the cells (process 0 cuts all windows at the start and at
    /// every repartition: calling window_cells() for each process costs
    /// processes x cells).
    static std::vector<std::vector<unsigned int>>
    all_window_cells(const BackgroundGrid<dim>       &grid,
                     const std::vector<unsigned int> &owners,
                     const unsigned int               n_processes);

  private:
    MPI_Comm                   comm;
    const BackgroundGrid<dim> &grid;
    unsigned int               n_processes;
    unsigned int               this_process;
    std::vector<unsigned int>  cell_owner;
    /// ghost_holders(c): ghost_list[ghost_start[c]..ghost_start[c + 1]).
    std::vector<unsigned int> ghost_start, ghost_list;
    std::vector<unsigned int> point_neighbour_ranks;
    std::vector<std::uint8_t> counted;

    /// Per neighbouring process: the rim nodes sent to it and received
    /// from it, ascending (both sides compute the same lists).
    struct Neighbour
    {
      unsigned int              rank;
      std::vector<unsigned int> send, receive;
    };
    std::vector<Neighbour>                 neighbours;
    mutable std::vector<std::vector<char>> send_buffers, receive_buffers;

    void
    exchange_bytes() const;

    /// Whether @p process holds cell @p c: owns it, or holds it as a ghost.
    bool
    holds(const unsigned int c, const unsigned int process) const
    {
      const auto holders = ghost_holders(c);
      return owner(c) == process
             || std::find(holders.begin(), holders.end(), process)
                  != holders.end();
    }
  };



  template <int dim>
  template <typename T>
  std::vector<T>
  DomainPartition<dim>::counted_values(const std::vector<T> &values) const
  {
    if (!grid.is_window())
      {
        std::vector<T> result = values;
        Parallel::take_values_of_owners(
          result,
          [this](const unsigned int i) { return counted[i] != 0; },
          comm);
        return result;
      }
    // A window: each process sends process 0 the whole-grid numbers and
    // values of the nodes it counts (each node is counted once).
    std::vector<unsigned int> index;
    std::vector<T>            own_values;
    for (unsigned int i = 0; i < values.size(); ++i)
      if (counted[i] != 0)
        {
          index.push_back(grid.global_node(i));
          own_values.push_back(values[i]);
        }
    return Parallel::gather_to_root(index,
                                    own_values,
                                    grid.n_global_nodes(),
                                    comm,
                                    [](T &to, const T &value) { to = value; });
  }



  template <int dim>
  template <typename T>
  void
  DomainPartition<dim>::update_ghost_nodes(
    std::vector<T>                  &values,
    const std::vector<std::uint8_t> &active_stamp,
    const std::uint8_t               stamp) const
  {
    if (neighbours.empty())
      return;
    send_buffers.resize(neighbours.size());
    receive_buffers.resize(neighbours.size());
    for (unsigned int k = 0; k < neighbours.size(); ++k)
      {
        const auto &send = neighbours[k].send;
        send_buffers[k].resize(send.size() * sizeof(T));
        for (unsigned int j = 0; j < send.size(); ++j)
          std::memcpy(send_buffers[k].data() + j * sizeof(T),
                      &values[send[j]],
                      sizeof(T));
        receive_buffers[k].resize(neighbours[k].receive.size() * sizeof(T));
      }
    exchange_bytes();
    for (unsigned int k = 0; k < neighbours.size(); ++k)
      {
        const auto &receive = neighbours[k].receive;
        for (unsigned int j = 0; j < receive.size(); ++j)
          if (active_stamp[receive[j]] == stamp)
            std::memcpy(&values[receive[j]],
                        receive_buffers[k].data() + j * sizeof(T),
                        sizeof(T));
      }
  }
} // namespace fsgmpm

#endif
