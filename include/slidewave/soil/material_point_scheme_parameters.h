#ifndef slidewave_soil_material_point_scheme_parameters_h
#define slidewave_soil_material_point_scheme_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace slidewave
{
  namespace soil
  {
    struct MaterialPointParameters;

    /** Declares the transfer scheme ('Shape functions', 'Update scheme', 'FLIP fraction',
     *  'Velocity transfer'), the time step ('Time step multiplier', 'Fixed time step'),
     *  'B-bar' and 'Gravity' in the handler's current subsection. */
    void
    declare_scheme_parameters(dealii::ParameterHandler &prm);

    /** Reads them into @p parameters; @p path names the subsection in the messages. Throws
     *  an InputError for a multiplier outside (0, 1/sqrt(2)], a gravity that is not two
     *  numbers, and a 'FLIP fraction' other than its default with 'Velocity transfer =
     *  apic' (which has no blend and would ignore it). */
    void
    parse_scheme_parameters(dealii::ParameterHandler &prm,
                            const std::string        &path,
                            MaterialPointParameters  &parameters);
  } // namespace soil
} // namespace slidewave

#endif
