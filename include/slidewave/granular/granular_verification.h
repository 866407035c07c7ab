#ifndef slidewave_granular_granular_verification_h
#define slidewave_granular_granular_verification_h

#include <array>
#include <fstream>
#include <memory>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/granular/granular_water_parameters.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/io/checkpoint_record.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/soil/material_point_parameters.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    /**
     * The exact solutions of a granular-water scene ('Granular water/Verification'):
     *
     * - Terzaghi: at each 'Time factors' T_v the largest error of the nodes' pore pressure
     *   in the column against the series (terzaghi.h), relative to the load, and the
     *   average degree of consolidation U = 1 - integral p / (p0 area) against the exact
     *   one; each profile (nodes' rows averaged) into terzaghi_profiles.csv;
     * - at rest: at the end, the nodes' pore pressure against rho^w g (top - y), relative to
     *   rho^w g H, and the points' effective stresses against the buoyant geostatic state,
     *   relative to its value at the base;
     * - seepage: at the end, the pressure gradient of the nodes in the middle half of the
     *   layer (least squares, with the odd-even mode between rows of nodes fitted apart)
     *   against the steady gradient C U / n_0^2 of the drag law
     *   (DragLaw) at the top inflow's superficial velocity U, relative to it;
     * - settling: a uniform suspension (porosity n_0 above 'Suspension porosity' n_s, Darcy
     *   drag) from the grid's bottom to 'Column height' H in a closed column of water falls
     *   at v(t) = v_inf (1 - exp(-t / tau)) while the bed it forms at n_s rises from the
     *   floor; at the end, before the bed reaches them, the displacement of the row of
     *   points started nearest below 0.7 H against v_inf (t - tau (1 - exp(-t / tau))),
     *   relative to it; after, the points' volume over the column's width against
     *   max(H - fall, H (1 - n_0) / (1 - n_s)) (the bed under what is left of the
     *   suspension, then the bed alone), relative to it.
     *
     * Its state (the profiles so far) goes into the checkpoints.
     */
    class GranularVerification
    {
    public:
      GranularVerification(const SceneParameters               &scene,
                           const soil::MaterialPointParameters &soil_parameters,
                           const fluid::FreeSurfaceParameters  &fluid_parameters,
                           const GranularWaterParameters       &parameters);

      /** Refuses, before the first step, a settling column with no points below 0.7 of
       *  'Column height' (InputError; collective); nothing for the other cases. */
      void
      check_points(const particles::PointCloud &cloud) const;

      /** terzaghi_profiles.csv: created, or continued by a resumed run (rank 0). */
      void
      open_files(bool append);

      /** Records the profiles due by @p time from the water's @p flow (collective). */
      void
      after_step(double time, const grid::FiniteElementField &flow);

      /** The verification's columns of a statistics row (collective). */
      void
      add_statistics(Statistics                     &statistics,
                     double                          time,
                     const grid::FiniteElementField &flow) const;

      /** Prints the comparison at @p time (rank 0); returns whether it is within
       *  'Tolerance' (collective). */
      bool
      finish(const grid::FiniteElementField &flow,
             const particles::PointCloud    &cloud,
             double                          time) const;

      /** The files that grow during the run (for the checkpoints). */
      std::vector<std::string>
      growing_files() const;

      void
      save(io::CheckpointRecord &record) const;

      void
      load(const io::CheckpointRecord &record);

      /** Seepage: the vertical component of the top's 'Inflow velocity' at the middle of
       *  the top at @p end_time (negative: downward), the superficial velocity whose exact
       *  gradient the check compares with. */
      static double
      seepage_inflow(const fluid::FreeSurfaceParameters &fluid_parameters, double end_time);

    private:
      /** T_v of time @p t. */
      double
      time_factor(double t) const;

      /** Terzaghi: the largest relative error of the nodes' pore pressure and U from the
       *  pore pressure at @p time (collective); the owned nodes' (y, p, exact) appended to
       *  @p samples unless null. */
      std::array<double, 2>
      terzaghi_errors(const grid::FiniteElementField &flow,
                      double                          time,
                      std::vector<double>            *samples) const;

      /** The profile of @p samples (every rank's) at @p tv (collective). */
      void
      write_profile(double tv, double time, const std::vector<double> &samples) const;

      /** At rest: the pore pressure's and the effective stresses' errors (collective). */
      std::array<double, 2>
      at_rest_errors(const grid::FiniteElementField &flow,
                     const particles::PointCloud    &cloud) const;

      /** Seepage: the measured and the exact pressure gradient [Pa/m], the exact one's
       *  Darcy part and the amplitude [Pa] of the pressure's odd-even mode between rows of
       *  nodes (collective). */
      std::array<double, 4>
      seepage_gradients(const grid::FiniteElementField &flow) const;

      /** Settling: the measured and the exact value (a row's fall before the bed reaches
       *  it, the bed's height after) and whether the bed reached it (collective). */
      std::array<double, 3>
      settling_values(const particles::PointCloud &cloud, double time) const;

      /** Settling: the initial height of the row of points that started highest at or
       *  below 0.7 of 'Column height'; refuses (InputError) a column with no points there
       *  (collective). */
      double
      settling_row(const particles::PointCloud &cloud) const;

      const SceneParameters               &scene;
      const soil::MaterialPointParameters &soil_parameters;
      const fluid::FreeSurfaceParameters  &fluid_parameters;
      const GranularWaterParameters       &parameters;
      /** Per time factor reached: T_v, largest pore pressure error, U from the pressure,
       *  U exact. */
      std::vector<std::array<double, 4>> profiles;
      std::unique_ptr<std::ofstream>     profile_file;
    };
  } // namespace granular
} // namespace slidewave

#endif
