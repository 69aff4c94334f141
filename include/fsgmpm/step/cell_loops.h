#ifndef fsgmpm_step_cell_loops_h
#define fsgmpm_step_cell_loops_h

#include <deal.II/base/parallel.h>

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/particles/particle_store.h>

#include <algorithm>
#include <array>
#include <vector>

namespace fsgmpm
{
  namespace CellLoops
  {
    /// Run f(begin, end) over [0, n) in parallel chunks (TBB through deal.II).
    template <typename Function>
    void
    parallel_range(const unsigned int n,
                   const Function    &f,
                   const unsigned int grain = 256)
    {
      dealii::parallel::apply_to_subranges(0u, n, f, grain);
    }

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
     * A reduction over the items [0, n) in fixed chunks of @p chunk, in
     * parallel: each chunk starts from @p initial, f(a, value) takes item a
     * in, in order, and merge(total, chunk_value) combines the chunks' values
     * in chunk order, starting from @p initial. The chunks do not depend on
     * the number of threads, so neither does the result.
     */
    template <typename Value, typename Function, typename Merge>
    Value
    chunked_reduction(const unsigned int n,
                      const unsigned int chunk,
                      const Value       &initial,
                      const Function    &f,
                      const Merge       &merge)
    {
      const unsigned int n_chunks = (n + chunk - 1) / chunk;
      std::vector<Value> partial(n_chunks, initial);
      parallel_range(
        n_chunks,
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int k = b; k < e; ++k)
            {
              // In a local, which the compiler can keep in registers.
              Value value = initial;
              for (unsigned int a = k * chunk; a < std::min(n, (k + 1) * chunk);
                   ++a)
                f(a, value);
              partial[k] = value;
            }
        },
        1);
      Value total = initial;
      for (const Value &p : partial)
        merge(total, p);
      return total;
    }

    /**
     * N compensated sums over the items [0, n), in parallel: f(a, sums)
     * adds item a's terms to sums[0..N-1]. The items are summed in fixed
     * chunks of 512 (small enough to share among threads), in order, and the
     * chunks' sums merged in order (CompensatedSum::add(const CompensatedSum
     * &)), so the result does not depend on the number of threads.
     */
    template <unsigned int N, typename Function>
    std::array<CompensatedSum, N>
    compensated_sums(const unsigned int n, const Function &f)
    {
      using Sums = std::array<CompensatedSum, N>;
      return chunked_reduction(
        n, 512, Sums(), f, [](Sums &total, const Sums &chunk_sums) {
          for (unsigned int q = 0; q < N; ++q)
            total[q].add(chunk_sums[q]);
        });
    }

    /**
     * N maxima over the items [0, n), in parallel: f(a, maxima) raises
     * maxima[0..N-1] by item a's values (std::max). Each chunk of 4096 items
     * starts from @p initial and the chunks' maxima are merged with
     * std::max: a maximum is exact, so the result does not depend on the
     * number of threads.
     */
    template <unsigned int N, typename Function>
    std::array<double, N>
    parallel_maxima(const unsigned int           n,
                    const std::array<double, N> &initial,
                    const Function              &f)
    {
      using Maxima = std::array<double, N>;
      return chunked_reduction(
        n, 4096, initial, f, [](Maxima &total, const Maxima &chunk_maxima) {
          for (unsigned int q = 0; q < N; ++q)
            total[q] = std::max(total[q], chunk_maxima[q]);
        });
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
