// Hydrostatic water column (2D triangles and 3D tetrahedra, 25 cells high,
// surface on a grid line), weakly compressible (p_max/K_f = 1e-3), starting
// from zero pressure with gravity and local damping until both Eq. (30)
// ratios stay below 1e-3.
// Reference: p = rho g (H - y).
// Asserts: (1) with NMD+ANP, particle pressure within 2% of rho g H of the
//   reference (top and bottom cell rows excluded; element_mean mapping) and
//   with the interpolate mapping everywhere; (2) checkerboard measure (RMS
//   over cells of the cell-mean pressure error minus the mean of its face
//   neighbours' cell-mean errors, / rho g H) below 1% with NMD+ANP;
//   (3) the settled column has no flagged point inside (surface on a grid
//   line: at most the top row may be flagged).
// The measure for none / NMD / ANP / NMD+ANP is printed for doc/.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <map>

using namespace fsgmpm;

namespace
{
  constexpr double H = 0.5, rho = 1000, g = 9.81, h = 0.02;

  struct Result
  {
    bool         converged             = false;
    unsigned int steps                 = 0;
    double       max_error             = 0; // / rho g H, interior rows
    double       max_error_all         = 0; // / rho g H, all points
    double       checkerboard          = 0;
    unsigned int flagged_below_top_row = 0, flagged = 0, points = 0;
  };

  template <int dim>
  Result
  run(const std::string &smoothing, const std::string &mapping)
  {
    std::string prm
      = "subsection Simulation\n  set Dimension = " + std::to_string(dim)
        + "\n  set End time = 3\n  set Maximum number of steps = 12000\n"
          "  set Termination = dr_converged\n"
          "end\n"
          "subsection Damping\n  set Local damping coefficient = 0.5\n"
          "  set Energy tolerance = 1e-3\n  set Force tolerance = 1e-3\n"
          "  set Convergence window = 100\nend\n"
          "subsection Grid\n";
    if (dim == 2)
      prm += "  set Upper corner = 0.08, 0.6\n  set Subdivisions = 4, 30\n"
             "  set Boundary conditions = 0: roller, 1: roller, 2: roller\n";
    else
      prm += "  set Lower corner = 0, 0, 0\n"
             "  set Upper corner = 0.04, 0.6, 0.04\n"
             "  set Subdivisions = 2, 30, 2\n"
             "  set Boundary conditions = 0: roller, 1: roller, 2: roller, "
             "4: roller, 5: roller\n";
    prm += "end\nsubsection Bodies\n subsection Body 0\n"
           "  set Material model = Newtonian fluid\n"
           "  set Box lower corner = 0, 0"
           + std::string(dim == 3 ? ", 0" : "") + "\n  set Box upper corner = "
           + std::string(dim == 3 ? "0.04, 0.5, 0.04" : "0.08, 0.5")
           + "\n  set Particles per cell = " + (dim == 2 ? "4" : "8")
           + "\n  set Volumetric smoothing = " + smoothing
           + "\n  set ANP mapping = " + mapping
           + "\n  subsection Newtonian fluid\n   set Bulk modulus = 4.905e6\n"
             "  end\n end\nend\n";
    auto           parameters = test_tools::make_parameters(prm);
    Simulator<dim> sim(*parameters);
    while (sim.advance())
      {}
    Result r;
    r.converged = sim.get_termination() == fsgmpm::Termination::dr_converged;
    r.steps     = sim.get_step();
    const auto  &ps    = sim.get_particles();
    const double scale = rho * g * H;
    std::map<unsigned int, std::pair<double, unsigned int>> cell_error;
    for (unsigned int p = 0; p < ps.size(); ++p)
      {
        const double y = ps.position[p][1];
        const double error
          = (-trace(ps.stress[p]) / 3. - rho * g * (H - y)) / scale;
        r.max_error_all = std::max(r.max_error_all, std::abs(error));
        if (y > h && y < H - h)
          r.max_error = std::max(r.max_error, std::abs(error));
        auto &ce = cell_error[ps.cell[p]];
        ce.first += error;
        ce.second += 1;
        r.flagged += ps.free_surface[p];
        r.flagged_below_top_row += ps.free_surface[p] && (y < H - h);
      }
    r.points = ps.size();
    // Checkerboard: cell-mean error against the mean of the face neighbours.
    double       sum = 0;
    unsigned int n   = 0;
    for (const auto &[c, ce] : cell_error)
      {
        double       neighbours = 0;
        unsigned int k          = 0;
        for (const unsigned int nb : sim.get_grid().cell_neighbors[c])
          {
            const auto it = cell_error.find(nb);
            if (it != cell_error.end())
              {
                neighbours += it->second.first / it->second.second;
                ++k;
              }
          }
        if (k == 0)
          continue;
        const double d = ce.first / ce.second - neighbours / k;
        sum += d * d;
        ++n;
      }
    r.checkerboard = std::sqrt(sum / n);
    std::cout << "[ measured ] " << dim << "D " << smoothing << " (" << mapping
              << "): " << (r.converged ? "converged" : "NOT converged")
              << " in " << r.steps
              << " steps; max |p error| / rho g H = " << 100 * r.max_error
              << " % (interior), " << 100 * r.max_error_all
              << " % (all points); checkerboard " << 100 * r.checkerboard
              << " %; flagged " << r.flagged << " of " << r.points << " ("
              << r.flagged_below_top_row << " below the top row)" << std::endl;
    return r;
  }
} // namespace

TEST(HydrostaticColumn, Triangles)
{
  const Result r = run<2>("NMD+ANP", "element_mean");
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.max_error, 0.02);
  EXPECT_LT(r.checkerboard, 0.01);
  EXPECT_EQ(r.flagged_below_top_row, 0u);
  const Result ri = run<2>("NMD+ANP", "interpolate");
  EXPECT_TRUE(ri.converged);
  EXPECT_LT(ri.max_error_all, 0.02);
  EXPECT_LT(ri.checkerboard, 0.01);
}

TEST(HydrostaticColumn, Tetrahedra)
{
  const Result r = run<3>("NMD+ANP", "element_mean");
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.max_error, 0.02);
  EXPECT_LT(r.checkerboard, 0.01);
  EXPECT_EQ(r.flagged_below_top_row, 0u);
}

// The table of doc/water_validation.md: the same column without and with
// each remedy (label validation). Asserts the table's reading: the
// laterally confined column does not lock, so none and NMD converge with
// the same pressure error as NMD+ANP (measured 1.43%, 1.44%, 1.46%) and no
// checkerboard (0.007%, 0.004%, 0.023%: asserted below 0.1%); ANP without
// NMD never converges (unstable in MPM, as the paper notes).
TEST(HydrostaticColumn, SmoothingTable)
{
  for (const char *s : {"none", "NMD", "NMD+ANP"})
    {
      const Result r = run<2>(s, "element_mean");
      EXPECT_TRUE(r.converged) << s;
      EXPECT_LT(r.max_error, 0.02) << s;
      EXPECT_LT(r.checkerboard, 1e-3) << s;
    }
  EXPECT_FALSE(run<2>("ANP", "element_mean").converged);
}
