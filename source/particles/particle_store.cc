#include <fsgmpm/particles/particle_store.h>

#include <algorithm>
#include <cstring>

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
  ParticleStore<dim>::permute(std::vector<T>                  &v,
                              const std::vector<unsigned int> &order)
  {
    value_scratch.resize(sizeof(T) * v.size());
    T *tmp = reinterpret_cast<T *>(value_scratch.data());
    for (unsigned int i = 0; i < order.size(); ++i)
      tmp[i] = v[order[i]];
    std::memcpy(static_cast<void *>(v.data()), tmp, sizeof(T) * v.size());
  }



  template <int dim>
  void
  ParticleStore<dim>::sort_by_cell(const unsigned int n_cells)
  {
    const unsigned int n = size();
    if (cell_begin.size() != n_cells)
      {
        cell_begin.assign(n_cells, 0);
        cell_end.assign(n_cells, 0);
        occupied_cells.clear();
      }
    // Empty the cells of the last sort, then count into cell_end and list
    // the occupied cells as they are met.
    for (const unsigned int c : occupied_cells)
      cell_begin[c] = cell_end[c] = 0;
    occupied_cells.clear();
    bool sorted = true;
    for (unsigned int p = 0; p < n; ++p)
      {
        if (cell_end[cell[p]]++ == 0)
          occupied_cells.push_back(cell[p]);
        sorted = sorted
                 && (p == 0 || cell[p - 1] < cell[p]
                     || (cell[p - 1] == cell[p] && id[p - 1] < id[p]));
      }
    // Met in point order: ascending already when the points are sorted.
    if (!sorted)
      std::sort(occupied_cells.begin(), occupied_cells.end());
    unsigned int start = 0;
    for (const unsigned int c : occupied_cells)
      {
        cell_begin[c] = start;
        start += cell_end[c];
        cell_end[c] = sorted ? start : cell_begin[c];
      }
    if (sorted)
      return;

    // Counting sort into the occupied cells; cell_end runs from cell_begin
    // to its final value.
    order_scratch.resize(n);
    for (unsigned int p = 0; p < n; ++p)
      order_scratch[cell_end[cell[p]]++] = p;
    // Inside each cell by id: the points that stayed keep their order and
    // the few that came in are inserted.
    for (const unsigned int c : occupied_cells)
      for (unsigned int i = cell_begin[c] + 1; i < cell_end[c]; ++i)
        {
          const unsigned int q = order_scratch[i];
          unsigned int       j = i;
          for (; j > cell_begin[c] && id[order_scratch[j - 1]] > id[q]; --j)
            order_scratch[j] = order_scratch[j - 1];
          order_scratch[j] = q;
        }

    permute(position, order_scratch);
    permute(velocity, order_scratch);
    permute(stress, order_scratch);
    permute(mass, order_scratch);
    permute(volume, order_scratch);
    permute(reference_volume, order_scratch);
    permute(cell, order_scratch);
    permute(material_id, order_scratch);
    permute(body_id, order_scratch);
    permute(free_surface, order_scratch);
    permute(id, order_scratch);
    if (!ghost.empty())
      permute(ghost, order_scratch);
    if (with_affine_velocity)
      permute(affine_velocity, order_scratch);
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
    shrink(position);
    shrink(velocity);
    shrink(stress);
    shrink(mass);
    shrink(volume);
    shrink(reference_volume);
    shrink(cell);
    shrink(material_id);
    shrink(body_id);
    shrink(free_surface);
    shrink(id);
    if (!ghost.empty())
      shrink(ghost);
    if (with_affine_velocity)
      shrink(affine_velocity);
  }



  template <int dim>
  double
  ParticleStore<dim>::bytes_per_particle() const
  {
    if (size() == 0)
      return 0;
    const double bytes
      = position.capacity() * sizeof(Point<dim>)
        + velocity.capacity() * sizeof(Tensor<1, dim>)
        + affine_velocity.capacity() * sizeof(Tensor<2, dim>)
        + stress.capacity() * sizeof(SymmetricTensor<2, 3>)
        + (mass.capacity() + volume.capacity() + reference_volume.capacity())
            * sizeof(double)
        + cell.capacity() * sizeof(unsigned int)
        + (material_id.capacity() + body_id.capacity()) * sizeof(std::uint16_t)
        + free_surface.capacity() + ghost.capacity()
        + id.capacity() * sizeof(unsigned int)
        + order_scratch.capacity() * sizeof(unsigned int)
        + value_scratch.capacity();
    return bytes / size();
  }

  template class ParticleStore<2>;
  template class ParticleStore<3>;
} // namespace fsgmpm
