// Newtonian fluid material point (no grid), against closed forms:
// linear law p = -K (J - 1) (Eq. 16) and power law p = (K/kappa)(J^-kappa - 1)
// (Eq. 15) with volume_ratio_for_pressure as their exact inverse; the
// viscous stress 2 mu dev(d) of Eq. (13) in simple shear; the tension
// cut-off and the admissible volume ratio; the wave speed sqrt(K_t/rho).
// The calls per run of points (the stress stage's update_stresses_of_run()
// and the time step's wave_speeds()) give the bits of the calls per point,
// for the fluid's own loops, for the materials that take the defaults and
// for a class derived from the fluid.

#include <fsgmpm/materials/linear_elastic.h>
#include <fsgmpm/materials/newtonian_fluid.h>
#include <gtest/gtest.h>

#include <type_traits>
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
  const double          K = 2.13e9;
  const NewtonianFluid  linear(K,
                              0,
                              1000,
                              NewtonianFluid::PressureLaw::linear,
                              7,
                              NewtonianFluid::no_tension_limit);
  const NewtonianFluid  power(K,
                             0,
                             1000,
                             NewtonianFluid::PressureLaw::power,
                             7,
                             NewtonianFluid::no_tension_limit);
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
    2e9, mu, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.);
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
  using Law = NewtonianFluid::PressureLaw;
  const NewtonianFluid no_tension(2e6, 0, 1000, Law::linear, 7, 0.);
  const NewtonianFluid tension(
    2e6, 0, 1000, Law::linear, 7, NewtonianFluid::no_tension_limit);
  const PointKinematics k;
  EXPECT_EQ(trace(stress_at(no_tension, 1.01, k)), 0.);
  EXPECT_NEAR(-trace(stress_at(tension, 1.01, k)) / 3, -2e4, 1e-6);
  EXPECT_EQ(no_tension.admissible_volume_ratio(1.01), 1.);
  EXPECT_EQ(no_tension.admissible_volume_ratio(0.99), 0.99);
  EXPECT_EQ(tension.admissible_volume_ratio(1.01), 1.01);

  // A cut-off p_c = -5 kPa: the law's pressure above it, p_c below, and
  // the volume ratio capped where the law reaches p_c (linear:
  // 1 - p_c/K; power: (1 + kappa p_c/K)^(-1/kappa)).
  const double         p_c = -5e3;
  const NewtonianFluid linear(2e6, 0, 1000, Law::linear, 7, p_c);
  const NewtonianFluid power(2e6, 0, 1000, Law::power, 7, p_c);
  EXPECT_NEAR(-trace(stress_at(linear, 1.001, k)) / 3, -2e3, 1e-6);
  EXPECT_NEAR(-trace(stress_at(linear, 1.01, k)) / 3, p_c, 1e-9);
  EXPECT_NEAR(-trace(stress_at(power, 1.001, k)) / 3,
              2e6 / 7 * (std::pow(1.001, -7.) - 1),
              1e-6);
  EXPECT_NEAR(-trace(stress_at(power, 1.01, k)) / 3, p_c, 1e-9);
  EXPECT_NEAR(linear.admissible_volume_ratio(1.01), 1.0025, 1e-15);
  EXPECT_EQ(linear.admissible_volume_ratio(1.001), 1.001);
  EXPECT_NEAR(power.pressure(power.admissible_volume_ratio(1.01)),
              p_c,
              1e-9 * 2e6);
  // The power law never pulls below -K/kappa: a cut-off beyond is none.
  const NewtonianFluid deep(2e6, 0, 1000, Law::power, 7, -1e6);
  EXPECT_EQ(deep.admissible_volume_ratio(50.), 50.);
  // A positive cut-off is refused; a bool does not convert to a cut-off.
  EXPECT_THROW(NewtonianFluid(2e6, 0, 1000, Law::linear, 7, 1.),
               dealii::ExceptionBase);
  static_assert(!std::is_constructible_v<NewtonianFluid,
                                         double,
                                         double,
                                         double,
                                         Law,
                                         double,
                                         bool>);
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
    2e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.);
  const RotatingFluid derived(
    2e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.);
  EXPECT_FALSE(fluid.rotates_stress());
  EXPECT_TRUE(derived.rotates_stress());
  EXPECT_TRUE(static_cast<const Material &>(derived).rotates_stress());
}

