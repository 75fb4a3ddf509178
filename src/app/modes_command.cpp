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
stiffness, contact links open), with each mode's effective modal mass along x (and y, z where the
scene moves so) as a fraction of the total, and the listed modes' sum along each (seismic codes
ask for 90 % along each direction the records shake): the periods Rayleigh damping is chosen
from and the ones a time step must resolve. --shapes writes the mode shapes (.csv, or .npy): a row per
free DOF (label column "dof": <node>.u_x, <node>.u_y, <node>.u_rz, as node recorders name them) and a column per mode,
mode_1, mode_2, ..., each scaled so that its largest component is +1; a DOF a constraint ties
has its row too, its master's motion there (a rigid floor's corner may pass 1). Rigid-body and
mechanism modes (no strain energy) are left out, and past 4,000 DOFs at most the first 500 modes
are listed: fewer modes than --count come with a line saying why ("fewer" in --json).

options)";

// A mode as listed: its number in the list, its period and its effective modal mass along x, y
// and z as a fraction of the total.
struct ListedMode {
  int number = 0;
  double period = 0.0;
  std::array<double, 3> mass_ratio{0.0, 0.0, 0.0};
  Vector shape;  // over the free DOFs, largest component +1
};

// The modes and the axes along which the scene's mass moves (x always; y, z when a DOF with mass
// moves so), with the listed modes' sums of effective mass along each.
struct ListedModes {
  std::vector<ListedMode> modes;
  std::vector<int> axes{0};
  std::array<double, 3> mass_sum{0.0, 0.0, 0.0};
  std::array<bool, 3> shaken{false, false, false};  // an excitation acts along the axis
  int asked = 0;
  std::string fewer;  // why fewer modes than asked are listed (assembly::fewer_modes_reason)
};

constexpr const char* kAxes = "xyz";
// Eurocode 8 (4.3.3.3.1) and ASCE 7 (12.9.1.1): the modes of a response spectrum analysis are to
// hold 90 % of the mass along each direction of the excitation.
constexpr double kCodeMassSum = 0.9;

