#ifndef fsgmpm_scene_body_h
#define fsgmpm_scene_body_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/material.h>
#include <fsgmpm/particles/body_shape.h>
#include <fsgmpm/step/material_options.h>

#include <memory>
#include <vector>

namespace fsgmpm
{
  /// The largest number of bodies a scene may declare.
  constexpr unsigned int max_n_bodies = 8;

  /**
   * One body of a scene, as given in subsection Bodies/Body N: the shape it
   * fills, its material and its initial state.
   */
  template <int dim>
  struct BodyDescription
  {
    std::string                     path; ///< "Bodies/Body N"
    std::unique_ptr<BodyShape<dim>> shape;
    /// Shape = membrane: fills the inside of the scene's membrane (shape is
    /// set once the membrane exists).
    bool                      fills_membrane = false;
    std::unique_ptr<Material> material;
    unsigned int              particles_per_cell;
    double                    density;
    Tensor<1, dim>            initial_velocity;
    /// Initial stress: none; geostatic (sigma_yy = -rho g (y_top - y),
    /// sigma_xx = sigma_zz = K0 sigma_yy) from the body's top surface; or
    /// hydrostatic (pressure rho g (y_top - y); fluids also get the matching
    /// compressed volume).
    enum class InitialStress
    {
      none,
      geostatic,
      hydrostatic
    };
    InitialStress initial_stress;
    double        k0;
    /// Velocity field of the body's points (BackgroundGrid's copies).
    unsigned int velocity_field = 0;
    /// NMD, ANP and free-surface switches of the body's material.
    MaterialOptions options;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Parse subsection Bodies (all bodies). Errors name the full path.
    static std::vector<BodyDescription<dim>>
    parse_bodies(ParameterHandler &prm);
  };
} // namespace fsgmpm

#endif
