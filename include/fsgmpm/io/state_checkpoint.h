#ifndef fsgmpm_io_state_checkpoint_h
#define fsgmpm_io_state_checkpoint_h

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/io/checkpoint_file.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/step/membrane_coupling.h>

namespace fsgmpm
{
  /**
   * The material points', the membrane's and its coupling's whole state in
   * a checkpoint (entries "particles/..." and "membrane/..."). Every array that
   * a step reads before it rewrites it is stored, bit for bit.
   */
  namespace StateCheckpoint
  {
    /// The points, each with its cell's number in the whole grid (@p grid
    /// may be a process's window).
    template <int dim>
    void
    save(CheckpointWriter          &out,
         const ParticleStore<dim>  &particles,
         const BackgroundGrid<dim> &grid);

    /// Replaces the points; rebuilds the per-cell index (@p n_cells cells,
    /// those of the whole grid: the points' cells are numbered there).
    template <int dim>
    void
    load(const CheckpointReader &in,
         ParticleStore<dim>     &particles,
         const unsigned int      n_cells);

    template <int dim>
    void
    save(CheckpointWriter &out, const Membrane<dim> &membrane);

    /// Replaces the membrane's nodes, elements and rings (splitting may
    /// have changed them since the scene was built).
    template <int dim>
    void
    load(const CheckpointReader &in, Membrane<dim> &membrane);

    /// The coupling's transfer weights ("membrane/weights").
    template <int dim>
    void
    save(CheckpointWriter &out, const MembraneCoupling<dim> &coupling);

    template <int dim>
    void
    load(const CheckpointReader &in, MembraneCoupling<dim> &coupling);
  } // namespace StateCheckpoint
} // namespace fsgmpm

#endif
