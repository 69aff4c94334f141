// The run-control pieces of a Simulator, each used alone:
// - TimeStepControl: the automatic step is the stages' stable step; a fixed
//   step is taken when stable and refused, naming the parameter, when not;
//   the last step lands on the end time exactly; dt_min (the steps as
//   chosen, not the last one cut to the end time) and dt_max; the step
//   limit told apart from the end time.
// - OutputSchedule: output at the first step at or past each multiple of
//   the interval (steps of 0.03 s, interval 0.1 s: after 0.12, 0.21, 0.3
//   s), never twice in a step; an interval below the round-off of the time
//   still moves past the time (1e-20 s at t = 1 s: every step is then due);
//   every N steps without an interval.
// - DynamicRelaxation: kinetic damping removes all kinetic energy (points,
//   APIC's affine velocities, membrane nodes excepted here) exactly when it
//   has passed a peak and books it as dissipated; Eq. (30) convergence
//   needs both ratios below tolerance for the whole window, after the load
//   time; at rest needs the grid's kinetic energy below the tolerance after
//   it was above.
// - EnergyBalance: kinetic, strain and potential energy of points with
//   known state against the hand sums (exact to round-off, 1e-14
//   relative), and the Eq. (30) ratios of a step.
// - CompensatedSum: the monitors' sums over points agree to a few roundings
//   whatever the order of the terms and however they are split, and the
//   parallel sums in chunks do not depend on the number of threads.
// - Stages::stable_time_step: the smallest cell bound h / max_p s_p over
//   the occupied cells, with the signal speed s_p = c(rho_p) + |v_p| +
//   2 d nu / (rho_p h), and the cells' stiffness sum_p V_p rho_p s_p^2,
//   the bits of a loop over the points (1 and 2 threads, 2D and 3D, 600
//   points: more than one block of the stage's vector loops), also with an
//   empty cell's points appended after the sorted ones, as MPI's ghost
//   copies are.

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/materials/linear_elastic.h>
#include <fsgmpm/materials/newtonian_fluid.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/run/dynamic_relaxation.h>
#include <fsgmpm/run/energy_balance.h>
#include <fsgmpm/run/output_schedule.h>
#include <fsgmpm/run/termination.h>
#include <fsgmpm/run/time_step_control.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <utility>

using namespace fsgmpm;

TEST(TimeStepControl, AutomaticFixedAndEndTime)
{
  TimeStepControl automatic({0.5, 0., 1.});
  EXPECT_EQ(automatic.choose(0.3, 0., 0), "");
  EXPECT_EQ(automatic.dt(), 0.3);
  automatic.record_step(1);
  EXPECT_EQ(automatic.choose(0.2, 0.3, 1), "");
  automatic.record_step(2);
  // Lands on the end time: 1 - 0.9 left.
  EXPECT_EQ(automatic.choose(0.4, 0.9, 2), "");
  EXPECT_DOUBLE_EQ(automatic.dt(), 0.1);
  automatic.record_step(3);
  // dt_min: the smallest step the stability limit chose (0.2); the last
  // step, cut to 0.1 to land on the end time, does not count.
  EXPECT_DOUBLE_EQ(automatic.dt_min(), 0.2);
  EXPECT_EQ(automatic.dt_max(), 0.3);
  EXPECT_DOUBLE_EQ(automatic.dt(), 0.1);
  // The end: at 0.9 + 0.1 (round-off below 1 included), not at 0.9.
  EXPECT_FALSE(automatic.reached_end(0.9, 2));
  EXPECT_TRUE(automatic.reached_end(0.9 + 0.1, 3));
  EXPECT_TRUE(automatic.reached_end(1. - 1e-15, 3));
  EXPECT_TRUE(automatic.reached_end_time(1. - 1e-15));
  // A largest number of steps: reached_end(), but not the end time (the
  // run reports max_steps).
  TimeStepControl::Settings limited{0.5, 0., 1., 3};
  EXPECT_FALSE(TimeStepControl(limited).reached_end(0.5, 2));
  EXPECT_TRUE(TimeStepControl(limited).reached_end(0.5, 3));
  EXPECT_FALSE(TimeStepControl(limited).reached_end_time(0.5));
  EXPECT_TRUE(TimeStepControl(limited).reached_end_time(1.));
  EXPECT_EQ(to_string(Termination::max_steps), "max_steps");
  EXPECT_TRUE(finished_normally(Termination::max_steps));
  EXPECT_EQ(to_string(Termination::interrupted), "interrupted");
  EXPECT_FALSE(finished_normally(Termination::interrupted));
  // A single step cut to the end time: dt_min is that step.
  TimeStepControl single({0.5, 0., 0.05});
  EXPECT_EQ(single.choose(0.3, 0., 0), "");
  single.record_step(1);
  EXPECT_DOUBLE_EQ(single.dt(), 0.05);
  EXPECT_DOUBLE_EQ(single.dt_min(), 0.05);

  // A fixed step within the limit dt_stable / Courant (0.6 here).
  TimeStepControl fixed({0.5, 0.5, 1.});
  EXPECT_EQ(fixed.choose(0.3, 0., 0), "");
  EXPECT_EQ(fixed.dt(), 0.5);
  // Above it: refused, dt unchanged.
  const std::string problem = fixed.choose(0.2, 0.5, 1);
  EXPECT_NE(problem.find("Simulation/Fixed time step"), std::string::npos)
    << problem;
  EXPECT_EQ(fixed.dt(), 0.5);

  // A non-finite step (a blow-up) is refused.
  TimeStepControl broken({0.5, 0., 1.});
  EXPECT_NE(broken.choose(std::numeric_limits<double>::quiet_NaN(), 0., 4), "");

  // The state round trip (checkpoints).
  TimeStepControl restored({0.5, 0., 1.});
  restored.set_state(automatic.state());
  EXPECT_EQ(restored.state(), automatic.state());
}



