#include "io/set_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "io/json_reader.hpp"
#include "io/model_reader.hpp"
#include "model/ground_motion.hpp"
#include "results/batch_quantities.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

bool is_safe_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

// The names of the batch folder's own files and folders (app/batch.hpp): a model id names a
// folder beside them. Names starting with '.' are the batch's too (.partial, locks).
bool is_reserved_id(const std::string& id) {
  return id.starts_with('.') || id == "batch_summary.csv" || id == "batch_plan.json" ||
         id == "batch_stats.json";
}

// Ids name folders: letters, digits, '.', '_', '-', not starting with '.' and none of the batch
// folder's own names.
std::string read_id(const JsonValue& value) {
  std::string id = value.as<std::string>(non_empty);
  if (!std::all_of(id.begin(), id.end(), is_safe_name_char) || id == "." || id == "..")
    value.fail(fmt::format("id '{}' names a folder: use letters, digits, '.', '_' or '-'", id));
  if (is_reserved_id(id))
    value.fail(fmt::format("id '{}' is {}: choose another", id,
                           id.starts_with('.') ? "a hidden folder name (it starts with '.')"
                                               : "the name of a file of the batch folder"));
  return id;
}

// An id made from a file name, with anything unsafe for a folder name replaced by '_' (a leading
// '.' too) and '_' added to a name the batch folder uses itself.
std::string id_from_file(const fs::path& file) {
  std::string id = file.stem().string();
  std::replace_if(
      id.begin(), id.end(), [](char c) { return !is_safe_name_char(c); }, '_');
  if (id.starts_with('.')) id.front() = '_';
  if (is_reserved_id(id)) id += '_';
  return id.empty() ? "record" : id;
}

// A path in the set file, relative to the set file's folder.
std::string resolve(const fs::path& folder, const std::string& path) {
  return fs::path(path).is_absolute() ? path : (folder / path).lexically_normal().string();
}

void require_file(const JsonValue& where, const std::string& path, const char* what,
                  std::uintmax_t max_bytes) {
  try {
    check_input_file(path, max_bytes);
  } catch (const FileAccessError& error) {
    where.fail(fmt::format("{} '{}': {}", what, path, error.reason()));
  }
}

builder::BatchModel read_model_entry(const JsonValue& value, const fs::path& folder) {
  builder::BatchModel model;
  if (value.json().is_string()) {
    model.path = resolve(folder, value.as<std::string>(non_empty));
    model.id = id_from_file(model.path);
    require_file(value, model.path, "model file", kMaxDocumentBytes);
    return model;
  }
  read_object(value, [&](JsonObject& object) {
    const JsonValue file = object.at("file");
    model.path = resolve(folder, file.as<std::string>(non_empty));
    require_file(file, model.path, "model file", kMaxDocumentBytes);
    const std::optional<JsonValue> id = object.find("id");
    model.id = id ? read_id(*id) : id_from_file(model.path);
  });
  return model;
}

