#ifndef fsgmpm_step_membrane_coupling_h
#define fsgmpm_step_membrane_coupling_h

#include <deal.II/base/symmetric_tensor.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/parallel/domain_partition.h>

#include <array>
#include <vector>

namespace fsgmpm
{
  /**
   * The FEM-MPM coupling of a membrane to the background grid through the
   * shared grid nodes (paper Section 2.1.2, Eqs. 17-21): the membrane's
   * stages of the explicit step, and the state that only the step needs,
   * the transfer weights N_i(x_a) of every membrane node to the nodes of
   * its cell. The membrane nodes take part in the transfers like material
   * points, with shape values only (never gradients):
   *
   *   p2g() after Stages::p2g -> time_step() -> g2p() after the grid update
   *   -> remap() inside Stages::remap -> update_positions()
   *   -> relocate() after Stages::relocate
   *
   * The weights are the shape values at the start of the step, set by
   * p2g() and used by every other stage of the step. The membrane is small
   * (10^2-10^4 nodes against 10^5 points), so the stages run serially.
   * MpmStep owns one when a membrane is attached.
   *
   * MPI (attach_partition()): every process holds the whole membrane and
   * its window of the grid (the cells of its own nodes and the cells
   * around them). It adds the membrane nodes in its window to its nodes
   * (p2g, remap): every node it computes exactly gets the membrane's full
   * share, as a window holds every cell that touches such a node. The
   * nodes' cells are whole-grid numbers, the same on every process, found
   * by all processes together (locate_on_windows()). What reads grid
   * values (the
   * nodes' velocities and displacements) is computed by the owner of the
   * node's cell, the only process whose values there are exact, and summed
   * over the processes (the others contribute -0, so the sum is the
   * owner's value bit for bit); the nodal time-step bound is the minimum
   * over the nodes each process counts. Everything else (slip, splits,
   * location, element forces) runs on identical data on every process.
   */
  template <int dim>
  class MembraneCoupling
  {
  public:
    /// Couples @p membrane to @p grid; cables longer than @p split_length
    /// are split when they stretch (0: never).
    MembraneCoupling(const BackgroundGrid<dim> &grid,
                     Membrane<dim>             &membrane,
                     const double               split_length = 0);

    /// MPI: the partition whose cell owners compute the membrane nodes'
    /// grid velocities (see the class comment).
    void
    attach_partition(const DomainPartition<dim> &p)
    {
      partition = &p;
    }

    /// Stage 1m (Eqs. 3, 4, 17): mass, momentum and element forces of the
    /// membrane nodes to the nodes of their cells (which become active),
    /// with the transfer weights at the nodes' current positions, which the
    /// other stages of the step reuse. Call after Stages::p2g.
    void
    p2g(NodalFields<dim> &nodes);

    /// Nodal time-step bound with the membrane: min over the grid
    /// nodes the membrane touches and over directions of 2 sqrt(m_i / k),
    /// k an eigenvalue of a bound D_i + k_p,i I of the stiffness at node i
    /// (K <= diag(D_i + k_p,i I)): the membrane's as the grid sees it,
    /// N^T K_m N, by Cauchy-Schwarz with the nodal masses as weights
    /// (Membrane::ElementStiffness; a node the membrane barely reaches gets
    /// little of it), plus the material points' row sums
    /// sum_c S_c |grad N_i^c| sum_j |grad N_j^c| (S_c from
    /// Stages::stable_time_step()'s @p cell_stiffness over @p
    /// occupied_cells). The points' share matters at nearly empty nodes of
    /// partly covered cells (the geotube's lower corners): the membrane
    /// nodes take their grid velocity before the remap (PIC), so such a
    /// node's small mass is not protected by Eq. (20) as the points are.
    /// Without the Courant factor. If @p dt_floor > 0 (dynamic relaxation
    /// with mass scaling), the directions whose bound would fall below
    /// dt_floor get the fictitious inertia NodalFields::added_mass = (k
    /// dt_floor^2 / 4 - m_i) e(x)e instead (along the cables, not across
    /// them), and the returned bound is at least dt_floor. Writes nothing
    /// else to @p nodes. After p2g().
    double
    time_step(const std::vector<double>       &cell_stiffness,
              const std::vector<unsigned int> &occupied_cells,
              NodalFields<dim>                &nodes,
              const double                     dt_floor = 0);

