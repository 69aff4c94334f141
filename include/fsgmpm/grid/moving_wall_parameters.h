#ifndef fsgmpm_grid_moving_wall_parameters_h
#define fsgmpm_grid_moving_wall_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Input of a rigid plane wall with a prescribed velocity history: the gate
   * of a dam-break experiment, lifted while the column collapses. It
   * declares and parses its own subsection ("Moving wall"; moving_wall.cc),
   * and this light header is all that Parameters needs of the wall.
   */
  struct MovingWallParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read and validate the subsection (@p dim components per vector).
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);

    bool enabled = false;
    /// Axis of the wall's normal and the sign of the outward normal (from
    /// the material into the wall): material side "-x" gives +x.
    unsigned int axis         = 0;
    double       outward_sign = 1.;
    /// Opposite corners of the wall at t = 0 (equal along the axis).
    std::vector<double> lower, upper;
    /// Samples (t, v_0, ..., v_{dim-1}), t strictly increasing from 0; the
    /// velocity is piecewise linear between them and held after the last.
    std::vector<std::array<double, 4>> history;
  };
} // namespace fsgmpm

#endif
