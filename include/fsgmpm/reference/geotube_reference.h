// Analytic reference for the cross-section of a geosynthetic tube
// (Leshchinsky et al. 1996): an inextensible, weightless closed membrane of
// circumference L holding a fluid of unit weight gamma with cross-section
// area A, resting on a rigid frictionless horizontal base (y = 0).
//
// Model. The membrane tension T is constant; the pressure is hydrostatic,
// p(y) = p_top + gamma (H - y); the free part has curvature p / T; the part on
// the base is a flat strip of width b carrying p_bottom = p_top + gamma H. The
// section is symmetric about x = 0.
//
// Method. With z = H - y (depth below the top) and lengths measured in units
// of l = sqrt(T / gamma), the free curve obeys
//   dx/ds = cos(theta), dz/ds = -sin(theta), dtheta/ds = -(c + z),
// with the single parameter c = p_top / sqrt(T gamma). Starting at the top
// (x = z = theta = 0) the tangent turns monotonically (the curvature c + z is
// positive), so we integrate in the turning angle phi = -theta from 0 to pi:
// the end of the curve, where the tangent is horizontal again and the curve
// meets the base, is then exactly phi = pi and no end event has to be
// located. The height is H = z(pi) and the half contact width x(pi). Every
// shape is fixed by c up to scale, so A / L^2 depends on c only: a scalar
// root find on log(c) matches it (bracketing, then Illinois regula falsi),
// and the scale l follows from L. Then T = gamma l^2 and p_top = c gamma l.
// The ODE is integrated with an adaptive Dormand-Prince 5(4) pair at a
// relative tolerance of 1e-13.
//
// Closed forms as checks (not used by the solver): the ODE has the first
// integral (c + z)^2 = c^2 + 4 sin^2(phi / 2), i.e. p_bottom^2 - p_top^2 =
// 4 gamma T, which is the horizontal equilibrium of a half section; the
// vertical equilibrium is p_bottom b = gamma A.
//
// Limits. A / L^2 must lie in (0, 1 / (4 pi)) (the circle holds the most
// area; p_top grows without bound towards it). Very flat tubes need c ~
// exp(-L^2 / A) (A / L^2 ~ 1 / ln(1 / c)); the search stops at c = 1e-250,
// so solve() throws below A / L^2 ~ 4.3e-4 (e.g. A < 0.037 m^2 for L = 9.2 m).

