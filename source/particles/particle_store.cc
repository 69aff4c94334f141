#include <deal.II/base/exceptions.h>
#include <deal.II/base/parallel.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/particles/particle_store.h>

#include <algorithm>
#include <functional>
#include <iterator>

namespace fsgmpm
{
  template <int dim>
  void
  ParticleStore<dim>::add(const Point<dim>            &x,
                          const unsigned int           c,
                          const double                 m,
                          const double                 v0,
                          const Tensor<1, dim>        &vel,
                          const SymmetricTensor<2, 3> &sigma,
                          const std::uint16_t          material,
                          const std::uint16_t          body)
  {
    position.push_back(x);
    cell.push_back(c);
    mass.push_back(m);
    volume.push_back(v0);
    reference_volume.push_back(v0);
    velocity.push_back(vel);
    stress.push_back(sigma);
    material_id.push_back(material);
    body_id.push_back(body);
    free_surface.push_back(0);
    id.push_back(next_id++);
    if (!ghost.empty())
      ghost.push_back(0);
    if (with_affine_velocity)
      affine_velocity.emplace_back();
    if (with_initial_position)
      initial_position.push_back(x);
    if (with_plasticity)
      {
        plastic_strain.push_back(0.);
        yielding.push_back(0);
      }
  }



  template <int dim>
  void
  ParticleStore<dim>::reserve(const unsigned int n)
  {
    for_each_array([n](const char *, auto &v) { v.reserve(n); });
  }



  template <int dim>
  void
  ParticleStore<dim>::enable_initial_position()
  {
    with_initial_position = true;
    initial_position      = position;
  }



  template <int dim>
  void
  ParticleStore<dim>::enable_plasticity()
  {
    with_plasticity = true;
    plastic_strain.resize(size());
    yielding.resize(size());
  }



  template <int dim>
  void
  ParticleStore<dim>::enable_affine_velocity()
  {
    with_affine_velocity = true;
    affine_velocity.resize(size());
  }



  template <int dim>
  template <typename T>
  void
  ParticleStore<dim>::permute(std::vector<T> &v) const
  {
    // Along each cycle s -> order[s] -> ...: v[j] takes v[order[j]], which
    // is still unwritten; the cycle closes with the saved v[s].
    for (const unsigned int s : cycle_starts)
      {
        const T      first = v[s];
        unsigned int j     = s;
        for (unsigned int k = order_scratch[j]; k != s; k = order_scratch[j])
          {
            v[j] = v[k];
            j    = k;
          }
        v[j] = first;
      }
  }



