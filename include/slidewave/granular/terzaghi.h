#ifndef slidewave_granular_terzaghi_h
#define slidewave_granular_terzaghi_h

namespace slidewave
{
  namespace granular
  {
    /**
     * Terzaghi's one-dimensional consolidation (paper 002, §4.1; ../shared/VERIFICATION.md):
     * a layer of height H drained at one face and impervious at the other, loaded at
     * t = 0 by p0, carries the load first in its pore water (u = p0) and then drains:
     *
     *   u / p0 = sum_{m >= 0} (2 / M) sin(M Z) exp(-M^2 T_v),   M = (2m + 1) pi / 2,
     *
     * Z = z / H the depth from the drained face, T_v = c_v t / H^2 and, for a skeleton of
     * constrained modulus E_oed = E (1 - nu) / ((1 + nu) (1 - 2 nu)) and intrinsic
     * permeability k in water of viscosity mu, c_v = k E_oed / mu (the k_hydraulic /
     * (m_v gamma_w) of soil mechanics). The sum runs until its terms are below 1e-16.
     */
    double
    terzaghi_pore_pressure(double depth_ratio, double time_factor);

    /** The average degree of consolidation U = 1 - sum 2 / M^2 exp(-M^2 T_v) (the share
     *  of the load carried by the skeleton, averaged over the height). */
    double
    terzaghi_average_degree(double time_factor);

    /** c_v = k E_oed / mu [m^2/s] of a skeleton of Young's modulus @p youngs_modulus,
     *  Poisson's ratio @p poisson_ratio, intrinsic permeability @p permeability in water
     *  of viscosity @p viscosity. */
    double
    consolidation_coefficient(double youngs_modulus,
                              double poisson_ratio,
                              double permeability,
                              double viscosity);
  } // namespace granular
} // namespace slidewave

#endif
