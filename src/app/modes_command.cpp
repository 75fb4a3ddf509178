#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <iostream>
#include <numbers>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "assembly/modal_analysis.hpp"
#include "core/errors.hpp"
#include "io/document.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {
constexpr const char* kModesUsage = R"(usage: pound modes MODEL.json [--count N] [--json]

Natural periods of a model as it starts (linear elements, structural springs at their initial
stiffness, contact links open), with each mode's effective modal mass in x and y as a fraction of
the total: the periods Rayleigh damping is chosen from and the ones a time step must resolve.

options)";
}  // namespace

int modes_command(const Arguments& arguments) {
  po::options_description options(kModesUsage);
  std::string model_path;
  int count = 12;
  options.add_options()("help,h", "show this help")(
      "count,n", po::value(&count)->default_value(count), "how many modes to list")(
      "json", "print the modes as one JSON object");
  const auto parsed = parse_command_line(arguments, options, "model", model_path);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  if (model_path.empty() || count < 1) {
    std::cerr << "pound modes: name a model file and a --count >= 1 (see `pound modes --help`)\n";
    return 1;
  }
  const LoadedModel loaded = load_model(model_path);
  std::unique_ptr<assembly::StructuralSystem> system;
  try {
    system = std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
  const assembly::Modes modes = assembly::modal_analysis(*system);
  // Effective modal mass along x and y: (phi^T M iota)^2 with mass-normalised phi.
  const int dpn = system->dofs().dofs_per_node();
  const auto& nodes = loaded.built.model.nodes;
  Vector influence[2] = {Vector::Zero(system->size()), Vector::Zero(system->size())};
  for (Index node = 0; node < static_cast<Index>(nodes.size()); ++node)
    for (int d = 0; d < std::min(dpn, 2); ++d)
      if (const Index row = system->dofs().equation(node, d); row >= 0) influence[d][row] = 1.0;
  const auto mass = system->mass_matrix();
  double total[2];
  for (int d = 0; d < 2; ++d) total[d] = influence[d].dot(mass * influence[d]);

  const double largest = modes.omega_squared.size() ? modes.omega_squared.maxCoeff() : 0.0;
  std::vector<io::Document> rows;
  std::string table =
      fmt::format("{}: {} DOFs\n{:>5} {:>12} {:>12} {:>10} {:>10}\n", model_path, system->size(),
                  "mode", "period", "frequency", "mass x", "mass y");
  int listed = 0;
  for (Index k = 0; k < modes.omega_squared.size() && listed < count; ++k) {
    if (!(modes.omega_squared[k] > 1e-10 * largest)) continue;  // rigid-body motion
    ++listed;
    const double period = 2.0 * std::numbers::pi / std::sqrt(modes.omega_squared[k]);
    double share[2];
    for (int d = 0; d < 2; ++d) {
      const double participation = modes.shapes.col(k).dot(mass * influence[d]);
      share[d] = total[d] > 0.0 ? participation * participation / total[d] : 0.0;
    }
    table += fmt::format("{:>5} {:>12.5g} {:>12.5g} {:>10.4f} {:>10.4f}\n", listed, period,
                         1.0 / period, share[0], share[1]);
    io::Document row;
    row.set("mode", listed)
        .set("period", period)
        .set("frequency", 1.0 / period)
        .set("mass_ratio_x", share[0])
        .set("mass_ratio_y", share[1]);
    rows.push_back(row);
  }
  if (vm.count("json")) {
    io::Document doc;
    doc.set("model", model_path).set("dofs", static_cast<long>(system->size())).set("modes", rows);
    std::cout << doc.dump() << "\n";
  } else {
    std::cout << table;
  }
  return 0;
}

}  // namespace pound::app
