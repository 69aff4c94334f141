#include <deal.II/base/exceptions.h>

#include <fsgmpm/membrane/membrane_fe.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/membrane/membrane_slip.h>

#include <algorithm>
#include <cmath>

namespace fsgmpm
{
  namespace MembraneSlip
  {
    namespace
    {
      // Point at fraction t of loop chord e (from loop node e to e + 1), on
      // the circle through loop nodes (e-1, e, e+1) and on the one through
      // (e, e+1, e+2), averaged: exact on circular pieces, so the enclosed
      // area is kept.
      template <int dim>
      Point<dim>
      point_on_loop(const std::vector<Point<dim>>   &position,
                    const std::vector<unsigned int> &node,
                    const unsigned int               e,
                    const double                     t)
      {
        const unsigned int n  = node.size();
        const Point<dim>  &p0 = position[node[(e + n - 1) % n]],
                         &p1  = position[node[e]],
                         &p2  = position[node[(e + 1) % n]],
                         &p3  = position[node[(e + 2) % n]];
        const Point<dim> x
          = MembraneGeometry::point_on_arc(p0, p1, p2, p1, p2, t);
        const Point<dim> y
          = MembraneGeometry::point_on_arc(p1, p2, p3, p1, p2, t);
        return Point<dim>(0.5 * (x + y));
      }



      // Ties the nodes stacked along z (ring[k] of every ring) to their
      // mean x-y: the slab's plane strain. Returns the largest move.
      template <int dim>
      double
      tie_stacks(std::vector<Point<dim>>                      &position,
                 const std::vector<std::vector<unsigned int>> &rings)
      {
        double max_move = 0;
        for (unsigned int k = 0; k < rings[0].size(); ++k)
          {
            double x = 0, y = 0;
            for (const auto &ring : rings)
              {
                x += position[ring[k]][0] / rings.size();
                y += position[ring[k]][1] / rings.size();
              }
            for (const auto &ring : rings)
              {
                Point<dim> &p = position[ring[k]];
                max_move = std::max(max_move, std::hypot(p[0] - x, p[1] - y));
                p[0]     = x;
                p[1]     = y;
              }
          }
        return max_move;
      }



      // equalize_stretch() on one closed loop of nodes @p node with the
      // rest lengths of its edges, in x-y (a 3D ring in its plane).
      template <int dim>
      double
      equalize_loop(std::vector<Point<dim>>         &position,
                    const std::vector<unsigned int> &node,
                    const std::vector<double>       &rest_length)
      {
        const unsigned int  n = node.size();
        std::vector<double> s(n + 1, 0.), S(n + 1, 0.);
        for (unsigned int e = 0; e < n; ++e)
          {
            const Point<dim> &a = position[node[e]];
            const Point<dim> &b = position[node[(e + 1) % n]];
            s[e + 1]            = s[e] + std::hypot(b[0] - a[0], b[1] - a[1]);
            S[e + 1]            = S[e] + rest_length[e];
          }
        const double length = s[n], rest = S[n];
        // Target arc length of node k: proportional to the rest length
        // before it, shifted so that the mean shift is zero (no drift along
        // the loop).
        double shift = 0;
        for (unsigned int k = 0; k < n; ++k)
          shift += s[k] - S[k] * length / rest;
        shift /= n;

        std::vector<Point<dim>> moved(n);
        double                  max_move = 0;
        unsigned int            e        = 0;
        for (unsigned int k = 0; k < n; ++k)
          {
            double target = S[k] * length / rest + shift;
            target        = std::fmod(target + length, length);
            // Find the chord holding the target arc length (monotone in k
            // up to the wrap-around).
            unsigned int tries = 0;
            while (!(s[e] <= target && target <= s[e + 1]) && tries++ <= n)
              e = (e + 1) % n;
            const double t
              = (s[e + 1] > s[e]) ? (target - s[e]) / (s[e + 1] - s[e]) : 0.;
            moved[k] = point_on_loop(position, node, e, t);
            max_move = std::max(max_move, moved[k].distance(position[node[k]]));
          }
        for (unsigned int k = 0; k < n; ++k)
          position[node[k]] = moved[k];
        return max_move;
      }

    } // namespace



    template <int dim>
    bool
    applies(const Membrane<dim> &membrane)
    {
      return dim == 2 ? membrane.is_closed_loop() : !membrane.rings.empty();
    }



