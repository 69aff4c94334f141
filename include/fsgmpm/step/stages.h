#ifndef fsgmpm_step_stages_h
#define fsgmpm_step_stages_h

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/materials/material.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/step/material_options.h>
#include <fsgmpm/step/membrane_coupling.h>
#include <fsgmpm/step/smoothing_fields.h>
#include <fsgmpm/step/stress_integration.h>

#include <functional>
#include <memory>
#include <vector>

namespace fsgmpm
{
  /**
   * The explicit MPM step as a fixed sequence of named stages (paper Fig. 1,
   * Eqs. 17-21). A stage knows nothing about the scene; MpmStep
   * (step/mpm_step.h) calls
   *
   *   MUSL (default):  p2g (-> contact_normals) -> grid_update
   *                    (-> field_contact) -> g2p -> remap (-> field_contact)
   *                    -> velocity_gradients (-> store_affine_velocity,
   *                    APIC only) -> nmd -> stress_update
   *                    -> detect_free_surface
   *                    -> average_nodal_pressure -> update_positions
   *                    -> relocate
   *   USL:             the same without remap
   *   (field_contact and contact_normals act only with two velocity fields)
   *
   * A membrane takes part through its MembraneCoupling
   * (step/membrane_coupling.h), whose stages follow p2g, grid_update
   * (g2p), remap (inside it), update_positions and relocate.
   *
   * Particles must be sorted by cell (ParticleStore::sort_by_cell) before
   * p2g. Scatters run in parallel over the cells of one colour, so they are
   * race free and their result does not depend on the number of threads.
   */
  namespace Stages
  {
    /// Stage 1 (Eqs. 3, 4, 17): lumped mass, momentum, internal force; the
    /// nodes of occupied cells become the active nodes. With APIC the
    /// momentum carries the affine part: m_p (v_p + C_p (x_i - x_p)).
    /// With the nodal projection, @p synchronise (MPI: the rim nodes'
    /// values) runs after the points' sums (pass 1: volume_stress,
    /// lumped_volume, occupied_volume) and after the quadrature weights'
    /// sums (pass 2: support_volume), before the integration.
    /// @p stabilisation, per material (empty: none), is the share alpha of
    /// each point's mean stress that the projection leaves to the point's
    /// own cell (MaterialOptions::smoothing_stabilisation; the strain rate
    /// of stress_update() keeps the same share of the cell's own volumetric
    /// rate, so the points' stress power stays the nodal forces' power).
    template <int dim>
    void
    p2g(const BackgroundGrid<dim> &grid,
        const ParticleStore<dim>  &particles,
        NodalFields<dim>          &nodes,
        const StressIntegration    integration = StressIntegration::points,
        const std::function<void(unsigned int)> &synchronise   = {},
        const std::vector<double>               &stabilisation = {});

    /// The stress field that p2g's nodal projection integrates, at the
    /// point of barycentric coordinates @p lambda in cell @p c:
    /// sum_k lambda_k s_k with s_k = volume_stress_k / support_volume_k
    /// (in-plane components in 2D). Returns false, leaving @p stress alone,
    /// where a node of the cell has no support (the last p2g did not project
    /// there, or integrated at the points).
    template <int dim>
    inline bool
    projected_stress(const BackgroundGrid<dim>         &grid,
                     const NodalFields<dim>            &nodes,
                     const unsigned int                 c,
                     const std::array<double, dim + 1> &lambda,
                     Tensor<2, dim>                    &stress)
    {
      if (nodes.support_volume.empty())
        return false;
      Tensor<2, dim> s;
      for (unsigned int k = 0; k < dim + 1; ++k)
        {
          const unsigned int n = grid.cell_nodes[c][k];
          if (!(nodes.support_volume[n] > 0))
            return false;
          s += (lambda[k] / nodes.support_volume[n]) * nodes.volume_stress[n];
        }
      stress = s;
      return true;
    }

