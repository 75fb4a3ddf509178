#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "app/rod_impact_request.hpp"
#include "builder/spec.hpp"
#include "core/errors.hpp"
#include "integrators/integrator_catalog.hpp"
#include "io/model_reader.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"
#include "verification/block_belt.hpp"
#include "verification/rod_impact_2d.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kVerifyUsage = R"(usage: pound verify <benchmark> [options]

benchmarks:
  rod-impact    two rods collide; FE against the exact wave solution (options below)
  two-element   Suzuki & Toi's two-element model: the program's generalised eigenvalues against
                eqs. 4 and 23-24 over a sweep of alpha0/k, alpha2, k2/k1, m2/m1 (error <= 1e-10)
  restitution   two masses collide once through every impact law, e = 0.3, 0.5, 0.7, 0.9:
                target and achieved restitution, peak force, contact time, penetration
  rod-impact-2d Suzuki & Toi's rods (fixed-end case, 50 elements, extended penalty) as 2-D
                strips of quads with mu = 0.6 at the interface: force_l2_error of the 2-D and the
                1-D model against the exact 1-D solution (--n-across, --csv)
  block-belt    Suzuki & Toi's elastic block on a moving belt (--model, default
                models/block_on_belt.json) swept over Pi = V0 sqrt(m k_s) / (mu P): apparent
                mu_dynamic / mu_static, stick-slip and tumbling per speed (--speeds, --periods,
                --out DIR writes block_belt_sweep.csv and block_belt_histories.csv)

rod-impact: two elastic rods collide; the finite element solution (lumped-mass rods, contact link,
Newmark with Newton iteration) is compared with the exact solution of the wave equation computed by
characteristics. Defaults: Kawashima (1980): E = 100, A = 1, rho = 0.1, L = 10, V0 = 0.1 each
way, n = 10 elements per rod, link as stiff as the adjacent element, dt = T_I/100 (explicit
integrators: 0.8 of their stable step).

Metrics (docs/design.md section 3.1): force_l2_error over [0, 1.5 T], duration_error,
separation_velocity_error, peak_force_ratio, max_penetration, min_force, run_time_s (solve alone),
steps, newton_iterations.

Each benchmark reads its own options; one it does not read (or --alpha without hht, --rho-inf
without generalized_alpha, --eta without extended_penalty, a step longer than the run) is refused
rather than ignored.

options)";

// Every option of `pound verify`; each benchmark reads its own.
struct VerifyOptions {
  int elements = 10;
  double stiffness_ratio = 1.0, dt_ratio = 0.01, duration_ratio = 3.0, tolerance = 1e-10;
  std::string law = "gap_spring", case_name = "kawashima", csv, profiles_csv, study, integrator;
  double courant = 0.0, eta = 1.0, hht_alpha = -0.1, rho_infinity = 0.8;
  bool courant_given = false, dt_ratio_given = false;
  bool eta_given = false, hht_alpha_given = false, rho_infinity_given = false;
  std::string block_model = "models/block_on_belt.json", speeds, out_folder;
  double periods = 4.0;
  int elements_across = 4;
  bool json = false;
};

int usage_error(const std::string& what) {
  std::cerr << "pound verify: " << what << "\n";
  return 1;
}

// The integrators `--integrator` takes, from the catalog.
std::string integrator_option_help() {
  std::string names;
  for (const std::string& name : integrators::preset_names())
    names += (names.empty() ? "" : " | ") + name;
  return names + " (explicit ones: refused above their stable step)";
}

