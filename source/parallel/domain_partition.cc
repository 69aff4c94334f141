#include <fsgmpm/parallel/domain_partition.h>

#include <metis.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

namespace fsgmpm
{
  template <int dim>
  DomainPartition<dim>::DomainPartition(const MPI_Comm            &comm,
                                        const BackgroundGrid<dim> &grid)
    : comm(comm)
    , grid(grid)
    , n_processes(Utilities::MPI::n_mpi_processes(comm))
    , this_process(Utilities::MPI::this_mpi_process(comm))
    , cell_owner(grid.n_global_cells(), 0)
    , ghost_start(grid.n_cells() + 1, 0)
    , counted(grid.n_nodes(), 1)
  {}



  template <int dim>
  void
  DomainPartition<dim>::partition(
    const std::vector<unsigned int> &points_per_cell)
  {
    AssertThrow(!grid.is_window(),
                ExcMessage("METIS splits the whole grid: split() with the "
                           "whole grid, then hand the owners to the "
                           "windows' partitions (set_owners)."));
    set_owners(split(grid, points_per_cell, comm));
  }



  template <int dim>
  std::vector<unsigned int>
  DomainPartition<dim>::split(const BackgroundGrid<dim>       &grid,
                              const std::vector<unsigned int> &points_per_cell,
                              const MPI_Comm                  &comm)
  {
    // Process 0's grid tells the size (another's may be empty yet).
    const unsigned int n_cells
      = Utilities::MPI::broadcast(comm, grid.n_global_cells(), 0);
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    std::vector<unsigned int> cell_owner(n_cells, 0);
    if (n_processes > 1)
      {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            AssertThrow(!grid.is_window(),
                        ExcMessage("METIS splits the whole grid: process 0 "
                                   "must hold it."));
            AssertThrow(points_per_cell.size() == n_cells, ExcInternalError());
            // An empty cell still costs a little (its share of the mesh);
            // a point costs its transfers. The copies of a cell in the
            // other velocity fields (multi-field contact) share the base
            // cell's nodes in the contact stage: they go with it.
            const unsigned int        n_base = grid.n_base_cells();
            std::vector<unsigned int> weights(n_base, 1);
            for (unsigned int c = 0; c < n_cells; ++c)
              weights[c % n_base] += 64 * points_per_cell[c];
            const std::vector<unsigned int> base_owner
              = metis_split(grid, weights, n_processes);
            for (unsigned int c = 0; c < n_base; ++c)
              for (unsigned int f = 0; f < grid.n_velocity_fields(); ++f)
                cell_owner[grid.cell_in_field(c, f)] = base_owner[c];
          }
        const int ierr
          = MPI_Bcast(cell_owner.data(), n_cells, MPI_UNSIGNED, 0, comm);
        AssertThrowMPI(ierr);
      }
    return cell_owner;
  }



  template <int dim>
  std::vector<unsigned int>
  DomainPartition<dim>::metis_split(const BackgroundGrid<dim>       &grid,
                                    const std::vector<unsigned int> &weights,
                                    const unsigned int               n_parts)
  {
    const unsigned int n_base = grid.n_base_cells();
    AssertThrow(weights.size() == n_base && n_parts > 0, ExcInternalError());
    AssertThrow(grid.n_cells() < std::size_t(1) << 31,
                ExcMessage("METIS counts in int: the grid has more than "
                           "2^31 - 1 cells."));
    // METIS splits the grid's blocks of cells (BackgroundGrid::
    // cell_block(): 32 consecutive cells, a compact strip of the mesh), not
    // the cells: METIS holds about 110 B per vertex of its graph, on
    // process 0, which was the largest memory of process 0 (86 MB of the
    // 153 MB heap at its peak for 768 000 triangles), and a block is far
    // below a process's share of the cells. A grid of fewer than 16
    // blocks per part is split by cells. Otherwise the graph is the one
    // GridTools::partition_triangulation gives METIS, of units instead of
    // cells: each unit with itself first, then the units across its cells'
    // faces in ascending order (deal.II 9.4 grid_tools.cc:3732-3758), and
    // METIS is called as SparsityTools::partition calls it (sparsity_tools.
    // cc, partition_metis): the same owners as deal.II's on the same graph
    // (tested), built straight from the grid's neighbours.
    // The units in the grid's own numbers: cell_block() grows with the cell
    // number, so a unit's cells follow one another.
    const bool by_blocks = grid.cell_block(n_base - 1) + 1 >= 16 * n_parts;
    const auto unit      = [&](const unsigned int c) {
      return by_blocks ? grid.cell_block(c) : c;
    };
    const unsigned int         n_units = unit(n_base - 1) + 1;
    std::vector<idx_t>         xadj(1, 0), adjncy;
    std::vector<std::uint64_t> unit_weights(n_units, 0);
    std::vector<unsigned int>  across;
    adjncy.reserve(std::size_t(n_units) * (dim + 3));
    for (unsigned int c = 0; c < n_base; ++c)
      {
        const unsigned int u = unit(c);
        unit_weights[u] += weights[c];
        for (const unsigned int nb : grid.cell_neighbors[c])
          if (nb != BackgroundGrid<dim>::invalid && unit(nb) != u)
            across.push_back(unit(nb));
        if (c + 1 < n_base && unit(c + 1) == u)
          continue;
        // The unit's last cell: its row of the graph.
        std::sort(across.begin(), across.end());
        across.erase(std::unique(across.begin(), across.end()), across.end());
        adjncy.push_back(u);
        adjncy.insert(adjncy.end(), across.begin(), across.end());
        xadj.push_back(adjncy.size());
        across.clear();
      }
    Assert(xadj.size() == n_units + 1, ExcInternalError());
    // METIS sums the weights in int: a run whose weights would overflow
    // it has them divided by a common factor (a few points per cell lost
    // in the rounding, against 10^8 or more in all).
    std::uint64_t total = 0;
    for (const std::uint64_t w : unit_weights)
      total += w;
    const std::uint64_t max_total = std::numeric_limits<idx_t>::max() / 2;
    const std::uint64_t factor    = total / max_total + 1;
    std::vector<idx_t>  vertex_weights(n_units);
    for (unsigned int u = 0; u < n_units; ++u)
      vertex_weights[u] = std::max<std::uint64_t>(1, unit_weights[u] / factor);
    std::vector<idx_t> part(n_units, 0);
    idx_t              n = n_units, n_constraints = 1, edge_cut = 0;
    // METIS cannot split n units into more than n parts.
    idx_t n_metis_parts = std::min<idx_t>(n, n_parts);
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    // SparsityTools::partition's choice: recursive bisection up to 8 parts.
    const int status
      = (n_metis_parts <= 8 ? METIS_PartGraphRecursive
                            : METIS_PartGraphKway)(&n,
                                                   &n_constraints,
                                                   xadj.data(),
                                                   adjncy.data(),
                                                   vertex_weights.data(),
                                                   nullptr,
                                                   nullptr,
                                                   &n_metis_parts,
                                                   nullptr,
                                                   nullptr,
                                                   options,
                                                   &edge_cut,
                                                   part.data());
    AssertThrow(status == METIS_OK,
                ExcMessage("METIS failed to split the grid's cells (error "
                           + std::to_string(status) + ")."));
    std::vector<unsigned int> owners(n_base);
    for (unsigned int c = 0; c < n_base; ++c)
      owners[c] = part[unit(c)];
    return owners;
  }



  template <int dim>
  void
  DomainPartition<dim>::check_owners(const BackgroundGrid<dim>       &grid,
                                     const std::vector<unsigned int> &owners,
                                     const unsigned int n_processes)
  {
    const unsigned int n_global = grid.n_global_cells();
    bool               fits     = owners.size() == n_global;
    for (unsigned int c = 0; fits && c < n_global; ++c)
      fits = owners[c] < n_processes
             && owners[c] == owners[grid.global_base_cell(c)];
    AssertThrow(fits,
                ExcMessage("The cell owners do not fit this mesh and this "
                           "number of processes (or split the copies of a "
                           "cell in the velocity fields)."));
  }



  template <int dim>
  void
  DomainPartition<dim>::set_owners(const std::vector<unsigned int> &owners)
  {
    check_owners(grid, owners, n_processes);
    if (&owners != &cell_owner)
      cell_owner = owners;

    // The cells around every node (CSR), in this grid's numbers: a whole
    // grid or a window. A window holds every cell around a node of our own
    // cells, so what follows is the same in both for those nodes.
    const unsigned int n_cells = grid.n_cells();
    const unsigned int n_nodes = grid.n_nodes();
    const typename BackgroundGrid<dim>::CellsAroundNodes around_nodes
      = grid.cells_around_nodes();
    const std::vector<unsigned int> &start = around_nodes.start;
    const std::vector<unsigned int> &cells = around_nodes.cells;

    // A process holds cell c (owned or ghost) if it owns a cell that shares
    // a vertex with c.
    // Stored as one list with offsets (most cells have no ghost holder; a
    // vector per cell cost 24 B per cell on every process).
    std::vector<unsigned int> ranks;
    ghost_start.assign(n_cells + 1, 0);
    ghost_list.clear();
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        ranks.clear();
        for (const unsigned int i : grid.cell_nodes[c])
          for (unsigned int j = start[i]; j < start[i + 1]; ++j)
            ranks.push_back(owner(cells[j]));
        std::sort(ranks.begin(), ranks.end());
        ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
        ranks.erase(std::find(ranks.begin(), ranks.end(), owner(c)));
        ghost_list.insert(ghost_list.end(), ranks.begin(), ranks.end());
        ghost_start[c + 1] = ghost_list.size();
      }
    ghost_list.shrink_to_fit();
    // The processes whose cells share a vertex with ours: those that hold
    // our cells as ghosts, and whose cells we hold (the relation is
    // symmetric). Ghost copies go only to them, and so do nearly all
    // migrating points.
    point_neighbour_ranks.clear();
    for (unsigned int c = 0; c < n_cells; ++c)
      if (owner(c) == this_process)
        point_neighbour_ranks.insert(point_neighbour_ranks.end(),
                                     ghost_holders(c).begin(),
                                     ghost_holders(c).end());
    std::sort(point_neighbour_ranks.begin(), point_neighbour_ranks.end());
    point_neighbour_ranks.erase(std::unique(point_neighbour_ranks.begin(),
                                            point_neighbour_ranks.end()),
                                point_neighbour_ranks.end());

    // Node i is exact on every process owning a cell around it. It is
    // counted by the lowest-ranked of them. A node of our ghost cells that
    // is no node of ours (the rim) comes from the lowest-ranked owner of
    // the cells around it that we hold: we cannot see all of its cells, so
    // we ask that process for it (every owner computes the same bits).
    std::vector<std::uint8_t> held(n_cells, 0);
    for (unsigned int c = 0; c < n_cells; ++c)
      held[c] = holds(c, this_process);
    counted.assign(n_nodes, 0);
    std::map<unsigned int, std::vector<unsigned int>> receive, wanted;
    std::vector<unsigned int>                         around;
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        around.clear();
        for (unsigned int j = start[i]; j < start[i + 1]; ++j)
          if (held[cells[j]])
            around.push_back(owner(cells[j]));
        if (around.empty())
          continue;
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        if (std::binary_search(around.begin(), around.end(), this_process))
          counted[i] = (around.front() == this_process);
        else
          {
            receive[around.front()].push_back(i);
            wanted[around.front()].push_back(grid.global_node(i));
          }
      }
    // Whose rim nodes we compute: each process tells the owners it chose.
    std::map<unsigned int, std::vector<unsigned int>> send;
    for (auto &[rank, global_nodes] :
         Utilities::MPI::some_to_some(comm, wanted))
      {
        auto &local = send[rank];
        for (const unsigned int g : global_nodes)
          {
            const unsigned int i = grid.local_node(g);
            AssertThrow(i != BackgroundGrid<dim>::invalid, ExcInternalError());
            local.push_back(i);
          }
      }
    neighbours.clear();
    for (unsigned int q = 0; q < n_processes; ++q)
      if (send.count(q) || receive.count(q))
        neighbours.push_back({q, std::move(send[q]), std::move(receive[q])});
  }



  template <int dim>
  void
  DomainPartition<dim>::exchange_bytes() const
  {
    std::vector<MPI_Request> requests;
    requests.reserve(2 * neighbours.size());
    const int tag = 1507;
    // Receives first, so that the sends find them posted.
    for (const bool receive : {true, false})
      for (unsigned int k = 0; k < neighbours.size(); ++k)
        {
          std::vector<char> &buffer
            = receive ? receive_buffers[k] : send_buffers[k];
          if (buffer.empty())
            continue;
          requests.emplace_back();
          const int ierr = receive ? MPI_Irecv(buffer.data(),
                                               buffer.size(),
                                               MPI_BYTE,
                                               neighbours[k].rank,
                                               tag,
                                               comm,
                                               &requests.back())
                                   : MPI_Isend(buffer.data(),
                                               buffer.size(),
                                               MPI_BYTE,
                                               neighbours[k].rank,
                                               tag,
                                               comm,
                                               &requests.back());
          AssertThrowMPI(ierr);
        }
    const int ierr
      = MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
    AssertThrowMPI(ierr);
  }



  template <int dim>
  unsigned int
  DomainPartition<dim>::n_halo_nodes() const
  {
    unsigned int n = 0;
    for (const auto &k : neighbours)
      n += k.send.size() + k.receive.size();
    return n;
  }



  template <int dim>
  unsigned int
  DomainPartition<dim>::n_owned_cells() const
  {
    return std::count(cell_owner.begin(), cell_owner.end(), this_process);
  }

  template <int dim>
  std::vector<unsigned int>
  DomainPartition<dim>::window_cells() const
  {
    return window_cells(this_process);
  }



  template <int dim>
  std::vector<unsigned int>
  DomainPartition<dim>::window_cells(const unsigned int process) const
  {
    return window_cells(grid, cell_owner, process);
  }



  template <int dim>
  std::vector<unsigned int>
  DomainPartition<dim>::window_cells(const BackgroundGrid<dim>       &grid,
                                     const std::vector<unsigned int> &owners,
                                     const unsigned int               process)
  {
    AssertThrow(!grid.is_window(), ExcMessage("Take windows of a whole grid."));
    // The caller checked the owners (check_owners()).
    Assert(owners.size() == grid.n_cells(), ExcInternalError());
    // The nodes of the process's own cells; a cell holds one of them if it
    // shares a vertex with an own cell (then the process holds it).
    std::vector<std::uint8_t> own_node(grid.n_base_nodes(), 0);
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      if (owners[c] == process)
        for (const unsigned int i : grid.cell_nodes[c])
          own_node[i] = 1;
    std::vector<unsigned int> cells;
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      for (const unsigned int i : grid.cell_nodes[c])
        if (own_node[i] != 0)
          {
            cells.push_back(c);
            break;
          }
    return cells;
  }



  template <int dim>
  std::vector<std::vector<unsigned int>>
  DomainPartition<dim>::all_window_cells(
    const BackgroundGrid<dim>       &grid,
    const std::vector<unsigned int> &owners,
    const unsigned int               n_processes)
  {
    AssertThrow(!grid.is_window(), ExcMessage("Take windows of a whole grid."));
    // The caller checked the owners (check_owners()).
    Assert(owners.size() == grid.n_cells(), ExcInternalError());
    // A cell belongs to the window of every owner of a cell around one of
    // its nodes. Most nodes have one owner around them: keep it; the
    // others (on the partition's seams) are "mixed", with their owners
    // listed aside as sorted (node, owner) pairs.
    const unsigned int        none  = numbers::invalid_unsigned_int;
    const unsigned int        mixed = none - 1;
    std::vector<unsigned int> node_owner(grid.n_base_nodes(), none);
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      for (const unsigned int i : grid.cell_nodes[c])
        if (node_owner[i] == none)
          node_owner[i] = owners[c];
        else if (node_owner[i] != owners[c])
          node_owner[i] = mixed;
    std::vector<std::pair<unsigned int, unsigned int>> around;
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      for (const unsigned int i : grid.cell_nodes[c])
        if (node_owner[i] == mixed)
          around.emplace_back(i, owners[c]);
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());

    std::vector<std::vector<unsigned int>> windows(n_processes);
    std::vector<unsigned int>              holders;
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      {
        holders.clear();
        for (const unsigned int i : grid.cell_nodes[c])
          if (node_owner[i] != mixed)
            holders.push_back(node_owner[i]);
          else
            for (auto it = std::lower_bound(around.begin(),
                                            around.end(),
                                            std::make_pair(i, 0u));
                 it != around.end() && it->first == i;
                 ++it)
              holders.push_back(it->second);
        std::sort(holders.begin(), holders.end());
        holders.erase(std::unique(holders.begin(), holders.end()),
                      holders.end());
        for (const unsigned int q : holders)
          windows[q].push_back(c);
      }
    return windows;
  }



  template class DomainPartition<2>;
  template class DomainPartition<3>;
} // namespace fsgmpm
