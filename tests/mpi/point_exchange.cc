// DistributedPoints on 3 MPI processes (mpirun -np 3): the ghost copies
// and the migration of points, with their whole state, point to point
// between the processes whose cells share a vertex, and the collective
// fallback for a point that lands in the cells of a process that is not
// one of those (after a repartition, or a jump across a sliver cell).
//
// The unit square in 6 x 6 squares (72 triangles) is split in three
// vertical strips by the x of the cell centres: process 0 owns x < 1/3,
// process 1 the middle, process 2 x > 2/3. Strips 0 and 2 share no vertex,
// so they are not point neighbours. Every process puts one point at the
// centre of each of its cells, with an id, mass, velocity and stress made
// from the cell's index, so that every field can be checked on arrival.
//
// And BackgroundGrid::window: the part of the grid a process needs (its
// cells and their ghost layer, numbered on its own) gives every node of its
// own cells the whole grid's sums bit for bit, in 2D and 3D; its partition
// and the points' exchange between windows agree with the whole grid's.
// And a run (Simulator) holds its window from the first partition on, through
// repartitions, a scene with a membrane too (its nodes' cells agree on every
// process). DomainPartition::all_window_cells gives every window in one pass.
// And Parallel::gather_to_root combines the processes' entries in their
// order, and refuses a gather past 2^31 - 1 entries.

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/parallel/distributed_points.h>
#include <fsgmpm/parallel/domain_partition.h>
#include <fsgmpm/parallel/gather_to_root.h>
#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/simulator.h>
#include <fsgmpm/step/cell_loops.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "grid_comparison.h"
#include "test_utilities.h"

namespace
{
  using namespace fsgmpm;

  constexpr int dim = 2;

  Point<dim>
  centre(const BackgroundGrid<dim> &grid, const unsigned int c)
  {
    return grid.position(c, {{1. / 3, 1. / 3, 1. / 3}});
  }

  unsigned int
  strip(const BackgroundGrid<dim> &grid, const unsigned int c)
  {
    const double x = centre(grid, c)[0];
    return x < 1. / 3 ? 0 : (x < 2. / 3 ? 1 : 2);
  }

  /// The point a process puts into cell c: every field from c.
  void
  add_point(const BackgroundGrid<dim> &grid,
            const unsigned int         c,
            ParticleStore<dim>        &particles)
  {
    particles.next_id = 1000 + c;
    Tensor<1, dim> velocity;
    velocity[0] = c;
    velocity[1] = -0.5 * c;
    SymmetricTensor<2, 3> stress;
    stress[0][0] = -double(c);
    stress[0][1] = 0.25 * c;
    particles.add(
      centre(grid, c), c, 1. + c, 2. + c, velocity, stress, c % 3, c % 2);
  }

  /// Whether point p carries exactly the state add_point() gave the point
  /// with its id (which may since have moved to another cell).
  bool
  intact(const ParticleStore<dim> &particles, const unsigned int p)
  {
    const unsigned int c = particles.id[p] - 1000;
    return particles.mass[p] == 1. + c && particles.volume[p] == 2. + c
           && particles.reference_volume[p] == 2. + c
           && particles.velocity[p][0] == double(c)
           && particles.velocity[p][1] == -0.5 * c
           && particles.stress[p][0][0] == -double(c)
           && particles.stress[p][0][1] == 0.25 * c
           && particles.stress[p][1][1] == 0.
           && particles.material_id[p] == c % 3
           && particles.body_id[p] == c % 2;
  }

  struct ThreeStrips
  {
    const MPI_Comm                        comm = MPI_COMM_WORLD;
    std::unique_ptr<BackgroundGrid<dim>>  grid;
    std::unique_ptr<DomainPartition<dim>> partition;
    ParticleStore<dim>                    particles;
    unsigned int                          rank;

    ThreeStrips()
    {
      AssertThrow(Utilities::MPI::n_mpi_processes(comm) == 3,
                  ExcMessage("Run on 3 processes: mpirun -np 3"));
      grid      = test_tools::make_unit_box_grid<dim>(6);
      partition = std::make_unique<DomainPartition<dim>>(comm, *grid);
      rank      = Utilities::MPI::this_mpi_process(comm);
      std::vector<unsigned int> owners(grid->n_cells());
      for (unsigned int c = 0; c < grid->n_cells(); ++c)
        owners[c] = strip(*grid, c);
      partition->set_owners(owners);
      for (unsigned int c = 0; c < grid->n_cells(); ++c)
        if (owners[c] == rank)
          add_point(*grid, c, particles);
      particles.sort_by_cell(grid->n_cells());
    }
  };
} // namespace



TEST(PointExchange, NeighboursAreTheProcessesWhoseCellsShareAVertex)
{
  ThreeStrips               s;
  std::vector<unsigned int> expected;
  if (s.rank == 0)
    expected = {1};
  else if (s.rank == 1)
    expected = {0, 2};
  else
    expected = {1};
  EXPECT_EQ(s.partition->point_neighbours(), expected);
}