    /// What grid_update reports for energy bookkeeping and Eq. (30).
    struct GridUpdateResult
    {
      // Sums over the nodes, compensated so that a sum over the processes
      // (sum_over_processes()) equals the serial one to a rounding.
      CompensatedSum external_work_increment; ///< dt * F_ext . v_mid
      CompensatedSum damping_work_increment;  ///< energy removed by damping
      CompensatedSum unbalanced_norm_sq;      ///< |F_ext - F_int|^2, free comps
      CompensatedSum external_norm_sq;        ///< |F_ext|^2, free components
    };

    /// Stage 2 (Eq. 18): a = (F_ext - F_int + F_damp)/m with gravity in
    /// F_ext, local non-viscous damping F_damp = -alpha |F_unbal| sign(v),
    /// wall conditions on v^{n+1} = v^n + dt a, and a consistent with them.
    /// With @p counted_nodes (MPI), the result sums only the nodes marked
    /// 1 there, so that the sums over all processes count each node once.
    /// The damping work is booked at every node as dt F_damp . v^n (a loss
    /// at each node). With two velocity fields (@p grid given), where the
    /// fields meet (both have mass, and the points fill
    /// @p contact_volume_fraction of the node's volume, as field_contact()
    /// asks), the damping reads the node's mass share of both fields'
    /// unbalanced force, in which the contact reaction cancels: each
    /// field's own is not zero at rest there (the weight the other body
    /// carries), and damping by it kept two bodies resting on each other
    /// chattering.
    template <int dim>
    GridUpdateResult
    grid_update(const NodalConstraints<dim>     &constraints,
                const Tensor<1, dim>            &gravity,
                const double                     damping_alpha,
                const double                     dt,
                NodalFields<dim>                &nodes,
                const std::vector<std::uint8_t> *counted_nodes = nullptr,
                const BackgroundGrid<dim>       *grid          = nullptr,
                const double                     contact_volume_fraction = 0);

    /// Multi-field contact, part 1 (once per step, after p2g and
    /// MembraneCoupling::p2g): at every node of field 0 the contact normal,
    /// field 0's outward normal from its smoothed nodal mass
    /// (NodalFields::contact_normal), and the volume of the points of both
    /// fields (NodalFields::contact_volume). Nothing to do with one field.
    template <int dim>
    void
    contact_normals(const BackgroundGrid<dim> &grid,
                    const ParticleStore<dim>  &particles,
                    NodalFields<dim>          &nodes);

    /// True where the two velocity fields meet at base node @p i: both
    /// have mass, field 0 has an outward normal there, and the points of
    /// both fill @p volume_fraction of the node's volume (a node that both
    /// fields merely reach, a gap of up to a cell, would stop the bodies
    /// early). field_contact() acts there, and grid_update()'s damping
    /// reads both fields' force there.
    template <int dim>
    inline bool
    fields_meet(const BackgroundGrid<dim> &grid,
                const NodalFields<dim>    &nodes,
                const unsigned int         i,
                const double               volume_fraction)
    {
      return nodes.mass[i] > 0 && nodes.mass[i + grid.n_base_nodes()] > 0
             && nodes.contact_normal[i].norm_square() > 0
             && nodes.contact_volume[i]
                  >= volume_fraction * grid.node_volume[i];
    }

    /// Multi-field contact, part 2 (after grid_update and after remap;
    /// Bardenhagen et al. 2000, 2001): at a node where both fields have
    /// mass, the points fill at least @p volume_fraction of the node's
    /// volume, and the fields approach, (v_0 - v_cm) . n > 0, their normal
    /// velocities become the centre of mass's and their tangential relative
    /// velocity is reduced by Coulomb friction @p friction (stick if that
    /// stops it); separating fields are left alone. Momentum is conserved
    /// (the walls act again after). With @p update_acceleration the nodal
    /// accelerations follow the velocity change (FLIP's Eq. 19), and if
    /// @p unbalanced_norm_sq is given (grid_update()'s sum for Eq. 30), the
    /// contact reaction m dv/dt joins each field's unbalanced force
    /// m g - f_int there (the free components; on the nodes of
    /// @p counted_nodes if given): two bodies resting on each other are in
    /// equilibrium only with it.
    template <int dim>
    void
    field_contact(const BackgroundGrid<dim>       &grid,
                  const NodalConstraints<dim>     &constraints,
                  const double                     friction,
                  const double                     volume_fraction,
                  const double                     dt,
                  const bool                       update_acceleration,
                  NodalFields<dim>                &nodes,
                  const Tensor<1, dim>            &gravity = Tensor<1, dim>(),
                  CompensatedSum                  *unbalanced_norm_sq = nullptr,
                  const std::vector<std::uint8_t> *counted_nodes = nullptr);