void add_verify_options(po::options_description& description, VerifyOptions& options) {
  description.add_options()("help,h", "show this help")(
      "case", po::value(&options.case_name)->default_value(options.case_name),
      "benchmark case: kawashima (free rods, +-V0), fixed-end (rod into a rod at rest with a fixed "
      "far end), area-ratio-3 (fixed-end with the striking rod's area 3x), unequal-lengths "
      "(free rods of one material, the struck one at rest and twice as long: apparent "
      "restitution 1/2, the striking rod at rest after), rigid-wall (the striking rod into a fixed "
      "rigid wall across a gap of L/200: contact at gap/V0 for 2L/C0 at the force rho C0 V0 A)")(
      "n", po::value(&options.elements)->default_value(options.elements), "elements per rod")(
      "k-ratio", po::value(&options.stiffness_ratio)->default_value(options.stiffness_ratio),
      "link stiffness / axial stiffness E A / h of the softer adjacent element")(
      "dt-ratio", po::value(&options.dt_ratio)->default_value(options.dt_ratio),
      "time step / exact contact duration")(
      "courant", po::value(&options.courant),
      "time step as a Courant number dt C0 / h of the striking rod (in place of --dt-ratio)")(
      "duration-ratio", po::value(&options.duration_ratio)->default_value(options.duration_ratio),
      "run length after first contact / exact contact duration")(
      "law", po::value(&options.law)->default_value(options.law),
      "contact law: gap_spring (stiffness from --k-ratio), extended_penalty (Suzuki & Toi's "
      "automatic numbers) or hard_contact (a constraint, e = 0; any integrator)")(
      "eta", po::value(&options.eta)->default_value(options.eta),
      "extended_penalty: damping factor of alpha1")(
      "integrator", po::value(&options.integrator)->default_value("newmark_average_acceleration"),
      integrator_option_help().c_str())(
      "alpha",
      po::value(&options.hht_alpha)
          ->default_value(options.hht_alpha, fmt::format("{:g}", options.hht_alpha)),
      "hht: alpha in [-1/3, 0]")(
      "rho-inf",
      po::value(&options.rho_infinity)
          ->default_value(options.rho_infinity, fmt::format("{:g}", options.rho_infinity)),
      "generalized_alpha: spectral radius at infinite frequency, in [0, 1]")(
      "tolerance", po::value(&options.tolerance)->default_value(options.tolerance),
      "relative unbalanced-force tolerance of the Newton iteration")(
      "json", "print the metrics as one JSON object")(
      "csv", po::value(&options.csv),
      "write time, force, exact_force, penetration to this CSV file")(
      "profiles-csv", po::value(&options.profiles_csv),
      "write velocity and stress along both rods at 0, T/4, T/2, 3T/4 after first contact, FE and "
      "exact (Kawashima Fig. 6)")(
      "n-across", po::value(&options.elements_across)->default_value(options.elements_across),
      "rod-impact-2d: elements across each strip")(
      "model", po::value(&options.block_model)->default_value(options.block_model),
      "block-belt: the block-on-belt model")(
      "speeds", po::value(&options.speeds),
      "block-belt: comma-separated values of Pi (default: 1e-3 ... 1e8)")(
      "periods", po::value(&options.periods)->default_value(options.periods),
      "block-belt: run length in spring periods 2 pi sqrt(m / k_s), at most 1000")(
      "out", po::value(&options.out_folder), "block-belt: folder for the sweep and history CSVs")(
      "study", po::value(&options.study),
      "kawashima: Kawashima's tables over k_I, n and dt; penalty: Suzuki & Toi's alpha0-only and "
      "extended-penalty cases (Figs. 7-8)");
}

int verify_two_element(bool json) {
  const auto results = verification::two_element_sweep();
  std::cout << (json ? verification::to_document(results).dump() + "\n"
                     : verification::format_two_element(results));
  double worst = 0.0;
  for (const auto& r : results) worst = std::max(worst, r.relative_error);
  return worst <= 1e-10 ? 0 : 1;
}

int verify_restitution(bool json) {
  const auto rows = verification::restitution_study();
  std::cout << (json ? verification::to_document(rows).dump() + "\n"
                     : verification::format_restitution(rows));
  bool met = true;
  for (const auto& r : rows)
    met = met && (!r.calibrated || std::abs(r.achieved - r.target) <= 0.005);
  return met ? 0 : 1;
}

int verify_rod_impact_2d(int elements_across, const std::string& csv) {
  if (elements_across < 1) return usage_error("--n-across must be >= 1");
  verification::RodImpact2dOptions run = verification::suzuki_toi_rods_2d();
  run.elements_across = elements_across;
  // Two DOFs a node; each strip has (along + 1) x (across + 1) nodes.
  const double along = run.pair.left.elements + run.pair.right.elements + 2.0;
  if (const auto shortfall = memory_shortfall(2.0 * along * (elements_across + 1.0)))
    return usage_error(
        fmt::format("--n-across {}: the strips would {}", elements_across, *shortfall));
  const verification::RodImpact2dResult r = verification::run_rod_impact_2d(run);
  if (!csv.empty()) io::write_csv_atomic(csv, verification::rod_impact_2d_table(r));
  std::cout << fmt::format(
      "rod impact in 2-D (Suzuki & Toi 1987, Fig. 11): fixed-end case, 50 x {} quads per strip, "
      "mu = {:g}, {} contact links\n"
      "                 force_l2_error  peak/exact   steps\n"
      "  2-D strips     {:>14.4f}  {:>10.4f}  {:>6}\n"
      "  1-D rods       {:>14.4f}  {:>10.4f}  {:>6}\n"
      "exact 1-D: peak force {:.6g}, contact duration {:.6g}\n",
      run.elements_across, run.friction, r.contact_links, r.force_l2_error_2d,
      r.peak_force_2d / r.exact_peak_force, r.steps_2d, r.force_l2_error_1d,
      r.peak_force_1d / r.exact_peak_force, r.steps_1d, r.exact_peak_force, r.exact_duration);
  return 0;
}

