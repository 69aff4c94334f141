#ifndef fsgmpm_grid_boundary_conditions_h
#define fsgmpm_grid_boundary_conditions_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/moving_wall.h>
#include <fsgmpm/grid/wall_condition.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Velocity constraints of the nodes on walls. The outward normal of a wall
   * at a node is the normalised mean of the outward normals of the adjacent
   * boundary faces with the same boundary id; the normals of different walls
   * meeting at a node (corners) are orthogonalised.
   */
  template <int dim>
  class NodalConstraints
  {
  public:
    NodalConstraints(const BackgroundGrid<dim>                         &grid,
                     const std::map<types::boundary_id, WallCondition> &walls,
                     const MovingWallParameters &moving_wall_parameters = {});

    /// Move the moving wall (if any) to time @p t; call before each grid
    /// update with the time the updated velocity belongs to.
    void
    set_time(const double t)
    {
      if (moving_wall)
        moving_wall->set_time(t);
    }

    /// The moving wall, or nullptr.
    const MovingWall<dim> *
    get_moving_wall() const
    {
      return moving_wall.get();
    }

    /**
     * Apply the wall conditions, contact force included, to the velocity
     * v^{n+1} of the grid update: fixed walls stop the node, rollers remove
     * the normal component, slip and friction walls remove the component
     * into the wall and, for friction, reduce the tangential speed by
     * mu times that normal speed (Coulomb, down to rest). Returns what the
     * walls did, for apply_kinematic() in the remap: a bit per unilateral
     * wall that pushed the node, and one where static friction held it.
     */
    std::uint8_t
    apply(const unsigned int node, Tensor<1, dim> &v) const
    {
      return constrain(node, v, true, 0);
    }

    /**
     * Only the kinematic part of the wall conditions, for the remapped
     * velocity of Eq. (20): no penetration (and no separation from rollers,
     * no motion at fixed walls), but no friction. The friction impulse was
     * already given by apply() in the grid update and reached the points
     * through their accelerations; reducing the tangential velocity again
     * here would apply it twice to the positions and strain rates.
     * @p contact is what apply() returned for the node in the grid update:
     * a unilateral wall that held the node there holds its normal velocity
     * at zero here too, both ways (the remapped velocity may not leave the
     * wall in the step in which the wall pushed the node), and a node that
     * static friction held at rest stays at rest (a remapped velocity
     * sliding along the wall let a block below its friction angle creep
     * down the slope).
     */
    void
    apply_kinematic(const unsigned int node,
                    Tensor<1, dim>    &v,
                    const std::uint8_t contact = 0) const
    {
      if (contact & stuck_flag)
        v = Tensor<1, dim>();
      else
        constrain(node, v, false, contact);
    }

    /// Whether any wall is unilateral (slip or friction), whose contact the
    /// remap must remember (NodalFields::wall_contact).
    bool
    has_unilateral_walls() const
    {
      return any_unilateral_wall;
    }

    /// Remove the constrained components of a nodal vector (for the force
    /// criterion of Eq. (30), which excludes support reactions).
    void
    project_out(const unsigned int node, Tensor<1, dim> &f) const
    {
      if (moving_wall && moving_wall->is_active(node))
        {
          const Tensor<1, dim> &n = moving_wall->outward_normal();
          f -= (f * n) * n;
        }
      const unsigned int idx = node_to_entry[node];
      if (idx == BackgroundGrid<dim>::invalid)
        return;
      const Entry &e = entries[idx];
      if (e.fixed)
        {
          f = Tensor<1, dim>();
          return;
        }
      for (unsigned int k = 0; k < e.n_walls; ++k)
        f -= (f * e.normal[k]) * e.normal[k];
    }

    bool
    is_constrained(const unsigned int node) const
    {
      return node_to_entry[node] != BackgroundGrid<dim>::invalid
             || (moving_wall && moving_wall->is_active(node));
    }

  private:
    /// A bit of apply()'s result: static friction held the node at rest.
    static constexpr std::uint8_t stuck_flag = 0x80;

    /// apply() (with_friction) and apply_kinematic() (@p contact: what
    /// apply() returned). Returns bit k set where unilateral wall k pushed
    /// the node, and stuck_flag where a friction wall stopped it.
    std::uint8_t
    constrain(const unsigned int node,
              Tensor<1, dim>    &v,
              const bool         with_friction,
              const std::uint8_t contact) const
    {
      // The moving wall first: frictionless and unilateral, on the velocity
      // relative to the wall (a slip wall in the wall's frame).
      if (moving_wall && moving_wall->is_active(node))
        {
          const Tensor<1, dim> &n  = moving_wall->outward_normal();
          const double          vn = (v - moving_wall->current_velocity()) * n;
          if (vn > 0)
            v -= vn * n;
        }
      const unsigned int idx = node_to_entry[node];
      if (idx == BackgroundGrid<dim>::invalid)
        return 0;
      const Entry &e = entries[idx];
      if (e.fixed)
        {
          v = Tensor<1, dim>();
          return 0;
        }
      std::uint8_t state = 0;
      for (unsigned int k = 0; k < e.n_walls; ++k)
        {
          const double vn = v * e.normal[k];
          if (e.type[k] == WallType::roller || (contact & (1u << k)))
            v -= vn * e.normal[k];
          else if (vn > 0) // slip or friction wall: only when moving into it
            {
              state |= (1u << k);
              if (!with_friction)
                {
                  v -= vn * e.normal[k];
                  continue;
                }
              Tensor<1, dim> vt  = v - vn * e.normal[k];
              const double   vtn = vt.norm();
              const double   red = e.friction[k] * vn;
              if (vtn > red)
                v = vt * (1. - red / vtn);
              else
                {
                  v = Tensor<1, dim>();
                  state |= stuck_flag;
                }
            }
        }
      return state;
    }

    struct Entry
    {
      bool                            fixed   = false;
      unsigned int                    n_walls = 0;
      std::array<Tensor<1, dim>, dim> normal;
      std::array<WallType, dim>       type;
      std::array<double, dim>         friction;
    };
    std::vector<Entry>               entries;
    std::vector<unsigned int>        node_to_entry;
    std::unique_ptr<MovingWall<dim>> moving_wall;
    bool                             any_unilateral_wall = false;
  };
} // namespace fsgmpm

#endif
