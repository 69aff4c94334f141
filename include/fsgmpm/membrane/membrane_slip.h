#ifndef fsgmpm_membrane_membrane_slip_h
#define fsgmpm_membrane_membrane_slip_h

#include <fsgmpm/membrane/membrane.h>

#include <vector>

namespace fsgmpm
{
  /**
   * Frictionless (slip) contact between the membrane and its fill
   * (Membrane::tangential_slip): a fluid at rest carries no shear, so the
   * tension is uniform along the membrane. After every position update the
   * nodes are moved along the membrane: at degree 1 so that every cable (2D
   * closed loop) or every ring edge (3D membrane extruded along z, each
   * ring in its z plane) has the same stretch (equalize_stretch()), at
   * degree 2 until no tangential internal force is left
   * (relax_tangential_forces()). Applies to those two kinds of membrane
   * only (applies()).
   */
  namespace MembraneSlip
  {
    /// True if the slip can act on @p membrane: a 2D closed loop, or a 3D
    /// membrane with rings (Membrane::rings).
    template <int dim>
    bool
    applies(const Membrane<dim> &membrane);

    /// Moves the nodes along the membrane to equal stretch. The curve is
    /// kept: nodes are placed on circular arcs through three consecutive
    /// nodes (averaged over the two arcs of each chord; exact on circular
    /// pieces), and the mean tangential shift is zero. 3D: the nodes
    /// stacked along z first take their mean x-y position. Returns the
    /// largest shift; does nothing (returns 0) unless applies().
    template <int dim>
    double
    equalize_stretch(Membrane<dim> &membrane);

    /// The slip at any element degree (used at degree 2, where placing
    /// the nodes by chord lengths is off by O((kappa h)^2) against the
    /// quadratic cells' own stretch): moves the nodes along the membrane
    /// until the tangential components of their internal forces vanish, as
    /// a frictionless contact leaves them. Newton steps on the nodes'
    /// shifts along the loop (3D: along the first ring, the stacked nodes
    /// tied to it), with the loop's 1D bar stiffness (the cells' EA on
    /// their rest lengths, cyclic; 3D: EA H / (1 - nu^2) for the slab's
    /// height H in plane strain) as the Jacobian, solved directly with the
    /// mean shift held at zero; the nodes are placed on circular arcs as
    /// equalize_stretch() places them, and a step is taken only if it
    /// lowers MembraneFE::strain_energy() (halved up to 8 times otherwise),
    /// so the slip cannot create energy (a step whose predicted drop, r.d/2,
    /// is below 1e-12 of the energy, which its round-off cannot show, is
    /// taken whole without the test). Returns the largest move; does
    /// nothing (returns 0) unless applies(). If @p released is given, it
    /// receives the strain energy the moves removed (J per metre in 2D, J
    /// in 3D).
    template <int dim>
    double
    relax_tangential_forces(Membrane<dim>     &membrane,
                            const unsigned int newton_steps = 2,
                            double            *released     = nullptr);

    /// Per node, a bound on the stiffness that the loop's length change
    /// gives it, (EA/L) |theta_a| sum_b |theta_b| (theta: turning angle at
    /// the node, floored at the circle's pi (l_a + l_{a-1}) / L; 3D: times
    /// the node's share of the height). With slip, Membrane::
    /// node_stiffness() gives it in place of the cables' EA in x-y, which
    /// equalize_stretch() spreads. Needs applies().
    template <int dim>
    std::vector<double>
    loop_axial_stiffness(const Membrane<dim> &membrane);
  } // namespace MembraneSlip
} // namespace fsgmpm

#endif
