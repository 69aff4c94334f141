// NodalConstraints on a simplex box (2D and 3D), floor = boundary id 2:
// - each wall type on a floor node: apply() (grid update) and
//   apply_kinematic() (remap) for a velocity into and one away from the
//   floor: fixed stops the node; roller removes the normal component both
//   ways; slip and friction remove it only into the wall, friction also
//   reduces the tangential speed by mu v_n, in apply() only;
// - friction once per step: points in the bottom cell row move at v0 into a
//   'friction mu' floor (no stress, no gravity); after p2g, grid_update, g2p
//   and remap, (a) every floor node has the tangential speed |v_t| - mu v_n
//   after the grid update, (b) the points' tangential momentum fell by
//   exactly the friction impulse sum_floor m_i mu v_n, and (c) the remapped
//   nodal momentum (which moves the points) equals the points' momentum:
//   the remap gives no second friction impulse, and no floor node moves
//   into the floor. All to 1e-12 (relative).
// - contact kept: a node a unilateral wall pushed in the grid update keeps
//   zero normal velocity in the remap (both ways), a node static friction
//   stopped stays at rest, a node the wall did not push may leave;
// - the parser reads 'slip' as the unilateral frictionless wall.

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/step/stages.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <random>

using namespace fsgmpm;

namespace
{
  constexpr double mu = 0.4;

  template <int dim>
  std::unique_ptr<BackgroundGrid<dim>>
  make_grid()
  {
    return test_tools::make_unit_box_grid<dim>(4);
  }

