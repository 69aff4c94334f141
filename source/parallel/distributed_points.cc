#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <fsgmpm/parallel/distributed_points.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>

namespace fsgmpm
{
  namespace DistributedPoints
  {
    namespace
    {
      /// The bytes of one point's state as it travels: each state array's
      /// entry in turn (ParticleStore::for_each_state_array()).
      template <int dim>
      std::size_t
      record_size(const ParticleStore<dim> &particles)
      {
        std::size_t bytes = 0;
        particles.for_each_state_array(
          [&](const char *, const auto &v) { bytes += sizeof(v[0]); });
        return bytes;
      }

      template <int dim>
      void
      pack(const ParticleStore<dim> &particles,
           const unsigned int        p,
           const unsigned int        global_cell,
           std::vector<char>        &buffer)
      {
        particles.for_each_state_array([&](const char *, const auto &v) {
          // On the way, a cell goes by its number in the whole grid: the
          // processes may hold windows of it, numbered each their own way.
          const char *value = reinterpret_cast<const char *>(
            (static_cast<const void *>(&v)
             == static_cast<const void *>(&particles.cell))
              ? static_cast<const void *>(&global_cell)
              : static_cast<const void *>(&v[p]));
          buffer.insert(buffer.end(), value, value + sizeof(v[0]));
        });
      }

      /// Append the points of @p buffer; @p ghost marks them as copies.
      template <int dim>
      void
      unpack(const BackgroundGrid<dim> &grid,
             const std::vector<char>   &buffer,
             const std::uint8_t         ghost,
             ParticleStore<dim>        &particles)
      {
        const std::size_t size = record_size(particles);
        AssertThrow(buffer.size() % size == 0, ExcInternalError());
        for (std::size_t k = 0; k < buffer.size(); k += size)
          {
            std::size_t offset = k;
            particles.for_each_state_array([&](const char *, auto &v) {
              v.emplace_back();
              std::memcpy(&v.back(), buffer.data() + offset, sizeof(v[0]));
              offset += sizeof(v[0]);
            });
            unsigned int      &cell        = particles.cell.back();
            const unsigned int global_cell = cell;
            cell                           = grid.local_cell(global_cell);
            AssertThrow(cell != BackgroundGrid<dim>::invalid,
                        ExcMessage("A point arrived in cell "
                                   + std::to_string(global_cell)
                                   + ", which this process does not hold."));
            if (!particles.ghost.empty())
              particles.ghost.push_back(ghost);
          }
      }

      /**
       * Send each point neighbour its buffer of @p send (an empty message
       * where there is none) and receive one message from each: both sides
       * know whom to expect, so there is no collective (deal.II's
       * some_to_some() finds the senders with a consensus algorithm: an
       * all-reduce, two barriers and a non-blocking one per call). Returns
       * the non-empty buffers received, by rank.
       */
      std::map<unsigned int, std::vector<char>>
      exchange_with_neighbours(
        const std::vector<unsigned int>                 &neighbours,
        const std::map<unsigned int, std::vector<char>> &send,
        const MPI_Comm                                  &comm,
        const int                                        tag)
      {
        static const std::vector<char> nothing;
        for ([[maybe_unused]] const auto &[rank, buffer] : send)
          Assert(std::binary_search(neighbours.begin(), neighbours.end(), rank),
                 ExcInternalError());
        std::vector<MPI_Request> requests(neighbours.size());
        for (unsigned int k = 0; k < neighbours.size(); ++k)
          {
            const auto  it     = send.find(neighbours[k]);
            const auto &buffer = (it == send.end()) ? nothing : it->second;
            AssertThrow(buffer.size() <= std::numeric_limits<int>::max(),
                        ExcMessage(
                          "More than 2 GB of points to send to one "
                          "process in one step: run on more processes."));
            const int ierr = MPI_Isend(buffer.data(),
                                       static_cast<int>(buffer.size()),
                                       MPI_BYTE,
                                       neighbours[k],
                                       tag,
                                       comm,
                                       &requests[k]);
            AssertThrowMPI(ierr);
          }
        std::map<unsigned int, std::vector<char>> received;
        for (const unsigned int q : neighbours)
          {
            MPI_Status status;
            int        ierr = MPI_Probe(q, tag, comm, &status);
            AssertThrowMPI(ierr);
            int n = 0;
            ierr  = MPI_Get_count(&status, MPI_BYTE, &n);
            AssertThrowMPI(ierr);
            std::vector<char> buffer(n);
            ierr = MPI_Recv(
              buffer.data(), n, MPI_BYTE, q, tag, comm, MPI_STATUS_IGNORE);
            AssertThrowMPI(ierr);
            if (n > 0)
              received.emplace(q, std::move(buffer));
          }
        const int ierr
          = MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
        AssertThrowMPI(ierr);
        return received;
      }

