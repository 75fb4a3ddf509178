#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "app/pushover.hpp"
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
acceleration (mass), or the masses times their height above the lowest node (triangular), of
the structure the node is in (joined by elements, ties and links other than contacts: a
building, not its neighbour), scaled so that the load factor is the base shear. Writes into DIR (default out/<model name>):
  pushover.csv   control displacement, base shear, and the deformation of every yielding link
  pushover.json  initial stiffness, first yield, peak base shear, final slope
(`python3 tools/plot_pushover.py DIR` draws the curve: pushover.png)
A push that cannot reach D (a mechanism) writes the curve up to there and exits with code 3.
A model with hard contacts is refused (they have no force law for the push; give them a penalty
law such as gap_spring for it).

options)";

struct CommandLine {
  std::string model_path, out;
  PushoverRequest push;
  bool json = false;
};

}  // namespace

int pushover_command(const Arguments& arguments) {
  po::options_description options(kPushoverUsage);
  CommandLine command;
  PushoverRequest& request = command.push;
  options.add_options()("help,h", "show this help")("node", po::value(&request.node),
                                                    "control node id")(
      "to", po::value(&request.target),
      "target displacement of the control node [L] (at least 1e-9 of the model's size)")(
      "direction", po::value(&request.direction)->default_value("x"), "x or y")(
      "pattern", po::value(&request.pattern)->default_value("point"), "point, mass or triangular")(
      "increments", po::value(&request.increments)->default_value(100), "equal increments")(
      "out", po::value(&command.out), "output folder (default out/<model name>)")(
      "json", "print the summary as one JSON object");
  const auto parsed = parse_command_line(arguments, options, "model", command.model_path);
  if (!parsed) return 0;
  command.json = parsed->count("json") > 0;
  std::string error = command.model_path.empty() ? "name a model file"
                      : request.node.empty()     ? "name the control node with --node"
                                                 : "";
  if (const auto bad = pushover_request_error(request); error.empty() && bad)
    error = fmt::format("--{} {}", bad->setting, bad->why);
  if (!error.empty()) {
    std::cerr << "pound pushover: " << error << " (see `pound pushover --help`)\n";
    return 1;
  }
  const std::string& model_path = command.model_path;
  const std::string out =
      command.out.empty() ? io::folder_named_after("out", model_path, "--out") : command.out;
  check_pushover_outputs(out, model_path, "--out");
  const PushoverFindings push =
      pushover_findings(load_model_structure(model_path), model_path, request);
  write_pushover_outputs(out, push);
  std::cout << (command.json ? push.document.dump() + "\n"
                             : fmt::format("pushover -> {}/pushover.csv\n{}", out, push.text));
  if (!push.stopped.empty()) {
    std::cerr << fmt::format("error: {}: pushover stopped: {} (the curve up to there is in {})\n",
                             model_path, push.stopped,
                             (std::filesystem::path(out) / "pushover.csv").string());
    return 3;
  }
  return 0;
}

}  // namespace pound::app
