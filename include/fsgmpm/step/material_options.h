#ifndef fsgmpm_step_material_options_h
#define fsgmpm_step_material_options_h

namespace fsgmpm
{
  /**
   * Which of the volumetric-locking and free-surface stages act on the
   * points of one material (paper Sections 3 and 4). A scene only pays for
   * what its bodies switch on.
   */
  struct MaterialOptions
  {
    bool nmd = false; ///< nodal mixed discretisation, Eqs. (22)-(25)
    bool anp = false; ///< average nodal pressure, Eqs. (28)-(29)
    /**
     * Weights of the NMD and ANP nodal averages. false: each point's volume
     * (paper, Eqs. 24 and 29). true: each cell's points together weigh
     * min(sum_p V_p, V_c), so a cell whose points have packed beyond its
     * volume does not outweigh its neighbours (doc/geocontainer_validation.md
     * Section 6: removes most of the water's point compaction).
     */
    bool capped_weights = false;
    /**
     * Stabilisation of the nodal averages, 0 <= alpha <= 1: the share of a
     * cell's own volumetric strain rate kept beside NMD's smoothed one, and
     * of a point's own pressure beside ANP's average, eps_v = (1 - alpha)
     * S(eps_v) + alpha eps_v and p = (1 - alpha) S(p) + alpha p with the
     * same weights, so that the stress power still equals the power of the
     * nodal forces. The averages S alone have a null space (cell patterns
     * of compression and expansion that average out at every node) in which
     * the points can pack without any pressure: under gravity they do, and
     * still water starts to slosh (doc/water_validation.md, "Still water").
     * alpha gives those patterns the stiffness alpha K. With the nodal
     * stress projection (which replaces NMD and ANP) the same share of a
     * cell's own volumetric rate and of its points' mean stress is kept
     * beside the projected fields (Stages::p2g,
     * Stages::stabilised_point_velocity_gradient).
     */
    double smoothing_stabilisation = 0;
    /// ANP back-mapping: false = element mean (paper), true = interpolate.
    bool   anp_interpolate        = false;
    bool   detect_free_surface    = false; ///< volume-fraction form, Eq. (33)
    double free_surface_threshold = 0.6;   ///< f_c
  };
} // namespace fsgmpm

#endif