TEST(PointExchange, GhostCopiesAreThePointsOfTheCellsAroundOursInOrder)
{
  ThreeStrips        s;
  const unsigned int n_owned = s.particles.size();
  DistributedPoints::add_ghosts(*s.partition, s.particles);

  // The ghost cells: cells of other processes that share a vertex with
  // one of ours; their points come by rank, then by cell.
  std::set<unsigned int> our_nodes;
  for (unsigned int c = 0; c < s.grid->n_cells(); ++c)
    if (s.partition->owner(c) == s.rank)
      our_nodes.insert(s.grid->cell_nodes[c].begin(),
                       s.grid->cell_nodes[c].end());
  std::vector<std::pair<unsigned int, unsigned int>> expected;
  for (unsigned int c = 0; c < s.grid->n_cells(); ++c)
    if (s.partition->owner(c) != s.rank
        && std::any_of(s.grid->cell_nodes[c].begin(),
                       s.grid->cell_nodes[c].end(),
                       [&](const unsigned int i) {
                         return our_nodes.count(i) == 1;
                       }))
      expected.emplace_back(s.partition->owner(c), c);
  std::sort(expected.begin(), expected.end());

  ASSERT_EQ(s.particles.size(), n_owned + expected.size());
  for (unsigned int k = 0; k < expected.size(); ++k)
    {
      const unsigned int p = n_owned + k;
      EXPECT_EQ(s.particles.cell[p], expected[k].second);
      EXPECT_EQ(s.particles.id[p], 1000 + expected[k].second);
      EXPECT_EQ(s.particles.ghost[p], 1);
      EXPECT_TRUE(intact(s.particles, p)) << "point " << s.particles.id[p];
      EXPECT_EQ(s.particles.cell_begin(s.particles.cell[p]), p);
      EXPECT_EQ(s.particles.cell_end(s.particles.cell[p]), p + 1);
    }
  EXPECT_TRUE(std::is_sorted(s.particles.occupied_cells.begin(),
                             s.particles.occupied_cells.end()));
  EXPECT_EQ(s.particles.occupied_cells.size(), s.particles.size());

  DistributedPoints::drop_ghosts(s.particles);
  EXPECT_EQ(s.particles.size(), n_owned);
  EXPECT_EQ(s.particles.occupied_cells.size(), n_owned);
}



TEST(PointExchange, PointsMoveToTheirNewOwnersNearAndFar)
{
  ThreeStrips s;
  // Process 0 moves its first point into the first cell of process 2 (not
  // a neighbour: the collective fallback) and its second into the first
  // cell of process 1 (a neighbour). Process 2 moves its last point into
  // process 1's last cell.
  const auto first_of = [&](const unsigned int owner) {
    for (unsigned int c = 0; c < s.grid->n_cells(); ++c)
      if (s.partition->owner(c) == owner)
        return c;
    return BackgroundGrid<dim>::invalid;
  };
  const auto last_of = [&](const unsigned int owner) {
    unsigned int last = BackgroundGrid<dim>::invalid;
    for (unsigned int c = 0; c < s.grid->n_cells(); ++c)
      if (s.partition->owner(c) == owner)
        last = c;
    return last;
  };
  const unsigned int n_global
    = DistributedPoints::global_size(*s.partition, s.particles);
  const auto move = [&](const unsigned int p, const unsigned int c) {
    s.particles.cell[p]     = c;
    s.particles.position[p] = centre(*s.grid, c);
  };
  std::vector<unsigned int> cells_of_0, cells_of_2;
  for (unsigned int c = 0; c < s.grid->n_cells(); ++c)
    if (s.partition->owner(c) == 0)
      cells_of_0.push_back(c);
    else if (s.partition->owner(c) == 2)
      cells_of_2.push_back(c);
  // Sorted by cell, process 0's first points are in its first cells.
  const unsigned int far_id  = 1000 + cells_of_0[0];
  const unsigned int near_id = 1000 + cells_of_0[1];
  const unsigned int back_id = 1000 + cells_of_2.back();
  if (s.rank == 0)
    {
      EXPECT_EQ(s.particles.id[0], far_id);
      EXPECT_EQ(s.particles.id[1], near_id);
      move(0, first_of(2));
      move(1, first_of(1));
    }
  if (s.rank == 2)
    {
      EXPECT_EQ(s.particles.id.back(), back_id);
      move(s.particles.size() - 1, last_of(1));
    }
  DistributedPoints::migrate(*s.partition, s.particles);

  EXPECT_EQ(DistributedPoints::global_size(*s.partition, s.particles),
            n_global);
  for (unsigned int p = 0; p < s.particles.size(); ++p)
    {
      EXPECT_EQ(s.partition->owner(s.particles.cell[p]), s.rank);
      EXPECT_TRUE(intact(s.particles, p)) << "point " << s.particles.id[p];
      if (p > 0)
        {
          // Sorted by cell, then by id (the canonical order).
          EXPECT_TRUE(s.particles.cell[p - 1] < s.particles.cell[p]
                      || (s.particles.cell[p - 1] == s.particles.cell[p]
                          && s.particles.id[p - 1] < s.particles.id[p]));
        }
    }
  const auto holds = [&](const unsigned int id) {
    return std::count(s.particles.id.begin(), s.particles.id.end(), id);
  };
  if (s.rank == 2)
    {
      EXPECT_EQ(holds(far_id), 1);
      EXPECT_EQ(holds(back_id), 0);
    }
  if (s.rank == 1)
    {
      EXPECT_EQ(holds(near_id), 1);
      EXPECT_EQ(holds(back_id), 1);
      EXPECT_EQ(s.particles.size(),
                std::count_if(s.particles.cell.begin(),
                              s.particles.cell.end(),
                              [&](const unsigned int c) {
                                return s.partition->owner(c) == 1;
                              }));
    }
  if (s.rank == 0)
    {
      EXPECT_EQ(holds(far_id), 0);
      EXPECT_EQ(holds(near_id), 0);
    }
}



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  AssertThrow(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) >= 2,
              dealii::ExcMessage("Run on 3 processes: mpirun -np 3 (the "
                                 "GridWindowSize figures on 2 or more)"));
  ::testing::InitGoogleTest(&argc, argv);
  const int failures = RUN_ALL_TESTS();
  // Every process's failures count.
  return dealii::Utilities::MPI::max(failures, MPI_COMM_WORLD);
}