TEST(OutputSchedule, IntervalStepsAndRoundOff)
{
  OutputSchedule      schedule(0.1);
  std::vector<double> written;
  double              time = 0;
  for (unsigned int step = 1; step <= 10; ++step)
    {
      time += 0.03;
      if (schedule.due(time, step))
        {
          written.push_back(time);
          schedule.written(time, step);
          EXPECT_FALSE(schedule.due(time, step));
        }
    }
  ASSERT_EQ(written.size(), 3u);
  EXPECT_NEAR(written[0], 0.12, 1e-15);
  EXPECT_NEAR(written[1], 0.21, 1e-15);
  EXPECT_NEAR(written[2], 0.30, 1e-15);
  // The final state of a run is written whatever the schedule.
  EXPECT_TRUE(schedule.due(time + 0.01, 11, true));

  // An interval below the round-off of the time.
  OutputSchedule tiny(1e-20);
  tiny.written(1., 1);
  EXPECT_GT(tiny.next_time(), 1.);
  // (so every later step is due)
  EXPECT_TRUE(tiny.due(1. + 1e-9, 2));

  OutputSchedule every(0., 4);
  EXPECT_TRUE(every.active());
  EXPECT_FALSE(every.due(1., 3));
  EXPECT_TRUE(every.due(1., 4));
  EXPECT_FALSE(OutputSchedule(0., 0).active());
}



