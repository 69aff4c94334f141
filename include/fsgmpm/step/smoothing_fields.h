#ifndef fsgmpm_step_smoothing_fields_h
#define fsgmpm_step_smoothing_fields_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/particles/particle_store.h>

#include <cstdint>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Scratch nodal fields of the NMD, ANP and free-surface stages: one
   * numerator/denominator pair per material that uses them (volume-weighted
   * averages per material), the free-surface volume fraction, and the
   * velocity gradient of every occupied cell. Only the active nodes are
   * reset.
   */
  template <int dim>
  struct SmoothingFields
  {
    void
    resize(const unsigned int n_materials, const unsigned int n_nodes)
    {
      numerator.assign(n_materials, {});
      denominator.assign(n_materials, {});
      divided.assign(n_materials, 0);
      this->n_nodes = n_nodes;
      velocity_gradient.clear();
    }

    /**
     * Size this step's velocity gradients for the occupied cells of
     * @p particles: they are stored for the occupied cells only (a tank is
     * mostly empty; a gradient for every cell held 32 B per triangle, 72 B
     * per tetrahedron), in the order of the points' occupied_cells, and
     * cell_velocity_gradient(c) finds cell c's by its slot there. Valid
     * until the points are sorted again.
     */
    void
    number_occupied_cells(const ParticleStore<dim> &particles)
    {
      points = &particles;
      velocity_gradient.resize(particles.occupied_cells.size());
    }

    /// The velocity gradient of occupied cell @p c (numbered by
    /// number_occupied_cells() this step).
    Tensor<2, dim> &
    cell_velocity_gradient(const unsigned int c)
    {
      AssertIndexRange(points->occupied_slot(c), velocity_gradient.size());
      return velocity_gradient[points->occupied_slot(c)];
    }

    const Tensor<2, dim> &
    cell_velocity_gradient(const unsigned int c) const
    {
      AssertIndexRange(points->occupied_slot(c), velocity_gradient.size());
      return velocity_gradient[points->occupied_slot(c)];
    }

    /// Make sure material m has nodal arrays and zero them on @p nodes.
    void
    reset(const unsigned int m, const std::vector<unsigned int> &nodes)
    {
      if (numerator[m].size() != n_nodes)
        {
          numerator[m].assign(n_nodes, 0.);
          denominator[m].assign(n_nodes, 0.);
        }
      for_each_node(nodes, [&](const unsigned int i) {
        numerator[m][i] = denominator[m][i] = 0.;
      });
      divided[m] = 0;
    }

    /// Once material m's sums on @p nodes are complete (and, MPI, their
    /// rim refreshed): replace each numerator by its average, so that
    /// average() reads it instead of dividing at every read (a cell's
    /// dim + 1 nodes per run of points, in the stress update and ANP). The
    /// same quotient, so the same bits. Until reset(m).
    void
    divide(const unsigned int m, const std::vector<unsigned int> &nodes)
    {
      Assert(!divided[m], ExcInternalError());
      for_each_node(nodes, [&](const unsigned int i) {
        numerator[m][i]
          = denominator[m][i] > 0 ? numerator[m][i] / denominator[m][i] : 0.;
      });
      divided[m] = 1;
    }

    /// Nodal average of material m at node i (0 if nothing contributed).
    double
    average(const unsigned int m, const unsigned int i) const
    {
      if (divided[m])
        return numerator[m][i];
      return denominator[m][i] > 0 ? numerator[m][i] / denominator[m][i] : 0.;
    }

    /// Bytes held by the arrays (their capacities).
    std::size_t
    memory_consumption() const
    {
      return MemoryConsumption::memory_consumption(numerator)
             + MemoryConsumption::memory_consumption(denominator)
             + MemoryConsumption::memory_consumption(volume_fraction)
             + MemoryConsumption::memory_consumption(lumped_volume)
             + MemoryConsumption::memory_consumption(velocity_gradient)
             + MemoryConsumption::memory_consumption(nodal_velocity_gradient);
    }

    std::vector<std::vector<double>> numerator, denominator;
    /// Per material, whether divide() has turned numerator into averages.
    std::vector<std::uint8_t> divided;
    std::vector<double>       volume_fraction, lumped_volume;
    /// Velocity gradient of the occupied cells, in the order of the
    /// points' occupied_cells (cell_velocity_gradient()).
    std::vector<Tensor<2, dim>> velocity_gradient;
    /// The points whose occupied cells number velocity_gradient.
    const ParticleStore<dim> *points = nullptr;
    /// Stress integration = nodal projection: the cell-volume weighted
    /// nodal average of velocity_gradient (Stages::nodal_velocity_gradients).
    std::vector<Tensor<2, dim>> nodal_velocity_gradient;
    unsigned int                n_nodes = 0;
  };
} // namespace fsgmpm

#endif
