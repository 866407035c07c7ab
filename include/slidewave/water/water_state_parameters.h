#ifndef slidewave_water_water_state_parameters_h
#define slidewave_water_water_state_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/table_1d.h>
#include <slidewave/water/water_mesh.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace water
  {
    /**
     * The bed elevation B(x) of subsection "Bed": a function of x (and of t for a moving
     * bed) or a table. In a water scene it is the bed; in a coupled scene it is the fixed
     * terrain under and beside the soil.
     */
    class BedElevation
    {
    public:
      /** Declares the entries of subsection "Bed" (the handler must be inside it). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads subsection "Bed"; @p path names it in error messages. */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const SceneParameters    &scene);

      bool
      time_dependent() const
      {
        return is_time_dependent;
      }

      /** B at @p x and time @p t (t matters only for a time-dependent function). */
      double
      value(double x, double t) const;

      /** B at the centres of @p mesh at time @p t; throws InputError where not finite. */
      std::vector<double>
      sample(const WaterMesh &mesh, double t) const;

    private:
      std::string                       path;
      std::unique_ptr<ParsedExpression> expression;
      std::unique_ptr<Table1D>          table;
      bool                              is_time_dependent = false;
    };



    /**
     * The initial water of subsection "Initial condition": the depth h(x) or the free
     * surface eta(x) (then h = max(eta - B, 0)), and the velocity u(x).
     */
    class InitialCondition
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** Depth and discharge per cell of @p mesh over the bed @p bed at time @p t; throws
       *  InputError on non-finite values or negative depths. */
      void
      evaluate(const WaterMesh           &mesh,
               const std::vector<double> &bed,
               double                     t,
               std::vector<double>       &depth,
               std::vector<double>       &discharge) const;

    private:
      std::string                       path, level_text;
      std::unique_ptr<ParsedExpression> level, velocity;
      bool                              is_free_surface = false;
    };
  } // namespace water
} // namespace slidewave

#endif