    template <int dim>
    double
    equalize_stretch(Membrane<dim> &membrane)
    {
      if (!applies(membrane))
        return 0;
      auto &position = membrane.position;
      if constexpr (dim == 2)
        return equalize_loop(position,
                             membrane.loop_nodes(),
                             membrane.rest_size);
      else
        {
          // Extruded membrane in a slab with roller faces (plane strain):
          // the nodes stacked along z share their x-y position (the grid's
          // tetrahedra move the front and back faces slightly differently,
          // which the membrane's shear stiffness would turn into large
          // forces), and the rings are equalized as the 2D loop.
          const auto                   &rings        = membrane.rings;
          const std::vector<Point<dim>> old_position = position;
          const unsigned int            n            = rings[0].size();
          tie_stacks(position, rings);
          equalize_loop(position, rings[0], membrane.ring_rest_length[0]);
          double max_move = 0;
          for (const auto &ring : rings)
            for (unsigned int k = 0; k < n; ++k)
              {
                position[ring[k]][0] = position[rings[0][k]][0];
                position[ring[k]][1] = position[rings[0][k]][1];
                max_move
                  = std::max(max_move,
                             position[ring[k]].distance(old_position[ring[k]]));
              }
          return max_move;
        }
    }



    template <int dim>
    double
    relax_tangential_forces(Membrane<dim>     &membrane,
                            const unsigned int newton_steps,
                            double            *released)
    {
      if (released)
        *released = 0;
      if (!applies(membrane))
        return 0;
      const MembraneFE<dim> &fe       = membrane.get_fe();
      const unsigned int     degree   = fe.get_degree();
      auto                  &position = membrane.position;

      // The support points' positions, and the support point of each node.
      std::vector<unsigned int> dof_of_node(membrane.n_nodes(), 0);
      std::vector<Point<dim>>   x(fe.n_support_points());
      auto                      gather = [&](const std::vector<Point<dim>> &p) {
        for (unsigned int i = 0; i < x.size(); ++i)
          x[i] = p[membrane.support_point_node(i)];
      };
      for (unsigned int i = 0; i < x.size(); ++i)
        dof_of_node[membrane.support_point_node(i)] = i;

      // The energy released is measured from the start (3D: the tying of
      // the stacks included).
      double start_energy = 0;
      if (released)
        {
          gather(position);
          start_energy = fe.strain_energy(x);
        }

      // The loop the nodes slide along, starting at a cell's vertex, the
      // rest lengths of its pieces and the bar stiffness along it. 2D: the
      // cables. 3D (an extrusion in a slab with roller faces): the first
      // ring, each of its nodes carrying the nodes stacked above it (the
      // same x-y, as equalize_stretch() ties them), and the stiffness of
      // the whole height in plane strain, EA H / (1 - nu^2).
      std::vector<unsigned int>              loop;
      std::vector<double>                    rest;
      std::vector<std::vector<unsigned int>> stack;
      double EA        = membrane.properties.axial_stiffness;
      double max_shift = 0;
      if constexpr (dim == 2)
        {
          loop = membrane.loop_nodes();
          rest = membrane.rest_size;
          for (const unsigned int a : loop)
            stack.push_back({a});
        }
      else
        {
          const auto &rings = membrane.rings;
          loop              = rings[0];
          rest              = membrane.ring_rest_length[0];
          if (degree == 2
              && std::find(membrane.vertex_node.begin(),
                           membrane.vertex_node.end(),
                           loop[0])
                   == membrane.vertex_node.end())
            {
              std::rotate(loop.begin(), loop.begin() + 1, loop.end());
              std::rotate(rest.begin(), rest.begin() + 1, rest.end());
            }
          const unsigned int first = rings[0][0] == loop[0] ? 0 : 1;
          stack.resize(loop.size());
          for (unsigned int k = 0; k < loop.size(); ++k)
            for (const auto &ring : rings)
              stack[k].push_back(ring[(k + first) % loop.size()]);
          const double height = std::abs(position[rings.back()[0]][dim - 1]
                                         - position[rings[0][0]][dim - 1]);
          const double nu     = membrane.properties.poisson_ratio;
          EA *= height / (1 - nu * nu);
          // Tie the stacks (their mean x-y), as equalize_stretch() does.
          max_shift = tie_stacks(position, rings);
        }
      const unsigned int n = loop.size();
      AssertThrow(n % degree == 0 && rest.size() == n,
                  ExcMessage("The membrane's slip loop does not hold whole "
                             "cells of degree "
                             + std::to_string(degree) + "."));
      auto remove_mean = [&](std::vector<double> &v) {
        double mean = 0;
        for (const double a : v)
          mean += a / n;
        for (double &a : v)
          a -= mean;
      };
      // The Newton step solves K d = r with K the 1D bar stiffness of the
      // loop along its arc, per cell of rest length L (its pieces' rest
      // lengths added; the pieces of a cell are consecutive from element
      // 0): EA/L [1 -1; -1 1] at degree 1, EA/(3L) [7 -8 1; -8 16 -8; 1 -8
      // 7] at degree 2. The middle nodes condensed out (their loads go half
      // to each vertex), the vertices form a ring of springs EA/L, solved
      // directly: the spring forces F_c = F + (loads up to vertex c), F
      // such that the stretches F_c L_c / EA add up to zero around the
      // ring; the rigid slide along the loop is fixed by a zero mean shift.
      auto solve = [&](const std::vector<double> &r) {
        const unsigned int  n_cells = n / degree;
        std::vector<double> L(n_cells, 0.), R(n_cells, 0.), d(n, 0.);
        for (unsigned int c = 0; c < n_cells; ++c)
          {
            for (unsigned int k = 0; k < degree; ++k)
              L[c] += rest[degree * c + k];
            R[c] += r[degree * c];
            if (degree == 2)
              {
                R[c] += 0.5 * r[2 * c + 1];
                R[(c + 1) % n_cells] += 0.5 * r[2 * c + 1];
              }
          }
        double              sum = 0, length = 0, loads = 0;
        std::vector<double> F(n_cells);
        for (unsigned int c = 0; c < n_cells; ++c)
          {
            sum += R[c];
            F[c] = sum;
            loads += F[c] * L[c];
            length += L[c];
          }
        for (unsigned int c = 0; c < n_cells; ++c)
          F[c] -= loads / length;
        for (unsigned int c = 0; c + 1 < n_cells; ++c)
          d[degree * (c + 1)] = d[degree * c] - F[c] * L[c] / EA;
        if (degree == 2)
          for (unsigned int c = 0; c < n_cells; ++c)
            d[2 * c + 1] = (3 * L[c] * r[2 * c + 1] / EA + 8 * d[2 * c]
                            + 8 * d[(2 * c + 2) % n])
                           / 16;
        remove_mean(d);
        return d;
      };

      double energy = -1;
      for (unsigned int step = 0; step < newton_steps; ++step)
        {
          gather(position);
          const std::vector<Tensor<1, dim>> force = fe.internal_forces(x);
          // The energy is known after an accepted, tested step.
          if (!(energy >= 0))
            energy = fe.strain_energy(x);
          if (!(energy > 0))
            break;
          // The tangential forces (along the chord through the neighbours),
          // of each stack.
          std::vector<double> r(n, 0.);
          for (unsigned int k = 0; k < n; ++k)
            {
              Tensor<1, dim> t
                = position[loop[(k + 1) % n]] - position[loop[(k + n - 1) % n]];
              if (t.norm() > 0)
                t /= t.norm();
              for (const unsigned int a : stack[k])
                r[k] += force[dof_of_node[a]] * t;
            }
          remove_mean(r);
          const std::vector<double> d = solve(r);
          // Nearly converged, the Newton step lowers the energy by r.d / 2,
          // below what the energy's round-off can show: it is taken without
          // the energy test (which could only guess, after up to 9
          // evaluations).
          double predicted = 0;
          for (unsigned int k = 0; k < n; ++k)
            predicted += 0.5 * r[k] * d[k];
          const bool below_round_off = !(predicted > 1e-12 * energy);

          // The move along the loop, by a fraction of the Newton step if
          // the whole one does not lower the strain energy.
          std::vector<double> chord(n);
          for (unsigned int k = 0; k < n; ++k)
            chord[k] = position[loop[k]].distance(position[loop[(k + 1) % n]]);
          bool accepted = false;
          for (double fraction = 1; fraction > 1. / 300 && !accepted;
               fraction /= 2)
            {
              std::vector<Point<dim>> moved   = position;
              double                  largest = 0;
              for (unsigned int k = 0; k < n; ++k)
                {
                  // At most half a chord: the nodes keep their order.
                  const unsigned int before = (k + n - 1) % n;
                  const double       s      = std::clamp(fraction * d[k],
                                              -0.5 * chord[before],
                                              0.5 * chord[k]);
                  const Point<dim>   p
                    = s >= 0
                        ? (chord[k] > 0
                             ? point_on_loop(position, loop, k, s / chord[k])
                             : position[loop[k]])
                        : point_on_loop(position,
                                        loop,
                                        before,
                                        1 + s / chord[before]);
                  for (const unsigned int a : stack[k])
                    for (unsigned int d = 0; d < 2; ++d)
                      moved[a][d] = p[d];
                  largest = std::max(largest, std::abs(s));
                }
              if (below_round_off)
                {
                  energy    = -1;
                  position  = std::move(moved);
                  max_shift = std::max(max_shift, largest);
                  accepted  = true;
                  break;
                }
              gather(moved);
              const double moved_energy = fe.strain_energy(x);
              if (moved_energy < energy)
                {
                  energy    = moved_energy;
                  position  = std::move(moved);
                  max_shift = std::max(max_shift, largest);
                  accepted  = true;
                }
            }
          if (!accepted)
            break;
        }
      if (released)
        {
          gather(position);
          *released = start_energy - fe.strain_energy(x);
        }
      return max_shift;
    }