// The energies call add_strain_energy() once per run of points. The
// fluid's stored energy is that of its state J = V / V_ref: V_ref e(J),
// summed in point order after the caller's sum, whatever pressure the
// stress holds (the nodal pressure average overwrites it); e(J) is the
// integral of the pressure, so de/dJ = -p (central differences, both
// laws, without tension, with a cut-off and without limit). A derived class
// that changes the density (step-2's Bingham mud adds its elastic deviator's)
// gets its own stress-based density through it.
TEST(NewtonianFluid, StrainEnergyIsThatOfTheVolumeRatio)
{
  using Law = NewtonianFluid::PressureLaw;
  const NewtonianFluid fluid(2.5e6, 1e-3, 1000, Law::linear, 7, 0.);
  std::vector<SymmetricTensor<2, 3>> stress(5);
  std::vector<double>                volume(5), reference_volume(5);
  for (unsigned int i = 0; i < 5; ++i)
    {
      for (unsigned int d = 0; d < 3; ++d)
        stress[i][d][d] = -1234.567 * (i + 1) - 0.1 * d;
      stress[i][0][1]     = 17.3 * i;
      reference_volume[i] = 1e-4 * (1. + 0.37 * i);
      volume[i]           = reference_volume[i] * (1. - 1e-3 * i);
    }
  const double before   = 0.123456789;
  double       expected = before;
  for (unsigned int i = 0; i < 5; ++i)
    expected += reference_volume[i]
                * fluid.volume_ratio_energy(volume[i] / reference_volume[i]);
  EXPECT_EQ(fluid.add_strain_energy(
              stress.data(), volume.data(), reference_volume.data(), 5, before),
            expected);
  // The stress does not enter.
  std::vector<SymmetricTensor<2, 3>> other_stress(5);
  EXPECT_EQ(fluid.add_strain_energy(other_stress.data(),
                                    volume.data(),
                                    reference_volume.data(),
                                    5,
                                    before),
            expected);

  for (const Law law : {Law::linear, Law::power})
    for (const double kappa : {7., 1.})
      for (const double p_c : {0., -2e3, NewtonianFluid::no_tension_limit})
        {
          const NewtonianFluid f(2.5e6, 1e-3, 1000, law, kappa, p_c);
          EXPECT_EQ(f.volume_ratio_energy(1.), 0.);
          for (const double J : {0.97, 0.999, 1.002})
            {
              const double e = 1e-6;
              const double dedJ
                = (f.volume_ratio_energy(J + e) - f.volume_ratio_energy(J - e))
                  / (2 * e);
              const double p = std::max(f.pressure(J), p_c);
              EXPECT_NEAR(dedJ, -p, 1e-6 * 2.5e6) << J;
              EXPECT_GE(f.volume_ratio_energy(J), 0.);
            }
        }

  struct ShearEnergyFluid : NewtonianFluid
  {
    using NewtonianFluid::NewtonianFluid;
    double
    strain_energy_density(const SymmetricTensor<2, 3> &s) const override
    {
      return NewtonianFluid::strain_energy_density(s) + s[0][1] * s[0][1];
    }
  };
  const ShearEnergyFluid derived(2.5e6, 1e-3, 1000, Law::linear, 7, 0.);
  double                 derived_expected = 0;
  for (unsigned int i = 0; i < 5; ++i)
    derived_expected += volume[i] * derived.strain_energy_density(stress[i]);
  EXPECT_EQ(static_cast<const Material &>(derived).add_strain_energy(
              stress.data(), volume.data(), reference_volume.data(), 5, 0.),
            derived_expected);
}