// One record entry: a file, or every file of a folder matching a pattern (in name order).
std::vector<builder::BatchRecord> read_record_entry(JsonObject& object, const fs::path& folder) {
  builder::ExcitationSpec excitation;
  read_record_fields(object, excitation);
  // A set's periods are seconds: pound spectrum's range is 1000 s (a model's own excitation is
  // held to it in its unit of time, builder/excitations.cpp).
  if (excitation.target_sa && !(excitation.sa_period <= model::kLongestSpectralPeriod))
    JsonObject(object.at("scale"))
        .at("period")
        .fail(fmt::format("must be <= {:g} (pound spectrum's range), got {}",
                          model::kLongestSpectralPeriod, excitation.sa_period));
  const std::optional<JsonValue> file = object.find("file");
  const std::optional<JsonValue> records_folder = object.find("folder");
  const std::optional<JsonValue> id = object.find("id");
  if (file.has_value() == records_folder.has_value())
    object.fail("give either 'file' (one record) or 'folder' with 'pattern' (every match)");
  const std::string suffix =
      excitation.column == 1 ? std::string() : fmt::format("_col{}", excitation.column);
  std::vector<builder::BatchRecord> records;
  if (excitation.pair && excitation.pair->record) {
    // Named from the set's folder; models open it from wherever they are.
    const JsonValue second = JsonObject(object.at("pair")).at("record");
    if (!file) second.fail("a pair's second file belongs to one record: give it with 'file'");
    excitation.pair->record = fs::absolute(resolve(folder, *excitation.pair->record)).string();
    require_file(second, *excitation.pair->record, "record", kMaxRecordBytes);
  }
  if (file) {
    excitation.record = resolve(folder, file->as<std::string>(non_empty));
    require_file(*file, excitation.record, "record", kMaxRecordBytes);
    records.push_back({id ? read_id(*id) : id_from_file(excitation.record) + suffix, excitation});
    return records;
  }
  if (id) id->fail("an id names one record: give it with 'file', not 'folder'");
  const std::string path = resolve(folder, records_folder->as<std::string>(non_empty));
  const JsonValue pattern_value = object.at("pattern");
  const std::string pattern = pattern_value.as<std::string>(non_empty);
  std::error_code error;
  if (!fs::is_directory(path, error))
    records_folder->fail(fmt::format(
        "folder '{}' {}", path, fs::exists(path, error) ? "is not a folder" : "does not exist"));
  std::vector<fs::path> matches;
  for (const fs::directory_entry& entry : fs::directory_iterator(path, error))
    if (entry.is_regular_file() &&
        ::fnmatch(pattern.c_str(), entry.path().filename().c_str(), 0) == 0)
      matches.push_back(entry.path());
  if (error) records_folder->fail(fmt::format("cannot list '{}': {}", path, error.message()));
  if (matches.empty())
    pattern_value.fail(fmt::format("no file in '{}' matches '{}'", path, pattern));
  std::sort(matches.begin(), matches.end());
  for (const fs::path& match : matches) {
    excitation.record = match.string();
    records.push_back({id_from_file(match) + suffix, excitation});
  }
  return records;
}

// A limit on a name that is no quantity: the quantities whose names begin with it (a limit on
// "max_drift" means "max_drift_ratio"), or the closest one, and the list of them all.
void refuse_unknown_quantities(const JsonValue& limits) {
  std::vector<std::string> names;
  for (const results::BatchQuantity& quantity : results::batch_quantities())
    names.emplace_back(quantity.name);
  for (const auto& field : limits.json().items()) {
    const std::string& key = field.key();
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    std::vector<std::string> beginning;
    for (const std::string& name : names)
      if (name.starts_with(key)) beginning.push_back(name);
    const std::optional<std::string> closest = closest_name(key, names);
    const std::string meant =
        !beginning.empty() ? fmt::format(" (did you mean '{}'?)", fmt::join(beginning, "' or '"))
        : closest          ? fmt::format(" (did you mean '{}'?)", *closest)
                           : std::string();
    JsonObject(limits).at(key).fail(
        fmt::format("unknown quantity{}; a limit is on one of: {}", meant, fmt::join(names, ", ")));
  }
}

builder::IntensityMeasure read_intensity(JsonObject& object) {
  builder::IntensityMeasure measure;
  measure.type = object.one_of("type", {"pga", "sa"}) == "sa" ? builder::IntensityKind::sa
                                                              : builder::IntensityKind::pga;
  if (measure.type == builder::IntensityKind::sa) {
    measure.period = object.required<double>("period", positive);
    if (!(measure.period <= 1000.0))  // pound spectrum's range: no structure's period is longer
      object.at("period").fail(
          fmt::format("must be <= 1000 (pound spectrum's range), got {}", measure.period));
    measure.damping = object.optional<double>("damping", 0.05, non_negative);
    if (!(measure.damping < 1.0))  // Sa of an underdamped oscillator (pound spectrum's range)
      object.at("damping").fail(
          fmt::format("must be below 1 (an underdamped oscillator), got {}", measure.damping));
  }
  if (object.has("pair"))
    measure.pair = object.one_of("pair", {"rotd50", "geometric_mean"}) == "rotd50"
                       ? builder::PairMeasure::rot_d50
                       : builder::PairMeasure::geometric_mean;
  return measure;
}

