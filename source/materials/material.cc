#include <fsgmpm/materials/material.h>

#include <vector>

namespace fsgmpm
{
  void
  Material::update_stresses_of_run(const PointKinematics &shared,
                                   const double          *volume_ratio,
                                   SymmetricTensor<2, 3> *stress,
                                   const unsigned int     n,
                                   const double           dt) const
  {
    // A buffer per thread, grown to the longest run and kept: a buffer on
    // the stack would be constructed (zeroed, 128 B per entry) at every
    // call, which made the soil's stress update 8 % slower.
    thread_local std::vector<PointKinematics> kinematics;
    if (kinematics.size() < n)
      kinematics.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        kinematics[i]              = shared;
        kinematics[i].volume_ratio = volume_ratio[i];
      }
    update_stresses(kinematics.data(), stress, n, dt);
  }
} // namespace fsgmpm
