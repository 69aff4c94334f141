#ifndef fsgmpm_membrane_membrane_ground_h
#define fsgmpm_membrane_membrane_ground_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <limits>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  template <int dim>
  class Membrane;

  /**
   * Rigid frictionless ground y = level acting on the membrane nodes
   * themselves: a normal penalty force on the nodes below it, so that the
   * membrane can rest on the ground exactly instead of one cell early as
   * with a wall of the grid. Held by Membrane (Membrane::ground), whose
   * compute_forces() and node_stiffness() add its force and stiffness.
   * Off while the level is not finite.
   */
  template <int dim>
  struct MembraneGround
  {
    double level     = -std::numeric_limits<double>::infinity();
    double stiffness = 0; ///< penalty per metre (N/m^2)

    bool
    active() const
    {
      return std::isfinite(level);
    }

    /// The penalty of node a (N/m): stiffness in 2D (per metre of depth),
    /// stiffness times the node's width in 3D.
    double
    node_stiffness(const Membrane<dim> &membrane, const unsigned int a) const;

    /// How far node a is below the ground (0 above it).
    double
    depth(const Membrane<dim> &membrane, const unsigned int a) const;

    /// Adds the penalty force k_a (level - y_a) along y to the nodes below
    /// the ground (no tangential force).
    void
    add_forces(const Membrane<dim>         &membrane,
               std::vector<Tensor<1, dim>> &force) const;

    /// The penalty's stored energy, sum of k_a (level - y_a)^2 / 2 over the
    /// nodes below the ground (a spring: in the energy balance's strain
    /// energy).
    double
    energy(const Membrane<dim> &membrane) const;

    /// Adds node_stiffness() along y to every node, also far above the
    /// ground (for the nodal time-step bound, Membrane::node_stiffness()).
    void
    add_stiffness(const Membrane<dim>                  &membrane,
                  std::vector<SymmetricTensor<2, dim>> &k) const;
  };
} // namespace fsgmpm

#endif
