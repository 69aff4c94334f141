#ifndef fsgmpm_grid_background_grid_h
#define fsgmpm_grid_background_grid_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The simplex background grid of the MPM (triangles in 2D, tetrahedra in
   * 3D) with the per-cell affine data that the explicit step needs.
   *
   * For linear simplices the shape function of local vertex k at a point x is
   * its barycentric coordinate lambda_k(x) and its gradient is constant over
   * the cell. We therefore precompute for every cell the exact inverse A of
   * the affine map once: its rows are the gradients of vertices 1..dim
   * (lambda_1..lambda_dim = A (x - x_0); lambda_0 = 1 - sum, whose gradient
   * is minus theirs), so point location and all particle-grid transfers use
   * only these gradients and the node positions, never a mapping's Newton
   * iteration. Negatively oriented cells (Gmsh tets) need no special care:
   * A is the inverse of the cell's edge matrix whatever the sign of its
   * determinant.
   *
   * Nodes are numbered as the degrees of freedom of a scalar
   * FE_SimplexP<dim>(1) on the triangulation, and cells as its active cells.
   * The grid keeps no deal.II mesh: after its arrays are built, the
   * Triangulation and DoFHandler are released (some 170 B per cell by their
   * memory_consumption(), about 320 B resident; the mesh's vertices and
   * connectivity are node_positions and cell_nodes).
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    static constexpr unsigned int n_vertices = dim + 1;
    static constexpr unsigned int invalid    = static_cast<unsigned int>(-1);

    /**
     * Take ownership of a simplex triangulation (moved in), build all
     * per-cell data from it, and release it. Throws if the mesh is not made
     * of simplices or has a degenerate cell.
     */
    explicit BackgroundGrid(Triangulation<dim> &&triangulation);

    /// An empty grid, for broadcast() to fill.
    BackgroundGrid() = default;

    /**
     * MPI: make the grid of every process of @p communicator a copy of
     * process @p root's, which built it from the mesh; the others call
     * this on an empty grid. Then only one process ever holds deal.II's
     * mesh, whose creation is the peak of a process's memory (its cell
     * list, connectivity and arrays: some 320 B per triangle, where the
     * grid keeps about 80 B). Call before set_velocity_fields().
     */
    void
    broadcast(const MPI_Comm &communicator, const unsigned int root = 0);

    unsigned int
    n_cells() const
    {
      return cell_nodes.size();
    }

    unsigned int
    n_nodes() const
    {
      return node_positions.size();
    }

    // ---- velocity fields (multi-field contact) ---------------------------
    /**
     * Give the grid @p n_fields velocity fields (Bardenhagen et al. 2000):
     * field f > 0 is a copy of the mesh whose cells and nodes are numbered
     * after those of field f - 1 (cell c of field f is c + f n_base_cells(),
     * its nodes i + f n_base_nodes()). A point of field f lives in that
     * field's cells, so every stage of the step transfers it to its own
     * field's nodes without knowing about fields; the contact stage couples
     * the fields where they meet. Call once, before anything is sized by
     * n_cells() or n_nodes(). Copies get colours of their own, so a scatter
     * may also add to the base node (i mod n_base_nodes()) without races.
     */
    void
    set_velocity_fields(const unsigned int n_fields);

    unsigned int
    n_velocity_fields() const
    {
      return n_fields;
    }

    /// Cells and nodes of one field (the deal.II mesh's).
    unsigned int
    n_base_cells() const
    {
      return n_cells() / n_fields;
    }

    unsigned int
    n_base_nodes() const
    {
      return n_nodes() / n_fields;
    }

    unsigned int
    field_of_cell(const unsigned int c) const
    {
      return c / n_base_cells();
    }

    /// The cell of field @p f over the same triangle as cell @p c.
    unsigned int
    cell_in_field(const unsigned int c, const unsigned int f) const
    {
      return c % n_base_cells() + f * n_base_cells();
    }

    unsigned int
    base_node(const unsigned int i) const
    {
      return i % n_base_nodes();
    }

    /// Barycentric coordinates of @p x with respect to cell @p c.
    std::array<double, dim + 1>
    barycentric(const unsigned int c, const Point<dim> &x) const
    {
      // lambda_{k} = grad lambda_k . (x - x_0) for k >= 1 (lambda_k(x_0) =
      // 0): the gradients are the rows of the inverse edge matrix.
      std::array<double, dim + 1> lambda;
      const Tensor<1, dim>        d   = x - node_positions[cell_nodes[c][0]];
      double                      sum = 0;
      for (unsigned int k = 0; k < dim; ++k)
        {
          lambda[k + 1] = inverse_edges[c][k] * d;
          sum += lambda[k + 1];
        }
      lambda[0] = 1. - sum;
      return lambda;
    }

    /**
     * Gradients of the dim + 1 shape functions of cell @p c (constant over
     * the cell): those of vertices 1..dim are the rows of the inverse edge
     * matrix, that of vertex 0 minus their sum (the shape functions sum to
     * one). Computed, not stored: the sum costs dim additions where a
     * stored copy cost 16 B per triangle, 24 B per tetrahedron.
     */
    std::array<Tensor<1, dim>, dim + 1>
    shape_gradients(const unsigned int c) const
    {
      std::array<Tensor<1, dim>, dim + 1> g;
      for (unsigned int k = 0; k < dim; ++k)
        {
          g[k + 1] = inverse_edges[c][k];
          g[0] -= inverse_edges[c][k];
        }
      return g;
    }

    /// Smallest altitude of cell @p c: min_k 1/|grad lambda_k| (for the
    /// time step and the displacement guards; computed, not stored).
    double
    min_altitude(const unsigned int c) const
    {
      double     hmin = std::numeric_limits<double>::max();
      const auto g    = shape_gradients(c);
      for (unsigned int k = 0; k < n_vertices; ++k)
        hmin = std::min(hmin, 1. / g[k].norm());
      return hmin;
    }

    /// Cartesian position from barycentric coordinates in cell @p c.
    Point<dim>
    position(const unsigned int c, const std::array<double, dim + 1> &l) const
    {
      Point<dim> x;
      for (unsigned int k = 0; k < n_vertices; ++k)
        x += l[k] * node_positions[cell_nodes[c][k]];
      return x;
    }

    /// Index of the cell of field 0 containing @p x by testing all cells
    /// (slow; used only as a fallback and in tests). Returns invalid if none
    /// does.
    unsigned int
    find_cell_brute_force(const Point<dim> &x, const double tolerance) const;

    /// Bytes held by the per-cell and per-node arrays.
    std::size_t
    memory_consumption() const;

    /// Smallest and largest cell altitude (for time step and checks).
    double min_altitude_global;
    double max_altitude_global;

    /// Bounding box of the mesh.
    Point<dim> lower_corner;
    Point<dim> upper_corner;

    // ---- per-node data -------------------------------------------------
    std::vector<Point<dim>> node_positions;
    /// Lumped volume of the node: sum over its cells of V_c / (dim + 1).
    std::vector<double> node_volume;

    // ---- per-cell data (index = active cell index) ---------------------
    std::vector<std::array<unsigned int, dim + 1>> cell_nodes;
    /// Inverse of the edge matrix (x_k - x_0): row k - 1 is the gradient of
    /// lambda_k, so lambda_k = grad lambda_k . (x - x_0) (shape_gradients()).
    std::vector<Tensor<2, dim>> inverse_edges;
    std::vector<double>         cell_volume;
    /// Cell across the face opposite local vertex k, or invalid.
    std::vector<std::array<unsigned int, dim + 1>> cell_neighbors;

    /// A face on the mesh boundary: the face of @p cell opposite its local
    /// vertex @p vertex, with its deal.II boundary id.
    struct BoundaryFace
    {
      unsigned int       cell;
      unsigned int       vertex;
      types::boundary_id boundary_id;
    };
    /// The boundary faces (the faces without a neighbour), by cell and then
    /// local vertex: a list, not an id per face of every cell, since only
    /// the setup of the wall conditions reads them.
    std::vector<BoundaryFace> boundary_faces;

    /// Cells in blocks of consecutive numbers (a box mesh numbers its cells
    /// row by row, so a block is a compact strip), and the blocks in colours
    /// such that no two blocks of one colour share a node. Scatters run the
    /// blocks of one colour in parallel without races, each block's cells in
    /// order: the summation order (hence the result) does not depend on the
    /// number of threads, and a block's points and nodes stay in cache.
    /// Block numbers grow with the cell number.
    std::vector<unsigned int> cell_block;
    std::vector<unsigned int> block_colour;
    unsigned int              n_colours = 0;

  private:
    unsigned int n_fields = 1;

    void
    compute_cell_data(const DoFHandler<dim> &dof_handler);
    void
    compute_neighbors();
    void
    compute_colouring();
  };
} // namespace fsgmpm

#endif