  template <int dim>
  void
  ParticleStore<dim>::sort_by_cell(const unsigned int n_cells)
  {
    const unsigned int n = size();
    // The slots are numbered anew.
    geometry_cache.clear();
    if (slot_of_cell.size() != n_cells)
      {
        // A fresh array: a window's after the whole grid's (a restart's
        // points come by whole-grid cells) keeps no whole-grid capacity.
        std::vector<unsigned int>(n_cells, invalid_slot).swap(slot_of_cell);
        occupied_cells.clear();
      }
    // Empty the cells of the last sort, then list the occupied cells as
    // they are met and count their points (in slot_begin, by slot).
    for (const unsigned int c : occupied_cells)
      slot_of_cell[c] = invalid_slot;
    occupied_cells.clear();
    slot_begin.clear();
    // By runs of points of one cell (the points of a cell are mostly
    // together): one count per run, not an increment of the same counter
    // per point, which waited for the previous one.
    bool sorted = true;
    for (unsigned int p = 0; p < n;)
      {
        const unsigned int c = cell[p];
        unsigned int       q = p + 1;
        while (q < n && cell[q] == c)
          ++q;
        unsigned int &j = slot_of_cell[c];
        if (j == invalid_slot)
          {
            j = occupied_cells.size();
            occupied_cells.push_back(c);
            slot_begin.push_back(0);
          }
        slot_begin[j] += q - p;
        // Sorted: the cells ascend, and inside a cell the ids.
        if (sorted)
          {
            sorted = (p == 0 || cell[p - 1] < c);
            for (unsigned int k = p + 1; sorted && k < q; ++k)
              sorted = id[k - 1] < id[k];
          }
        p = q;
      }
    // Met in point order: ascending already when the points are sorted.
    // Otherwise sort the cells and renumber their slots, counts along.
    if (!sorted)
      {
        std::sort(occupied_cells.begin(), occupied_cells.end());
        slot_cursor.resize(occupied_cells.size());
        for (unsigned int j = 0; j < occupied_cells.size(); ++j)
          slot_cursor[j] = slot_begin[slot_of_cell[occupied_cells[j]]];
        for (unsigned int j = 0; j < occupied_cells.size(); ++j)
          {
            slot_of_cell[occupied_cells[j]] = j;
            slot_begin[j]                   = slot_cursor[j];
          }
      }
    unsigned int start = 0;
    for (unsigned int &begin : slot_begin)
      {
        const unsigned int count = begin;
        begin                    = start;
        start += count;
      }
    slot_end.resize(slot_begin.size());
    for (unsigned int j = 0; j + 1 < slot_begin.size(); ++j)
      slot_end[j] = slot_begin[j + 1];
    if (!slot_end.empty())
      slot_end.back() = n;
    if (sorted)
      return;

    // Counting sort into the occupied cells.
    slot_cursor = slot_begin;
    order_scratch.resize(n);
    for (unsigned int p = 0; p < n;)
      {
        unsigned int      &cursor = slot_cursor[slot_of_cell[cell[p]]];
        unsigned int       to     = cursor;
        const unsigned int c      = cell[p];
        for (; p < n && cell[p] == c; ++p)
          order_scratch[to++] = p;
        cursor = to;
      }
    // Inside each cell by id: the points that stayed keep their order and
    // the few that came in are inserted.
    for (unsigned int j = 0; j < slot_begin.size(); ++j)
      for (unsigned int i = slot_begin[j] + 1; i < slot_end[j]; ++i)
        {
          const unsigned int q = order_scratch[i];
          unsigned int       k = i;
          for (; k > slot_begin[j] && id[order_scratch[k - 1]] > id[q]; --k)
            order_scratch[k] = order_scratch[k - 1];
          order_scratch[k] = q;
        }
    // The cycles of the permutation, once for all arrays.
    cycle_starts.clear();
    {
      std::vector<bool> done(n, false);
      for (unsigned int i = 0; i < n; ++i)
        if (!done[i] && order_scratch[i] != i)
          {
            cycle_starts.push_back(i);
            for (unsigned int k = i; !done[k]; k = order_scratch[k])
              done[k] = true;
          }
    }

    // Each array along the same cycles, the arrays in parallel (one task
    // each; serial, the sort held back the second thread).
    std::vector<std::function<void()>> arrays;
    for_each_array([&](const char *, auto &v) {
      arrays.emplace_back([this, &v]() { permute(v); });
    });
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(arrays.size()),
      [&](const unsigned int b, const unsigned int e) {
        for (unsigned int k = b; k < e; ++k)
          arrays[k]();
      },
      1);
  }



  template <int dim>
  void
  ParticleStore<dim>::remove_flagged(const std::vector<std::uint8_t> &flag)
  {
    std::vector<unsigned int> keep;
    keep.reserve(size());
    for (unsigned int p = 0; p < size(); ++p)
      if (flag[p] == 0)
        keep.push_back(p);
    if (keep.size() == size())
      return;
    auto shrink = [&](auto &v) {
      for (unsigned int i = 0; i < keep.size(); ++i)
        v[i] = v[keep[i]];
      v.resize(keep.size());
    };
    for_each_array([&](const char *, auto &v) { shrink(v); });
  }



  template <int dim>
  void
  ParticleStore<dim>::append_cell_range(const unsigned int c,
                                        const unsigned int begin,
                                        const unsigned int end)
  {
    AssertThrow(slot_of_cell[c] == invalid_slot,
                ExcMessage("A cell's points must be appended in one run."));
    slot_of_cell[c] = slot_begin.size();
    slot_begin.push_back(begin);
    slot_end.push_back(end);
  }



  template <int dim>
  void
  ParticleStore<dim>::keep_cell_ranges(const std::vector<unsigned int> &cells)
  {
    // Renumber the kept cells' slots in their order (the slots of a sort),
    // their cached geometry along.
    if (!geometry_cache.empty())
      {
        std::vector<CellGeometry<dim>> kept;
        kept.reserve(cells.size());
        for (const unsigned int c : cells)
          {
            const CellGeometry<dim> *g = cached_geometry(c);
            if (g == nullptr)
              break;
            kept.push_back(*g);
          }
        geometry_cache.swap(kept);
      }
    slot_cursor.resize(2 * cells.size());
    for (unsigned int j = 0; j < cells.size(); ++j)
      {
        slot_cursor[2 * j]     = cell_begin(cells[j]);
        slot_cursor[2 * j + 1] = cell_end(cells[j]);
      }
    for (const unsigned int c : occupied_cells)
      slot_of_cell[c] = invalid_slot;
    slot_begin.resize(cells.size());
    slot_end.resize(cells.size());
    for (unsigned int j = 0; j < cells.size(); ++j)
      {
        slot_of_cell[cells[j]] = j;
        slot_begin[j]          = slot_cursor[2 * j];
        slot_end[j]            = slot_cursor[2 * j + 1];
      }
    occupied_cells = cells;
  }



  template <int dim>
  void
  ParticleStore<dim>::cache_cell_geometry(const BackgroundGrid<dim> &grid)
  {
    if (!caches_geometry || occupied_cells.empty()
        || geometry_cache.size() == occupied_cells.size())
      return;
    // One entry per slot. Slot j is not always occupied_cells[j]: the
    // cells of MPI ghost copies get the slots after the sorted ones but
    // are merged into occupied_cells in ascending order.
    geometry_cache.resize(occupied_cells.size());
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(occupied_cells.size()),
      [&](const unsigned int b, const unsigned int e) {
        for (unsigned int i = b; i < e; ++i)
          {
            const unsigned int c = occupied_cells[i];
            AssertIndexRange(slot_of_cell[c], geometry_cache.size());
            geometry_cache[slot_of_cell[c]] = grid.geometry(c);
          }
      },
      256);
  }



  template <int dim>
  double
  ParticleStore<dim>::bytes_per_particle() const
  {
    if (size() == 0)
      return 0;
    double bytes = 0;
    for_each_state_array([&](const char *, const auto &v) {
      bytes += v.capacity() * sizeof(v[0]);
    });
    bytes += ghost.capacity()
             + (occupied_cells.capacity() + slot_of_cell.capacity()
                + slot_begin.capacity() + slot_end.capacity()
                + order_scratch.capacity() + slot_cursor.capacity()
                + cycle_starts.capacity())
                 * sizeof(unsigned int)
             + geometry_cache.capacity() * sizeof(CellGeometry<dim>);
    return bytes / size();
  }



  template class ParticleStore<2>;
  template class ParticleStore<3>;
} // namespace fsgmpm
