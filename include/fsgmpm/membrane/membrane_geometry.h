#ifndef fsgmpm_membrane_membrane_geometry_h
#define fsgmpm_membrane_membrane_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/membrane.h>

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fsgmpm
{
  /**
   * The membrane of a scene, as given in subsection Membrane: its shape
   * (an ellipse of given circumference and enclosed area, a closed polygon,
   * or in 3D a Gmsh surface), element size and material. In 3D the ellipse
   * and polygon shapes are extruded along z over the grid's thickness (an
   * elliptic cylinder whose open ends lie on the z walls).
   */
  template <int dim>
  struct MembraneDescription
  {
    bool                  enabled = false;
    std::string           shape;
    double                circumference = 0, area = 0;
    Point<2>              bottom; ///< lowest point of the ellipse (x, y)
    std::vector<Point<2>> polygon;
    std::string           mesh_file;
    /// Initial element length (0: 0.4 grid cells) and the length above
    /// which a cable is split (as a fraction of the grid cell size).
    double element_size    = 0;
    double split_fraction  = 0.5;
    bool   tangential_slip = false;
    /// No material point passes through the membrane (MembraneCrossing).
    bool               impermeable_to_points = true;
    double             ground_level = -std::numeric_limits<double>::infinity();
    double             ground_stiffness = 1e7;
    MembraneProperties properties;

    static void
    declare_parameters(ParameterHandler &prm);

    explicit MembraneDescription(ParameterHandler &prm);

    /// Shape = ellipse or polygon: the closed outline in x-y,
    /// counter-clockwise, with segments of at most the element size.
    /// @p size_factor scales the element size (3D uses 1/sqrt(2) so that
    /// the diagonals of the extruded triangles keep the element size).
    std::vector<Point<2>>
    outline(const double cell_size, const double size_factor = 1.) const;

    /// The codimension-one mesh: the closed polygon or ellipse in 2D, the
    /// extruded surface over z in [z0, z1] or the Gmsh surface in 3D. A
    /// Gmsh surface of second-order (6-node) triangles also gives the
    /// middle nodes of its curved edges in @p edge_middle_points (if
    /// given), for Membrane's constructor; the extruded surface gives
    /// middle nodes on the arcs through the outline's points (a curved
    /// rest surface at degree 2).
    void
    make_mesh(const double                     cell_size,
              const std::pair<double, double> &z_range,
              Triangulation<dim - 1, dim>     &mesh,
              std::map<std::pair<unsigned int, unsigned int>, Point<dim>>
                *edge_middle_points
              = nullptr) const;
  };

  namespace MembraneGeometry
  {
    /// Perimeter of the ellipse with semi-axes a, b (numerical quadrature
    /// of the complete elliptic integral, relative error < 1e-12).
    double
    ellipse_perimeter(const double a, const double b);

    /// Semi-axes (a >= b) of the ellipse with perimeter @p L and area @p A;
    /// throws unless 0 < A < L^2 / (4 pi) (a circle holds the most).
    std::pair<double, double>
    ellipse_axes(const double L, const double A);

    /// @p n points on the ellipse, equally spaced in arc length,
    /// counter-clockwise from the lowest point.
    std::vector<Point<2>>
    ellipse_points(const Point<2>    &center,
                   const double       a,
                   const double       b,
                   const unsigned int n);

    /// Signed area of the closed polygon @p outline (shoelace; positive
    /// counter-clockwise).
    double
    signed_area(const std::vector<Point<2>> &outline);

    /// Point at fraction @p t of the arc from @p from to @p to on the circle
    /// through @p a, @p b, @p c in x-y (z is kept); the chord where the
    /// three points are (nearly) collinear. The degree-2 membrane's initial
    /// edge midpoints and the slip (MembraneSlip) place nodes with it.
    template <int dim>
    Point<dim>
    point_on_arc(const Point<dim> &a,
                 const Point<dim> &b,
                 const Point<dim> &c,
                 const Point<dim> &from,
                 const Point<dim> &to,
                 const double      t);
  } // namespace MembraneGeometry
} // namespace fsgmpm

#endif
