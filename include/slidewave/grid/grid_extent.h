#ifndef slidewave_grid_grid_extent_h
#define slidewave_grid_grid_extent_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <string>

namespace slidewave
{
  namespace grid
  {
    /**
     * The rectangle of a background grid and its square cell size: the entries 'Lower
     * left', 'Upper right' and 'Cell size' of a "Grid" subsection, checked (a non-empty
     * rectangle, a cell size that divides its sides, at most 10^7 cells).
     */
    struct GridExtent
    {
      /** Declares the entries (the handler inside the "Grid" subsection). */
      static void
      declare_parameters(dealii::ParameterHandler &prm,
                         const std::string        &default_cell_size = "0.05");

      /** Reads and checks them; @p path names the subsection in errors. With
       *  @p with_corners false only the cell size is read: the corners come later, from
       *  fit_inside(). */
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       bool                      with_corners = true);

      /** The largest grid of whole cells, its corners on multiples of the cell size,
       *  inside [@p lower, @p upper]; checked as the entries are. Errors name the entry
       *  'Extent' of the subsection @p path, set to @p extent. */
      void
      fit_inside(const dealii::Point<2> &lower,
                 const dealii::Point<2> &upper,
                 const std::string      &path,
                 const std::string      &extent);

      dealii::Point<2> lower_left, upper_right;
      double           cell_size = 0.05;

    private:
      /** At most 10^7 cells. */
      void
      check_size(const std::string &path) const;
    };
  } // namespace grid
} // namespace slidewave

#endif
