/* ---------------------------------------------------------------------
 * fsgmpm tutorial step-1: a water column collapses, driven from C++
 * ---------------------------------------------------------------------
 *
 * <h1>Introduction</h1>
 *
 * fsgmpm runs parameter files (`fsgmpm scene.prm`), but it is also a
 * library: a program builds a scene, advances it one explicit step at a
 * time, looks at the material points between steps and measures what it
 * wants. This first tutorial does that for the classic test of a fluid
 * code, the collapse of a water column (Martin and Moyce, 1952; the scene
 * of `prm/water_column_collapse_n2.prm`, doc/water_validation.md):
 *
 * - a column of water a = 0.114 m wide and 2a high stands against the left
 *   wall of a tank and is released at t = 0;
 * - the water is a Newtonian fluid, weakly compressible (bulk modulus
 *   2.5 MPa, a sound speed of 50 m/s, twenty times the flow's speed: the
 *   answer of real water, 2.13 GPa, to 0.001 in the front, with 28 times
 *   fewer steps), with the paper's volumetric smoothing (NMD and ANP) and
 *   free-surface detection;
 * - the program follows the surge front, the largest x of the points in
 *   the bottom cell row, and compares it, in Martin and Moyce's
 *   dimensionless variables Z = z/a and T = t sqrt(2g/a), with their
 *   measurements.
 *
 * The method itself (MPM on a simplex background grid, the paper's
 * Eqs. 19-33) is in README.md, section "The method, in the code".
 */

// @sect3{Include files}
//
// The scene's parameters are declared by fsgmpm::Parameters, as in every
// fsgmpm program; the Simulator owns the grid, the points and the
// materials and advances them.
#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

namespace Step1
{
  using namespace dealii;
  using namespace fsgmpm;

  // @sect3{The scene}
  //
  // A scene is a set of parameters. We declare all of fsgmpm's (so that a
  // misspelt entry is an error, as for a user's prm) and give the ones that
  // differ from the defaults as text; @p cells_across is the number of
  // cells across the column's width.
  void
  describe_scene(ParameterHandler &prm, const unsigned int cells_across)
  {
    Parameters<2>::declare_parameters(prm);
    prm.parse_input_from_string(R"(
subsection Simulation
  set Dimension = 2
  set End time  = 0.26
  set Gravity   = 0, -9.81
end
subsection Grid
  set Upper corner        = 0.684, 0.285
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 3: free
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0, 0
    set Box upper corner = 0.114, 0.228
    set Density          = 1000
    set Material model   = Newtonian fluid
    set Initial stress   = hydrostatic
    subsection Newtonian fluid
      set Bulk modulus = 2.5e6
      set Viscosity    = 8.9e-4
    end
  end
end
subsection Output
  set Directory = output_step-1
  set Quiet     = true
end
)");
    // The resolution: a/h cells across the column, the tank 6a wide and
    // 2.5a high.
    prm.enter_subsection("Grid");
    prm.set("Subdivisions",
            std::to_string(6 * cells_across) + ", "
              + std::to_string(5 * cells_across / 2));
    prm.leave_subsection();
  }



  // @sect3{Our own measurement: the surge front}
  //
  // Between two steps the points are there to be read: positions, volumes,
  // stresses, velocities (fsgmpm::ParticleStore, one array per field).
  // The front is the largest x of the points in the bottom cell row, plus
  // half a point spacing (a point stands for the volume around it).
  double
  front_position(const ParticleStore<2> &particles, const double row_height)
  {
    double front = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.position[p][1] < row_height)
        front = std::max(front,
                         particles.position[p][0]
                           + 0.5 * std::sqrt(particles.volume[p]));
    return front;
  }



  // @sect3{Martin and Moyce's front}
  //
  // Their Table 2 for n^2 = 2 (tests/reference/martin_moyce_1952_n2.csv),
  // (T, Z), and a linear interpolation in it.
  const std::vector<std::pair<double, double>> experiment = {{0.00, 1.00},
                                                             {0.41, 1.11},
                                                             {0.84, 1.22},
                                                             {1.19, 1.44},
                                                             {1.43, 1.67},
                                                             {1.63, 1.89},
                                                             {1.83, 2.11},
                                                             {1.98, 2.33},
                                                             {2.20, 2.56},
                                                             {2.32, 2.78},
                                                             {2.51, 3.00},
                                                             {2.65, 3.22},
                                                             {2.83, 3.44},
                                                             {2.98, 3.67},
                                                             {3.11, 3.89},
                                                             {3.33, 4.11}};

  double
  experimental_front(const double T)
  {
    for (unsigned int i = 1; i < experiment.size(); ++i)
      if (T <= experiment[i].first)
        return experiment[i - 1].second
               + (experiment[i].second - experiment[i - 1].second)
                   * (T - experiment[i - 1].first)
                   / (experiment[i].first - experiment[i - 1].first);
    return experiment.back().second;
  }



  // @sect3{The run}
  //
  // The constructor of the Simulator reads and checks the whole scene and
  // fills the body with points; advance() takes one explicit step (the
  // stages of include/fsgmpm/step/stages.h: p2g, grid update, g2p, NMD,
  // stress update, ANP, ...) and returns false when the run ends (End
  // time, or a stability guard with its diagnosis). Every 10 ms we print
  // the front against the experiment; the RMS of the difference is the
  // program's result.
  double
  run(const unsigned int cells_across)
  {
    ParameterHandler prm;
    describe_scene(prm, cells_across);
    Simulator<2> simulator(prm);

    const double a = 0.114, g = 9.81;
    const double row_height = a / cells_across;
    std::cout << "Column of " << simulator.get_particles().size() << " points, "
              << cells_across << " cells across it.\n"
              << "     t [s]        T   Z (fsgmpm)   Z (experiment)\n";

    double       sum_squares = 0;
    unsigned int samples     = 0;
    double       next_report = 0;
    do
      {
        if (simulator.get_time() >= next_report - 1e-12)
          {
            const double T = simulator.get_time() * std::sqrt(2 * g / a);
            const double Z
              = front_position(simulator.get_particles(), row_height) / a;
            std::cout << std::fixed << std::setprecision(3) << std::setw(10)
                      << simulator.get_time() << std::setw(9) << T
                      << std::setw(13) << Z << std::setw(17)
                      << experimental_front(T) << '\n';
            if (T <= experiment.back().first)
              {
                sum_squares += std::pow(Z - experimental_front(T), 2);
                ++samples;
              }
            next_report += 0.01;
          }
    } while (simulator.advance());

    AssertThrow(simulator.get_termination() == fsgmpm::Termination::end_time,
                ExcMessage("The run stopped early: "
                           + simulator.get_diagnosis()));
    std::cout << "Steps: " << simulator.get_step() << "\n";
    return std::sqrt(sum_squares / samples);
  }
} // namespace Step1



// @sect3{The main function}
//
// As in deal.II's tutorials: run, and report errors in words.
int
main(int argc, char **argv)
{
  try
    {
      const unsigned int cells_across = (argc > 1) ? std::stoi(argv[1]) : 20;
      const double       rms          = Step1::run(cells_across);
      std::cout << "RMS difference of the front from the experiment over "
                   "T <= 3.33: "
                << std::setprecision(3) << rms << std::endl;
    }
  catch (std::exception &exc)
    {
      std::cerr << "step-1: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}

/* <h1>Results</h1>
 *
 * The output of this program and what it shows are in README.md beside
 * this file.
 */