// update_stresses_of_run(): a run of 37 points (then of 1: the default
// keeps its larger buffer) sharing a strain rate and rotation, each with
// its volume ratio, against update_stresses() with the kinematics copied
// per point. The
// fluid's own loop (linear law, with and without tension; power law), the
// default (an elastic solid, which reads the rotation and its old
// stresses), and a class derived from the fluid that changes
// update_stresses() (as step-2's Bingham mud does), through the base
// reference. The same for wave_speeds() against wave_speed().
TEST(NewtonianFluid, RunCallsAreTheirPointsCalls)
{
  struct ShearThickFluid : NewtonianFluid
  {
    using NewtonianFluid::NewtonianFluid;
    void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const override
    {
      NewtonianFluid::update_stresses(kinematics, stress, n, dt);
      for (unsigned int i = 0; i < n; ++i)
        stress[i][0][1] *= 1. + kinematics[i].volume_ratio;
    }
    double
    wave_speed(const double rho) const override
    {
      return 3. * NewtonianFluid::wave_speed(rho);
    }
  };
  std::vector<std::unique_ptr<Material>> materials;
  materials.push_back(std::make_unique<NewtonianFluid>(
    2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.));
  materials.push_back(
    std::make_unique<NewtonianFluid>(2.5e6,
                                     1e-3,
                                     1000,
                                     NewtonianFluid::PressureLaw::linear,
                                     7,
                                     NewtonianFluid::no_tension_limit));
  materials.push_back(std::make_unique<NewtonianFluid>(
    2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::power, 7, 0.));
  materials.push_back(std::make_unique<LinearElastic>(1e7, 0.3, 2000));
  materials.push_back(std::make_unique<ShearThickFluid>(
    2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.));

  const unsigned int n = 37;
  PointKinematics    shared;
  for (unsigned int a = 0; a < 3; ++a)
    for (unsigned int b = a; b < 3; ++b)
      shared.strain_rate[a][b] = 0.3 * a - 0.7 * b + 0.11;
  const double angle    = 0.01;
  shared.rotation       = unit_symmetric_tensor<3>();
  shared.rotation[0][0] = shared.rotation[1][1] = std::cos(angle);
  shared.rotation[0][1]                         = -std::sin(angle);
  shared.rotation[1][0]                         = std::sin(angle);
  shared.volume_ratio                           = -1; // not read
  std::vector<double> J(n), rho(n);
  for (unsigned int i = 0; i < n; ++i)
    {
      J[i]   = 0.995 + 0.0003 * i; // both sides of 1: tension cut-off
      rho[i] = 1000. / J[i];
    }
  for (const auto &material : materials)
    {
      std::vector<SymmetricTensor<2, 3>> by_run(n), by_point(n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int a = 0; a < 3; ++a)
          by_run[i][a][a] = by_point[i][a][a] = -1e3 * (i + a);
      std::vector<PointKinematics> kinematics(n, shared);
      for (unsigned int i = 0; i < n; ++i)
        kinematics[i].volume_ratio = J[i];
      material->update_stresses(kinematics.data(), by_point.data(), n, 1e-4);
      material->update_stresses_of_run(
        shared, J.data(), by_run.data(), n, 1e-4);
      EXPECT_EQ(by_run, by_point) << material->name();

      std::vector<double> speeds(n);
      material->wave_speeds(rho.data(), speeds.data(), n);
      for (unsigned int i = 0; i < n; ++i)
        EXPECT_EQ(speeds[i], material->wave_speed(rho[i])) << material->name();
    }
  // The derived class's own update and speed, not the fluid's loops.
  SymmetricTensor<2, 3> derived, fluid;
  materials[4]->update_stresses_of_run(shared, J.data(), &derived, 1, 1e-4);
  materials[0]->update_stresses_of_run(shared, J.data(), &fluid, 1, 1e-4);
  EXPECT_NE(derived[0][1], fluid[0][1]);
  double derived_speed, fluid_speed;
  materials[4]->wave_speeds(rho.data(), &derived_speed, 1);
  materials[0]->wave_speeds(rho.data(), &fluid_speed, 1);
  EXPECT_EQ(derived_speed, 3. * fluid_speed);
}
