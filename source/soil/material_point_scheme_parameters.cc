#include <slidewave/core/input_error.h>
#include <slidewave/soil/material_point_parameters.h>
#include <slidewave/soil/material_point_scheme_parameters.h>

namespace slidewave
{
  namespace soil
  {
    void
    declare_scheme_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Shape functions",
                        "q1",
                        Selection("q1|gimp|cpgimp|bspline"),
                        "'q1': bilinear functions of the cell holding the point (standard "
                        "MPM). 'gimp': uGIMP, Q1 averaged over a square domain of the "
                        "point's initial size (paper 000, Eq. 11), smooth across cell faces "
                        "(no cell-crossing noise). 'cpgimp': the domain stretches with the "
                        "point along x and y. 'bspline': quadratic B-splines centred on the "
                        "nodes (paper 002, Appendix A; support three cells, C1), which are "
                        "GIMP with a whole cell as every point's domain (doc/mpm.md).");
      prm.declare_entry("Update scheme",
                        "usl",
                        Selection("usl|musl"),
                        "'usl': stresses from the updated nodal velocities (update stress "
                        "last, paper 000). 'musl': from nodal velocities re-mapped from the "
                        "updated particle velocities (less noisy for fast flows).");
      prm.declare_entry("FLIP fraction",
                        "0.99", // default_flip_fraction (material_point_parameters.h)
                        Double(0., 1.),
                        "Blend of the particle velocity update: 1 is pure FLIP (increments "
                        "of the nodal velocities, no dissipation, noisy), 0 pure PIC (nodal "
                        "velocities, dissipative). The blend of a step at the default "
                        "multiplier 0.5 (dt_ref = 0.5 h / max_p (c_p + |v_p|)); a step dt "
                        "blends FLIP^(dt / dt_ref), so that PIC's damping is a rate and the "
                        "results converge as the step shrinks (doc/mpm.md). With 'Velocity "
                        "transfer = apic' only the default.");
      prm.declare_entry("Velocity transfer",
                        "flip",
                        Selection("flip|apic"),
                        "How the points' velocities go to the grid and back. 'flip': they "
                        "scatter m_p v_p and take back the 'FLIP fraction' blend. 'apic': "
                        "the affine particle-in-cell transfer (Jiang et al. 2015): each "
                        "point also carries the velocity gradient C_p of the grid's new "
                        "velocities (properties affine_xx, affine_xy, affine_yx, affine_yy), "
                        "scatters m_p N_I (v_p + C_p (x_I - xbar_p)) and takes back the nodal "
                        "velocity: PIC without PIC's damping of rotation and shear, and "
                        "without FLIP's noise; 'FLIP fraction' must then keep its default "
                        "(there is no blend; doc/mpm.md). "
                        "With Physics = granular water not with 'Drag coupling' = "
                        "semi-implicit projected, the default (doc/granular-water.md).");
      prm.declare_entry("Time step multiplier",
                        "0.5",
                        Double(),
                        "alpha in dt = alpha h / max_p (c_p + |v_p|) (paper 000, Eq. 23); "
                        "in (0, 0.7071]: with lumped mass the highest mode of a 2D grid is "
                        "sqrt(2) times faster than along a line, so alpha above 1/sqrt(2) is "
                        "unstable (doc/stability.md).");
      prm.declare_entry("Fixed time step",
                        "0",
                        Double(0.),
                        "If > 0, this time step [s] instead of Eq. 23 (it is checked against "
                        "the stability limit at the start).");
      prm.declare_entry("B-bar",
                        "true",
                        Bool(),
                        "Average the volumetric strain increment over each cell (B-bar / "
                        "mean dilatation, paper 000 §3.1) against volumetric locking.");
      prm.declare_entry("B-bar point volumes",
                        "cell mean",
                        Selection("cell mean|own"),
                        "With 'B-bar = true', how each point's volume changes. 'cell mean' "
                        "(the default): by the cell's mean dilatation, as its stress. 'own': "
                        "by its own tr L dt, while its stress keeps the cell's mean; per "
                        "cell the volumes' sum changes by the same amount, only its share "
                        "among the points differs, so a point's porosity follows its own "
                        "motion (doc/mpm.md, \"B-bar\"). Small-strain materials only (a "
                        "hencky drucker prager material's volume is its stress's J).");
      prm.declare_entry("Gravity", "0, -9.81", Anything(), "Gravity vector g_x, g_y [m/s^2].");
    }



    void
    parse_scheme_parameters(dealii::ParameterHandler &prm,
                            const std::string        &path,
                            MaterialPointParameters  &parameters)
    {
      const std::string shape   = prm.get("Shape functions");
      parameters.shape_function = shape == "gimp"    ? grid::ShapeFunction::gimp :
                                  shape == "cpgimp"  ? grid::ShapeFunction::cpgimp :
                                  shape == "bspline" ? grid::ShapeFunction::bspline :
                                                       grid::ShapeFunction::q1;
      parameters.update_scheme
        = prm.get("Update scheme") == "musl" ? UpdateScheme::musl : UpdateScheme::usl;
      parameters.flip_fraction     = prm.get_double("FLIP fraction");
      parameters.velocity_transfer = prm.get("Velocity transfer") == "apic" ?
                                       engine::VelocityTransfer::apic :
                                       engine::VelocityTransfer::flip;
      // APIC has no blend: a 'FLIP fraction' other than its default would be ignored.
      if (parameters.velocity_transfer == engine::VelocityTransfer::apic
          && parameters.flip_fraction != default_flip_fraction)
        throw InputError(path + "/FLIP fraction",
                         prm.get("FLIP fraction"),
                         "its default, " + to_string(default_flip_fraction)
                           + ", with 'Velocity transfer = apic' (APIC takes back "
                             "the nodal velocity and its gradient, with no blend); set "
                             "'Velocity transfer = flip' to use a FLIP fraction");
      parameters.time_step_multiplier = prm.get_double("Time step multiplier");
      if (!(parameters.time_step_multiplier > 0.
            && parameters.time_step_multiplier <= max_time_step_multiplier))
        throw InputError(path + "/Time step multiplier",
                         prm.get("Time step multiplier"),
                         "a number in (0, 0.7071]: the explicit step on a 2D grid with lumped "
                         "mass is stable only up to alpha = 1/sqrt(2) in Eq. 23 "
                         "(doc/stability.md)");
      parameters.fixed_time_step = prm.get_double("Fixed time step");
      parameters.b_bar           = prm.get_bool("B-bar");
      parameters.own_volumes     = prm.get("B-bar point volumes") == "own";
      if (parameters.own_volumes && !parameters.b_bar)
        throw InputError(path + "/B-bar point volumes",
                         "own",
                         "cell mean with 'B-bar = false' (without B-bar every point's "
                         "volume follows its own tr L dt already)");
      const auto g
        = parse_number_list(path + "/Gravity", prm.get("Gravity"), "2 comma-separated numbers", 2);
      parameters.gravity[0] = g[0];
      parameters.gravity[1] = g[1];
    }
  } // namespace soil
} // namespace slidewave
