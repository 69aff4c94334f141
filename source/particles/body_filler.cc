#include <deal.II/base/exceptions.h>

#include <fsgmpm/particles/body_filler.h>
#include <fsgmpm/particles/point_locator.h>

#include <algorithm>
#include <limits>

namespace fsgmpm
{
  namespace
  {
    template <int dim>
    using Simplex = std::array<std::array<double, dim + 1>, dim + 1>;

    template <int dim>
    std::array<double, dim + 1>
    midpoint(const std::array<double, dim + 1> &a,
             const std::array<double, dim + 1> &b)
    {
      std::array<double, dim + 1> m;
      for (unsigned int k = 0; k < dim + 1; ++k)
        m[k] = 0.5 * (a[k] + b[k]);
      return m;
    }

    // Regular refinement of a triangle into 4 and of a tetrahedron into 8
    // children of equal volume (Bey's rule).
    template <int dim>
    std::vector<Simplex<dim>>
    refine(const Simplex<dim> &s)
    {
      if constexpr (dim == 2)
        {
          const auto m01 = midpoint<2>(s[0], s[1]),
                     m02 = midpoint<2>(s[0], s[2]),
                     m12 = midpoint<2>(s[1], s[2]);
          return {{{s[0], m01, m02}},
                  {{m01, s[1], m12}},
                  {{m02, m12, s[2]}},
                  {{m01, m12, m02}}};
        }
      else
        {
          const auto x01
            = midpoint<3>(s[0], s[1]),
            x02 = midpoint<3>(s[0], s[2]), x03 = midpoint<3>(s[0], s[3]),
            x12 = midpoint<3>(s[1], s[2]), x13 = midpoint<3>(s[1], s[3]),
            x23 = midpoint<3>(s[2], s[3]);
          return {{{s[0], x01, x02, x03}},
                  {{x01, s[1], x12, x13}},
                  {{x02, x12, s[2], x23}},
                  {{x03, x13, x23, s[3]}},
                  {{x01, x02, x03, x13}},
                  {{x01, x02, x12, x13}},
                  {{x02, x03, x13, x23}},
                  {{x02, x12, x13, x23}}};
        }
    }
  } // namespace



  template <int dim>
  std::vector<std::array<double, dim + 1>>
  reference_particle_points(const unsigned int particles_per_cell)
  {
    std::vector<Simplex<dim>> simplices(1);
    for (unsigned int k = 0; k < dim + 1; ++k)
      for (unsigned int j = 0; j < dim + 1; ++j)
        simplices[0][k][j] = (k == j) ? 1. : 0.;
    while (simplices.size() < particles_per_cell)
      {
        std::vector<Simplex<dim>> next;
        for (const auto &s : simplices)
          for (const auto &child : refine<dim>(s))
            next.push_back(child);
        simplices.swap(next);
      }
    AssertThrow(simplices.size() == particles_per_cell,
                ExcMessage("Particles per cell must be a power of "
                           + std::to_string(1u << dim) + " (1, "
                           + std::to_string(1u << dim) + ", "
                           + std::to_string(1u << (2 * dim)) + ", ...) in "
                           + std::to_string(dim) + "D; got "
                           + std::to_string(particles_per_cell) + "."));
    std::vector<std::array<double, dim + 1>> points;
    for (const auto &s : simplices)
      {
        std::array<double, dim + 1> c{};
        for (unsigned int v = 0; v < dim + 1; ++v)
          for (unsigned int k = 0; k < dim + 1; ++k)
            c[k] += s[v][k] / (dim + 1);
        points.push_back(c);
      }
    return points;
  }



