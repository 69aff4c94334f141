#ifndef fsgmpm_run_monitors_h
#define fsgmpm_run_monitors_h

#include <array>
#include <string>

namespace fsgmpm
{
  /// Global quantities monitored every step (the common columns of
  /// monitors.csv).
  struct Monitors
  {
    double       kinetic_energy    = 0; ///< sum_p m_p |v_p|^2 / 2
    double       strain_energy     = 0; ///< sum_p V_p w(sigma_p)
    double       potential_energy  = 0; ///< -sum_p m_p g . x_p
    double       external_work     = 0; ///< accumulated F_ext . du (Eq. 30)
    double       dissipated_energy = 0; ///< removed by damping
    double       dr_energy_ratio   = 0; ///< Eq. (30): E_kin / W_ext (nodal)
    double       dr_force_ratio    = 0; ///< Eq. (30): |F_ext-F_int|/|F_ext|
    unsigned int lost_particles    = 0;
    /// sum_i m_i |v_i|^2 / 2 over the grid nodes (remapped velocities): the
    /// motion the grid resolves. FLIP (Eq. 19) keeps point-velocity
    /// fluctuations that the grid cannot see and that move nothing, so a
    /// deposit at rest can hold most of kinetic_energy as such noise;
    /// Termination = at_rest and Eq. (30) use this one.
    double grid_kinetic_energy = 0;
    /// The losses the step books (accumulated, J; J/m in 2D), so that the
    /// energy balance's residual is what no monitor books (walls, contact,
    /// the grid transfers): plastic and viscous work
    /// (Material::dissipated_energy());
    double material_dissipation = 0;
    /// what the FLIP-PIC/XPIC blend or APIC's transfer took from the points'
    /// kinetic energy and the free-surface reset from their stored energy;
    double numerical_dissipation = 0;
    /// the kinetic and stored energy of the points that left the mesh.
    double outflow_energy = 0;
    /// Flagged (free-surface) points / points of detecting materials.
    double free_surface_fraction = 0;

    static constexpr unsigned int n_values = 13;

    /// The columns of values() in monitors.csv (after time, step and dt).
    static std::array<std::string, n_values>
    names()
    {
      return {{"kinetic_energy",
               "strain_energy",
               "potential_energy",
               "external_work",
               "dissipated_energy",
               "dr_energy_ratio",
               "dr_force_ratio",
               "lost_particles",
               "grid_kinetic_energy",
               "material_dissipation",
               "numerical_dissipation",
               "outflow_energy",
               "free_surface_fraction"}};
    }

    /// Their SI units: energies per metre of thickness in 2D (J/m), of the
    /// whole body in 3D (J); the ratios and the count have none.
    static std::array<std::string, n_values>
    units(const unsigned int dim)
    {
      const std::string e = dim == 2 ? "J/m" : "J";
      return {{e, e, e, e, e, "", "", "", e, e, e, e, ""}};
    }

    /// The values in the order of monitors.csv's columns (kinetic_energy
    /// ... grid_kinetic_energy, material_dissipation, numerical_dissipation,
    /// outflow_energy, free_surface_fraction), for output and checkpoints.
    std::array<double, n_values>
    values() const
    {
      return {{kinetic_energy,
               strain_energy,
               potential_energy,
               external_work,
               dissipated_energy,
               dr_energy_ratio,
               dr_force_ratio,
               double(lost_particles),
               grid_kinetic_energy,
               material_dissipation,
               numerical_dissipation,
               outflow_energy,
               free_surface_fraction}};
    }

    /// The inverse of values().
    void
    set_values(const std::array<double, n_values> &v)
    {
      kinetic_energy        = v[0];
      strain_energy         = v[1];
      potential_energy      = v[2];
      external_work         = v[3];
      dissipated_energy     = v[4];
      dr_energy_ratio       = v[5];
      dr_force_ratio        = v[6];
      lost_particles        = static_cast<unsigned int>(v[7]);
      grid_kinetic_energy   = v[8];
      material_dissipation  = v[9];
      numerical_dissipation = v[10];
      outflow_energy        = v[11];
      free_surface_fraction = v[12];
    }
  };
} // namespace fsgmpm

#endif
