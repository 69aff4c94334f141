#include <deal.II/base/mpi.templates.h>

#include <fsgmpm/membrane/membrane_slip.h>
#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/step/membrane_coupling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace fsgmpm
{
  template <int dim>
  MembraneCoupling<dim>::MembraneCoupling(const BackgroundGrid<dim> &grid,
                                          Membrane<dim>             &membrane,
                                          const double split_length)
    : grid(grid)
    , membrane(membrane)
    , split_length(split_length)
  {}



  template <int dim>
  void
  MembraneCoupling<dim>::p2g(NodalFields<dim> &nodes)
  {
    // The shape values at the node (start of step) are the transfer
    // weights of every membrane stage of this step. MPI: a node whose cell
    // the window lacks adds nothing here; it touches no node that this
    // process counts (a window holds every cell around its own nodes).
    weights.resize(membrane.n_nodes());
    cell_here.resize(membrane.n_nodes());
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      {
        cell_here[a] = grid.local_cell(membrane.cell[a]);
        weights[a]   = {};
        if (cell_here[a] == BackgroundGrid<dim>::invalid)
          continue;
        const auto l = grid.barycentric(cell_here[a], membrane.position[a]);
        std::copy(l.begin(), l.end(), weights[a].begin());
      }

    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      {
        const unsigned int c = cell_here[a];
        if (c == BackgroundGrid<dim>::invalid)
          continue;
        nodes.activate(grid.cell_nodes[c]);
        const auto  &lambda = weights[a];
        const double m      = membrane.mass[a];
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid.cell_nodes[c][k];
            nodes.mass[i] += lambda[k] * m;
            nodes.momentum[i] += (lambda[k] * m) * membrane.velocity[a];
            // The element force acts on the node: M a = F_ext - F_int.
            nodes.internal_force[i] -= lambda[k] * membrane.force[a];
          }
      }
  }



  template <int dim>
  double
  MembraneCoupling<dim>::time_step(
    const std::vector<double>       &cell_stiffness,
    const std::vector<unsigned int> &occupied_cells,
    NodalFields<dim>                &nodes,
    const double                     dt_floor)
  {
    if (dt_floor > 0)
      nodes.use(nodes.added_mass);

    // The touched grid nodes, sorted; index t of node i by bisection.
    touched.clear();
    touched.reserve(membrane.n_nodes() * (dim + 1));
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      if (cell_here[a] != BackgroundGrid<dim>::invalid)
        for (const unsigned int i : grid.cell_nodes[cell_here[a]])
          touched.push_back(i);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    auto index_of = [&](const unsigned int i) {
      return std::lower_bound(touched.begin(), touched.end(), i)
             - touched.begin();
    };

    // MPI: the masses of the window's outer rim, exact (in a copy: the
    // step's own values there stay as they are).
    const std::vector<double> *mass = &nodes.mass;
    if (partition != nullptr)
      {
        rim_mass = nodes.mass;
        partition->update_ghost_nodes(rim_mass,
                                      nodes.active_stamp,
                                      nodes.stamp);
        mass = &rim_mass;
      }

    // The elements as the grid sees them (Membrane::ElementStiffness): the
    // grid gradients G_i = sum_a N_i(x_a) g_a over the nodes of the cells
    // of the element's nodes, and with the nodal masses as the weights
    // S_e = size sum_j |G_j|^2 / m_j, so that the element adds m_i S_e C_e
    // at node i. The masses make the bound tight: a node that a membrane
    // element barely reaches has a small G_i as well as a small mass, where
    // the row sums (weights |G|) gave it the element's whole stiffness
    // (the 2D geocontainer: 15 us there, against 0.1 ms by this bound and
    // 0.16 ms exactly, doc/stability.md).
    // With mass scaling the fictitious inertia follows this bound every
    // step: weighted by the nodal masses it would follow their fluctuation
    // as points cross cells, and a nodal inertia that changes from step to
    // step creates energy (stability_extremes, 5 GN/m on 0.01 kg/m^2: 45%
    // of the work, none with the row sums). Mass scaling takes the row
    // sums, which depend on the membrane's geometry alone.
    const bool by_mass  = !(dt_floor > 0);
    const auto elements = membrane.element_stiffness();
    support.resize(elements.size());
    support_gradient.resize(elements.size());
    n_support.assign(elements.size(), 0);
    element_weight.assign(elements.size(), -1.);
    auto &gradient = support_gradient;
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        bool complete = true;
        for (unsigned int q = 0; q < dim; ++q)
          {
            const unsigned int a = elements[e].nodes[q];
            const unsigned int c = cell_here[a];
            if (elements[e].gradient[q].norm_square() == 0)
              continue;
            if (c == BackgroundGrid<dim>::invalid)
              {
                complete = false;
                continue;
              }
            for (unsigned int k = 0; k < dim + 1; ++k)
              {
                const unsigned int i = grid.cell_nodes[c][k];
                unsigned int       s = 0;
                while (s < n_support[e] && support[e][s] != i)
                  ++s;
                if (s == n_support[e])
                  {
                    support[e][s]  = i;
                    gradient[e][s] = Tensor<1, dim>();
                    ++n_support[e];
                  }
                gradient[e][s] += weights[a][k] * elements[e].gradient[q];
              }
          }
        if (!complete)
          continue;
        double S = 0;
        for (unsigned int s = 0; s < n_support[e]; ++s)
          if ((*mass)[support[e][s]] > 0)
            S += gradient[e][s].norm_square() / (*mass)[support[e][s]];
        element_weight[e] = elements[e].size * S;
      }
    // MPI: an element whose nodes' cells are not all in this window gets
    // its S_e from a process whose window holds them (the same value bit
    // for bit: exact masses, the same order).
    if (partition != nullptr && by_mass)
      Utilities::MPI::max(make_array_view(std::as_const(element_weight)),
                          partition->get_communicator(),
                          make_array_view(element_weight));

    // D_i: the elements, then the stiffness on single nodes (the ground,
    // the slip loop), with a margin of 1.25 over the bound.
    touched_stiffness.assign(touched.size(), SymmetricTensor<2, dim>());
    for (unsigned int e = 0; e < elements.size(); ++e)
      if (by_mass && element_weight[e] >= 0)
        for (unsigned int s = 0; s < n_support[e]; ++s)
          {
            const unsigned int i = support[e][s];
            if (gradient[e][s].norm_square() > 0 && (*mass)[i] > 0)
              touched_stiffness[index_of(i)]
                += ((*mass)[i] * element_weight[e]) * elements[e].modulus;
          }
      else
        {
          // Mass scaling, or a node outside the mesh (or an element longer
          // than any process's window): the weights |g_a|, which need no
          // grid masses; the element's own bound, each node's share
          // projected to the grid as a single node's stiffness.
          double g_sum = 0;
          for (const auto &g : elements[e].gradient)
            g_sum += g.norm();
          for (unsigned int q = 0; q < dim; ++q)
            {
              const unsigned int a = elements[e].nodes[q];
              if (cell_here[a] == BackgroundGrid<dim>::invalid)
                continue;
              for (unsigned int k = 0; k < dim + 1; ++k)
                touched_stiffness[index_of(grid.cell_nodes[cell_here[a]][k])]
                  += (std::max(weights[a][k], 0.) * elements[e].size
                      * elements[e].gradient[q].norm() * g_sum)
                     * elements[e].modulus;
            }
        }
    // A stiffness k_a on one membrane node moves with u_a = sum_i N_i(x_a)
    // u_i: the same bound with G_i = N_i(x_a), m_i k_a sum_j N_j(x_a)^2 /
    // m_j at node i (the window holds the node's cell with exact masses);
    // with mass scaling the row sums N_i(x_a) k_a (the weights sum to 1).
    const std::vector<SymmetricTensor<2, dim>> k_node
      = membrane.node_stiffness();
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      {
        const unsigned int c = cell_here[a];
        if (c == BackgroundGrid<dim>::invalid || k_node[a].norm() == 0)
          continue;
        double S = 0;
        for (unsigned int k = 0; k < dim + 1; ++k)
          if ((*mass)[grid.cell_nodes[c][k]] > 0)
            S += weights[a][k] * weights[a][k] / (*mass)[grid.cell_nodes[c][k]];
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid.cell_nodes[c][k];
            if (!by_mass)
              touched_stiffness[index_of(i)]
                += std::max(weights[a][k], 0.) * k_node[a];
            else if (weights[a][k] != 0 && (*mass)[i] > 0)
              touched_stiffness[index_of(i)] += ((*mass)[i] * S) * k_node[a];
          }
      }
    for (auto &D : touched_stiffness)
      D *= 1.25;

    // The points' row sums on the touched nodes.
    touched_points.assign(touched.size(), 0.);
    if (!cell_stiffness.empty())
      for (const unsigned int c : occupied_cells)
        {
          const auto   grad = grid.shape_gradients(c);
          const double S    = cell_stiffness[c];
          if (!(S > 0))
            continue;
          double row = 0;
          for (unsigned int k = 0; k < dim + 1; ++k)
            row += grad[k].norm();
          for (unsigned int k = 0; k < dim + 1; ++k)
            {
              const auto it = std::lower_bound(touched.begin(),
                                               touched.end(),
                                               grid.cell_nodes[c][k]);
              if (it != touched.end() && *it == grid.cell_nodes[c][k])
                touched_points[it - touched.begin()]
                  += S * grad[k].norm() * row;
            }
        }

    // MPI: the bound over the nodes this process counts (their masses and
    // the points' stiffness around them are exact here); the caller takes
    // the minimum over the processes. The fictitious inertia is set on all
    // touched nodes: wherever this process's values are inexact, the grid
    // update's result is overwritten or unused.
    double dt = std::numeric_limits<double>::max();
    for (unsigned int t = 0; t < touched.size(); ++t)
      {
        const unsigned int i = touched[t];
        const bool         counted
          = partition == nullptr || partition->counted_nodes()[i];
        const SymmetricTensor<2, dim> D
          = touched_stiffness[t]
            + touched_points[t] * unit_symmetric_tensor<dim>();
        if (!nodes.added_mass.empty())
          nodes.added_mass[i] = SymmetricTensor<2, dim>();
        const double m = nodes.mass[i];
        if (m <= 0)
          continue;
        for (const auto &[k, e] : eigenvectors(D))
          if (k > 0)
            {
              // Fictitious inertia only in the directions that need it.
              const double added
                = std::max(0.25 * k * dt_floor * dt_floor - m, 0.);
              if (added > 0)
                nodes.added_mass[i] += added * symmetrize(outer_product(e, e));
              if (counted)
                dt = std::min(dt, 2. * std::sqrt((m + added) / k));
            }
      }
    return dt;
  }



  template <int dim>
  template <typename Function>
  std::vector<Tensor<1, dim>>
  MembraneCoupling<dim>::from_cell_owners(const Function &f) const
  {
    std::vector<Tensor<1, dim>> values(membrane.n_nodes());
    if (partition == nullptr)
      {
        for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
          values[a] = f(a);
        return values;
      }
    const auto owned = [&](const unsigned int a) {
      return cell_here[a] != BackgroundGrid<dim>::invalid
             && partition->owner(cell_here[a]) == partition->rank();
    };
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      if (owned(a))
        values[a] = f(a);
    Parallel::take_values_of_owners(values,
                                    owned,
                                    partition->get_communicator());
    return values;
  }



  template <int dim>
  Tensor<1, dim>
  MembraneCoupling<dim>::grid_velocity(const NodalFields<dim> &nodes,
                                       const unsigned int      a) const
  {
    const unsigned int c      = cell_here[a];
    const auto        &lambda = weights[a];
    Tensor<1, dim>     v;
    for (unsigned int k = 0; k < dim + 1; ++k)
      v += lambda[k] * nodes.velocity[grid.cell_nodes[c][k]];
    return v;
  }



  template <int dim>
  void
  MembraneCoupling<dim>::g2p(const NodalFields<dim> &nodes)
  {
    membrane.velocity = from_cell_owners(
      [&](const unsigned int a) { return grid_velocity(nodes, a); });
  }



  template <int dim>
  void
  MembraneCoupling<dim>::remap(NodalFields<dim> &nodes) const
  {
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      {
        const unsigned int c = cell_here[a];
        if (c == BackgroundGrid<dim>::invalid)
          continue;
        const auto &lambda = weights[a];
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.momentum[grid.cell_nodes[c][k]]
            += (lambda[k] * membrane.mass[a]) * membrane.velocity[a];
      }
  }



  template <int dim>
  double
  MembraneCoupling<dim>::update_positions(const NodalFields<dim> &nodes,
                                          const double            dt)
  {
    const std::vector<Tensor<1, dim>> displacement
      = from_cell_owners([&](const unsigned int a) {
          Tensor<1, dim> dx = grid_velocity(nodes, a);
          dx *= dt;
          return dx;
        });
    double ratio = 0;
    for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
      {
        const Tensor<1, dim> &dx = displacement[a];
        membrane.position[a] += dx;
        // (MPI: the caller takes the largest over the processes.)
        if (cell_here[a] != BackgroundGrid<dim>::invalid)
          ratio = std::max(ratio, dx.norm() / grid.min_altitude(cell_here[a]));
      }
    return ratio;
  }



  template <int dim>
  unsigned int
  MembraneCoupling<dim>::relocate()
  {
    const unsigned int unknown = BackgroundGrid<dim>::invalid;
    // The slip: by chord lengths at degree 1 (exact there), by relaxing
    // the tangential forces at degree 2.
    if (membrane.tangential_slip)
      {
        if (membrane.properties.element_degree == 1)
          MembraneSlip::equalize_stretch(membrane);
        else
          MembraneSlip::relax_tangential_forces(membrane);
      }
    if (split_length > 0)
      membrane.split_long_elements(split_length);
    unsigned int outside = 0;
    if (grid.is_window())
      outside = locate_on_windows();
    else
      {
        const PointLocator<dim> locator(grid);
        for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
          {
            // (A split's new nodes start from their element's first node's
            // cell; a cell is unknown only if the caller left it so.)
            const unsigned int guess
              = membrane.cell[a] == unknown ? 0 : membrane.cell[a];
            const unsigned int c = locator.locate(membrane.position[a], guess);
            if (c == unknown)
              ++outside;
            else
              membrane.cell[a] = c;
          }
      }
    membrane.compute_forces();
    return outside;
  }



  template <int dim>
  unsigned int
  MembraneCoupling<dim>::locate_on_windows()
  {
    AssertThrow(partition != nullptr,
                ExcMessage("A membrane on a window of the grid needs the "
                           "partition (attach_partition())."));
    const MPI_Comm          comm    = partition->get_communicator();
    const unsigned int      unknown = BackgroundGrid<dim>::invalid;
    const unsigned int      n       = membrane.n_nodes();
    const PointLocator<dim> locator(grid);

    // 1. The walk of the whole grid's locate(), from the node's cell, by
    // every process that holds that cell. A walk that settles inside a
    // window took the whole grid's path, so all that settle agree; the
    // others (out of the window or the mesh) give unknown, the largest
    // number, and the minimum over the processes is the walk's cell.
    std::vector<unsigned int> found(n, unknown);
    for (unsigned int a = 0; a < n; ++a)
      {
        const unsigned int guess = grid.local_cell(membrane.cell[a]);
        if (guess == unknown)
          continue;
        const unsigned int c = locator.walk(membrane.position[a], guess);
        if (c != unknown)
          found[a] = grid.global_cell(c);
      }
    int ierr = MPI_Allreduce(
      MPI_IN_PLACE, found.data(), n, MPI_UNSIGNED, MPI_MIN, comm);
    AssertThrowMPI(ierr);

    // 2. The nodes no walk placed (walks out of the mesh or across every
    // window's edge, a node without a cell): the whole grid's search,
    // over the windows. Each process's best cell (the largest smallest
    // barycentric coordinate, the lowest number on a tie) and MAXLOC's
    // tie rule (the lower index) give the whole grid's answer. The
    // membrane lives in velocity field 0, where the search looks.
    std::vector<unsigned int> rest;
    for (unsigned int a = 0; a < n; ++a)
      if (found[a] == unknown)
        rest.push_back(a);
    if (!rest.empty())
      {
        AssertThrow(grid.n_global_cells() <= std::numeric_limits<int>::max(),
                    ExcMessage("The membrane's search numbers cells by int: "
                               "at most 2^31 - 1 cells."));
        struct ExcessAndCell
        {
          double excess;
          int    cell;
        };
        std::vector<ExcessAndCell> best(rest.size());
        for (unsigned int r = 0; r < rest.size(); ++r)
          {
            double             excess = 0;
            const unsigned int c
              = grid.find_cell_brute_force(membrane.position[rest[r]],
                                           PointLocator<dim>::default_tolerance,
                                           &excess);
            best[r] = c == unknown
                        ? ExcessAndCell{-std::numeric_limits<double>::max(), 0}
                        : ExcessAndCell{excess,
                                        static_cast<int>(grid.global_cell(c))};
          }
        ierr = MPI_Allreduce(MPI_IN_PLACE,
                             best.data(),
                             best.size(),
                             MPI_DOUBLE_INT,
                             MPI_MAXLOC,
                             comm);
        AssertThrowMPI(ierr);
        for (unsigned int r = 0; r < rest.size(); ++r)
          if (best[r].excess >= -PointLocator<dim>::default_tolerance)
            found[rest[r]] = best[r].cell;
      }

    unsigned int outside = 0;
    for (unsigned int a = 0; a < n; ++a)
      if (found[a] == unknown)
        ++outside;
      else
        membrane.cell[a] = found[a];
    return outside;
  }



  template class MembraneCoupling<2>;
  template class MembraneCoupling<3>;
} // namespace fsgmpm