      // Tags of the two exchanges (DomainPartition's node values use 1507).
      constexpr int ghost_tag = 1508, migration_tag = 1509;
    } // namespace



    template <int dim>
    void
    add_ghosts(const DomainPartition<dim> &partition,
               ParticleStore<dim>         &particles)
    {
      if (partition.n_ranks() == 1)
        return;
      std::map<unsigned int, std::vector<char>> send;
      for (const unsigned int c : particles.occupied_cells)
        for (const unsigned int q : partition.ghost_holders(c))
          {
            std::vector<char> &buffer = send[q];
            for (unsigned int p = particles.cell_begin(c);
                 p < particles.cell_end(c);
                 ++p)
              pack(particles, p, partition.get_grid().global_cell(c), buffer);
          }
      // Every ghost holder of our cells is a point neighbour.
      const auto received
        = exchange_with_neighbours(partition.point_neighbours(),
                                   send,
                                   partition.get_communicator(),
                                   ghost_tag);
      if (received.empty())
        return;
      // Append the copies without sorting: a ghost cell has one owner,
      // which sent all its points together, in the canonical order, so each
      // ghost cell is one run of the appended points. Only the cell ranges
      // and the list of occupied cells need them (the ghost cells held no
      // points before).
      const unsigned int n_owned = particles.size();
      particles.ghost.assign(n_owned, 0);
      for (const auto &[rank, buffer] : received)
        unpack(partition.get_grid(), buffer, 1, particles);
      std::vector<unsigned int> ghost_cells;
      for (unsigned int p = n_owned; p < particles.size();)
        {
          const unsigned int c   = particles.cell[p];
          unsigned int       end = p + 1;
          while (end < particles.size() && particles.cell[end] == c)
            ++end;
          particles.append_cell_range(c, p, end);
          ghost_cells.push_back(c);
          p = end;
        }
      std::sort(ghost_cells.begin(), ghost_cells.end());
      std::vector<unsigned int> occupied;
      occupied.reserve(particles.occupied_cells.size() + ghost_cells.size());
      std::merge(particles.occupied_cells.begin(),
                 particles.occupied_cells.end(),
                 ghost_cells.begin(),
                 ghost_cells.end(),
                 std::back_inserter(occupied));
      particles.occupied_cells.swap(occupied);
    }



    template <int dim>
    void
    drop_ghosts(ParticleStore<dim> &particles)
    {
      if (particles.ghost.empty())
        return;
      const unsigned int n_owned
        = std::find(particles.ghost.begin(), particles.ghost.end(), 1)
          - particles.ghost.begin();
      AssertThrow(std::find(particles.ghost.begin() + n_owned,
                            particles.ghost.end(),
                            0)
                    == particles.ghost.end(),
                  ExcInternalError());
      // The ghost cells are those whose points lie in the cut tail.
      std::vector<unsigned int> owned_cells;
      owned_cells.reserve(particles.occupied_cells.size());
      for (const unsigned int c : particles.occupied_cells)
        if (particles.cell_begin(c) < n_owned)
          owned_cells.push_back(c);
      particles.keep_cell_ranges(owned_cells);
      particles.for_each_state_array(
        [n_owned](const char *, auto &v) { v.resize(n_owned); });
      particles.ghost.clear();
    }



