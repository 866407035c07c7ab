#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/grid_extent.h>

namespace slidewave
{
  namespace grid
  {
    void
    GridExtent::declare_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &default_cell_size)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Lower left", "0, 0", Anything(), "Corner x, y of the domain [m].");
      prm.declare_entry("Upper right", "1, 1", Anything(), "Corner x, y of the domain [m].");
      prm.declare_entry("Cell size",
                        default_cell_size,
                        Double(),
                        "Side of the square background cells [m]; the domain sides must "
                        "be (close to) multiples of it.");
    }



    void
    GridExtent::parse_parameters(dealii::ParameterHandler &prm,
                                 const std::string        &path,
                                 const bool                with_corners)
    {
      cell_size = prm.get_double("Cell size");
      require_positive(path + "/Cell size", cell_size);
      if (!with_corners)
        return;
      const std::string allowed = "2 comma-separated numbers";
      const auto a = parse_number_list(path + "/Lower left", prm.get("Lower left"), allowed, 2);
      const auto b = parse_number_list(path + "/Upper right", prm.get("Upper right"), allowed, 2);
      lower_left   = dealii::Point<2>(a[0], a[1]);
      upper_right  = dealii::Point<2>(b[0], b[1]);
      if (!(b[0] > a[0]) || !(b[1] > a[1]))
        throw InputError(path + "/Upper right",
                         prm.get("Upper right"),
                         "a corner above and to the right of 'Lower left'");
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double n = (b[d] - a[d]) / cell_size;
          if (std::abs(n - std::round(n)) > 1e-6 * n)
            throw InputError(path + "/Cell size",
                             to_string(cell_size),
                             "a size that divides the domain sides (" + to_string(b[0] - a[0])
                               + " x " + to_string(b[1] - a[1]) + " m)");
        }
      check_size(path);
    }



    void
    GridExtent::check_size(const std::string &path) const
    {
      // The supported size: beyond it the grid alone takes most of a machine's memory.
      const double n_cells = std::round((upper_right[0] - lower_left[0]) / cell_size)
                             * std::round((upper_right[1] - lower_left[1]) / cell_size);
      if (n_cells > 1e7)
        throw InputError(path + "/Cell size",
                         to_string(cell_size),
                         "a size giving at most 10^7 grid cells (this one gives "
                           + to_string(n_cells) + ")");
    }



    void
    GridExtent::fit_inside(const dealii::Point<2> &lower,
                           const dealii::Point<2> &upper,
                           const std::string      &path,
                           const std::string      &extent)
    {
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower_left[d]  = std::ceil(lower[d] / cell_size - 1e-9) * cell_size;
          upper_right[d] = std::floor(upper[d] / cell_size + 1e-9) * cell_size;
          if (!(upper_right[d] > lower_left[d]))
            throw InputError(path + "/Extent",
                             extent,
                             "an area holding at least one cell of " + to_string(cell_size)
                               + " m (its data span [" + to_string(lower[0]) + ", "
                               + to_string(upper[0]) + "] x [" + to_string(lower[1]) + ", "
                               + to_string(upper[1]) + "])");
        }
      check_size(path);
    }
  } // namespace grid
} // namespace slidewave
