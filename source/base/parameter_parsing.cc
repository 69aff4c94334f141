#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/parameter_parsing.h>

#include <cmath>
#include <sstream>

namespace fsgmpm
{
  template <int dim>
  Tensor<1, dim>
  parse_vector(const std::string &text, const std::string &path)
  {
    const auto     items = Utilities::split_string_list(text, ',');
    Tensor<1, dim> v;
    // A two-entry value is accepted in 3D with z = 0: y is vertical in 2D
    // and 3D alike, so 2D vectors such as gravity carry over unchanged.
    AssertThrow(items.size() == dim || (dim == 3 && items.size() == 2),
                ExcMessage(path + " must have " + std::to_string(dim)
                           + " comma-separated numbers; got <" + text + ">."));
    for (unsigned int d = 0; d < items.size(); ++d)
      {
        try
          {
            v[d] = Utilities::string_to_double(items[d]);
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage(path + ": <" + items[d]
                                   + "> is not a number."));
          }
        AssertThrow(std::isfinite(v[d]),
                    ExcMessage(path + ": <" + items[d]
                               + "> is not a finite number."));
      }
    return v;
  }



  double
  parse_auto_or_double(const std::string &text,
                       const double       fallback,
                       const std::string &path)
  {
    const std::string t = Utilities::trim(text);
    if (t == "auto")
      return fallback;
    std::istringstream in(t);
    double             x = 0;
    in >> x;
    AssertThrow(!in.fail() && in.eof() && std::isfinite(x)
                  && std::abs(x) <= 1e9,
                ExcMessage(path
                           + " must be auto or a finite number (m, within "
                             "+-1e9); got <"
                           + text + ">."));
    return x;
  }



  unsigned int
  get_dimension(ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    const unsigned int d = prm.get_integer("Dimension");
    prm.leave_subsection();
    return d;
  }



  std::vector<Point<2>>
  parse_polygon(const std::string &text, const std::string &path)
  {
    std::vector<Point<2>> vertices;
    for (const auto &item : Utilities::split_string_list(text, ';'))
      vertices.emplace_back(parse_vector<2>(item, path));
    AssertThrow(vertices.size() >= 3,
                ExcMessage(path
                           + " needs at least three vertices "
                             "'x0, y0; x1, y1; x2, y2'."));
    return vertices;
  }

  template Tensor<1, 2>
  parse_vector<2>(const std::string &, const std::string &);
  template Tensor<1, 3>
  parse_vector<3>(const std::string &, const std::string &);
} // namespace fsgmpm
