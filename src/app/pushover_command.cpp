#include <fmt/format.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "assembly/pushover.hpp"
#include "assembly/static_equilibrium.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "io/document.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kPushoverUsage =
    R"(usage: pound pushover MODEL.json --node ID --to D [--direction x|y] [--pattern P]
                     [--increments N] [--out DIR] [--json]

Static pushover of a model under displacement control: the model's constant loads (gravity,
nodal loads) act first and stay on, its records are left out; a lateral load pattern then grows
until node ID has moved D along the direction, in N equal increments (halved where Newton does
not converge). The load pattern is a point load at the node (point), the masses times a uniform
acceleration (mass), or the masses times their height above the lowest node (triangular),
scaled so that the load factor is the base shear. Writes into DIR (default out/<model name>):
  pushover.csv   control displacement, base shear, and the deformation of every yielding link
  pushover.json  initial stiffness, first yield, peak base shear, final slope
(`python3 tools/plot_pushover.py DIR` draws the curve: pushover.png)
A push that cannot reach D (a mechanism) writes the curve up to there and exits with code 3.
A model with hard contacts is refused (they have no force law for the push; give them a penalty
law such as gap_spring for it).

options)";

enum class Pattern { point, mass, triangular };

struct PushoverRequest {
  std::string model_path, node, direction = "x", pattern = "point", out;
  double target = 0.0;
  int increments = 100;
  bool json = false;
};

// A target far below the model's size pushes by round-off: at --to 1e-320 the loads underflowed
// and the curve read "initial stiffness 0". 1e-9 of the size (0.1 um on a 100 m bridge) still
// gives forces many digits above round-off.
void check_target_resolved(const PushoverRequest& r, const model::Model& model) {
  double size = 0.0;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    double low = INFINITY, high = -INFINITY;
    for (const model::Node& node : model.nodes) {
      low = std::min(low, node.position[axis]);
      high = std::max(high, node.position[axis]);
    }
    if (low <= high) size = std::max(size, high - low);
  }
  if (std::abs(r.target) < 1e-9 * size)
    throw InputError(r.model_path, "--to",
                     fmt::format("{:g} is below what the model resolves: at least {:g} (1e-9 "
                                 "of its size, {:g}; a target in other units?)",
                                 r.target, 1e-9 * size, size));
}

// What is wrong with the command line, or empty.
std::string request_error(const PushoverRequest& r) {
  if (r.model_path.empty()) return "name a model file";
  if (r.node.empty()) return "name the control node with --node";
  if (!std::isfinite(r.target) || r.target == 0.0)
    return "--to must be a finite, nonzero displacement";
  if (r.direction != "x" && r.direction != "y") return "--direction must be x or y";
  if (r.pattern != "point" && r.pattern != "mass" && r.pattern != "triangular")
    return "--pattern must be point, mass or triangular";
  if (r.increments < 1 || r.increments > 1000000) return "--increments must be 1 to 1000000";
  return {};
}

// The load pattern over the free DOFs, its components along the push summing to 1.
Vector load_pattern(const LoadedModel& loaded, const assembly::StructuralSystem& system,
                    Index control, int direction, const std::string& pattern) {
  Vector p = Vector::Zero(system.size());
  if (pattern == "point") {
    p[control] = 1.0;
    return p;
  }
  const model::Model& model = loaded.built.model;
  // Heights along y in a plane, along z in space.
  const std::size_t up = model.dimension == 3 ? 2 : 1;
  double lowest = std::numeric_limits<double>::infinity();
  for (const model::Node& node : model.nodes) lowest = std::min(lowest, node.position[up]);
  Vector along = Vector::Zero(system.size());
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    if (const Index row = system.dofs().own_equation(node, direction); row >= 0)
      along[row] = pattern == "mass"
                       ? 1.0
                       : model.nodes[static_cast<std::size_t>(node)].position[up] - lowest;
  system.multiply_mass(along, p);
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < system.dofs().dofs_per_node(); ++d)
      if (const Index row = system.dofs().own_equation(node, d); row >= 0 && d != direction)
        p[row] = 0.0;  // the push only: a consistent mass gives rotations their share too
  const double total = p.sum();
  if (!(total > 0.0))
    throw InputError(loaded.spec.source, "--pattern",
                     fmt::format("the {} pattern has no load along {} (no mass{})", pattern,
                                 direction == 0 ? "x" : "y",
                                 pattern == "triangular" ? " above the lowest node" : ""));
  return p / total;
}

// A link that yields: its law (one row, a yield deformation), or its coupled shear (its
// tangential rows, each direction's yield deformation: it yields when |(s_a / delta_ya)| >= 1).
struct YieldingLink {
  Index link = 0;
  std::vector<Index> rows;
  std::vector<double> yield_deformations;
};

