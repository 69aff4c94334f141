// APIC transfers (Simulation/Velocity transfer = APIC) on simplex grids,
// 2D and 3D, with random point positions and masses:
// - an affine velocity field v(x) = a + G x carried by the points
//   (v_p = v(x_p), C_p = G) maps to every active node exactly:
//   momentum / mass = v(x_i) to 1e-12 (relative). Without the affine part
//   (FLIP/PIC points) the same points give nodal errors of order |G| h,
//   which the test also checks, so the exactness is not a property of the
//   point layout;
// - back from the grid, an affine nodal field gives v_p = v(x_p) and
//   C_p = G to 1e-12.
// - Velocity transfer = APIC affine remap: APIC's affine momentum
//   sum_p N_i m_p (v_p + C_p (x_i - x_p)) after g2p is m_i v_i for any
//   (not affine) grid-updated field v_i on linear simplices, to 1e-12; the
//   remap keeps v_i at nodes whose points fill a quarter of their volume or
//   more and blends it with the mass average below (weight 4 x fill), to
//   1e-12 against a brute-force sum. The points fill part of the box, so
//   the test has full, partly filled and nearly empty nodes.

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/step/smoothing_fields.h>
#include <fsgmpm/step/stages.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <random>

using namespace fsgmpm;

namespace
{
  template <int dim>
  struct AffineField
  {
    Tensor<1, dim> a;
    Tensor<2, dim> G;

    Tensor<1, dim>
    operator()(const Point<dim> &x) const
    {
      return a + G * x;
    }
  };

  template <int dim>
  AffineField<dim>
  random_field(std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> u(-1, 1);
    AffineField<dim>                       f;
    for (unsigned int i = 0; i < dim; ++i)
      {
        f.a[i] = u(rng);
        for (unsigned int j = 0; j < dim; ++j)
          f.G[i][j] = 3 * u(rng);
      }
    return f;
  }

  template <int dim>
  std::unique_ptr<BackgroundGrid<dim>>
  make_grid()
  {
    return test_tools::make_unit_box_grid<dim>(4);
  }