    /// Stage 3m: membrane-node velocities from the grid velocities (PIC:
    /// the nodes' mass is negligible, and PIC keeps their velocity free of
    /// noise).
    void
    g2p(const NodalFields<dim> &nodes);

    /// Stage 4m: the membrane nodes' momenta added to the nodal momenta of
    /// the remap (Eq. 20; Stages::remap calls it).
    void
    remap(NodalFields<dim> &nodes) const;

    /// Stage 6m: x_a += dt sum_i N_i(x_a) v_i. Returns the largest
    /// displacement over the cell's smallest altitude.
    double
    update_positions(const NodalFields<dim> &nodes, const double dt);

    /// Stage 7m: the slip (if the membrane slips along its fill:
    /// MembraneSlip::equalize_stretch at degree 1,
    /// MembraneSlip::relax_tangential_forces at degree 2), splits of cables
    /// longer than the split length, the nodes' cells, and the element
    /// forces from the new positions. Returns the number of nodes outside
    /// the mesh (their cell is unchanged).
    unsigned int
    relocate();

    /// The transfer weights of each membrane node to the nodes of its cell
    /// (barycentric coordinates), as of the last p2g().
    const std::vector<std::array<double, dim + 1>> &
    get_weights() const
    {
      return weights;
    }

    /// Restores the weights (a checkpoint).
    void
    set_weights(const std::vector<std::array<double, dim + 1>> &w)
    {
      weights = w;
    }

    double
    get_split_length() const
    {
      return split_length;
    }

  private:
    const BackgroundGrid<dim> &grid;
    Membrane<dim>             &membrane;
    const double               split_length;

    std::vector<std::array<double, dim + 1>> weights;

    /// Each node's cell in this grid (on a window, invalid where the window
    /// lacks it; its weights are then 0), as of the last p2g().
    std::vector<unsigned int> cell_here;

    const DomainPartition<dim> *partition = nullptr;

    /// MPI: the value of @p f(a) for every membrane node a, computed by the
    /// owner of the node's cell and summed over the processes (-0
    /// elsewhere). Serial: f(a) for every node.
    template <typename Function>
    std::vector<Tensor<1, dim>>
    from_cell_owners(const Function &f) const;

    /// relocate() on windows of the grid: every node's cell as the whole
    /// grid's location would find it (PointLocator::locate(): the walk
    /// from the old cell, else the search of all cells), by the walks and
    /// searches of all processes, combined in two all-reductions. Returns
    /// the number of nodes outside the mesh (their cell is unchanged).
    unsigned int
    locate_on_windows();

    /// sum_i N_i(x_a) v_i over the nodes of node a's cell, with the
    /// transfer weights.
    Tensor<1, dim>
    grid_velocity(const NodalFields<dim> &nodes, const unsigned int a) const;

    /// Scratch of time_step(), kept between steps: the grid nodes the
    /// membrane touches (sorted), and at each the membrane's projected
    /// stiffness D_i and the points' row sum.
    std::vector<unsigned int>            touched;
    std::vector<SymmetricTensor<2, dim>> touched_stiffness;
    std::vector<double>                  touched_points;
    /// time_step()'s scratch: the nodal masses with the window's rim made
    /// exact (MPI), and each element's size sum_j |G_j|^2 / m_j.
    std::vector<double> rim_mass;
    std::vector<double> element_weight;
    /// time_step()'s scratch per element: the grid nodes its nodes' cells
    /// reach, the grid gradient G_i at each, and how many there are.
    static constexpr unsigned int max_support = dim * (dim + 1);
    std::vector<std::array<unsigned int, max_support>>   support;
    std::vector<std::array<Tensor<1, dim>, max_support>> support_gradient;
    std::vector<unsigned int>                            n_support;
  };
} // namespace fsgmpm

#endif