    template <int dim>
    std::vector<double>
    loop_axial_stiffness(const Membrane<dim> &membrane)
    {
      // Per loop node k: (EA/L) max(|theta_k|, 2 pi l_k/L) sum_j |theta_j|,
      // with l_k the mean length of the two edges at k; the floor keeps the
      // bound of a circle (theta = 2 pi l/L) on straight pieces, where the
      // one pass of equalize_stretch() leaves some local stiffness. 3D: the
      // first ring's value times each node's share of the height.
      const auto                     &position = membrane.position;
      const std::vector<unsigned int> loop     = membrane.loop_nodes();
      const unsigned int              n        = loop.size();
      std::vector<double>             theta(n), l(n);
      std::vector<Tensor<1, dim>>     t(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          t[k] = position[loop[(k + 1) % n]] - position[loop[k]];
          l[k] = t[k].norm();
          if (l[k] > 0)
            t[k] /= l[k];
        }
      double sum = 0, length = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const unsigned int p = (k + n - 1) % n;
          // A zero-length edge (coincident nodes) adds no turning.
          theta[k] = (l[p] > 0 && l[k] > 0)
                       ? std::acos(std::clamp(t[p] * t[k], -1., 1.))
                       : 0.;
          sum += theta[k];
          length += l[k];
        }
      AssertThrow(length > 0,
                  ExcMessage("The membrane loop has zero length (all its "
                             "nodes coincide)."));
      const double        EA = membrane.properties.axial_stiffness;
      std::vector<double> value(n);
      for (unsigned int k = 0; k < n; ++k)
        value[k]
          = EA / length * sum
            * std::max(theta[k], M_PI * (l[k] + l[(k + n - 1) % n]) / length);

