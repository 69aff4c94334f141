#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>

#include <deal.II/lac/vector.h>

#include <deal.II/numerics/data_out.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/membrane_fe_output.h>

#include <cmath>

namespace fsgmpm
{
  template <int dim>
  void
  write_membrane_fe_vtu(const Membrane<dim> &membrane, const std::string &file)
  {
    const MembraneFE<dim>          &fe     = membrane.get_fe();
    const DoFHandler<dim - 1, dim> &scalar = fe.get_dof_handler();
    const unsigned int              degree = fe.get_degree();

    // The vector-valued P_k of the membrane on the same triangulation: its
    // DoF (cell, base index b, component d) is component d of scalar DoF b
    // of that cell.
    const FESystem<dim - 1, dim> system(FE_SimplexP<dim - 1, dim>(degree), dim);
    DoFHandler<dim - 1, dim>     dof_handler(scalar.get_triangulation());
    dof_handler.distribute_dofs(system);
    Vector<double> position(dof_handler.n_dofs()),
      velocity(dof_handler.n_dofs()), displacement(dof_handler.n_dofs());
    const auto                          &rest = fe.rest_support_points();
    std::vector<types::global_dof_index> dofs(system.n_dofs_per_cell()),
      scalar_dofs(scalar.get_fe().n_dofs_per_cell());
    auto scalar_cell = scalar.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        scalar_cell->get_dof_indices(scalar_dofs);
        for (unsigned int j = 0; j < dofs.size(); ++j)
          {
            const auto [d, b]     = system.system_to_component_index(j);
            const unsigned int i  = scalar_dofs[b];
            const unsigned int a  = membrane.support_point_node(i);
            position[dofs[j]]     = membrane.position[a][d];
            velocity[dofs[j]]     = membrane.velocity[a][d];
            displacement[dofs[j]] = membrane.position[a][d] - rest[i][d];
          }
        ++scalar_cell;
      }

    // Per active cell: the principal stresses, evaluated here from the
    // current positions (so that the file never depends on when forces were
    // last computed, e.g. right after a restart), and the stretch from the
    // cell's straight pieces (the cell itself at degree 1).
    const unsigned int n_cells = scalar.get_triangulation().n_active_cells();
    std::vector<Point<dim>> x(fe.n_support_points());
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = membrane.position[membrane.support_point_node(i)];
    std::vector<Tensor<1, dim>>          force;
    std::vector<std::array<double, 2>>   stress;
    std::vector<SymmetricTensor<2, dim>> tension_tensor;
    fe.internal_forces(x, force, &stress, &tension_tensor);
    Vector<double>      major(n_cells), minor(n_cells), stretch(n_cells);
    std::vector<double> size(n_cells, 0.), rest_size(n_cells, 0.);
    for (unsigned int e = 0; e < membrane.n_elements(); ++e)
      {
        const unsigned int c
          = membrane.active_cell_of(membrane.element_cell[e]);
        size[c] += membrane.element_size(e);
        rest_size[c] += membrane.rest_size[e];
      }
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        major[c]           = stress[c][0];
        minor[c]           = stress[c][1];
        const double ratio = size[c] / rest_size[c];
        stretch[c]         = dim == 2 ? ratio : std::sqrt(ratio);
      }

    // The cell-averaged tension tensor as a constant per cell (DG_0, dim x
    // dim components): DataOut writes cell data of one component only.
    const FESystem<dim - 1, dim> constant(FE_SimplexDGP<dim - 1, dim>(0),
                                          dim * dim);
    DoFHandler<dim - 1, dim>     tensor_dofs(scalar.get_triangulation());
    tensor_dofs.distribute_dofs(constant);
    Vector<double>                       tensor(tensor_dofs.n_dofs());
    std::vector<types::global_dof_index> tensor_cell_dofs(
      constant.n_dofs_per_cell());
    for (const auto &cell : tensor_dofs.active_cell_iterators())
      {
        cell->get_dof_indices(tensor_cell_dofs);
        for (unsigned int j = 0; j < tensor_cell_dofs.size(); ++j)
          {
            const unsigned int k = constant.system_to_component_index(j).first;
            tensor[tensor_cell_dofs[j]]
              = tension_tensor[cell->active_cell_index()][k / dim][k % dim];
          }
      }

    const MappingFEField<dim - 1, dim, Vector<double>> mapping(dof_handler,
                                                               position);
    DataOut<dim - 1, dim>                              data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(velocity,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim - 1, dim>::type_dof_data,
                             vector);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim - 1, dim>::type_dof_data,
                             vector);
    data_out.add_data_vector(major,
                             "tension",
                             DataOut<dim - 1, dim>::type_cell_data);
    data_out.add_data_vector(minor,
                             "minor_tension",
                             DataOut<dim - 1, dim>::type_cell_data);
    data_out.add_data_vector(stretch,
                             "stretch",
                             DataOut<dim - 1, dim>::type_cell_data);
    data_out.add_data_vector(
      tensor_dofs,
      tensor,
      std::vector<std::string>(dim * dim, "tension_tensor"),
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim * dim, DataComponentInterpretation::component_is_part_of_tensor));
    // Degree 2: one quadratic (Lagrange) VTK cell per FE cell, curved as
    // the element is.
    data_out.build_patches(mapping, degree);
    DataOutBase::VtkFlags flags;
    flags.write_higher_order_cells = degree > 1;
    data_out.set_flags(flags);
    write_file_atomically(file,
                          [&](std::ostream &out) { data_out.write_vtu(out); });
  }

  template void
  write_membrane_fe_vtu<2>(const Membrane<2> &, const std::string &);
  template void
  write_membrane_fe_vtu<3>(const Membrane<3> &, const std::string &);
} // namespace fsgmpm
