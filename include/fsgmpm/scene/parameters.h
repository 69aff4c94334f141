#ifndef fsgmpm_scene_parameters_h
#define fsgmpm_scene_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/grid/moving_wall_parameters.h>
#include <fsgmpm/grid/wall_condition.h>
#include <fsgmpm/run/dynamic_relaxation.h>
#include <fsgmpm/run/stability_guard.h>
#include <fsgmpm/run/time_step_control.h>
#include <fsgmpm/step/stress_integration.h>

#include <map>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * All run parameters that do not depend on the bodies, read from a
   * ParameterHandler and validated (including the open intervals that
   * deal.II's patterns cannot express). Every error message names the full
   * parameter path.
   */
  template <int dim>
  struct Parameters
  {
    /// Declare every parameter of fsgmpm (also those of bodies/materials).
    static void
    declare_parameters(ParameterHandler &prm);

    explicit Parameters(ParameterHandler &prm);

    // Simulation
    /// End time, Courant number, fixed time step.
    TimeStepControl::Settings time_step;
    bool                      use_musl;
    bool                      use_apic;
    /// Velocity transfer = APIC affine remap: Stages::remap keeps the
    /// grid-updated velocity at filled nodes.
    bool apic_affine_remap;
    /// Internal force of Eq. (3): at the points or from the nodal projection.
    Stages::StressIntegration stress_integration;
    /// FLIP-PIC blend: sub-cell noise decays over this time (s; 0: FLIP).
    double flip_noise_relaxation_time;
    /// The velocity the noise relaxes to: XPIC(m)'s (1: PIC's).
    unsigned int xpic_order;
    /// Coulomb friction between velocity fields (multi-field contact).
    double contact_friction;
    /// Contact acts where both fields fill this fraction of a node.
    double         contact_volume_fraction;
    Tensor<1, dim> gravity;
    double         gravity_ramp_time;
    unsigned int   n_threads;
    /// MPI: repartition when max/mean points per process exceeds this
    /// (0: never).
    double repartition_imbalance;

    // Damping of the step (local, mass scaling)
    double local_damping;
    bool   mass_scaling;
    /// Dynamic relaxation's run control: kinetic damping, Eq. (30), rest,
    /// Simulation/Termination.
    DynamicRelaxation::Settings relaxation;
    StabilityGuard::Settings    stability;

    // Grid
    std::string                                 grid_type;
    Point<dim>                                  lower_corner, upper_corner;
    std::vector<unsigned int>                   subdivisions;
    std::string                                 mesh_file;
    double                                      extrusion_thickness;
    std::map<types::boundary_id, WallCondition> walls;
    MovingWallParameters                        moving_wall;

    // Output
    std::string output_directory;
    double      output_interval;
    /// Simulated time between checkpoints (0: none).
    double       checkpoint_interval;
    unsigned int output_every_steps;
    bool         write_particles;
    bool         write_grid;
    /// "vtu" or "hdf5" (points and membrane).
    std::string output_format;
    /// "pieces" or "finite elements" (io/membrane_fe_output.h).
    std::string  membrane_output;
    unsigned int monitor_every_steps;
    bool         quiet;
  };

} // namespace fsgmpm

#endif
