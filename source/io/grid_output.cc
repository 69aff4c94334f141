#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

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
    Vector<double>              mass(n);
    std::vector<Vector<double>> velocity(dim, Vector<double>(n));
    for (unsigned int i = 0; i < n; ++i)
      {
        Tensor<1, dim> momentum;
        for (unsigned int j = i; j < grid.n_nodes(); j += n)
          {
            mass[i] += nodes.mass[j];
            momentum += nodes.mass[j] * nodes.velocity[j];
          }
        for (unsigned int d = 0; d < dim; ++d)
          velocity[d][i] = (grid.n_velocity_fields() == 1)
                             ? nodes.velocity[i][d]
                             : (mass[i] > 0 ? momentum[d] / mass[i] : 0.);
      }
    DataOut<dim> data_out;
    data_out.attach_dof_handler(grid.get_dof_handler());
    data_out.add_data_vector(mass, "nodal_mass");
    const char *names[3] = {"velocity_x", "velocity_y", "velocity_z"};
    for (unsigned int d = 0; d < dim; ++d)
      data_out.add_data_vector(velocity[d], names[d]);
    const MappingFE<dim> mapping(grid.get_dof_handler().get_fe());
    data_out.build_patches(mapping);
    write_file_atomically(file_name,
                          [&](std::ostream &out) { data_out.write_vtu(out); });
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
