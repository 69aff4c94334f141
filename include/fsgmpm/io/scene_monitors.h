#ifndef fsgmpm_io_scene_monitors_h
#define fsgmpm_io_scene_monitors_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Scene-specific columns of monitors.csv, selected by name in subsection
   * Monitors. Dam break (SPEC 3.3), both from the non-flagged points:
   * - front_position: largest x - x_wall of the points in the bottom cell
   *   row, plus half a point spacing (V_p^(1/dim));
   * - column_height: largest y - y_base of the points within one cell of the
   *   wall, plus half a point spacing.
   */
  template <int dim>
  class SceneMonitors
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// @p lower, @p cell_size: mesh corner and cell size per direction,
    /// used where the parameters say "auto"; @p n_bodies for the per-body
    /// columns.
    SceneMonitors(ParameterHandler  &prm,
                  const Point<dim>  &lower,
                  const Point<dim>  &cell_size,
                  const unsigned int n_bodies = 1);

    const std::vector<std::string> &
    names() const
    {
      return columns;
    }

    /// The columns' values; the geotube columns (io/membrane_output.h)
    /// need @p membrane.
    std::vector<double>
    evaluate(const ParticleStore<dim> &particles,
             const Membrane<dim>      *membrane = nullptr) const;

    /// True if a column needs a membrane.
    bool
    needs_membrane() const;

  private:
    std::vector<std::string> columns;
    double                   wall_x, base_y, row_height, column_width;
    double                   contact_tolerance, strip_width;
    unsigned int             n_bodies, container;
  };
} // namespace fsgmpm

#endif