TEST(DynamicRelaxation, KineticDampingConvergenceAndRest)
{
  ParticleStore<2> particles;
  particles.enable_affine_velocity();
  particles.add(
    Point<2>(0.5, 0.5), 0, 2., 1., Tensor<1, 2>({1., 0.}), {}, 0, 0);
  particles.affine_velocity.back()[0][1] = 3.;

  DynamicRelaxation::Settings settings;
  settings.kinetic_damping     = true;
  settings.convergence_window  = 3;
  settings.load_time           = 0.5;
  settings.rest_tolerance      = 1e-3;
  settings.stop_when_converged = true;
  DynamicRelaxation relaxation(settings);
  Monitors          m;
  m.kinetic_energy = 1.;
  relaxation.reset(m, 100.);

  // Rising kinetic energy: no damping.
  m.kinetic_energy = 2.;
  relaxation.apply_kinetic_damping(m,
                                   particles,
                                   static_cast<Membrane<2> *>(nullptr));
  EXPECT_EQ(particles.velocity[0][0], 1.);
  EXPECT_EQ(m.dissipated_energy, 0.);
  // Past the peak: everything stops, the energy is booked.
  m.kinetic_energy = 1.5;
  relaxation.apply_kinetic_damping(m,
                                   particles,
                                   static_cast<Membrane<2> *>(nullptr));
  EXPECT_EQ(particles.velocity[0].norm(), 0.);
  EXPECT_EQ(particles.affine_velocity[0].norm(), 0.);
  EXPECT_EQ(m.dissipated_energy, 1.5);
  EXPECT_EQ(m.kinetic_energy, 0.);

  // Eq. (30): not before the load time, then the whole window.
  m.dr_energy_ratio = 0.01;
  m.dr_force_ratio  = 0.01;
  EXPECT_EQ(relaxation.update(m, 0.4), Termination::running);
  EXPECT_EQ(relaxation.converged_steps(), 0u);
  EXPECT_EQ(relaxation.update(m, 0.6), Termination::running);
  EXPECT_EQ(relaxation.update(m, 0.7), Termination::running);
  m.dr_force_ratio = 0.1; // above E_f = 0.05: starts again
  EXPECT_EQ(relaxation.update(m, 0.8), Termination::running);
  EXPECT_EQ(relaxation.converged_steps(), 0u);
  m.dr_force_ratio = 0.01;
  EXPECT_EQ(relaxation.update(m, 0.9), Termination::running);
  EXPECT_EQ(relaxation.update(m, 1.0), Termination::running);
  EXPECT_EQ(relaxation.update(m, 1.1), Termination::dr_converged);

  // At rest: below 1e-3 x 100 J only counts once it has moved.
  settings.stop_when_converged = false;
  settings.stop_when_at_rest   = true;
  DynamicRelaxation rest(settings);
  rest.reset(m, 100.);
  m.grid_kinetic_energy = 0.01;
  for (unsigned int s = 0; s < 5; ++s)
    EXPECT_EQ(rest.update(m, 1. + s), Termination::running);
  m.grid_kinetic_energy = 1.;
  EXPECT_EQ(rest.update(m, 7.), Termination::running);
  m.grid_kinetic_energy = 0.01;
  EXPECT_EQ(rest.update(m, 8.), Termination::running);
  EXPECT_EQ(rest.update(m, 9.), Termination::running);
  EXPECT_EQ(rest.update(m, 10.), Termination::at_rest);

  // The state round trip (checkpoints).
  DynamicRelaxation restored(settings);
  restored.set_state(rest.energy_state(), rest.counter_state());
  EXPECT_EQ(restored.energy_state(), rest.energy_state());
  EXPECT_EQ(restored.counter_state(), rest.counter_state());
}



