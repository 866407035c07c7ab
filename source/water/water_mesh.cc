#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
#include <slidewave/water/water_mesh.h>

namespace slidewave
{
  namespace water
  {
    namespace
    {
      std::vector<double>
      parse_double_list(const std::string &parameter, const std::string &text)
      {
        return parse_number_list(parameter, text, "a comma-separated list of numbers");
      }



      /** A band of refined cells: from, to and the target cell width [m]. */
      struct RefinedBand
      {
        double from, to, width;
      };



      /** The cell interfaces of 'Cell widths' laid from @p left; the widths must add up to
       *  @p right - @p left. */
      std::vector<double>
      cell_width_interfaces(dealii::ParameterHandler &prm,
                            const std::string        &parameter,
                            const double              left,
                            const double              right)
      {
        const auto widths = parse_double_list(parameter, prm.get("Cell widths"));
        if (widths.empty())
          throw InputError(parameter, "", "at least one cell width");
        std::vector<double> interfaces{left};
        for (const double w : widths)
          {
            if (!(w > 0.))
              throw InputError(parameter, prm.get("Cell widths"), "widths > 0");
            interfaces.push_back(interfaces.back() + w);
          }
        if (std::abs(interfaces.back() - right) > 1e-9 * (right - left))
          throw InputError(parameter,
                           prm.get("Cell widths"),
                           "widths adding up to Right end - Left end = " + to_string(right - left)
                             + " (they add up to " + to_string(interfaces.back() - left) + ")");
        interfaces.back() = right;
        return interfaces;
      }



      /** The bands of 'Refined bands', inside [@p left, @p right], sorted and checked not to
       *  overlap. */
      std::vector<RefinedBand>
      parse_refined_bands(dealii::ParameterHandler &prm,
                          const std::string        &parameter,
                          const double              left,
                          const double              right)
      {
        std::vector<RefinedBand> bands;
        for (const std::string &item :
             dealii::Utilities::split_string_list(prm.get("Refined bands"), ';'))
          {
            const auto          numbers = dealii::Utilities::split_string_list(item, ':');
            std::vector<double> values;
            try
              {
                for (const auto &n : numbers)
                  values.push_back(std::stod(n));
              }
            catch (const std::exception &)
              {
                values.clear();
              }
            if (values.size() != 3 || !(values[1] > values[0]) || !(values[2] > 0.)
                || values[0] < left || values[1] > right)
              throw InputError(parameter,
                               prm.get("Refined bands"),
                               "bands 'from:to:width' separated by ';', with Left end <= from "
                               "< to <= Right end and width > 0");
            bands.push_back({values[0], values[1], values[2]});
          }
        std::sort(bands.begin(), bands.end(), [](const RefinedBand &a, const RefinedBand &b) {
          return a.from < b.from;
        });
        for (unsigned int b = 1; b < bands.size(); ++b)
          if (bands[b].from < bands[b - 1].to)
            throw InputError(parameter, prm.get("Refined bands"), "bands that do not overlap");
        return bands;
      }



      /** The interfaces of [@p left, @p right] split at the band edges, every segment filled
       *  with the fewest equal cells not wider than its target width. */
      std::vector<double>
      refined_band_interfaces(const std::vector<RefinedBand> &bands,
                              const double                    left,
                              const double                    right,
                              const double                    base_width)
      {
        std::vector<double> interfaces{left};
        const auto          fill = [&interfaces](const double to, const double width) {
          const double from = interfaces.back();
          if (!(to > from))
            return;
          const auto n = static_cast<unsigned int>(std::ceil((to - from) / width - 1e-9));
          for (unsigned int k = 1; k <= std::max(n, 1u); ++k)
            interfaces.push_back(k == std::max(n, 1u) ? to :
                                                        from + (to - from) * k / std::max(n, 1u));
        };
        for (const RefinedBand &band : bands)
          {
            fill(band.from, base_width);
            fill(band.to, band.width);
          }
        fill(right, base_width);
        return interfaces;
      }
    } // namespace



