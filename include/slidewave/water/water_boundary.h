#ifndef slidewave_water_water_boundary_h
#define slidewave_water_water_boundary_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/table_1d.h>
#include <string>

namespace slidewave
{
  namespace water
  {
    /**
     * What happens at one end of the water column. The finite-volume solver asks it for the
     * state just outside the domain (the ghost state) given the state just inside, and
     * solves the Riemann problem between the two.
     *
     * - wall: mirror state (same depth, opposite velocity); no water crosses.
     * - transmissive: copy of the inside state (waves leave with little reflection).
     * - discharge: a given discharge q(t) per unit width [m^2/s], positive in the +x
     *   direction (so q > 0 enters at the left end and leaves at the right end). The ghost
     *   depth is the inside depth, or the critical depth (q^2/g)^(1/3) when the inside is dry.
     * - depth: a given depth h_b(t) [m]; the ghost velocity follows from the Riemann invariant
     *   of the characteristic that leaves the domain (u -+ 2 sqrt(g h) conserved).
     *
     * q(t) and h_b(t) are expressions of t or a CSV time series (t, value).
     */
    class WaterBoundary
    {
    public:
      enum class Type
      {
        wall,
        transmissive,
        discharge,
        depth
      };

      /** Declares the entries of one boundary subsection. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads them (the handler inside the subsection); @p path names it in errors. */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const SceneParameters    &scene);

      /** A wall; what a solver built without parameters gets. */
      WaterBoundary() = default;

      explicit WaterBoundary(Type type);

      Type
      type() const
      {
        return boundary_type;
      }

      /**
       * The ghost state (depth and velocity) outside the domain, given the depth and
       * velocity @p h_inside, @p u_inside just inside, at time @p t. @p left_end tells which
       * end this boundary is.
       */
      void
      ghost_state(double  h_inside,
                  double  u_inside,
                  double  t,
                  double  gravity,
                  double  dry_depth,
                  bool    left_end,
                  double &h_ghost,
                  double &u_ghost) const;

    private:
      double
      prescribed_value(double t) const;

      Type                              boundary_type = Type::wall;
      std::shared_ptr<ParsedExpression> expression;
      std::shared_ptr<Table1D>          series;
    };
  } // namespace water
} // namespace slidewave

#endif
