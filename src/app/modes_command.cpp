#include <fmt/format.h>

#include <array>
#include <boost/program_options.hpp>
#include <cmath>
#include <iostream>
#include <numbers>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "app/model_queries.hpp"
#include "assembly/modal_analysis.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "io/document.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"
#include "model/direction.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {
constexpr const char* kModesUsage =
    R"(usage: pound modes MODEL.json [--count N] [--json] [--shapes F]

Natural periods of a model as it starts (linear elements, structural springs at their initial
stiffness, contact links open), with each mode's effective modal mass in x (and y, in a scene
that moves along y) as a fraction of the total: the periods Rayleigh damping is chosen from and
the ones a time step must resolve. --shapes writes the mode shapes (.csv, or .npy): a row per
free DOF (label column "dof": <node>.u_x, <node>.u_y, <node>.u_rz, as node recorders name them) and a column per mode,
mode_1, mode_2, ..., each scaled so that its largest component is +1; a DOF a constraint ties
has its row too, its master's motion there (a rigid floor's corner may pass 1). Rigid-body and
mechanism modes (no strain energy) are left out, and past 4,000 DOFs at most the first 500 modes
are listed: fewer modes than --count come with a line saying why ("fewer" in --json).

options)";

// A mode as listed: its number in the list, its period and its effective modal mass along x and
// y as a fraction of the total.
struct ListedMode {
  int number = 0;
  double period = 0.0;
  std::array<double, 2> mass_ratio{0.0, 0.0};
  Vector shape;  // over the free DOFs, largest component +1
};

// The modes and the directions along which the scene moves (x always; y when a DOF moves so).
struct ListedModes {
  std::vector<ListedMode> modes;
  int directions = 1;
  int asked = 0;
  std::string fewer;  // why fewer modes than asked are listed (assembly::fewer_modes_reason)
};

std::unique_ptr<assembly::StructuralSystem> assemble(const LoadedModel& loaded,
                                                     const std::string& model_path) {
  try {
    return std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
}

// A unit displacement of every node along x (0) and y (1), at the rows of its free DOFs.
std::array<Vector, 2> influence_vectors(const assembly::StructuralSystem& system,
                                        std::size_t node_count) {
  const int dpn = system.dofs().dofs_per_node();
  std::array<Vector, 2> influence{Vector::Zero(system.size()), Vector::Zero(system.size())};
  for (Index node = 0; node < static_cast<Index>(node_count); ++node)
    for (int d = 0; d < std::min(dpn, 2); ++d)
      if (const Index row = system.dofs().own_equation(node, d); row >= 0) influence[d][row] = 1.0;
  return influence;
}

// The first `count` modes that are not rigid-body motion.
ListedModes list_modes(const assembly::StructuralSystem& system, std::size_t node_count,
                       int count) {
  const assembly::Modes modes = assembly::vibration_modes(system, count);
  // Effective modal mass along x and y: (phi^T M iota)^2 with mass-normalised phi.
  const std::array<Vector, 2> influence = influence_vectors(system, node_count);
  const auto mass = system.mass_matrix();
  double total[2];
  for (int d = 0; d < 2; ++d) total[d] = influence[d].dot(mass * influence[d]);

  ListedModes result;
  result.directions = total[1] > 0.0 ? 2 : 1;
  result.asked = count;
  const auto dofs_with_mass = static_cast<Index>((mass.diagonal().array() > 0.0).count());
  result.fewer = assembly::fewer_modes_reason(system.size(), dofs_with_mass, count,
                                              modes.omega_squared.size());
  for (Index k = 0; k < modes.omega_squared.size(); ++k) {
    ListedMode mode;
    mode.number = static_cast<int>(k) + 1;
    mode.period = 2.0 * std::numbers::pi / std::sqrt(modes.omega_squared[k]);
    for (int d = 0; d < 2; ++d) {
      const double participation = modes.shapes.col(k).dot(mass * influence[d]);
      mode.mass_ratio[d] = total[d] > 0.0 ? participation * participation / total[d] : 0.0;
    }
    mode.shape = modes.shapes.col(k);
    Index at = 0;
    mode.shape.cwiseAbs().maxCoeff(&at);
    if (mode.shape[at] != 0.0) mode.shape /= mode.shape[at];
    result.modes.push_back(mode);
  }
  return result;
}

// The shapes as a table: a row per free DOF, a column per mode.
Table shapes_table(const LoadedModel& loaded, const assembly::StructuralSystem& system,
                   const std::vector<ListedMode>& modes) {
  std::vector<std::string> columns;
  for (const ListedMode& mode : modes) columns.push_back(fmt::format("mode_{}", mode.number));
  Table table = table_with_columns(columns);
  std::vector<std::string>& labels = table.text_columns.emplace_back(TextColumn{"dof", {}}).values;
  const model::DofMap& dofs = system.dofs();
  for (Index node = 0; node < static_cast<Index>(loaded.built.model.nodes.size()); ++node)
    for (int d = 0; d < dofs.dofs_per_node(); ++d) {
      const std::span<const model::DofTerm> terms = dofs.terms(node, d);
      if (terms.empty()) continue;
      const model::Direction along = model::direction(d, dofs.dimension());
      // As the node recorders name them: u_x, u_y, u_rz.
      labels.push_back(fmt::format("{}.u_{}{}",
                                   loaded.built.model.nodes[static_cast<std::size_t>(node)].id,
                                   along.rotation ? "r" : "", "xyz"[along.axis]));
      for (std::size_t m = 0; m < modes.size(); ++m)
        table.values[m].push_back(model::value_of(terms, modes[m].shape) + 0.0);  // no -0
    }
  return table;
}

// The modes with their units in the header (period in the model's time unit, frequency in Hz
// where that is seconds); the mass columns are ratios of the total.
std::string modes_table(const std::string& model_path, Index dofs, const ListedModes& listed,
                        const std::string& time) {
  const bool y = listed.directions > 1;
  const std::string period = time.empty() ? "period" : fmt::format("period [{}]", time);
  const std::string frequency = time.empty()  ? "frequency"
                                : time == "s" ? "freq. [Hz]"
                                              : fmt::format("freq. [1/{}]", time);
  std::string table =
      fmt::format("{}: {} DOFs\n{:>5} {:>12} {:>12} {:>10}{}\n", model_path, dofs, "mode", period,
                  frequency, "mass x", y ? fmt::format(" {:>10}", "mass y") : "");
  for (const ListedMode& mode : listed.modes)
    table += fmt::format("{:>5} {:>12.5g} {:>12.5g} {:>10.4f}{}\n", mode.number, mode.period,
                         1.0 / mode.period, mode.mass_ratio[0],
                         y ? fmt::format(" {:>10.4f}", mode.mass_ratio[1]) : "");
  if (!listed.fewer.empty())
    table += fmt::format("{} of the {} modes asked for: {}\n", listed.modes.size(), listed.asked,
                         listed.fewer);
  return table;
}

io::Document modes_document(const std::string& model_path, Index dofs, const ListedModes& listed) {
  std::vector<io::Document> rows;
  for (const ListedMode& mode : listed.modes) {
    io::Document row;
    row.set("mode", mode.number)
        .set("period", mode.period)
        .set("frequency", 1.0 / mode.period)
        .set("mass_ratio_x", mode.mass_ratio[0]);
    if (listed.directions > 1) row.set("mass_ratio_y", mode.mass_ratio[1]);
    rows.push_back(row);
  }
  io::Document doc;
  doc.set("model", model_path).set("dofs", static_cast<long>(dofs)).set("asked", listed.asked);
  if (!listed.fewer.empty()) doc.set("fewer", listed.fewer);
  doc.set("modes", rows);
  return doc;
}

}  // namespace

