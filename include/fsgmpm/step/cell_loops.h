#ifndef fsgmpm_step_cell_loops_h
#define fsgmpm_step_cell_loops_h

#include <fsgmpm/base/parallel_reductions.h>
#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/particles/particle_store.h>

#include <algorithm>
#include <array>
#include <vector>

namespace fsgmpm
{
  namespace CellLoops
  {
    // The generic reductions, for the stages' loops.
    using Reductions::chunked_reduction;
    using Reductions::compensated_sums;
    using Reductions::parallel_maxima;
    using Reductions::parallel_range;

    /// The geometry of cell @p c: the points' cached one
    /// (ParticleStore::cache_cell_geometry(), 3D) if they have it, else
    /// computed from the cell's vertices. The same bits either way.
    template <int dim>
    inline CellGeometry<dim>
    geometry(const BackgroundGrid<dim> &grid,
             const ParticleStore<dim>  &particles,
             const unsigned int         c)
    {
      // Without a cache (2D) the vertices' geometry, inlined, with no
      // lookup.
      if constexpr (ParticleStore<dim>::caches_geometry)
        if (const CellGeometry<dim> *cached = particles.cached_geometry(c))
          return *cached;
      return grid.geometry(c);
    }

    /// The volume of cell @p c, from its cached geometry if it has one.
    template <int dim>
    inline double
    cell_volume(const BackgroundGrid<dim> &grid,
                const ParticleStore<dim>  &particles,
                const unsigned int         c)
    {
      if constexpr (ParticleStore<dim>::caches_geometry)
        if (const CellGeometry<dim> *cached = particles.cached_geometry(c))
          return cached->volume;
      return grid.cell_volume(c);
    }

    /**
     * Call f(cell) for every occupied cell, colour by colour, the blocks of
     * a colour in parallel, the cells of a block in order
     * (BackgroundGrid::cell_block). No two blocks of a colour share a node,
     * so f may add to the nodes of its cell without locks, and every node
     * receives its contributions in the same order whatever the number of
     * threads.
     */
    template <int dim, typename Function>
    void
    scatter_by_colour(const BackgroundGrid<dim> &grid,
                      const ParticleStore<dim>  &particles,
                      const Function            &f)
    {
      // Per colour, the ranges of occupied_cells that are one block each
      // (the occupied cells ascend, and so do their blocks).
      thread_local std::vector<std::vector<std::array<unsigned int, 2>>>
        by_colour;
      by_colour.resize(grid.n_colours);
      for (auto &v : by_colour)
        v.clear();
      const auto &cells = particles.occupied_cells;
      for (unsigned int i = 0; i < cells.size();)
        {
          const unsigned int block = grid.cell_block(cells[i]);
          unsigned int       j     = i + 1;
          while (j < cells.size() && grid.cell_block(cells[j]) == block)
            ++j;
          // A block met twice would run twice in one colour, in parallel
          // with itself: a race. sort_by_cell() sorts; one comparison per
          // block keeps a program that fills occupied_cells itself honest.
          AssertThrow(j == cells.size() || grid.cell_block(cells[j]) > block,
                      ExcMessage("ParticleStore::occupied_cells must ascend "
                                 "(call sort_by_cell())."));
          by_colour[grid.block_colour[block]].push_back({{i, j}});
          i = j;
        }
      for (const auto &ranges : by_colour)
        parallel_range(
          ranges.size(),
          [&](const unsigned int b, const unsigned int e) {
            for (unsigned int r = b; r < e; ++r)
              for (unsigned int i = ranges[r][0]; i < ranges[r][1]; ++i)
                f(cells[i]);
          },
          1);
    }

    /// The points' volumes of cell @p c shared to its dim + 1 nodes,
    /// share[k] = sum_p N_k(x_p) V_p (free-surface volume fraction, contact).
    template <int dim>
    std::array<double, dim + 1>
    volume_shares(const BackgroundGrid<dim> &grid,
                  const ParticleStore<dim>  &particles,
                  const unsigned int         c)
    {
      std::array<double, dim + 1> share = {};
      const CellGeometry<dim>     geometry
        = CellLoops::geometry(grid, particles, c);
      for (unsigned int p = particles.cell_begin(c); p < particles.cell_end(c);
           ++p)
        {
          const auto lambda = geometry.barycentric(particles.position[p]);
          for (unsigned int k = 0; k < dim + 1; ++k)
            share[k] += lambda[k] * particles.volume[p];
        }
      return share;
    }

    /**
     * Scale of each point's weight in the NMD and ANP averages of cell @p c,
     * per material: 1 for point-volume weights, min(1, V_c / sum_p V_p) for
     * capped weights (MaterialOptions::capped_weights), the sum over the
     * material's points for which @p counts(p) is true.
     */
    template <int dim, typename Options, typename Predicate>
    void
    weight_scales(const BackgroundGrid<dim> &grid,
                  const ParticleStore<dim>  &particles,
                  const Options             &options,
                  const unsigned int         c,
                  const Predicate           &counts,
                  std::vector<double>       &scale)
    {
      // Point-volume weights (the default) need no pass over the points.
      scale.assign(options.size(), 1.);
      if (std::none_of(options.begin(), options.end(), [](const auto &o) {
            return o.capped_weights;
          }))
        return;
      // scale[m] first holds the sum of the material's counted volumes.
      std::fill(scale.begin(), scale.end(), 0.);
      for (unsigned int p = particles.cell_begin(c); p < particles.cell_end(c);
           ++p)
        if (options[particles.material_id[p]].capped_weights && counts(p))
          scale[particles.material_id[p]] += particles.volume[p];
      const double cell_volume = CellLoops::cell_volume(grid, particles, c);
      for (unsigned int m = 0; m < options.size(); ++m)
        scale[m] = (options[m].capped_weights && scale[m] > 0)
                     ? std::min(1., cell_volume / scale[m])
                     : 1.;
    }

    /**
     * Stress integration = nodal projection: the share gamma_c of cell @p c
     * whose quadrature of the projected stress is the cell's own, V_c /
     * (dim + 1) per node, the rest its points', sum_p N_k(x_p) V_p, from the
     * smallest fill of its nodes, @p min_node_fill (a node's fill is
     * sum_p N_k(x_p) V_p over the occupied cells' V_c / (dim + 1) around
     * it). 0 up to a fill of 3/4, 1 from 0.9 on, linear between. Inside the
     * material the cell's own weights keep the forces smooth as points
     * cross edges (the nodal fill is continuous in the points' positions,
     * and 0.9 leaves room for the fill's fluctuations there); in a cell
     * partly filled at a free surface, a membrane or a body in another
     * velocity field the points' weights integrate only where there is
     * material, so a uniform stress gives Eq. (3)'s forces exactly and a
     * nearly empty node is pushed only by what its points fill.
     */
    inline double
    geometric_quadrature_share(const double min_node_fill)
    {
      return std::clamp((min_node_fill - 0.75) / 0.15, 0., 1.);
    }

    /// Call f(cell) for every occupied cell in parallel (no scatter).
    template <int dim, typename Function>
    void
    for_each_occupied_cell(const ParticleStore<dim> &particles,
                           const Function           &f)
    {
      const auto &cells = particles.occupied_cells;
      parallel_range(
        cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int i = b; i < e; ++i)
            f(cells[i]);
        },
        16);
    }
  } // namespace CellLoops
} // namespace fsgmpm

#endif
