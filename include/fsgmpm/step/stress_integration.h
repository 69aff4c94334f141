#ifndef fsgmpm_step_stress_integration_h
#define fsgmpm_step_stress_integration_h

namespace fsgmpm
{
  namespace Stages
  {
    /// How p2g integrates the internal force of Eq. (3).
    enum class StressIntegration
    {
      /// At the points (paper Eq. 3): F_i = sum_p V_p sigma_p grad N_i(x_p).
      /// A point that crosses an edge moves its V_p sigma_p to another
      /// cell's gradients at once: its nodal forces jump by V_p sigma_p
      /// |grad N|.
      points,
      /// Over the occupied cells, from the stress projected to the nodes
      /// (double mapping in the spirit of DDMP, Zhang et al. 2011): nodal
      /// s_j = sum_p N_j(x_p) V_p sigma_p / V_j with V_j the node's share
      /// of the occupied cells' volume, then F_i = sum_c grad N_i^c
      /// int_c sum_j N_j s_j dV. The forces depend on the points only
      /// through N_j(x_p), continuous across edges, so a point crossing an
      /// edge between occupied cells moves them continuously.
      nodal_projection
    };
  } // namespace Stages
} // namespace fsgmpm

#endif
