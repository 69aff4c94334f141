#include <deal.II/base/data_out_base.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/particle_output.h>
#include <fsgmpm/io/vtu_arrays.h>
#include <fsgmpm/step/stages.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace fsgmpm
{

  template <int dim>
  typename ParticleOutput<dim>::NodalPointFields
  ParticleOutput<dim>::nodal_point_fields(const BackgroundGrid<dim> &grid,
                                          const NodalFields<dim>    &nodes,
                                          const ParticleStore<dim>  &particles,
                                          const unsigned int         p)
  {
    // Linear simplex: grad v = sum_i v_i (x) grad N_i is constant in the
    // cell; omega_z = dv_y/dx - dv_x/dy.
    const unsigned int      c        = particles.cell[p];
    const CellGeometry<dim> geometry = grid.geometry(c);
    const auto              grad     = geometry.shape_gradients();
    double                  omega    = 0;
    for (unsigned int k = 0; k < dim + 1; ++k)
      {
        const auto &v = nodes.velocity[grid.cell_nodes[c][k]];
        const auto &g = grad[k];
        omega += v[1] * g[0] - v[0] * g[1];
      }
    const auto &s              = particles.stress[p];
    double      in_plane_trace = 0;
    for (unsigned int d = 0; d < dim; ++d)
      in_plane_trace += s[d][d];
    double         projected = -in_plane_trace / dim;
    Tensor<2, dim> s_projected;
    if (Stages::projected_stress(grid,
                                 nodes,
                                 c,
                                 geometry.barycentric(particles.position[p]),
                                 s_projected))
      projected = -trace(s_projected) / dim;
    return {{omega, projected}};
  }



  template <int dim>
  void
  ParticleOutput<dim>::build_patches(const ParticleStore<dim>  &particles,
                                     const BackgroundGrid<dim> *grid,
                                     const NodalFields<dim>    *nodes)
  {
    const unsigned int n = particles.size();
    positions.assign(3 * n, 0.);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int d = 0; d < dim; ++d)
        positions[3 * p + d] = particles.position[p][d];

    fields.clear();
    const auto add = [&](const std::string &name,
                         const unsigned int n_components,
                         const bool         integer,
                         const auto        &value_of) {
      Field field{name, n_components, integer, {}};
      field.values.resize(std::size_t(n_components) * n);
      for (unsigned int p = 0; p < n; ++p)
        value_of(p, &field.values[std::size_t(n_components) * p]);
      fields.push_back(std::move(field));
    };
    const auto vector = [&](const std::string &name, const auto &value_of) {
      add(name, 3, false, [&](const unsigned int p, double *out) {
        const Tensor<1, dim> v = value_of(p);
        for (unsigned int d = 0; d < dim; ++d)
          out[d] = v[d];
        for (unsigned int d = dim; d < 3; ++d)
          out[d] = 0;
      });
    };
    const auto scalar
      = [&](const std::string &name, const bool integer, const auto &value_of) {
          add(name, 1, integer, [&](const unsigned int p, double *out) {
            out[0] = value_of(p);
          });
        };

    vector("velocity",
           [&](const unsigned int p) { return particles.velocity[p]; });
    // The whole 3 x 3 stress (plane strain's sigma_zz included), row by
    // row, as VTK reads a tensor.
    add("stress", 9, false, [&](const unsigned int p, double *out) {
      const auto &s = particles.stress[p];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          out[3 * i + j] = s[i][j];
    });
    scalar("pressure", false, [&](const unsigned int p) {
      return -trace(particles.stress[p]) / 3.;
    });
    scalar("mass", false, [&](const unsigned int p) {
      return particles.mass[p];
    });
    scalar("volume", false, [&](const unsigned int p) {
      return particles.volume[p];
    });
    scalar("material_id", true, [&](const unsigned int p) {
      return particles.material_id[p];
    });
    scalar("body_id", true, [&](const unsigned int p) {
      return particles.body_id[p];
    });
    scalar("free_surface", true, [&](const unsigned int p) {
      return particles.free_surface[p];
    });
    std::vector<NodalPointFields> nodal(n);
    for (unsigned int p = 0; p < n; ++p)
      if (grid != nullptr && nodes != nullptr)
        nodal[p] = nodal_point_fields(*grid, *nodes, particles, p);
      else
        {
          double in_plane_trace = 0;
          for (unsigned int d = 0; d < dim; ++d)
            in_plane_trace += particles.stress[p][d][d];
          nodal[p] = {{0., -in_plane_trace / dim}};
        }
    scalar("vorticity", false, [&](const unsigned int p) {
      return nodal[p][0];
    });
    scalar("projected_pressure", false, [&](const unsigned int p) {
      return nodal[p][1];
    });
    // q = sqrt(3 J2) of the whole (3 x 3, plane strain's sigma_zz
    // included) stress: the soil's deviator stress.
    scalar("von_mises", false, [&](const unsigned int p) {
      const auto                 &s = particles.stress[p];
      const SymmetricTensor<2, 3> deviator
        = s - trace(s) / 3. * unit_symmetric_tensor<3>();
      return std::sqrt(1.5 * (deviator * deviator));
    });
    if (particles.has_plasticity())
      {
        scalar("plastic_strain", false, [&](const unsigned int p) {
          return particles.plastic_strain[p];
        });
        scalar("yielding", true, [&](const unsigned int p) {
          return particles.yielding[p];
        });
      }
    if (particles.has_initial_position())
      vector("displacement", [&](const unsigned int p) {
        return particles.position[p] - particles.initial_position[p];
      });
  }



  namespace
  {
    /// The type="..." Name="..." [NumberOfComponents="..."] attributes of
    /// a field's DataArray.
    template <typename FieldType>
    std::string
    array_attributes(const FieldType &field)
    {
      std::string a = std::string("type=\"")
                      + (field.integer ? "Int32" : "Float32") + "\" Name=\""
                      + field.name + "\"";
      if (field.n_components > 1)
        a += " NumberOfComponents=\"" + std::to_string(field.n_components)
             + "\"";
      return a;
    }

    /// The PointData element's attributes naming the active arrays.
    std::string
    active_arrays()
    {
      return "Scalars=\"pressure\" Vectors=\"velocity\" "
             "Tensors=\"stress\"";
    }
  } // namespace



  template <int dim>
  void
  ParticleOutput<dim>::write_vtu(std::ostream &out) const
  {
    const unsigned int n = positions.size() / 3;
    write_vtu_header(out, n, n);
    write_vtu_binary_array(out,
                           "type=\"Float32\" NumberOfComponents=\"3\"",
                           std::vector<float>(positions.begin(),
                                              positions.end()));
    out << "</Points>\n<Cells>\n";
    // One vertex cell (VTK_VERTEX) per point.
    std::vector<std::int32_t> connectivity(n), offsets(n);
    for (unsigned int p = 0; p < n; ++p)
      {
        connectivity[p] = p;
        offsets[p]      = p + 1;
      }
    write_vtu_binary_array(out,
                           "type=\"Int32\" Name=\"connectivity\"",
                           connectivity);
    write_vtu_binary_array(out, "type=\"Int32\" Name=\"offsets\"", offsets);
    write_vtu_binary_array(out,
                           "type=\"UInt8\" Name=\"types\"",
                           std::vector<std::uint8_t>(n, 1));
    out << "</Cells>\n<PointData " << active_arrays() << ">\n";
    for (const auto &field : fields)
      if (field.integer)
        write_vtu_binary_array(out,
                               array_attributes(field),
                               std::vector<std::int32_t>(field.values.begin(),
                                                         field.values.end()));
      else
        write_vtu_binary_array(out,
                               array_attributes(field),
                               std::vector<float>(field.values.begin(),
                                                  field.values.end()));
    out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  }



  template <int dim>
  void
  ParticleOutput<dim>::write_pvtu_record(
    std::ostream                   &out,
    const std::vector<std::string> &pieces) const
  {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\">\n"
           "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData "
        << active_arrays() << ">\n";
    for (const auto &field : fields)
      out << "<PDataArray " << array_attributes(field) << "/>\n";
    out << "</PPointData>\n<PPoints>\n<PDataArray type=\"Float32\" "
           "NumberOfComponents=\"3\"/>\n</PPoints>\n";
    for (const auto &piece : pieces)
      out << "<Piece Source=\"" << piece << "\"/>\n";
    out << "</PUnstructuredGrid>\n</VTKFile>\n";
  }



  template <int dim>
  void
  ParticleOutput<dim>::write_xdmf(XdmfSeries &series, const double time) const
  {
    std::vector<XdmfSeries::Field> xdmf_fields;
    for (const auto &field : fields)
      xdmf_fields.push_back(
        {field.name, field.n_components, false, field.values});
    series.write(
      time, positions, XdmfSeries::CellType::vertex, {}, xdmf_fields);
  }



  PvdSeries::PvdSeries(const std::string &directory,
                       const std::string &base_name,
                       const std::string &extension)
    : directory(directory)
    , base_name(base_name)
    , extension(extension)
  {}

  std::string
  PvdSeries::next_file(const double time)
  {
    std::ostringstream name;
    name << base_name << "_" << std::setw(5) << std::setfill('0')
         << records.size() << extension;
    records.emplace_back(time, name.str());
    return name.str();
  }

  void
  PvdSeries::restore(const std::vector<double> &times)
  {
    records.clear();
    for (const double t : times)
      {
        std::string       name  = next_file(t);
        const std::string other = name.substr(0, name.rfind('.'))
                                  + (extension == ".vtu" ? ".pvtu" : ".vtu");
        if (!std::filesystem::exists(directory + "/" + name)
            && std::filesystem::exists(directory + "/" + other))
          records.back().second = other;
      }
  }

  void
  PvdSeries::write_pvd() const
  {
    write_file_atomically(directory + "/" + base_name + ".pvd",
                          [&](std::ostream &out) {
                            DataOutBase::write_pvd_record(out, records);
                          });
  }

  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace fsgmpm