namespace
{
  // Window cell c is the whole grid's cell g: the same nodes, neighbours
  // (where the window holds them) and colour.
  template <int d>
  void
  expect_same_cell(const BackgroundGrid<d> &whole,
                   const BackgroundGrid<d> &w,
                   const unsigned int       c,
                   const unsigned int       g)
  {
    const auto invalid = BackgroundGrid<d>::invalid;
    EXPECT_EQ(w.global_cell(c), g);
    EXPECT_EQ(w.local_cell(g), c);
    EXPECT_EQ(w.block_colour[w.cell_block(c)],
              whole.block_colour[whole.cell_block(g)]);
    for (unsigned int k = 0; k < d + 1; ++k)
      {
        EXPECT_EQ(w.global_node(w.cell_nodes[c][k]), whole.cell_nodes[g][k]);
        const unsigned int nb = whole.cell_neighbors[g][k];
        EXPECT_EQ(w.cell_neighbors[c][k],
                  nb == invalid ? invalid : w.local_cell(nb));
      }
  }

  // Windows of a box in vertical strips (process r owns the cells whose
  // centre has r/P <= x < (r+1)/P): the window holds what DomainPartition
  // says, maps back to the whole grid, keeps its blocks' colours, and a
  // scatter over it (the free-surface volume shares, CellLoops::
  // scatter_by_colour) gives every node of an owned cell the whole grid's
  // value bit for bit, while the rim of the ghost layer misses some.
  template <int d>
  void
  check_windows(const unsigned int n)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const auto         grid    = test_tools::make_unit_box_grid<d>(n);
    const auto         invalid = BackgroundGrid<d>::invalid;
    grid->compute_node_volumes();
    std::vector<unsigned int> owners(grid->n_cells());
    std::set<unsigned int>    owned_nodes;
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      {
        double x = 0;
        for (const unsigned int i : grid->cell_nodes[c])
          x += grid->node_positions[i][0] / (d + 1);
        owners[c] = std::min<unsigned int>(n_ranks - 1, x * n_ranks);
        if (owners[c] == rank)
          owned_nodes.insert(grid->cell_nodes[c].begin(),
                             grid->cell_nodes[c].end());
      }
    DomainPartition<d> partition(comm, *grid);
    partition.set_owners(owners);

    std::vector<unsigned int> expected;
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      if (std::any_of(grid->cell_nodes[c].begin(),
                      grid->cell_nodes[c].end(),
                      [&](const unsigned int i) {
                        return owned_nodes.count(i) > 0;
                      }))
        expected.push_back(c);
    const std::vector<unsigned int> cells = partition.window_cells();
    EXPECT_EQ(cells, expected);
    ASSERT_LT(cells.size(), grid->n_cells());

    const BackgroundGrid<d> w = grid->window(cells);
    EXPECT_TRUE(w.is_window());
    EXPECT_FALSE(grid->is_window());
    ASSERT_EQ(w.n_cells(), cells.size());
    EXPECT_EQ(
      w.n_nodes(), owned_nodes.size() + [&]() {
        std::set<unsigned int> rim;
        for (const unsigned int c : cells)
          for (const unsigned int i : grid->cell_nodes[c])
            if (owned_nodes.count(i) == 0)
              rim.insert(i);
        return rim.size();
      }());
    EXPECT_EQ(w.n_colours, grid->n_colours);
    EXPECT_EQ(w.min_altitude_global, grid->min_altitude_global);
    EXPECT_EQ(w.upper_corner, grid->upper_corner);
    for (unsigned int c = 0; c < w.n_cells(); ++c)
      {
        const unsigned int g = cells[c];
        expect_same_cell(*grid, w, c, g);
        if (c > 0)
          {
            const bool same_block
              = grid->cell_block(g) == grid->cell_block(cells[c - 1]);
            EXPECT_EQ(w.cell_block(c) - w.cell_block(c - 1),
                      same_block ? 0u : 1u);
          }
      }
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      if (!std::binary_search(cells.begin(), cells.end(), c))
        {
          EXPECT_EQ(w.local_cell(c), invalid);
        }
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      {
        EXPECT_EQ(w.local_node(w.global_node(i)), i);
        EXPECT_EQ(w.node_positions[i], grid->node_positions[w.global_node(i)]);
        EXPECT_EQ(w.node_volume[i], grid->node_volume[w.global_node(i)]);
      }
    unsigned int n_faces = 0;
    for (const auto &face : grid->boundary_faces)
      if (w.local_cell(face.cell) != invalid)
        {
          ASSERT_LT(n_faces, w.boundary_faces.size());
          EXPECT_EQ(w.boundary_faces[n_faces].cell, w.local_cell(face.cell));
          EXPECT_EQ(w.boundary_faces[n_faces].vertex, face.vertex);
          EXPECT_EQ(w.boundary_faces[n_faces].boundary_id, face.boundary_id);
          ++n_faces;
        }
    EXPECT_EQ(n_faces, w.boundary_faces.size());