std::vector<YieldingLink> yielding_links(const assembly::StructuralSystem& system) {
  const integrators::LinkSet& links = system.links();
  std::vector<YieldingLink> yielding;
  for (Index k = 0; k < links.count(); ++k) {
    if (const std::optional<double> yield = links.law(k).yield_deformation())
      yielding.push_back({k, {links.row(k)}, {*yield}});
    const links::CoupledShear* shear = links.shear(k);
    if (!shear || !shear->numbers()[0].yields()) continue;
    YieldingLink coupled{k, {}, {}};
    for (int a = 0; a < shear->tangents(); ++a) {
      coupled.rows.push_back(links.row(k) + 1 + a);
      coupled.yield_deformations.push_back(
          shear->numbers()[static_cast<std::size_t>(a)].yield_deformation());
    }
    yielding.push_back(coupled);
  }
  return yielding;
}

struct FirstYield {
  std::string link;
  double displacement = 0.0, base_shear = 0.0;
};

// The capacity curve as it is pushed, and where a link first passed its yield deformation.
class CapacityRecorder {
 public:
  CapacityRecorder(const LoadedModel& loaded, const assembly::StructuralSystem& system)
      : system_(system), links_(yielding_links(system)) {
    std::vector<std::string> columns{"displacement", "base_shear", "iterations"};
    for (const auto& [id, index] : loaded.built.link_index) ids_[index] = id;
    for (const YieldingLink& link : links_) {
      if (link.rows.size() == 1 && link.rows.front() == system.links().row(link.link)) {
        columns.push_back(ids_[link.link] + ".deformation");
        continue;
      }
      for (std::size_t a = 0; a < link.rows.size(); ++a)  // a coupled shear, along each tangent
        columns.push_back(fmt::format("{}.deformation_{}", ids_[link.link], a + 1));
    }
    table_ = table_with_columns(columns);
  }

  void record(const assembly::PushoverPoint& point, const Vector& u) {
    Vector delta;
    system_.links().penetration(u, delta);
    append_row(table_, {point.displacement, point.load_factor, double(point.iterations)});
    std::size_t column = 3;
    for (const YieldingLink& link : links_) {
      double ratio = 0.0;  // |(delta_a / delta_ya)|: past 1, the link has yielded
      for (std::size_t a = 0; a < link.rows.size(); ++a) {
        const double deformation = delta[link.rows[a]];
        table_.values[column++].push_back(deformation);
        const double share = deformation / link.yield_deformations[a];
        ratio += share * share;
      }
      if (!first_yield_ && std::sqrt(ratio) >= 1 - 1e-9)
        first_yield_ = FirstYield{ids_[link.link], point.displacement, point.load_factor};
    }
  }

  const Table& table() const { return table_; }
  const std::optional<FirstYield>& first_yield() const { return first_yield_; }

 private:
  const assembly::StructuralSystem& system_;
  std::vector<YieldingLink> links_;
  std::map<Index, std::string> ids_;
  Table table_;
  std::optional<FirstYield> first_yield_;
};

// What the curve says: its first and last slopes, its peak, and the first yield.
struct CapacitySummary {
  std::optional<double> initial_stiffness, final_slope;
  assembly::PushoverPoint peak;
  std::optional<FirstYield> first_yield;
};

CapacitySummary summarise(const assembly::PushoverResult& run,
                          const std::optional<FirstYield>& first_yield) {
  const auto& curve = run.curve;
  CapacitySummary summary{.peak = curve.front(), .first_yield = first_yield};
  const auto slope = [](const assembly::PushoverPoint& a, const assembly::PushoverPoint& b) {
    return (b.load_factor - a.load_factor) / (b.displacement - a.displacement);
  };
  if (curve.size() > 1) {
    summary.initial_stiffness = slope(curve[0], curve[1]);
    summary.final_slope = slope(curve[curve.size() - 2], curve.back());
  }
  for (const assembly::PushoverPoint& point : curve)
    if (std::abs(point.load_factor) > std::abs(summary.peak.load_factor)) summary.peak = point;
  return summary;
}

io::Document capacity_document(const PushoverRequest& request, const assembly::PushoverResult& run,
                               const CapacitySummary& summary) {
  io::Document doc;
  doc.set("model", request.model_path)
      .set("node", request.node)
      .set("direction", request.direction)
      .set("pattern", request.pattern)
      .set("target", request.target)
      .set("reached", run.curve.back().displacement)
      .set("status", run.stopped.empty() ? "completed" : "stopped");
  if (!run.stopped.empty()) doc.set("stopped", run.stopped);
  if (summary.initial_stiffness)
    doc.set("initial_stiffness", *summary.initial_stiffness)
        .set("final_slope", *summary.final_slope);
  doc.set("peak_base_shear", summary.peak.load_factor)
      .set("peak_displacement", summary.peak.displacement);
  if (summary.first_yield) {
    io::Document yield;
    yield.set("link", summary.first_yield->link)
        .set("displacement", summary.first_yield->displacement)
        .set("base_shear", summary.first_yield->base_shear);
    doc.set("first_yield", yield);
  }
  return doc;
}