  template <int dim>
  unsigned int
  fill_body(const BackgroundGrid<dim>                 &grid,
            const BodyShape<dim>                      &shape,
            const unsigned int                         particles_per_cell,
            const double                               density,
            const Tensor<1, dim>                      &initial_velocity,
            const std::uint16_t                        material_id,
            const std::uint16_t                        body_id,
            ParticleStore<dim>                        &particles,
            const std::vector<const BodyShape<dim> *> &taken,
            const std::vector<std::uint8_t>           *keep_cell,
            std::vector<unsigned int>                 *points_per_base_cell,
            const std::vector<unsigned int>           *first_id)
  {
    Assert(!keep_cell || keep_cell->size() == grid.n_base_cells(),
           ExcInternalError());
    Assert(!points_per_base_cell
             || points_per_base_cell->size() == grid.n_base_cells(),
           ExcInternalError());
    AssertThrow(!grid.is_window()
                  || (first_id && first_id->size() == grid.n_base_cells()),
                ExcInternalError());
    const std::string body_name
      = "Body " + std::to_string(body_id) + " (" + shape.description()
        + (shape.parameters.empty() ? "" : ", from " + shape.parameters);
    // The whole body lies in the mesh. The outline's points follow one
    // another: each walk starts from the previous point's cell, as far as
    // it needs (a box's corners are the mesh's width apart; a walk of 64
    // cells then searched all cells: 0.2 s of the start of a 1.2
    // M-tetrahedron grid), and all cells are searched only if it fails
    // (a non-convex mesh; the geotube at 1 cm, 422 400 cells: 11 s of its
    // set-up when every point searched all cells). Round-off on the mesh
    // boundary is allowed. (A window is part of the mesh: the process
    // that fills the whole grid checks the whole body.)
    const PointLocator<dim> locator(grid, 1e-9);
    unsigned int            previous = 0;
    if (!grid.is_window())
      for (const Point<dim> &p : shape.outline_points())
        {
          unsigned int c = locator.walk(p, previous, grid.n_base_cells());
          if (c == BackgroundGrid<dim>::invalid)
            c = locator.locate(p, previous);
          if (c != BackgroundGrid<dim>::invalid)
            previous = c;
          AssertThrow(c != BackgroundGrid<dim>::invalid,
                      ExcMessage(
                        body_name
                        + ") reaches outside the background mesh, e.g. "
                          "at the point ("
                        +
                        [&] {
                          std::ostringstream s;
                          s << p;
                          return s.str();
                        }()
                        + "). Move the body or enlarge the grid."));
        }

    const auto   ref   = reference_particle_points<dim>(particles_per_cell);
    unsigned int added = 0, overlapped = 0;
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      {
        if (first_id)
          particles.next_id = (*first_id)[c];
        const double v = grid.cell_volume(c) / ref.size();
        for (const auto &lambda : ref)
          {
            const Point<dim> x = grid.position(c, lambda);
            if (!shape.inside(x))
              continue;
            if (std::any_of(taken.begin(), taken.end(), [&](const auto *s) {
                  return s->inside(x);
                }))
              {
                ++overlapped;
                continue;
              }
            if (!keep_cell || (*keep_cell)[c])
              particles.add(x,
                            c,
                            density * v,
                            v,
                            initial_velocity,
                            SymmetricTensor<2, 3>(),
                            material_id,
                            body_id);
            else
              ++particles.next_id; // the id this point has in a serial run
            if (points_per_base_cell)
              ++(*points_per_base_cell)[c];
            ++added;
          }
      }
    AssertThrow(added > 0 || grid.is_window(),
                ExcMessage(
                  body_name
                  + (overlapped > 0
                       ? ") lies entirely inside bodies listed before it "
                         "(bodies fill in order, an earlier body keeps the "
                         "region they share); list it before them."
                       : ") contains no material point: it is smaller than "
                         "the grid resolution or outside the mesh.")));
    return added;
  }



  template <int dim>
  double
  surface_height_above(const BodyShape<dim> &shape,
                       const Point<dim>     &x,
                       const double          y_top,
                       const double          step,
                       const double          tolerance)
  {
    Assert(step > 0 && tolerance > 0, ExcMessage("Positive step needed."));
    // March up to the first point outside, then bisect the last step.
    Point<dim> probe = x;
    double     below = x[1];
    while (below < y_top)
      {
        probe[1] = std::min(below + step, y_top);
        if (!shape.inside(probe))
          break;
        below = probe[1];
      }
    if (below >= y_top)
      return y_top;
    double above = probe[1];
    while (above - below > tolerance)
      {
        probe[1]                              = 0.5 * (below + above);
        (shape.inside(probe) ? below : above) = probe[1];
      }
    return 0.5 * (below + above);
  }

  template std::vector<std::array<double, 3>>
  reference_particle_points<2>(const unsigned int);
  template std::vector<std::array<double, 4>>
  reference_particle_points<3>(const unsigned int);
  template unsigned int
  fill_body<2>(const BackgroundGrid<2> &,
               const BodyShape<2> &,
               const unsigned int,
               const double,
               const Tensor<1, 2> &,
               const std::uint16_t,
               const std::uint16_t,
               ParticleStore<2> &,
               const std::vector<const BodyShape<2> *> &,
               const std::vector<std::uint8_t> *,
               std::vector<unsigned int> *,
               const std::vector<unsigned int> *);
  template double
  surface_height_above<2>(const BodyShape<2> &,
                          const Point<2> &,
                          const double,
                          const double,
                          const double);
  template double
  surface_height_above<3>(const BodyShape<3> &,
                          const Point<3> &,
                          const double,
                          const double,
                          const double);
  template unsigned int
  fill_body<3>(const BackgroundGrid<3> &,
               const BodyShape<3> &,
               const unsigned int,
               const double,
               const Tensor<1, 3> &,
               const std::uint16_t,
               const std::uint16_t,
               ParticleStore<3> &,
               const std::vector<const BodyShape<3> *> &,
               const std::vector<std::uint8_t> *,
               std::vector<unsigned int> *,
               const std::vector<unsigned int> *);
} // namespace fsgmpm
