#ifndef fsgmpm_tests_hydrostatic_error_h
#define fsgmpm_tests_hydrostatic_error_h

#include <fsgmpm/particles/particle_store.h>

#include <cmath>
#include <limits>

namespace fsgmpm
{
  namespace test_tools
  {
    /// Largest |p - rho g (H - y)| / (rho g H) over the 2D points with
    /// y_low < y < y_high (away from the rows where the element mean or the
    /// surface offsets the pressure); NaN if a position or stress is not
    /// finite.
    inline double
    max_hydrostatic_error(const ParticleStore<2> &ps,
                          const double            rho_g,
                          const double            H,
                          const double            y_low,
                          const double            y_high)
    {
      double e = 0;
      for (unsigned int p = 0; p < ps.size(); ++p)
        {
          const double y = ps.position[p][1];
          if (!std::isfinite(y) || !std::isfinite(trace(ps.stress[p])))
            return std::numeric_limits<double>::quiet_NaN();
          if (y > y_low && y < y_high)
            e = std::max(e,
                         std::abs(-trace(ps.stress[p]) / 3. - rho_g * (H - y))
                           / (rho_g * H));
        }
      return e;
    }
  } // namespace test_tools
} // namespace fsgmpm

#endif
