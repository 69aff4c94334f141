// The moving wall (a lifted gate) on a simplex unit box with h = 1/4:
// - its prescribed motion: the piecewise-linear velocity and its exact
//   integral (1e-15);
// - the nodes it acts on: those of its plane inside its current extent,
//   counted as the gate's lower edge rises past node rows (2D and 3D);
// - its constraint: on an active node the velocity relative to the wall
//   may not point into it (slip, frictionless), may leave it, and keeps its
//   tangential part; nodes below the lifted edge are free; Eq. (30)'s
//   force criterion drops the normal component there;
// - the other sides: a lid (material side +y) sliding in x; a gate on a
//   roller floor (the corner node keeps both constraints);
// - input checks: a plane off the grid lines, a normal velocity, times not
//   starting at 0, spacing.

#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/moving_wall.h>
#include <fsgmpm/scene/parameter_path.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <cctype>

using namespace fsgmpm;

namespace
{
  template <int dim>
  MovingWallParameters
  gate(const std::string &history, const std::string &x = "0.5")
  {
    auto prm = test_tools::make_parameters("");
    prm->enter_subsection("Moving wall");
    prm->set("Enabled", "true");
    prm->set("Material side", "-x");
    prm->set("Lower corner", x + (dim == 2 ? ", 0" : ", 0, 0"));
    prm->set("Upper corner", x + (dim == 2 ? ", 1" : ", 1, 1"));
    prm->set("Velocity history", history);
    prm->leave_subsection();
    MovingWallParameters p;
    p.parse_parameters(*prm, dim);
    return p;
  }

  // deal.II wraps messages over lines: compare with single spaces.
  std::string
  flat(const std::exception &e)
  {
    std::string text;
    for (const char c : std::string(e.what()))
      if (!std::isspace(static_cast<unsigned char>(c)))
        text += c;
      else if (!text.empty() && text.back() != ' ')
        text += ' ';
    return text;
  }

  template <int dim>
  unsigned int
  node_at(const BackgroundGrid<dim> &grid, const double x, const double y)
  {
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      if (std::abs(grid.node_positions[i][0] - x) < 1e-12
          && std::abs(grid.node_positions[i][1] - y) < 1e-12
          && (dim == 2
              || std::abs(grid.node_positions[i][dim - 1] - 0.5) < 1e-12))
        return i;
    return BackgroundGrid<dim>::invalid;
  }

  template <int dim>
  void
  check_gate()
  {
    const auto grid = test_tools::make_unit_box_grid<dim>(4);
    // At rest for 10 ms, then lifted: ramp to 1 m/s over 0.1 s.
    const std::string lift = (dim == 2) ? "0: 0 0, 0.01: 0 0, 0.11: 0 1"
                                        : "0: 0 0 0, 0.01: 0 0 0, 0.11: 0 1 0";
    MovingWall<dim>   wall(gate<dim>(lift), *grid);
    EXPECT_NEAR(wall.velocity(0.06)[1], 0.5, 1e-15);
    EXPECT_NEAR(wall.displacement(0.06)[1], 0.5 * 0.05 * 0.5, 1e-15);
    EXPECT_NEAR(wall.displacement(0.31)[1], 0.05 + 0.2, 1e-15);
    EXPECT_EQ(wall.velocity(0.31)[0], 0.);

    // Nodes of the plane x = 0.5: 5 per column of nodes (y = 0 ... 1).
    const unsigned int per_row = (dim == 2) ? 1 : 5;
    EXPECT_EQ(wall.n_active_nodes(), 5 * per_row);
    wall.set_time(0.31); // lower edge at y = 0.25 exactly: still holds it
    EXPECT_EQ(wall.n_active_nodes(), 4 * per_row);
    wall.set_time(0.32); // edge at 0.26
    EXPECT_EQ(wall.n_active_nodes(), 3 * per_row);

    // The constraint through NodalConstraints (no other walls).
    MovingWallParameters  p = gate<dim>(lift);
    NodalConstraints<dim> constraints(*grid, {}, p);
    constraints.set_time(0.32);
    const unsigned int held = node_at(*grid, 0.5, 0.5);
    const unsigned int free = node_at(*grid, 0.5, 0.25);
    ASSERT_NE(held, BackgroundGrid<dim>::invalid);
    ASSERT_NE(free, BackgroundGrid<dim>::invalid);
    EXPECT_TRUE(constraints.is_constrained(held));
    EXPECT_FALSE(constraints.is_constrained(free));

    Tensor<1, dim> into, away;
    into[0] = 2., into[1] = -0.3;
    away[0] = -2., away[1] = -0.3;
    Tensor<1, dim> v = into;
    constraints.apply(held, v);
    EXPECT_EQ(v[0], 0.);
    EXPECT_EQ(v[1], -0.3); // frictionless: the wall's lift does not drag
    v = into;
    constraints.apply_kinematic(held, v);
    EXPECT_EQ(v[0], 0.);
    v = away;
    constraints.apply(held, v);
    EXPECT_EQ(v, away); // the material may leave the gate
    v = into;
    constraints.apply(free, v);
    EXPECT_EQ(v, into); // below the lifted edge the flow passes
    Tensor<1, dim> f = into;
    constraints.project_out(held, f);
    EXPECT_EQ(f[0], 0.);
    EXPECT_EQ(f[1], -0.3);
  }
} // namespace