// The values of --speeds, or nothing when one is not a positive number (said on stderr).
std::optional<std::vector<double>> parse_speeds(const std::string& list) {
  std::vector<double> speeds;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, end - start);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty() || !(value > 0.0) || !std::isfinite(value)) {
      std::cerr << fmt::format("pound verify: --speeds: '{}' is not a positive number\n", item);
      return std::nullopt;
    }
    speeds.push_back(value);
    start = end + 1;
  }
  return speeds;
}

int verify_block_belt(const VerifyOptions& options) {
  std::vector<double> speeds = verification::block_belt_speeds();
  if (!options.speeds.empty()) {
    const std::optional<std::vector<double>> given = parse_speeds(options.speeds);
    if (!given) return 1;
    speeds = *given;
  }
  if (!(options.periods > 0.0 && options.periods <= verification::kMostBlockBeltPeriods))
    return usage_error(fmt::format(
        "--periods must be in (0, {:g}]: the steady state settles within the default 4, and a "
        "spring period of the bundled block is about 10^4 steps",
        verification::kMostBlockBeltPeriods));
  const builder::ModelSpec spec = io::read_model_file(options.block_model);
  const verification::BlockBeltScene scene = verification::block_belt_scene(spec);
  verification::BlockBeltOptions run;
  run.periods = options.periods;
  std::vector<verification::BlockBeltPoint> points;
  for (double speed : speeds) {
    points.push_back(verification::run_block_belt(spec, speed, run));
    if (!options.json)
      std::cerr << fmt::format("  Pi = {:.3g}: {} steps in {:.2f} s\n", speed, points.back().steps,
                               points.back().run_time_s);
  }
  if (!options.out_folder.empty()) {
    std::filesystem::create_directories(options.out_folder);
    io::write_csv_atomic(options.out_folder + "/block_belt_sweep.csv",
                         verification::block_belt_sweep_table(points));
    io::write_csv_atomic(options.out_folder + "/block_belt_histories.csv",
                         verification::block_belt_history_table(points));
  }
  std::cout << (options.json ? verification::to_document(scene, points).dump() + "\n"
                             : verification::format_block_belt(scene, points));
  return 0;
}

int verify_rod_impact_study(const std::string& study, bool json) {
  if (study != "kawashima" && study != "penalty")
    return usage_error(fmt::format("unknown study '{}' (known: kawashima, penalty)", study));
  const auto studies =
      study == "kawashima" ? verification::kawashima_study() : verification::penalty_study();
  if (json) {
    std::cout << verification::to_document(studies).dump() << "\n";
  } else {
    for (const auto& s : studies) std::cout << verification::format_study(s) << "\n";
  }
  return 0;
}

// The rod-impact numbers among the options.
RodImpactRequest rod_impact_request(const VerifyOptions& options) {
  RodImpactRequest request;
  request.case_name = options.case_name;
  request.elements = options.elements;
  request.stiffness_ratio = options.stiffness_ratio;
  request.dt_ratio = options.dt_ratio;
  request.dt_ratio_given = options.dt_ratio_given;
  if (options.courant_given) request.courant = options.courant;
  request.duration_ratio = options.duration_ratio;
  request.law = options.law;
  request.eta = options.eta;
  request.eta_given = options.eta_given;
  request.integrator = options.integrator;
  request.hht_alpha = options.hht_alpha;
  request.hht_alpha_given = options.hht_alpha_given;
  request.rho_infinity = options.rho_infinity;
  request.rho_infinity_given = options.rho_infinity_given;
  request.tolerance = options.tolerance;
  request.profiles = !options.profiles_csv.empty();
  return request;
}