    /// XPIC(m)'s scratch (xpic_correction()): nodal vectors sized to the
    /// grid's nodes when first used.
    template <int dim>
    struct XpicFields
    {
      /// v* - v^n, the correction g2p adds to the grid velocity.
      std::vector<Tensor<1, dim>> correction;
      std::vector<Tensor<1, dim>> previous, next;
      std::vector<double>         point_mass;
    };

    /// Stage 3a, FLIP's noise relaxation with XPIC(m) (Hammerquist and Nairn
    /// 2017), @p order m >= 2: after the grid update, the nodal correction
    /// v* - v^n of the velocity the points relax to, S (v^L - v^n + v*),
    /// where v* = sum_{k=1}^m (-1)^(k+1) C(m, k) A^(k-1) v^n and A is the
    /// mass-weighted round trip grid -> points -> grid. PIC (m = 1) damps a
    /// grid-resolved mode by 1 - a per relaxation (a = A's eigenvalue,
    /// about 1 - (kh)^2 / 6), XPIC(m) by (1 - a)^m; both drop the sub-cell
    /// noise. @p synchronise (MPI) refreshes a nodal vector's rim values.
    template <int dim>
    void
    xpic_correction(
      const BackgroundGrid<dim>                                &grid,
      const ParticleStore<dim>                                 &particles,
      const NodalConstraints<dim>                              &constraints,
      const NodalFields<dim>                                   &nodes,
      const unsigned int                                        order,
      XpicFields<dim>                                          &xpic,
      const std::function<void(std::vector<Tensor<1, dim>> &)> &synchronise
      = {});

    /// Stage 3 (Eq. 19): FLIP v_p += dt sum_i N_i(x_p) a_i, then blended
    /// with the fraction @p pic_fraction of PIC's v_p = sum_i N_i(x_p) v_i
    /// (0: pure FLIP), or of XPIC's sum_i N_i(x_p) (v_i + c_i) with the
    /// nodal @p xpic_correction c if given; or, if the points carry an
    /// affine velocity, APIC: v_p = sum_i N_i(x_p) v_i. With @p removed,
    /// the kinetic energy that the blend or APIC's transfer takes from the
    /// owned points, against FLIP's v_p + dt a(x_p), is added to it. (FLIP's
    /// own interpolation of the nodal increments is not booked: its grid
    /// side, sum_i m_i |dt a_i|^2 / 2, is dominated by nearly empty nodes
    /// whose velocities the points never take.)
    template <int dim>
    void
    g2p(const BackgroundGrid<dim>         &grid,
        const NodalFields<dim>            &nodes,
        const double                       dt,
        ParticleStore<dim>                &particles,
        const double                       pic_fraction    = 0,
        const std::vector<Tensor<1, dim>> *xpic_correction = nullptr,
        CompensatedSum                    *removed         = nullptr);

    /// Stage 4 (Eq. 20): nodal velocities from the updated particle (and
    /// membrane-node) momenta, with the kinematic wall conditions
    /// (NodalConstraints::apply_kinematic: no penetration, no second
    /// friction impulse); suppresses the small-mass-node instability. The
    /// membrane nodes' momenta come from @p membrane (its coupling,
    /// MembraneCoupling::remap), if given. With
    /// @p affine (APIC affine remap) the remap carries APIC's affine term,
    /// i.e. keeps the grid-updated velocity, at nodes whose points fill a
    /// quarter of their volume or more, blended to the mass average below.
    template <int dim>
    void
    remap(const BackgroundGrid<dim>   &grid,
          const ParticleStore<dim>    &particles,
          const NodalConstraints<dim> &constraints,
          NodalFields<dim>            &nodes,
          const MembraneCoupling<dim> *membrane = nullptr,
          const bool                   affine   = false);