    // Three points in every cell, volumes over three decades so that the
    // order of the sums shows in the bits; the window gets those of its
    // cells, in the same order.
    ParticleStore<d>                       all, mine;
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      for (unsigned int q = 0; q < 3; ++q)
        {
          std::array<double, d + 1> l;
          double                    sum = 0;
          for (auto &v : l)
            sum += (v = u(rng) + 0.05);
          for (auto &v : l)
            v /= sum;
          const Point<d> x      = grid->position(c, l);
          const double   volume = std::pow(10., -3 * u(rng));
          all.add(x, c, 1., volume, {}, {}, 0, 0);
          if (w.local_cell(c) != invalid)
            {
              mine.next_id = all.next_id - 1;
              mine.add(x, w.local_cell(c), 1., volume, {}, {}, 0, 0);
            }
        }
    all.sort_by_cell(grid->n_cells());
    mine.sort_by_cell(w.n_cells());
    const auto scatter
      = [](const BackgroundGrid<d> &g, const ParticleStore<d> &points) {
          std::vector<double> phi(g.n_nodes(), 0.);
          CellLoops::scatter_by_colour(g, points, [&](const unsigned int c) {
            const auto share = CellLoops::volume_shares(g, points, c);
            for (unsigned int k = 0; k < d + 1; ++k)
              phi[g.cell_nodes[c][k]] += share[k];
          });
          return phi;
        };
    const std::vector<double> phi_all  = scatter(*grid, all),
                              phi_mine = scatter(w, mine);
    unsigned int exact = 0, partial = 0;
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      if (owned_nodes.count(w.global_node(i)))
        {
          EXPECT_EQ(phi_mine[i], phi_all[w.global_node(i)]) << i;
          ++exact;
        }
      else
        partial += (phi_mine[i] < phi_all[w.global_node(i)]);
    EXPECT_EQ(exact, owned_nodes.size());
    EXPECT_GT(partial, 0u);

    // The window's own partition: the same owners, neighbours, counted
    // nodes and halo as the whole grid's; its rim exchange completes every
    // node of the window to the whole grid's value.
    DomainPartition<d> window_partition(comm, w);
    window_partition.set_owners(owners);
    EXPECT_EQ(window_partition.point_neighbours(),
              partition.point_neighbours());
    EXPECT_EQ(window_partition.n_halo_nodes(), partition.n_halo_nodes());
    EXPECT_EQ(window_partition.n_owned_cells(), partition.n_owned_cells());
    for (unsigned int c = 0; c < w.n_cells(); ++c)
      {
        EXPECT_EQ(window_partition.owner(c), partition.owner(cells[c]));
        if (window_partition.owner(c) == rank)
          {
            const auto a = window_partition.ghost_holders(c),
                       b = partition.ghost_holders(cells[c]);
            EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
          }
      }
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      EXPECT_EQ(window_partition.counted_nodes()[i],
                partition.counted_nodes()[w.global_node(i)]);
    std::vector<double>       phi_rim = phi_mine;
    std::vector<std::uint8_t> active(w.n_nodes(), 1);
    window_partition.update_ghost_nodes(phi_rim, active, 1);
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      EXPECT_EQ(phi_rim[i], phi_all[w.global_node(i)]) << i;

