#ifndef slidewave_fluid_porous_medium_h
#define slidewave_fluid_porous_medium_h

#include <array>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /** The grains' nodes of a skeleton whose nodal momentum the water's solve takes with it
     *  (NodalGrainsCoupling): their layout, hanging nodes and masses m_I (nodal_mass), and
     *  per component 1 on the owned nodes solved for, 0 on the held, hanging and empty
     *  ones. */
    struct NodalGrains
    {
      const grid::NodalWorkspace                         *nodes = nullptr;
      std::array<const grid::NodalWorkspace::Vector *, 2> free{};
    };



    /**
     * A porous solid in the flow: what the granular skeleton of issue 27 (or a fixed porous
     * structure) gives the fluid. Every field is optional (nullptr: none, and nothing of it
     * is evaluated): the fluid fraction n (1 where there is no solid: the effective
     * 1 - theta (1 - n_s) of paper 002 with the solid volume fraction theta), the inverse
     * permeability 1/kappa [1/m^2] (0: no drag) and the solid's flux j = (1 - n) v_s
     * (Q1^2, zero when absent; the solid's velocity at a point is j / (1 - n) there, so that
     * a node the grains barely touch, whose velocity a material point method leaves
     * arbitrary, hands over a flux as small as its grains). With them the momentum and continuity
     * equations read
     *
     *   n rho (du/dt + u_bar . grad u) = -n grad p + div(2 mu n eps(u)) + n rho g
     *                                    - C (u - v_s),    C = n^2 mu / kappa,
     *   div(n u) + div((1 - n) v_s) = 0,
     *
     * the Darcy drag C of a saturated porous medium (paper 002, Eq. 3 without its
     * Forchheimer part); with n = 1 and no drag, the equations of the open water.
     *
     * <h3>A moving skeleton with its momentum eliminated (grain_density > 0)</h3>
     * The skeleton's nodal momentum balance over the step, with the drag and the pressure
     * of the new step (per unit volume, rho_b = rho^s (1 - n) its bulk density),
     *
     *   rho_b (v - v*) / dt = -(1 - n) grad p + C (u - v),
     *
     * with v* the skeleton's velocity after its own forces (stress, gravity, walls) and
     * the old pressure's force -(1 - n) grad p^n (the nodal velocity v^n + dt f / m with
     * the pressure force of the last step), the drag and the pressure increment implicit:
     *
     *   rho_b (v - v*) / dt = -(1 - n) grad (p - p^n) + C (u - v),
     *
     * gives v = (1 - s) v* + s u - Delta (1 - n) grad (p - p^n) with Delta = dt / (rho_b +
     * dt C) and s = C Delta. Put into the water's drag and the mixture's continuity, the
     * water's equations become
     *
     *   n rho du/dt + ... + n grad p + s (1 - n) grad (p - p^n) + C (1 - s) (u - v*) = ...,
     *   div(n u) + div((1 - n) v*)
     *     + div((1 - n)(s (u - v*) - (1 - n) Delta grad (p - p^n))) = 0:
     *
     * the drag against the predicted velocity with the coefficient C rho_b / (rho_b + dt C)
     * (the grains' inertia over the step where the drag is stiff), the share s of the
     * solid's pressure gradient carried by the water, and the Darcy flow through the grains
     * as a pressure diffusion. A skeleton at rest in water at rest stays so exactly (v* =
     * 0 and p = p^n solve the equations), which the elimination of the whole pressure at
     * the quadrature points against a nodal v* would not. The last divergence in weak form, its
     * flux through the boundary neglected (zero at walls, where u, v* and the relative flow are
     * held; at an open side it leaves v = v* there). The skeleton then takes the same step at its
     * nodes (SkeletonFluidExchange, PorousSkeletonModel). Stable at any dt C / rho_b: the water and
     * the grains move together where the drag is stiff (the undrained limit) and separately where
     * it is weak; the explicit coupling (v_s of the old step) is stable only for dt below about
     * rho^s (1 - n) k / mu (doc/granular-water.md).
     */
    struct PorousMedium
    {
      const grid::FiniteElementField *fluid_fraction       = nullptr;
      const grid::FiniteElementField *inverse_permeability = nullptr;
      const grid::FiniteElementField *solid_flux           = nullptr;
      /** rho^s [kg/m^3] of a skeleton whose momentum the flow eliminates; 0: v_s given. */
      double grain_density = 0.;
      /** With grain_density: the grains' nodes, whose momentum the water's solve takes
       *  with it (NodalGrainsCoupling); null: the grains' momentum eliminated at the
       *  quadrature points only. */
      const NodalGrains *nodal_grains = nullptr;

      bool
      active() const
      {
        return fluid_fraction != nullptr || inverse_permeability != nullptr
               || solid_flux != nullptr;
      }
    };



    /** Where the owned cells' values of a PorousMedium's fields (fluid fraction, inverse
     *  permeability, solid flux) sit in their vectors (linear_algebra::CellGather). */
    using PorousMediumGathers = std::array<linear_algebra::CellGather, 3>;



    /** The coefficients of a porous medium at one quadrature point (PorousMedium). */
    struct PorousCoefficients
    {
      /** The fluid fraction and its gradient. */
      double               n = 1.;
      dealii::Tensor<1, 2> grad_n;
      /** The drag coefficient of the water's momentum [kg/(m^3 s)]: C, or C (1 - s). */
      double drag = 0.;
      /** C = n^2 mu / kappa itself. */
      double drag_coefficient = 0.;
      /** The solid's velocity the drag acts against: v_s, or v*. */
      dealii::Tensor<1, 2> v_s;
      /** div((1 - n) v_s), known (v_s or v*; tested by q). */
      double solid_divergence = 0.;
      /** - s (1 - n) v*: the known part of the solid's correction flux s (1 - n)(u - v*),
       *  tested by grad q (its divergence in weak form). */
      dealii::Tensor<1, 2> correction_flux;
      /** s (1 - n): the share of the solid's pressure gradient and of its velocity u. */
      double pressure_share = 0.;
      /** (1 - n)^2 Delta: the Darcy flow's pressure diffusion [m^3 s / kg]. */
      double pressure_diffusion = 0.;
    };



    /**
     * Evaluates a PorousMedium's fields on a cell of the grid at the points of a
     * quadrature and makes the coefficients of the water's equations (PorousCoefficients).
     */
    class PorousMediumValues
    {
    public:
      /** The gathers, if given, read the medium's fields on the owned cells in tree order
       *  (reinit() with a cell number); the caller keeps them between steps (built here
       *  when empty, rebuilt when a field's layout changed). */
      PorousMediumValues(const grid::BackgroundGrid  &grid,
                         const PorousMedium          &medium,
                         const dealii::Quadrature<2> &quadrature,
                         const dealii::Quadrature<1> &face_quadrature,
                         PorousMediumGathers         *gathers = nullptr);

      /** The coefficients on @p cell (any DoFHandler on the grid's triangulation) at a
       *  step of length @p dt, with the viscosity mu(q) of each quadrature point. */
      template <class Cell>
      void
      reinit(const Cell &cell, const double dt, const std::vector<double> &mu)
      {
        evaluate(cell, -1, dt, mu);
      }

      /** The same on the owned cell @p cell numbered @p cell_number in tree order
       *  (grid::for_each_owned_cell_in_tree_order), its fields read by the gathers: the
       *  same numbers, bit for bit, without a lookup per degree of freedom. */
      template <class Cell>
      void
      reinit(const Cell                &cell,
             const unsigned int         cell_number,
             const double               dt,
             const std::vector<double> &mu)
      {
        evaluate(cell, -1, dt, mu, static_cast<int>(cell_number));
      }

      /** The same on the face @p face of @p cell (face quadrature), into face(q). */
      template <class Cell>
      void
      reinit_face(const Cell                &cell,
                  const unsigned int         face,
                  const double               dt,
                  const std::vector<double> &mu)
      {
        evaluate(cell, static_cast<int>(face), dt, mu);
      }

      const PorousCoefficients &
      operator[](const unsigned int q) const
      {
        return coefficients[q];
      }

      /** The fluid fraction at the cell's vertices (after a reinit() with a cell number). */
      const std::vector<double> &
      vertex_fluid_fraction() const
      {
        return dofs_fraction;
      }

      const PorousCoefficients &
      face(const unsigned int q) const
      {
        return face_coefficients[q];
      }

      /**
       * On an open side (after reinit_face()), the flux of the solid's correction through
       * it, s (1 - n)(u - v*) - (1 - n)^2 Delta grad (p - p^n), tested by the continuity's
       * q: into the flow's cell matrix and right-hand side (@p fv_face on that face of the
       * flow's element, @p grad_p_n the old pressure's gradient at its points).
       */
      void
      add_open_side_flux(const dealii::FEFaceValues<2>           &fv_face,
                         const std::vector<dealii::Tensor<1, 2>> &grad_p_n,
                         dealii::FullMatrix<double>              &local_matrix,
                         dealii::Vector<double>                  &local_rhs) const;

    private:
      /** On @p cell of the grid (any DoFHandler's iterator on its triangulation converts)
       *  or one of its faces (@p face >= 0); by the gathers with a @p cell_number (>= 0). */
      void
      evaluate(const dealii::Triangulation<2>::active_cell_iterator &cell,
               int                                                   face,
               double                                                dt,
               const std::vector<double>                            &mu,
               int                                                   cell_number = -1);

      const grid::BackgroundGrid              &grid;
      const PorousMedium                      &medium;
      std::unique_ptr<dealii::FEValues<2>>     fv_scalar, fv_solid;
      std::unique_ptr<dealii::FEFaceValues<2>> ff_scalar, ff_solid;
      std::vector<double>                      n, inverse_permeability, div_flux;
      std::vector<dealii::Tensor<1, 2>>        grad_n, flux;
      std::vector<PorousCoefficients>          coefficients, face_coefficients;
      PorousMediumGathers                     *gathers;
      /** A cell's values of the fields, and the solid flux's shape functions' components. */
      std::vector<double>       dofs_fraction, dofs_permeability, dofs_flux;
      std::vector<unsigned int> flux_component;
    };
  } // namespace fluid
} // namespace slidewave

#endif
