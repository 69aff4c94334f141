#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/particle_output.h>
#include <fsgmpm/step/stages.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace fsgmpm
{
  namespace
  {
    // Field layout: velocity (dim), stress xx yy zz xy [xz yz], pressure,
    // mass, volume, material id, body id, free surface, vorticity,
    // projected pressure, von Mises stress, [plastic strain, yielding],
    // [displacement (dim)].
    constexpr unsigned int
    n_stress_components(const int dim)
    {
      return dim == 2 ? 4 : 6;
    }
  } // namespace

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
    with_displacement           = particles.has_initial_position();
    with_plasticity             = particles.has_plasticity();
    const unsigned int n_fields = dim + n_stress_components(dim) + 9
                                  + (with_plasticity ? 2 : 0)
                                  + (with_displacement ? dim : 0);
    patches.resize(particles.size());
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        auto &patch       = patches[p];
        patch.vertices[0] = particles.position[p];
        patch.patch_index = p;
        patch.data.reinit(n_fields, 1);
        unsigned int f = 0;
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(f++, 0) = particles.velocity[p][d];
        const auto &s      = particles.stress[p];
        patch.data(f++, 0) = s[0][0];
        patch.data(f++, 0) = s[1][1];
        patch.data(f++, 0) = s[2][2];
        patch.data(f++, 0) = s[0][1];
        if (dim == 3)
          {
            patch.data(f++, 0) = s[0][2];
            patch.data(f++, 0) = s[1][2];
          }
        patch.data(f++, 0)    = -trace(s) / 3.;
        patch.data(f++, 0)    = particles.mass[p];
        patch.data(f++, 0)    = particles.volume[p];
        patch.data(f++, 0)    = particles.material_id[p];
        patch.data(f++, 0)    = particles.body_id[p];
        patch.data(f++, 0)    = particles.free_surface[p];
        double in_plane_trace = 0;
        for (unsigned int d = 0; d < dim; ++d)
          in_plane_trace += s[d][d];
        NodalPointFields fields = {{0., -in_plane_trace / dim}};
        if (grid != nullptr && nodes != nullptr)
          fields = nodal_point_fields(*grid, *nodes, particles, p);
        patch.data(f++, 0) = fields[0];
        patch.data(f++, 0) = fields[1];
        // q = sqrt(3 J2) of the whole (3 x 3, plane strain's sigma_zz
        // included) stress: the soil's deviator stress.
        const SymmetricTensor<2, 3> deviator
          = s - trace(s) / 3. * unit_symmetric_tensor<3>();
        patch.data(f++, 0) = std::sqrt(1.5 * (deviator * deviator));
        if (with_plasticity)
          {
            patch.data(f++, 0) = particles.plastic_strain[p];
            patch.data(f++, 0) = particles.yielding[p];
          }
        if (with_displacement)
          for (unsigned int d = 0; d < dim; ++d)
            patch.data(f++, 0)
              = particles.position[p][d] - particles.initial_position[p][d];
      }
  }

  template <int dim>
  void
  ParticleOutput<dim>::write_xdmf(XdmfSeries &series, const double time) const
  {
    const unsigned int  n = patches.size();
    std::vector<double> positions(3 * n, 0.);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int d = 0; d < dim; ++d)
        positions[3 * p + d] = patches[p].vertices[0][d];
    const auto                     names = get_dataset_names();
    std::vector<XdmfSeries::Field> fields;
    // The vectors (velocity, displacement) as 3-vectors, the rest scalars.
    for (unsigned int f = 0; f < names.size();)
      if (f + 1 < names.size() && names[f + 1] == names[f])
        {
          fields.push_back(
            {names[f], 3, false, std::vector<double>(3 * n, 0.)});
          for (unsigned int p = 0; p < n; ++p)
            for (unsigned int d = 0; d < dim; ++d)
              fields.back().values[3 * p + d] = patches[p].data(f + d, 0);
          f += dim;
        }
      else
        {
          fields.push_back({names[f], 1, false, std::vector<double>(n)});
          for (unsigned int p = 0; p < n; ++p)
            fields.back().values[p] = patches[p].data(f, 0);
          ++f;
        }
    series.write(time, positions, XdmfSeries::CellType::vertex, {}, fields);
  }



  template <int dim>
  std::vector<std::string>
  ParticleOutput<dim>::get_dataset_names() const
  {
    std::vector<std::string> names(dim, "velocity");
    for (const auto &n : {"stress_xx", "stress_yy", "stress_zz", "stress_xy"})
      names.emplace_back(n);
    if (dim == 3)
      {
        names.emplace_back("stress_xz");
        names.emplace_back("stress_yz");
      }
    for (const auto &n : {"pressure",
                          "mass",
                          "volume",
                          "material_id",
                          "body_id",
                          "free_surface",
                          "vorticity",
                          "projected_pressure",
                          "von_mises"})
      names.emplace_back(n);
    if (with_plasticity)
      {
        names.emplace_back("plastic_strain");
        names.emplace_back("yielding");
      }
    if (with_displacement)
      names.resize(names.size() + dim, "displacement");
    return names;
  }

  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  ParticleOutput<dim>::get_nonscalar_data_ranges() const
  {
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges = {std::make_tuple(
        0u,
        dim - 1u,
        std::string("velocity"),
        DataComponentInterpretation::component_is_part_of_vector)};
    if (with_displacement)
      {
        const unsigned int first = get_dataset_names().size() - dim;
        ranges.emplace_back(
          first,
          first + dim - 1,
          std::string("displacement"),
          DataComponentInterpretation::component_is_part_of_vector);
      }
    return ranges;
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