std::unique_ptr<assembly::StructuralSystem> assemble(const LoadedModel& loaded,
                                                     const std::string& model_path) {
  try {
    return std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
}

// A unit displacement of every node along x (0), y (1) and z (2), at the rows of its free
// translations.
std::array<Vector, 3> influence_vectors(const assembly::StructuralSystem& system,
                                        std::size_t node_count) {
  const model::DofMap& dofs = system.dofs();
  std::array<Vector, 3> influence;
  for (Vector& v : influence) v = Vector::Zero(system.size());
  for (Index node = 0; node < static_cast<Index>(node_count); ++node)
    for (int d = 0; d < dofs.dofs_per_node(); ++d) {
      const model::Direction along = model::direction(d, dofs.dimension());
      if (const Index row = dofs.own_equation(node, d); row >= 0 && !along.rotation)
        influence[static_cast<std::size_t>(along.axis)][row] = 1.0;
    }
  return influence;
}

// The axes an excitation of the model shakes (a component above 1e-9 of its direction).
std::array<bool, 3> shaken_axes(const model::Model& model,
                                const std::vector<model::Coordinates>& unread) {
  std::array<bool, 3> shaken{false, false, false};
  const auto add = [&](const model::Coordinates& direction) {
    for (std::size_t a = 0; a < 3; ++a) shaken[a] = shaken[a] || std::abs(direction[a]) > 1e-9;
  };
  for (const model::UniformExcitation& e : model.excitations) add(e.direction);
  for (const model::SupportExcitation& e : model.support_excitations) add(e.direction);
  for (const model::Coordinates& direction : unread) add(direction);
  return shaken;
}

// The first `count` modes that are not rigid-body motion.
ListedModes list_modes(const assembly::StructuralSystem& system, const model::Model& model,
                       int count, const std::vector<model::Coordinates>& unread) {
  const assembly::Modes modes = assembly::vibration_modes(system, count);
  // Effective modal mass along x, y and z: (phi^T M iota)^2 with mass-normalised phi.
  const std::array<Vector, 3> influence = influence_vectors(system, model.nodes.size());
  const auto mass = system.mass_matrix();
  std::array<double, 3> total{};
  for (std::size_t d = 0; d < 3; ++d) total[d] = influence[d].dot(mass * influence[d]);

  ListedModes result;
  for (int d = 1; d < 3; ++d)
    if (total[static_cast<std::size_t>(d)] > 0.0) result.axes.push_back(d);
  result.shaken = shaken_axes(model, unread);
  result.asked = count;
  const auto dofs_with_mass = static_cast<Index>((mass.diagonal().array() > 0.0).count());
  result.fewer = assembly::fewer_modes_reason(system.size(), dofs_with_mass, count,
                                              modes.omega_squared.size());
  for (Index k = 0; k < modes.omega_squared.size(); ++k) {
    ListedMode mode;
    mode.number = static_cast<int>(k) + 1;
    mode.period = 2.0 * std::numbers::pi / std::sqrt(modes.omega_squared[k]);
    for (std::size_t d = 0; d < 3; ++d) {
      const double participation = modes.shapes.col(k).dot(mass * influence[d]);
      mode.mass_ratio[d] = total[d] > 0.0 ? participation * participation / total[d] : 0.0;
      result.mass_sum[d] += mode.mass_ratio[d];
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

// Where the listed modes hold less than the codes' 90 % of the mass along an axis a record
// shakes: say so, and that more modes are needed for a modal (spectrum) analysis along it.
std::string mass_sum_note(const ListedModes& listed) {
  std::string short_axes;
  for (const int axis : listed.axes) {
    const auto a = static_cast<std::size_t>(axis);
    if (listed.shaken[a] && listed.mass_sum[a] < kCodeMassSum)
      short_axes += fmt::format("{}{} ({:.1f} %)", short_axes.empty() ? "" : ", ", kAxes[axis],
                                100.0 * listed.mass_sum[a]);
  }
  if (short_axes.empty()) return "";
  return fmt::format(
      "the {} listed hold{} less than 90 % of the mass along {}, which the records shake: a "
      "response spectrum analysis needs more (Eurocode 8 4.3.3.3.1, ASCE 7 12.9.1.1; --count); "
      "the time history has every mode\n",
      listed.modes.size() == 1 ? "one mode" : fmt::format("{} modes", listed.modes.size()),
      listed.modes.size() == 1 ? "s" : "", short_axes);
}

// The modes with their units in the header (period in the model's time unit, frequency in Hz
// where that is seconds); the mass columns are ratios of the total.
std::string modes_table(const std::string& model_path, Index dofs, const ListedModes& listed,
                        const std::string& time) {
  const std::string period = time.empty() ? "period" : fmt::format("period [{}]", time);
  const std::string frequency = time.empty()  ? "frequency"
                                : time == "s" ? "freq. [Hz]"
                                              : fmt::format("freq. [1/{}]", time);
  std::string table =
      fmt::format("{}: {} DOFs\n{:>5} {:>12} {:>12}", model_path, dofs, "mode", period, frequency);
  for (const int axis : listed.axes)
    table += fmt::format(" {:>10}", fmt::format("mass {}", kAxes[axis]));
  table += "\n";
  for (const ListedMode& mode : listed.modes) {
    table += fmt::format("{:>5} {:>12.5g} {:>12.5g}", mode.number, mode.period, 1.0 / mode.period);
    for (const int axis : listed.axes)
      table += fmt::format(" {:>10.4f}", mode.mass_ratio[static_cast<std::size_t>(axis)]);
    table += "\n";
  }
  table += fmt::format("{:>5} {:>25}", "sum", "");
  for (const int axis : listed.axes)
    table += fmt::format(" {:>10.4f}", listed.mass_sum[static_cast<std::size_t>(axis)]);
  table += "\n" + mass_sum_note(listed);
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
    for (const int axis : listed.axes)
      if (axis > 0)
        row.set(fmt::format("mass_ratio_{}", kAxes[axis]),
                mode.mass_ratio[static_cast<std::size_t>(axis)]);
    rows.push_back(row);
  }
  io::Document doc, sums;
  for (const int axis : listed.axes)
    sums.set(std::string(1, kAxes[axis]), listed.mass_sum[static_cast<std::size_t>(axis)]);
  doc.set("model", model_path).set("dofs", static_cast<long>(dofs)).set("asked", listed.asked);
  doc.set("mass_ratio_sum", sums);
  if (!listed.fewer.empty()) doc.set("fewer", listed.fewer);
  doc.set("modes", rows);
  return doc;
}

}  // namespace

ModalFindings modal_findings(const LoadedModel& loaded, const std::string& model_path, int count) {
  const std::unique_ptr<assembly::StructuralSystem> system = assemble(loaded, model_path);
  ListedModes modes;
  try {
    modes = list_modes(*system, loaded.built.model, count, loaded.unread_excitation_directions);
  } catch (const assembly::NotPositiveDefinite& failure) {
    throw builder::not_held_error(loaded.built, system->dofs(), failure,
                                  "the condensation of the massless DOFs", model_path);
  } catch (const assembly::ModalAnalysisError& error) {
    throw builder::extreme_mode_error(loaded.built, *system, error.what(), model_path);
  }
  io::Document document = modes_document(model_path, system->size(), modes);
  document.set("units", units_document(loaded.spec.units));
  return {std::move(document), shapes_table(loaded, *system, modes.modes),
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
  const LoadedModel loaded = load_model_structure(model_path);
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