    // Points between windows (cells travel by their whole-grid numbers):
    // the ghost copies, then every point moved across a face into a cell
    // that may be another process's, arrive as between whole grids.
    ParticleStore<d> on_whole, on_window;
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      if (owners[c] == rank)
        {
          const Point<d> x = grid->position(c, {});
          on_whole.next_id = on_window.next_id = c;
          on_whole.add(x, c, 1., 1., {}, {}, 0, 0);
          on_window.add(x, w.local_cell(c), 1., 1., {}, {}, 0, 0);
        }
    const auto same_points = [&](const char *when) {
      ASSERT_EQ(on_window.size(), on_whole.size()) << when;
      for (unsigned int p = 0; p < on_whole.size(); ++p)
        {
          EXPECT_EQ(on_window.id[p], on_whole.id[p]) << when;
          EXPECT_EQ(w.global_cell(on_window.cell[p]), on_whole.cell[p]) << when;
        }
    };
    on_whole.sort_by_cell(grid->n_cells());
    on_window.sort_by_cell(w.n_cells());
    DistributedPoints::add_ghosts(partition, on_whole);
    DistributedPoints::add_ghosts(window_partition, on_window);
    EXPECT_GT(on_whole.ghost.size(), 0u);
    same_points("ghost copies");
    DistributedPoints::drop_ghosts(on_whole);
    DistributedPoints::drop_ghosts(on_window);
    // Across the face into another process's cell where there is one.
    unsigned int n_leaving = 0;
    for (unsigned int p = 0; p < on_whole.size(); ++p)
      {
        unsigned int to = on_whole.cell[p];
        for (const unsigned int nb : grid->cell_neighbors[on_whole.cell[p]])
          if (nb != invalid && (to == on_whole.cell[p] || owners[nb] != rank))
            to = nb;
        n_leaving += (owners[to] != rank);
        on_whole.cell[p]  = to;
        on_window.cell[p] = w.local_cell(to);
      }
    DistributedPoints::migrate(partition, on_whole);
    DistributedPoints::migrate(window_partition, on_window);
    EXPECT_GT(Utilities::MPI::sum(n_leaving, comm), 0u);
    same_points("migration");
  }

  // A grid with two velocity fields (multi-field contact): the window holds
  // the same cells in both, numbered as the whole grid numbers its fields,
  // arrives the same when process 0 sends it, and its partition counts the
  // nodes of both fields as the whole grid's.
  template <int d>
  void
  check_window_fields(const unsigned int n)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const auto         grid    = test_tools::make_unit_box_grid<d>(n);
    grid->set_velocity_fields(2);
    grid->compute_node_volumes();
    const unsigned int        n_base = grid->n_base_cells();
    std::vector<unsigned int> owners(grid->n_cells());
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      owners[c] = std::min<unsigned int>(
        n_ranks - 1, grid->node_positions[grid->cell_nodes[c][0]][0] * n_ranks);
    DomainPartition<d> partition(comm, *grid);
    partition.set_owners(owners);
    const std::vector<unsigned int> cells = partition.window_cells();
    const BackgroundGrid<d>         w     = grid->window(cells);

    // The same window sent by process 0, which knows every process's
    // cells, to the others, which need no whole grid for it.
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    if (rank == 0)
      for (unsigned int r = 1; r < n_ranks; ++r)
        grid->send_window(partition.window_cells(r), r, comm);
    else
      {
        const BackgroundGrid<d> sent
          = BackgroundGrid<d>::receive_window(0, comm);
        EXPECT_TRUE(sent.is_window());
        EXPECT_EQ(sent.n_velocity_fields(), 2u);
        Testing::expect_same_grid_arrays(sent, w);
        EXPECT_EQ(sent.n_global_cells(), w.n_global_cells());
        for (unsigned int c = 0; c < w.n_cells(); ++c)
          {
            EXPECT_EQ(sent.global_cell(c), w.global_cell(c));
            EXPECT_EQ(sent.cell_block(c), w.cell_block(c));
          }
        for (unsigned int i = 0; i < w.n_nodes(); ++i)
          EXPECT_EQ(sent.global_node(i), w.global_node(i));
      }
    ASSERT_EQ(w.n_velocity_fields(), 2u);
    ASSERT_EQ(w.n_cells(), 2 * cells.size());
    EXPECT_EQ(w.n_global_cells(), grid->n_cells());
    EXPECT_EQ(w.n_colours, grid->n_colours);
    for (unsigned int c = 0; c < w.n_cells(); ++c)
      {
        expect_same_cell(*grid,
                         w,
                         c,
                         cells[c % cells.size()] + w.field_of_cell(c) * n_base);
      }
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      {
        EXPECT_EQ(w.local_node(w.global_node(i)), i);
        EXPECT_EQ(w.node_volume[i], grid->node_volume[w.global_node(i)]);
      }
    DomainPartition<d> window_partition(comm, w);
    window_partition.set_owners(owners);
    EXPECT_EQ(window_partition.point_neighbours(),
              partition.point_neighbours());
    for (unsigned int i = 0; i < w.n_nodes(); ++i)
      EXPECT_EQ(window_partition.counted_nodes()[i],
                partition.counted_nodes()[w.global_node(i)]);
  }
} // namespace



namespace
{
  // DomainPartition::metis_split() against deal.II's SparsityTools::
  // partition() on the graph GridTools::get_face_connectivity_of_cells()
  // builds (each unit with itself and the units across its faces), of
  // the grid's blocks of cells (cell_block()) when the grid has at least 16
  // blocks per part, else of cells; every cell goes to its unit's part.
  template <int d>
  void
  expect_deal_iis_metis_split(const std::vector<unsigned int> &subdivisions,
                              const std::vector<unsigned int> &parts,
                              const bool                       by_blocks)
  {
    Point<d> upper;
    for (unsigned int k = 0; k < d; ++k)
      upper[k] = 1. + k;
    const BackgroundGrid<d> grid(
      MeshGeneration::box_simplices(Point<d>(), upper, subdivisions));
    std::mt19937                                rng(7);
    std::uniform_int_distribution<unsigned int> points(0, 5);
    std::vector<unsigned int>                   weights(grid.n_cells());
    for (unsigned int &w : weights)
      w = 1 + 64 * (points(rng) < 2 ? points(rng) : 0);

    const auto unit = [&](const unsigned int c) {
      return by_blocks ? grid.cell_block(c) : c;
    };
    const unsigned int        n_units = unit(grid.n_cells() - 1) + 1;
    std::vector<unsigned int> unit_weights(n_units, 0);
    DynamicSparsityPattern    connectivity(n_units, n_units);
    for (unsigned int c = 0; c < grid.n_cells(); ++c)
      {
        unit_weights[unit(c)] += weights[c];
        connectivity.add(unit(c), unit(c));
        for (const unsigned int nb : grid.cell_neighbors[c])
          if (nb != BackgroundGrid<d>::invalid)
            {
              connectivity.add(unit(c), unit(nb));
              connectivity.add(unit(nb), unit(c));
            }
      }
    SparsityPattern graph;
    graph.copy_from(connectivity);
    for (const unsigned int n_parts : parts)
      {
        std::vector<unsigned int> unit_part(n_units);
        SparsityTools::partition(graph,
                                 unit_weights,
                                 n_parts,
                                 unit_part,
                                 SparsityTools::Partitioner::metis);
        std::vector<unsigned int> expected(grid.n_cells());
        for (unsigned int c = 0; c < grid.n_cells(); ++c)
          expected[c] = unit_part[unit(c)];
        EXPECT_EQ(DomainPartition<d>::metis_split(grid, weights, n_parts),
                  expected)
          << d << "D, " << grid.n_cells() << " cells, " << n_parts << " parts";
      }
  }
} // namespace

