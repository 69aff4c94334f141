#ifndef fsgmpm_step_mpm_step_h
#define fsgmpm_step_mpm_step_h

#include <deal.II/base/timer.h>

#include <fsgmpm/parallel/domain_partition.h>
#include <fsgmpm/step/membrane_crossing.h>
#include <fsgmpm/step/stages.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * One explicit MPM step (paper Fig. 1, Eqs. 17-21): the stages of
   * Stages, in their order, each timed by a TimerOutput::Scope, and nothing
   * else. Time-step choice, stability guards, monitors and output are run
   * control (Simulator, or a program's own loop).
   *
   * The step works on state it does not own (points, nodal fields,
   * smoothing scratch and, if attached, a membrane), so a program can look
   * at and change that state between steps. A step is
   *
   *   transfer_to_grid();              // p2g: nodal mass, momentum, forces
   *   dt = stable_time_step();         // needs the nodal masses
   *   result = advance(dt, t + dt, g); // grid update ... relocate
   *
   * and the points must be sorted by cell (ParticleStore::sort_by_cell)
   * before the first transfer_to_grid(); relocate keeps them sorted.
   */
  template <int dim>
  class MpmStep
  {
  public:
    /// The numerical settings of the step (Simulation and Contact
    /// subsections of a prm; Simulator fills them from Parameters).
    struct Settings
    {
      Stages::StressIntegration stress_integration
        = Stages::StressIntegration::points;
      /// MUSL (Eq. 20 remap before the stress update) or USL.
      bool use_musl = true;
      /// APIC only: remap the affine velocity too.
      bool apic_affine_remap = false;
      /// FLIP noise relaxation time tau (0: pure FLIP/PIC blend of g2p).
      double flip_noise_relaxation_time = 0;
      /// The velocity the noise relaxes to: XPIC(m)'s (1: PIC's).
      unsigned int xpic_order = 1;
      /// Local non-viscous damping alpha (dynamic relaxation).
      double local_damping = 0;
      double courant       = 0.5;
      /// Directional mass scaling of the membrane's nodal bound.
      bool mass_scaling = false;
      /// Two velocity fields: friction coefficient and the volume fraction
      /// above which a node is in contact.
      double contact_friction        = 0;
      double contact_volume_fraction = 0;
    };

    /// What run control needs from a step.
    struct Result
    {
      Stages::GridUpdateResult grid;
      /// Largest displacement over cell size (points and membrane nodes);
      /// not finite after a blow-up (relocate is then skipped).
      double       displacement_ratio     = 0;
      unsigned int lost_particles         = 0;
      unsigned int membrane_nodes_outside = 0;
      /// Points put back on their side of the membrane (MembraneCrossing).
      unsigned int membrane_crossings = 0;
      /// (flagged, detecting) points of the free-surface detection.
      std::pair<unsigned int, unsigned int> free_surface = {0, 0};
      /// The step's energy losses at the points this process owns
      /// (monitors.csv): plastic and viscous work; what the FLIP-PIC/XPIC
      /// blend or APIC's transfer and the free-surface reset removed; the
      /// kinetic and stored energy of the points that left the mesh.
      CompensatedSum material_dissipation, numerical_dissipation,
        outflow_energy;
    };

    MpmStep(const BackgroundGrid<dim>                    &grid,
            NodalConstraints<dim>                        &constraints,
            const std::vector<std::unique_ptr<Material>> &materials,
            const std::vector<MaterialOptions>           &material_options,
            const Settings                               &settings,
            ParticleStore<dim>                           &particles,
            NodalFields<dim>                             &nodes,
            SmoothingFields<dim>                         &smoothing);

    /// Couple a membrane (FEM-MPM, Eqs. 19-21) through a MembraneCoupling
    /// that the step owns; cables longer than @p split_length are split
    /// when they stretch (0: never). If @p impermeable_to_points, no point
    /// passes through it (MembraneCrossing).
    void
    attach_membrane(Membrane<dim> &membrane,
                    const double   split_length,
                    const bool     impermeable_to_points = true);

    /**
     * MPI: the partition whose ghost-layer rim nodes are refreshed after
     * every stage whose nodal values the points read back (so that ghost
     * points evolve as their originals), and whose counted nodes make the
     * grid update's sums local to this process. Call after
     * attach_membrane(); the membrane's coupling uses it too.
     */
    void
    attach_partition(const DomainPartition<dim> &partition)
    {
      this->partition = &partition;
      if (membrane_coupling)
        membrane_coupling->attach_partition(partition);
    }

    /**
     * MPI: refresh the rim values of the free-surface volume fraction (the
     * synchronise hook of Stages::detect_free_surface); nothing in serial.
     */
    void
    synchronise_free_surface();

    /**
     * MPI: refresh the rim values of the nodal stress projection after
     * Stages::p2g's pass @p pass (its synchronise hook); nothing in serial.
     */
    void
    synchronise_projection(const unsigned int pass);

    /// Per material, the share of a point's mean stress and volumetric rate
    /// that the nodal projection leaves to the point's own cell (each
    /// body's `Smoothing stabilisation`; Stages::p2g).
    const std::vector<double> &
    projection_stabilisation() const
    {
      return stabilisation;
    }

    /// The coupling of the attached membrane (its transfer weights; for a
    /// checkpoint, or to run its stages in a program's own order); null
    /// without a membrane.
    MembraneCoupling<dim> *
    get_membrane_coupling()
    {
      return membrane_coupling.get();
    }
    const MembraneCoupling<dim> *
    get_membrane_coupling() const
    {
      return membrane_coupling.get();
    }

    /// Stage 1 (Eqs. 3, 4, 17): points and membrane to the grid. Does not
    /// depend on dt.
    void
    transfer_to_grid();

    /// The explicit bound on dt after transfer_to_grid(), Courant number
    /// and local damping included: the points' cell bound and, with a
    /// membrane, the nodal bound where it touches the grid.
    double
    stable_time_step();

    /// The stages after p2g with step @p dt: grid update, g2p, remap, NMD,
    /// stress update, free surface, ANP, positions, relocate. Walls with
    /// prescribed motion act at @p new_time = t + dt.
    Result
    advance(const double          dt,
            const double          new_time,
            const Tensor<1, dim> &gravity);

    /// Names of the timed stages, in the order they run; "membrane" last
    /// collects the membrane's part of every stage (its transfers, time-step
    /// bound, position update, slip, splits and element forces).
    static const std::vector<std::string> &
    stage_names();

    /// Wall seconds spent in each stage so far, in stage_names() order.
    std::vector<double>
    stage_seconds() const;

    /// The timer itself (print_summary() gives deal.II's table).
    const TimerOutput &
    get_timer() const
    {
      return timer;
    }

  private:
    const BackgroundGrid<dim>                    &grid;
    NodalConstraints<dim>                        &constraints;
    const std::vector<std::unique_ptr<Material>> &materials;
    const std::vector<MaterialOptions>           &material_options;
    /// Each material's smoothing stabilisation (projection_stabilisation()),
    /// read once from material_options.
    std::vector<double>   stabilisation;
    const Settings        settings;
    ParticleStore<dim>   &particles;
    NodalFields<dim>     &nodes;
    SmoothingFields<dim> &smoothing;
    /// The attached membrane's coupling, if any.
    std::unique_ptr<MembraneCoupling<dim>> membrane_coupling;
    std::unique_ptr<MembraneCrossing<dim>> membrane_crossing;
    const DomainPartition<dim>            *partition = nullptr;

    /// MPI: refresh the rim values of the nodal numerators and
    /// denominators of the materials for which @p uses is true.
    template <typename Predicate>
    void
    synchronise_smoothing(const Predicate &uses);
    /// XPIC's nodal scratch (xpic_order >= 2).
    Stages::XpicFields<dim> xpic;
    /// Per cell sum_p V_p M_p for the membrane's nodal time-step bound.
    std::vector<double> cell_stiffness;

    /// The timer's report goes nowhere: stage_seconds() and the summary
    /// are the outputs.
    std::ostringstream timer_stream;
    TimerOutput        timer;
  };
} // namespace fsgmpm

#endif