  // A node in the middle of the floor y = 0 (away from the other walls).
  template <int dim>
  unsigned int
  floor_node(const BackgroundGrid<dim> &grid)
  {
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      {
        const Point<dim> &x      = grid.node_positions[i];
        bool              inside = std::abs(x[1]) < 1e-12;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != 1)
            inside = inside && x[d] > 0.1 && x[d] < 0.9;
        if (inside)
          return i;
      }
    return BackgroundGrid<dim>::invalid;
  }

  template <int dim>
  Tensor<1, dim>
  vector(const double x, const double y, const double z)
  {
    Tensor<1, dim> v;
    v[0] = x;
    v[1] = y;
    if (dim == 3)
      v[2] = z;
    return v;
  }

  template <int dim>
  void
  check_wall_types()
  {
    const auto         grid = make_grid<dim>();
    const unsigned int i    = floor_node(*grid);
    ASSERT_NE(i, BackgroundGrid<dim>::invalid);
    // Floor outward normal (0, -1): v_y < 0 moves into the floor.
    const Tensor<1, dim> into = vector<dim>(0.6, -0.5, 0.8),
                         away = vector<dim>(0.6, 0.5, 0.8);
    const double vt           = (dim == 3) ? 1. : 0.6;
    struct Case
    {
      std::string    walls;
      Tensor<1, dim> into_update, into_remap, away_update, away_remap;
    };
    const Tensor<1, dim>    tangential = vector<dim>(0.6, 0, 0.8);
    const Tensor<1, dim>    zero;
    const std::vector<Case> cases
      = {{"2: fixed", zero, zero, zero, zero},
         {"2: roller", tangential, tangential, tangential, tangential},
         {"2: slip", tangential, tangential, away, away},
         {"2: friction 0.4",
          tangential * (1 - mu * 0.5 / vt),
          tangential,
          away,
          away}};
    for (const Case &c : cases)
      {
        const NodalConstraints<dim> constraints(*grid,
                                                parse_wall_conditions(c.walls,
                                                                      "test"));
        const std::array<std::pair<Tensor<1, dim>, Tensor<1, dim>>, 4> checks
          = {{{into, c.into_update},
              {into, c.into_remap},
              {away, c.away_update},
              {away, c.away_remap}}};
        for (unsigned int k = 0; k < 4; ++k)
          {
            Tensor<1, dim> v = checks[k].first;
            if (k % 2 == 0)
              constraints.apply(i, v);
            else
              constraints.apply_kinematic(i, v);
            EXPECT_LT((v - checks[k].second).norm(), 1e-14)
              << c.walls << (k % 2 == 0 ? " apply(" : " apply_kinematic(")
              << checks[k].first << ") = " << v << ", expected "
              << checks[k].second;
          }
      }
  }

  template <int dim>
  void
  check_friction_once_per_step()
  {
    const auto                  grid = make_grid<dim>();
    const NodalConstraints<dim> constraints(
      *grid, parse_wall_conditions("2: friction 0.4", "test"));
    // Into the floor at vn = 0.5 with a tangential speed |v_t| = 1 (so the
    // floor nodes keep sliding: mu vn < |v_t|).
    const Tensor<1, dim> v0
      = (dim == 3) ? vector<dim>(0.6, -0.5, 0.8) : vector<dim>(1, -0.5, 0);
    const double         vn = 0.5;
    const Tensor<1, dim> t0 = v0 + vn * vector<dim>(0, 1, 0); // tangential

    ParticleStore<dim>                     particles;
    std::mt19937                           rng(11 + dim);
    std::uniform_real_distribution<double> u(0.02, 0.98), h(0.01, 0.24),
      m(0.5, 2.);
    for (unsigned int n = 0; n < 200; ++n)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = (d == 1) ? h(rng) : u(rng);
        const unsigned int c = grid->find_cell_brute_force(x, 1e-12);
        ASSERT_NE(c, BackgroundGrid<dim>::invalid);
        particles.add(x, c, m(rng), 1e-3, v0, SymmetricTensor<2, 3>(), 0, 0);
      }
    particles.sort_by_cell(grid->n_cells());
    const Tensor<1, dim> t_dir             = t0 / t0.norm();
    const auto           particle_momentum = [&]() {
      double p = 0, total_mass = 0;
      for (unsigned int q = 0; q < particles.size(); ++q)
        {
          p += particles.mass[q] * (particles.velocity[q] * t_dir);
          total_mass += particles.mass[q];
        }
      return std::make_pair(p, total_mass);
    };
    const auto [p0, total_mass] = particle_momentum();
    const double scale          = total_mass * v0.norm();

    NodalFields<dim> nodes;
    nodes.resize(grid->n_nodes());
    const double dt = 1e-3;
    Stages::p2g(*grid, particles, nodes);
    Stages::grid_update(constraints, Tensor<1, dim>(), 0., dt, nodes);
    double       impulse = 0;
    unsigned int n_floor = 0;
    for (const unsigned int i : nodes.active_nodes)
      if (constraints.is_constrained(i) && nodes.mass[i] > 0)
        {
          ++n_floor;
          impulse += nodes.mass[i] * mu * vn;
          EXPECT_NEAR(nodes.velocity[i] * t_dir, t0.norm() - mu * vn, 1e-12)
            << "grid update, floor node " << i;
          EXPECT_NEAR(nodes.velocity[i][1], 0, 1e-12);
        }
    EXPECT_GT(n_floor, 4u);
    Stages::g2p(*grid, nodes, dt, particles);
    Stages::remap(*grid, particles, constraints, nodes);

    const double p1      = particle_momentum().first;
    double       p_nodes = 0;
    for (const unsigned int i : nodes.active_nodes)
      {
        p_nodes += nodes.mass[i] * (nodes.velocity[i] * t_dir);
        if (constraints.is_constrained(i) && nodes.mass[i] > 0)
          {
            EXPECT_GE(nodes.velocity[i][1], -1e-12 * v0.norm())
              << "remapped floor node " << i << " moves into the floor";
          }
      }
    std::cout << "[ measured ] " << dim << "D: tangential momentum " << p0
              << " -> points " << p1 << ", remapped nodes " << p_nodes
              << "; friction impulse " << impulse << std::endl;
    EXPECT_NEAR(p0 - p1, impulse, 1e-12 * scale);
    EXPECT_NEAR(p_nodes, p1, 1e-12 * scale)
      << "the remap changed the tangential momentum (a second friction "
         "impulse?)";
  }

  // What the grid update's wall did is kept in the remap of the same step:
  // a node a unilateral wall pushed may not leave it (its remapped velocity
  // away from the wall loses the normal component), a node static friction
  // stopped stays at rest, and a node the wall did not push may leave.
  template <int dim>
  void
  check_contact_kept_in_the_remap()
  {
    const auto         grid = make_grid<dim>();
    const unsigned int i    = floor_node(*grid);
    ASSERT_NE(i, BackgroundGrid<dim>::invalid);
    const Tensor<1, dim> into       = vector<dim>(0.6, -0.5, 0.8),
                         away       = vector<dim>(0.6, 0.5, 0.8),
                         slow       = vector<dim>(0.1, -0.5, 0.);
    const Tensor<1, dim> tangential = vector<dim>(0.6, 0, 0.8);
    for (const std::string walls : {"2: slip", "2: friction 0.4"})
      {
        const NodalConstraints<dim> constraints(*grid,
                                                parse_wall_conditions(walls,
                                                                      "test"));
        Tensor<1, dim>              v       = into;
        const std::uint8_t          contact = constraints.apply(i, v);
        EXPECT_NE(contact, 0) << walls;
        Tensor<1, dim> remapped = away;
        constraints.apply_kinematic(i, remapped, contact);
        EXPECT_LT((remapped - tangential).norm(), 1e-14)
          << walls << ": pushed in the grid update, left in the remap";
        Tensor<1, dim>     free = away;
        const std::uint8_t none = constraints.apply(i, free);
        EXPECT_EQ(none, 0) << walls;
        constraints.apply_kinematic(i, free, none);
        EXPECT_LT((free - away).norm(), 1e-14) << walls;
      }
    const NodalConstraints<dim> friction(*grid,
                                         parse_wall_conditions("2: friction "
                                                               "0.4",
                                                               "test"));
    Tensor<1, dim>              v = slow; // |v_t| = 0.1 < mu v_n = 0.2: sticks
    const std::uint8_t          stuck = friction.apply(i, v);
    EXPECT_LT(v.norm(), 1e-14);
    Tensor<1, dim> remapped = tangential;
    friction.apply_kinematic(i, remapped, stuck);
    EXPECT_LT(remapped.norm(), 1e-14) << "stuck in the grid update, slid in "
                                         "the remap";
  }
} // namespace



