#include <deal.II/base/exceptions.h>
#include <deal.II/base/memory_consumption.h>

#include <deal.II/fe/fe_simplex_p.h>

#include <fsgmpm/base/broadcast_vector.h>
#include <fsgmpm/grid/background_grid.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>

namespace fsgmpm
{
  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(Triangulation<dim> &&tria)
  {
    // The mesh lives only as long as this constructor: nothing of the step
    // asks deal.II's mesh again, and on every MPI process it held more
    // memory than the grid's own arrays.
    const Triangulation<dim> triangulation(std::move(tria));
    AssertThrow(triangulation.n_active_cells() > 0,
                ExcMessage("The background grid has no cells."));
    AssertThrow(triangulation.all_reference_cells_are_simplex(),
                ExcMessage("The background grid must consist of simplices "
                           "(triangles in 2D, tetrahedra in 3D). Convert "
                           "quadrilateral or hexahedral meshes before use."));
    {
      const FE_SimplexP<dim> fe(1);
      DoFHandler<dim>        dof_handler(triangulation);
      dof_handler.distribute_dofs(fe);
      compute_cell_data(dof_handler);
    }
    check_cells();
    compute_neighbors();
    compute_colouring();
  }



  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(
    const MeshGeneration::SimplexMesh<dim> &mesh)
  {
    AssertThrow(!mesh.cells.empty(),
                ExcMessage("The background grid has no cells."));
    // The nodes are numbered as a DoFHandler numbers the degrees of
    // freedom of FE_SimplexP<dim>(1) on the mesh: by first appearance, cell
    // by cell, vertex by vertex (the numbers of the constructor above;
    // tested).
    std::vector<unsigned int> node_of_vertex(mesh.vertices.size(), invalid);
    cell_nodes.resize(mesh.cells.size());
    unsigned int n = 0;
    for (unsigned int c = 0; c < mesh.cells.size(); ++c)
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int vertex = mesh.cells[c][v];
          AssertThrow(vertex < mesh.vertices.size(),
                      ExcMessage("Cell " + std::to_string(c)
                                 + " of the background grid names vertex "
                                 + std::to_string(vertex) + " of "
                                 + std::to_string(mesh.vertices.size()) + "."));
          if (node_of_vertex[vertex] == invalid)
            node_of_vertex[vertex] = n++;
          cell_nodes[c][v] = node_of_vertex[vertex];
        }
    node_positions.resize(n);
    for (unsigned int vertex = 0; vertex < mesh.vertices.size(); ++vertex)
      if (node_of_vertex[vertex] != invalid)
        node_positions[node_of_vertex[vertex]] = mesh.vertices[vertex];
    check_cells();
    compute_neighbors();
    // A face without a neighbour is on the boundary, with the id of the
    // bounding box's plane it lies on (make_box()'s colorize rule).
    for (unsigned int c = 0; c < n_cells(); ++c)
      for (unsigned int k = 0; k < n_vertices; ++k)
        if (cell_neighbors[c][k] == invalid)
          {
            Point<dim> center;
            for (unsigned int v = 0; v < n_vertices; ++v)
              if (v != k)
                center += node_positions[cell_nodes[c][v]];
            center /= dim;
            boundary_faces.push_back(
              {c,
               k,
               MeshGeneration::bounding_box_id(
                 center, lower_corner, upper_corner, 0)});
          }
    compute_colouring();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::compute_cell_data(const DoFHandler<dim> &dof_handler)
  {
    const unsigned int n = dof_handler.get_triangulation().n_active_cells();
    cell_nodes.resize(n);
    boundary_faces.clear();
    node_positions.resize(dof_handler.n_dofs());

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        AssertThrow(cell->n_vertices() == n_vertices,
                    ExcMessage("Only simplex cells are supported."));
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            const unsigned int node = cell->vertex_dof_index(v, 0);
            cell_nodes[c][v]        = node;
            node_positions[node]    = cell->vertex(v);
          }

