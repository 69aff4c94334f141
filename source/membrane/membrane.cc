#include <deal.II/base/exceptions.h>

#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/membrane/membrane_slip.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace fsgmpm
{
  template <int dim>
  Membrane<dim>::Membrane(const Triangulation<dim - 1, dim> &mesh,
                          const MembraneProperties          &props,
                          const std::map<std::pair<unsigned int, unsigned int>,
                                         Point<dim>>        &edge_middle_points)
    : properties(props)
  {
    AssertThrow(props.axial_stiffness > 0
                  && std::isfinite(props.axial_stiffness),
                ExcMessage("Membrane/Axial stiffness EA must be positive."));
    AssertThrow(props.areal_mass > 0 && std::isfinite(props.areal_mass),
                ExcMessage("Membrane/Areal mass must be positive (the "
                           "membrane nodes need mass to move with the "
                           "grid)."));
    AssertThrow(props.initial_strain > -0.5 && props.initial_strain < 1,
                ExcMessage("Membrane/Initial strain must lie in (-0.5, 1)."));
    AssertThrow(props.poisson_ratio > -1 && props.poisson_ratio < 1,
                ExcMessage("Membrane/Poisson ratio must lie in (-1, 1)."));

    AssertThrow(props.element_degree == 1 || props.element_degree == 2,
                ExcMessage("Membrane/Element degree must be 1 or 2; got "
                           + std::to_string(props.element_degree) + "."));

    // Only the vertices used by cells become nodes, numbered in order of
    // first use (at degree 2 with the edge midpoints between them) so that
    // a closed 2D loop is stored in loop order. The rest state is the
    // initial one shrunk by 1 + eps0.
    const double                         s = 1. / (1. + props.initial_strain);
    const auto                          &vertices = mesh.get_vertices();
    std::map<unsigned int, unsigned int> rest_vertex_of;
    auto                                 add_node = [&](const Point<dim> &x) {
      position.push_back(x);
      return static_cast<unsigned int>(position.size() - 1);
    };
    for (const auto &c : mesh.active_cell_iterators())
      {
        std::array<unsigned int, dim> cell_vertices;
        for (unsigned int k = 0; k < dim; ++k)
          {
            const unsigned int v  = c->vertex_index(k);
            auto               it = rest_vertex_of.find(v);
            if (it == rest_vertex_of.end())
              {
                it = rest_vertex_of.emplace(v, rest_vertex.size()).first;
                rest_vertex.push_back(Point<dim>(s * vertices[v]));
                vertex_node.push_back(static_cast<unsigned int>(-1));
              }
            cell_vertices[k] = it->second;
          }
        // Vertex nodes, and at degree 2 the edge midpoints (2D: between the
        // two vertices in the loop order).
        for (unsigned int k = 0; k < dim; ++k)
          {
            const unsigned int v = cell_vertices[k];
            if (vertex_node[v] == static_cast<unsigned int>(-1))
              vertex_node[v] = add_node(vertices[c->vertex_index(k)]);
            if (props.element_degree == 2 && (dim == 3 || k == 0))
              {
                const unsigned int w  = cell_vertices[(k + 1) % dim];
                const unsigned int wk = (k + 1) % dim;
                if (node_of_edge(v, w) == static_cast<unsigned int>(-1))
                  {
                    const unsigned int mv = c->vertex_index(k),
                                       mw = c->vertex_index(wk);
                    const auto curved     = edge_middle_points.find(
                      {std::min(mv, mw), std::max(mv, mw)});
                    edge_lookup[{std::min(v, w), std::max(v, w)}]
                      = edge_node.size();
                    edge_node.push_back(
                      {{std::min(v, w),
                        std::max(v, w),
                        add_node(curved != edge_middle_points.end()
                                   ? curved->second
                                   : Point<dim>(
                                     0.5 * (vertices[mv] + vertices[mw])))}});
                  }
              }
          }
        fe_cells.push_back(cell_vertices);
      }
    AssertThrow(!fe_cells.empty(),
                ExcMessage("The membrane mesh has no elements."));
    // Degree 2 in 2D: the middle nodes on the smooth curve through the
    // vertices (the arcs through each cell's neighbours, averaged, as
    // MembraneSlip::equalize_stretch() places nodes), so that a curved membrane
    // is curved at rest and not strained by (kappa h)^2/24 when it keeps its
    // shape.
    if (dim == 2 && props.element_degree == 2 && edge_middle_points.empty())
      {
        const unsigned int        invalid = static_cast<unsigned int>(-1);
        std::vector<unsigned int> cell_ending_at(rest_vertex.size(), invalid),
          cell_starting_at(rest_vertex.size(), invalid);
        for (unsigned int c = 0; c < fe_cells.size(); ++c)
          {
            cell_starting_at[fe_cells[c][0]]     = c;
            cell_ending_at[fe_cells[c][dim - 1]] = c;
          }
        for (unsigned int c = 0; c < fe_cells.size(); ++c)
          {
            const unsigned int v0 = fe_cells[c][0], v1 = fe_cells[c][dim - 1];
            const Point<dim>  &x0 = position[vertex_node[v0]];
            const Point<dim>  &x1 = position[vertex_node[v1]];
            Point<dim>         sum;
            unsigned int       n_arcs = 0;
            if (cell_ending_at[v0] != invalid)
              {
                sum += MembraneGeometry::point_on_arc(
                  position[vertex_node[fe_cells[cell_ending_at[v0]][0]]],
                  x0,
                  x1,
                  x0,
                  x1,
                  0.5);
                ++n_arcs;
              }
            if (cell_starting_at[v1] != invalid)
              {
                sum += MembraneGeometry::point_on_arc(
                  x0,
                  x1,
                  position
                    [vertex_node[fe_cells[cell_starting_at[v1]][dim - 1]]],
                  x0,
                  x1,
                  0.5);
                ++n_arcs;
              }
            if (n_arcs > 0)
              position[node_of_edge(v0, v1)] = Point<dim>(sum / n_arcs);
          }
      }
    for (const auto &e : edge_node)
      edge_rest_point.push_back(Point<dim>(s * position[e[2]]));
    for (unsigned int c = 0; c < fe_cells.size(); ++c)
      add_elements_of_cell(c);

    const unsigned int n = position.size();
    velocity.assign(n, Tensor<1, dim>());
    force.assign(n, Tensor<1, dim>());
    cell.assign(n, static_cast<unsigned int>(-1));
    setup_finite_elements();
    find_rings();
    compute_forces();
  }



  template <int dim>
  unsigned int
  Membrane<dim>::edge_index(const unsigned int v, const unsigned int w) const
  {
    if (!edge_lookup_valid)
      {
        edge_lookup.clear();
        for (unsigned int k = 0; k < edge_node.size(); ++k)
          edge_lookup[{edge_node[k][0], edge_node[k][1]}] = k;
        edge_lookup_valid = true;
      }
    const auto it = edge_lookup.find({std::min(v, w), std::max(v, w)});
    return it == edge_lookup.end() ? static_cast<unsigned int>(-1) : it->second;
  }



  template <int dim>
  unsigned int
  Membrane<dim>::node_of_edge(const unsigned int v, const unsigned int w) const
  {
    const unsigned int k = edge_index(v, w);
    return k == static_cast<unsigned int>(-1) ? k : edge_node[k][2];
  }



  template <int dim>
  void
  Membrane<dim>::add_elements_of_cell(const unsigned int c)
  {
    const auto &v = fe_cells[c];
    // The pieces by their nodes and the rest positions of those nodes.
    std::vector<std::array<unsigned int, dim>> pieces;
    std::vector<std::array<Point<dim>, dim>>   rest;
    if (properties.element_degree == 1)
      {
        std::array<unsigned int, dim> e;
        std::array<Point<dim>, dim>   X;
        for (unsigned int k = 0; k < dim; ++k)
          {
            e[k] = vertex_node[v[k]];
            X[k] = rest_vertex[v[k]];
          }
        pieces.push_back(e);
        rest.push_back(X);
      }
    else
      {
        std::array<unsigned int, dim> corner, middle;
        std::array<Point<dim>, dim>   C, M;
        for (unsigned int k = 0; k < dim; ++k)
          {
            const unsigned int edge = edge_index(v[k], v[(k + 1) % dim]);
            corner[k]               = vertex_node[v[k]];
            middle[k]               = edge_node[edge][2];
            C[k]                    = rest_vertex[v[k]];
            M[k]                    = edge_rest_point[edge];
          }
        if constexpr (dim == 2)
          {
            pieces = {{{corner[0], middle[0]}}, {{middle[0], corner[1]}}};
            rest   = {{{C[0], M[0]}}, {{M[0], C[1]}}};
          }
        else
          {
            pieces = {{{corner[0], middle[0], middle[2]}},
                      {{middle[0], corner[1], middle[1]}},
                      {{middle[2], middle[1], corner[2]}},
                      {{middle[0], middle[1], middle[2]}}};
            rest   = {{{C[0], M[0], M[2]}},
                      {{M[0], C[1], M[1]}},
                      {{M[2], M[1], C[2]}},
                      {{M[0], M[1], M[2]}}};
          }
      }
    for (unsigned int k = 0; k < pieces.size(); ++k)
      {
        // Rest size: the straight piece's length (2D) or area (3D).
        const auto &X    = rest[k];
        double      size = 0;
        if constexpr (dim == 2)
          size = X[0].distance(X[1]);
        else
          size = 0.5 * cross_product_3d(X[1] - X[0], X[2] - X[0]).norm();
        AssertThrow(size > 0,
                    ExcMessage("Membrane element " + std::to_string(c)
                               + " has zero size (coincident nodes)."));
        elements.push_back(pieces[k]);
        rest_size.push_back(size);
        element_cell.push_back(c);
        tension.push_back(0.);
        minor_tension.push_back(0.);
      }
  }



  template <int dim>
  void
  Membrane<dim>::setup_finite_elements()
  {
    // The rest structure may have been rewritten (a checkpoint, a split).
    edge_lookup_valid = false;
    std::vector<CellData<dim - 1>> cells(fe_cells.size());
    for (unsigned int c = 0; c < fe_cells.size(); ++c)
      cells[c].vertices.assign(fe_cells[c].begin(), fe_cells[c].end());
    Triangulation<dim - 1, dim> rest;
    rest.create_triangulation(rest_vertex, cells, SubCellData());
    fe = std::make_unique<MembraneFE<dim>>(rest,
                                           properties.element_degree,
                                           properties.axial_stiffness,
                                           properties.poisson_ratio);

    // The node of every support point: vertex DoFs come first on a cell,
    // then one per edge at degree 2 (FE_SimplexP's order).
    const unsigned int invalid = static_cast<unsigned int>(-1);
    node_of_dof.assign(fe->n_support_points(), invalid);
    active_cell_of_cell.assign(fe_cells.size(), invalid);
    const auto                          &dof_handler = fe->get_dof_handler();
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        // create_triangulation keeps the cells' order and vertex numbers.
        const unsigned int c = cell->index();
        for (unsigned int k = 0; k < dim; ++k)
          AssertThrow(std::find(fe_cells[c].begin(),
                                fe_cells[c].end(),
                                cell->vertex_index(k))
                        != fe_cells[c].end(),
                      ExcInternalError());
        active_cell_of_cell[c] = cell->active_cell_index();
        for (unsigned int k = 0; k < dim; ++k)
          node_of_dof[dofs[k]] = vertex_node[cell->vertex_index(k)];
        // Degree 2: the edge DoFs follow, one per line of the reference
        // cell (2D: the cable's interior DoF).
        if (properties.element_degree == 2)
          for (unsigned int l = 0; l < (dim == 2 ? 1 : 3); ++l)
            {
              const unsigned int node
                = dim == 2
                    ? node_of_edge(cell->vertex_index(0), cell->vertex_index(1))
                    : node_of_edge(cell->line(l)->vertex_index(0),
                                   cell->line(l)->vertex_index(1));
              AssertThrow(node != invalid, ExcInternalError());
              node_of_dof[dofs[dim + l]] = node;
            }
      }
    for (const unsigned int a : node_of_dof)
      AssertThrow(a != invalid && a < position.size(), ExcInternalError());

    // Degree 2: the rest cells through the rest middle nodes (curved where
    // the membrane was).
    if (properties.element_degree == 2)
      {
        std::vector<Point<dim>> X(fe->n_support_points());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dim; ++k)
              X[dofs[k]] = rest_vertex[cell->vertex_index(k)];
            for (unsigned int l = 0; l < (dim == 2 ? 1 : 3); ++l)
              X[dofs[dim + l]]
                = edge_rest_point[dim == 2 ? edge_index(cell->vertex_index(0),
                                                        cell->vertex_index(1))
                                           : edge_index(
                                             cell->line(l)->vertex_index(0),
                                             cell->line(l)->vertex_index(1))];
          }
        fe->set_rest_support_points(X);
      }

    // Lumped masses of the support points (HRZ, positive at every node).
    const std::vector<double> dof_mass
      = fe->lumped_masses(properties.areal_mass);
    mass.assign(position.size(), 0.);
    for (unsigned int i = 0; i < dof_mass.size(); ++i)
      mass[node_of_dof[i]] = dof_mass[i];
  }



  template <int dim>
  void
  Membrane<dim>::compute_forces()
  {
    dof_position.resize(node_of_dof.size());
    for (unsigned int i = 0; i < node_of_dof.size(); ++i)
      dof_position[i] = position[node_of_dof[i]];
    fe->internal_forces(dof_position, dof_force, &cell_stress);
    for (unsigned int i = 0; i < node_of_dof.size(); ++i)
      force[node_of_dof[i]] = dof_force[i];
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const auto &stress = cell_stress[active_cell_of_cell[element_cell[e]]];
        tension[e]         = stress[0];
        minor_tension[e]   = stress[1];
      }
    // Ground contact (frictionless: a normal penalty force only).
    ground.add_forces(*this, force);
  }



  template <int dim>
  unsigned int
  Membrane<dim>::split_long_elements(const double max_length)
  {
    if constexpr (dim == 3)
      {
        unsigned int n_long = 0;
        for (unsigned int e = 0; e < elements.size(); ++e)
          for (unsigned int k = 0; k < 3; ++k)
            if (position[elements[e][k]].distance(
                  position[elements[e][(k + 1) % 3]])
                > max_length)
              {
                ++n_long;
                break;
              }
        return n_long;
      }
    else
      {
        const unsigned int n_before = n_nodes();
        const unsigned int per_cell = properties.element_degree;
        // The elements of a cell are consecutive (loop order).
        for (unsigned int e = 0; e < elements.size(); e += per_cell)
          {
            bool too_long = false;
            for (unsigned int k = 0; k < per_cell; ++k)
              too_long = too_long
                         || position[elements[e + k][0]].distance(
                              position[elements[e + k][1]])
                              > max_length;
            if (!too_long)
              continue;
            const unsigned int c  = element_cell[e];
            const unsigned int v0 = fe_cells[c][0], v1 = fe_cells[c][1];
            const unsigned int a = elements[e][0],
                               b = elements[e + per_cell - 1][1];
            // A new node lies within the element's length of node a: its
            // cell is where the location's walk starts.
            const unsigned int cell_of_a = cell[a];
            auto add_node = [&](const Point<dim> &x, const Tensor<1, dim> &v) {
              position.push_back(x);
              velocity.push_back(v);
              force.push_back(Tensor<1, dim>());
              cell.push_back(cell_of_a);
              return static_cast<unsigned int>(position.size() - 1);
            };
            // The new rest vertex at the middle of the rest cell; the cell
            // becomes (v0, m) and a new cell (m, v1) follows it.
            // At degree 2 the middle node's rest point, so that the halves
            // are the same rest curve.
            const unsigned int m = rest_vertex.size();
            const unsigned int parent_edge
              = per_cell == 2 ? edge_index(v0, v1) : 0;
            const Point<dim> X0 = rest_vertex[v0], X1 = rest_vertex[v1];
            const Point<dim> Xm = per_cell == 2 ? edge_rest_point[parent_edge]
                                                : Point<dim>(0.5 * (X0 + X1));
            rest_vertex.push_back(Xm);
            std::vector<std::array<unsigned int, dim>> pieces;
            if (per_cell == 1)
              {
                // Degree 1: the new node at the chord's midpoint.
                vertex_node.push_back(
                  add_node(Point<dim>(0.5 * (position[a] + position[b])),
                           0.5 * (velocity[a] + velocity[b])));
                pieces = {{{a, vertex_node[m]}}, {{vertex_node[m], b}}};
              }
            else
              {
                // Degree 2: the midpoint node becomes the vertex; the new
                // edge midpoints take the quadratic at 1/4 and 3/4,
                // x(1/4) = (3 x0 - x1)/8 + 3 xm/4.
                const unsigned int mid = elements[e][1];
                vertex_node.push_back(mid);
                auto quarter = [](const Tensor<1, dim> &x0,
                                  const Tensor<1, dim> &x1,
                                  const Tensor<1, dim> &xm) {
                  return Tensor<1, dim>(0.375 * x0 - 0.125 * x1 + 0.75 * xm);
                };
                const unsigned int q0 = add_node(
                  Point<dim>(quarter(position[a], position[b], position[mid])),
                  quarter(velocity[a], velocity[b], velocity[mid]));
                const unsigned int q1 = add_node(
                  Point<dim>(quarter(position[b], position[a], position[mid])),
                  quarter(velocity[b], velocity[a], velocity[mid]));
                edge_node.erase(edge_node.begin() + parent_edge);
                edge_lookup_valid = false;
                edge_rest_point.erase(edge_rest_point.begin() + parent_edge);
                edge_node.push_back({{std::min(v0, m), std::max(v0, m), q0}});
                edge_node.push_back({{std::min(m, v1), std::max(m, v1), q1}});
                edge_rest_point.push_back(Point<dim>(quarter(X0, X1, Xm)));
                edge_rest_point.push_back(Point<dim>(quarter(X1, X0, Xm)));
                pieces = {{{a, q0}}, {{q0, mid}}, {{mid, q1}}, {{q1, b}}};
              }
            const unsigned int c_new = fe_cells.size();
            fe_cells[c]              = {{v0, m}};
            fe_cells.push_back({{m, v1}});
            // Replace the cell's elements by the two halves' in loop order.
            std::vector<double> piece(pieces.size());
            if (per_cell == 1)
              piece = {X0.distance(Xm), Xm.distance(X1)};
            else
              {
                const Point<dim> Q0
                  = edge_rest_point[edge_rest_point.size() - 2],
                  Q1  = edge_rest_point.back();
                piece = {X0.distance(Q0),
                         Q0.distance(Xm),
                         Xm.distance(Q1),
                         Q1.distance(X1)};
              }
            const double T = tension[e];
            elements.erase(elements.begin() + e,
                           elements.begin() + e + per_cell);
            rest_size.erase(rest_size.begin() + e,
                            rest_size.begin() + e + per_cell);
            element_cell.erase(element_cell.begin() + e,
                               element_cell.begin() + e + per_cell);
            tension.erase(tension.begin() + e, tension.begin() + e + per_cell);
            minor_tension.erase(minor_tension.begin() + e,
                                minor_tension.begin() + e + per_cell);
            for (unsigned int k = 0; k < pieces.size(); ++k)
              {
                elements.insert(elements.begin() + e + k, pieces[k]);
                rest_size.insert(rest_size.begin() + e + k, piece[k]);
                element_cell.insert(element_cell.begin() + e + k,
                                    k < pieces.size() / 2 ? c : c_new);
                tension.insert(tension.begin() + e + k, T);
                minor_tension.insert(minor_tension.begin() + e + k, 0.);
              }
            e -= per_cell; // the first half may still be too long
          }
        if (n_nodes() > n_before)
          setup_finite_elements();
        return n_nodes() - n_before;
      }
  }



  template <int dim>
  double
  Membrane<dim>::element_size(const unsigned int e) const
  {
    const auto &el = elements[e];
    if constexpr (dim == 2)
      return position[el[0]].distance(position[el[1]]);
    else
      return 0.5
             * cross_product_3d(position[el[1]] - position[el[0]],
                                position[el[2]] - position[el[0]])
                 .norm();
  }



  template <int dim>
  double
  Membrane<dim>::max_element_length() const
  {
    double l = 0;
    for (const auto &el : elements)
      for (unsigned int k = 0; k < dim; ++k)
        l = std::max(l, position[el[k]].distance(position[el[(k + 1) % dim]]));
    return l;
  }



  template <int dim>
  std::vector<typename Membrane<dim>::ElementStiffness>
  Membrane<dim>::element_stiffness() const
  {
    const double EA   = properties.axial_stiffness;
    const bool   slip = tangential_slip && MembraneSlip::applies(*this);
    // Degree 2: the elements are the cells' halves (quarters in 3D); the
    // P2 stiffness is at most 4/3 of that of its linear sub-elements (the
    // largest generalised eigenvalue, for the cable and for the Laplacian
    // on a triangle).
    const double degree_factor = properties.element_degree == 2 ? 4. / 3. : 1.;
    const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
    std::vector<ElementStiffness> result;
    result.reserve(elements.size() * ((dim == 3 && slip) ? 3 : 1));
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const auto  &el = elements[e];
        const double T  = std::max(tension[e], 0.);
        if (dim == 3 && !slip)
          {
            // Constant-strain triangle: g_i = n x (x_{i+2} - x_{i+1}) / 2A
            // in its plane; the plane-stress modulus EA/(1 - nu^2) [(1 - nu)
            // eps + nu tr(eps) I] has the eigenvalues EA/(1 - nu) and
            // EA/(1 + nu).
            const Tensor<1, dim> n
              = cross_product_3d(position[el[1]] - position[el[0]],
                                 position[el[2]] - position[el[0]]);
            const double two_area = n.norm();
            if (!(two_area > 0))
              continue;
            const Tensor<1, dim> unit_n = n / two_area;
            ElementStiffness     k;
            k.nodes = el;
            for (unsigned int i = 0; i < dim; ++i)
              k.gradient[i] = cross_product_3d(unit_n,
                                               position[el[(i + 2) % dim]]
                                                 - position[el[(i + 1) % dim]])
                              / two_area;
            k.size    = degree_factor * two_area / 2;
            k.modulus = EA / (1 - std::abs(properties.poisson_ratio))
                          * (I - symmetrize(outer_product(unit_n, unit_n)))
                        + T * I;
            result.push_back(k);
          }
        else
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int   j = (i + 1) % dim;
              const Tensor<1, dim> d = position[el[j]] - position[el[i]];
              const double         l = d.norm();
              if (!(l > 0))
                continue;
              const SymmetricTensor<2, dim> tt
                = symmetrize(outer_product(d / l, d / l));
              // Slip in 3D keeps the axial stiffness along z, which the
              // rings do not spread (the roller faces hold z anyway).
              SymmetricTensor<2, dim> axial = tt;
              if (slip)
                {
                  axial = SymmetricTensor<2, dim>();
                  if (dim == 3)
                    axial[dim - 1][dim - 1] = tt[dim - 1][dim - 1];
                }
              ElementStiffness k;
              k.nodes       = el;
              k.nodes[0]    = el[i];
              k.nodes[1]    = el[j];
              k.gradient[0] = -d / (l * l);
              k.gradient[1] = d / (l * l);
              k.size        = degree_factor * l;
              k.modulus     = EA * axial + T * (I - tt);
              result.push_back(k);
              if (dim == 2)
                break;
            }
      }
    return result;
  }



  template <int dim>
  std::vector<SymmetricTensor<2, dim>>
  Membrane<dim>::node_stiffness() const
  {
    std::vector<SymmetricTensor<2, dim>> k(n_nodes());
    // With the frictionless slip, MembraneSlip::equalize_stretch() spreads
    // every local stretch over the whole loop after each position update, so
    // the grid feels the cables' axial stiffness only through the loop's length
    // L: dT = EA dL / L with dL = sum_b theta_b n_b . dx_b (theta_b: turning
    // angle at node b), a rank-one stiffness (EA/L) theta_a theta_b n_a n_b
    // whose rows are bounded by (EA/L) |theta_a| sum_b |theta_b|. Bounding
    // the mass scaling by EA/l instead would give the grid nodes next to
    // the membrane ~100x the fluid's inertia along it and slow the
    // relaxation of the shape (doc/membrane_validation.md).
    if (tangential_slip && MembraneSlip::applies(*this))
      {
        const std::vector<double> loop
          = MembraneSlip::loop_axial_stiffness(*this);
        for (unsigned int a = 0; a < n_nodes(); ++a)
          k[a] += loop[a] * unit_symmetric_tensor<dim>();
      }
    ground.add_stiffness(*this, k);
    return k;
  }



  template <int dim>
  double
  Membrane<dim>::total_size() const
  {
    double s = 0;
    for (unsigned int e = 0; e < elements.size(); ++e)
      s += element_size(e);
    return s;
  }



  template <int dim>
  double
  Membrane<dim>::enclosed_area() const
  {
    // Shoelace over the elements (in x-y): each directed edge contributes.
    if (dim != 2)
      return 0;
    double a = 0;
    for (const auto &el : elements)
      {
        const auto &p = position[el[0]];
        const auto &q = position[el[dim - 1]];
        a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    return a;
  }



  template <int dim>
  std::vector<Point<dim>>
  Membrane<dim>::ordered_nodes() const
  {
    std::vector<Point<dim>> p;
    for (const unsigned int a : loop_nodes())
      p.push_back(position[a]);
    return p;
  }



  template <int dim>
  std::vector<unsigned int>
  Membrane<dim>::loop_nodes() const
  {
    if (dim == 3 && !rings.empty())
      return rings[0];
    // Element order: element e goes from node(e) to node(e+1) on a 2D loop.
    std::vector<unsigned int> node(elements.size());
    for (unsigned int e = 0; e < elements.size(); ++e)
      node[e] = elements[e][0];
    return node;
  }



  template <int dim>
  double
  Membrane<dim>::kinetic_energy() const
  {
    double k = 0;
    for (unsigned int a = 0; a < n_nodes(); ++a)
      k += 0.5 * mass[a] * velocity[a].norm_square();
    return k;
  }



  template <int dim>
  double
  Membrane<dim>::strain_energy() const
  {
    // 2D: T^2 L / (2 EA); 3D plane stress in principal values; plus the
    // ground penalty's spring energy.
    const double EA = properties.axial_stiffness, nu = properties.poisson_ratio;
    double       w = ground.energy(*this);
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        const double s1 = tension[e], s2 = minor_tension[e];
        w += rest_size[e] * (s1 * s1 + s2 * s2 - 2 * nu * s1 * s2) / (2 * EA);
      }
    return w;
  }



  template <int dim>
  void
  Membrane<dim>::find_rings()
  {
    rings.clear();
    ring_rest_length.clear();
    if (dim != 3)
      return;
    // Nodes grouped by z; within a group, the element edges joining two of
    // its nodes must form one closed loop per group.
    std::vector<unsigned int> order(n_nodes());
    for (unsigned int a = 0; a < n_nodes(); ++a)
      order[a] = a;
    std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
      return position[a][dim - 1] < position[b][dim - 1];
    });
    const double tol = 1e-9
                       * (1. + std::abs(position[order.back()][dim - 1])
                          + std::abs(position[order.front()][dim - 1]));
    std::vector<unsigned int> level(n_nodes());
    unsigned int              n_levels = 0;
    for (unsigned int k = 0; k < order.size(); ++k)
      {
        if (k > 0
            && position[order[k]][dim - 1]
                 > position[order[k - 1]][dim - 1] + tol)
          ++n_levels;
        level[order[k]] = n_levels;
      }
    ++n_levels;
    if (n_levels < 2)
      return; // a flat membrane is no extrusion

    const unsigned int none = static_cast<unsigned int>(-1);
    std::vector<std::array<unsigned int, 2>> neighbours(n_nodes(),
                                                        {{none, none}});
    auto link = [&](const unsigned int a, const unsigned int b) {
      for (const unsigned int c : neighbours[a])
        if (c == b)
          return true;
      for (unsigned int &c : neighbours[a])
        if (c == none)
          {
            c = b;
            return true;
          }
      return false; // a third neighbour in the ring: not an extrusion
    };
    for (const auto &el : elements)
      for (unsigned int i = 0; i < dim; ++i)
        {
          const unsigned int a = el[i], b = el[(i + 1) % dim];
          if (level[a] == level[b] && !(link(a, b) && link(b, a)))
            return;
        }

    std::vector<std::vector<unsigned int>> found(n_levels);
    std::vector<unsigned int>              count(n_levels, 0);
    for (unsigned int a = 0; a < n_nodes(); ++a)
      ++count[level[a]];
    std::vector<bool> used(n_nodes(), false);
    for (unsigned int a = 0; a < n_nodes(); ++a)
      {
        if (used[a])
          continue;
        if (!found[level[a]].empty() || neighbours[a][1] == none)
          return; // two loops at one level, or an open chain
        auto &ring = found[level[a]];
        for (unsigned int prev = none, b = a; !used[b];)
          {
            used[b] = true;
            ring.push_back(b);
            const unsigned int next = (neighbours[b][0] != prev)
                                        ? neighbours[b][0]
                                        : neighbours[b][1];
            prev                    = b;
            b                       = next;
            if (b == none)
              return;
          }
        if (ring.size() != count[level[a]])
          return;
      }
    for (auto &ring : found)
      {
        if (loop_area(ring) < 0)
          std::reverse(ring.begin(), ring.end());
        // Start every ring at the node stacked above the first ring's first
        // node, so that ring[k] are the same outline point at every level.
        if (!rings.empty())
          {
            if (ring.size() != rings[0].size())
              {
                rings.clear();
                ring_rest_length.clear();
                return;
              }
            const Point<dim> &x0    = position[rings[0][0]];
            unsigned int      first = 0;
            double            best  = std::numeric_limits<double>::max();
            for (unsigned int k = 0; k < ring.size(); ++k)
              {
                const double d = std::hypot(position[ring[k]][0] - x0[0],
                                            position[ring[k]][1] - x0[1]);
                if (d < best)
                  {
                    best  = d;
                    first = k;
                  }
              }
            // The first nodes must be stacked exactly (an extrusion).
            if (best > 1e-9 * loop_length(rings[0]))
              {
                rings.clear();
                ring_rest_length.clear();
                return;
              }
            std::rotate(ring.begin(), ring.begin() + first, ring.end());
          }
        std::vector<double> rest(ring.size());
        for (unsigned int k = 0; k < ring.size(); ++k)
          rest[k]
            = position[ring[k]].distance(position[ring[(k + 1) % ring.size()]])
              / (1. + properties.initial_strain);
        rings.push_back(ring);
        ring_rest_length.push_back(rest);
      }
  }



  template <int dim>
  double
  Membrane<dim>::loop_length(const std::vector<unsigned int> &loop) const
  {
    double l = 0;
    for (unsigned int k = 0; k < loop.size(); ++k)
      l += position[loop[k]].distance(position[loop[(k + 1) % loop.size()]]);
    return l;
  }



  template <int dim>
  double
  Membrane<dim>::loop_area(const std::vector<unsigned int> &loop) const
  {
    double a = 0;
    for (unsigned int k = 0; k < loop.size(); ++k)
      {
        const auto &p = position[loop[k]];
        const auto &q = position[loop[(k + 1) % loop.size()]];
        a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    return a;
  }



  template <int dim>
  bool
  Membrane<dim>::is_closed_loop() const
  {
    if (dim != 2)
      return false;
    // Every node in exactly two elements, as end of one and start of the
    // next, and one single cycle.
    std::vector<unsigned int> next(n_nodes(), static_cast<unsigned int>(-1));
    std::vector<unsigned int> in_count(n_nodes(), 0);
    for (const auto &el : elements)
      {
        if (next[el[0]] != static_cast<unsigned int>(-1))
          return false;
        next[el[0]] = el[dim - 1];
        ++in_count[el[dim - 1]];
      }
    for (unsigned int a = 0; a < n_nodes(); ++a)
      if (in_count[a] != 1 || next[a] == static_cast<unsigned int>(-1))
        return false;
    unsigned int a = 0, steps = 0;
    do
      {
        a = next[a];
        ++steps;
    } while (a != 0 && steps <= n_nodes());
    return steps == n_nodes();
  }

  template class Membrane<2>;
  template class Membrane<3>;
} // namespace fsgmpm
