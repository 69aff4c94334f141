#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <limits>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    double
    stable_time_step(const BackgroundGrid<dim>                    &grid,
                     const ParticleStore<dim>                     &particles,
                     const std::vector<std::unique_ptr<Material>> &materials,
                     const double                                  courant,
                     std::vector<double> *cell_stiffness)
    {
      const auto         &cells = particles.occupied_cells;
      std::vector<double> cell_dt(cells.size());
      if (cell_stiffness != nullptr)
        cell_stiffness->assign(grid.n_cells(), 0.);
      CellLoops::parallel_range(
        cells.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int i = b; i < e; ++i)
            {
              const unsigned int c = cells[i];
              const double       h
                = CellLoops::geometry(grid, particles, c).min_altitude();
              double             speed = 0, stiffness = 0;
              const unsigned int end = particles.cell_end(c);
              for (unsigned int p = particles.cell_begin(c); p < end;)
                {
                  // A run of points of one material: its viscous term's
                  // numerator once, not a second virtual call per point.
                  const unsigned int last = particles.material_run_end(p, end);
                  const Material    &mat = *materials[particles.material_id[p]];
                  const double       viscous = 2. * dim * mat.viscosity();
                  for (; p < last; ++p)
                    {
                      const double rho
                        = particles.mass[p] / particles.volume[p];
                      // Wave speed, advection, and the viscous limit
                      // 2 d nu/h folded into one signal speed.
                      const double s = mat.wave_speed(rho)
                                       + particles.velocity[p].norm()
                                       + viscous / (rho * h);
                      speed = std::max(speed, s);
                      // V_p M_p with the P-wave modulus M_p = rho s^2 of the
                      // same signal speed, for the nodal bound.
                      stiffness += particles.volume[p] * rho * s * s;
                    }
                }
              cell_dt[i]
                = (speed > 0) ? h / speed : std::numeric_limits<double>::max();
              if (cell_stiffness != nullptr)
                (*cell_stiffness)[c] = stiffness;
            }
        },
        16);
      double dt = std::numeric_limits<double>::max();
      for (const double d : cell_dt)
        dt = std::min(dt, d);
      return courant * dt;
    }

    template double
    stable_time_step<2>(const BackgroundGrid<2> &,
                        const ParticleStore<2> &,
                        const std::vector<std::unique_ptr<Material>> &,
                        const double,
                        std::vector<double> *);
    template double
    stable_time_step<3>(const BackgroundGrid<3> &,
                        const ParticleStore<3> &,
                        const std::vector<std::unique_ptr<Material>> &,
                        const double,
                        std::vector<double> *);
  } // namespace Stages
} // namespace fsgmpm
