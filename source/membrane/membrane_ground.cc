#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/membrane/membrane_ground.h>

#include <algorithm>
#include <cmath>

namespace fsgmpm
{
  template <int dim>
  double
  MembraneGround<dim>::node_stiffness(const Membrane<dim> &membrane,
                                      const unsigned int   a) const
  {
    // 2D: per metre of depth. 3D: the same per metre of the node's width,
    // the square root of its share of the rest area (mass / areal mass), so
    // that the penetration, about the bottom pressure times the element
    // size over k, and the ground's time-step bound sqrt(m/k) are those of
    // 2D at the same element size.
    return dim == 2
             ? stiffness
             : stiffness
                 * std::sqrt(membrane.mass[a] / membrane.properties.areal_mass);
  }



  template <int dim>
  double
  MembraneGround<dim>::depth(const Membrane<dim> &membrane,
                             const unsigned int   a) const
  {
    return std::max(level - membrane.position[a][1], 0.);
  }



  template <int dim>
  void
  MembraneGround<dim>::add_forces(const Membrane<dim>         &membrane,
                                  std::vector<Tensor<1, dim>> &force) const
  {
    if (!active())
      return;
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      force[a][1] += node_stiffness(membrane, a) * depth(membrane, a);
  }



  template <int dim>
  double
  MembraneGround<dim>::energy(const Membrane<dim> &membrane) const
  {
    double w = 0;
    if (active())
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        w += 0.5 * node_stiffness(membrane, a)
             * std::pow(depth(membrane, a), 2);
    return w;
  }



  template <int dim>
  void
  MembraneGround<dim>::add_stiffness(
    const Membrane<dim>                  &membrane,
    std::vector<SymmetricTensor<2, dim>> &k) const
  {
    // The penalty on every node, also far above the ground: a bound that
    // let the time step grow while the membrane is away from it made the 2D
    // ellipse scene's energy grow (doc/geocontainer_validation.md, section
    // 8).
    if (!active())
      return;
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      k[a][1][1] += node_stiffness(membrane, a);
  }

  template struct MembraneGround<2>;
  template struct MembraneGround<3>;
} // namespace fsgmpm