TEST(EnergyBalance, EnergiesAndRelaxationRatios)
{
  const auto grid = test_tools::make_unit_box_grid<2>(4);
  std::vector<std::unique_ptr<Material>> materials;
  materials.push_back(std::make_unique<LinearElastic>(1e6, 0.25, 1000.));
  ParticleStore<2>      particles;
  const Tensor<1, 2>    g({0., -9.81});
  double                ke = 0, pe = 0, se = 0;
  SymmetricTensor<2, 3> sigma;
  sigma[0][0]    = -2e3;
  sigma[1][1]    = -1e3;
  sigma[0][1]    = 500.;
  const double E = 1e6, nu = 0.25;
  const double w
    = 0.5
      * ((1 + nu) / E * (sigma * sigma) - nu / E * std::pow(trace(sigma), 2));
  for (unsigned int n = 0; n < 20; ++n)
    {
      const Point<2>     x(0.05 + 0.045 * n, 0.1 + 0.04 * n);
      const Tensor<1, 2> v({0.1 * n, -0.05 * n});
      const double       m = 1. + 0.1 * n, V = 1e-3 * (1 + n % 3);
      particles.add(
        x, grid->find_cell_brute_force(x, 1e-12), m, V, v, sigma, 0, 0);
      ke += 0.5 * m * v.norm_square();
      pe -= m * (g * x);
      se += V * w;
    }
  particles.sort_by_cell(grid->n_cells());
  Monitors monitors;
  EnergyBalance::compute_energies<2>(
    particles, materials, nullptr, g, monitors);
  EXPECT_NEAR(monitors.kinetic_energy, ke, 1e-14 * ke);
  EXPECT_NEAR(monitors.potential_energy, pe, 1e-14 * pe);
  EXPECT_NEAR(monitors.strain_energy, se, 1e-14 * se);
  EXPECT_NEAR(EnergyBalance::potential_energy_above(particles, g, Point<2>()),
              pe,
              1e-14 * pe);

  // A step's work and the Eq. (30) ratios from the nodal velocities.
  NodalFields<2> nodes;
  nodes.resize(grid->n_nodes());
  nodes.activate(grid->cell_nodes[0]);
  double nodal_ke = 0;
  for (const unsigned int i : nodes.active_nodes)
    {
      nodes.mass[i]     = 2.;
      nodes.velocity[i] = Tensor<1, 2>({0.3, 0.4});
      nodal_ke += 0.5 * 2. * 0.25;
    }
  Stages::GridUpdateResult step;
  step.external_work_increment = CompensatedSum(4.);
  step.damping_work_increment  = CompensatedSum(1.);
  step.unbalanced_norm_sq      = CompensatedSum(1.);
  step.external_norm_sq        = CompensatedSum(100.);
  std::vector<double> totals;
  for (const CompensatedSum &e : EnergyBalance::local_energies<2>(
         particles, materials, nullptr, g, &nodes))
    totals.push_back(e.value());
  EnergyBalance::set_energies(make_array_view(std::as_const(totals)), monitors);
  EXPECT_NEAR(monitors.kinetic_energy, ke, 1e-14 * ke);
  EnergyBalance::add_step(step, {}, 2, monitors);
  EXPECT_EQ(monitors.external_work, 4.);
  EXPECT_EQ(monitors.dissipated_energy, 1.);
  EXPECT_EQ(monitors.lost_particles, 2u);
  EXPECT_DOUBLE_EQ(monitors.grid_kinetic_energy, nodal_ke);
  EXPECT_DOUBLE_EQ(monitors.dr_energy_ratio, nodal_ke / 4.);
  EXPECT_DOUBLE_EQ(monitors.dr_force_ratio, 0.1);
}



namespace
{
  // 10^5 pseudo-random terms of alternating sign and magnitudes 1e-6 to 1e6
  // (a linear congruential generator from @p seed).
  std::vector<double>
  alternating_terms(unsigned int seed)
  {
    std::vector<double> terms;
    for (unsigned int k = 0; k < 100000; ++k)
      {
        seed           = 1664525u * seed + 1013904223u;
        const double r = (seed >> 8) * (1. / (1u << 24));
        terms.push_back((k % 2 ? -1. : 1.) * r
                        * std::pow(10., int(k % 13) - 6));
      }
    return terms;
  }

  // f() on 1 thread, then on 2 (the thread limit restored after).
  template <typename Function>
  auto
  on_one_and_two_threads(const Function &f)
  {
    const unsigned int threads = MultithreadInfo::n_threads();
    MultithreadInfo::set_thread_limit(1);
    const auto one_thread = f();
    MultithreadInfo::set_thread_limit(2);
    EXPECT_EQ(MultithreadInfo::n_threads(), 2u);
    const auto two_threads = f();
    MultithreadInfo::set_thread_limit(threads);
    return std::make_pair(one_thread, two_threads);
  }
} // namespace



// The monitors' sums over points (energies, body masses, the geotube's
// pressure fit) are compensated so that they do not depend on the order of
// the points nor on how they are split over MPI processes. 10^5 terms of
// alternating sign and magnitudes 1e-6 to 1e6, summed forwards, backwards
// and in three parts combined as sum_over_processes() does: the plain sums
// of the two orders differ by 7.4e-15 of the sum (asserted: more than
// 1e-15, or the terms no longer test anything), the compensated ones are
// identical forwards and backwards and differ by 2.1e-16 split in three
// (asserted: 4e-16).
TEST(CompensatedSum, IndependentOfOrderAndSplit)
{
  const std::vector<double> terms = alternating_terms(12345);

  double         plain_forward = 0, plain_backward = 0;
  CompensatedSum forward, backward;
  for (unsigned int k = 0; k < terms.size(); ++k)
    {
      plain_forward += terms[k];
      forward.add(terms[k]);
      plain_backward += terms[terms.size() - 1 - k];
      backward.add(terms[terms.size() - 1 - k]);
    }
  // Three "processes", combined as sum_over_processes() combines them.
  std::vector<CompensatedSum> parts(3);
  for (unsigned int k = 0; k < terms.size(); ++k)
    parts[k * 3 / terms.size()].add(terms[k]);
  double s = 0, c = 0;
  for (const auto &p : parts)
    {
      s += p.sum();
      c += p.correction();
    }
  const double split = s + c;

  const double scale = std::abs(forward.value());
  EXPECT_GT(std::abs(plain_forward - plain_backward), 1e-15 * scale)
    << "the plain sums happen to agree: the test no longer shows anything";
  EXPECT_NEAR(forward.value(), backward.value(), 4e-16 * scale);
  EXPECT_NEAR(forward.value(), split, 4e-16 * scale);
  // A single process through MPI_COMM_SELF: the same value.
  EXPECT_EQ(sum_over_processes(std::vector<CompensatedSum>{forward},
                               MPI_COMM_SELF)[0],
            forward.value());
  EXPECT_EQ(sum_over_processes(forward, MPI_COMM_SELF), forward.value());
}