      std::vector<double> k_node(membrane.n_nodes(), 0.);
      if constexpr (dim == 2)
        for (unsigned int k = 0; k < n; ++k)
          k_node[loop[k]] = value[k];
      else
        {
          // Each ring's share of the height: half the distance between its
          // neighbouring rings (rings need at least two).
          const auto        &rings   = membrane.rings;
          const unsigned int n_rings = rings.size();
          auto               z       = [&](const unsigned int r) {
            return position[rings[r][0]][dim - 1];
          };
          for (unsigned int r = 0; r < n_rings; ++r)
            {
              const double share = 0.5
                                   * std::abs(z(std::min(r + 1, n_rings - 1))
                                              - z(r > 0 ? r - 1 : 0));
              for (unsigned int k = 0; k < n; ++k)
                k_node[rings[r][k]] = share * value[k];
            }
        }
      return k_node;
    }

#define FSGMPM_INSTANTIATE(dim)                                                 \
  template bool                applies<dim>(const Membrane<dim> &);             \
  template double              equalize_stretch<dim>(Membrane<dim> &);          \
  template double              relax_tangential_forces<dim>(Membrane<dim> &,    \
                                               const unsigned int, \
                                               double *);          \
  template std::vector<double> loop_axial_stiffness<dim>(const Membrane<dim> &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace MembraneSlip
} // namespace fsgmpm
