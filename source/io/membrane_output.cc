#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/xdmf_series.h>
#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace fsgmpm
{
  namespace
  {
    /// Length ratio (2D) or the square root of the area ratio (3D) of
    /// element @p e to its rest size.
    template <int dim>
    double
    element_stretch(const Membrane<dim> &membrane, const unsigned int e)
    {
      const double ratio = membrane.element_size(e) / membrane.rest_size[e];
      return dim == 2 ? ratio : std::sqrt(ratio);
    }

    template <int dim>
    std::vector<double>
    padded(const std::vector<Tensor<1, dim>> &values)
    {
      std::vector<double> out;
      out.reserve(3 * values.size());
      for (const auto &v : values)
        for (unsigned int d = 0; d < 3; ++d)
          out.push_back(d < dim ? v[d] : 0.);
      return out;
    }
  } // namespace



  template <int dim>
  void
  write_membrane_xdmf(const Membrane<dim> &membrane,
                      XdmfSeries          &series,
                      const double         time)
  {
    std::vector<unsigned int> cells;
    for (const auto &el : membrane.elements)
      cells.insert(cells.end(), el.begin(), el.end());
    std::vector<double> stretch(membrane.n_elements());
    for (unsigned int e = 0; e < membrane.n_elements(); ++e)
      stretch[e] = element_stretch(membrane, e);
    std::vector<Tensor<1, dim>> positions(membrane.position.begin(),
                                          membrane.position.end());
    series.write(time,
                 padded(positions),
                 dim == 2 ? XdmfSeries::CellType::line
                          : XdmfSeries::CellType::triangle,
                 cells,
                 {{"tension", 1, true, membrane.tension},
                  {"stretch", 1, true, stretch},
                  {"velocity", 3, false, padded(membrane.velocity)}});
  }



  template <int dim>
  void
  write_membrane_vtu(const Membrane<dim> &membrane, const std::string &file)
  {
    write_file_atomically(file, [&](std::ostream &out) {
      const unsigned int nn = membrane.n_nodes(), ne = membrane.n_elements();
      out << std::setprecision(10);
      out
        << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << ne
        << "\">\n<Points>\n<DataArray type=\"Float64\" "
           "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &p : membrane.position)
        out << p[0] << ' ' << p[1] << ' ' << (dim == 3 ? p[dim - 1] : 0.)
            << '\n';
      out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
             "Name=\"connectivity\" format=\"ascii\">\n";
      for (const auto &el : membrane.elements)
        {
          for (const unsigned int a : el)
            out << a << ' ';
          out << '\n';
        }
      out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
             "format=\"ascii\">\n";
      for (unsigned int e = 1; e <= ne; ++e)
        out << e * dim << '\n';
      out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
      for (unsigned int e = 0; e < ne; ++e)
        out << (dim == 2 ? 3 : 5) << '\n'; // VTK_LINE, VTK_TRIANGLE
      out << "</DataArray>\n</Cells>\n<CellData Scalars=\"tension\">\n"
          << "<DataArray type=\"Float64\" Name=\"tension\" "
             "format=\"ascii\">\n";
      for (const double t : membrane.tension)
        out << t << '\n';
      out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"stretch\" "
             "format=\"ascii\">\n";
      for (unsigned int e = 0; e < ne; ++e)
        out << element_stretch(membrane, e) << '\n';
      out << "</DataArray>\n</CellData>\n<PointData Vectors=\"velocity\">\n"
          << "<DataArray type=\"Float64\" Name=\"velocity\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &v : membrane.velocity)
        out << v[0] << ' ' << v[1] << ' ' << (dim == 3 ? v[dim - 1] : 0.)
            << '\n';
      out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
             "</VTKFile>\n";
    });
  }



  template <int dim>
  void
  write_membrane_shape_csv(const Membrane<dim> &membrane,
                           const std::string   &file)
  {
    write_file_atomically(file, [&](std::ostream &out) {
      out << (dim == 2 ? "x,y\n" : "x,y,z\n") << std::setprecision(17);
      for (const auto &p : membrane.ordered_nodes())
        {
          for (unsigned int d = 0; d < dim; ++d)
            out << (d ? "," : "") << p[d];
          out << '\n';
        }
    });
  }



  const std::vector<std::string> &
  membrane_monitor_names()
  {
    static const std::vector<std::string> names = {"height",
                                                   "width",
                                                   "contact_width",
                                                   "max_tension",
                                                   "mean_tension",
                                                   "top_pressure",
                                                   "bottom_pressure",
                                                   "membrane_length",
                                                   "enclosed_area",
                                                   "fluid_volume",
                                                   "particles_outside"};
    return names;
  }



  template <int dim>
  std::map<std::string, double>
  membrane_monitors(const Membrane<dim>      &membrane,
                    const ParticleStore<dim> &particles,
                    const double              contact_tolerance,
                    const double              strip_width,
                    const unsigned int        fill_body)
  {
    constexpr double big = std::numeric_limits<double>::max();
    double           x0 = big, x1 = -big, y0 = big, y1 = -big;
    for (const auto &p : membrane.position)
      {
        x0 = std::min(x0, p[0]);
        x1 = std::max(x1, p[0]);
        y0 = std::min(y0, p[1]);
        y1 = std::max(y1, p[1]);
      }
    double c0 = big, c1 = -big;
    for (const auto &p : membrane.position)
      if (p[1] <= y0 + contact_tolerance)
        {
          c0 = std::min(c0, p[0]);
          c1 = std::max(c1, p[0]);
        }

    double max_t = 0, tl = 0, l = 0;
    for (unsigned int e = 0; e < membrane.n_elements(); ++e)
      {
        const double s = membrane.element_size(e);
        max_t          = std::max(max_t, membrane.tension[e]);
        tl += membrane.tension[e] * s;
        l += s;
      }

    // Least-squares p = p0 + p1 (y - y_mean) over the central strip.
    const double xc = 0.5 * (x0 + x1);
    double       n = 0, sy = 0, sp = 0, syy = 0, syp = 0, volume = 0;
    for (unsigned int q = 0; q < particles.size(); ++q)
      {
        if (particles.body_id[q] != fill_body)
          continue;
        volume += particles.volume[q];
        if (std::abs(particles.position[q][0] - xc) > 0.5 * strip_width)
          continue;
        const double y = particles.position[q][1];
        const double p = -trace(particles.stress[q]) / 3.;
        n += 1;
        sy += y;
        sp += p;
        syy += y * y;
        syp += y * p;
      }
    double p_top = 0, p_bottom = 0;
    if (n >= 2)
      {
        const double ym = sy / n, pm = sp / n;
        const double var   = syy / n - ym * ym;
        const double slope = var > 0 ? (syp / n - ym * pm) / var : 0.;
        p_top              = pm + slope * (y1 - ym);
        p_bottom           = pm + slope * (y0 - ym);
      }

    // Extruded 3D membrane: length and area per ring (their mean) and the
    // fluid volume per unit thickness, comparable with the 2D scene.
    double length = membrane.total_size(), area = membrane.enclosed_area();
    if (dim == 3 && !membrane.rings.empty())
      {
        double z0 = big, z1 = -big;
        for (const auto &p : membrane.position)
          {
            z0 = std::min(z0, p[dim - 1]);
            z1 = std::max(z1, p[dim - 1]);
          }
        length = area = 0;
        for (const auto &ring : membrane.rings)
          {
            length += membrane.loop_length(ring) / membrane.rings.size();
            area += membrane.loop_area(ring) / membrane.rings.size();
          }
        if (z1 > z0)
          volume /= z1 - z0;
      }

    // Points outside the closed membrane (even-odd rule in x-y; 3D: the
    // first ring of an extruded membrane): fluid that leaked between
    // membrane nodes.
    double outside = 0;
    if (dim == 2 || !membrane.rings.empty())
      {
        std::vector<Point<2>> poly;
        for (const auto &x : membrane.ordered_nodes())
          poly.emplace_back(x[0], x[1]);
        for (unsigned int q = 0; q < particles.size(); ++q)
          if (particles.body_id[q] == fill_body)
            outside += !inside_polygon(poly,
                                       Point<2>(particles.position[q][0],
                                                particles.position[q][1]));
      }

    return {{"particles_outside", outside},
            {"height", y1 - y0},
            {"width", x1 - x0},
            {"contact_width", c1 - c0},
            {"max_tension", max_t},
            {"mean_tension", l > 0 ? tl / l : 0.},
            {"top_pressure", p_top},
            {"bottom_pressure", p_bottom},
            {"membrane_length", length},
            {"enclosed_area", area},
            {"fluid_volume", volume}};
  }

#define FSGMPM_INSTANTIATE(dim)                                      \
  template void write_membrane_vtu<dim>(const Membrane<dim> &,       \
                                        const std::string &);        \
  template void write_membrane_xdmf<dim>(const Membrane<dim> &,      \
                                         XdmfSeries &,               \
                                         const double);              \
  template void write_membrane_shape_csv<dim>(const Membrane<dim> &, \
                                              const std::string &);  \
  template std::map<std::string, double> membrane_monitors<dim>(     \
    const Membrane<dim> &,                                           \
    const ParticleStore<dim> &,                                      \
    const double,                                                    \
    const double,                                                    \
    const unsigned int);
  FSGMPM_INSTANTIATE(2)
  FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
} // namespace fsgmpm
