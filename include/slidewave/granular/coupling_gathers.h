#ifndef slidewave_granular_coupling_gathers_h
#define slidewave_granular_coupling_gathers_h

#include <slidewave/grid/finite_element_field.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <utility>

namespace slidewave
{
  namespace granular
  {
    /**
     * Where the owned cells' values (in tree order) of the fields the skeleton's exchange
     * with the water reads sit in their vectors (linear_algebra::CellGather): the fluid
     * fraction, the inverse permeability, the solid's flux, the flow (velocity and
     * pressure, states 0 and 1 share a layout) and the phase field. Kept by the exchange's
     * classes between steps, so that a cell's values are read by plain array accesses
     * instead of FEValues' lookups per degree of freedom in Trilinos vectors; the values
     * are summed as FEValues sums them (linear_algebra::evaluate_scalar and friends), so
     * the numbers are the same bit for bit.
     */
    struct CouplingGathers
    {
      linear_algebra::CellGather fraction, permeability, solid, flow, phase;

      /** Forgets every position (the grid changed). */
      void
      clear()
      {
        for (linear_algebra::CellGather *g : {&fraction, &permeability, &solid, &flow, &phase})
          g->clear();
      }

      /** Builds the positions of each given field (null: skipped) that has none, or whose
       *  layout changed. */
      void
      prepare(const grid::FiniteElementField *fraction_field,
              const grid::FiniteElementField *permeability_field,
              const grid::FiniteElementField *solid_field,
              const grid::FiniteElementField *flow_field,
              const grid::FiniteElementField *phase_field)
      {
        const std::pair<linear_algebra::CellGather *, const grid::FiniteElementField *> pairs[]
          = {{&fraction, fraction_field},
             {&permeability, permeability_field},
             {&solid, solid_field},
             {&flow, flow_field},
             {&phase, phase_field}};
        for (const auto &[gather, field] : pairs)
          if (field != nullptr && (gather->empty() || !gather->matches(field->values(0))))
            gather->reinit(field->dof_handler(), field->values(0));
      }
    };
  } // namespace granular
} // namespace slidewave

#endif