    void
    WaterMesh::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Type",
                        "uniform",
                        Selection("uniform|cell widths|interfaces|refined bands"),
                        "How the control volumes are given. 'uniform': 'Number of cells' "
                        "equal cells on [Left end, Right end]. 'cell widths': the list 'Cell "
                        "widths' laid from 'Left end'. 'interfaces': the list 'Interface "
                        "positions'. 'refined bands': cells of 'Base cell width' with the "
                        "'Refined bands' in finer cells.");
      prm.declare_entry("Left end", "0", Double(), "Left end of the water domain [m].");
      prm.declare_entry("Right end", "1", Double(), "Right end of the water domain [m].");
      prm.declare_entry("Number of cells",
                        "100",
                        Integer(1, 10000000),
                        "Cells of a uniform mesh (at most 10^7: the 1D solver lives on one "
                        "rank).");
      prm.declare_entry("Cell widths",
                        "",
                        Anything(),
                        "Comma-separated cell widths [m], laid from 'Left end'; they must add "
                        "up to 'Right end' - 'Left end'.");
      prm.declare_entry("Interface positions",
                        "",
                        Anything(),
                        "Comma-separated, strictly increasing interface positions [m]; the "
                        "first and last are the ends of the domain.");
      prm.declare_entry("Base cell width",
                        "0.01",
                        Double(0.),
                        "Target cell width outside the refined bands [m].");
      prm.declare_entry("Refined bands",
                        "",
                        Anything(),
                        "Semicolon-separated bands 'from:to:width', e.g. '0.25:0.75:0.016'. "
                        "Each segment (band or gap between bands) is split into the fewest "
                        "equal cells not wider than its target width.");
    }



    WaterMesh
    WaterMesh::from_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      const std::string type  = prm.get("Type");
      const double      left  = prm.get_double("Left end");
      const double      right = prm.get_double("Right end");
      if (!(right > left))
        throw InputError(path + "/Right end",
                         to_string(right),
                         "a position greater than 'Left end' = " + to_string(left));

      if (type == "uniform")
        return uniform(left, right, prm.get_integer("Number of cells"));

      if (type == "interfaces")
        return WaterMesh(parse_double_list(path + "/Interface positions",
                                           prm.get("Interface positions")),
                         path + "/Interface positions");

      if (type == "cell widths")
        {
          const std::string parameter = path + "/Cell widths";
          return WaterMesh(cell_width_interfaces(prm, parameter, left, right), parameter);
        }

      // Refined bands: split [left, right] at the band edges and fill every segment with
      // the fewest equal cells not wider than its target width.
      const std::string parameter  = path + "/Refined bands";
      const double      base_width = prm.get_double("Base cell width");
      require_positive(path + "/Base cell width", base_width);
      const std::vector<RefinedBand> bands = parse_refined_bands(prm, parameter, left, right);
      return WaterMesh(refined_band_interfaces(bands, left, right, base_width), parameter);
    }



    WaterMesh::WaterMesh(std::vector<double> interfaces, const std::string &parameter)
      : interface_positions(std::move(interfaces))
    {
      if (interface_positions.size() < 2)
        throw InputError(parameter, "", "at least two interface positions (one cell)");
      for (unsigned int i = 1; i < interface_positions.size(); ++i)
        if (!(interface_positions[i] > interface_positions[i - 1]))
          throw InputError(parameter,
                           to_string(interface_positions[i]),
                           "strictly increasing interface positions (this one follows "
                             + to_string(interface_positions[i - 1]) + ")");
    }



    WaterMesh
    WaterMesh::uniform(const double left, const double right, const unsigned int n_cells)
    {
      std::vector<double> interfaces(n_cells + 1);
      for (unsigned int i = 0; i <= n_cells; ++i)
        interfaces[i] = left + (right - left) * i / n_cells;
      interfaces.back() = right;
      return WaterMesh(interfaces);
    }



    unsigned int
    WaterMesh::cell_containing(const double x) const
    {
      const auto upper
        = std::upper_bound(interface_positions.begin(), interface_positions.end(), x);
      if (upper == interface_positions.begin())
        return 0;
      return std::min<unsigned int>(upper - interface_positions.begin() - 1, n_cells() - 1);
    }



    double
    WaterMesh::min_width() const
    {
      double w = width(0);
      for (unsigned int i = 1; i < n_cells(); ++i)
        w = std::min(w, width(i));
      return w;
    }



    double
    WaterMesh::max_width() const
    {
      double w = width(0);
      for (unsigned int i = 1; i < n_cells(); ++i)
        w = std::max(w, width(i));
      return w;
    }
  } // namespace water
} // namespace slidewave
