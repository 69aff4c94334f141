#include <fsgmpm/io/state_checkpoint.h>

#include <algorithm>
#include <string>
#include <type_traits>

namespace fsgmpm
{
  namespace StateCheckpoint
  {
    namespace
    {
      /// A per-point array as rows of the checkpoint, by its type.
      template <typename T>
      void
      put_array(CheckpointWriter     &out,
                const std::string    &name,
                const std::vector<T> &v)
      {
        if constexpr (std::is_same_v<T,
                                     double> || std::is_same_v<T, unsigned int>)
          out.put_rows(name, v);
        else if constexpr (std::is_integral_v<T>)
          out.put_integer_rows(name, v);
        else
          out.put_tensor_rows(name, v);
      }

      template <typename T>
      std::vector<T>
      get_array(const CheckpointReader &in, const std::string &name)
      {
        if constexpr (std::is_same_v<T, double>)
          return in.doubles(name);
        else if constexpr (std::is_same_v<T, unsigned int>)
          return in.uints(name);
        else if constexpr (std::is_integral_v<T>)
          return in.integers<T>(name);
        else
          return in.tensors<T>(name);
      }
    } // namespace



    template <int dim>
    void
    save(CheckpointWriter          &out,
         const ParticleStore<dim>  &p,
         const BackgroundGrid<dim> &grid)
    {
      // One row per point; with MPI each process writes its own points.
      out.put("particles/has_affine_velocity", double(p.has_affine_velocity()));
      p.for_each_state_array([&](const char *name, const auto &v) {
        const std::string key = std::string("particles/") + name;
        using T               = typename std::decay_t<decltype(v)>::value_type;
        if constexpr (std::is_same_v<T, unsigned int>)
          if (&v == &p.cell)
            {
              // Cells by their number in the whole grid.
              std::vector<unsigned int> cell(v.size());
              for (unsigned int q = 0; q < cell.size(); ++q)
                cell[q] = grid.global_cell(v[q]);
              put_array(out, key, cell);
              return;
            }
        put_array(out, key, v);
      });
    }



    template <int dim>
    void
    load(const CheckpointReader &in,
         ParticleStore<dim>     &p,
         const unsigned int      n_cells)
    {
      // The optional arrays the checkpoint holds are switched on; those
      // this run keeps and an older checkpoint lacks start from the
      // restart (zero, or the displacement counted from there).
      if (in.scalar("particles/has_affine_velocity") != 0
          && !p.has_affine_velocity())
        p.enable_affine_velocity();
      if (in.has("particles/initial_position") && !p.has_initial_position())
        p.enable_initial_position();
      if (in.has("particles/plastic_strain") && !p.has_plasticity())
        p.enable_plasticity();
      // An array the checkpoint lacks stays empty: an optional one is
      // filled in below, any other fails the length check.
      p.for_each_state_array([&](const char *name, auto &v) {
        using T               = typename std::decay_t<decltype(v)>::value_type;
        const std::string key = std::string("particles/") + name;
        v = in.has(key) ? get_array<T>(in, key) : std::vector<T>();
      });
      const unsigned int n = p.position.size();
      if (p.has_affine_velocity() && p.affine_velocity.empty())
        p.affine_velocity.resize(n);
      if (p.has_initial_position() && p.initial_position.empty())
        p.initial_position = p.position;
      if (p.has_plasticity() && p.plastic_strain.empty())
        {
          p.plastic_strain.assign(n, 0.);
          p.yielding.assign(n, 0);
        }
      p.for_each_state_array([&](const char *name, const auto &v) {
        AssertThrow(v.size() == n,
                    ExcMessage(
                      "The checkpoint's point array " + std::string(name)
                      + " has " + std::to_string(v.size()) + " entries for "
                      + std::to_string(n) + " points: it is damaged."));
      });
      for (const unsigned int c : p.cell)
        AssertThrow(c < n_cells,
                    ExcMessage("The checkpoint names cell " + std::to_string(c)
                               + ", but the mesh has " + std::to_string(n_cells)
                               + " cells: it was written for another mesh."));
      // With MPI (in.rows_split()) the points this process read; the
      // caller takes the maximum over the processes.
      p.next_id = 0;
      for (const unsigned int i : p.id)
        p.next_id = std::max(p.next_id, i + 1);
      p.ghost.clear();
      // The points were stored by cell, then id (with MPI, process by
      // process, each holding whole cells): the sort orders the cells and
      // rebuilds the per-cell index, and keeps each cell's order.
      p.sort_by_cell(n_cells);
    }