TEST(GridPartition, MetisSplitIsDealIIsPartition)
{
  // 600 blocks; 2 blocks; 150 blocks (16 per part up to 9 parts).
  expect_deal_iis_metis_split<2>({120, 80}, {2, 3, 8, 11}, true);
  expect_deal_iis_metis_split<2>({6, 5}, {2, 3}, false);
  expect_deal_iis_metis_split<3>({12, 10, 8}, {2, 3, 8}, true);
  expect_deal_iis_metis_split<3>({12, 10, 8}, {11}, false);
}



// Figures, not asserted (ctest grid_window_size, label performance): the
// background grids of the 2D and 3D dam breaks of the benchmark (960 x 400
// squares, 768 000 triangles; 40 x 20 x 20 cubes, 80 000 tetrahedra), split
// by METIS with every cell weighing the same. Each process prints its
// window's cells, nodes and bytes against the whole grid's.
TEST(GridWindowSize, DamBreakGrids)
{
  const auto measure = [](auto &&grid) {
    using Grid           = std::remove_reference_t<decltype(*grid)>;
    constexpr int      d = Grid::n_vertices - 1;
    DomainPartition<d> partition(MPI_COMM_WORLD, *grid);
    partition.partition(std::vector<unsigned int>(grid->n_cells(), 1));
    const Grid w = grid->window(partition.window_cells());
    for (unsigned int r = 0; r < partition.n_ranks(); ++r)
      {
        if (r == partition.rank())
          std::printf("%dD, %u processes, process %u: owns %u of %u cells; "
                      "window %u cells, %u of %u nodes, %.1f of %.1f MB "
                      "(%.3f)\n",
                      d,
                      partition.n_ranks(),
                      r,
                      partition.n_owned_cells(),
                      grid->n_cells(),
                      w.n_cells(),
                      w.n_nodes(),
                      grid->n_nodes(),
                      w.memory_consumption() / 1e6,
                      grid->memory_consumption() / 1e6,
                      double(w.memory_consumption())
                        / grid->memory_consumption());
        std::fflush(stdout);
        MPI_Barrier(MPI_COMM_WORLD);
      }
    EXPECT_LT(w.memory_consumption(), grid->memory_consumption());
  };
  {
    Triangulation<2> tria;
    MeshGeneration::make_box(Point<2>(),
                             Point<2>(3.2, 4. / 3),
                             {960, 400},
                             tria);
    measure(std::make_unique<BackgroundGrid<2>>(std::move(tria)));
  }
  {
    Triangulation<3> tria;
    MeshGeneration::make_box(Point<3>(),
                             Point<3>(1, 0.5, 0.5),
                             {40, 20, 20},
                             tria);
    measure(std::make_unique<BackgroundGrid<3>>(std::move(tria)));
  }
}



// What process 0 spends cutting every process's window (at the start and
// at each repartition): window_cells() once per process against
// all_window_cells() in one pass, same results; the 2D dam break's grid
// (768 000 triangles) in square blocks of cells for 4, 64 and 1 024
// processes. Process 0 measures; the others wait.
TEST(GridWindowSize, CuttingAllWindows)
{
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return;
  Triangulation<2> tria;
  MeshGeneration::make_box(Point<2>(), Point<2>(3.2, 4. / 3), {960, 400}, tria);
  const BackgroundGrid<2> grid(std::move(tria));
  for (const unsigned int side : {2u, 8u, 32u})
    {
      const unsigned int        n_processes = side * side;
      std::vector<unsigned int> owners(grid.n_cells());
      for (unsigned int c = 0; c < grid.n_cells(); ++c)
        {
          const Point<2> x = centre(grid, c);
          owners[c]
            = std::min<unsigned int>(x[0] / 3.2 * side, side - 1) * side
              + std::min<unsigned int>(x[1] / (4. / 3) * side, side - 1);
        }
      Timer                                  timer;
      std::vector<std::vector<unsigned int>> each(n_processes);
      for (unsigned int q = 0; q < n_processes; ++q)
        each[q] = DomainPartition<2>::window_cells(grid, owners, q);
      const double per_process = timer.wall_time();
      timer.restart();
      const std::vector<std::vector<unsigned int>> all
        = DomainPartition<2>::all_window_cells(grid, owners, n_processes);
      const double one_pass = timer.wall_time();
      EXPECT_EQ(all, each);
      std::printf("cutting %u windows of %u cells: window_cells() per "
                  "process %.3f s, all_window_cells() %.3f s\n",
                  n_processes,
                  grid.n_cells(),
                  per_process,
                  one_pass);
    }
}



