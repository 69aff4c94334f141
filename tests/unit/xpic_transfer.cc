// XPIC(m) (Simulation/XPIC order), 2D and 3D, random points filling part of
// a simplex box (full, partly filled and nearly empty nodes):
// - Stages::xpic_correction() against an independent dense evaluation of
//   v* - v^n, v* = sum_{k=1}^m (-1)^(k+1) C(m, k) A^(k-1) v^n, with the
//   round-trip matrix A_ij = sum_p N_i(x_p) m_p N_j(x_p) / m_i assembled
//   point by point and the binomials from std::tgamma, to 1e-12 (relative)
//   for m = 2, 3, 5, 8;
// - a uniform velocity is a fixed point of the round trip (A 1 = 1): no
//   correction, to 1e-13;
// - a grid-resolved field (point velocities S w for a random nodal w) is
//   returned as S v* with v* - w = (I - A)^m w: the error falls with the
//   order (PIC, m = 1, keeps A w), which is why XPIC's viscosity is lower.

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <cmath>
#include <map>
#include <random>

using namespace fsgmpm;

namespace
{
  template <int dim>
  struct Setup
  {
    std::unique_ptr<BackgroundGrid<dim>> grid;
    ParticleStore<dim>                   particles;
    NodalFields<dim>                     nodes;
  };

