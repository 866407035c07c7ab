#ifndef slidewave_water_water_mesh_h
#define slidewave_water_water_mesh_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace water
  {
    /**
     * The control volumes [x_{i-1/2}, x_{i+1/2}] of the 1D finite-volume water column
     * (paper 000, §3.2): any strictly increasing list of interface positions, so the cell
     * widths may vary by large factors. Built from parameters (uniform, a list of widths, a
     * list of interfaces, or a uniform mesh with refined bands), or directly from interface
     * positions supplied by a caller (the coupling takes them from the MPM grid).
     */
    class WaterMesh
    {
    public:
      /** Declares the entries of subsection "Mesh". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Builds the mesh from subsection "Mesh" (the handler must be inside it).
       * @p path is the subsection path used in error messages.
       */
      static WaterMesh
      from_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** Interfaces x_{1/2} < ... < x_{n+1/2}; throws InputError naming @p parameter. */
      explicit WaterMesh(std::vector<double> interfaces,
                         const std::string  &parameter = "Mesh/Interface positions");

      static WaterMesh
      uniform(double left, double right, unsigned int n_cells);

      unsigned int
      n_cells() const
      {
        return static_cast<unsigned int>(interface_positions.size()) - 1;
      }

      double
      left_end() const
      {
        return interface_positions.front();
      }

      double
      right_end() const
      {
        return interface_positions.back();
      }

      /** Centre x_i of cell @p i. */
      double
      center(unsigned int i) const
      {
        return 0.5 * (interface_positions[i] + interface_positions[i + 1]);
      }

      /** Width Δx_i of cell @p i. */
      double
      width(unsigned int i) const
      {
        return interface_positions[i + 1] - interface_positions[i];
      }

      const std::vector<double> &
      interfaces() const
      {
        return interface_positions;
      }

      /** The cell containing @p x (the last cell for x at the right end). */
      unsigned int
      cell_containing(double x) const;

      double
      min_width() const;

      double
      max_width() const;

    private:
      std::vector<double> interface_positions;
    };
  } // namespace water
} // namespace slidewave

#endif