namespace
{
  // all_window_cells() gives, in one pass, each process's window_cells():
  // for owners in strips (few seams) and at random (seams everywhere, a
  // node amid up to all owners), with a process that owns no cell.
  template <int dim>
  void
  check_all_windows(const unsigned int n)
  {
    const auto                grid = test_tools::make_unit_box_grid<dim>(n);
    const unsigned int        n_processes = 5;
    std::vector<unsigned int> strips(grid->n_cells()), random(grid->n_cells());
    std::mt19937              rng(7);
    std::uniform_int_distribution<unsigned int> any(0, n_processes - 2);
    for (unsigned int c = 0; c < grid->n_cells(); ++c)
      {
        strips[c] = std::min<unsigned int>(
          grid->node_positions[grid->cell_nodes[c][0]][0] * (n_processes - 1),
          n_processes - 2);
        random[c] = any(rng);
      }
    for (const auto &owners : {strips, random})
      {
        const std::vector<std::vector<unsigned int>> all
          = DomainPartition<dim>::all_window_cells(*grid, owners, n_processes);
        ASSERT_EQ(all.size(), n_processes);
        for (unsigned int q = 0; q < n_processes; ++q)
          EXPECT_EQ(all[q],
                    DomainPartition<dim>::window_cells(*grid, owners, q))
            << "process " << q;
        EXPECT_TRUE(all[n_processes - 1].empty());
      }
  }
} // namespace



TEST(GridWindow, AllWindowsInOnePassAreEachProcesssWindow)
{
  check_all_windows<2>(12);
  check_all_windows<3>(4);
}



TEST(GridWindow, TwoVelocityFieldsAndSentFromProcessZero)
{
  check_window_fields<2>(12);
  check_window_fields<3>(4);
}



TEST(GridWindow, OwnNodesGetTheWholeGridsSumsBitForBit2D)
{
  check_windows<2>(24);
}



TEST(GridWindow, OwnNodesGetTheWholeGridsSumsBitForBit3D)
{
  check_windows<3>(6);
}



namespace
{
  void
  set_parameter(ParameterHandler  &prm,
                const std::string &section,
                const std::string &name,
                const std::string &value)
  {
    prm.enter_subsection(section);
    prm.set(name, value);
    prm.leave_subsection();
  }
} // namespace



// The shipped dam break (60 x 25 squares) repartitioned before every step:
// after each step every process holds a window of the grid, each of its
// points is in a cell of the window, and no point is lost or doubled. The
// results are the serial ones (mpi_reproduces_serial); this test sees that
// the grid is a window at all.
TEST(SimulatorWindow, ARunHoldsItsWindowThroughRepartitions)
{
  auto prm = test_tools::make_parameters_from_scene("default_dam_break.prm");
  set_parameter(*prm, "Simulation", "Repartition imbalance", "1");
  set_parameter(*prm, "Simulation", "Number of threads", "1");
  set_parameter(*prm, "Output", "Quiet", "true");
  Simulator<2>       sim(*prm);
  const MPI_Comm     comm = MPI_COMM_WORLD;
  const unsigned int n_points
    = Utilities::MPI::sum(sim.get_particles().size(), comm);
  for (unsigned int step = 0; step < 20; ++step)
    {
      ASSERT_TRUE(sim.advance());
      const BackgroundGrid<2> &grid = sim.get_grid();
      ASSERT_TRUE(grid.is_window());
      EXPECT_EQ(grid.n_global_cells(), 2u * 60 * 25);
      EXPECT_LT(grid.n_cells(), grid.n_global_cells());
      for (const unsigned int c : sim.get_particles().cell)
        ASSERT_LT(c, grid.n_cells());
      EXPECT_EQ(Utilities::MPI::sum(sim.get_particles().size(), comm),
                n_points);
    }
  // Each repartition cut new windows.
  EXPECT_GE(sim.get_n_repartitions(), 10u);
}