    namespace
    {
      /// migrate() and move_to_owners(): the points' cells are numbers of
      /// the partition's grid, or of the whole grid if @p whole_numbers.
      template <int dim>
      double
      send_to_owners(const DomainPartition<dim> &partition,
                     ParticleStore<dim>         &particles,
                     const double                value,
                     const bool                  whole_numbers)
      {
        const BackgroundGrid<dim> &grid       = partition.get_grid();
        const auto                &neighbours = partition.point_neighbours();
        std::map<unsigned int, std::vector<char>> near, far;
        std::vector<std::uint8_t>                 flag(particles.size(), 0);
        bool                                      leaving = false;
        for (unsigned int p = 0; p < particles.size(); ++p)
          {
            const unsigned int global_cell
              = whole_numbers ? particles.cell[p]
                              : grid.global_cell(particles.cell[p]);
            const unsigned int q = partition.owners()[global_cell];
            if (q != partition.rank())
              {
                const bool neighbour
                  = std::binary_search(neighbours.begin(), neighbours.end(), q);
                pack(particles, p, global_cell, (neighbour ? near : far)[q]);
                flag[p] = leaving = true;
              }
          }
        // A step moves a point less than its cell's smallest altitude, so
        // into a cell around its old one (whose owner is a neighbour) but
        // for slivers; after a repartition or a restart on another number
        // of processes the new owner may be anyone. Those go the collective
        // way, when some process has any.
        const MPI_Comm &comm = partition.get_communicator();
        auto            received
          = exchange_with_neighbours(neighbours, near, comm, migration_tag);
        // The caller's maximum rides in the same all-reduce.
        const std::vector<double> local = {far.empty() ? 0. : 1., value};
        std::vector<double>       global(2);
        Utilities::MPI::max(make_array_view(local),
                            comm,
                            make_array_view(global));
        if (global[0] > 0)
          for (auto &[rank, buffer] : Utilities::MPI::some_to_some(comm, far))
            {
              std::vector<char> &all = received[rank];
              all.insert(all.end(), buffer.begin(), buffer.end());
            }
        if (leaving)
          particles.remove_flagged(flag);
        if (whole_numbers)
          for (unsigned int &c : particles.cell)
            {
              const unsigned int g = c;
              c                    = grid.local_cell(g);
              AssertThrow(c != BackgroundGrid<dim>::invalid,
                          ExcMessage("This process owns cell "
                                     + std::to_string(g)
                                     + " but does not hold it."));
            }
        for (const auto &[rank, buffer] : received)
          unpack(grid, buffer, 0, particles);
        particles.sort_by_cell(grid.n_cells());
        return global[1];
      }
    } // namespace



    template <int dim>
    double
    migrate(const DomainPartition<dim> &partition,
            ParticleStore<dim>         &particles,
            const double                value)
    {
      if (partition.n_ranks() == 1)
        return value;
      // After the step: MpmStep::advance cut the ghost copies off.
      Assert(particles.ghost.empty(), ExcInternalError());
      return send_to_owners(partition, particles, value, false);
    }



    template <int dim>
    void
    move_to_owners(const DomainPartition<dim> &partition,
                   ParticleStore<dim>         &particles)
    {
      Assert(particles.ghost.empty(), ExcInternalError());
      send_to_owners(partition, particles, 0., true);
    }



    template <int dim>
    unsigned int
    global_size(const DomainPartition<dim> &partition,
                const ParticleStore<dim>   &particles)
    {
      Assert(particles.ghost.empty(), ExcInternalError());
      return Utilities::MPI::sum(particles.size(),
                                 partition.get_communicator());
    }



    template <int dim>
    std::vector<unsigned int>
    points_per_cell_on_root(const BackgroundGrid<dim> &grid,
                            const ParticleStore<dim>  &particles,
                            const bool                 whole_numbers,
                            const MPI_Comm            &comm)
    {
      std::vector<unsigned int> cells, counts;
      cells.reserve(particles.occupied_cells.size());
      counts.reserve(particles.occupied_cells.size());
      for (const unsigned int c : particles.occupied_cells)
        {
          cells.push_back(whole_numbers ? c : grid.global_cell(c));
          counts.push_back(particles.cell_end(c) - particles.cell_begin(c));
        }
      return Parallel::gather_to_root(cells,
                                      counts,
                                      grid.n_global_cells(),
                                      comm,
                                      [](unsigned int      &sum,
                                         const unsigned int n) { sum += n; });
    }



#define FSGMPM_INSTANTIATE(dim)                                           \
  template void         add_ghosts<dim>(const DomainPartition<dim> &,     \
                                ParticleStore<dim> &);            \
  template double       migrate<dim>(const DomainPartition<dim> &,        \
                               ParticleStore<dim> &,                \
                               const double);                       \
  template void         drop_ghosts<dim>(ParticleStore<dim> &);           \
  template void         move_to_owners<dim>(const DomainPartition<dim> &, \
                                    ParticleStore<dim> &);        \
  template unsigned int global_size<dim>(const DomainPartition<dim> &,    \
                                         const ParticleStore<dim> &);     \
  template std::vector<unsigned int> points_per_cell_on_root<dim>(        \
    const BackgroundGrid<dim> &,                                          \
    const ParticleStore<dim> &,                                           \
    const bool,                                                           \
    const MPI_Comm &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace DistributedPoints
} // namespace fsgmpm
