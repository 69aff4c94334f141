#include <deal.II/base/mpi.h>

#include <fsgmpm/parallel/distributed_points.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <map>

namespace fsgmpm
{
  namespace DistributedPoints
  {
    namespace
    {
      /// The whole state of one point, as it travels.
      template <int dim>
      struct Record
      {
        Point<dim>            position;
        Tensor<1, dim>        velocity;
        Tensor<2, dim>        affine_velocity;
        SymmetricTensor<2, 3> stress;
        double                mass, volume, reference_volume;
        unsigned int          cell, id;
        std::uint16_t         material_id, body_id;
        std::uint8_t          free_surface;
      };

      template <int dim>
      void
      pack(const ParticleStore<dim> &particles,
           const unsigned int        p,
           std::vector<char>        &buffer)
      {
        Record<dim> r;
        r.position = particles.position[p];
        r.velocity = particles.velocity[p];
        if (particles.has_affine_velocity())
          r.affine_velocity = particles.affine_velocity[p];
        r.stress            = particles.stress[p];
        r.mass              = particles.mass[p];
        r.volume            = particles.volume[p];
        r.reference_volume  = particles.reference_volume[p];
        r.cell              = particles.cell[p];
        r.id                = particles.id[p];
        r.material_id       = particles.material_id[p];
        r.body_id           = particles.body_id[p];
        r.free_surface      = particles.free_surface[p];
        const std::size_t n = buffer.size();
        buffer.resize(n + sizeof(r));
        std::memcpy(buffer.data() + n, &r, sizeof(r));
      }

      /// Append the points of @p buffer; @p ghost marks them as copies.
      template <int dim>
      void
      unpack(const std::vector<char> &buffer,
             const std::uint8_t       ghost,
             ParticleStore<dim>      &particles)
      {
        AssertThrow(buffer.size() % sizeof(Record<dim>) == 0,
                    ExcInternalError());
        for (std::size_t k = 0; k < buffer.size(); k += sizeof(Record<dim>))
          {
            Record<dim> r;
            std::memcpy(&r, buffer.data() + k, sizeof(r));
            particles.position.push_back(r.position);
            particles.velocity.push_back(r.velocity);
            if (particles.has_affine_velocity())
              particles.affine_velocity.push_back(r.affine_velocity);
            particles.stress.push_back(r.stress);
            particles.mass.push_back(r.mass);
            particles.volume.push_back(r.volume);
            particles.reference_volume.push_back(r.reference_volume);
            particles.cell.push_back(r.cell);
            particles.id.push_back(r.id);
            particles.material_id.push_back(r.material_id);
            particles.body_id.push_back(r.body_id);
            particles.free_surface.push_back(r.free_surface);
            if (!particles.ghost.empty())
              particles.ghost.push_back(ghost);
          }
      }
    } // namespace



    template <int dim>
    void
    keep_owned(const DomainPartition<dim> &partition,
               ParticleStore<dim>         &particles)
    {
      std::vector<std::uint8_t> flag(particles.size());
      for (unsigned int p = 0; p < particles.size(); ++p)
        flag[p] = (partition.owner(particles.cell[p]) != partition.rank());
      particles.remove_flagged(flag);
      particles.ghost.clear();
      particles.sort_by_cell(particles.cell_begin.size());
    }



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
            for (unsigned int p = particles.cell_begin[c];
                 p < particles.cell_end[c];
                 ++p)
              pack(particles, p, buffer);
          }
      const auto received
        = Utilities::MPI::some_to_some(partition.get_communicator(), send);
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
        unpack(buffer, 1, particles);
      std::vector<unsigned int> ghost_cells;
      for (unsigned int p = n_owned; p < particles.size(); ++p)
        {
          const unsigned int c = particles.cell[p];
          if (p == n_owned || particles.cell[p - 1] != c)
            {
              Assert(particles.cell_end[c] == particles.cell_begin[c],
                     ExcInternalError());
              ghost_cells.push_back(c);
              particles.cell_begin[c] = p;
            }
          particles.cell_end[c] = p + 1;
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
        if (particles.cell_begin[c] < n_owned)
          owned_cells.push_back(c);
        else
          particles.cell_begin[c] = particles.cell_end[c] = 0;
      particles.occupied_cells.swap(owned_cells);
      auto cut = [n_owned](auto &v) { v.resize(n_owned); };
      cut(particles.position);
      cut(particles.velocity);
      if (particles.has_affine_velocity())
        cut(particles.affine_velocity);
      cut(particles.stress);
      cut(particles.mass);
      cut(particles.volume);
      cut(particles.reference_volume);
      cut(particles.cell);
      cut(particles.material_id);
      cut(particles.body_id);
      cut(particles.free_surface);
      cut(particles.id);
      particles.ghost.clear();
    }



    template <int dim>
    void
    migrate(const DomainPartition<dim> &partition,
            ParticleStore<dim>         &particles)
    {
      if (partition.n_ranks() == 1)
        return;
      // After the step: MpmStep::advance cut the ghost copies off.
      Assert(particles.ghost.empty(), ExcInternalError());
      std::map<unsigned int, std::vector<char>> send;
      std::vector<std::uint8_t>                 flag(particles.size(), 0);
      bool                                      leaving = false;
      for (unsigned int p = 0; p < particles.size(); ++p)
        if (partition.owner(particles.cell[p]) != partition.rank())
          {
            pack(particles, p, send[partition.owner(particles.cell[p])]);
            flag[p] = leaving = true;
          }
      const auto received
        = Utilities::MPI::some_to_some(partition.get_communicator(), send);
      if (leaving)
        particles.remove_flagged(flag);
      for (const auto &[rank, buffer] : received)
        unpack(buffer, 0, particles);
      particles.sort_by_cell(particles.cell_begin.size());
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



#define FSGMPM_INSTANTIATE(dim)                                        \
  template void         keep_owned<dim>(const DomainPartition<dim> &,  \
                                ParticleStore<dim> &);         \
  template void         add_ghosts<dim>(const DomainPartition<dim> &,  \
                                ParticleStore<dim> &);         \
  template void         migrate<dim>(const DomainPartition<dim> &,     \
                             ParticleStore<dim> &);            \
  template void         drop_ghosts<dim>(ParticleStore<dim> &);        \
  template unsigned int global_size<dim>(const DomainPartition<dim> &, \
                                         const ParticleStore<dim> &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace DistributedPoints
} // namespace fsgmpm
