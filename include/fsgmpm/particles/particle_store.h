#ifndef fsgmpm_particles_particle_store_h
#define fsgmpm_particles_particle_store_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <fsgmpm/grid/cell_geometry.h>

#include <cstdint>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  template <int dim>
  class BackgroundGrid;

  /**
   * Material points in structure-of-arrays storage, kept sorted by the
   * background cell that contains them so that every per-cell quantity
   * (velocity gradient, shape gradients, node indices) is read once and
   * reused for all points of the cell.
   *
   * The stress is always a 3x3 symmetric tensor: in 2D (plane strain) it
   * keeps sigma_zz. It is the Cauchy stress, tension positive.
   */
  template <int dim>
  class ParticleStore
  {
  public:
    unsigned int
    size() const
    {
      return position.size();
    }

    /// Append one point; its cell must already be known. It gets the next
    /// point id (ids count the points in the order they are added).
    void
    add(const Point<dim>            &x,
        const unsigned int           cell,
        const double                 m,
        const double                 v0,
        const Tensor<1, dim>        &vel,
        const SymmetricTensor<2, 3> &sigma,
        const std::uint16_t          material,
        const std::uint16_t          body);

    /// Room for @p n points in every array, so that the fill leaves no
    /// spare capacity (push_back's doubling left up to half of each array
    /// unused: 33 B per point in the 2D dam break).
    void
    reserve(const unsigned int n);

    /**
     * Sort by cell, and inside a cell by point id: a canonical order that
     * depends only on which points are where, not on the history of the
     * array, so every sum over the points of a cell is the same whichever
     * process holds them (MPI runs reproduce serial runs bit for bit).
     * Rebuilds the cell ranges and occupied_cells. The cost is
     * O(n + k log k) for n points in k occupied cells, whatever the number
     * of cells: work follows the material, not the mesh (only the entries
     * of the cells occupied before and after are touched); the points of a
     * cell are ordered by insertion sort, linear when few moved.
     */
    void
    sort_by_cell(const unsigned int n_cells);

    /// Remove the points with flag != 0 (keeps the order of the others).
    void
    remove_flagged(const std::vector<std::uint8_t> &flag);

    /**
     * Switch on the affine velocity C_p of APIC (Jiang et al. 2015): from
     * now on every point carries it (zero for the points already stored).
     */
    void
    enable_affine_velocity();

    /**
     * Switch on the points' initial positions (for the displacement in the
     * output): from now on every point keeps where it was when this was
     * called (its position now; a point added later, where it is added).
     * Scenes with a solid body switch it on; pure water, whose
     * displacement means little, saves the memory.
     */
    void
    enable_initial_position();

    /**
     * Switch on the points' plastic state (for the output): the
     * accumulated equivalent plastic strain and the yield flag of the last
     * step, zero for the points already stored. Scenes with a material that
     * yields switch it on.
     */
    void
    enable_plasticity();

    /// Whether the points keep their plastic state.
    bool
    has_plasticity() const
    {
      return with_plasticity;
    }

    /// Whether the points keep their initial positions.
    bool
    has_initial_position() const
    {
      return with_initial_position;
    }

    /// Whether the points carry an affine velocity (APIC transfers).
    bool
    has_affine_velocity() const
    {
      return with_affine_velocity;
    }

    /// Memory held per point in bytes (all arrays, including scratch and
    /// the per-cell ranges).
    double
    bytes_per_particle() const;

    /// The number of cells of the last sort_by_cell().
    unsigned int
    n_cells() const
    {
      return slot_of_cell.size();
    }

    /// The slot of cell @p c (a number below occupied_cells.size(), its
    /// index there after sort_by_cell()), or numbers::invalid_unsigned_int
    /// if it holds no point.
    unsigned int
    occupied_slot(const unsigned int c) const
    {
      return slot_of_cell[c];
    }

    /// The points of cell c are [cell_begin(c), cell_end(c)) (an empty
    /// range for an empty cell).
    unsigned int
    cell_begin(const unsigned int c) const
    {
      const unsigned int j = slot_of_cell[c];
      return j == invalid_slot ? 0 : slot_begin[j];
    }

    unsigned int
    cell_end(const unsigned int c) const
    {
      const unsigned int j = slot_of_cell[c];
      return j == invalid_slot ? 0 : slot_end[j];
    }

    /// The end of the run of points of one material that starts at @p p,
    /// before @p end: the first point after p of another material, or end.
    /// A loop over a cell's points by runs looks its material up (a
    /// virtual material's function, a per-material array) once per run.
    unsigned int
    material_run_end(unsigned int p, const unsigned int end) const
    {
      const auto m = material_id[p];
      while (++p < end && material_id[p] == m)
        ;
      return p;
    }

    /// The cells with at least one point, ascending.
    std::vector<unsigned int> occupied_cells;

    /**
     * 3D: compute the geometry (CellGeometry) of every occupied cell once,
     * by slot, for the stages of a step to read (cached_geometry())
     * instead of each computing it from the cell's vertices again: the
     * 3 x 3 inverse and the four scattered vertices were 9 % of a step of
     * the 3D dam break, computed some ten times per cell and step. The
     * same arithmetic, so the same bits. Valid until the slots change
     * (sort_by_cell() forgets it); a cell appended later
     * (append_cell_range()) is not in it. In 2D, where the 2 x 2 inverse is
     * cheap and the memory per point is near its aim (104 B per cell would
     * be 14 B per point), nothing is cached.
     */
    void
    cache_cell_geometry(const BackgroundGrid<dim> &grid);

    /// Whether cache_cell_geometry() caches (3D only, above).
    static constexpr bool caches_geometry = (dim == 3);

    /// The cached geometry of cell @p c (cache_cell_geometry()), or
    /// nullptr if it has none.
    const CellGeometry<dim> *
    cached_geometry(const unsigned int c) const
    {
      if (c >= slot_of_cell.size())
        return nullptr;
      const unsigned int j = slot_of_cell[c];
      return j < geometry_cache.size() ? &geometry_cache[j] : nullptr;
    }

    /**
     * MPI (DistributedPoints::add_ghosts): cell @p c, empty so far, holds
     * the points [begin, end), appended after the sorted ones. It gets the
     * next slot; occupied_cells is the caller's to update.
     */
    void
    append_cell_range(const unsigned int c,
                      const unsigned int begin,
                      const unsigned int end);

    /// MPI (DistributedPoints::drop_ghosts): keep the ranges of the
    /// ascending @p cells only, which become occupied_cells.
    void
    keep_cell_ranges(const std::vector<unsigned int> &cells);

    std::vector<Point<dim>>     position;
    std::vector<Tensor<1, dim>> velocity;
    /// APIC only (empty otherwise): the affine part C_p of the point's
    /// velocity field, v(x) = v_p + C_p (x - x_p) within its cell.
    std::vector<Tensor<2, dim>>        affine_velocity;
    std::vector<SymmetricTensor<2, 3>> stress;
    /// Where each point was at the start (empty unless
    /// enable_initial_position()): the displacement is position minus it.
    std::vector<Point<dim>> initial_position;
    /// Accumulated equivalent plastic strain and whether the point yielded
    /// in the last step (empty unless enable_plasticity();
    /// PointPlasticity).
    std::vector<double>       plastic_strain;
    std::vector<std::uint8_t> yielding;
    std::vector<double>       mass;
    std::vector<double>       volume;
    /// Reference volume: the volume at zero pressure (fluids: m/rho_ref),
    /// so that J = V/V_ref is the deformation state of Eq. (16).
    std::vector<double>        reference_volume;
    std::vector<unsigned int>  cell;
    std::vector<std::uint16_t> material_id;
    std::vector<std::uint16_t> body_id;
    /// 1 for points flagged as free surface or drops (paper Eq. 33).
    std::vector<std::uint8_t> free_surface;
    /// Point id, unique over all processes: the fill order of the serial
    /// run, which fixes the order of the points inside a cell.
    std::vector<unsigned int> id;
    /// MPI runs only (empty otherwise): 1 for a copy of a point owned by
    /// another process, held during a step because its cell touches a node
    /// of one of this process's cells (DistributedPoints).
    std::vector<std::uint8_t> ghost;

    /// The id the next added point gets.
    unsigned int next_id = 0;

    /**
     * Calls f(name, array) for every per-point array that makes up the
     * points' state, in a fixed order: the optional arrays only when they
     * are switched on, the process-local `ghost` flags never. This is the
     * one list of the arrays: sorting, reserving, removing, the MPI
     * exchange, the checkpoints and the memory count all go through it, so
     * a new per-point array is added here and in add() and nowhere else.
     * @p name is the array's name in checkpoints.
     */
    template <typename Function>
    void
    for_each_state_array(const Function &f)
    {
      arrays_of(*this, f);
    }

    template <typename Function>
    void
    for_each_state_array(const Function &f) const
    {
      arrays_of(*this, f);
    }

    /// for_each_state_array() and, in MPI runs, the `ghost` flags.
    template <typename Function>
    void
    for_each_array(const Function &f)
    {
      arrays_of(*this, f);
      if (!ghost.empty())
        f("ghost", ghost);
    }

  private:
    template <typename Self, typename Function>
    static void
    arrays_of(Self &self, const Function &f)
    {
      f("position", self.position);
      f("velocity", self.velocity);
      if (self.with_affine_velocity)
        f("affine_velocity", self.affine_velocity);
      if (self.with_initial_position)
        f("initial_position", self.initial_position);
      if (self.with_plasticity)
        {
          f("plastic_strain", self.plastic_strain);
          f("yielding", self.yielding);
        }
      f("stress", self.stress);
      f("mass", self.mass);
      f("volume", self.volume);
      f("reference_volume", self.reference_volume);
      f("cell", self.cell);
      f("material_id", self.material_id);
      f("body_id", self.body_id);
      f("free_surface", self.free_surface);
      f("id", self.id);
    }

    static constexpr unsigned int invalid_slot = static_cast<unsigned int>(-1);

    /// Reorder @p v to v[order[i]] in place, along the cycles of the
    /// permutation (cycle_starts): no copy of the array, which cost up to
    /// 48 B per point as scratch.
    template <typename T>
    void
    permute(std::vector<T> &v) const;

    bool with_affine_velocity  = false;
    bool with_initial_position = false;
    bool with_plasticity       = false;
    /// Per cell: its slot, or invalid_slot (4 B per cell, where a begin
    /// and an end per cell took 8).
    std::vector<unsigned int> slot_of_cell;
    /// Per occupied cell j: its points are [slot_begin[j], slot_end[j]).
    /// A slot is a number below occupied_cells.size(); sort_by_cell()
    /// numbers the cells in ascending order.
    std::vector<unsigned int> slot_begin, slot_end;
    /// Scratch of the sort: the new order, a cursor per occupied cell, one
    /// index of each cycle of the permutation that is not a fixed point.
    std::vector<unsigned int> order_scratch;
    std::vector<unsigned int> slot_cursor;
    std::vector<unsigned int> cycle_starts;
    /// cache_cell_geometry(): the geometry of the cell of each slot.
    std::vector<CellGeometry<dim>> geometry_cache;
  };
} // namespace fsgmpm

#endif
