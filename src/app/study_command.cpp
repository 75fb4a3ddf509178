#include <fmt/format.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "io/output.hpp"
#include "verification/error_study.hpp"
#include "verification/rod_impact_report.hpp"
#include "verification/stability_map.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {
constexpr const char* kStudyUsage =
    R"(usage: pound study rod-impact|stability [--out DIR] [--repeats N] [--quick]

stability: the stability map of the rod benchmark (n = 200 per rod): every integrator x law over
link stiffness ratio 1e-2 .. 1e8 and dt / T 1e-3 .. 0.5, each cell accurate, inaccurate, unstable
(NaN/Inf or energy growth over 10 %) or refused before running; --out writes stability_map.csv.

rod-impact:
Error against run time on the rod benchmark: integrators (Newmark average acceleration, HHT
alpha = -0.1, generalised-alpha rho_inf = 0.5, explicit central difference) x contact laws (gap
spring at k-ratio 1, extended penalty on automatic numbers, hard contact) x
elements per rod (50, 200, 1000) x
Courant numbers dt C0 / h (1, 0.5, 0.25), on Kawashima's case, the fixed-end A2 = 3 A1 case, two
rods of unequal lengths and a bar striking a rigid wall across a gap (--cases picks some).
Every metric of docs/design.md section 3.1, the run time of the solve alone (median of the
repeats), and the Pareto front per case (no other run has both less force error and less run
time). Explicit steps above their stable limit are listed as refused. With --out:
error_study.csv and error_study.json (plot with tools/plot_pareto.py).

options)";
// The names of --cases, or nothing when one is not a rod-impact case (said on stderr).
std::optional<std::vector<std::string>> parse_cases(const std::string& list) {
  const std::vector<std::string> known = verification::rod_impact_case_names();
  std::vector<std::string> chosen;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    std::string name = list.substr(start, end - start);
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::cerr << fmt::format(
          "pound study: --cases: '{}' is not a rod-impact case (expected: {})\n", name,
          fmt::join(known, ", "));
      return std::nullopt;
    }
    if (std::find(chosen.begin(), chosen.end(), name) == chosen.end())
      chosen.push_back(std::move(name));
    start = end + 1;
  }
  return chosen;
}

}  // namespace

int study_command(const Arguments& arguments) {
  po::options_description options(kStudyUsage);
  std::string benchmark, out, cases;
  int repeats = 3;
  options.add_options()("help,h", "show this help")("out,o", po::value(&out),
                                                    "write error_study.csv/.json here")(
      "repeats", po::value(&repeats)->default_value(repeats), "timed solves per run (median)")(
      "quick", "a reduced grid (n = 50, 200; Courant 1, 0.5)")(
      "cases", po::value(&cases),
      "rod-impact: comma-separated cases (default: kawashima,area-ratio-3,unequal-lengths,"
      "rigid-wall; `pound verify --help` says what each is)");
  const auto parsed = parse_command_line(arguments, options, "benchmark", benchmark);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  if (benchmark == "stability") {
    verification::StabilityOptions map;
    if (vm.count("quick")) {
      map.stiffness_ratios = {1e-2, 1, 1e4, 1e8};
      map.step_ratios = {1e-2, 0.1, 0.5};
    }
    const auto cells = verification::stability_map(map);
    std::cout << verification::format_stability_map(cells);
    if (!out.empty()) {
      io::create_output_folder(out);
      io::write_text_atomic((std::filesystem::path(out) / "stability_map.csv").string(),
                            io::to_csv(verification::stability_table(cells)));
    }
    return 0;
  }
  if (benchmark != "rod-impact" || repeats < 1) {
    std::cerr << "pound study: name the study (rod-impact or stability) and --repeats >= 1 (see "
                 "`pound study --help`)\n";
    return 1;
  }
  verification::ErrorStudyOptions study;
  study.repeats = repeats;
  if (!cases.empty()) {
    const std::optional<std::vector<std::string>> chosen = parse_cases(cases);
    if (!chosen) return 1;
    study.benchmarks = *chosen;
  }
  if (vm.count("quick")) {
    study.elements = {50, 200};
    study.courants = {1.0, 0.5};
  }
  const auto results = verification::error_study(study);
  std::cout << verification::format_error_study(results);
  if (!out.empty()) {
    io::create_output_folder(out);
    io::write_text_atomic((std::filesystem::path(out) / "error_study.csv").string(),
                          io::to_csv(verification::error_study_table(results)));
    io::write_text_atomic((std::filesystem::path(out) / "error_study.json").string(),
                          verification::to_document(results).dump() + "\n");
  }
  return 0;
}

}  // namespace pound::app
