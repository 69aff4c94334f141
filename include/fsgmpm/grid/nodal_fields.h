#ifndef fsgmpm_grid_nodal_fields_h
#define fsgmpm_grid_nodal_fields_h

#include <deal.II/base/memory_consumption.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /// Call f(i) for every node i of @p node_list (e.g. the active nodes) in
  /// parallel: for loops over nodes whose iterations touch only their own
  /// node (serial, such loops between the parallel stages held back the
  /// second thread).
  template <typename Function>
  void
  for_each_node(const std::vector<unsigned int> &node_list, const Function &f)
  {
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(node_list.size()),
      [&](const unsigned int b, const unsigned int e) {
        for (unsigned int a = b; a < e; ++a)
          f(node_list[a]);
      },
      1024);
  }

  /**
   * Lumped nodal quantities of the background grid. Only the nodes of cells
   * that hold material ("active nodes") are reset and updated each step, so
   * empty parts of the domain cost nothing.
   */
  template <int dim>
  struct NodalFields
  {
    void
    resize(const unsigned int n_nodes)
    {
      // Fresh arrays, not assign(): a window after a whole grid, or a
      // smaller window after a repartition, keeps no larger capacity.
      refill(mass, n_nodes);
      refill(momentum, n_nodes);
      refill(internal_force, n_nodes);
      refill(velocity, n_nodes);
      refill(acceleration, n_nodes);
      // The fields of one option each are sized when it first writes them
      // (use()): most scenes need none of them.
      release(added_mass);
      release(contact_normal);
      release(contact_volume);
      release(volume_stress);
      release(support_volume);
      release(lumped_volume);
      release(occupied_volume);
      release(projection_weights);
      release(stabilised_trace);
      release(projection_own_trace);
      release(wall_contact);
      release(field_contact_state);
      refill(active_stamp, n_nodes);
      release(active_nodes);
      stamp = 0;
    }

    /// Zero every field at the nodes that were active.
    void
    reset_active()
    {
      for_each_node(active_nodes, [this](const unsigned int i) {
        mass[i]           = 0.;
        momentum[i]       = Tensor<1, dim>();
        internal_force[i] = Tensor<1, dim>();
        velocity[i]       = Tensor<1, dim>();
        acceleration[i]   = Tensor<1, dim>();
        if (!added_mass.empty())
          added_mass[i] = SymmetricTensor<2, dim>();
        if (!wall_contact.empty())
          wall_contact[i] = 0;
        if (!volume_stress.empty())
          {
            volume_stress[i]   = Tensor<2, dim>();
            support_volume[i]  = 0.;
            lumped_volume[i]   = 0.;
            occupied_volume[i] = 0.;
          }
        if (!stabilised_trace.empty())
          stabilised_trace[i] = 0.;
      });
      active_nodes.clear();
      // A byte per node: when the stamp wraps, every node is unmarked once
      // (O(nodes) every 255 steps).
      if (++stamp == 0)
        {
          std::fill(active_stamp.begin(), active_stamp.end(), 0);
          stamp = 1;
        }
    }

    /// Size an optional field (added_mass, contact_normal and
    /// contact_volume, volume_stress and support_volume: empty until their
    /// option first writes them), zero, if it is not sized yet.
    template <typename T>
    void
    use(std::vector<T> &field) const
    {
      if (field.size() != mass.size())
        field.assign(mass.size(), T());
    }

    /// Bytes held by the nodal arrays (their capacities).
    std::size_t
    memory_consumption() const
    {
      return MemoryConsumption::memory_consumption(mass)
             + MemoryConsumption::memory_consumption(momentum)
             + MemoryConsumption::memory_consumption(internal_force)
             + MemoryConsumption::memory_consumption(velocity)
             + MemoryConsumption::memory_consumption(acceleration)
             + MemoryConsumption::memory_consumption(added_mass)
             + MemoryConsumption::memory_consumption(contact_normal)
             + MemoryConsumption::memory_consumption(contact_volume)
             + MemoryConsumption::memory_consumption(volume_stress)
             + MemoryConsumption::memory_consumption(support_volume)
             + MemoryConsumption::memory_consumption(lumped_volume)
             + MemoryConsumption::memory_consumption(occupied_volume)
             + MemoryConsumption::memory_consumption(projection_weights)
             + MemoryConsumption::memory_consumption(stabilised_trace)
             + MemoryConsumption::memory_consumption(projection_own_trace)
             + MemoryConsumption::memory_consumption(wall_contact)
             + MemoryConsumption::memory_consumption(field_contact_state)
             + MemoryConsumption::memory_consumption(active_nodes)
             + MemoryConsumption::memory_consumption(active_stamp);
    }

    /// Mark the nodes of one occupied cell active (call after reset_active).
    template <typename NodeArray>
    void
    activate(const NodeArray &nodes)
    {
      for (const unsigned int i : nodes)
        if (active_stamp[i] != stamp)
          {
            active_stamp[i] = stamp;
            active_nodes.push_back(i);
          }
    }

    std::vector<double>         mass;
    std::vector<Tensor<1, dim>> momentum;
    /// F_int of Eq. (3), with the sign of the paper: M a = F_ext - F_int.
    /// F_ext of Eq. (4) is gravity only, m_i g: the grid update computes
    /// it where it needs it (no array).
    std::vector<Tensor<1, dim>> internal_force;
    /// Nodal velocity: v^{n+1} after the grid update, then the remapped
    /// velocity of Eq. (20) in MUSL.
    std::vector<Tensor<1, dim>> velocity;
    /// Constrained nodal acceleration a^n of Eq. (18).
    std::vector<Tensor<1, dim>> acceleration;
    /// Fictitious inertia of dynamic relaxation (mass scaling; empty
    /// without), a tensor so
    /// that it acts only in the directions in which a stiff membrane needs
    /// it (along the cables): a = (m I + added_mass)^-1 F. It slows the
    /// node's acceleration but carries no weight and no momentum.
    std::vector<SymmetricTensor<2, dim>> added_mass;
    /// Multi-field contact (empty with one velocity field): at a node of
    /// field 0, the unnormalised normal
    /// from field 0 towards field 1 (grad m_1 - grad m_0), set by
    /// Stages::contact_normals.
    std::vector<Tensor<1, dim>> contact_normal;
    /// Multi-field contact: at a node of field 0, sum_p N_i(x_p) V_p over
    /// the points of all fields (the volume the materials fill there).
    std::vector<double> contact_volume;

    /// Nodal stress projection (Stress integration = nodal projection;
    /// empty without): sum_p N_i(x_p) V_p sigma_p, the in-plane part.
    std::vector<Tensor<2, dim>> volume_stress;
    /// Nodal stress projection: sum over the occupied cells c around node i
    /// of the cell's quadrature weight q_ic (projection_weights): the volume
    /// that s_i = volume_stress_i / support_volume_i is the average over.
    std::vector<double> support_volume;
    /// Nodal stress projection: sum_p N_i(x_p) V_p, the points' volume
    /// lumped to node i.
    std::vector<double> lumped_volume;
    /// Nodal stress projection: sum over the occupied cells c around node i
    /// of V_c / (dim + 1); lumped_volume / occupied_volume is the node's
    /// fill.
    std::vector<double> occupied_volume;
    /// Nodal stress projection, per occupied cell (in the order of the
    /// points' occupied_cells, ParticleStore::occupied_slot()): the weight
    /// q_kc of each of its nodes in the cell's quadrature of the projected
    /// stress (Stages::p2g).
    std::vector<std::array<double, dim + 1>> projection_weights;
    /// Nodal stress projection with a body's `Smoothing stabilisation`
    /// alpha (empty without): sum_p N_i(x_p) alpha_p V_p tr(sigma_p) / dim
    /// (in-plane trace), the share of the points' mean stress that the
    /// projection leaves to each point's own cell.
    std::vector<double> stabilised_trace;
    /// The same, per occupied cell (by slot): sum_p alpha_p V_p tr(sigma_p)
    /// / dim over the cell's points, integrated in the cell itself.
    std::vector<double> projection_own_trace;

    /// Unilateral walls (empty without): what the walls did to the node in
    /// this step's grid update (NodalConstraints::apply), so that the remap
    /// keeps a node the walls held (NodalConstraints::apply_kinematic).
    std::vector<std::uint8_t> wall_contact;
    /// Multi-field contact (empty with one velocity field), at a node of
    /// field 0: what the contact did in this step's grid update (0 none, 1
    /// held the normal approach, 2 stuck), kept in the remap
    /// (Stages::field_contact).
    std::vector<std::uint8_t> field_contact_state;

    std::vector<unsigned int> active_nodes;
    /// active_stamp[i] == stamp: node i is in active_nodes this step.
    std::vector<std::uint8_t> active_stamp;
    std::uint8_t              stamp = 0;

  private:
    template <typename T>
    static void
    release(std::vector<T> &field)
    {
      std::vector<T>().swap(field);
    }

    /// @p field as @p n zeros, its capacity n.
    template <typename T>
    static void
    refill(std::vector<T> &field, const unsigned int n)
    {
      release(field);
      field.resize(n, T());
    }
  };
} // namespace fsgmpm

#endif