  // Points in the lower 60 % of the unit box (4^dim boxes of simplices),
  // velocities from @p velocity.
  template <int dim, typename Velocity>
  void
  fill(Setup<dim> &s, const Velocity &velocity, std::mt19937 &rng)
  {
    s.grid = test_tools::make_unit_box_grid<dim>(4);
    std::uniform_real_distribution<double> u(0.02, 0.98), m(0.5, 2.);
    for (unsigned int n = 0; n < 300 * dim; ++n)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = u(rng);
        x[dim - 1] *= 0.6;
        const unsigned int c = s.grid->find_cell_brute_force(x, 1e-12);
        ASSERT_NE(c, BackgroundGrid<dim>::invalid);
        s.particles.add(x, c, m(rng), 1e-3, velocity(x), {}, 0, 0);
      }
    s.particles.sort_by_cell(s.grid->n_cells());
    s.nodes.resize(s.grid->n_nodes());
    Stages::p2g(*s.grid, s.particles, s.nodes);
  }

  // The barycentric weights of point p in its cell.
  template <int dim>
  std::array<double, dim + 1>
  weights(const Setup<dim> &s, const unsigned int c, const unsigned int p)
  {
    const auto geometry = CellLoops::geometry(*s.grid, s.particles, c);
    const auto lambda   = geometry.barycentric(s.particles.position[p]);
    std::array<double, dim + 1> w;
    for (unsigned int k = 0; k < dim + 1; ++k)
      w[k] = lambda[k];
    return w;
  }

  // (S u)(x_p) for point p of cell c: the nodal field u interpolated.
  template <int dim>
  Tensor<1, dim>
  interpolate(const Setup<dim>                             &s,
              const unsigned int                            c,
              const unsigned int                            p,
              const std::map<unsigned int, Tensor<1, dim>> &u)
  {
    const auto     w = weights(s, c, p);
    Tensor<1, dim> Su;
    for (unsigned int k = 0; k < dim + 1; ++k)
      Su += w[k] * u.at(s.grid->cell_nodes[c][k]);
    return Su;
  }

  // (A u)_i, assembled point by point.
  template <int dim>
  std::map<unsigned int, Tensor<1, dim>>
  round_trip(const Setup<dim>                             &s,
             const std::map<unsigned int, Tensor<1, dim>> &u)
  {
    std::map<unsigned int, Tensor<1, dim>> Au;
    for (const unsigned int i : s.nodes.active_nodes)
      Au[i] = Tensor<1, dim>();
    for (const unsigned int c : s.particles.occupied_cells)
      for (unsigned int p = s.particles.cell_begin(c);
           p < s.particles.cell_end(c);
           ++p)
        {
          const auto           w  = weights(s, c, p);
          const Tensor<1, dim> Su = interpolate(s, c, p, u);
          for (unsigned int k = 0; k < dim + 1; ++k)
            Au[s.grid->cell_nodes[c][k]] += w[k] * s.particles.mass[p] * Su;
        }
    for (auto &[i, v] : Au)
      v /= s.nodes.mass[i];
    return Au;
  }

  template <int dim>
  std::map<unsigned int, Tensor<1, dim>>
  nodal_velocity(const Setup<dim> &s)
  {
    std::map<unsigned int, Tensor<1, dim>> v;
    for (const unsigned int i : s.nodes.active_nodes)
      v[i] = s.nodes.momentum[i] / s.nodes.mass[i];
    return v;
  }

  template <int dim>
  void
  check_against_dense()
  {
    std::mt19937                           rng(11 + dim);
    std::uniform_real_distribution<double> u(-1, 1);
    Setup<dim>                             s;
    fill(
      s,
      [&](const Point<dim> &) {
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = u(rng);
        return v;
      },
      rng);
    const NodalConstraints<dim> no_walls(*s.grid, {});
    const auto                  vn    = nodal_velocity(s);
    double                      scale = 0;
    for (const auto &[i, v] : vn)
      scale = std::max(scale, v.norm());
    for (const unsigned int m : {2u, 3u, 5u, 8u})
      {
        Stages::XpicFields<dim> xpic;
        Stages::xpic_correction(
          *s.grid, s.particles, no_walls, s.nodes, m, xpic);
        // Dense: sum_k (-1)^(k+1) C(m, k) A^(k-1) v^n.
        std::map<unsigned int, Tensor<1, dim>> power = vn, star;
        for (const auto &[i, v] : vn)
          star[i] = Tensor<1, dim>();
        for (unsigned int k = 1; k <= m; ++k)
          {
            const double binomial
              = std::round(std::tgamma(m + 1.)
                           / (std::tgamma(k + 1.) * std::tgamma(m - k + 1.)));
            for (auto &[i, v] : star)
              v += ((k % 2 == 1) ? binomial : -binomial) * power[i];
            power = round_trip(s, power);
          }
        double error = 0;
        for (const auto &[i, v] : star)
          error = std::max(error, (xpic.correction[i] - (v - vn.at(i))).norm());
        std::printf("measured %dD XPIC(%u) correction against the dense "
                    "series: %.2e (relative)\n",
                    dim,
                    m,
                    error / scale);
        EXPECT_LT(error / scale, 1e-12) << "XPIC(" << m << ")";
      }
  }

  template <int dim>
  void
  check_uniform_and_resolved()
  {
    std::mt19937   rng(5 + dim);
    Tensor<1, dim> a;
    for (unsigned int d = 0; d < dim; ++d)
      a[d] = 0.3 + d;
    {
      Setup<dim> s;
      fill(
        s, [&](const Point<dim> &) { return a; }, rng);
      const NodalConstraints<dim> no_walls(*s.grid, {});
      Stages::XpicFields<dim>     xpic;
      Stages::xpic_correction(*s.grid, s.particles, no_walls, s.nodes, 4, xpic);
      double largest = 0;
      for (const unsigned int i : s.nodes.active_nodes)
        largest = std::max(largest, xpic.correction[i].norm());
      EXPECT_LT(largest / a.norm(), 1e-13);
    }
    // A resolved field: v_p = S w for a random nodal w (mass-weighted
    // errors over the active nodes).
    Setup<dim> s;
    fill(
      s, [&](const Point<dim> &) { return Tensor<1, dim>(); }, rng);
    std::uniform_real_distribution<double> u(-1, 1);
    std::map<unsigned int, Tensor<1, dim>> w;
    for (const unsigned int i : s.nodes.active_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        w[i][d] = u(rng);
    for (const unsigned int c : s.particles.occupied_cells)
      for (unsigned int p = s.particles.cell_begin(c);
           p < s.particles.cell_end(c);
           ++p)
        s.particles.velocity[p] = interpolate(s, c, p, w);
    s.nodes.reset_active();
    s.nodes.resize(s.grid->n_nodes());
    Stages::p2g(*s.grid, s.particles, s.nodes);
    const NodalConstraints<dim> no_walls(*s.grid, {});
    const auto                  vn = nodal_velocity(s);
    auto error = [&](const std::vector<Tensor<1, dim>> *correction) {
      double e = 0, norm = 0;
      for (const auto &[i, v] : vn)
        {
          const Tensor<1, dim> star = correction ? v + (*correction)[i] : v;
          e += s.nodes.mass[i] * (star - w[i]).norm_square();
          norm += s.nodes.mass[i] * w[i].norm_square();
        }
      return std::sqrt(e / norm);
    };
    double previous = error(nullptr);
    std::printf("measured %dD resolved field kept by PIC: error %.3f",
                dim,
                previous);
    for (const unsigned int m : {2u, 4u, 8u})
      {
        Stages::XpicFields<dim> xpic;
        Stages::xpic_correction(
          *s.grid, s.particles, no_walls, s.nodes, m, xpic);
        const double e = error(&xpic.correction);
        std::printf(", XPIC(%u) %.3f", m, e);
        EXPECT_LT(e, 0.8 * previous) << "XPIC(" << m << ")";
        previous = e;
      }
    std::printf("\n");
  }
} // namespace

TEST(XpicTransfer, CorrectionIsTheDenseSeries2D)
{
  check_against_dense<2>();
}

TEST(XpicTransfer, CorrectionIsTheDenseSeries3D)
{
  check_against_dense<3>();
}

TEST(XpicTransfer, UniformIsKeptAndResolvedErrorFallsWithOrder2D)
{
  check_uniform_and_resolved<2>();
}

TEST(XpicTransfer, UniformIsKeptAndResolvedErrorFallsWithOrder3D)
{
  check_uniform_and_resolved<3>();
}
