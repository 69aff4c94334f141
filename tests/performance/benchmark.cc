// Benchmark of the full explicit MPM step (elastic block, 2D and 3D, more
// than 100 000 material points each) against a baseline made of deal.II's
// stock ParticleHandler with MappingFE doing the same relocation and
// P2G/G2P (the step-19/step-70 pattern: FEValues at the particles' reference
// locations, cell by cell). The baseline is a speed reference only: deal.II
// 9.4 mislocates particles on simplices (doc/foundation_validation.md).
//
// Usage: benchmark [steps] [filter]: runs the cases whose name contains
// filter (all by default), each for the given number of timed steps (50).
//
// Prints one line per case:
//   BENCH <case> dim=<d> particles=<n> steps=<s> updates_per_second=<x>
//         bytes_per_particle=<b> resident_bytes_per_particle=<r>
//         baseline_updates_per_second=<y>
// and the time per step of each stage. Not a test with a timed assertion.
// bytes_per_particle counts the point store, the grid's arrays and the
// nodal and smoothing fields per point; resident_bytes_per_particle is what
// the process holds more at the end of the case than before it (VmRSS), per
// point: also the allocator's slack. (The grid keeps no deal.II mesh; the
// baseline builds its own, after both are measured.)
//
// The membrane: the geotube cases time the membrane's share of
// the step (stage "membrane"), slip at degree 1 as shipped and no-slip at
// degrees 1 and 2 with the same nodes; membrane_forces_2d/3d time the
// element forces of MembraneFE against the hand-written cables and
// triangles (MembraneMechanics, kept as the tests' reference) on the same
// membrane:
//   BENCH membrane_forces_<d>d elements=<n> fe_degree1_ns_per_element=<x>
//         hand_written_ns_per_element=<y> ratio=<x/y>
//         fe_degree2_ns_per_cell=<z>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/particles/particle_handler.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/membrane/membrane_mechanics.h>
#include <fsgmpm/simulator.h>

#include <malloc.h>

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "test_utilities.h"

using namespace fsgmpm;
using Clock = std::chrono::steady_clock;

namespace
{
  double
  seconds_since(const Clock::time_point t0)
  {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  // The 2D dam break of doc/performance.md at 102 400 points: fluid with
  // NMD + ANP + free-surface detection, in a tank mostly empty at the start.
  std::string
  dam_break_scene()
  {
    return R"(
subsection Simulation
  set End time = 100
end
subsection Grid
  set Upper corner = 0.684, 0.285
  set Subdivisions = 480, 200
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 3: free
end
subsection Bodies
  subsection Body 0
    set Material model = Newtonian fluid
    set Initial stress = hydrostatic
    set Box lower corner = 0, 0
    set Box upper corner = 0.114, 0.228
    set Particles per cell = 4
    subsection Newtonian fluid
      set Bulk modulus = 2.5e6
    end
  end
end
)";
  }

  // The same water column in a tank of 10 times the area (sqrt(10) times
  // the width and height) at the same cell size: work should follow the
  // material, not the mesh (the aim in doc/performance.md: at most 1.3
  // times the time per step of dam_break_2d).
  std::string
  dam_break_scene_wide_tank()
  {
    return dam_break_scene() + R"(
subsection Grid
  set Upper corner = 2.1630, 0.9013
  set Subdivisions = 1518, 632
end
)";
  }

  // The same dam break in 3D: a slab of 0.057 m depth with slip faces,
  // 8 points per tetrahedron, 320 000 points.
  std::string
  dam_break_scene_3d()
  {
    return R"(
subsection Simulation
  set Dimension = 3
  set End time = 100
end
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 0.684, 0.285, 0.057
  set Subdivisions = 120, 50, 10
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 4: roller, 5: roller
end
subsection Bodies
  subsection Body 0
    set Material model = Newtonian fluid
    set Initial stress = hydrostatic
    set Box lower corner = 0, 0, 0
    set Box upper corner = 0.114, 0.228, 0.057
    set Particles per cell = 8
    subsection Newtonian fluid
      set Bulk modulus = 2.5e6
    end
  end
end
)";
  }

  template <int dim>
  std::string
  scene()
  {
    // The block fills the lower 80% of the mesh; gravity makes it move.
    if (dim == 2)
      return R"(
subsection Simulation
  set Dimension = 2
  set End time = 100
end
subsection Grid
  set Upper corner = 1.6, 1.0
  set Subdivisions = 160, 100
  set Boundary conditions = 0: roller, 1: roller, 2: roller
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0, 0
    set Box upper corner = 1.6, 0.8
    set Particles per cell = 4
    subsection Linear elastic
      set Young's modulus = 1e6
    end
  end
end
)";
    return R"(
