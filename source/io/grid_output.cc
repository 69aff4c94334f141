#include <deal.II/base/data_out_base.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/grid_output.h>

namespace fsgmpm
{
  template <int dim>
  void
  write_grid_vtu(const BackgroundGrid<dim> &grid,
                 const NodalFields<dim>    &nodes,
                 const std::string         &file_name)
  {
    // With several velocity fields: their total mass and centre-of-mass
    // velocity at each node of the mesh.
    const unsigned int          n = grid.n_base_nodes();
    std::vector<double>         mass(n, 0.);
    std::vector<Tensor<1, dim>> velocity(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        Tensor<1, dim> momentum;
        for (unsigned int j = i; j < grid.n_nodes(); j += n)
          {
            mass[i] += nodes.mass[j];
            momentum += nodes.mass[j] * nodes.velocity[j];
          }
        for (unsigned int d = 0; d < dim; ++d)
          velocity[i][d] = (grid.n_velocity_fields() == 1)
                             ? nodes.velocity[i][d]
                             : (mass[i] > 0 ? momentum[d] / mass[i] : 0.);
      }

    // One patch per cell, as DataOut builds them for a P1 simplex field
    // (deal.II 9.4 data_out.cc, build_one_patch): the cell's vertices, the
    // values at them (rows: the data, then the vertex coordinates, which a
    // simplex patch always carries), single precision. The grid keeps no
    // deal.II mesh to hand DataOut, and needs none for this.
    std::vector<DataOutBase::Patch<dim, dim>> patches(grid.n_base_cells());
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      {
        auto &patch                = patches[c];
        patch.reference_cell       = ReferenceCells::get_simplex<dim>();
        patch.n_subdivisions       = 1;
        patch.patch_index          = c;
        patch.points_are_available = true;
        patch.data.reinit(1 + dim + dim, dim + 1);
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int i = grid.cell_nodes[c][k];
            patch.vertices[k]    = grid.node_positions[i];
            patch.data(0, k)     = mass[i];
            for (unsigned int d = 0; d < dim; ++d)
              {
                patch.data(1 + d, k)       = velocity[i][d];
                patch.data(1 + dim + d, k) = grid.node_positions[i][d];
              }
          }
      }
    const std::vector<std::string> names
      = {"nodal_mass", "velocity_x", "velocity_y", "velocity_z"};
    const std::vector<std::string> data_names(names.begin(),
                                              names.begin() + 1 + dim);
    write_file_atomically(file_name, [&](std::ostream &out) {
      DataOutBase::write_vtu(
        patches, data_names, {}, DataOutBase::VtkFlags(), out);
    });
  }

  template void
  write_grid_vtu<2>(const BackgroundGrid<2> &,
                    const NodalFields<2> &,
                    const std::string &);
  template void
  write_grid_vtu<3>(const BackgroundGrid<3> &,
                    const NodalFields<3> &,
                    const std::string &);
} // namespace fsgmpm