    template <int dim>
    void
    save(CheckpointWriter &out, const Membrane<dim> &m)
    {
      out.put_tensors("membrane/position", m.position);
      out.put_tensors("membrane/velocity", m.velocity);
      out.put("membrane/mass", m.mass);
      out.put_tensors("membrane/force", m.force);
      out.put("membrane/cell", m.cell);
      out.put("membrane/tangential_slip", double(m.tangential_slip));
      std::vector<unsigned int> ring_sizes, ring_nodes;
      std::vector<double>       ring_rest_length;
      for (unsigned int r = 0; r < m.rings.size(); ++r)
        {
          ring_sizes.push_back(m.rings[r].size());
          ring_nodes.insert(ring_nodes.end(),
                            m.rings[r].begin(),
                            m.rings[r].end());
          ring_rest_length.insert(ring_rest_length.end(),
                                  m.ring_rest_length[r].begin(),
                                  m.ring_rest_length[r].end());
        }
      out.put("membrane/ring_sizes", ring_sizes);
      out.put("membrane/ring_nodes", ring_nodes);
      out.put("membrane/ring_rest_length", ring_rest_length);
      std::vector<unsigned int> elements;
      for (const auto &e : m.elements)
        elements.insert(elements.end(), e.begin(), e.end());
      out.put("membrane/elements", elements);
      out.put("membrane/rest_size", m.rest_size);
      // The rest structure of the membrane's finite elements.
      out.put("membrane/element_degree", double(m.properties.element_degree));
      std::vector<double> rest_vertex;
      for (const auto &x : m.rest_vertex)
        for (unsigned int d = 0; d < dim; ++d)
          rest_vertex.push_back(x[d]);
      out.put("membrane/rest_vertex", rest_vertex);
      std::vector<unsigned int> fe_cells, edge_node;
      for (const auto &c : m.fe_cells)
        fe_cells.insert(fe_cells.end(), c.begin(), c.end());
      for (const auto &e : m.edge_node)
        edge_node.insert(edge_node.end(), e.begin(), e.end());
      out.put("membrane/fe_cells", fe_cells);
      out.put("membrane/vertex_node", m.vertex_node);
      out.put("membrane/edge_node", edge_node);
      std::vector<double> edge_rest_point;
      for (const auto &x : m.edge_rest_point)
        for (unsigned int d = 0; d < dim; ++d)
          edge_rest_point.push_back(x[d]);
      out.put("membrane/edge_rest_point", edge_rest_point);
      out.put("membrane/element_cell", m.element_cell);
      out.put("membrane/tension", m.tension);
      out.put("membrane/minor_tension", m.minor_tension);
    }



