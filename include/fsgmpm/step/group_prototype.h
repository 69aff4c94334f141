#ifndef fsgmpm_step_group_prototype_h
#define fsgmpm_step_group_prototype_h
// PROTOTYPE: smoothing over the parent box of a simplex cell.
#include <fsgmpm/grid/background_grid.h>
#include <cstdlib>
#include <cmath>
namespace fsgmpm
{
  inline bool
  group_mode()
  {
    static const bool on = std::getenv("FSGMPM_GROUP_H") != nullptr;
    return on;
  }
  template <int dim>
  inline unsigned int
  group_of(const BackgroundGrid<dim> &grid, const unsigned int c)
  {
    static const double h = std::atof(std::getenv("FSGMPM_GROUP_H"));
    static const int    nx = std::atoi(std::getenv("FSGMPM_GROUP_NX"));
    static const int    ny = std::getenv("FSGMPM_GROUP_NY") ? std::atoi(std::getenv("FSGMPM_GROUP_NY")) : 1;
    Point<dim> centre;
    for (const unsigned int i : grid.cell_nodes[c])
      centre += grid.node_positions[i];
    centre /= (dim + 1);
    unsigned int g = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const int k = int(std::floor((centre[d] - grid.lower_corner[d]) / h));
        g += k * stride;
        stride *= (d == 0 ? nx : ny);
      }
    return g;
  }
}
#endif
