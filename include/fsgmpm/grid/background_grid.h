#ifndef fsgmpm_grid_background_grid_h
#define fsgmpm_grid_background_grid_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <fsgmpm/grid/cell_geometry.h>
#include <fsgmpm/grid/mesh_generation.h>

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
   * The grid stores node positions, cell connectivity and neighbours
   * only; a cell's affine data (inverse edge matrix, volume: CellGeometry)
   * is computed from its vertices where a loop needs it.
   *
   * Nodes are numbered as the degrees of freedom of a scalar
   * FE_SimplexP<dim>(1) on the triangulation, and cells as its active cells.
   * The grid keeps no deal.II mesh: after its arrays are built, the
   * Triangulation and DoFHandler are released (some 170 B per cell by their
   * memory_consumption(), about 320 B resident; the mesh's vertices and
   * connectivity are node_positions and cell_nodes). A box (the "box" and
   * "extruded box" grids of the scenes) never creates them: its grid is
   * built from the vertices and cells that deal.II's generator would hand
   * its Triangulation, the nodes numbered as the DoFHandler would number
   * them (BackgroundGrid(const SimplexMesh &), tested equal array for
   * array), since creating the mesh held some 300 B per triangle at its
   * peak.
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

    /**
     * The grid of a mesh given as arrays (MeshGeneration::box_simplices(),
     * extrude_simplices()), without creating deal.II's Triangulation, which
     * at its creation holds some 15 times the memory of these arrays. The same
     * grid as the constructor above makes from the Triangulation that
     * Triangulation::create_triangulation() makes of these vertices and
     * cells, array for array (nodes numbered as the DoFHandler numbers
     * them); boundary faces get the id of the bounding box's plane they lie
     * on, as MeshGeneration::make_box() gives them. Throws as above.
     */
    explicit BackgroundGrid(const MeshGeneration::SimplexMesh<dim> &mesh);

    /// An empty grid, for receive_window() to fill.
    BackgroundGrid() = default;

    /**
     * MPI: the part of this grid that one process needs, numbered on its
     * own: the cells @p cells (ascending cell numbers of this grid; for a
     * process, those it owns and every cell that shares a vertex with one
     * of them, DomainPartition::window_cells()) and their nodes. Both keep
     * the order of this grid's numbers, and every cell keeps its block's
     * colour, so a scatter over the window's cells (CellLoops::
     * scatter_by_colour) adds to a node in the order the whole grid does:
     * a node whose cells the window holds all gets the whole grid's sum,
     * bit for bit. A face towards a cell outside the window has no
     * neighbour and is not a boundary face. The size of a window is that of
     * the process's share of the mesh, not of the mesh (the road to a grid
     * that no process holds whole: doc/mpi.md, "Grid windows").
     *
     * @p cells are cells of the first velocity field; a grid with several
     * fields gives a window with as many, each holding the same cells. The
     * nodal volumes go along if this grid has them (a window cannot compute
     * them on its rim).
     */
    BackgroundGrid<dim>
    window(const std::vector<unsigned int> &cells) const;

    /**
     * MPI: send process @p rank of @p communicator its window() of this
     * (whole) grid, the cells @p cells; it calls receive_window(). Only
     * the window travels (field 0 of it; the receiver copies the other
     * velocity fields), so no process but the sender holds the whole grid.
     */
    void
    send_window(const std::vector<unsigned int> &cells,
                const unsigned int               rank,
                const MPI_Comm                  &communicator) const;

    /// The window process @p root sends with send_window().
    static BackgroundGrid<dim>
    receive_window(const unsigned int root, const MPI_Comm &communicator);

    /// Whether this grid is a window() of a whole grid.
    bool
    is_window() const
    {
      return n_whole_cells > 0;
    }

    /// The number in the whole grid of cell @p c (itself in a whole grid).
    unsigned int
    global_cell(const unsigned int c) const
    {
      return is_window() ? global_cell_index[c % n_base_cells()]
                             + field_of_cell(c) * n_whole_cells
                         : c;
    }

    /// The number in the whole grid of node @p i (itself in a whole grid).
    unsigned int
    global_node(const unsigned int i) const
    {
      return is_window() ? global_node_index[i % n_base_nodes()]
                             + (i / n_base_nodes()) * n_whole_nodes
                         : i;
    }

    /// Cells of the whole grid (of all velocity fields; n_cells() in a
    /// whole grid).
    unsigned int
    n_global_cells() const
    {
      return is_window() ? n_whole_cells * n_fields : n_cells();
    }

    /// Nodes of the whole grid (of all velocity fields; n_nodes() in a
    /// whole grid).
    unsigned int
    n_global_nodes() const
    {
      return is_window() ? n_whole_nodes * n_fields : n_nodes();
    }

    /// The cell of field 0 of the whole grid over the same triangle as the
    /// whole grid's cell @p g.
    unsigned int
    global_base_cell(const unsigned int g) const
    {
      return g % (n_global_cells() / n_fields);
    }

    /// The number here of the whole grid's cell @p g, or invalid if this
    /// window does not hold it.
    unsigned int
    local_cell(const unsigned int g) const;

    /// The number here of the whole grid's node @p g, or invalid.
    unsigned int
    local_node(const unsigned int g) const;

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

    // One velocity field (most scenes): no integer division in the loops
    // that ask these per point.
    unsigned int
    field_of_cell(const unsigned int c) const
    {
      return n_fields == 1 ? 0 : c / n_base_cells();
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
      return n_fields == 1 ? i : i % n_base_nodes();
    }

    /// The affine data of cell @p c (inverse edge matrix, volume),
    /// computed from its vertices. Loops over the points of a cell compute
    /// it once per cell.
    CellGeometry<dim>
    geometry(const unsigned int c) const
    {
      return CellGeometry<dim>(vertices(c));
    }

    /// The positions of the vertices of cell @p c.
    std::array<Point<dim>, dim + 1>
    vertices(const unsigned int c) const
    {
      std::array<Point<dim>, dim + 1> x;
      for (unsigned int k = 0; k < n_vertices; ++k)
        x[k] = node_positions[cell_nodes[c][k]];
      return x;
    }

    /// Barycentric coordinates of @p x with respect to cell @p c (computes
    /// the cell's geometry: in a loop over a cell's points, call geometry()
    /// once instead).
    std::array<double, dim + 1>
    barycentric(const unsigned int c, const Point<dim> &x) const
    {
      return geometry(c).barycentric(x);
    }

    /// Gradients of the dim + 1 shape functions of cell @p c.
    std::array<Tensor<1, dim>, dim + 1>
    shape_gradients(const unsigned int c) const
    {
      return geometry(c).shape_gradients();
    }

    /// Smallest altitude of cell @p c.
    double
    min_altitude(const unsigned int c) const
    {
      return geometry(c).min_altitude();
    }

    /// Volume (area in 2D) of cell @p c.
    double
    cell_volume(const unsigned int c) const
    {
      return CellGeometry<dim>::volume_of(
        CellGeometry<dim>::edge_matrix(vertices(c)));
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
    /// does. The cell with the largest smallest barycentric coordinate
    /// wins, the lowest number on a tie; @p excess (if given) receives that
    /// coordinate.
    unsigned int
    find_cell_brute_force(const Point<dim> &x,
                          const double      tolerance,
                          double           *excess = nullptr) const;

    /// find_cell_brute_force()'s cell, from @p start, a cell of field 0
    /// that holds @p x up to @p tolerance: the cells that hold x are those
    /// around the vertex, edge or face x lies on, face neighbours of one
    /// another, so a search through face neighbours that hold x finds all
    /// of them (a handful, not all cells).
    unsigned int
    best_cell_around(const Point<dim>  &x,
                     const double       tolerance,
                     const unsigned int start) const;

    /// The cells around each node, as one list with offsets: the cells
    /// around node i are cells[start[i]], ..., cells[start[i + 1] - 1], in
    /// ascending order (a temporary: the neighbours and an MPI partition's
    /// ghost layer are built from it, 4 B per cell and vertex).
    struct CellsAroundNodes
    {
      std::vector<unsigned int> start, cells;
    };

    CellsAroundNodes
    cells_around_nodes() const;

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
    /// Empty until compute_node_volumes() (only the multi-field contact and
    /// APIC's affine remap read it).
    std::vector<double> node_volume;

    /// Fill node_volume (if it is empty), in cell order.
    void
    compute_node_volumes();

    // ---- per-cell data (index = active cell index) ---------------------
    std::vector<std::array<unsigned int, dim + 1>> cell_nodes;
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
    unsigned int
    cell_block(const unsigned int c) const
    {
      return n_fields == 1
               ? base_cell_block(c)
               : base_cell_block(c % n_base_cells())
                   + field_of_cell(c) * (block_colour.size() / n_fields);
    }
    static constexpr unsigned int cells_per_block = 32;
    std::vector<unsigned int>     block_colour;
    unsigned int                  n_colours = 0;

  private:
    unsigned int n_fields = 1;

    /// A window's cells and nodes by their numbers in the whole grid
    /// (ascending), the whole grid's sizes, and each cell's block (its
    /// blocks are the whole grid's blocks it meets, in order). All empty or
    /// zero in a whole grid (which has cells: n_whole_cells > 0 marks a
    /// window).
    std::vector<unsigned int> global_cell_index, global_node_index;
    unsigned int              n_whole_cells = 0, n_whole_nodes = 0;
    std::vector<unsigned int> window_block;

    /// window() of field 0 only.
    BackgroundGrid<dim>
    base_window(const std::vector<unsigned int> &cells) const;

    /// Call f(v) for every array a window sends (send_window(),
    /// receive_window()): one list, so the two cannot disagree. @p Grid is
    /// BackgroundGrid or its const.
    template <typename Grid, typename Function>
    static void
    for_each_window_array(Grid &w, const Function &f)
    {
      f(w.global_cell_index);
      f(w.global_node_index);
      f(w.window_block);
      f(w.node_positions);
      f(w.node_volume);
      f(w.cell_nodes);
      f(w.cell_neighbors);
      f(w.boundary_faces);
      f(w.block_colour);
    }

    unsigned int
    base_cell_block(const unsigned int c) const
    {
      return is_window() ? window_block[c] : c / cells_per_block;
    }

    void
    compute_cell_data(const DoFHandler<dim> &dof_handler);
    /// The bounding box and the altitudes; throws on a degenerate cell.
    void
    check_cells();
    void
    compute_neighbors();
    void
    compute_colouring();
  };
} // namespace fsgmpm

#endif
