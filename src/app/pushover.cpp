#include "app/pushover.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

#include "assembly/pushover.hpp"
#include "assembly/static_equilibrium.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"

namespace pound::app {
namespace {

// A target far below the model's size pushes by round-off: at --to 1e-320 the loads underflowed
// and the curve read "initial stiffness 0". 1e-9 of the size (0.1 um on a 100 m bridge) still
// gives forces many digits above round-off.
void check_target_resolved(const std::string& model_path, const PushoverRequest& r,
                           const model::Model& model) {
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
    throw InputError(model_path, r.name("to"),
                     fmt::format("{:g} is below what the model resolves: at least {:g} (1e-9 "
                                 "of its size, {:g}; a target in other units?)",
                                 r.target, 1e-9 * size, size));
}

// Whether each node belongs to the structure of `pushed`: joined to it through elements, ties and
// links that are not contacts (bearings, hinges, storeys, restrainers), never through a node
// that does not move (supports are the ground, which every structure stands on). Two buildings
// side by side are two structures; a bridge's girders, piers and abutments one.
std::vector<char> pushed_structure(const model::Model& model, const model::DofMap& dofs,
                                   Index pushed) {
  const auto count = static_cast<Index>(model.nodes.size());
  std::vector<Index> root(static_cast<std::size_t>(count));
  std::iota(root.begin(), root.end(), Index{0});
  const auto find = [&](Index node) {
    while (root[static_cast<std::size_t>(node)] != node)
      node = root[static_cast<std::size_t>(node)] =
          root[static_cast<std::size_t>(root[static_cast<std::size_t>(node)])];
    return node;
  };
  const auto moves = [&](Index node) {
    for (int d = 0; d < dofs.dofs_per_node(); ++d)
      if (!dofs.terms(node, d).empty()) return true;
    return false;
  };
  const auto join = [&](Index a, Index b) {
    if (moves(a) && moves(b)) root[static_cast<std::size_t>(find(a))] = find(b);
  };
  for (const auto& element : model.elements)
    for (std::size_t k = 1; k < element->nodes().size(); ++k)
      join(element->nodes()[k - 1], element->nodes()[k]);
  for (const model::Constraint& constraint : model.constraints)
    for (const Index slave : constraint.slaves) join(constraint.master, slave);
  for (const model::Link& link : model.links)
    if (link.role() != links::LinkRole::contact) join(link.node_i, link.node_j);
  std::vector<char> in(static_cast<std::size_t>(count), 0);
  for (Index node = 0; node < count; ++node)
    in[static_cast<std::size_t>(node)] = find(node) == find(pushed);
  return in;
}

// The load pattern over the free DOFs of the pushed node's structure, its components along the
// push summing to 1: a mass or triangular pattern loads the pushed building, not its neighbour
// across an open gap too (whose share made the base shear 1.4x the building's: audit 71).
Vector load_pattern(const LoadedModel& loaded, const assembly::StructuralSystem& system,
                    Index control, Index pushed, int direction, const PushoverRequest& request) {
  const std::string& pattern = request.pattern;
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
  const std::vector<char> structure = pushed_structure(model, system.dofs(), pushed);
  Vector along = Vector::Zero(system.size());
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    if (const Index row = system.dofs().own_equation(node, direction);
        row >= 0 && structure[static_cast<std::size_t>(node)])
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
    throw InputError(loaded.spec.source, request.name("pattern"),
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
  std::size_t point = 0;  // the curve's first point past it
};

// The capacity curve as it is pushed, and where a link first passed its yield deformation.
class CapacityRecorder {
 public:
  CapacityRecorder(const LoadedModel& loaded, const assembly::StructuralSystem& system)
      : system_(system), links_(yielding_links(system)) {
    std::vector<std::string> columns{"displacement", "base_shear", "iterations"};
    const UnitNames& names = loaded.built.units;
    std::vector<std::string> units{names.of(Dimension::length), names.of(Dimension::force), ""};
    for (const auto& [id, index] : loaded.built.link_index) ids_[index] = id;
    for (const YieldingLink& link : links_) {
      const bool rotational =
          loaded.built.model.links[static_cast<std::size_t>(link.link)].rotational;
      const std::string& unit = names.of(rotational ? Dimension::angle : Dimension::length);
      if (link.rows.size() == 1 && link.rows.front() == system.links().row(link.link)) {
        columns.push_back(ids_[link.link] + ".deformation");
        units.push_back(unit);
        continue;
      }
      for (std::size_t a = 0; a < link.rows.size(); ++a) {  // a coupled shear, along each tangent
        columns.push_back(fmt::format("{}.deformation_{}", ids_[link.link], a + 1));
        units.push_back(unit);
      }
    }
    table_ = table_with_columns(columns);
    table_.units = units;
  }

  // The first yield is found in the increment that passes it, on each link's share of its yield
  // deformation (first_yield_within).
  void record(const assembly::PushoverPoint& point, const Vector& u) {
    Vector delta;
    system_.links().penetration(u, delta);
    append_row(table_, {point.displacement, point.load_factor, double(point.iterations)});
    std::size_t column = 3;
    ratios_.resize(links_.size(), 0.0);
    earlier_ratios_.resize(links_.size(), 0.0);
    for (std::size_t k = 0; k < links_.size(); ++k) {
      const YieldingLink& link = links_[k];
      double ratio = 0.0;  // |(delta_a / delta_ya)|: past 1, the link has yielded
      for (std::size_t a = 0; a < link.rows.size(); ++a) {
        const double deformation = delta[link.rows[a]];
        table_.values[column++].push_back(deformation);
        const double share = deformation / link.yield_deformations[a];
        ratio += share * share;
      }
      ratio = std::sqrt(ratio);
      if (!first_yield_ && ratio >= 1 - 1e-9) first_yield_ = first_yield_within(k, point, ratio);
      earlier_ratios_[k] = ratios_[k];
      ratios_[k] = ratio;
    }
    earlier_ = previous_;
    previous_ = point;
    ++points_;
  }

  const Table& table() const { return table_; }
  const std::optional<FirstYield>& first_yield() const { return first_yield_; }

 private:
  // Link k's first yield in the increment from previous_ to `point`, where its ratio reached
  // `ratio`: on the line of the increment before (elastic, so exact for a structure that is
  // linear up to it; the end point's own ratio holds the yielded part and would put it early),
  // or between the increment's ends where there is no such increment.
  FirstYield first_yield_within(std::size_t k, const assembly::PushoverPoint& point,
                                double ratio) const {
    const double before = ratios_[k];
    FirstYield found{ids_.at(links_[k].link), point.displacement, point.load_factor, points_};
    if (points_ == 0) return found;
    const double step = point.displacement - previous_.displacement;
    if (points_ >= 2 && before > earlier_ratios_[k] &&
        previous_.displacement != earlier_.displacement) {
      const double span = previous_.displacement - earlier_.displacement;
      const double rate = (before - earlier_ratios_[k]) / span;
      const double at = previous_.displacement + (1.0 - before) / rate;
      if ((at - previous_.displacement) / step <= 1.0) {
        found.displacement = at;
        found.base_shear = previous_.load_factor + (previous_.load_factor - earlier_.load_factor) /
                                                       span * (at - previous_.displacement);
        return found;
      }
    }
    const double t = ratio > before ? (1.0 - before) / (ratio - before) : 1.0;
    found.displacement = previous_.displacement + t * step;
    found.base_shear = previous_.load_factor + t * (point.load_factor - previous_.load_factor);
    return found;
  }

  const assembly::StructuralSystem& system_;
  std::vector<YieldingLink> links_;
  std::map<Index, std::string> ids_;
  Table table_;
  std::optional<FirstYield> first_yield_;
  // Each link's ratio at the previous point and at the one before, and those points.
  std::vector<double> ratios_, earlier_ratios_;
  assembly::PushoverPoint previous_, earlier_;
  std::size_t points_ = 0;
};

// A second push of a fresh copy of the model, finer than the user's increments up to where a
// link first yielded: the tangent at the start and the first yield to a thousandth of that
// displacement (read at the user's increments' ends they were off by up to an increment: the
// default 100 increments to 0.8 m put a cantilever's first yield at 8 mm, not 3.6, and its
// initial stiffness at 46 % of 3EI/h^3).
constexpr int kFineIncrements = 1000;
struct FinePush {
  double initial_stiffness = 0.0;
  std::optional<FirstYield> first_yield;
};

// What the curve says: its first and last slopes, its peak, and the first yield.
struct CapacitySummary {
  std::optional<double> initial_stiffness, final_slope;
  assembly::PushoverPoint peak;
  std::optional<FirstYield> first_yield;
  // Where the base shear, past its peak, has fallen to zero (a yielded structure whose weight's
  // P-Delta overcomes its post-yield stiffness): it has no lateral strength left, and past that
  // the push, not the structure, holds it up.
  std::optional<double> zero_shear_displacement;
};

// The displacement, interpolated between the curve's points, at which the base shear past the
// peak first reaches zero or changes sign; none when it does not.
std::optional<double> zero_shear_after_peak(const std::vector<assembly::PushoverPoint>& curve,
                                            const assembly::PushoverPoint& peak) {
  if (!(std::abs(peak.load_factor) > 0.0)) return std::nullopt;
  const double sign = peak.load_factor > 0.0 ? 1.0 : -1.0;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const assembly::PushoverPoint &a = curve[k - 1], &b = curve[k];
    if (std::abs(a.displacement) < std::abs(peak.displacement)) continue;
    if (!(sign * b.load_factor <= 0.0) || !(sign * a.load_factor > 0.0)) continue;
    const double share = a.load_factor / (a.load_factor - b.load_factor);
    return a.displacement + share * (b.displacement - a.displacement);
  }
  return std::nullopt;
}

double slope(const assembly::PushoverPoint& a, const assembly::PushoverPoint& b) {
  return (b.load_factor - a.load_factor) / (b.displacement - a.displacement);
}

// The curve's summary; `fine` (a push to past the first yield in kFineIncrements, when the
// curve's own increments are coarser) gives the initial stiffness and the first yield instead.
// A curve that softens from its first yield peaks there, between its points.
CapacitySummary summarise(const assembly::PushoverResult& run,
                          const std::optional<FirstYield>& first_yield,
                          const std::optional<FinePush>& fine) {
  const auto& curve = run.curve;
  CapacitySummary summary{.peak = curve.front(), .first_yield = first_yield};
  if (curve.size() > 1) {
    summary.initial_stiffness = slope(curve[0], curve[1]);
    summary.final_slope = slope(curve[curve.size() - 2], curve.back());
  }
  if (fine) {
    summary.initial_stiffness = fine->initial_stiffness;
    if (fine->first_yield) summary.first_yield = fine->first_yield;
  }
  for (const assembly::PushoverPoint& point : curve)
    if (std::abs(point.load_factor) > std::abs(summary.peak.load_factor)) summary.peak = point;
  if (summary.first_yield &&
      std::abs(summary.first_yield->base_shear) > std::abs(summary.peak.load_factor))
    summary.peak = {summary.first_yield->displacement, summary.first_yield->base_shear, 0};
  summary.zero_shear_displacement = zero_shear_after_peak(curve, summary.peak);
  return summary;
}

io::Document capacity_document(const std::string& model_path, const PushoverRequest& request,
                               const assembly::PushoverResult& run, const CapacitySummary& summary,
                               double start) {
  io::Document doc;
  doc.set("model", model_path)
      .set("node", request.node)
      .set("direction", request.direction)
      .set("pattern", request.pattern)
      .set("target", request.target)
      .set("reached", run.curve.back().displacement - start)  // as the target, from the start
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
  if (summary.zero_shear_displacement)
    doc.set("zero_shear_displacement", *summary.zero_shear_displacement);
  return doc;
}

// A number with its unit, where the model names one (forces need a mass unit).
std::string with_unit(double value, const std::string& unit) {
  return unit.empty() ? fmt::format("{:.6g}", value) : fmt::format("{:.6g} {}", value, unit);
}

std::string capacity_text(const CapacitySummary& summary, const UnitNames& units) {
  const std::string& force = units.of(Dimension::force);
  const std::string& length = units.of(Dimension::length);
  const std::string stiffness = force.empty() ? "" : force + "/" + length;
  std::string text;
  if (summary.initial_stiffness)
    text += fmt::format("  initial stiffness {}, final slope {}\n",
                        with_unit(*summary.initial_stiffness, stiffness),
                        with_unit(*summary.final_slope, stiffness));
  if (summary.first_yield)
    text +=
        fmt::format("  first yield: {} at displacement {}, base shear {}\n",
                    summary.first_yield->link, with_unit(summary.first_yield->displacement, length),
                    with_unit(summary.first_yield->base_shear, force));
  else
    text += "  no link reached its yield deformation\n";
  text += fmt::format("  peak base shear {} at displacement {}\n",
                      with_unit(summary.peak.load_factor, force),
                      with_unit(summary.peak.displacement, length));
  if (summary.zero_shear_displacement)
    text += fmt::format(
        "  the base shear falls to zero at displacement {}: past its peak the structure lost "
        "its lateral strength (its weight's P-Delta beyond its post-yield stiffness), a collapse; "
        "the curve beyond holds it up by the push\n",
        with_unit(*summary.zero_shear_displacement, length));
  return text;
}

// The push's Newton takes each link's force law; a hard contact has none, so it would let the
// structure pass through it (the hard-contact bridge pushed 0.3 m through its joints).
void refuse_hard_contacts(const builder::BuiltModel& built,
                          const assembly::StructuralSystem& system, const std::string& model_path) {
  for (Index k = 0; k < system.links().count(); ++k)
    if (system.links().law(k).is_hard_contact())
      throw InputError(model_path, built.link_origins.at(static_cast<std::size_t>(k)),
                       fmt::format("link '{}' is a hard_contact, which a pushover does not take "
                                   "yet (it would push through it); give it a penalty law (e.g. "
                                   "gap_spring) for the pushover",
                                   built.model.links.at(static_cast<std::size_t>(k)).id));
}

// The control node's equation along the push, which must be its own (free, not tied).
Index control_equation(const builder::BuiltModel& built, const assembly::StructuralSystem& system,
                       Index node, int direction, const std::string& model_path,
                       const PushoverRequest& request) {
  // A 1-D (axial) model's nodes move along x only: y would read the next node's x.
  if (direction >= system.dofs().dofs_per_node())
    throw InputError(
        model_path, request.name("direction"),
        fmt::format("the model is {}-D: its nodes move along x only", built.model.dimension));
  if (system.dofs().tied(node, direction))
    throw InputError(model_path, request.name("node"),
                     fmt::format("node '{}' is tied to its master along {} by a constraint: push "
                                 "the master",
                                 request.node, request.direction));
  const Index control = system.dofs().own_equation(node, direction);
  if (control < 0)
    throw InputError(model_path, request.name("node"),
                     fmt::format("node '{}' is fixed along {}: push a free node", request.node,
                                 request.direction));
  return control;
}

// Why the push stopped, with the DOFs the pattern loads that nothing held (the likely mechanism:
// a mass the pattern pushes away from the links that would hold it).
std::string stopped_words(const builder::BuiltModel& built,
                          const assembly::StructuralSystem& system,
                          const assembly::PushoverResult& result) {
  if (result.stopped.empty() || result.unheld_loaded.empty()) return result.stopped;
  constexpr std::size_t kNamed = 3;
  std::string unheld;
  for (std::size_t k = 0; k < std::min(kNamed, result.unheld_loaded.size()); ++k)
    unheld += (k == 0 ? "" : "; ") +
              builder::equation_words(built, system.dofs(), result.unheld_loaded[k]);
  if (result.unheld_loaded.size() > kNamed)
    unheld += fmt::format(" and {} more", result.unheld_loaded.size() - kNamed);
  const bool one = result.unheld_loaded.size() == 1;
  return fmt::format(
      "{}. The pattern loads {}, which nothing held as the increment started (no element there, "
      "{} links open or pulled apart): a free mass under a static load, which the push cannot "
      "carry to the contact that would hold it. Push with the point pattern, or restrain {}",
      result.stopped, unheld, one ? "its" : "their", one ? "it" : "them");
}

// A model ready to push: its system with the laws at the start (the static state under its loads
// and gravity, from which the push is measured), and the push's settings.
struct PushSetup {
  std::unique_ptr<assembly::StructuralSystem> system;
  Vector start;
  assembly::PushoverControl settings;
};

PushSetup set_up_push(const LoadedModel& loaded, const std::string& model_path,
                      const PushoverRequest& request, Index node) {
  PushSetup push;
  try {
    push.system = std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
  assembly::StructuralSystem& system = *push.system;
  refuse_hard_contacts(loaded.built, system, model_path);
  const int direction = request.direction == "x" ? 0 : 1;
  const Index control =
      control_equation(loaded.built, system, node, direction, model_path, request);
  push.settings = {.equation = control, .target = request.target, .increments = request.increments};
  push.settings.pattern = load_pattern(loaded, system, control, node, direction, request);
  push.start = system.has_external_force() ? assembly::static_equilibrium(system, 0.0).displacement
                                           : Vector::Zero(system.size());
  push.settings.target += push.start[control];  // the push is measured from the loaded state
  return push;
}

// The fine push (FinePush): to the first point past the first yield in kFineIncrements, or,
// where nothing yielded, one increment of a thousandth of the first for the initial stiffness.
// Nothing before the first yield depends on the path, so a fresh copy retraces the curve.
std::optional<FinePush> fine_push(const LoadedModel& loaded, const std::string& model_path,
                                  const PushoverRequest& request, Index node,
                                  const assembly::PushoverResult& coarse,
                                  const std::optional<FirstYield>& coarse_yield) {
  PushSetup push = set_up_push(loaded, model_path, request, node);
  const double start = push.start[push.settings.equation];
  const double until = coarse_yield
                           ? coarse.curve[coarse_yield->point].displacement
                           : start + (coarse.curve[1].displacement - start) / kFineIncrements;
  push.settings.target = until;
  push.settings.increments = coarse_yield ? kFineIncrements : 1;
  CapacityRecorder recorder(loaded, *push.system);
  const assembly::PushoverResult fine = assembly::pushover(
      *push.system, push.start, push.settings,
      [&](const assembly::PushoverPoint& point, const Vector& u) { recorder.record(point, u); });
  if (!fine.stopped.empty() || fine.curve.size() < 2) return std::nullopt;
  return FinePush{slope(fine.curve[0], fine.curve[1]), recorder.first_yield()};
}

}  // namespace

std::optional<PushoverRequestError> pushover_request_error(const PushoverRequest& r) {
  if (!std::isfinite(r.target) || r.target == 0.0)
    return PushoverRequestError{"to", "must be a finite, nonzero displacement"};
  if (r.direction != "x" && r.direction != "y")
    return PushoverRequestError{"direction", "must be x or y"};
  if (r.pattern != "point" && r.pattern != "mass" && r.pattern != "triangular")
    return PushoverRequestError{"pattern", "must be point, mass or triangular"};
  if (r.increments < 1 || r.increments > 1000000)
    return PushoverRequestError{"increments", "must be 1 to 1000000"};
  return std::nullopt;
}

PushoverFindings pushover_findings(LoadedModel loaded, const std::string& model_path,
                                   const PushoverRequest& request) {
  if (const auto error = pushover_request_error(request))
    throw InputError(model_path, request.name(error->setting), error->why);
  loaded.built.model.excitations.clear();  // the push replaces the records
  loaded.built.model.support_excitations.clear();
  const auto node = loaded.built.node_index.find(request.node);
  if (node == loaded.built.node_index.end())
    throw InputError(model_path, request.name("node"),
                     fmt::format("no node '{}' in the model", request.node));
  check_target_resolved(model_path, request, loaded.built.model);
  PushSetup push = set_up_push(loaded, model_path, request, node->second);
  CapacityRecorder recorder(loaded, *push.system);
  const assembly::PushoverResult result = assembly::pushover(
      *push.system, push.start, push.settings,
      [&](const assembly::PushoverPoint& point, const Vector& u) { recorder.record(point, u); });
  const std::optional<FinePush> fine =
      request.increments < kFineIncrements && result.curve.size() > 1
          ? fine_push(loaded, model_path, request, node->second, result, recorder.first_yield())
          : std::nullopt;
  const CapacitySummary summary = summarise(result, recorder.first_yield(), fine);
  const double start = push.start[push.settings.equation];
  io::Document document = capacity_document(model_path, request, result, summary, start);
  document.set("units", units_document(loaded.spec.units));
  return {recorder.table(), std::move(document), capacity_text(summary, loaded.built.units),
          stopped_words(loaded.built, *push.system, result)};
}

namespace {
std::string csv_path(const std::string& out) {
  return (std::filesystem::path(out) / "pushover.csv").string();
}
std::string json_path(const std::string& out) {
  return (std::filesystem::path(out) / "pushover.json").string();
}
}  // namespace

void check_pushover_outputs(const std::string& out, const std::string& model_path,
                            const std::string& out_name) {
  io::check_outputs_apart({{model_path, "the model"}},
                          {{csv_path(out), out_name}, {json_path(out), out_name}});
}

void write_pushover_outputs(const std::string& out, const PushoverFindings& push) {
  io::create_output_folder(out);
  io::StagedFiles files;
  files.write_csv(csv_path(out), push.curve);
  files.write(json_path(out), push.document.dump() + "\n");
  files.commit();
}

}  // namespace pound::app
