#include <slidewave/granular/granular_water_scene.h>
#include <sstream>

namespace slidewave
{
  namespace granular
  {
    std::string
    GranularWaterScene::checkpoint_signature() const
    {
      std::ostringstream out;
      out.precision(12);
      out << "granular water; grid " << fluid_parameters.lower_left << " to "
          << fluid_parameters.upper_right << ", cell size " << fluid_parameters.cell_size
          << "; grains " << parameters.grain_density << "; drag "
          << (parameters.forchheimer ? "Forchheimer" : "Darcy") << " coupled "
          << (!parameters.implicit_drag  ? "explicitly" :
              parameters.projected_drag  ? "semi-implicitly, projected" :
              parameters.consistent_drag ? "semi-implicitly, consistent" :
                                           "semi-implicitly, lumped")
          << "; suspension above n = " << parameters.suspension_porosity
          << (fluid_parameters.dynamic_subscales ? "; dynamic subscales" : "") << "; materials";
      // (a material's model decides its points' properties: Hencky's carry b^e)
      for (const auto &material : soil_parameters.materials)
        out << " " << material.signature();
      out << engine::signature(soil_parameters.velocity_transfer) << fluid_output.signature();
      // (a solid holds the water's and the skeleton's nodes: another one is another scene)
      for (const auto &solid : fluid_parameters.solids)
        {
          out << "; solid";
          for (const auto &vertex : solid.polygon)
            out << " " << vertex;
        }
      return out.str();
    }



    std::vector<std::string>
    GranularWaterScene::growing_files() const
    {
      std::vector<std::string> files = verification.growing_files();
      for (const auto &file : fluid_output.growing_files())
        files.push_back(file);
      return files;
    }



    void
    GranularWaterScene::save(io::CheckpointRecord &record)
    {
      const Engine::State state = engine->state();
      record.put("skeleton/time", state.time);
      record.put("skeleton/lost_mass", state.lost_mass);
      record.put("skeleton/steps", state.n_steps);
      record.put("fluid/time", fluid_solver->time);
      record.put("fluid/last_dt", fluid_solver->last_dt);
      record.put("fluid/steps", fluid_solver->n_steps);
      record.put("fluid/water_outflow", fluid_solver->water_outflow);
      balance.save(record);
      record.put("fluid/last_iterations", static_cast<double>(last_report.flow.iterations));
      record.put_files("skeleton/particle_files", particle_output.files);
      record.put_files("fluid/field_files", fluid_output.files);
      verification.save(record);
    }



    void
    GranularWaterScene::save_data(const std::string &prefix)
    {
      engine->save(prefix);
    }



    void
    GranularWaterScene::resume(const io::CheckpointRecord &record,
                               const std::string          &prefix,
                               dealii::TimerOutput        &timer_output)
    {
      timer = &timer_output;
      dealii::TimerOutput::Scope scope(timer_output, "granular: setup");
      create_solvers();
      engine->load(prefix);
      engine->set_state({record.get("skeleton/time"),
                         record.get("skeleton/lost_mass"),
                         record.get_unsigned("skeleton/steps")});
      fluid_solver->time          = record.get("fluid/time");
      fluid_solver->last_dt       = record.get("fluid/last_dt");
      fluid_solver->n_steps       = record.get_unsigned("fluid/steps");
      fluid_solver->water_outflow = record.get("fluid/water_outflow");
      balance.load(record);
      last_report.flow.iterations = static_cast<unsigned int>(record.get("fluid/last_iterations"));
      particle_output.files       = record.get_files("skeleton/particle_files");
      fluid_output.files          = record.get_files("fluid/field_files");
      verification.load(record);
      verification.open_files(true);
      fluid_output.open_gauges(true);
    }
  } // namespace granular
} // namespace slidewave