        // Boundary ids, by the local vertex opposite the face.
        for (unsigned int f = 0; f < cell->n_faces(); ++f)
          if (cell->face(f)->at_boundary())
            {
              // The face's vertices are all cell vertices but one.
              unsigned int opposite = invalid;
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  bool on_face = false;
                  for (unsigned int fv = 0; fv < cell->face(f)->n_vertices();
                       ++fv)
                    if (cell->face(f)->vertex_index(fv)
                        == cell->vertex_index(v))
                      on_face = true;
                  if (!on_face)
                    opposite = v;
                }
              Assert(opposite != invalid, ExcInternalError());
              boundary_faces.push_back(
                {c, opposite, cell->face(f)->boundary_id()});
            }
      }
    std::sort(boundary_faces.begin(),
              boundary_faces.end(),
              [](const BoundaryFace &a, const BoundaryFace &b) {
                return std::make_pair(a.cell, a.vertex)
                       < std::make_pair(b.cell, b.vertex);
              });
  }



  template <int dim>
  void
  BackgroundGrid<dim>::check_cells()
  {
    min_altitude_global = std::numeric_limits<double>::max();
    max_altitude_global = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower_corner[d] = std::numeric_limits<double>::max();
        upper_corner[d] = -std::numeric_limits<double>::max();
      }
    for (const Point<dim> &x : node_positions)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower_corner[d] = std::min(lower_corner[d], x[d]);
          upper_corner[d] = std::max(upper_corner[d], x[d]);
        }

    for (unsigned int c = 0; c < n_cells(); ++c)
      {
        // A degenerate cell has no inverse edge matrix: refuse it here,
        // once, so that no loop meets it.
        const auto     x = vertices(c);
        Tensor<2, dim> edges;
        double         scale = 1;
        for (unsigned int k = 0; k < dim; ++k)
          {
            for (unsigned int d = 0; d < dim; ++d)
              edges[d][k] = x[k + 1][d] - x[0][d];
            scale *= (x[k + 1] - x[0]).norm();
          }
        // (The message, with the cell's centre, is built only on failure.)
        AssertThrow(std::abs(determinant(edges)) > 1e-12 * scale,
                    ExcMessage("Background-grid cell " + std::to_string(c)
                               + " near " + Utilities::to_string([&x] {
                                   double sum = 0;
                                   for (const Point<dim> &v : x)
                                     sum += v[0];
                                   return sum / n_vertices;
                                 }())
                               + " is degenerate (zero volume)."));

        const double hmin   = min_altitude(c);
        min_altitude_global = std::min(min_altitude_global, hmin);
        max_altitude_global = std::max(max_altitude_global, hmin);
      }
  }



  template <int dim>
  typename BackgroundGrid<dim>::CellsAroundNodes
  BackgroundGrid<dim>::cells_around_nodes() const
  {
    CellsAroundNodes           result;
    std::vector<unsigned int> &start = result.start;
    std::vector<unsigned int> &cells = result.cells;
    start.assign(n_nodes() + 1, 0);
    for (const auto &nodes : cell_nodes)
      for (const unsigned int node : nodes)
        ++start[node + 1];
    for (unsigned int i = 0; i < n_nodes(); ++i)
      start[i + 1] += start[i];
    cells.resize(start.back());
    std::vector<unsigned int> next(start.begin(), start.end() - 1);
    for (unsigned int c = 0; c < n_cells(); ++c)
      for (const unsigned int node : cell_nodes[c])
        cells[next[node]++] = c;
    return result;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::compute_neighbors()
  {
    // The cells around each node (CSR), then the cell across the face
    // opposite vertex k of cell c is the other cell that holds all the
    // face's nodes, searched among the cells around the face's node with
    // the fewest: independent of deal.II's face numbering and orientation
    // conventions for simplices, and a few cells per face where a map of
    // all faces by their nodes took 14 % of the start of a 1.2 M-tetrahedron
    // run (tested against deal.II's neighbours).
    const CellsAroundNodes           around_nodes = cells_around_nodes();
    const std::vector<unsigned int> &start        = around_nodes.start;
    const std::vector<unsigned int> &around       = around_nodes.cells;
    cell_neighbors.assign(n_cells(), {});
    for (auto &nb : cell_neighbors)
      nb.fill(invalid);
    const auto holds = [this](const unsigned int d, const unsigned int node) {
      bool found = false;
      for (const unsigned int i : cell_nodes[d])
        found |= (i == node);
      return found;
    };
    for (unsigned int c = 0; c < n_cells(); ++c)
      for (unsigned int k = 0; k < n_vertices; ++k)
        {
          // Each face once: from the cell with the lower number.
          if (cell_neighbors[c][k] != invalid)
            continue;
          std::array<unsigned int, dim> face;
          for (unsigned int v = 0, j = 0; v < n_vertices; ++v)
            if (v != k)
              face[j++] = cell_nodes[c][v];
          // Search the cells around the face's node with the fewest.
          std::swap(face[0],
                    *std::min_element(face.begin(),
                                      face.end(),
                                      [&](const unsigned int x,
                                          const unsigned int y) {
                                        return start[x + 1] - start[x]
                                               < start[y + 1] - start[y];
                                      }));
          for (unsigned int q = start[face[0]]; q < start[face[0] + 1]; ++q)
            {
              const unsigned int d = around[q];
              if (d == c)
                continue;
              bool holds_face = true;
              for (unsigned int j = 1; j < dim; ++j)
                holds_face = holds_face && holds(d, face[j]);
              if (!holds_face)
                continue;
              AssertThrow(cell_neighbors[c][k] == invalid,
                          ExcMessage("A face of background-grid cell "
                                     + std::to_string(c)
                                     + " is shared by more than two cells: "
                                       "the mesh is not conforming."));
              cell_neighbors[c][k] = d;
              // The same face seen from d: opposite its vertex off the face.
              for (unsigned int v = 0; v < n_vertices; ++v)
                if (std::find(face.begin(), face.end(), cell_nodes[d][v])
                    == face.end())
                  cell_neighbors[d][v] = c;
            }
        }
  }



  template <int dim>
  void
  BackgroundGrid<dim>::compute_colouring()
  {
    // Blocks of consecutive cells: colouring single cells sent a scatter
    // across the whole domain once per colour, missing the cache at every
    // cell (p2g 2.4 times slower in the 3D dam break); a block's cells are
    // neighbours. 16 to 128 cells measured alike (cells_per_block = 32).
    const unsigned int n_blocks
      = (n_cells() + cells_per_block - 1) / cells_per_block;

    // Greedy colouring of the block-node-block graph, in block order so that
    // the result is deterministic.
    std::vector<std::vector<unsigned int>> node_blocks(n_nodes());
    for (unsigned int c = 0; c < n_cells(); ++c)
      for (const unsigned int node : cell_nodes[c])
        if (node_blocks[node].empty()
            || node_blocks[node].back() != cell_block(c))
          node_blocks[node].push_back(cell_block(c));

    block_colour.assign(n_blocks, invalid);
    n_colours = 0;
    std::vector<unsigned int> used_stamp;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        for (unsigned int c = b * cells_per_block;
             c < std::min(n_cells(), (b + 1) * cells_per_block);
             ++c)
          for (const unsigned int node : cell_nodes[c])
            for (const unsigned int other : node_blocks[node])
              if (block_colour[other] != invalid)
                {
                  if (block_colour[other] >= used_stamp.size())
                    used_stamp.resize(block_colour[other] + 1, invalid);
                  used_stamp[block_colour[other]] = b;
                }
        unsigned int colour = 0;
        while (colour < used_stamp.size() && used_stamp[colour] == b)
          ++colour;
        block_colour[b] = colour;
        n_colours       = std::max(n_colours, colour + 1);
      }
  }



  template <int dim>
  void
  BackgroundGrid<dim>::compute_node_volumes()
  {
    if (node_volume.size() == n_nodes())
      return;
    // A rim node of a window misses the volumes of cells further out.
    AssertThrow(!is_window(),
                ExcMessage("Compute the nodal volumes of the whole grid "
                           "before taking its windows."));
    node_volume.assign(n_nodes(), 0.);
    for (unsigned int c = 0; c < n_cells(); ++c)
      {
        const double volume = cell_volume(c);
        for (const unsigned int node : cell_nodes[c])
          node_volume[node] += volume / n_vertices;
      }
  }



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::find_cell_brute_force(const Point<dim> &x,
                                             const double      tolerance,
                                             double           *excess) const
  {
    unsigned int best        = invalid;
    double       best_excess = -std::numeric_limits<double>::max();
    for (unsigned int c = 0; c < n_base_cells(); ++c)
      {
        const auto   l    = barycentric(c, x);
        const double lmin = *std::min_element(l.begin(), l.end());
        if (lmin >= -tolerance && lmin > best_excess)
          {
            best        = c;
            best_excess = lmin;
          }
      }
    if (excess != nullptr)
      *excess = best_excess;
    return best;
  }

  template <int dim>
  unsigned int
  BackgroundGrid<dim>::best_cell_around(const Point<dim>  &x,
                                        const double       tolerance,
                                        const unsigned int start) const
  {
    Assert(start < n_base_cells(), ExcIndexRange(start, 0, n_base_cells()));
    // find_cell_brute_force() keeps the first cell (in number order) with
    // the largest smallest barycentric coordinate: the same rule here.
    unsigned int              best        = invalid;
    double                    best_excess = -std::numeric_limits<double>::max();
    std::vector<unsigned int> seen        = {start};
    for (unsigned int q = 0; q < seen.size(); ++q)
      {
        const unsigned int c    = seen[q];
        const auto         l    = barycentric(c, x);
        const double       lmin = *std::min_element(l.begin(), l.end());
        if (lmin < -tolerance)
          continue;
        if (lmin > best_excess || (lmin == best_excess && c < best))
          {
            best        = c;
            best_excess = lmin;
          }
        for (const unsigned int nb : cell_neighbors[c])
          if (nb != invalid
              && std::find(seen.begin(), seen.end(), nb) == seen.end())
            seen.push_back(nb);
      }
    return best;
  }



  template <int dim>
  BackgroundGrid<dim>
  BackgroundGrid<dim>::window(const std::vector<unsigned int> &cells) const
  {
    BackgroundGrid<dim> w = base_window(cells);
    if (n_fields > 1)
      w.set_velocity_fields(n_fields);
    return w;
  }



  template <int dim>
  BackgroundGrid<dim>
  BackgroundGrid<dim>::base_window(const std::vector<unsigned int> &cells) const
  {
    AssertThrow(!is_window(), ExcMessage("Take windows of a whole grid."));
    AssertThrow(std::adjacent_find(cells.begin(),
                                   cells.end(),
                                   std::greater_equal<unsigned int>())
                    == cells.end()
                  && (cells.empty() || cells.back() < n_base_cells()),
                ExcMessage("The cells of a window must be cells of the "
                           "grid's first velocity field, in ascending order, "
                           "each once."));
    // Field 0 here; the window copies it into the other fields as
    // set_velocity_fields() does for the whole grid.
    BackgroundGrid<dim> w;
    w.n_whole_cells       = n_base_cells();
    w.n_whole_nodes       = n_base_nodes();
    w.min_altitude_global = min_altitude_global;
    w.max_altitude_global = max_altitude_global;
    w.lower_corner        = lower_corner;
    w.upper_corner        = upper_corner;
    w.n_colours           = n_colours / n_fields;
    w.global_cell_index   = cells;

    // The nodes in the whole grid's order.
    auto &nodes = w.global_node_index;
    nodes.reserve(cells.size() * n_vertices);
    for (const unsigned int c : cells)
      nodes.insert(nodes.end(), cell_nodes[c].begin(), cell_nodes[c].end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    nodes.shrink_to_fit();
    w.node_positions.resize(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      w.node_positions[i] = node_positions[nodes[i]];
    if (!node_volume.empty())
      {
        w.node_volume.resize(nodes.size());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          w.node_volume[i] = node_volume[nodes[i]];
      }

    w.cell_nodes.resize(cells.size());
    w.cell_neighbors.resize(cells.size());
    w.window_block.resize(cells.size());
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const unsigned int g = cells[c];
        for (unsigned int k = 0; k < n_vertices; ++k)
          {
            w.cell_nodes[c][k]     = w.local_node(cell_nodes[g][k]);
            const unsigned int nb  = cell_neighbors[g][k];
            w.cell_neighbors[c][k] = nb == invalid ? invalid : w.local_cell(nb);
          }
        // The whole grid's blocks, renumbered in order, with their colours.
        if (c == 0 || g / cells_per_block != cells[c - 1] / cells_per_block)
          w.block_colour.push_back(block_colour[g / cells_per_block]);
        w.window_block[c] = w.block_colour.size() - 1;
      }
    // The mesh's own boundary faces (sorted by cell, so they stay sorted).
    for (const BoundaryFace &face : boundary_faces)
      if (face.cell < n_base_cells())
        {
          const unsigned int c = w.local_cell(face.cell);
          if (c != invalid)
            w.boundary_faces.push_back({c, face.vertex, face.boundary_id});
        }
    return w;
  }



  namespace
  {
    // The number in a window of the whole grid's cell or node g: fields of
    // n_whole numbers there, of index.size() here, index the whole grid's
    // numbers of field 0 (ascending); invalid if the window lacks it.
    unsigned int
    window_number(const std::vector<unsigned int> &index,
                  const unsigned int               n_whole,
                  const unsigned int               n_fields,
                  const unsigned int               g)
    {
      const unsigned int base = g % n_whole, field = g / n_whole;
      const auto it = std::lower_bound(index.begin(), index.end(), base);
      if (field >= n_fields || it == index.end() || *it != base)
        return numbers::invalid_unsigned_int;
      return (it - index.begin()) + field * index.size();
    }
  } // namespace



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::local_cell(const unsigned int g) const
  {
    if (!is_window())
      return g < n_cells() ? g : invalid;
    return window_number(global_cell_index, n_whole_cells, n_fields, g);
  }



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::local_node(const unsigned int g) const
  {
    if (!is_window())
      return g < n_nodes() ? g : invalid;
    return window_number(global_node_index, n_whole_nodes, n_fields, g);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::set_velocity_fields(const unsigned int n)
  {
    AssertThrow(n_fields == 1 && n >= 1,
                ExcMessage("The velocity fields of a grid are set once."));
    const unsigned int nc = n_cells(), nn = n_nodes(), nb = block_colour.size(),
                       nk = n_colours;
    n_fields              = n;
    auto replicate        = [&](auto &v) {
      const auto base = v;
      v.reserve(n * base.size());
      for (unsigned int f = 1; f < n; ++f)
        v.insert(v.end(), base.begin(), base.end());
    };
    replicate(node_positions);
    replicate(node_volume);
    replicate(boundary_faces);
    replicate(cell_nodes);
    replicate(cell_neighbors);
    replicate(block_colour);
    n_colours = n * nk;
    for (unsigned int f = 1; f < n; ++f)
      for (unsigned int c = f * nc; c < (f + 1) * nc; ++c)
        {
          for (auto &i : cell_nodes[c])
            i += f * nn;
          for (auto &neighbor : cell_neighbors[c])
            if (neighbor != invalid)
              neighbor += f * nc;
        }
    const unsigned int n_boundary_faces = boundary_faces.size() / n;
    for (unsigned int f = 1; f < n; ++f)
      for (unsigned int b = f * n_boundary_faces;
           b < (f + 1) * n_boundary_faces;
           ++b)
        boundary_faces[b].cell += f * nc;
    for (unsigned int f = 1; f < n; ++f)
      for (unsigned int b = f * nb; b < (f + 1) * nb; ++b)
        block_colour[b] += f * nk;
  }



  namespace
  {
    using Parallel::for_each_piece;

    // The bytes of a vector of plain values, point to point, in pieces.
    constexpr int window_tag = 1511;

    template <typename T>
    void
    send_vector(const std::vector<T> &values,
                const unsigned int    rank,
                const MPI_Comm       &communicator)
    {
      const std::uint64_t n = values.size();
      int ierr = MPI_Send(&n, 1, MPI_UINT64_T, rank, window_tag, communicator);
      AssertThrowMPI(ierr);
      const char *bytes = reinterpret_cast<const char *>(values.data());
      for_each_piece(n * sizeof(T),
                     [&](const std::uint64_t offset, const int count) {
                       ierr = MPI_Send(bytes + offset,
                                       count,
                                       MPI_BYTE,
                                       rank,
                                       window_tag,
                                       communicator);
                       AssertThrowMPI(ierr);
                     });
    }

    template <typename T>
    void
    receive_vector(std::vector<T>    &values,
                   const unsigned int root,
                   const MPI_Comm    &communicator)
    {
      std::uint64_t n    = 0;
      int           ierr = MPI_Recv(
        &n, 1, MPI_UINT64_T, root, window_tag, communicator, MPI_STATUS_IGNORE);
      AssertThrowMPI(ierr);
      values.resize(n);
      char *bytes = reinterpret_cast<char *>(values.data());
      for_each_piece(n * sizeof(T),
                     [&](const std::uint64_t offset, const int count) {
                       ierr = MPI_Recv(bytes + offset,
                                       count,
                                       MPI_BYTE,
                                       root,
                                       window_tag,
                                       communicator,
                                       MPI_STATUS_IGNORE);
                       AssertThrowMPI(ierr);
                     });
    }
  } // namespace



  template <int dim>
  void
  BackgroundGrid<dim>::send_window(const std::vector<unsigned int> &cells,
                                   const unsigned int               rank,
                                   const MPI_Comm &communicator) const
  {
    const BackgroundGrid<dim> w       = base_window(cells);
    std::vector<double>       scalars = {w.min_altitude_global,
                                         w.max_altitude_global,
                                         double(w.n_colours),
                                         double(w.n_whole_cells),
                                         double(w.n_whole_nodes),
                                         double(n_fields)};
    for (unsigned int d = 0; d < dim; ++d)
      {
        scalars.push_back(w.lower_corner[d]);
        scalars.push_back(w.upper_corner[d]);
      }
    send_vector(scalars, rank, communicator);
    for_each_window_array(w, [&](const auto &values) {
      send_vector(values, rank, communicator);
    });
  }



  template <int dim>
  BackgroundGrid<dim>
  BackgroundGrid<dim>::receive_window(const unsigned int root,
                                      const MPI_Comm    &communicator)
  {
    BackgroundGrid<dim> w;
    std::vector<double> scalars;
    receive_vector(scalars, root, communicator);
    AssertThrow(scalars.size() == 6 + 2 * dim, ExcInternalError());
    w.min_altitude_global = scalars[0];
    w.max_altitude_global = scalars[1];
    w.n_colours           = static_cast<unsigned int>(scalars[2]);
    w.n_whole_cells       = static_cast<unsigned int>(scalars[3]);
    w.n_whole_nodes       = static_cast<unsigned int>(scalars[4]);
    const auto n          = static_cast<unsigned int>(scalars[5]);
    for (unsigned int d = 0; d < dim; ++d)
      {
        w.lower_corner[d] = scalars[6 + 2 * d];
        w.upper_corner[d] = scalars[7 + 2 * d];
      }
    for_each_window_array(w, [&](auto &values) {
      receive_vector(values, root, communicator);
    });
    if (n > 1)
      w.set_velocity_fields(n);
    return w;
  }



  template <int dim>
  std::size_t
  BackgroundGrid<dim>::memory_consumption() const
  {
    return MemoryConsumption::memory_consumption(node_positions)
           + MemoryConsumption::memory_consumption(node_volume)
           + MemoryConsumption::memory_consumption(cell_nodes)
           + MemoryConsumption::memory_consumption(cell_neighbors)
           + boundary_faces.capacity() * sizeof(BoundaryFace)
           + MemoryConsumption::memory_consumption(block_colour)
           + MemoryConsumption::memory_consumption(global_cell_index)
           + MemoryConsumption::memory_consumption(global_node_index)
           + MemoryConsumption::memory_consumption(window_block);
  }



  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace fsgmpm