// The loops over nodes and cells sum in parallel through
// CellLoops::compensated_sums: fixed chunks of 512 items, merged in order.
// The same terms on 1 and 2 threads give the same bits; the value is the
// serial compensated sum's (measured: equal for both sums of these terms,
// so asserted equal; in general it may differ by a rounding), and a sum of
// at most one chunk is the serial one bit for bit.
TEST(CompensatedSum, ChunkedInParallelIndependentOfThreads)
{
  const std::vector<double> terms   = alternating_terms(54321);
  const auto                chunked = [&](const unsigned int n) {
    return CellLoops::compensated_sums<2>(
      n, [&](const unsigned int a, std::array<CompensatedSum, 2> &sums) {
        sums[0].add(terms[a]);
        sums[1].add(terms[a] * terms[a]);
      });
  };
  const auto [one_thread, two_threads]
    = on_one_and_two_threads([&]() { return chunked(terms.size()); });
  CompensatedSum serial[2];
  for (const double t : terms)
    {
      serial[0].add(t);
      serial[1].add(t * t);
    }
  for (unsigned int q = 0; q < 2; ++q)
    {
      std::cout << "[ measured ] chunked sum " << q << " against serial: "
                << std::abs(two_threads[q].value() - serial[q].value())
                     / std::abs(serial[q].value())
                << " relative" << std::endl;
      EXPECT_EQ(one_thread[q].sum(), two_threads[q].sum());
      EXPECT_EQ(one_thread[q].correction(), two_threads[q].correction());
      EXPECT_EQ(two_threads[q].value(), serial[q].value());
    }
  // One chunk: the serial sum itself.
  CompensatedSum first;
  for (unsigned int k = 0; k < 512; ++k)
    first.add(terms[k]);
  EXPECT_EQ(chunked(512)[0].sum(), first.sum());
  EXPECT_EQ(chunked(512)[0].correction(), first.correction());
}



// The scene monitors' maxima over the points (CellLoops::parallel_maxima):
// chunks of 4096 in parallel, merged with std::max. A maximum is exact, so
// 1 and 2 threads give the serial loop's values; an item may raise one
// maximum and not the other, and no item leaves the initial values.
TEST(CellLoops, ParallelMaximaAreTheSerialOnes)
{
  const std::vector<double> terms  = alternating_terms(54321);
  const auto                maxima = [&](const unsigned int n) {
    return CellLoops::parallel_maxima<2>(
      n, {{-1., 0.}}, [&](const unsigned int a, std::array<double, 2> &m) {
        m[0] = std::max(m[0], terms[a]);
        if (a % 3 == 0)
          m[1] = std::max(m[1], terms[a] * terms[a]);
      });
  };
  std::array<double, 2> serial = {{-1., 0.}};
  for (unsigned int a = 0; a < terms.size(); ++a)
    {
      serial[0] = std::max(serial[0], terms[a]);
      if (a % 3 == 0)
        serial[1] = std::max(serial[1], terms[a] * terms[a]);
    }
  const auto [one_thread, two_threads]
    = on_one_and_two_threads([&]() { return maxima(terms.size()); });
  EXPECT_EQ(one_thread, serial);
  EXPECT_EQ(two_threads, serial);
  EXPECT_GT(serial[0], -1.);
  EXPECT_EQ(maxima(0), (std::array<double, 2>{{-1., 0.}}));
}