#ifndef fsgmpm_reference_geotube_reference_h
#define fsgmpm_reference_geotube_reference_h

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace geotube_reference
{
  struct Solution
  {
    double height, width, contact_width, tension, top_pressure, bottom_pressure;
    double circumference, area; // as achieved by the solution (check)
    // Closed polygon of the full membrane, counter-clockwise, x centred at 0,
    // y from 0 to height; the first point (left end of the contact strip) is
    // not repeated at the end.
    std::vector<std::array<double, 2>> shape;
  };

  namespace internal
  {
    constexpr double pi = 3.14159265358979323846;

    // Numbers in error messages, with enough digits to tell them apart.
    inline std::string
    format_number(const double v)
    {
      std::ostringstream s;
      s.precision(10);
      s << v;
      return s.str();
    }

    // Scale-free state along the right half, in units of l = sqrt(T/gamma):
    // x, depth z below the top, arc length s, and q = integral of z dx (the
    // area between the curve and the top's horizontal line, signed).
    using State = std::array<double, 4>;

    // d(state)/dphi: ds/dphi is the radius of curvature 1 / (c + z).
    inline State
    rhs(const double c, const double phi, const State &u)
    {
      const double radius = 1. / (c + u[1]);
      const double cx     = std::cos(phi) * radius;
      return {{cx, std::sin(phi) * radius, radius, u[1] * cx}};
    }

    // What one pass over the right half gives (scale-free).
    struct HalfCurve
    {
      double x_max  = 0; // x at phi = pi/2: half the width
      double x_end  = 0; // half the contact width
      double height = 0; // z at phi = pi
      double length = 0; // arc length of the free curve
      double q      = 0; // integral of z dx over the curve
      // Accepted points (x, z) from phi = 0 to pi, if sampling was asked.
      std::vector<std::array<double, 2>> points;

      double
      half_perimeter() const
      {
        return length + x_end;
      }

      // Area of the half section: the rectangle H x_end under the top line
      // minus what lies between the top line and the curve.
      double
      area() const
      {
        return 2 * (height * x_end - q);
      }
    };

    // Adaptive Dormand-Prince 5(4) from phi0 to phi1. h is the step to try
    // and returns the suggested next step. Steps are capped at max_dphi and
    // at an arc length of about max_ds (for evenly spread samples); every
    // accepted (x, z) is appended to points if it is non-null.
    inline void
    integrate(const double                        c,
              const double                        phi0,
              const double                        phi1,
              State                              &u,
              double                             &h,
              const double                        max_dphi,
              const double                        max_ds,
              std::vector<std::array<double, 2>> *points)
    {
      constexpr double rtol = 1e-13;
      // Absolute floors (relative to the natural size of each component:
      // lengths ~ 1/(1 + c), q ~ length^2) so growth from zero is cheap.
      const double length = 1. / (1. + c);
      const State  atol   = {{rtol * 1e-3 * length,
                              rtol * 1e-3 * length,
                              rtol * 1e-3 * length,
                              rtol * 1e-3 * length * length}};

      double       phi = phi0;
      unsigned int n   = 0;
      while (phi < phi1)
        {
          if (++n > 10000000 || !(phi + std::min(h, phi1 - phi) > phi))
            throw std::invalid_argument(
              "geotube_reference: the shape integration made no progress");
          const double cap  = std::min(max_dphi, max_ds * (c + u[1]));
          const bool   last = (phi + std::min(h, cap) >= phi1);
          const double step = last ? phi1 - phi : std::min(h, cap);

          // Dormand-Prince stages; the last one is the 5th order solution
          // (first same as last), whose slope enters the error estimate.
          constexpr double nodes[7]
            = {0, 1. / 5, 3. / 10, 4. / 5, 8. / 9, 1, 1};
          constexpr double a[7][6] = {
            {},
            {1. / 5},
            {3. / 40, 9. / 40},
            {44. / 45, -56. / 15, 32. / 9},
            {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729},
            {9017. / 3168,
             -355. / 33,
             46732. / 5247,
             49. / 176,
             -5103. / 18656},
            {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
          std::array<State, 7> k;
          State                u_new = u;

          k[0] = rhs(c, phi, u);
          for (int r = 1; r < 7; ++r)
            {
              u_new = u;
              for (int j = 0; j < r; ++j)
                for (int i = 0; i < 4; ++i)
                  u_new[i] += step * a[r][j] * k[j][i];
              k[r] = rhs(c, phi + nodes[r] * step, u_new);
            }

          // Difference between the 5th and embedded 4th order solutions.
          constexpr std::array<double, 7> e = {{71. / 57600,
                                                0,
                                                -71. / 16695,
                                                71. / 1920,
                                                -17253. / 339200,
                                                22. / 525,
                                                -1. / 40}};

          double err = 0;
          for (int i = 0; i < 4; ++i)
            {
              double d = 0;
              for (int j = 0; j < 7; ++j)
                d += e[j] * k[j][i];
              const double scale
                = atol[i] + rtol * std::max(std::abs(u[i]), std::abs(u_new[i]));
              err = std::max(err, std::abs(step * d) / scale);
            }

          // Standard controller. A step shortened by the cap or the interval
          // end keeps h unless the estimate asks for less.
          const double factor
            = std::clamp(0.9 * std::pow(std::max(err, 1e-30), -0.2), 0.2, 5.);
          if (err <= 1)
            {
              phi = last ? phi1 : phi + step;
              u   = u_new;
              if (points)
                points->push_back({{u[0], u[1]}});
              if (step == h || factor < 1)
                h = step * factor;
            }
          else
            h = step * factor;
        }
    }

    // One pass over the right half for parameter c. Sampling (samples > 0)
    // caps the steps at pi/samples in angle and length/samples in arc length.
    inline HalfCurve
    shoot(const double       c,
          const unsigned int samples = 0,
          const double       length  = 0)
    {
      HalfCurve    curve;
      State        u        = {{0, 0, 0, 0}};
      double       h        = 1e-3 * std::min(1., c); // curvature scale ~ c
      const double inf      = std::numeric_limits<double>::infinity();
      const double max_dphi = samples > 0 ? pi / samples : inf;
      const double max_ds   = samples > 0 ? length / samples : inf;
      auto *const  points   = samples > 0 ? &curve.points : nullptr;
      if (points)
        points->push_back({{0, 0}});

      // Split at pi/2, where x is largest, to get the width exactly.
      integrate(c, 0, pi / 2, u, h, max_dphi, max_ds, points);
      curve.x_max = u[0];
      integrate(c, pi / 2, pi, u, h, max_dphi, max_ds, points);
      curve.x_end  = u[0];
      curve.height = u[1];
      curve.length = u[2];
      curve.q      = u[3];
      return curve;
    }

    // A / L^2 of the shape with parameter c.
    inline double
    area_ratio(const double c)
    {
      const HalfCurve curve = shoot(c);
      const double    L     = 2 * curve.half_perimeter();
      return curve.area() / (L * L);
    }
  } // namespace internal

  inline Solution
  solve(const double circumference, const double area, const double unit_weight)
  {
    using namespace internal;
    const double L = circumference;
    if (!(std::isfinite(L) && L > 0))
      throw std::invalid_argument(
        "geotube_reference: the circumference must be positive and finite");
    if (!(std::isfinite(unit_weight) && unit_weight > 0))
      throw std::invalid_argument(
        "geotube_reference: the unit weight must be positive and finite");
    const double circle = L * L / (4 * pi);
    if (!(std::isfinite(area) && area > 0 && area < circle))
      throw std::invalid_argument(
        "geotube_reference: the area must lie in (0, L^2/(4 pi)) = (0, "
        + format_number(circle) + ") m^2 for L = " + format_number(L)
        + " m (a circle holds the most area), got " + format_number(area)
        + " m^2");
    const double target = area / (L * L);

    // Bracket the root in decades of c (A/L^2 grows with c).
    const auto residual = [&](const double log_c) {
      return area_ratio(std::exp(log_c)) - target;
    };
    const double decade  = std::log(10.);
    const double log_min = std::log(1e-250), log_max = std::log(1e12);
    double       a = 0, fa = residual(a), b = a, fb = fa;
    while (fa > 0 && a > log_min)
      {
        b = a, fb = fa;
        a = std::max(a - decade, log_min), fa = residual(a);
      }
    while (fb < 0 && b < log_max)
      {
        a = b, fa = fb;
        b = std::min(b + decade, log_max), fb = residual(b);
      }
    if (!(fa <= 0 && fb >= 0))
      throw std::invalid_argument(
        "geotube_reference: no shape found for A/L^2 = " + format_number(target)
        + (fa > 0 ? " (too flat: the top pressure underflows)"
                  : " (too close to the circle)"));

    // Illinois regula falsi on log(c).
    double log_c = fa == 0 ? a : b, f = fa == 0 ? fa : fb;
    int    side = 0;
    for (unsigned int it = 0; it < 200 && f != 0; ++it)
      {
        log_c = (a * fb - b * fa) / (fb - fa);
        if (!(log_c > a && log_c < b)) // round-off: fall back to bisection
          log_c = 0.5 * (a + b);
        f = residual(log_c);
        if (std::abs(f) <= 1e-13 * target || b - a <= 1e-15 * std::abs(log_c))
          break;
        if (f > 0)
          {
            b = log_c, fb = f;
            if (side == 1)
              fa /= 2;
            side = 1;
          }
        else
          {
            a = log_c, fa = f;
            if (side == -1)
              fb /= 2;
            side = -1;
          }
      }
    const double c = std::exp(log_c);

    // Final pass with samples (at least 400 points per half; its steps are
    // capped using the arc length of a free pass), then rescale so the
    // circumference is L.
    constexpr unsigned int samples = 400;
    const HalfCurve        coarse  = shoot(c);
    const HalfCurve        curve   = shoot(c, samples, coarse.length);
    const double           l       = L / (2 * curve.half_perimeter());

    Solution s;
    s.height          = l * curve.height;
    s.width           = 2 * l * curve.x_max;
    s.contact_width   = 2 * l * curve.x_end;
    s.tension         = unit_weight * l * l;
    s.top_pressure    = c * unit_weight * l;
    s.bottom_pressure = s.top_pressure + unit_weight * s.height;
    s.circumference   = 2 * l * curve.half_perimeter();
    s.area            = l * l * curve.area();
    if (!(std::abs(s.area - area) <= 1e-9 * area
          && std::abs(s.circumference - L) <= 1e-9 * L))
      throw std::invalid_argument(
        "geotube_reference: the solver did not converge for L = "
        + format_number(L) + " m, A = " + format_number(area) + " m^2");

    // Polygon, counter-clockwise: the contact strip left to right, the right
    // half from the base up to the top, the mirrored left half down again.
    // The strip's spacing is at most the curve's (L / 2 / samples).
    const auto        &p = curve.points; // from the top (phi = 0) to the base
    const double       half_b  = 0.5 * s.contact_width;
    const unsigned int n_strip = static_cast<unsigned int>(
      std::max(1., std::ceil(s.contact_width / (L / (2. * samples)))));
    for (unsigned int i = 0; i < n_strip; ++i)
      s.shape.push_back({{-half_b + s.contact_width * i / n_strip, 0.}});
    for (auto it = p.rbegin(); it != p.rend(); ++it)
      s.shape.push_back({{l * (*it)[0], l * (curve.height - (*it)[1])}});
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
      s.shape.push_back({{-l * p[i][0], l * (curve.height - p[i][1])}});
    return s;
  }
} // namespace geotube_reference

#endif
