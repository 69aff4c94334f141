#ifndef fsgmpm_base_real_interval_h
#define fsgmpm_base_real_interval_h

#include <deal.II/base/patterns.h>

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * A real number in an interval whose ends may each be open: the pattern
   * of an entry whose check refuses an end (a Poisson's ratio below 0.5, a
   * modulus above 0), so that --print-parameters prints what the checks
   * accept (deal.II's Patterns::Double has closed ends only). Printed as
   * "[Double 0...0.5 (0 inclusive, 0.5 exclusive)]"; NaN and inf never
   * match.
   */
  class RealInterval : public Patterns::PatternBase
  {
  public:
    RealInterval(const double lower,
                 const double upper,
                 const bool   lower_open,
                 const bool   upper_open);

    /// (lower, +max]: a positive number (lower = 0), at most @p upper.
    static RealInterval
    above(const double lower,
          const double upper = std::numeric_limits<double>::max());

    bool
    match(const std::string &test_string) const override;

    std::string
    description(const OutputStyle style = Machine) const override;

    std::unique_ptr<Patterns::PatternBase>
    clone() const override;

  private:
    double lower, upper;
    bool   lower_open, upper_open;
  };



  inline RealInterval::RealInterval(const double lower,
                                    const double upper,
                                    const bool   lower_open,
                                    const bool   upper_open)
    : lower(lower)
    , upper(upper)
    , lower_open(lower_open)
    , upper_open(upper_open)
  {}



  inline RealInterval
  RealInterval::above(const double lower, const double upper)
  {
    return RealInterval(lower, upper, true, false);
  }



  inline bool
  RealInterval::match(const std::string &test_string) const
  {
    std::istringstream in(test_string);
    double             x;
    if (!(in >> x))
      return false;
    in >> std::ws;
    if (!in.eof() || !std::isfinite(x))
      return false;
    return (lower_open ? x > lower : x >= lower)
           && (upper_open ? x < upper : x <= upper);
  }



  inline std::string
  RealInterval::description(const OutputStyle) const
  {
    // As deal.II prints Patterns::Double, with each end said.
    const auto number = [](const double x) {
      if (x == std::numeric_limits<double>::max())
        return std::string("MAX_DOUBLE");
      if (x == -std::numeric_limits<double>::max())
        return std::string("-MAX_DOUBLE");
      std::ostringstream s;
      s << x;
      return s.str();
    };
    const auto end
      = [](const bool open) { return open ? " exclusive" : " inclusive"; };
    return "[Double " + number(lower) + "..." + number(upper) + " ("
           + number(lower) + end(lower_open) + ", " + number(upper)
           + end(upper_open) + ")]";
  }



  inline std::unique_ptr<Patterns::PatternBase>
  RealInterval::clone() const
  {
    return std::make_unique<RealInterval>(lower, upper, lower_open, upper_open);
  }
} // namespace fsgmpm

#endif
