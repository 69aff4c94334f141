#ifndef fsgmpm_particles_body_shape_h
#define fsgmpm_particles_body_shape_h

#include <deal.II/base/point.h>

#include <fsgmpm/particles/polygon_inside.h>

#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * A region of space that a body initially fills: box, polygon (2D) or
   * ellipse/ellipsoid. Shapes know whether a point is inside and give a few
   * points on their outline that must lie inside the mesh.
   */
  template <int dim>
  class BodyShape
  {
  public:
    virtual ~BodyShape() = default;
    virtual bool
    inside(const Point<dim> &x) const = 0;
    /// Extreme points of the shape (corners, vertices, ends of the axes).
    virtual std::vector<Point<dim>>
    outline_points() const = 0;
    virtual std::string
    description() const = 0;

    /// The input parameters that define the shape (for messages), e.g.
    /// "Bodies/Body 0/Box lower corner and Box upper corner"; may be empty.
    std::string parameters;
  };

  template <int dim>
  class BoxShape : public BodyShape<dim>
  {
  public:
    BoxShape(const Point<dim> &lower, const Point<dim> &upper);
    bool
    inside(const Point<dim> &x) const override;
    std::vector<Point<dim>>
    outline_points() const override;
    std::string
    description() const override;

  private:
    Point<dim> lower, upper;
  };

  template <int dim>
  class EllipseShape : public BodyShape<dim>
  {
  public:
    EllipseShape(const Point<dim> &center, const Tensor<1, dim> &semi_axes);
    bool
    inside(const Point<dim> &x) const override;
    std::vector<Point<dim>>
    outline_points() const override;
    std::string
    description() const override;

  private:
    Point<dim>     center;
    Tensor<1, dim> semi_axes;
  };

  /// Even-odd test: is @p x inside the closed polygon @p vertices (no
  /// validity check, so it also serves deformed outlines such as a
  /// membrane's)?
  bool
  inside_polygon(const std::vector<Point<2>> &vertices, const Point<2> &x);

  /// A simple closed polygon in 2D (even-odd rule); throws if it has fewer
  /// than three vertices or intersects itself.
  class PolygonShape : public BodyShape<2>
  {
  public:
    explicit PolygonShape(const std::vector<Point<2>> &vertices);
    bool
    inside(const Point<2> &x) const override;
    std::vector<Point<2>>
    outline_points() const override;
    std::string
    description() const override;

  private:
    /// The vertices and the even-odd test's bands.
    PolygonInside inside_test;
  };

  /// A simple closed polygon in x-y, extruded along z in 3D (over the
  /// given z range): the inside of a 2D membrane or of an extruded one.
  template <int dim>
  class CrossSectionShape : public BodyShape<dim>
  {
  public:
    CrossSectionShape(const std::vector<Point<2>> &vertices,
                      const double                 z0 = 0,
                      const double                 z1 = 0);
    bool
    inside(const Point<dim> &x) const override;
    std::vector<Point<dim>>
    outline_points() const override;
    std::string
    description() const override;

  private:
    PolygonShape polygon;
    double       z0, z1;
  };
} // namespace fsgmpm

#endif