  // Random points in the box with v_p = f(x_p) and, if apic, C_p = G.
  template <int dim>
  void
  fill(const BackgroundGrid<dim> &grid,
       const AffineField<dim>    &f,
       const bool                 apic,
       std::mt19937              &rng,
       ParticleStore<dim>        &particles)
  {
    std::uniform_real_distribution<double> u(0.02, 0.98), m(0.5, 2.);
    if (apic)
      particles.enable_affine_velocity();
    for (unsigned int n = 0; n < 400; ++n)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = u(rng);
        const unsigned int c = grid.find_cell_brute_force(x, 1e-12);
        ASSERT_NE(c, BackgroundGrid<dim>::invalid);
        particles.add(x, c, m(rng), 1e-3, f(x), {}, 0, 0);
        if (apic)
          particles.affine_velocity.back() = f.G;
      }
    particles.sort_by_cell(grid.n_cells());
  }

  // Largest |m_i v_i / m_i - f(x_i)| / |G| over the active nodes after p2g.
  template <int dim>
  double
  nodal_error(const BackgroundGrid<dim> &grid,
              const ParticleStore<dim>  &particles,
              const AffineField<dim>    &f,
              NodalFields<dim>          &nodes)
  {
    nodes.resize(grid.n_nodes());
    Stages::p2g(grid, particles, nodes);
    double error = 0;
    for (const unsigned int i : nodes.active_nodes)
      if (nodes.mass[i] > 1e-3)
        error = std::max(
          error,
          (nodes.momentum[i] / nodes.mass[i] - f(grid.node_positions[i])).norm()
            / f.G.norm());
    return error;
  }

  template <int dim>
  void
  check_affine_round_trip()
  {
    std::mt19937       rng(7 + dim);
    const auto         grid = make_grid<dim>();
    const auto         f    = random_field<dim>(rng);
    NodalFields<dim>   nodes;
    ParticleStore<dim> apic_points, flip_points;
    fill(*grid, f, true, rng, apic_points);
    fill(*grid, f, false, rng, flip_points);

    const double apic_error = nodal_error(*grid, apic_points, f, nodes);
    const double flip_error = nodal_error(*grid, flip_points, f, nodes);
    std::printf("measured %dD nodal velocity error / |G|: APIC %.2e, "
                "without the affine part %.2e\n",
                dim,
                apic_error,
                flip_error);
    EXPECT_LT(apic_error, 1e-12);
    EXPECT_GT(flip_error, 1e-3);

    // Grid to points: a new affine nodal field.
    const auto g = random_field<dim>(rng);
    nodes.resize(grid->n_nodes());
    Stages::p2g(*grid, apic_points, nodes);
    for (unsigned int i = 0; i < grid->n_nodes(); ++i)
      nodes.velocity[i] = g(grid->node_positions[i]);
    Stages::g2p(*grid, nodes, 1e-3, apic_points);
    SmoothingFields<dim> smoothing;
    smoothing.resize(1, grid->n_nodes());
    Stages::velocity_gradients(*grid, nodes, smoothing, apic_points);
    Stages::store_affine_velocity(smoothing, apic_points);
    double v_error = 0, C_error = 0;
    for (unsigned int p = 0; p < apic_points.size(); ++p)
      {
        v_error = std::max(
          v_error,
          (apic_points.velocity[p] - g(apic_points.position[p])).norm());
        C_error
          = std::max(C_error, (apic_points.affine_velocity[p] - g.G).norm());
      }
    EXPECT_LT(v_error, 1e-12 * g.G.norm());
    EXPECT_LT(C_error, 1e-12 * g.G.norm());
  }

  template <int dim>
  void
  check_affine_remap()
  {
    std::mt19937                           rng(11 + dim);
    std::uniform_real_distribution<double> u(0.02, 0.98), m(0.5, 2.), v(-1, 1);
    const auto                             grid = make_grid<dim>();
    grid->compute_node_volumes();
    ParticleStore<dim> points;
    points.enable_affine_velocity();
    // Points in x_0 < 0.6; their volumes fill that part about once.
    const unsigned int n      = 300 * dim;
    const double       volume = 0.6 / n;
    for (unsigned int k = 0; k < n; ++k)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = u(rng);
        x[0] *= 0.6;
        const unsigned int c = grid->find_cell_brute_force(x, 1e-12);
        ASSERT_NE(c, BackgroundGrid<dim>::invalid);
        points.add(x, c, m(rng), volume, {}, {}, 0, 0);
      }
    points.sort_by_cell(grid->n_cells());

    NodalFields<dim> nodes;
    nodes.resize(grid->n_nodes());
    Stages::p2g(*grid, points, nodes);
    // A grid-updated velocity that is not affine.
    std::vector<Tensor<1, dim>> updated(grid->n_nodes());
    for (const unsigned int i : nodes.active_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        nodes.velocity[i][d] = updated[i][d] = v(rng);
    Stages::g2p(*grid, nodes, 1e-3, points);
    SmoothingFields<dim> smoothing;
    smoothing.resize(1, grid->n_nodes());
    Stages::velocity_gradients(*grid, nodes, smoothing, points);
    Stages::store_affine_velocity(smoothing, points);

    // Brute force: APIC's affine momentum, the mass average, the fill.
    std::vector<Tensor<1, dim>> affine(grid->n_nodes()),
      average(grid->n_nodes());
    std::vector<double> mass(grid->n_nodes()), fill(grid->n_nodes());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const unsigned int c      = points.cell[p];
        const auto         lambda = grid->barycentric(c, points.position[p]);
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid->cell_nodes[c][k];
            const double       w = lambda[k] * points.mass[p];
            affine[i]
              += w
                 * (points.velocity[p]
                    + points.affine_velocity[p]
                        * (grid->node_positions[i] - points.position[p]));
            average[i] += w * points.velocity[p];
            mass[i] += w;
            fill[i] += lambda[k] * points.volume[p] / grid->node_volume[i];
          }
      }

    const NodalConstraints<dim> no_walls(*grid, {});
    Stages::remap<dim>(*grid, points, no_walls, nodes, nullptr, true);
    double       identity_error = 0, remap_error = 0;
    unsigned int full = 0, blended = 0;
    for (const unsigned int i : nodes.active_nodes)
      if (mass[i] > 0)
        {
          identity_error = std::max(identity_error,
                                    (affine[i] / mass[i] - updated[i]).norm());
          const double w = std::min(1., 4 * fill[i]);
          (w == 1 ? full : blended) += 1;
          remap_error
            = std::max(remap_error,
                       (nodes.velocity[i]
                        - (w * updated[i] + (1 - w) * average[i] / mass[i]))
                         .norm());
        }
    std::printf("measured %dD affine remap: |affine momentum / m - v_i| "
                "%.1e, remap error %.1e; %u full and %u blended nodes\n",
                dim,
                identity_error,
                remap_error,
                full,
                blended);
    EXPECT_LT(identity_error, 1e-12);
    EXPECT_LT(remap_error, 1e-12);
    EXPECT_GT(full, 0u);
    EXPECT_GT(blended, 0u);
  }
} // namespace

TEST(ApicTransfer, AffineRemapKeepsUpdatedVelocity2D)
{
  check_affine_remap<2>();
}

TEST(ApicTransfer, AffineRemapKeepsUpdatedVelocity3D)
{
  check_affine_remap<3>();
}

TEST(ApicTransfer, AffineFieldIsExact2D)
{
  check_affine_round_trip<2>();
}

TEST(ApicTransfer, AffineFieldIsExact3D)
{
  check_affine_round_trip<3>();
}
