#include "app/model_loading.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "builder/excitations.hpp"
#include "core/errors.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/json_reader.hpp"
#include "io/model_reader.hpp"
#include "io/system_memory.hpp"

namespace pound::app {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// Measured: 0.85 KiB per DOF for a 10^6-DOF rod pair (everything `run` holds, 200 steps); 2 KiB
// allows for the wider bands of frames.
std::optional<std::string> memory_shortfall(double dofs) {
  constexpr double bytes_per_dof = 2048.0;
  const double needed = bytes_per_dof * dofs;
  const std::optional<std::size_t> available = io::available_memory_bytes();
  if (!available || needed <= static_cast<double>(*available)) return std::nullopt;
  return fmt::format("need about {:.1f} GiB, more than the {:.1f} GiB of memory available",
                     needed / kGiB, static_cast<double>(*available) / kGiB);
}

namespace {

// A model too large for this machine is refused before its generators allocate it.
void check_model_fits(const builder::ModelSpec& spec, const std::string& path) {
  const builder::ModelSize size = builder::model_size(spec);
  if (const std::optional<std::string> shortfall = memory_shortfall(static_cast<double>(size.dofs)))
    throw InputError(path, size.largest_path,
                     fmt::format("the model would have up to {} DOFs ({} nodes, {} of them from "
                                 "here) and {}",
                                 size.dofs, size.nodes, size.largest_nodes, *shortfall));
}

// The SHA-1 of a record's values and sampling as bytes, so that a run from values can be traced to
// them as a file's run is to its bytes.
std::string sample_hash(const MotionOverride& samples) {
  std::string bytes;
  auto append = [&bytes](const std::vector<double>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  };
  append(*samples.accelerations);
  append(samples.times);
  if (samples.time_step) append({*samples.time_step});
  return io::sha1_hex(bytes);
}

// A record named in the model at `path`: as given where absolute, else relative to its folder.
std::string record_beside(const std::string& path, const std::string& record) {
  return std::filesystem::path(record).is_absolute()
             ? record
             : (std::filesystem::path(path).parent_path() / record).string();
}

// A record of excitation k found wrong as it was read: the model's entry that names it (`field`:
// the entry's field to fix, where one is), then the record's file and line, and why.
InputError record_error(const std::string& path, std::size_t k, const std::string& field,
                        const InputError& error) {
  const std::string line = error.where().empty() ? "" : ", " + error.where();
  return InputError(path, fmt::format("/excitations/{}{}", k, field),
                    fmt::format("record '{}'{}: {}", error.file(), line, error.reason()));
}

// A pair's second component: its own file (relative to the model) or another column of the
// first's (`first_record`, as opened), read as the first.
LoadedModel::SecondComponent read_second_component(const std::string& path, std::size_t k,
                                                   const builder::ExcitationSpec& e,
                                                   const std::string& first_record,
                                                   io::RecordFormat format,
                                                   const LoadedModel& loaded) {
  const builder::PairSpec& pair = *e.pair;
  LoadedModel::SecondComponent second;
  second.path = pair.record ? record_beside(path, *pair.record) : first_record;
  format.column = pair.column.value_or(e.column);
  const auto read = [&] {
    try {
      second.motion =
          io::read_ground_motion(second.path, format, loaded.spec.units.gravity(), &second.source);
    } catch (const io::StatedUnitsError& error) {
      throw record_error(path, k, "/units", error);
    } catch (const io::FileAccessError& error) {
      throw InputError(path, fmt::format("/excitations/{}/pair/record", k),
                       fmt::format("{}: '{}'", error.reason(), error.file()));
    } catch (const io::ColumnOfAt2Error&) {
      throw;
    } catch (const InputError& error) {
      throw record_error(path, k, "/pair", error);
    }
  };
  try {
    read();
  } catch (const io::ColumnOfAt2Error& error) {
    if (pair.column)
      throw InputError(path, fmt::format("/excitations/{}/pair/column", k),
                       fmt::format("{}: '{}'", error.reason(), error.file()));
    // Its own .AT2 file beside a columns file: the first's column was not meant for it.
    format.column = 1;
    format.time_column = false;
    read();
  }
  return second;
}

// Reads the records of `loaded.spec` and builds it. `first_as_given`: the first record's path is
// the caller's (relative to where pound runs), not relative to the model file.
// `given_samples`: the first record is these values, not a file.
void read_records_and_build(const std::string& path, bool first_as_given, LoadedModel& loaded,
                            const MotionOverride* given_samples = nullptr) {
  const builder::ModelSpec& spec = loaded.spec;
  for (std::size_t k = 0; k < spec.excitations.size(); ++k) {
    const builder::ExcitationSpec& e = spec.excitations[k];
    const std::string record = k == 0 && first_as_given ? e.record : record_beside(path, e.record);
    io::RecordFormat format;
    format.format = e.format;
    format.column = e.column;
    format.time_step = e.time_step;
    format.time_column = e.time_column;
    format.units = io::parse_acceleration_unit(e.units);
    format.second = spec.units.second();
    loaded.record_paths.push_back(record);
    if (k == 0 && given_samples) {
      loaded.records.push_back(io::ground_motion_from_samples(
          record, *given_samples->accelerations, given_samples->time_step, given_samples->times,
          format.units, spec.units.gravity()));
      loaded.record_sources.push_back({"samples", sample_hash(*given_samples)});
      loaded.second_components.emplace_back();  // the samples replaced a pair too
      continue;
    }
    try {
      loaded.records.push_back(io::read_ground_motion(record, format, spec.units.gravity(),
                                                      &loaded.record_sources.emplace_back()));
    } catch (const io::FileAccessError& error) {
      if (k == 0 && first_as_given) throw;  // the caller's path: its error names it
      // The record cannot be opened: the model's field that names it is what to fix.
      throw InputError(path, fmt::format("/excitations/{}/record", k),
                       fmt::format("{}: '{}'", error.reason(), error.file()));
    } catch (const io::StatedUnitsError& error) {
      if (k == 0 && first_as_given) throw;  // the caller's units
      throw record_error(path, k, "/units", error);
    } catch (const io::ColumnOfAt2Error& error) {
      if (k == 0 && first_as_given) throw;  // the caller's options asked for the column
      throw InputError(
          path, fmt::format("/excitations/{}/{}", k, e.time_column ? "time_column" : "column"),
          fmt::format("{}: '{}'", error.reason(), error.file()));
    } catch (const InputError& error) {
      if (k == 0 && first_as_given) throw;  // the caller's record: its error names it
      throw record_error(path, k, "", error);
    }
    loaded.second_components.push_back(
        e.pair ? std::optional(read_second_component(path, k, e, record, format, loaded))
               : std::nullopt);
  }
  std::vector<std::optional<model::GroundMotion>> seconds;
  for (const auto& second : loaded.second_components)
    seconds.push_back(second ? std::optional(second->motion) : std::nullopt);
  try {
    loaded.built = builder::build(spec, loaded.records, seconds);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(path) : error;
  }
}

}  // namespace

namespace {

// A record `into` taking the place of the excitation `was`: where that was a pair, a single
// record acts along the pair's first component (a pair brought by `into` ignores the direction).
void take_direction_of(const builder::ExcitationSpec& was, builder::ExcitationSpec& into) {
  if (!was.pair) return;
  const model::Coordinates along = builder::pair_direction(*was.pair, 0);
  into.direction.assign(along.begin(), along.end());
}

// The first excitation reads `motion` instead; the model's direction, supports and (unless the
// override scales) scaling stay.
void override_motion(const MotionOverride& motion, builder::ModelSpec& spec) {
  if (spec.excitations.empty()) spec.excitations.push_back({});
  builder::ExcitationSpec& first = spec.excitations.front();
  first.record = motion.path;
  first.format = "auto";
  take_direction_of(first, first);
  first.pair.reset();  // one record replaces the pair
  if (motion.units) first.units = *motion.units;
  first.time_column = motion.time_column;
  first.column = motion.column.value_or(motion.time_column ? 2 : 1);
  first.time_step = motion.time_step;
  if (motion.scale_factor || motion.target_pga) {
    first.scale_factor = motion.scale_factor;
    first.target_pga = motion.target_pga;
    first.target_sa.reset();
  }
}

LoadedModel load_model_spec(builder::ModelSpec spec, const std::string& path,
                            const std::optional<MotionOverride>& motion_override) {
  LoadedModel loaded;
  loaded.spec = std::move(spec);
  check_model_fits(loaded.spec, path);
  const MotionOverride* samples = nullptr;
  MotionOverride converted;  // an override whose times are in another unit than the model's
  if (motion_override) {
    const MotionOverride* motion = &*motion_override;
    if (motion->record_second) {
      converted = *motion;
      const double factor = loaded.spec.units.second() / *motion->record_second;
      if (converted.time_step) *converted.time_step *= factor;
      for (double& time : converted.times) time *= factor;
      motion = &converted;
    }
    override_motion(*motion, loaded.spec);
    loaded.first_record_replaced_by = motion->replaced_by;
    if (motion->accelerations) samples = motion;
  }
  read_records_and_build(path, motion_override.has_value(), loaded, samples);
  return loaded;
}

}  // namespace

LoadedModel load_model(const std::string& path,
                       const std::optional<MotionOverride>& motion_override) {
  return load_model_spec(io::read_model_file(path), path, motion_override);
}

LoadedModel load_model_structure(const std::string& path) {
  // Modes and pushovers need the structure, not its records: a model copied away from its
  // records still has periods (it was refused, naming the record it did not need).
  // Their files are still the model's inputs: kept by name, so no output goes over one.
  builder::ModelSpec spec = io::read_model_file(path);
  std::vector<model::Coordinates> directions;
  std::vector<std::string> records;
  for (const builder::ExcitationSpec& e : spec.excitations) {
    records.push_back(record_beside(path, e.record));
    if (!e.pair) {
      directions.push_back(model::to_coordinates(e.direction));
      continue;
    }
    if (e.pair->record) records.push_back(record_beside(path, *e.pair->record));
    for (const int component : {0, 1})
      directions.push_back(builder::pair_direction(*e.pair, component));
  }
  spec.excitations.clear();
  LoadedModel loaded = load_model_spec(std::move(spec), path, std::nullopt);
  loaded.unread_excitation_directions = std::move(directions);
  loaded.record_paths = std::move(records);
  return loaded;
}

LoadedModel load_model_text(const std::string& text, const std::string& path,
                            const std::optional<MotionOverride>& motion_override) {
  return load_model_spec(io::parse_model(text, path), path, motion_override);
}

LoadedModel load_model_with_record(const std::string& path, const builder::ExcitationSpec& record) {
  LoadedModel loaded;
  loaded.spec = io::read_model_file(path);
  check_model_fits(loaded.spec, path);
  builder::ModelSpec& spec = loaded.spec;
  if (spec.excitations.empty()) spec.excitations.push_back({});
  builder::ExcitationSpec& first = spec.excitations.front();
  builder::ExcitationSpec replaced = record;
  // A set serves models of any unit of time: its times are seconds (a 1 s Sa period read as 1 ms
  // scaled a millisecond model's record to another target, and its columns' step read likewise).
  replaced.sa_period *= spec.units.second();
  if (replaced.time_step) *replaced.time_step *= spec.units.second();
  replaced.direction = first.direction;
  replaced.supports = first.supports;
  replaced.apparent_velocity = first.apparent_velocity;
  replaced.wave_origin = first.wave_origin;
  take_direction_of(first, replaced);
  first = replaced;
  loaded.first_record_replaced_by = "the batch case";
  read_records_and_build(path, true, loaded);
  return loaded;
}

// The units the numbers are in: length and time always (m and s unless the model says otherwise:
// records in g are converted with them); force, moment and mass only with a mass unit.
io::Document units_document(const builder::UnitsSpec& units) {
  const UnitNames names = units.names();
  io::Document doc;
  doc.set("length", units.length)
      .set("time", units.time)
      .set("acceleration", names.of(Dimension::acceleration));
  if (units.mass)
    doc.set("mass", *units.mass)
        .set("force", names.of(Dimension::force))
        .set("moment", names.of(Dimension::moment));
  else
    doc.set("force", "the model's own (give units.mass to name it)");
  return doc;
}

}  // namespace pound::app