    /// Stage 5a: the velocity gradient of every occupied cell (constant on
    /// linear simplices), from the (remapped) nodal velocities.
    template <int dim>
    void
    velocity_gradients(const BackgroundGrid<dim> &grid,
                       const NodalFields<dim>    &nodes,
                       SmoothingFields<dim>      &smoothing,
                       const ParticleStore<dim>  &particles);

    /// Stage 5a (Stress integration = nodal projection only): the nodal
    /// average of the cells' velocity gradients with the weights of p2g's
    /// projection, Lbar_j = sum_c q_jc L_c / sum_c q_jc over the occupied
    /// cells (NodalFields::projection_weights, support_volume): the strain
    /// rate that is work-conjugate to the projected internal force, so the
    /// stress power of the points equals the power of the nodal forces.
    template <int dim>
    void
    nodal_velocity_gradients(const BackgroundGrid<dim> &grid,
                             const NodalFields<dim>    &nodes,
                             SmoothingFields<dim>      &smoothing,
                             const ParticleStore<dim>  &particles);

    /// With the nodal stress projection, the velocity gradient of a point
    /// at barycentric coordinates @p lambda in cell @p c: sum_k lambda_k
    /// Lbar_k, which is L at every point where the nodal velocities are
    /// v = L x (a weighted average of the cells' L at each node). Then
    /// sum_p V_p sigma_p : L_p is the power of p2g's internal forces exactly
    /// (test stress_integration).
    template <int dim>
    inline Tensor<2, dim>
    point_velocity_gradient(const BackgroundGrid<dim>         &grid,
                            const SmoothingFields<dim>        &smoothing,
                            const unsigned int                 c,
                            const std::array<double, dim + 1> &lambda)
    {
      Tensor<2, dim> L;
      for (unsigned int k = 0; k < dim + 1; ++k)
        L += lambda[k]
             * smoothing.nodal_velocity_gradient[grid.cell_nodes[c][k]];
      return L;
    }

    /// point_velocity_gradient() with a body's smoothing stabilisation
    /// @p alpha: its volumetric part moved by the share alpha toward the
    /// cell's own, L + alpha (tr(L_c) - tr(L)) / dim I, the rate that is
    /// work-conjugate to p2g's projected force when p2g leaves the same
    /// share of the point's mean stress to its cell (@p stabilisation).
    template <int dim>
    inline Tensor<2, dim>
    stabilised_point_velocity_gradient(
      const BackgroundGrid<dim>         &grid,
      const SmoothingFields<dim>        &smoothing,
      const unsigned int                 c,
      const std::array<double, dim + 1> &lambda,
      const double                       alpha)
    {
      Tensor<2, dim> L = point_velocity_gradient(grid, smoothing, c, lambda);
      if (alpha > 0)
        {
          const double correction
            = alpha * (trace(smoothing.cell_velocity_gradient(c)) - trace(L))
              / dim;
          for (unsigned int d = 0; d < dim; ++d)
            L[d][d] += correction;
        }
      return L;
    }

    /// Stage 5a' (APIC only): the affine velocity C_p of every point is the
    /// velocity gradient of its cell, which on a linear simplex equals
    /// APIC's B_p D_p^-1 exactly. It is taken from the remapped velocities
    /// (MUSL), not from the grid update, whose nearly empty nodes can carry
    /// large velocities that a gradient, unlike an interpolation, would
    /// pass on with full weight.
    template <int dim>
    void
    store_affine_velocity(const SmoothingFields<dim> &smoothing,
                          ParticleStore<dim>         &particles);

    /// Stage 5b, NMD (Eq. 24): nodal volumetric strain rates, averaged over
    /// the attached non-empty cells with the volumes of each material's
    /// points as weights, for the materials that use NMD.
    template <int dim>
    void
    nmd(const BackgroundGrid<dim>          &grid,
        const NodalFields<dim>             &nodes,
        const std::vector<MaterialOptions> &options,
        SmoothingFields<dim>               &smoothing,
        const ParticleStore<dim>           &particles);

