#ifndef fsgmpm_grid_wall_condition_h
#define fsgmpm_grid_wall_condition_h

#include <deal.II/base/types.h>

#include <map>
#include <string>

namespace fsgmpm
{
  using namespace dealii;

  /// The kind of wall a boundary id stands for.
  enum class WallType
  {
    free,    ///< no constraint
    fixed,   ///< all velocity components zero (no slip)
    roller,  ///< normal velocity zero both ways, tangential free (bilateral)
    slip,    ///< unilateral frictionless contact: may leave, never penetrate
    friction ///< unilateral contact with Coulomb friction coefficient mu
  };

  struct WallCondition
  {
    WallType type     = WallType::free;
    double   friction = 0.;
  };

  /**
   * Parse "id: type[, id: type ...]" where type is free, fixed, roller,
   * slip or "friction <mu>". Throws with a message naming @p parameter_path.
   */
  std::map<types::boundary_id, WallCondition>
  parse_wall_conditions(const std::string &text,
                        const std::string &parameter_path);
} // namespace fsgmpm

#endif