subsection Simulation
  set Dimension = 3
  set End time = 100
end
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 1.2, 1.0, 0.6
  set Subdivisions = 24, 20, 12
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 4: roller, 5: roller
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0, 0, 0
    set Box upper corner = 1.2, 0.8, 0.6
    set Particles per cell = 8
    subsection Linear elastic
      set Young's modulus = 1e6
    end
  end
end
)";
  }

  /**
   * The stock deal.II way: ParticleHandler + MappingFE, properties
   * (mass, volume, velocity, stress), P2G and G2P with FEValues built from
   * the particles' reference locations in each cell, then
   * sort_particles_into_subdomains_and_cells().
   */
  template <int dim>
  double
  baseline_updates_per_second(const Simulator<dim> &sim,
                              const unsigned int    steps)
  {
    const auto &grid = sim.get_grid();
    // The grid keeps no deal.II mesh: the same cells, in the same order
    // (active cell c is the grid's cell c), from its nodes.
    Triangulation<dim> tria;
    {
      std::vector<CellData<dim>> cells(grid.n_base_cells(),
                                       CellData<dim>(dim + 1));
      for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
        for (unsigned int k = 0; k < dim + 1; ++k)
          cells[c].vertices[k] = grid.cell_nodes[c][k];
      tria.create_triangulation(
        std::vector<Point<dim>>(grid.node_positions.begin(),
                                grid.node_positions.begin()
                                  + grid.n_base_nodes()),
        cells,
        SubCellData());
    }
    const FE_SimplexP<dim> fe(1);
    DoFHandler<dim>        dofh(tria);
    dofh.distribute_dofs(fe);
    const MappingFE<dim>            mapping(FE_SimplexP<dim>(1));
    const unsigned int              n_props = 2 + dim + dim * dim;
    Particles::ParticleHandler<dim> handler(tria, mapping, n_props);

    // Insert the simulator's points with their known cells.
    const auto &ps = sim.get_particles();
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &cell : tria.active_cell_iterators())
      cells.push_back(cell);
    std::vector<double> props(n_props, 0.);
    for (unsigned int p = 0; p < ps.size(); ++p)
      {
        const auto lambda = grid.barycentric(ps.cell[p], ps.position[p]);
        Point<dim> ref;
        for (unsigned int d = 0; d < dim; ++d)
          ref[d] = lambda[d + 1];
        props[0] = ps.mass[p];
        props[1] = ps.volume[p];
        handler.insert_particle(ps.position[p],
                                ref,
                                p,
                                cells[ps.cell[p]],
                                ArrayView<const double>(props));
      }

    const unsigned int          n = dofh.n_dofs();
    std::vector<double>         mass(n);
    std::vector<Tensor<1, dim>> momentum(n), force(n), velocity(n), accel(n);
    Tensor<1, dim>              gravity;
    gravity[1]        = -9.81;
    const double dt   = 1e-5;
    const double lame = 0, mu = 0.5e6 / 1.3; // stress update cost only
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    // FEValues at the reference locations of the particles of one cell (as
    // step-19 and step-70 do), and that cell's DoF indices.
    auto particle_fe_values = [&](const auto &range, const auto &cell) {
      std::vector<Point<dim>> refs;
      for (const auto &p : range)
        refs.push_back(p.get_reference_location());
      auto fev = std::make_unique<FEValues<dim>>(
        mapping, fe, Quadrature<dim>(refs), update_values | update_gradients);
      fev->reinit(cell);
      cell->get_dof_indices(dofs);
      return fev;
    };

    const auto t0 = Clock::now();
    for (unsigned int step = 0; step < steps; ++step)
      {
        std::fill(mass.begin(), mass.end(), 0.);
        std::fill(momentum.begin(), momentum.end(), Tensor<1, dim>());
        std::fill(force.begin(), force.end(), Tensor<1, dim>());
        // P2G
        for (const auto &cell : dofh.active_cell_iterators())
          {
            const auto range = handler.particles_in_cell(cell);
            if (range.begin() == range.end())
              continue;
            const auto           fev_pointer = particle_fe_values(range, cell);
            const FEValues<dim> &fev         = *fev_pointer;
            unsigned int         q           = 0;
            for (const auto &p : range)
              {
                const auto     pr = p.get_properties();
                Tensor<1, dim> v;
                Tensor<2, dim> s;
                for (unsigned int d = 0; d < dim; ++d)
                  v[d] = pr[2 + d];
                for (unsigned int d = 0; d < dim * dim; ++d)
                  s[d / dim][d % dim] = pr[2 + dim + d];
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    const double N = fev.shape_value(i, q);
                    mass[dofs[i]] += N * pr[0];
                    momentum[dofs[i]] += N * pr[0] * v;
                    force[dofs[i]]
                      += N * pr[0] * gravity - pr[1] * s * fev.shape_grad(i, q);
                  }
                ++q;
              }
          }
        // Grid update
        for (unsigned int i = 0; i < n; ++i)
          if (mass[i] > 0)
            {
              accel[i]    = force[i] / mass[i];
              velocity[i] = momentum[i] / mass[i] + dt * accel[i];
            }
        // G2P: velocity, strain rate, stress, position
        for (const auto &cell : dofh.active_cell_iterators())
          {
            const auto range = handler.particles_in_cell(cell);
            if (range.begin() == range.end())
              continue;
            const auto           fev_pointer = particle_fe_values(range, cell);
            const FEValues<dim> &fev         = *fev_pointer;
            unsigned int         q           = 0;
            for (auto &p : range)
              {
                auto           pr = p.get_properties();
                Tensor<1, dim> a, v;
                Tensor<2, dim> L;
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    const double N = fev.shape_value(i, q);
                    a += N * accel[dofs[i]];
                    v += N * velocity[dofs[i]];
                    L += outer_product(velocity[dofs[i]], fev.shape_grad(i, q));
                  }
                for (unsigned int d = 0; d < dim; ++d)
                  pr[2 + d] += dt * a[d];
                const Tensor<2, dim> eps = 0.5 * (L + transpose(L));
                for (unsigned int d = 0; d < dim * dim; ++d)
                  pr[2 + dim + d]
                    += dt
                       * (2 * mu * eps[d / dim][d % dim]
                          + (d / dim == d % dim ? lame * trace(eps) : 0.));
                p.set_location(p.get_location() + dt * v);
                ++q;
              }
          }
        handler.sort_particles_into_subdomains_and_cells();
      }
    return double(ps.size()) * steps / seconds_since(t0);
  }

  // Only the cases whose name contains this string run.
  std::string case_filter;

  // The shipped geotube at 16 cm cells with @p changes appended.
  std::string
  geotube_scene(const std::string &changes)
  {
    std::ifstream in(std::string(FSGMPM_TEST_SOURCE_DIR)
                     + "/../prm/geotube_A5.56.prm");
    AssertThrow(in, ExcMessage("cannot read prm/geotube_A5.56.prm"));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str()
           + "subsection Grid\n  set Cell size = 0.16\nend\n"
             "subsection Output\n  set Output interval = 0\nend\n"
           + changes;
  }

  // Element forces of a membrane: MembraneFE of degree 1 (what Membrane
  // runs) and 2 against the hand-written elements, @p reps evaluations of a
  // deformed ring of n cables (2D) or an n x n cylinder of triangles (3D).
  template <int dim>
  void
  membrane_forces_case(const unsigned int n, const unsigned int reps)
  {
    const std::string name = "membrane_forces_" + std::to_string(dim) + "d";
    if (name.find(case_filter) == std::string::npos)
      return;
    std::vector<Point<dim>>        vertices;
    std::vector<CellData<dim - 1>> cells;
    if constexpr (dim == 2)
      for (unsigned int i = 0; i < n; ++i)
        {
          vertices.emplace_back(std::cos(2 * M_PI * i / n),
                                std::sin(2 * M_PI * i / n));
          CellData<1> c;
          c.vertices = {i, (i + 1) % n};
          cells.push_back(c);
        }
    else
      {
        for (unsigned int j = 0; j <= n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            vertices.emplace_back(std::cos(2 * M_PI * i / n),
                                  std::sin(2 * M_PI * i / n),
                                  double(j) / n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int v0 = j * n + i, v1 = j * n + (i + 1) % n,
                                 v2 = v0 + n, v3 = v1 + n;
              CellData<2> a, b;
              a.vertices = {v0, v1, v3};
              b.vertices = {v0, v3, v2};
              cells.push_back(a);
              cells.push_back(b);
            }
      }
    Triangulation<dim - 1, dim> mesh;
    mesh.create_triangulation(vertices, cells, SubCellData());
    MembraneProperties props;
    props.axial_stiffness = 5e7;
    Membrane<dim> m(mesh, props);
    for (auto &x : m.position)
      x[0] *= 1.001; // a stretch, so that every element is in tension
    const auto t0 = Clock::now();
    for (unsigned int r = 0; r < reps; ++r)
      m.compute_forces();
    const double fe = seconds_since(t0) / reps / m.n_elements();

    // The hand-written elements on the same nodes and rest geometry.
    std::vector<MembraneMechanics::TriangleReference> reference;
    if constexpr (dim == 3)
      for (const auto &c : m.fe_cells)
        reference.push_back(MembraneMechanics::make_triangle_reference(
          m.rest_vertex[c[0]], m.rest_vertex[c[1]], m.rest_vertex[c[2]]));
    std::vector<Tensor<1, dim>> force(m.n_nodes());
    const auto                  t1 = Clock::now();
    for (unsigned int r = 0; r < reps; ++r)
      {
        for (auto &f : force)
          f = Tensor<1, dim>();
        for (unsigned int e = 0; e < m.n_elements(); ++e)
          {
            const auto &el = m.elements[e];
            if constexpr (dim == 2)
              {
                Tensor<1, 2> f1, f2;
                m.tension[e]
                  = MembraneMechanics::cable_forces(m.position[el[0]],
                                                    m.position[el[1]],
                                                    m.rest_size[e],
                                                    props.axial_stiffness,
                                                    f1,
                                                    f2);
                force[el[0]] += f1;
                force[el[1]] += f2;
              }
            else
              {
                std::array<Tensor<1, 3>, 3> f;
                const auto                  r
                  = MembraneMechanics::triangle_forces(reference[e],
                                                       m.position[el[0]],
                                                       m.position[el[1]],
                                                       m.position[el[2]],
                                                       props.axial_stiffness,
                                                       props.poisson_ratio,
                                                       f);
                m.tension[e] = r.major_principal;
                for (unsigned int k = 0; k < 3; ++k)
                  force[el[k]] += f[k];
              }
          }
      }
    const double hand = seconds_since(t1) / reps / m.n_elements();

    props.element_degree = 2;
    Membrane<dim> m2(mesh, props);
    for (auto &x : m2.position)
      x[0] *= 1.001;
    const auto t2 = Clock::now();
    for (unsigned int r = 0; r < reps; ++r)
      m2.compute_forces();
    const double fe2 = seconds_since(t2) / reps / m2.fe_cells.size();
    std::cout << "BENCH " << name << " elements=" << m.n_elements()
              << " fe_degree1_ns_per_element=" << std::setprecision(4)
              << 1e9 * fe << " hand_written_ns_per_element=" << 1e9 * hand
              << " ratio=" << fe / hand
              << " fe_degree2_ns_per_cell=" << 1e9 * fe2 << std::endl;
  }

  // Runs one case and returns the baseline's speed (0 if the case is
  // filtered out); a case that differs
  // from an earlier one only in fsgmpm settings passes that baseline in
  // (@p known_baseline > 0) instead of running the same stock code again.
  template <int dim>
  double
  run_case(const std::string &name,
           const unsigned int steps,
           const std::string &prm_text       = scene<dim>(),
           const double       known_baseline = 0)
  {
    if (name.find(case_filter) == std::string::npos)
      return 0.;
    // The memory the case holds: resident before it and at its end (the
    // grid and its deal.II mesh included). The memory of earlier cases is
    // given back to the system first (glibc keeps freed blocks otherwise,
    // and this case would reuse them unseen).
    malloc_trim(0);
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double       resident_before = 1024. * memory.VmRSS;
    auto               prm             = test_tools::make_parameters(prm_text);
    Simulator<dim>     sim(*prm);
    const unsigned int n = sim.get_particles().size();
    // One warm-up step, then the timed steps.
    sim.advance();
    const std::vector<double> before = sim.get_stage_seconds();
    const auto                t0     = Clock::now();
    for (unsigned int s = 0; s < steps; ++s)
      AssertThrow(sim.advance(), ExcMessage("benchmark run stopped early"));
    const double wall = seconds_since(t0);
    const double ups  = double(n) * steps / wall;
    const double bpp  = sim.get_particles().bytes_per_particle()
                       + sim.get_grid_memory_per_particle();
    Utilities::System::get_memory_stats(memory);
    const double resident = (1024. * memory.VmRSS - resident_before) / n;
    const double baseline
      = known_baseline > 0
          ? known_baseline
          : baseline_updates_per_second(sim, std::max(2u, steps / 5));
    std::cout << "BENCH " << name << " dim=" << dim << " particles=" << n
              << " steps=" << steps
              << " updates_per_second=" << std::setprecision(4) << ups
              << " bytes_per_particle=" << std::setprecision(4) << bpp
              << " resident_bytes_per_particle=" << resident
              << " baseline_updates_per_second=" << baseline
              << " speedup=" << ups / baseline
              << " threads=" << MultithreadInfo::n_threads() << std::endl;
    const auto &names = Simulator<dim>::stage_names();
    for (unsigned int s = 0; s < names.size(); ++s)
      std::cout << "STAGE " << name << " " << names[s] << "_ms_per_step="
                << 1e3 * (sim.get_stage_seconds()[s] - before[s]) / steps
                << std::endl;
    return baseline;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      const unsigned int steps    = (argc > 1) ? std::stoi(argv[1]) : 50;
      case_filter                 = (argc > 2) ? argv[2] : "";
      const double block_baseline = run_case<2>("elastic_block_2d", steps);
      // The internal force from the nodal stress projection:
      // the second pass over the cells and the per-point strain rate.
      const std::string projection = "subsection Simulation\n"
                                     "  set Stress integration = nodal "
                                     "projection\n"
                                     "end\n";
      run_case<2>("elastic_block_2d_projection",
                  steps,
                  scene<2>() + projection,
                  block_baseline);
      const double dam_break_baseline
        = run_case<2>("dam_break_2d", steps, dam_break_scene());
      // The same with APIC transfers (the cost of the affine velocity).
      // Its own baseline: the stock loops visit every cell.
      run_case<2>("dam_break_2d_wide_tank", steps, dam_break_scene_wide_tank());
      run_case<2>("dam_break_2d_apic",
                  steps,
                  dam_break_scene()
                    + "subsection Simulation\n"
                      "  set Velocity transfer = APIC\n"
                      "end\n",
                  dam_break_baseline);
      // The same with NMD and ANP weights capped per cell (the extra pass
      // over each cell's points in both averages).
      run_case<2>("dam_break_2d_capped",
                  steps,
                  dam_break_scene()
                    + "subsection Bodies\n"
                      "  subsection Body 0\n"
                      "    set Smoothing weights = capped cell volume\n"
                      "  end\n"
                      "end\n",
                  dam_break_baseline);
      run_case<2>("dam_break_2d_projection",
                  steps,
                  dam_break_scene() + projection,
                  dam_break_baseline);
      const double block_3d_baseline
        = run_case<3>("elastic_block_3d", std::max(2u, steps / 2));
      run_case<3>("elastic_block_3d_projection",
                  std::max(2u, steps / 2),
                  scene<3>() + projection,
                  block_3d_baseline);
      run_case<3>("dam_break_3d",
                  std::max(2u, steps / 2),
                  dam_break_scene_3d());
      // The membrane: the geotube as shipped (slip, degree 1),
      // and the paper's no-slip coupling at degree 1 (elements of 0.9
      // cells) and 2 (cells of 1.8 grid cells: the same nodes).
      const std::string no_slip
        = "subsection Membrane\n"
          "  set Tangential coupling = no-slip\n"
          "  set Split length = 1\n"
          "end\n"
          "subsection Simulation\n"
          "  set Stress integration = nodal projection\n"
          "end\n";
      const double geotube_baseline
        = run_case<2>("geotube_2d", steps, geotube_scene(""));
      run_case<2>("geotube_2d_no_slip",
                  steps,
                  geotube_scene(no_slip
                                + "subsection Membrane\n"
                                  "  set Element size = 0.144\n"
                                  "end\n"),
                  geotube_baseline);
      run_case<2>("geotube_2d_no_slip_degree2",
                  steps,
                  geotube_scene(no_slip
                                + "subsection Membrane\n"
                                  "  set Element size = 0.288\n"
                                  "  set Element degree = 2\n"
                                  "end\n"),
                  geotube_baseline);
      membrane_forces_case<2>(4000, 200);
      membrane_forces_case<3>(60, 50);
    }
  catch (std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 1;
    }
  return 0;
}