std::string capacity_text(const CapacitySummary& summary, const std::string& out) {
  std::string text = fmt::format("pushover -> {}/pushover.csv\n", out);
  if (summary.initial_stiffness)
    text += fmt::format("  initial stiffness {:.6g}, final slope {:.6g}\n",
                        *summary.initial_stiffness, *summary.final_slope);
  if (summary.first_yield)
    text += fmt::format("  first yield: {} at displacement {:.6g}, base shear {:.6g}\n",
                        summary.first_yield->link, summary.first_yield->displacement,
                        summary.first_yield->base_shear);
  else
    text += "  no link reached its yield deformation\n";
  text += fmt::format("  peak base shear {:.6g} at displacement {:.6g}\n", summary.peak.load_factor,
                      summary.peak.displacement);
  return text;
}

}  // namespace

int pushover_command(const Arguments& arguments) {
  po::options_description options(kPushoverUsage);
  PushoverRequest request;
  options.add_options()("help,h", "show this help")("node", po::value(&request.node),
                                                    "control node id")(
      "to", po::value(&request.target),
      "target displacement of the control node [L] (at least 1e-9 of the model's size)")(
      "direction", po::value(&request.direction)->default_value("x"), "x or y")(
      "pattern", po::value(&request.pattern)->default_value("point"), "point, mass or triangular")(
      "increments", po::value(&request.increments)->default_value(100), "equal increments")(
      "out", po::value(&request.out), "output folder (default out/<model name>)")(
      "json", "print the summary as one JSON object");
  const auto parsed = parse_command_line(arguments, options, "model", request.model_path);
  if (!parsed) return 0;
  request.json = parsed->count("json") > 0;
  if (const std::string error = request_error(request); !error.empty()) {
    std::cerr << "pound pushover: " << error << " (see `pound pushover --help`)\n";
    return 1;
  }
  LoadedModel loaded = load_model(request.model_path);
  loaded.built.model.excitations.clear();  // the push replaces the records
  loaded.built.model.support_excitations.clear();
  const auto node = loaded.built.node_index.find(request.node);
  if (node == loaded.built.node_index.end())
    throw InputError(request.model_path, "--node",
                     fmt::format("no node '{}' in the model", request.node));
  std::string out = request.out.empty() ? io::folder_named_after("out", request.model_path, "--out")
                                        : request.out;
  const std::string csv = (std::filesystem::path(out) / "pushover.csv").string();
  const std::string json = (std::filesystem::path(out) / "pushover.json").string();
  io::check_outputs_apart({{request.model_path, "the model"}}, {{csv, "--out"}, {json, "--out"}});

  assembly::StructuralSystem system = [&] {
    try {
      return assembly::StructuralSystem(loaded.built.model);
    } catch (const InputError& error) {
      throw error.file().empty() ? error.in_file(request.model_path) : error;
    }
  }();
  // The push's Newton takes each link's force law; a hard contact has none, so it would let the
  // structure pass through it (the hard-contact bridge pushed 0.3 m through its joints).
  for (Index k = 0; k < system.links().count(); ++k)
    if (system.links().law(k).is_hard_contact())
      throw InputError(request.model_path,
                       loaded.built.link_origins.at(static_cast<std::size_t>(k)),
                       fmt::format("link '{}' is a hard_contact, which a pushover does not take "
                                   "yet (it would push through it); give it a penalty law (e.g. "
                                   "gap_spring) for the pushover",
                                   loaded.built.model.links.at(static_cast<std::size_t>(k)).id));
  const int direction = request.direction == "x" ? 0 : 1;
  const Index control = system.dofs().own_equation(node->second, direction);
  if (system.dofs().tied(node->second, direction))
    throw InputError(request.model_path, "--node",
                     fmt::format("node '{}' is tied to its master along {} by a constraint: push "
                                 "the master",
                                 request.node, request.direction));
  if (control < 0)
    throw InputError(request.model_path, "--node",
                     fmt::format("node '{}' is fixed along {}: push a free node", request.node,
                                 request.direction));
  check_target_resolved(request, loaded.built.model);
  assembly::PushoverControl settings{
      .equation = control, .target = request.target, .increments = request.increments};
  settings.pattern = load_pattern(loaded, system, control, direction, request.pattern);
  const Vector start = system.has_external_force()
                           ? assembly::static_equilibrium(system, 0.0).displacement
                           : Vector::Zero(system.size());
  settings.target += start[control];  // the push is measured from the loaded state
  CapacityRecorder recorder(loaded, system);
  const assembly::PushoverResult result = assembly::pushover(
      system, start, settings,
      [&](const assembly::PushoverPoint& point, const Vector& u) { recorder.record(point, u); });
  const CapacitySummary summary = summarise(result, recorder.first_yield());
  const io::Document doc = capacity_document(request, result, summary);

  io::create_output_folder(out);
  io::StagedFiles files;
  files.write_csv(csv, recorder.table());
  files.write(json, doc.dump() + "\n");
  files.commit();
  std::cout << (request.json ? doc.dump() + "\n" : capacity_text(summary, out));
  if (!result.stopped.empty()) {
    std::cerr << fmt::format("error: {}: pushover stopped: {} (the curve up to there is in {})\n",
                             request.model_path, result.stopped, csv);
    return 3;
  }
  return 0;
}

}  // namespace pound::app
