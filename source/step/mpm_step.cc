#include <fsgmpm/parallel/distributed_points.h>
#include <fsgmpm/step/mpm_step.h>

#include <cmath>

namespace fsgmpm
{
  template <int dim>
  MpmStep<dim>::MpmStep(const BackgroundGrid<dim> &grid,
                        NodalConstraints<dim>     &constraints,
                        const std::vector<std::unique_ptr<Material>> &materials,
                        const std::vector<MaterialOptions> &material_options,
                        const Settings                     &settings,
                        ParticleStore<dim>                 &particles,
                        NodalFields<dim>                   &nodes,
                        SmoothingFields<dim>               &smoothing)
    : grid(grid)
    , constraints(constraints)
    , materials(materials)
    , material_options(material_options)
    , settings(settings)
    , particles(particles)
    , nodes(nodes)
    , smoothing(smoothing)
    , timer(timer_stream, TimerOutput::never, TimerOutput::wall_times)
  {
    for (const auto &o : material_options)
      stabilisation.push_back(o.smoothing_stabilisation);
  }



  template <int dim>
  void
  MpmStep<dim>::attach_membrane(Membrane<dim> &m,
                                const double   split_length,
                                const bool     impermeable_to_points)
  {
    membrane_coupling
      = std::make_unique<MembraneCoupling<dim>>(grid, m, split_length);
    if (impermeable_to_points)
      membrane_crossing = std::make_unique<MembraneCrossing<dim>>(m);
    if (partition != nullptr)
      membrane_coupling->attach_partition(*partition);
  }



  template <int dim>
  void
  MpmStep<dim>::synchronise_free_surface()
  {
    if (partition != nullptr)
      partition->update_ghost_nodes(smoothing.volume_fraction,
                                    nodes.active_stamp,
                                    nodes.stamp);
  }



  template <int dim>
  void
  MpmStep<dim>::synchronise_projection(const unsigned int pass)
  {
    if (partition == nullptr)
      return;
    const auto update = [&](auto &values) {
      partition->update_ghost_nodes(values, nodes.active_stamp, nodes.stamp);
    };
    if (pass == 1)
      {
        update(nodes.volume_stress);
        update(nodes.lumped_volume);
        update(nodes.occupied_volume);
        if (!nodes.stabilised_trace.empty())
          update(nodes.stabilised_trace);
      }
    else
      update(nodes.support_volume);
  }



  template <int dim>
  template <typename Predicate>
  void
  MpmStep<dim>::synchronise_smoothing(const Predicate &uses)
  {
    if (partition == nullptr)
      return;
    for (unsigned int m = 0; m < material_options.size(); ++m)
      if (uses(material_options[m]))
        {
          partition->update_ghost_nodes(smoothing.numerator[m],
                                        nodes.active_stamp,
                                        nodes.stamp);
          partition->update_ghost_nodes(smoothing.denominator[m],
                                        nodes.active_stamp,
                                        nodes.stamp);
        }
  }



  template <int dim>
  const std::vector<std::string> &
  MpmStep<dim>::stage_names()
  {
    static const std::vector<std::string> names = {"p2g",
                                                   "time_step",
                                                   "grid_update",
                                                   "g2p",
                                                   "remap",
                                                   "velocity_gradient_nmd",
                                                   "affine_velocity",
                                                   "stress_update",
                                                   "free_surface",
                                                   "anp",
                                                   "position_update",
                                                   "relocate",
                                                   "membrane"};
    return names;
  }



  template <int dim>
  std::vector<double>
  MpmStep<dim>::stage_seconds() const
  {
    const auto seconds = timer.get_summary_data(TimerOutput::total_wall_time);
    std::vector<double> result;
    for (const std::string &name : stage_names())
      {
        const auto it = seconds.find(name);
        result.push_back(it == seconds.end() ? 0. : it->second);
      }
    return result;
  }



  template <int dim>
  void
  MpmStep<dim>::transfer_to_grid()
  {
    {
      TimerOutput::Scope scope(timer, "p2g");
      // 3D: the occupied cells' geometry once for the whole step, which
      // starts here (then the time step, the step's stages); in p2g's time.
      particles.cache_cell_geometry(grid);
      Stages::p2g(
        grid,
        particles,
        nodes,
        settings.stress_integration,
        [this](const unsigned int pass) { synchronise_projection(pass); },
        projection_stabilisation());
    }
    if (membrane_coupling)
      {
        TimerOutput::Scope scope(timer, "membrane");
        membrane_coupling->p2g(nodes);
      }
    TimerOutput::Scope scope(timer, "p2g");
    // The contact normal at a node takes field 0's mass gradient in every
    // cell around it, so it reads the nodal masses one ring further out:
    // exact on the rim only after the refresh.
    if (partition != nullptr && grid.n_velocity_fields() > 1)
      partition->update_ghost_nodes(nodes.mass,
                                    nodes.active_stamp,
                                    nodes.stamp);
    Stages::contact_normals(grid, particles, nodes);
  }