int verify_rod_impact(const VerifyOptions& options) {
  const RodImpactRequest request = rod_impact_request(options);
  if (const std::optional<std::string> error = rod_impact_request_error(request))
    return usage_error(*error);
  if (!options.study.empty()) return verify_rod_impact_study(options.study, options.json);
  verification::RodImpactOptions run;
  try {
    run = rod_impact_options(request);
  } catch (const std::invalid_argument& error) {
    return usage_error(error.what());
  }
  if (!options.csv.empty() && !options.profiles_csv.empty())
    io::check_outputs_apart({}, {{options.csv, "--csv"}, {options.profiles_csv, "--profiles-csv"}});
  const verification::RodImpactResult result = verification::run_rod_impact(run);
  if (!options.csv.empty())
    io::write_csv_atomic(options.csv, verification::force_history_table(result));
  if (!options.profiles_csv.empty())
    io::write_csv_atomic(options.profiles_csv, verification::profile_table(result));
  if (options.json) {
    std::cout << verification::to_document(result.metrics).dump() << "\n";
  } else {
    std::cout << fmt::format(
                     "rod impact, case {}, n = {}, k-ratio {:g}, dt = {:.4e}{}, {}\n",
                     options.case_name, options.elements, options.stiffness_ratio, result.time_step,
                     run.stable_fraction ? fmt::format(" ({:g} x the stable step: no --dt-ratio or "
                                                       "--courant given)",
                                                       *run.stable_fraction)
                                         : std::string(),
                     options.integrator)
              << verification::format_metrics(result.metrics);
  }
  return 0;
}

int unknown_benchmark(const std::string& benchmark) {
  std::cerr << (benchmark.empty()
                    ? "pound verify: name a benchmark: rod-impact, two-element, restitution, "
                      "rod-impact-2d, block-belt\n"
                    : fmt::format("pound verify: unknown benchmark '{}' (known: rod-impact, "
                                  "two-element, restitution, rod-impact-2d, block-belt)\n",
                                  benchmark));
  return 1;
}

// An option given (not defaulted) that the benchmark does not read: it would be ignored, and the
// results taken for what it asked (`verify two-element --n 50`, `--study` with `--k-ratio`).
std::optional<std::string> option_of_another_benchmark(const po::variables_map& given,
                                                       const std::string& benchmark) {
  static const std::map<std::string, std::set<std::string>> reads{
      {"rod-impact",
       {"case", "n", "k-ratio", "dt-ratio", "courant", "duration-ratio", "law", "eta", "integrator",
        "alpha", "rho-inf", "tolerance", "json", "csv", "profiles-csv", "study"}},
      {"two-element", {"json"}},
      {"restitution", {"json"}},
      {"rod-impact-2d", {"n-across", "csv"}},
      {"block-belt", {"model", "speeds", "periods", "out", "json"}}};
  const auto benchmark_reads = reads.find(benchmark);
  if (benchmark_reads == reads.end()) return std::nullopt;  // unknown_benchmark says so
  const bool study = given.count("study") > 0;
  for (const auto& [name, value] : given) {
    if (name == "benchmark" || value.defaulted()) continue;
    if (study && name != "study" && name != "json")
      return fmt::format("--{} does not apply to --study, which runs its own grid of cases", name);
    if (!benchmark_reads->second.contains(name))
      return fmt::format("--{} is not an option of the {} benchmark (it would be ignored)", name,
                         benchmark);
  }
  return std::nullopt;
}

}  // namespace

int verify_command(const Arguments& arguments) {
  po::options_description description(kVerifyUsage);
  VerifyOptions options;
  add_verify_options(description, options);
  std::string benchmark;
  const auto parsed = parse_command_line(arguments, description, "benchmark", benchmark);
  if (!parsed) return 0;
  options.json = parsed->count("json") > 0;
  options.courant_given = parsed->count("courant") > 0;
  options.dt_ratio_given = !(*parsed)["dt-ratio"].defaulted();
  options.eta_given = !(*parsed)["eta"].defaulted();
  options.hht_alpha_given = !(*parsed)["alpha"].defaulted();
  options.rho_infinity_given = !(*parsed)["rho-inf"].defaulted();
  if (const std::optional<std::string> stray = option_of_another_benchmark(*parsed, benchmark))
    return usage_error(*stray);
  if (options.courant_given && options.dt_ratio_given)
    return usage_error(
        "--courant and --dt-ratio both give the time step: give one (the other would be ignored)");
  if (benchmark == "two-element") return verify_two_element(options.json);
  if (benchmark == "restitution") return verify_restitution(options.json);
  if (benchmark == "rod-impact-2d")
    return verify_rod_impact_2d(options.elements_across, options.csv);
  if (benchmark == "block-belt") return verify_block_belt(options);
  if (benchmark == "rod-impact") return verify_rod_impact(options);
  return unknown_benchmark(benchmark);
}

}  // namespace pound::app