TEST(WallConstraints, ContactKeptInTheRemap2D)
{
  check_contact_kept_in_the_remap<2>();
}

TEST(WallConstraints, ContactKeptInTheRemap3D)
{
  check_contact_kept_in_the_remap<3>();
}

TEST(WallConstraints, WallTypes2D)
{
  check_wall_types<2>();
}

TEST(WallConstraints, WallTypes3D)
{
  check_wall_types<3>();
}

TEST(WallConstraints, FrictionOncePerStep2D)
{
  check_friction_once_per_step<2>();
}

TEST(WallConstraints, FrictionOncePerStep3D)
{
  check_friction_once_per_step<3>();
}

TEST(WallConstraints, ParseSlip)
{
  const auto walls = parse_wall_conditions("0: slip, 1: roller, 2: friction "
                                           "0.5, 3: free",
                                           "Grid/Boundary conditions");
  EXPECT_EQ(walls.at(0).type, WallType::slip);
  EXPECT_EQ(walls.at(0).friction, 0.);
  EXPECT_EQ(walls.at(1).type, WallType::roller);
  EXPECT_EQ(walls.at(2).type, WallType::friction);
  EXPECT_EQ(walls.at(2).friction, 0.5);
  try
    {
      parse_wall_conditions("0: slip 0.3", "Grid/Boundary conditions");
      FAIL() << "'slip 0.3' accepted";
    }
  catch (const std::exception &e)
    {
      EXPECT_NE(std::string(e.what()).find("takes no coefficient"),
                std::string::npos)
        << e.what();
    }
  try
    {
      parse_wall_conditions("0: sticky", "Grid/Boundary conditions");
      FAIL() << "unknown wall type accepted";
    }
  catch (const std::exception &e)
    {
      EXPECT_NE(std::string(e.what()).find("slip"), std::string::npos)
        << e.what();
    }
}