  template <int dim>
  double
  MpmStep<dim>::stable_time_step()
  {
    double dt;
    {
      TimerOutput::Scope scope(timer, "time_step");
      dt = Stages::stable_time_step(grid,
                                    particles,
                                    materials,
                                    settings.courant,
                                    membrane_coupling ? &cell_stiffness
                                                      : nullptr);
    }
    if (membrane_coupling)
      {
        TimerOutput::Scope scope(timer, "membrane");
        // The points' bound over all processes: mass scaling's floor below
        // must be the serial one.
        if (partition != nullptr)
          dt = Utilities::MPI::min(dt, partition->get_communicator());
        // The nodes the membrane touches: the nodal bound with the
        // membrane's and the points' stiffness (which holds the points'
        // share there, so the smaller of the two bounds governs).
        const double dt_m
          = settings.courant
            * membrane_coupling->time_step(cell_stiffness,
                                           particles.occupied_cells,
                                           nodes,
                                           settings.mass_scaling
                                             ? dt / settings.courant
                                             : 0.);
        dt = std::min(dt, dt_m);
      }
    // Local damping -alpha |F| sign(v) stiffens every node by up to
    // (1 + alpha) while it moves away from equilibrium, so the central
    // difference limit 2 sqrt(m/k) drops to 2 sqrt(m/((1 + alpha) k))
    // (exact for one degree of freedom; doc/stability.md).
    return dt / std::sqrt(1. + settings.local_damping);
  }