// A membrane scene runs on windows too (the coarse geotube, 3 processes):
// every membrane node has one cell, the same whole-grid number on every
// process, and lies in it wherever a window holds that cell. Nodes whose
// cell is unknown (as when every walk leaves its window) are found by the
// search over all windows. (mpi_reproduces_serial compares the runs with
// serial ones.)
TEST(SimulatorWindow, AMembraneSceneRunsOnWindows)
{
  auto prm = test_tools::make_parameters_from_scene("geotube_A6.45.prm");
  set_parameter(*prm, "Grid", "Cell size", "0.16");
  set_parameter(*prm, "Simulation", "Number of threads", "1");
  set_parameter(*prm, "Output", "Quiet", "true");
  Simulator<2>             sim(*prm);
  const BackgroundGrid<2> &grid = sim.get_grid();
  ASSERT_TRUE(grid.is_window());
  EXPECT_LT(grid.n_cells(), grid.n_global_cells());
  const MPI_Comm comm = MPI_COMM_WORLD;

  const auto expect_cells_agree = [&]() {
    const Membrane<2>        &m = *sim.get_membrane();
    const unsigned int        n = m.n_nodes();
    std::vector<unsigned int> low(n), high(n), holders(n, 0);
    MPI_Allreduce(m.cell.data(), low.data(), n, MPI_UNSIGNED, MPI_MIN, comm);
    MPI_Allreduce(m.cell.data(), high.data(), n, MPI_UNSIGNED, MPI_MAX, comm);
    EXPECT_EQ(low, high);
    for (unsigned int a = 0; a < n; ++a)
      {
        ASSERT_LT(m.cell[a], grid.n_global_cells());
        const unsigned int c = grid.local_cell(m.cell[a]);
        if (c == BackgroundGrid<2>::invalid)
          continue;
        holders[a]   = 1;
        const auto l = grid.barycentric(c, m.position[a]);
        EXPECT_GE(*std::min_element(l.begin(), l.end()),
                  -PointLocator<2>::default_tolerance)
          << "node " << a;
      }
    Utilities::MPI::sum(holders, comm, holders);
    for (unsigned int a = 0; a < n; ++a)
      EXPECT_GE(holders[a], 1u) << "node " << a;
  };

  for (unsigned int step = 0; step < 20; ++step)
    ASSERT_TRUE(sim.advance());
  expect_cells_agree();

  // Forget every third node's cell: the search must find them.
  auto &membrane = const_cast<Membrane<2> &>(*sim.get_membrane());
  for (unsigned int a = 0; a < membrane.n_nodes(); a += 3)
    membrane.cell[a] = BackgroundGrid<2>::invalid;
  EXPECT_EQ(sim.get_mpm_step().get_membrane_coupling()->relocate(), 0u);
  expect_cells_agree();
}



// A point that walks out of a window through its edge (not the mesh's
// boundary) has left the cells its process holds: an error, not a lost
// point. One that leaves through the mesh's boundary is lost, as in a whole
// grid.
TEST(GridWindow, APointBeyondTheWindowIsAnErrorNotALoss)
{
  ThreeStrips             s;
  const BackgroundGrid<2> window = s.grid->window(s.partition->window_cells());
  const PointLocator<2>   locator(window);
  // A cell of the process's own strip, its centre 1/3 wide.
  unsigned int own = BackgroundGrid<2>::invalid;
  for (unsigned int c = 0; c < window.n_cells(); ++c)
    if (s.partition->owners()[window.global_cell(c)] == s.rank)
      own = c;
  ASSERT_NE(own, BackgroundGrid<2>::invalid);
  const double x = centre(window, own)[0];
  // In the farthest strip, past the ghost layer (1/6 wide).
  const double beyond = s.rank == 0 ? 0.95 : 0.05;
  EXPECT_THROW(locator.locate(Point<2>(beyond, 0.5), own), ExceptionBase);
  // The walk alone (the membrane's location) only says "not here".
  EXPECT_EQ(locator.walk(Point<2>(beyond, 0.5), own),
            BackgroundGrid<2>::invalid);
  EXPECT_EQ(locator.locate(Point<2>(x, -0.2), own), BackgroundGrid<2>::invalid);
  EXPECT_EQ(locator.locate(centre(window, own), own), own);
}



// Parallel::gather_to_root: process 0 gets every process's entries of a
// whole-grid array combined in the order of the processes; the others get
// nothing. Its MPI displacements are ints, and a total past 2^31 - 1
// entries is an error with a message (the counts of a gather that large
// cannot be sent here, so the check is tested on the counts alone).
TEST(GatherToRoot, CombinesEveryProcesssEntriesInProcessOrder)
{
  const MPI_Comm     comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n    = Utilities::MPI::n_mpi_processes(comm);
  // Entry `rank` alone, and entry n shared by all: appended in order.
  const std::vector<unsigned int> index  = {rank, n};
  const std::vector<double>       values = {rank + 0.5, double(rank + 1)};
  const auto                      result = Parallel::gather_to_root(
    index, values, n + 1, comm, [](double &sum, const double v) {
      sum = 10 * sum + v;
    });
  if (rank != 0)
    {
      EXPECT_TRUE(result.empty());
      return;
    }
  ASSERT_EQ(result.size(), n + 1);
  double in_order = 0;
  for (unsigned int q = 0; q < n; ++q)
    {
      EXPECT_EQ(result[q], q + 0.5);
      in_order = 10 * in_order + (q + 1);
    }
  EXPECT_EQ(result[n], in_order); // 123 on 3 processes: in process order
}

TEST(GatherToRoot, DisplacementsPastTwoToTheThirtyOneAreAnError)
{
  const int big = std::numeric_limits<int>::max() / 2 + 1; // 2^30
  EXPECT_EQ(Parallel::gather_displacements({3, 0, 4}),
            (std::vector<int>{0, 3, 3, 7}));
  EXPECT_EQ(Parallel::gather_displacements({big - 1, big}).back(),
            std::numeric_limits<int>::max());
  EXPECT_THROW(Parallel::gather_displacements({big, big}), ExceptionBase);
  EXPECT_THROW(Parallel::gather_displacements({big, 1, big}), ExceptionBase);
}