// "ensemble": {"copies": N, "perturbation": eps, "robust_spread": s, "rows": "median"}
builder::SetEnsemble read_ensemble(JsonObject& object) {
  builder::SetEnsemble ensemble;
  const JsonValue copies = object.at("copies");
  ensemble.copies = copies.as<int>();
  const std::optional<JsonValue> perturbation = object.find("perturbation");
  if (perturbation) ensemble.perturbation = perturbation->as<double>();
  const std::optional<JsonValue> robust_spread = object.find("robust_spread");
  if (robust_spread) ensemble.robust_spread = robust_spread->as<double>();
  if (const std::optional<JsonValue> rows = object.find("rows"))
    ensemble.medians = rows->as_one_of({"median", "unperturbed"}) == "median";
  object.finish();
  if (const auto error =
          builder::ensemble_error(ensemble.copies, ensemble.perturbation, ensemble.robust_spread)) {
    // A number left at its default is valid alone: the one named is there (else "copies").
    const JsonValue where =
        error->number == builder::EnsembleNumber::perturbation    ? perturbation.value_or(copies)
        : error->number == builder::EnsembleNumber::robust_spread ? robust_spread.value_or(copies)
                                                                  : copies;
    where.fail(error->why);
  }
  return ensemble;
}

builder::SetSpec read_set(JsonObject& top) {
  builder::SetSpec set;
  set.source = top.value().file();
  const fs::path folder = fs::path(set.source).parent_path();
  set.title = top.optional<std::string>("title", std::string());

  // A model file given where a set belongs: say so, not just that "models" is missing.
  if (!top.find("models") && (top.find("nodes") || top.find("generators") || top.find("links")))
    throw InputError(set.source, "",
                     "this is a model file (it has nodes, generators or links), and pound batch "
                     "takes a set file: its \"models\", \"records\" and \"scales\" "
                     "(docs/batch_format.md); to run one model, use pound run");
  UniqueNames model_ids("model id");
  const JsonValue models = top.at("models");
  for (const JsonValue& entry : models.elements(1)) {
    set.models.push_back(read_model_entry(entry, folder));
    model_ids.add(set.models.back().id, entry);
  }

  UniqueNames record_ids("record id");
  const JsonValue records = top.at("records");
  for (const JsonValue& entry : records.elements(1)) {
    const std::vector<builder::BatchRecord> expanded =
        read_object(entry, [&](JsonObject& object) { return read_record_entry(object, folder); });
    for (builder::BatchRecord record : expanded) {
      record_ids.add(record.id, entry);
      record.path = entry.path();
      set.records.push_back(std::move(record));
    }
  }

  if (const std::optional<JsonValue> scales = top.find("scales")) {
    set.scales.clear();
    for (const JsonValue& scale : scales->elements(1)) {
      const double factor = scale.as<double>(positive);
      if (std::find(set.scales.begin(), set.scales.end(), factor) != set.scales.end())
        scale.fail(fmt::format("scale {} is given twice", factor));
      set.scales.push_back(factor);
    }
  }
  set.histories = top.optional<bool>("histories", true);
  if (const std::optional<JsonValue> ensemble = top.find("ensemble"))
    set.ensemble = read_object(*ensemble, read_ensemble);
  if (const std::optional<JsonValue> intensity = top.find("intensity_measure"))
    set.intensity = read_object(*intensity, read_intensity);
  if (const std::optional<JsonValue> limits = top.find("limits")) {
    JsonObject object(*limits);
    // Zero is a limit too: "impacts" above 0 is any pounding at all.
    for (const results::BatchQuantity& quantity : results::batch_quantities())
      if (const std::optional<double> value =
              object.if_present<double>(quantity.name, non_negative))
        set.limits.push_back({std::string(quantity.name), *value});
    refuse_unknown_quantities(*limits);
  }
  return set;
}

}  // namespace

builder::SetSpec parse_set(const std::string& text, const std::string& source) {
  const nlohmann::json document = parse_json(text, source);
  return read_object(JsonValue(document, source, ""), read_set);
}

builder::SetSpec read_set_file(const std::string& path) {
  return parse_set(read_text_file(path), path);
}

}  // namespace pound::io
