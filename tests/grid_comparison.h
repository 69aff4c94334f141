// Two background grids equal array for array (GoogleTest expectations):
// a grid built two ways (point_location's BoxGrid tests), a window cut and
// the same window sent (point_exchange).
#ifndef fsgmpm_tests_grid_comparison_h
#define fsgmpm_tests_grid_comparison_h

#include <fsgmpm/grid/background_grid.h>
#include <gtest/gtest.h>

namespace fsgmpm
{
  namespace Testing
  {
    template <int dim>
    void
    expect_same_grid_arrays(const BackgroundGrid<dim> &a,
                            const BackgroundGrid<dim> &b)
    {
      ASSERT_EQ(a.n_cells(), b.n_cells());
      ASSERT_EQ(a.n_nodes(), b.n_nodes());
      EXPECT_EQ(a.node_positions, b.node_positions);
      EXPECT_EQ(a.node_volume, b.node_volume);
      EXPECT_EQ(a.cell_nodes, b.cell_nodes);
      EXPECT_EQ(a.cell_neighbors, b.cell_neighbors);
      ASSERT_EQ(a.boundary_faces.size(), b.boundary_faces.size());
      for (unsigned int f = 0; f < a.boundary_faces.size(); ++f)
        {
          EXPECT_EQ(a.boundary_faces[f].cell, b.boundary_faces[f].cell);
          EXPECT_EQ(a.boundary_faces[f].vertex, b.boundary_faces[f].vertex);
          EXPECT_EQ(a.boundary_faces[f].boundary_id,
                    b.boundary_faces[f].boundary_id);
        }
      EXPECT_EQ(a.block_colour, b.block_colour);
      EXPECT_EQ(a.n_colours, b.n_colours);
      EXPECT_EQ(a.min_altitude_global, b.min_altitude_global);
      EXPECT_EQ(a.max_altitude_global, b.max_altitude_global);
      EXPECT_EQ(a.lower_corner, b.lower_corner);
      EXPECT_EQ(a.upper_corner, b.upper_corner);
    }
  } // namespace Testing
} // namespace fsgmpm

#endif
