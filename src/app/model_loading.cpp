#include "app/model_loading.hpp"

#include <filesystem>

#include "core/errors.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/model_reader.hpp"

namespace pound::app {

LoadedModel load_model(const std::string& path, const std::optional<std::string>& motion_override) {
  LoadedModel loaded;
  loaded.spec = io::read_model_file(path);
  builder::ModelSpec& spec = loaded.spec;
  if (motion_override) {
    if (spec.excitations.empty()) spec.excitations.push_back({});
    spec.excitations.front().record = *motion_override;
    spec.excitations.front().format = "auto";
  }
  // Records are named relative to the model file (a --motion path relative to where pound runs).
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::vector<model::GroundMotion> motions;
  for (std::size_t k = 0; k < spec.excitations.size(); ++k) {
    const builder::ExcitationSpec& e = spec.excitations[k];
    const std::string record = (k == 0 && motion_override) || std::filesystem::path(e.record).is_absolute()
                                   ? e.record
                                   : (folder / e.record).string();
    io::RecordFormat format;
    format.format = e.format;
    format.column = e.column;
    format.time_step = e.time_step;
    format.time_column = e.time_column;
    format.units = io::parse_acceleration_unit(e.units);
    motions.push_back(io::read_ground_motion(record, format, spec.units.gravity()));
  }
  try {
    loaded.built = builder::build(spec, motions);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(path) : error;
  }
  return loaded;
}

}  // namespace pound::app