TEST(MovingWall, Gate2D)
{
  check_gate<2>();
}

TEST(MovingWall, Gate3D)
{
  check_gate<3>();
}

TEST(MovingWall, LidAndCorner)
{
  const auto grid = test_tools::make_unit_box_grid<2>(4);
  auto       prm  = test_tools::make_parameters("");
  set_parameter(*prm, "Moving wall/Enabled", "true");
  set_parameter(*prm, "Moving wall/Material side", "+y");
  set_parameter(*prm, "Moving wall/Lower corner", "0, 0.5");
  set_parameter(*prm, "Moving wall/Upper corner", "0.5, 0.5");
  set_parameter(*prm, "Moving wall/Velocity history", "0: 1  0");
  MovingWallParameters lid;
  lid.parse_parameters(*prm, 2);
  NodalConstraints<2> constraints(*grid, {}, lid);
  EXPECT_EQ(constraints.get_moving_wall()->n_active_nodes(), 3u);
  constraints.set_time(0.25); // x from 0.25 to 0.75
  EXPECT_EQ(constraints.get_moving_wall()->n_active_nodes(), 3u);
  EXPECT_NEAR(constraints.get_moving_wall()->displacement(0.25)[0],
              0.25,
              1e-15);
  const unsigned int i = node_at(*grid, 0.75, 0.5);
  ASSERT_TRUE(constraints.is_constrained(i));
  EXPECT_FALSE(constraints.is_constrained(node_at(*grid, 0., 0.5)));
  // Outward normal -y: the material above may not move down into the lid.
  Tensor<1, 2> v({0.3, -1.});
  constraints.apply(i, v);
  EXPECT_EQ(v, (Tensor<1, 2>({0.3, 0.})));
  v = Tensor<1, 2>({0.3, 1.});
  constraints.apply(i, v);
  EXPECT_EQ(v, (Tensor<1, 2>({0.3, 1.})));

  // A gate standing on a roller floor: the corner node holds both.
  std::map<types::boundary_id, WallCondition> floor;
  floor[2].type = WallType::roller;
  NodalConstraints<2> gated(*grid, floor, gate<2>("0: 0 1"));
  const unsigned int  corner = node_at(*grid, 0.5, 0.);
  v                          = Tensor<1, 2>({1., -1.});
  gated.apply(corner, v);
  EXPECT_EQ(v, (Tensor<1, 2>()));
  v = Tensor<1, 2>({-1., 1.});
  gated.apply(corner, v);
  EXPECT_EQ(v, (Tensor<1, 2>({-1., 0.})));
}

TEST(MovingWall, BadInput)
{
  const auto grid = test_tools::make_unit_box_grid<2>(4);
  // x = 0.6 is not a grid line of h = 1/4.
  try
    {
      MovingWall<2> wall(gate<2>("0: 0 1", "0.6"), *grid);
      ADD_FAILURE() << "a plane off the grid lines was accepted";
    }
  catch (const std::exception &e)
    {
      EXPECT_NE(flat(e).find("must be a grid line"), std::string::npos)
        << e.what();
    }
  const auto message = [](const std::string &history) {
    try
      {
        gate<2>(history);
      }
    catch (const std::exception &e)
      {
        return flat(e);
      }
    return std::string("accepted");
  };
  EXPECT_NE(message("0: 1 0").find("along its normal"), std::string::npos);
  EXPECT_NE(message("0.1: 0 1").find("start at 0"), std::string::npos);
  EXPECT_NE(message("0: 0 1, 0: 0 2").find("increase strictly"),
            std::string::npos);
  EXPECT_NE(message("0: 0").find("2 velocity components"), std::string::npos);
  EXPECT_NE(message("0: 0 x").find("is not a number"), std::string::npos);
  EXPECT_EQ(message("0:  0   1 ,0.1: 0 2"), "accepted");
}

// fsgmpm::set_parameter with a number keeps every digit (std::to_string
// would have written 1.5e-7 as 0.000000).
TEST(SetParameter, NumbersKeepTheirDigits)
{
  auto prm = test_tools::make_parameters("");
  set_parameter(*prm, "Simulation/Fixed time step", 1.5e-7);
  prm->enter_subsection("Simulation");
  EXPECT_EQ(prm->get_double("Fixed time step"), 1.5e-7);
  prm->leave_subsection();
}