ModalFindings modal_findings(const LoadedModel& loaded, const std::string& model_path, int count) {
  const std::unique_ptr<assembly::StructuralSystem> system = assemble(loaded, model_path);
  ListedModes modes;
  try {
    modes = list_modes(*system, loaded.built.model.nodes.size(), count);
  } catch (const assembly::NotPositiveDefinite& failure) {
    throw builder::not_held_error(loaded.built, system->dofs(), failure,
                                  "the condensation of the massless DOFs", model_path);
  } catch (const assembly::ModalAnalysisError& error) {
    throw builder::extreme_mode_error(loaded.built, *system, error.what(), model_path);
  }
  return {modes_document(model_path, system->size(), modes),
          shapes_table(loaded, *system, modes.modes),
          modes_table(model_path, system->size(), modes, loaded.built.units.of(Dimension::time))};
}

int modes_command(const Arguments& arguments) {
  po::options_description options(kModesUsage);
  std::string model_path;
  int count = 12;
  std::string shapes;
  options.add_options()("help,h", "show this help")(
      "count,n", po::value(&count)->default_value(count), "how many modes to list")(
      "json", "print the modes as one JSON object")(
      "shapes", po::value(&shapes), "write the mode shapes to this .csv or .npy file");
  const auto parsed = parse_command_line(arguments, options, "model", model_path);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  if (model_path.empty() || count < 1) {
    std::cerr << "pound modes: name a model file and a --count >= 1 (see `pound modes --help`)\n";
    return 1;
  }
  if (!shapes.empty() && !shapes.ends_with(".csv") && !shapes.ends_with(".npy")) {
    std::cerr << "pound modes: --shapes: a file name ending in .csv or .npy, got '" << shapes
              << "'\n";
    return 1;
  }
  const LoadedModel loaded = load_model(model_path);
  if (!shapes.empty()) {
    std::vector<io::NamedPath> inputs{{model_path, "the model"}};
    for (const std::string& record : loaded.record_paths) inputs.push_back({record, "a record"});
    for (const auto& second : loaded.second_components)
      if (second) inputs.push_back({second->path, "a record"});
    io::check_outputs_apart(inputs, {{shapes, "--shapes"}});
  }
  const ModalFindings findings = modal_findings(loaded, model_path, count);
  if (!shapes.empty()) {
    io::StagedFiles file;
    file.write_table(shapes, findings.shapes);
    file.commit();
  }
  std::cout << (vm.count("json") ? findings.document.dump() + "\n" : findings.text);
  return 0;
}

}  // namespace pound::app