    /// Stage 5c: per point, strain rate and spin with the NMD correction of
    /// Eq. (25) (cell-centre mean of the nodal rates), the volume update
    /// V <- V exp(dt tr d) with the same rate (limited by the material's
    /// admissible volume ratio), and the stress update per material. The
    /// velocity gradient is the cell's, or, with @p integration =
    /// nodal_projection, sum_j N_j(x_p) Lbar_j of nodal_velocity_gradients.
    /// With @p dissipation, the plastic and viscous work of the owned points
    /// (Material::dissipated_energy()) is added to it.
    template <int dim>
    void
    stress_update(const BackgroundGrid<dim>                    &grid,
                  const std::vector<std::unique_ptr<Material>> &materials,
                  const std::vector<MaterialOptions>           &options,
                  const double                                  dt,
                  SmoothingFields<dim>                         &smoothing,
                  ParticleStore<dim>                           &particles,
                  const StressIntegration                       integration
                  = StressIntegration::points,
                  CompensatedSum *dissipation = nullptr);

    /// Stage 5d (paper Section 4, volume-fraction form): flag the points of
    /// detecting materials whose interpolated nodal volume fraction is at
    /// most f_c; flagged points get zero pressure and their reference
    /// volume. Returns the numbers of flagged and of detecting points. With
    /// @p materials and @p reset_energy, the stored energy that the reset of
    /// the flagged owned points' volumes removes is added to it.
    template <int dim>
    std::pair<unsigned int, unsigned int>
    detect_free_surface(const BackgroundGrid<dim>          &grid,
                        const NodalFields<dim>             &nodes,
                        const std::vector<MaterialOptions> &options,
                        SmoothingFields<dim>               &smoothing,
                        ParticleStore<dim>                 &particles,
                        const std::function<void()>        &synchronise = {},
                        const std::vector<std::unique_ptr<Material>> *materials
                        = nullptr,
                        CompensatedSum *reset_energy = nullptr);

    /// Stage 5e, ANP (Eqs. 28-29): nodal volume-weighted average of the
    /// pressure of the non-flagged points per material, mapped back as the
    /// element mean (paper) or interpolated.
    template <int dim>
    void
    average_nodal_pressure(const BackgroundGrid<dim>          &grid,
                           const NodalFields<dim>             &nodes,
                           const std::vector<MaterialOptions> &options,
                           SmoothingFields<dim>               &smoothing,
                           ParticleStore<dim>                 &particles,
                           const std::function<void()> &synchronise = {});

    /// Stage 6 (Eq. 21): x_p += dt sum_i N_i(x_p) v_i. Returns the largest
    /// ratio of a point's displacement to its cell's smallest altitude
    /// (> 1 means a point crossed more than one cell: unstable).
    template <int dim>
    double
    update_positions(const BackgroundGrid<dim> &grid,
                     const NodalFields<dim>    &nodes,
                     const double               dt,
                     ParticleStore<dim>        &particles);

    /// Stage 7: locate every point again (walk from its old cell), remove
    /// points that left the mesh and sort by cell. Returns the number lost.
    /// With @p materials and @p outflow_energy, the kinetic and stored
    /// energy of the lost points is added to it.
    template <int dim>
    unsigned int
    relocate(const BackgroundGrid<dim>                    &grid,
             ParticleStore<dim>                           &particles,
             const std::vector<std::unique_ptr<Material>> *materials = nullptr,
             CompensatedSum *outflow_energy                          = nullptr);

    /// Stable time step C * min over points of h / (c_p + |v_p| + 2 d nu/h)
    /// (wave speed, particle speed, and the explicit viscous limit;
    /// source/step/time_step.cc). If @p cell_stiffness is given, it is set
    /// to sum_p V_p rho_p s_p^2 per cell (s_p the same signal speed; zero in
    /// empty cells), the points' share of the nodal bound of
    /// MembraneCoupling::time_step().
    template <int dim>
    double
    stable_time_step(const BackgroundGrid<dim>                    &grid,
                     const ParticleStore<dim>                     &particles,
                     const std::vector<std::unique_ptr<Material>> &materials,
                     const double                                  courant,
                     std::vector<double> *cell_stiffness = nullptr);
  } // namespace Stages
} // namespace fsgmpm

#endif