    template <int dim>
    void
    load(const CheckpointReader &in, Membrane<dim> &m)
    {
      auto damaged = [](const std::string &what) {
        return ExcMessage("The checkpoint's membrane is damaged: " + what
                          + ".");
      };
      m.position        = in.tensors<Point<dim>>("membrane/position");
      m.velocity        = in.tensors<Tensor<1, dim>>("membrane/velocity");
      m.mass            = in.doubles("membrane/mass");
      m.force           = in.tensors<Tensor<1, dim>>("membrane/force");
      m.cell            = in.uints("membrane/cell");
      m.tangential_slip = in.scalar("membrane/tangential_slip") != 0;

      const unsigned int n = m.position.size();
      AssertThrow(m.velocity.size() == n && m.mass.size() == n
                    && m.force.size() == n && m.cell.size() == n,
                  damaged("its node arrays differ in length"));

      const auto  &sizes = in.uints("membrane/ring_sizes");
      const auto  &nodes = in.uints("membrane/ring_nodes");
      const auto  &rest  = in.doubles("membrane/ring_rest_length");
      unsigned int total = 0;
      for (const unsigned int s : sizes)
        total += s;
      AssertThrow(nodes.size() == total && rest.size() == total,
                  damaged("its rings do not add up"));
      m.rings.assign(sizes.size(), {});
      m.ring_rest_length.assign(sizes.size(), {});
      for (unsigned int r = 0, k = 0; r < sizes.size(); k += sizes[r], ++r)
        {
          m.rings[r].assign(nodes.begin() + k, nodes.begin() + k + sizes[r]);
          m.ring_rest_length[r].assign(rest.begin() + k,
                                       rest.begin() + k + sizes[r]);
        }

      const auto &elements = in.uints("membrane/elements");
      AssertThrow(elements.size() % dim == 0,
                  damaged("its element list is not a list of "
                          + std::to_string(dim) + "-node elements"));
      m.elements.resize(elements.size() / dim);
      for (unsigned int e = 0; e < m.elements.size(); ++e)
        for (unsigned int k = 0; k < dim; ++k)
          {
            m.elements[e][k] = elements[dim * e + k];
            AssertThrow(m.elements[e][k] < n,
                        damaged("an element names a node it does not have"));
          }
      m.rest_size     = in.doubles("membrane/rest_size");
      m.tension       = in.doubles("membrane/tension");
      m.minor_tension = in.doubles("membrane/minor_tension");
      AssertThrow(
        in.scalar("membrane/element_degree") == m.properties.element_degree,
        ExcMessage("The checkpoint's membrane has elements of "
                   "degree "
                   + std::to_string(in.scalar("membrane/element_degree"))
                   + "; the scene asks for Membrane/Element "
                     "degree = "
                   + std::to_string(m.properties.element_degree) + "."));
      const auto &rest_vertex = in.doubles("membrane/rest_vertex");
      const auto &fe_cells    = in.uints("membrane/fe_cells");
      const auto &edge_node   = in.uints("membrane/edge_node");
      m.vertex_node           = in.uints("membrane/vertex_node");
      m.element_cell          = in.uints("membrane/element_cell");
      AssertThrow(rest_vertex.size() == dim * m.vertex_node.size()
                    && fe_cells.size() % dim == 0 && edge_node.size() % 3 == 0,
                  damaged("its rest structure is incomplete"));
      m.rest_vertex.resize(m.vertex_node.size());
      for (unsigned int v = 0; v < m.rest_vertex.size(); ++v)
        for (unsigned int d = 0; d < dim; ++d)
          m.rest_vertex[v][d] = rest_vertex[dim * v + d];
      m.fe_cells.resize(fe_cells.size() / dim);
      for (unsigned int c = 0; c < m.fe_cells.size(); ++c)
        for (unsigned int k = 0; k < dim; ++k)
          {
            m.fe_cells[c][k] = fe_cells[dim * c + k];
            AssertThrow(m.fe_cells[c][k] < m.rest_vertex.size(),
                        damaged("a cell names a vertex it does not have"));
          }
      const auto &edge_rest_point = in.doubles("membrane/edge_rest_point");
      AssertThrow(edge_rest_point.size() == dim * (edge_node.size() / 3),
                  damaged("its edge rest points are incomplete"));
      m.edge_rest_point.resize(edge_node.size() / 3);
      for (unsigned int e = 0; e < m.edge_rest_point.size(); ++e)
        for (unsigned int d = 0; d < dim; ++d)
          m.edge_rest_point[e][d] = edge_rest_point[dim * e + d];
      m.edge_node.resize(edge_node.size() / 3);
      for (unsigned int e = 0; e < m.edge_node.size(); ++e)
        for (unsigned int k = 0; k < 3; ++k)
          m.edge_node[e][k] = edge_node[3 * e + k];
      for (const unsigned int a : m.vertex_node)
        AssertThrow(a < n, damaged("a vertex names a node it does not have"));
      for (const auto &e : m.edge_node)
        AssertThrow(e[2] < n && e[0] < m.rest_vertex.size()
                      && e[1] < m.rest_vertex.size(),
                    damaged("an edge names a node it does not have"));
      for (const unsigned int c : m.element_cell)
        AssertThrow(c < m.fe_cells.size(),
                    damaged("an element names a cell it does not have"));
      const unsigned int n_elements = m.elements.size();
      AssertThrow(m.rest_size.size() == n_elements
                    && m.tension.size() == n_elements
                    && m.element_cell.size() == n_elements,
                  damaged("its element arrays differ in length"));
      // The finite elements from the restored rest structure (the lumped
      // masses it recomputes are those stored).
      m.setup_finite_elements();
    }



    template <int dim>
    void
    save(CheckpointWriter &out, const MembraneCoupling<dim> &coupling)
    {
      out.put_tensors("membrane/weights", coupling.get_weights());
    }



    template <int dim>
    void
    load(const CheckpointReader &in, MembraneCoupling<dim> &coupling)
    {
      coupling.set_weights(
        in.tensors<std::array<double, dim + 1>>("membrane/weights"));
    }



#define FSGMPM_INSTANTIATE(dim)                                          \
  template void save(CheckpointWriter &,                                 \
                     const ParticleStore<dim> &,                         \
                     const BackgroundGrid<dim> &);                       \
  template void load(const CheckpointReader &,                           \
                     ParticleStore<dim> &,                               \
                     const unsigned int);                                \
  template void save(CheckpointWriter &, const Membrane<dim> &);         \
  template void load(const CheckpointReader &, Membrane<dim> &);         \
  template void save(CheckpointWriter &, const MembraneCoupling<dim> &); \
  template void load(const CheckpointReader &, MembraneCoupling<dim> &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace StateCheckpoint
} // namespace fsgmpm