  template <int dim>
  typename MpmStep<dim>::Result
  MpmStep<dim>::advance(const double          dt,
                        const double          new_time,
                        const Tensor<1, dim> &gravity)
  {
    Result result;
    // Walls with prescribed motion act on v^{n+1}.
    constraints.set_time(new_time);
    {
      TimerOutput::Scope scope(timer, "grid_update");
      result.grid
        = Stages::grid_update(constraints,
                              gravity,
                              settings.local_damping,
                              dt,
                              nodes,
                              partition ? &partition->counted_nodes() : nullptr,
                              &grid,
                              settings.contact_volume_fraction);
      // The contact's dissipation is not booked as damping work: the nodal
      // kinetic energy it removes is not the points' (FLIP), and Eq. (30)'s
      // guard only objects to energy gained. Its reaction joins Eq. (30)'s
      // unbalanced force.
      Stages::field_contact(grid,
                            constraints,
                            settings.contact_friction,
                            settings.contact_volume_fraction,
                            dt,
                            true,
                            nodes,
                            gravity,
                            &result.grid.unbalanced_norm_sq,
                            partition ? &partition->counted_nodes() : nullptr);
      if (partition != nullptr)
        {
          partition->update_ghost_nodes(nodes.velocity,
                                        nodes.active_stamp,
                                        nodes.stamp);
          partition->update_ghost_nodes(nodes.acceleration,
                                        nodes.active_stamp,
                                        nodes.stamp);
        }
    }
    {
      TimerOutput::Scope scope(timer, "g2p");
      const double       tau  = settings.flip_noise_relaxation_time;
      const bool         xpic = tau > 0 && settings.xpic_order > 1
                        && !particles.has_affine_velocity();
      if (xpic)
        Stages::xpic_correction<dim>(
          grid,
          particles,
          constraints,
          nodes,
          settings.xpic_order,
          this->xpic,
          partition == nullptr
            ? std::function<void(std::vector<Tensor<1, dim>> &)>()
            : [this](std::vector<Tensor<1, dim>> &values) {
                partition->update_ghost_nodes(values,
                                              nodes.active_stamp,
                                              nodes.stamp);
              });
      Stages::g2p(grid,
                  nodes,
                  dt,
                  particles,
                  tau > 0 ? -std::expm1(-dt / tau) : 0.,
                  xpic ? &this->xpic.correction : nullptr,
                  &result.numerical_dissipation);
    }
    if (membrane_coupling)
      {
        TimerOutput::Scope scope(timer, "membrane");
        membrane_coupling->g2p(nodes);
      }
    if (settings.use_musl)
      {
        // Eq. (20): nodal velocities again from the updated points.
        TimerOutput::Scope scope(timer, "remap");
        Stages::remap(grid,
                      particles,
                      constraints,
                      nodes,
                      membrane_coupling.get(),
                      settings.apic_affine_remap);
        Stages::field_contact(grid,
                              constraints,
                              settings.contact_friction,
                              settings.contact_volume_fraction,
                              dt,
                              false,
                              nodes);
        if (partition != nullptr)
          partition->update_ghost_nodes(nodes.velocity,
                                        nodes.active_stamp,
                                        nodes.stamp);
      }
    {
      TimerOutput::Scope scope(timer, "velocity_gradient_nmd");
      Stages::velocity_gradients(grid, nodes, smoothing, particles);
      if (settings.stress_integration
          == Stages::StressIntegration::nodal_projection)
        {
          Stages::nodal_velocity_gradients(grid, nodes, smoothing, particles);
          if (partition != nullptr)
            partition->update_ghost_nodes(smoothing.nodal_velocity_gradient,
                                          nodes.active_stamp,
                                          nodes.stamp);
        }
      Stages::nmd(grid, nodes, material_options, smoothing, particles);
      synchronise_smoothing([](const MaterialOptions &o) { return o.nmd; });
      // The stress update reads the averages: each node's divided once.
      for (unsigned int m = 0; m < material_options.size(); ++m)
        if (material_options[m].nmd)
          smoothing.divide(m, nodes.active_nodes);
    }
    if (particles.has_affine_velocity())
      {
        TimerOutput::Scope scope(timer, "affine_velocity");
        Stages::store_affine_velocity(smoothing, particles);
      }
    {
      TimerOutput::Scope scope(timer, "stress_update");
      Stages::stress_update(grid,
                            materials,
                            material_options,
                            dt,
                            smoothing,
                            particles,
                            settings.stress_integration,
                            &result.material_dissipation);
    }
    {
      TimerOutput::Scope scope(timer, "free_surface");
      result.free_surface = Stages::detect_free_surface(
        grid,
        nodes,
        material_options,
        smoothing,
        particles,
        [this]() { synchronise_free_surface(); },
        &materials,
        &result.numerical_dissipation);
    }
    {
      TimerOutput::Scope scope(timer, "anp");
      Stages::average_nodal_pressure(
        grid, nodes, material_options, smoothing, particles, [this]() {
          synchronise_smoothing([](const MaterialOptions &o) { return o.anp; });
        });
    }
    // MPI: the ghost copies have served every nodal sum; their motion is
    // their owners'.
    if (partition != nullptr)
      DistributedPoints::drop_ghosts(particles);
    if (membrane_crossing)
      {
        TimerOutput::Scope scope(timer, "membrane");
        membrane_crossing->remember_start(nodes, particles, dt);
      }
    {
      TimerOutput::Scope scope(timer, "position_update");
      result.displacement_ratio
        = Stages::update_positions(grid, nodes, dt, particles);
    }
    if (membrane_coupling)
      {
        TimerOutput::Scope scope(timer, "membrane");
        result.displacement_ratio
          = std::max(result.displacement_ratio,
                     membrane_coupling->update_positions(nodes, dt));
      }
    // No point passes through the membrane (before the points are sorted
    // into their new cells).
    if (membrane_crossing && std::isfinite(result.displacement_ratio))
      {
        TimerOutput::Scope scope(timer, "membrane");
        const auto         outcome
          = membrane_crossing->keep_points_on_their_side(dt, particles);
        result.membrane_crossings = outcome.corrected;
        result.numerical_dissipation.add(outcome.kinetic_energy_removed);
      }
    // After a blow-up the positions are not finite and cannot be located;
    // run control stops the run on the ratio.
    if (std::isfinite(result.displacement_ratio))
      {
        {
          TimerOutput::Scope scope(timer, "relocate");
          result.lost_particles = Stages::relocate(grid,
                                                   particles,
                                                   &materials,
                                                   &result.outflow_energy);
        }
        // The membrane's slip, splits, location and element forces.
        if (membrane_coupling)
          {
            TimerOutput::Scope scope(timer, "membrane");
            result.membrane_nodes_outside = membrane_coupling->relocate();
          }
      }
    return result;
  }



  template class MpmStep<2>;
  template class MpmStep<3>;
} // namespace fsgmpm
