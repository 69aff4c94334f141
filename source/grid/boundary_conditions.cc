#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/grid/boundary_conditions.h>

#include <sstream>

namespace fsgmpm
{
  std::map<types::boundary_id, WallCondition>
  parse_wall_conditions(const std::string &text, const std::string &path)
  {
    std::map<types::boundary_id, WallCondition> walls;
    const std::string                           help
      = " Expected a comma-separated list of 'id: type' with type one of "
        "free, fixed (no slip), roller (bilateral: no motion through or away "
        "from the wall), slip (unilateral, frictionless: material may leave "
        "the wall) or 'friction <mu>' (unilateral Coulomb contact, mu >= 0), "
        "e.g. '0: slip, 1: roller, 2: friction 0.5'.";
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage(path + ": cannot read <" + item + ">." + help));
        int id = -1;
        try
          {
            id = Utilities::string_to_int(parts[0]);
          }
        catch (...)
          {}
        AssertThrow(id >= 0 && id < 255,
                    ExcMessage(path + ": <" + parts[0]
                               + "> is not a boundary id (0..254)." + help));
        std::istringstream in(parts[1]);
        std::string        type;
        in >> type;
        WallCondition w;
        if (type == "free")
          w.type = WallType::free;
        else if (type == "fixed")
          w.type = WallType::fixed;
        else if (type == "roller")
          w.type = WallType::roller;
        else if (type == "slip")
          w.type = WallType::slip; // friction stays 0
        else if (type == "friction")
          {
            w.type = WallType::friction;
            AssertThrow(in >> w.friction && w.friction >= 0,
                        ExcMessage(path + ": 'friction' for boundary id "
                                   + parts[0] + " needs a coefficient mu >= 0."
                                   + help));
          }
        else
          AssertThrow(false,
                      ExcMessage(path + ": unknown wall type <" + type + ">."
                                 + help));
        std::string rest;
        AssertThrow(!(in >> rest),
                    ExcMessage(path + ": unexpected <" + rest + "> in <" + item
                               + ">."
                               + (w.type == WallType::slip
                                    ? " 'slip' takes no coefficient; for "
                                      "Coulomb friction use 'friction <mu>'."
                                    : "")
                               + help));
        AssertThrow(walls.count(id) == 0,
                    ExcMessage(path + ": boundary id " + parts[0]
                               + " is given twice."));
        walls[id] = w;
      }
    return walls;
  }



  template <int dim>
  NodalConstraints<dim>::NodalConstraints(
    const BackgroundGrid<dim>                         &grid,
    const std::map<types::boundary_id, WallCondition> &walls,
    const MovingWallParameters                        &moving_wall_parameters)
  {
    for (const auto &[id, w] : walls)
      any_unilateral_wall = any_unilateral_wall || w.type == WallType::slip
                            || w.type == WallType::friction;
    if (moving_wall_parameters.enabled)
      moving_wall
        = std::make_unique<MovingWall<dim>>(moving_wall_parameters, grid);

    // Accumulate, per node and boundary id, the sum of outward face normals.
    std::vector<std::map<types::boundary_id, Tensor<1, dim>>> node_walls(
      grid.n_nodes());
    for (const auto &[c, k, id] : grid.boundary_faces)
      {
        const auto w = walls.find(id);
        if (w == walls.end() || w->second.type == WallType::free)
          continue;
        // Outward normal of the face opposite vertex k.
        const Tensor<1, dim> g = grid.shape_gradients(c)[k];
        const Tensor<1, dim> n = -g / g.norm();
        for (unsigned int v = 0; v < dim + 1; ++v)
          if (v != k)
            node_walls[grid.cell_nodes[c][v]][id] += n;
      }

    node_to_entry.assign(grid.n_nodes(), BackgroundGrid<dim>::invalid);
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      {
        if (node_walls[i].empty())
          continue;
        Entry e;
        for (const auto &[id, normal_sum] : node_walls[i])
          {
            const WallCondition &w = walls.at(id);
            if (w.type == WallType::fixed)
              {
                e.fixed = true;
                break;
              }
            // Gram-Schmidt against the walls already at this node.
            Tensor<1, dim> n = normal_sum / normal_sum.norm();
            for (unsigned int k = 0; k < e.n_walls; ++k)
              n -= (n * e.normal[k]) * e.normal[k];
            const double len = n.norm();
            if (len < 1e-8)
              continue;
            if (e.n_walls == dim)
              break;
            e.normal[e.n_walls]   = n / len;
            e.type[e.n_walls]     = w.type;
            e.friction[e.n_walls] = w.friction;
            ++e.n_walls;
          }
        // A node held in every direction by bilateral walls is fixed.
        if (e.n_walls == dim)
          {
            bool all_roller = true;
            for (unsigned int k = 0; k < dim; ++k)
              all_roller = all_roller && (e.type[k] == WallType::roller);
            e.fixed = e.fixed || all_roller;
          }
        node_to_entry[i] = entries.size();
        entries.push_back(e);
      }

    // The moving wall is applied before the static walls at a node; that
    // is a projection only if their normals are orthogonal or parallel.
    if (moving_wall)
      for (const unsigned int i : moving_wall->nodes_in_plane())
        if (node_to_entry[i] != BackgroundGrid<dim>::invalid)
          {
            const Entry &e = entries[node_to_entry[i]];
            for (unsigned int k = 0; k < (e.fixed ? 0 : e.n_walls); ++k)
              {
                const double c
                  = std::abs(e.normal[k] * moving_wall->outward_normal());
                AssertThrow(c < 1e-8 || c > 1 - 1e-8,
                            ExcMessage(
                              "Moving wall: the wall meets a wall of "
                              "Grid/Boundary conditions at an angle (at the "
                              "grid node at "
                              + format(grid.node_positions[i])
                              + "); only walls at right angles to it or "
                                "parallel to it are supported."));
              }
          }
  }

  template class NodalConstraints<2>;
  template class NodalConstraints<3>;
} // namespace fsgmpm
