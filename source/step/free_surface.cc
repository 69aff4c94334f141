#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    std::pair<unsigned int, unsigned int>
    detect_free_surface(const BackgroundGrid<dim>          &grid,
                        const NodalFields<dim>             &nodes,
                        const std::vector<MaterialOptions> &options,
                        SmoothingFields<dim>               &smoothing,
                        ParticleStore<dim>                 &particles,
                        const std::function<void()>        &synchronise,
                        const std::vector<std::unique_ptr<Material>> *materials,
                        CompensatedSum *reset_energy)
    {
      bool any = false;
      for (const auto &o : options)
        any = any || o.detect_free_surface;
      if (!any)
        return {0, 0};

      // phi_i = sum_p N_i(x_p) V_p / Vbar_i, Vbar_i the lumped volume of the
      // node's non-empty cells: the volume-fraction form of Eqs. (31)-(33),
      // counting the points of every material and of every velocity field
      // (on the base node: water beside a bag in another field is not at a
      // free surface). A cell occupied in two fields counts once in Vbar_i.
      auto &phi = smoothing.volume_fraction;
      auto &vol = smoothing.lumped_volume;
      if (phi.size() != grid.n_nodes())
        {
          phi.assign(grid.n_nodes(), 0.);
          vol.assign(grid.n_nodes(), 0.);
        }
      // With one velocity field every active node is its own base node, met
      // once: the loops over them run in parallel.
      const auto for_each_active_node = [&](const auto &f) {
        if (grid.n_velocity_fields() == 1)
          for_each_node(nodes.active_nodes, f);
        else
          for (const unsigned int i : nodes.active_nodes)
            f(i);
      };
      for_each_active_node([&](const unsigned int i) {
        phi[grid.base_node(i)] = vol[grid.base_node(i)] = 0.;
      });
      // Copies of a cell have different colours, so the sums on base nodes
      // are race free; the colours of field f come after those of the
      // fields before it, so a cell counts its volume unless a copy in a
      // lower field is occupied.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const auto share = CellLoops::volume_shares(grid, particles, c);
        bool       first = true;
        for (unsigned int f = 0; f < grid.field_of_cell(c); ++f)
          first = first
                  && particles.occupied_slot(grid.cell_in_field(c, f))
                       == numbers::invalid_unsigned_int;
        const double cell_volume
          = first ? CellLoops::cell_volume(grid, particles, c) : 0.;
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid.base_node(grid.cell_nodes[c][k]);
            phi[i] += share[k];
            if (first)
              vol[i] += cell_volume / (dim + 1);
          }
      });
      // Divide each base node once (zeroing its volume marks it done).
      for_each_active_node([&](const unsigned int i) {
        const unsigned int b = grid.base_node(i);
        if (vol[b] > 0)
          {
            phi[b] /= vol[b];
            vol[b] = 0;
          }
      });

      // MPI: the nodal values on the rim of the ghost layer from their
      // owners, before the points read them back.
      if (synchronise)
        synchronise();
      std::vector<std::pair<unsigned int, unsigned int>> flagged(
        particles.occupied_cells.size(), {0, 0});
      // The stored energy the reset removes, per cell (owned points only).
      const bool book = (materials != nullptr && reset_energy != nullptr);
      std::vector<double> reset(book ? particles.occupied_cells.size() : 0, 0.);
      CellLoops::parallel_range(
        particles.occupied_cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int ci = b; ci < e; ++ci)
            {
              const unsigned int      c = particles.occupied_cells[ci];
              const CellGeometry<dim> geometry
                = CellLoops::geometry(grid, particles, c);
              for (unsigned int p = particles.cell_begin(c);
                   p < particles.cell_end(c);
                   ++p)
                {
                  const MaterialOptions &o = options[particles.material_id[p]];
                  if (!o.detect_free_surface)
                    continue;
                  ++flagged[ci].second;
                  const auto lambda
                    = geometry.barycentric(particles.position[p]);
                  double phi_p = 0;
                  for (unsigned int k = 0; k < dim + 1; ++k)
                    phi_p
                      += lambda[k] * phi[grid.base_node(grid.cell_nodes[c][k])];
                  const bool free = (phi_p <= o.free_surface_threshold);
                  // A point flagged the step before started this step at
                  // zero pressure: no nodal force did work on its volume
                  // change, so the energy its volume ratio now holds is the
                  // explicit update's lag (K (tr d dt)^2 V / 2), created by
                  // the update and removed by the reset, not a loss.
                  const bool was_free       = particles.free_surface[p] != 0;
                  particles.free_surface[p] = free;
                  if (free)
                    {
                      if (book && !was_free
                          && (particles.ghost.empty()
                              || particles.ghost[p] == 0))
                        {
                          const Material &material
                            = *(*materials)[particles.material_id[p]];
                          const double before = material.add_strain_energy(
                            &particles.stress[p],
                            &particles.volume[p],
                            &particles.reference_volume[p],
                            1,
                            0.);
                          const SymmetricTensor<2, 3> after_stress
                            = deviator(particles.stress[p]);
                          reset[ci] += before
                                       - material.add_strain_energy(
                                         &after_stress,
                                         &particles.reference_volume[p],
                                         &particles.reference_volume[p],
                                         1,
                                         0.);
                        }
                      // Zero pressure, volume back to the reference state.
                      particles.stress[p] = deviator(particles.stress[p]);
                      particles.volume[p] = particles.reference_volume[p];
                      ++flagged[ci].first;
                    }
                }
            }
        },
        16);
      std::pair<unsigned int, unsigned int> n = {0, 0};
      for (const auto &f : flagged)
        {
          n.first += f.first;
          n.second += f.second;
        }
      // In the order of the cells: the same for any number of threads.
      for (const double e : reset)
        reset_energy->add(e);
      return n;
    }



    template std::pair<unsigned int, unsigned int>
    detect_free_surface<2>(const BackgroundGrid<2> &,
                           const NodalFields<2> &,
                           const std::vector<MaterialOptions> &,
                           SmoothingFields<2> &,
                           ParticleStore<2> &,
                           const std::function<void()> &,
                           const std::vector<std::unique_ptr<Material>> *,
                           CompensatedSum *);
    template std::pair<unsigned int, unsigned int>
    detect_free_surface<3>(const BackgroundGrid<3> &,
                           const NodalFields<3> &,
                           const std::vector<MaterialOptions> &,
                           SmoothingFields<3> &,
                           ParticleStore<3> &,
                           const std::function<void()> &,
                           const std::vector<std::unique_ptr<Material>> *,
                           CompensatedSum *);
  } // namespace Stages
} // namespace fsgmpm