namespace
{
  // Stages::stable_time_step against a plain loop over the points of each
  // occupied cell. Runs of four materials in random order: a linear fluid
  // (its own vectorised wave speeds), a power-law fluid (20 Pa s: its
  // viscous limit shows in the bits) and a fluid whose derived class
  // changes the wave speed (both take wave_speed() per point), and an
  // elastic solid (the default, no viscosity).
  template <int dim>
  void
  check_stable_time_step()
  {
    struct StiffFluid : NewtonianFluid
    {
      using NewtonianFluid::NewtonianFluid;
      double
      wave_speed(const double rho) const override
      {
        return 2. * NewtonianFluid::wave_speed(rho);
      }
    };
    std::vector<std::unique_ptr<Material>> materials;
    materials.push_back(std::make_unique<NewtonianFluid>(
      2.5e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.));
    materials.push_back(std::make_unique<NewtonianFluid>(
      2.5e6, 20., 1000, NewtonianFluid::PressureLaw::power, 7, 0.));
    materials.push_back(std::make_unique<StiffFluid>(
      1e6, 1e-3, 1000, NewtonianFluid::PressureLaw::linear, 7, 0.));
    materials.push_back(std::make_unique<LinearElastic>(1e7, 0.3, 2000));

    const auto         grid = test_tools::make_unit_box_grid<dim>(8);
    ParticleStore<dim> particles;
    std::mt19937       rng(11 + dim);
    std::uniform_real_distribution<double> u(0.02, 0.98), f(0.9, 1.1), v(-3, 3);
    std::uniform_int_distribution<unsigned int> material(0, 3);
    for (unsigned int n = 0; n < 600; ++n)
      {
        Point<dim>     x;
        Tensor<1, dim> velocity;
        for (unsigned int d = 0; d < dim; ++d)
          {
            // Left of x = 0.6 only: the cells on the right stay empty.
            x[d]        = (d == 0 ? 0.6 : 1.) * u(rng);
            velocity[d] = v(rng);
          }
        const unsigned int c = grid->find_cell_brute_force(x, 1e-12);
        ASSERT_NE(c, BackgroundGrid<dim>::invalid);
        const unsigned int m = (n % 5 == 0) ? material(rng) : 0;
        particles.add(x,
                      c,
                      1e-3 * f(rng) * materials[m]->reference_density(),
                      1e-3 * f(rng),
                      velocity,
                      {},
                      m,
                      0);
      }
    particles.sort_by_cell(grid->n_cells());

    // The plain loop over each occupied cell's points.
    const auto expected = [&]() {
      double              dt = std::numeric_limits<double>::max();
      std::vector<double> stiffness(grid->n_cells(), 0.);
      for (const unsigned int c : particles.occupied_cells)
        {
          const double h     = grid->min_altitude(c);
          double       speed = 0;
          for (unsigned int p = particles.cell_begin(c);
               p < particles.cell_end(c);
               ++p)
            {
              const Material &mat = *materials[particles.material_id[p]];
              const double    rho = particles.mass[p] / particles.volume[p];
              const double    s   = mat.wave_speed(rho)
                               + particles.velocity[p].norm()
                               + 2. * dim * mat.viscosity() / (rho * h);
              speed = std::max(speed, s);
              stiffness[c] += particles.volume[p] * rho * s * s;
            }
          dt = std::min(dt, h / speed);
        }
      return std::make_pair(dt, stiffness);
    };
    const auto check = [&]() {
      const auto [expected_dt, expected_stiffness] = expected();
      const auto [one_thread, two_threads] = on_one_and_two_threads([&]() {
        std::vector<double> stiffness;
        const double        dt = Stages::stable_time_step(
          *grid, particles, materials, 0.5, &stiffness);
        return std::make_pair(dt, stiffness);
      });
      EXPECT_EQ(one_thread.first, 0.5 * expected_dt);
      EXPECT_EQ(two_threads.first, 0.5 * expected_dt);
      EXPECT_EQ(one_thread.second, expected_stiffness);
      EXPECT_EQ(two_threads.second, expected_stiffness);
      EXPECT_EQ(Stages::stable_time_step(*grid, particles, materials, 1.),
                expected_dt);
    };
    check();
    // Not a vacuous comparison: every material is met.
    std::array<unsigned int, 4> count = {};
    for (const auto m : particles.material_id)
      ++count[m];
    for (const unsigned int n : count)
      EXPECT_GT(n, 10u);

    // As MPI's ghost copies: the points of an empty cell appended after
    // the sorted ones, the cell merged into occupied_cells in order, so
    // that the occupied cells' points are no longer one range. The fastest
    // points, so that they set the step.
    const double before
      = Stages::stable_time_step(*grid, particles, materials, 1.);
    unsigned int empty = 0;
    while (particles.occupied_slot(empty) != numbers::invalid_unsigned_int)
      ++empty;
    ASSERT_LT(empty, particles.occupied_cells.back());
    const unsigned int begin = particles.size();
    Tensor<1, dim>     fast;
    fast[0] = 100.;
    for (unsigned int n = 0; n < 3; ++n)
      particles.add(grid->vertices(empty)[0],
                    empty,
                    materials[0]->reference_density() * 1e-3,
                    1e-3,
                    fast,
                    {},
                    0,
                    0);
    particles.append_cell_range(empty, begin, particles.size());
    auto &cells = particles.occupied_cells;
    cells.insert(std::lower_bound(cells.begin(), cells.end(), empty), empty);
    check();
    EXPECT_LT(Stages::stable_time_step(*grid, particles, materials, 1.),
              0.9 * before);
  }
} // namespace



