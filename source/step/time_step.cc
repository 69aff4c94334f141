#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fsgmpm
{
  namespace Stages
  {
    namespace
    {
      /**
       * The bounds of the occupied cells [b, e) (numbers in
       * occupied_cells), whose points must be one range. Each point's
       * signal speed in loops over whole runs of one material across the
       * cells, which the compiler vectorises (two points per division and
       * square root, which bound this stage), then each cell's maximum and
       * sum over its points in order: cell_dt[i] = h / max_p s_p, and
       * (*cell_stiffness)[c] = sum_p V_p rho_p s_p^2 if given.
       */
      template <int dim>
      void
      bound_cells(const BackgroundGrid<dim>                    &grid,
                  const ParticleStore<dim>                     &particles,
                  const std::vector<std::unique_ptr<Material>> &materials,
                  const unsigned int                            b,
                  const unsigned int                            e,
                  std::vector<double>                          &cell_dt,
                  std::vector<double>                          *cell_stiffness)
      {
        const auto        &cells = particles.occupied_cells;
        const unsigned int first = particles.cell_begin(cells[b]);
        const unsigned int n     = particles.cell_end(cells[e - 1]) - first;
        thread_local std::vector<double> rho, signal, point_h, cell_h;
        if (rho.size() < n)
          {
            rho.resize(n);
            signal.resize(n);
            point_h.resize(n);
          }
        cell_h.resize(e - b);
        for (unsigned int i = b; i < e; ++i)
          {
            const unsigned int c = cells[i];
            cell_h[i - b]
              = CellLoops::geometry(grid, particles, c).min_altitude();
            std::fill(point_h.begin() + (particles.cell_begin(c) - first),
                      point_h.begin() + (particles.cell_end(c) - first),
                      cell_h[i - b]);
          }
        const double         *mass     = particles.mass.data() + first;
        const double         *volume   = particles.volume.data() + first;
        const Tensor<1, dim> *velocity = particles.velocity.data() + first;
        for (unsigned int k = 0; k < n;)
          {
            const unsigned int last
              = particles.material_run_end(first + k, first + n) - first;
            const Material &mat = *materials[particles.material_id[first + k]];
            for (unsigned int q = k; q < last; ++q)
              rho[q] = mass[q] / volume[q];
            mat.wave_speeds(rho.data() + k, signal.data() + k, last - k);
            // Wave speed, advection, and the viscous limit 2 d nu/h folded
            // into one signal speed.
            const double viscous = 2. * dim * mat.viscosity();
            for (unsigned int q = k; q < last; ++q)
              signal[q] = signal[q] + velocity[q].norm()
                          + viscous / (rho[q] * point_h[q]);
            k = last;
          }
        for (unsigned int i = b; i < e; ++i)
          {
            const unsigned int c     = cells[i];
            const unsigned int begin = particles.cell_begin(c) - first;
            const unsigned int end   = particles.cell_end(c) - first;
            double             speed = 0;
            for (unsigned int q = begin; q < end; ++q)
              speed = std::max(speed, signal[q]);
            cell_dt[i] = (speed > 0) ? cell_h[i - b] / speed
                                     : std::numeric_limits<double>::max();
            if (cell_stiffness != nullptr)
              {
                // V_p M_p with the P-wave modulus M_p = rho s^2 of the same
                // signal speed, for the nodal bound.
                double stiffness = 0;
                for (unsigned int q = begin; q < end; ++q)
                  stiffness += volume[q] * rho[q] * signal[q] * signal[q];
                (*cell_stiffness)[c] = stiffness;
              }
          }
      }
    } // namespace



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
        [&](const unsigned int chunk_begin, const unsigned int chunk_end) {
          // By cells whose points are one range (after a sort all of them,
          // but with MPI the ghost points come after the owned ones), up
          // to some 512 points, so that the buffers stay in the L1 cache.
          for (unsigned int b = chunk_begin, e; b < chunk_end; b = e)
            {
              e = b + 1;
              while (e < chunk_end
                     && particles.cell_begin(cells[e])
                          == particles.cell_end(cells[e - 1])
                     && particles.cell_end(cells[e - 1])
                            - particles.cell_begin(cells[b])
                          < 512)
                ++e;
              bound_cells(
                grid, particles, materials, b, e, cell_dt, cell_stiffness);
            }
        },
        64);
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
