#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/scene/shape_factory.h>

#include <sstream>

// The built-in body shapes as ShapeFactory plug-ins: each declares its
// entries in the body's subsection and creates its BodyShape
// (particles/body_shape.h) from them; errors name the entries.

namespace fsgmpm
{
  namespace
  {
    template <int dim>
    Point<dim>
    parse_point(const std::string &text, const std::string &path)
    {
      return Point<dim>(parse_vector<dim>(text, path));
    }

    // Runs make(); a geometry error of the shape is rethrown naming the
    // entries that gave it (and @p got, the values, if given).
    template <typename Make>
    auto
    naming_entries(const std::string &entries,
                   const Make        &make,
                   const std::string &got = "")
    {
      try
        {
          auto shape        = make();
          shape->parameters = entries;
          return shape;
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          AssertThrow(false,
                      ExcMessage(entries + ": " + Utilities::trim(info.str())
                                 + got));
        }
      return decltype(make())();
    }

    template <int dim>
    std::unique_ptr<BodyShape<dim>>
    make_box(const Point<dim>  &lower,
             const Point<dim>  &upper,
             const std::string &entries)
    {
      return naming_entries(
        entries,
        [&]() -> std::unique_ptr<BodyShape<dim>> {
          return std::make_unique<BoxShape<dim>>(lower, upper);
        },
        " Got [" + format(lower) + "] - [" + format(upper) + "].");
    }



    template <int dim>
    struct BoxInput
    {
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Box lower corner",
                          "0.3, 0.2",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Shape = box: lower corner (dim coordinates, m).");
        prm.declare_entry("Box upper corner",
                          "0.7, 0.4",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Shape = box: upper corner (dim coordinates, m).");
      }

      static std::unique_ptr<BodyShape<dim>>
      create(ParameterHandler &prm, const std::string &path)
      {
        return make_box(parse_point<dim>(prm.get("Box lower corner"),
                                         path + "/Box lower corner"),
                        parse_point<dim>(prm.get("Box upper corner"),
                                         path + "/Box upper corner"),
                        path + "/Box lower corner and Box upper corner");
      }
    };



    template <int dim>
    struct ColumnInput
    {
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Column base corner",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Shape = column: lower corner (m); in 3D the depth "
                          "is that of Box lower/upper corner.");
        prm.declare_entry("Column width",
                          "0.2",
                          RealInterval::above(0),
                          "Shape = column: width L0 in x (m, > 0).");
        prm.declare_entry("Column aspect ratio",
                          "1",
                          RealInterval::above(0),
                          "Shape = column: a = H0/L0 (> 0).");
      }

      static std::unique_ptr<BodyShape<dim>>
      create(ParameterHandler &prm, const std::string &path)
      {
        const Point<dim> base  = parse_point<dim>(prm.get("Column base corner"),
                                                 path + "/Column base corner");
        const double     width = prm.get_double("Column width");
        const double     a     = prm.get_double("Column aspect ratio");
        AssertThrow(width > 0 && a > 0,
                    ExcMessage(path
                               + ": Column width and Column aspect ratio "
                                 "must be positive."));
        Point<dim> upper = base;
        upper[0] += width;
        upper[1] += a * width;
        if (dim == 3)
          upper[2] = parse_point<dim>(prm.get("Box upper corner"),
                                      path + "/Box upper corner")[2];
        return make_box(base,
                        upper,
                        path
                          + "/Column base corner, Column width and Column "
                            "aspect ratio");
      }
    };



    template <int dim>
    struct EllipseInput
    {
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Ellipse center",
                          "0.5, 0.5",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Shape = ellipse: centre (m).");
        prm.declare_entry("Ellipse semi-axes",
                          "0.1, 0.1",
                          Patterns::List(Patterns::Double(0), 2, 3),
                          "Shape = ellipse: semi-axes along x, y (, z) (m).");
      }

      static std::unique_ptr<BodyShape<dim>>
      create(ParameterHandler &prm, const std::string &path)
      {
        auto shape = std::make_unique<EllipseShape<dim>>(
          parse_point<dim>(prm.get("Ellipse center"), path + "/Ellipse center"),
          parse_vector<dim>(prm.get("Ellipse semi-axes"),
                            path + "/Ellipse semi-axes"));
        shape->parameters = path + "/Ellipse center and Ellipse semi-axes";
        return shape;
      }
    };



    template <int dim>
    struct PolygonInput
    {
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Polygon vertices",
                          "",
                          Patterns::Anything(),
                          "Shape = polygon: closed simple polygon as "
                          "'x0, y0; x1, y1; ...' (m), 2D only.");
      }

      static std::unique_ptr<BodyShape<dim>>
      create(ParameterHandler &prm, const std::string &path)
      {
        AssertThrow(dim == 2,
                    ExcMessage(path
                               + "/Shape = polygon is only available in "
                                 "2D."));
        const auto vertices = parse_polygon(prm.get("Polygon vertices"),
                                            path + "/Polygon vertices");
        if constexpr (dim == 2)
          return naming_entries(path + "/Polygon vertices",
                                [&]() -> std::unique_ptr<BodyShape<2>> {
                                  return std::make_unique<PolygonShape>(
                                    vertices);
                                });
        return nullptr;
      }
    };
  } // namespace

  FSGMPM_REGISTER_SHAPE(BoxInput, "box", "a box given by its corners")
  FSGMPM_REGISTER_SHAPE(ColumnInput,
                        "column",
                        "a box given by its base corner, width and aspect "
                        "ratio")
  FSGMPM_REGISTER_SHAPE(EllipseInput, "ellipse", "an ellipse (ellipsoid in 3D)")
  FSGMPM_REGISTER_SHAPE(PolygonInput,
                        "polygon",
                        "a simple closed polygon (2D only)")
} // namespace fsgmpm
