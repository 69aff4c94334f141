// Newtonian fluid material point (no grid), against closed forms:
// linear law p = -K (J - 1) (Eq. 16) and power law p = (K/kappa)(J^-kappa - 1)
// (Eq. 15) with volume_ratio_for_pressure as their exact inverse; the
// viscous stress 2 mu dev(d) of Eq. (13) in simple shear; the tension
// cut-off and the admissible volume ratio; the wave speed sqrt(K_t/rho).

#include <fsgmpm/materials/newtonian_fluid.h>
#include <gtest/gtest.h>

#include <vector>

using namespace fsgmpm;

namespace
{
  SymmetricTensor<2, 3>
  stress_at(const NewtonianFluid  &fluid,
            const double           J,
            const PointKinematics &k0)
  {
    PointKinematics k = k0;
    k.volume_ratio    = J;
    SymmetricTensor<2, 3> s;
    fluid.update_stresses(&k, &s, 1, 1e-4);
    return s;
  }
} // namespace

TEST(NewtonianFluid, PressureLaws)
{
  const double         K = 2.13e9;
  const NewtonianFluid linear(
    K, 0, 1000, NewtonianFluid::PressureLaw::linear, 7, true);
  const NewtonianFluid power(
    K, 0, 1000, NewtonianFluid::PressureLaw::power, 7, true);
  const PointKinematics k;
  for (const double J : {0.999, 0.9999, 1.0, 1.0001})
    {
      EXPECT_NEAR(-trace(stress_at(linear, J, k)) / 3,
                  -K * (J - 1),
                  1e-6 * K * 1e-4);
      EXPECT_NEAR(-trace(stress_at(power, J, k)) / 3,
                  K / 7 * (std::pow(J, -7.) - 1),
                  1e-6 * K * 1e-4);
    }
  for (const double p : {0., 1e3, 1e5, 1e7})
    {
      EXPECT_NEAR(linear.pressure(linear.volume_ratio_for_pressure(p)),
                  p,
                  1e-9 * K);
      EXPECT_NEAR(power.pressure(power.volume_ratio_for_pressure(p)),
                  p,
                  1e-9 * K);
    }
  // Same bulk modulus at the reference state.
  EXPECT_NEAR((power.pressure(1 - 1e-7) - power.pressure(1 + 1e-7)) / 2e-7,
              K,
              1e-4 * K);
  EXPECT_NEAR(linear.wave_speed(1000), std::sqrt(K / 1000), 1e-9);
}

TEST(NewtonianFluid, ViscousStressInSimpleShear)
{
  const double         mu = 1.0;
  const NewtonianFluid fluid(
    2e9, mu, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  PointKinematics k;
  const double    gamma_dot = 3.0; // v_x = gamma_dot y
  k.strain_rate[0][1]       = 0.5 * gamma_dot;
  const auto s              = stress_at(fluid, 1.0, k);
  EXPECT_NEAR(s[0][1], mu * gamma_dot, 1e-12);
  EXPECT_NEAR(s[0][0], 0, 1e-12);
  EXPECT_NEAR(s[2][2], 0, 1e-12);
  // Uniaxial compression rate: the deviatoric part only (Stokes).
  PointKinematics c;
  c.strain_rate[0][0] = -1;
  const auto sc       = stress_at(fluid, 1.0, c);
  EXPECT_NEAR(sc[0][0], 2 * mu * (-1 + 1. / 3), 1e-12);
  EXPECT_NEAR(trace(sc), 0, 1e-12);
}

TEST(NewtonianFluid, TensionPolicy)
{
  const NewtonianFluid no_tension(
    2e6, 0, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  const NewtonianFluid tension(
    2e6, 0, 1000, NewtonianFluid::PressureLaw::linear, 7, true);
  const PointKinematics k;
  EXPECT_EQ(trace(stress_at(no_tension, 1.01, k)), 0.);
  EXPECT_NEAR(-trace(stress_at(tension, 1.01, k)) / 3, -2e4, 1e-6);
  EXPECT_EQ(no_tension.admissible_volume_ratio(1.01), 1.);
  EXPECT_EQ(no_tension.admissible_volume_ratio(0.99), 0.99);
  EXPECT_EQ(tension.admissible_volume_ratio(1.01), 1.01);
}

// The stress stage computes the rotation of the step only for materials
// that read it: the fluid's Eq. (13) does not, but a class derived from
// it (tutorial step-2's Bingham mud rotates its elastic deviator) gets it
// unless it says otherwise.
TEST(NewtonianFluid, OnlyItsOwnClassSkipsTheRotation)
{
  struct RotatingFluid : NewtonianFluid
  {
    using NewtonianFluid::NewtonianFluid;
  };
  const NewtonianFluid fluid(
    2e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  const RotatingFluid derived(
    2e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  EXPECT_FALSE(fluid.rotates_stress());
  EXPECT_TRUE(derived.rotates_stress());
  EXPECT_TRUE(static_cast<const Material &>(derived).rotates_stress());
}

// The energies call add_strain_energy() once per run of points: the fluid's
// own loop must give the bits of strain_energy_density() summed point by
// point after the caller's sum, and a derived class that changes the
// density (step-2's Bingham mud adds its elastic deviator's) must get its
// own density through it.
TEST(NewtonianFluid, StrainEnergyOfARunIsItsPointsSummedInOrder)
{
  const NewtonianFluid fluid(
    2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  std::vector<SymmetricTensor<2, 3>> stress(5);
  std::vector<double>                volume(5);
  for (unsigned int i = 0; i < 5; ++i)
    {
      for (unsigned int d = 0; d < 3; ++d)
        stress[i][d][d] = -1234.567 * (i + 1) - 0.1 * d;
      stress[i][0][1] = 17.3 * i;
      volume[i]       = 1e-4 * (1. + 0.37 * i);
    }
  const double before   = 0.123456789;
  double       expected = before;
  for (unsigned int i = 0; i < 5; ++i)
    expected += volume[i] * fluid.strain_energy_density(stress[i]);
  EXPECT_EQ(fluid.add_strain_energy(stress.data(), volume.data(), 5, before),
            expected);

  struct ShearEnergyFluid : NewtonianFluid
  {
    using NewtonianFluid::NewtonianFluid;
    double
    strain_energy_density(const SymmetricTensor<2, 3> &s) const override
    {
      return NewtonianFluid::strain_energy_density(s) + s[0][1] * s[0][1];
    }
  };
  const ShearEnergyFluid derived(
    2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, false);
  double derived_expected = 0;
  for (unsigned int i = 0; i < 5; ++i)
    derived_expected += volume[i] * derived.strain_energy_density(stress[i]);
  EXPECT_EQ(static_cast<const Material &>(derived).add_strain_energy(
              stress.data(), volume.data(), 5, 0.),
            derived_expected);
  EXPECT_GT(derived_expected,
            fluid.add_strain_energy(stress.data(), volume.data(), 5, 0.));
}
