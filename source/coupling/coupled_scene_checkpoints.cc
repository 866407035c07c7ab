#include <deal.II/base/mpi.h>
#include <slidewave/coupling/coupled_scene.h>
#include <slidewave/io/solver_checkpoints.h>
#include <slidewave/water/water_checkpoint.h>
#include <sstream>

// CoupledScene, its checkpoints: the signature a checkpoint must match, what is saved
// (the soil, the soil columns and water cells, the water's state, the loads on the soil
// and the running maxima) and the resumed run built from it. The set-up, the steps, the
// checks and the output are in coupled_scene.cc.
namespace slidewave
{
  namespace coupling
  {
    std::string
    CoupledScene::checkpoint_signature() const
    {
      std::ostringstream out;
      out.precision(12);
      out << "coupled; grid " << soil_parameters.lower_left << " to " << soil_parameters.upper_right
          << ", cell size " << soil_parameters.cell_size << ", adaptive levels "
          << (soil_parameters.adaptivity.enabled ? soil_parameters.adaptivity.levels : 0)
          << "; materials";
      for (const auto &material : soil_parameters.materials)
        out << " " << material.signature();
      out << engine::signature(soil_parameters.velocity_transfer);
      out << "; water cells: "
          << (coupling.water_cells == WaterCells::grid_columns ? "grid columns" : "water mesh")
          << "; loads on soil: " << (coupling.loads_on_soil ? "yes" : "no");
      if (coupling.loads_on_soil)
        out << "; water pressure: "
            << (coupling.water_pressure == WaterPressure::hydrostatic ?
                  "hydrostatic" :
                  "excess over initial level");
      return out.str();
    }



    std::vector<std::string>
    CoupledScene::growing_files() const
    {
      return {"water/gauges.csv"};
    }



    void
    CoupledScene::save(io::CheckpointRecord &record)
    {
      gauges.flush();
      io::save_state(record, "soil", *soil);
      record.put("coupling/columns", columns);
      record.put("coupling/water_interfaces", water->mesh().interfaces());
      const dealii::Tensor<1, 2> load = interface->load_on_soil();
      record.put("coupling/load_on_soil", std::vector<double>{load[0], load[1]});
      record.put("coupling/initial_level", interface->initial_level());
      record.put("coupling/initial_volume", initial_volume);
      record.put("coupling/initial_toe", initial_toe);
      record.put("coupling/max_volume_balance", max_volume_balance);
      record.put("coupling/max_deviation", max_deviation);
      record.put("coupling/max_soil_speed", max_soil_speed);
      water::save_state(record, "water", *water);
      record.put_files("soil/particle_files", particle_output.files);
    }



    void
    CoupledScene::save_data(const std::string &prefix)
    {
      soil->save(prefix);
    }



    void
    CoupledScene::resume(const io::CheckpointRecord &record,
                         const std::string          &prefix,
                         dealii::TimerOutput        &timer_output)
    {
      dealii::TimerOutput::Scope scope(timer_output, "coupled: setup");
      create_soil(timer_output);
      soil->load(prefix);
      io::restore_state(record, "soil", *soil);

      // The water cells and the soil columns of the set-up (the grid may have been
      // refined since), the water's state and the loads of the last step (the point
      // forces themselves travel with the material points).
      build_water(water::WaterMesh(record.get_vector("coupling/water_interfaces")),
                  record.get_vector("coupling/columns"));
      water::restore_state(record, "water", *water);
      const auto &load = record.get_vector("coupling/load_on_soil");
      interface->restore_load_on_soil(dealii::Tensor<1, 2>({load.at(0), load.at(1)}));
      interface->restore_initial_level(record.get_vector("coupling/initial_level"));
      initial_volume        = record.get("coupling/initial_volume");
      initial_toe           = record.get("coupling/initial_toe");
      max_volume_balance    = record.get("coupling/max_volume_balance");
      max_deviation         = record.get("coupling/max_deviation");
      max_soil_speed        = record.get("coupling/max_soil_speed");
      particle_output.files = record.get_files("soil/particle_files");
      gauges.open(scene.output_directory + "/water/gauges.csv",
                  dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0,
                  true);
    }

  } // namespace coupling
} // namespace slidewave