TEST(StableTimeStep, IsThePointsBoundOverRunsOfMaterials)
{
  check_stable_time_step<2>();
  check_stable_time_step<3>();
}



namespace
{
  // Stages::update_positions: x_p += dt sum_k lambda_k(x_p) v_k, and the
  // returned guard ratio max_p |dx_p| / h_c (h_c the smallest altitude of
  // the point's cell), computed there as the root of the largest squared
  // ratio. Against a loop over the points, with an affine nodal velocity,
  // so that the displacements differ from point to point; the ratio to a
  // few roundings (it only guards, > 1 is unstable, and is not written).
  template <int dim>
  void
  check_displacement_ratio()
  {
    const auto         grid = test_tools::make_unit_box_grid<dim>(4);
    ParticleStore<dim> particles;
    std::mt19937       rng(5 + dim);
    std::uniform_real_distribution<double> u(0.02, 0.98);
    for (unsigned int n = 0; n < 300; ++n)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = u(rng);
        particles.add(x,
                      grid->find_cell_brute_force(x, 1e-12),
                      1.,
                      1.,
                      Tensor<1, dim>(),
                      {},
                      0,
                      0);
      }
    particles.sort_by_cell(grid->n_cells());
    NodalFields<dim> nodes;
    nodes.resize(grid->n_nodes());
    for (unsigned int i = 0; i < grid->n_nodes(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        nodes.velocity[i][d] = 1. + d + 3. * grid->node_positions[i][0]
                               - grid->node_positions[i][dim - 1];
    const double dt = 0.01;

    double                  expected = 0;
    std::vector<Point<dim>> moved(particles.position);
    for (const unsigned int c : particles.occupied_cells)
      for (unsigned int p = particles.cell_begin(c); p < particles.cell_end(c);
           ++p)
        {
          const auto     lambda = grid->barycentric(c, particles.position[p]);
          Tensor<1, dim> dx;
          for (unsigned int k = 0; k < dim + 1; ++k)
            dx += lambda[k] * nodes.velocity[grid->cell_nodes[c][k]];
          dx *= dt;
          moved[p] += dx;
          expected = std::max(expected, dx.norm() / grid->min_altitude(c));
        }
    const double ratio = Stages::update_positions(*grid, nodes, dt, particles);
    std::cout << dim << "D displacement ratio " << ratio << ", relative to "
              << "the loop's " << std::abs(ratio - expected) / expected
              << std::endl;
    EXPECT_EQ(particles.position, moved);
    EXPECT_NEAR(ratio, expected, 4e-16 * expected);
    EXPECT_GT(expected, 0.1); // not a vacuous comparison
  }
} // namespace



TEST(PositionUpdate, DisplacementRatioIsTheLargestMoveOverItsCellsAltitude)
{
  check_displacement_ratio<2>();
  check_displacement_ratio<3>();
}
