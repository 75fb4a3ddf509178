#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "core/errors.hpp"
#include "io/document.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"
#include "model/ground_motion.hpp"
#include "model/record_pair.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kSpectrumUsage = R"(usage: pound spectrum RECORD [options]

Reads a ground-acceleration record (PEER .AT2, or text columns) and prints its number of points,
time step, duration, peak ground acceleration and its linear elastic response spectrum:
pseudo-spectral acceleration Sa [g], pseudo-velocity Sv = Sa/w [m/s] and displacement
Sd = Sa/w^2 [m], computed with the exact piecewise-linear recurrence of Nigam & Jennings (1969).
Default periods: 40 log-spaced from 0.02 s to 10 s. --scale or --pga scale the record first, as
a model's excitation "scale" does.

With the second horizontal component of the same station (--pair FILE, or --pair-column N of
the same columns file) it prints the pair's intensity measures instead: each component's Sa, their
geometric mean, and the orientation-independent RotD50 and RotD100 (Boore 2010: the median and the
largest over the directions 0..179 degrees of the peak oscillator response to the rotated pair),
with the direction of RotD100 from the first component towards the second. --rotation turns the
pair's axes first (the components' Sa change, RotD50 and RotD100 do not).

options)";

constexpr double kStandardGravity = 9.80665;  // m/s^2
// "0.1,0.2,1" -> periods in [0, model::kLongestSpectralPeriod]; throws std::invalid_argument
// naming the bad entry.
std::vector<double> parse_periods(const std::string& text) {
  std::vector<double> periods;
  std::istringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    std::size_t used = 0;
    double period = -1.0;
    try {
      period = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" ", used) != std::string::npos || !(period >= 0.0) ||
        !std::isfinite(period))
      throw std::invalid_argument(
          fmt::format("--periods: '{}' is not a period in seconds (>= 0)", item));
    if (period > model::kLongestSpectralPeriod)
      throw std::invalid_argument(
          fmt::format("--periods: '{}' s is beyond any structure's period (at most {:g} s)", item,
                      model::kLongestSpectralPeriod));
    periods.push_back(period);
  }
  if (periods.empty()) throw std::invalid_argument("--periods: give at least one period");
  return periods;
}

struct Spectrum {
  std::vector<double> periods, sa_g, sv, sd;  // Sa in g, Sv in m/s, Sd in m
};

// A pair's spectra, in g; the direction of RotD100 in degrees.
struct PairSpectrum {
  std::vector<double> periods, first_g, second_g, geometric_mean_g, rot_d50_g, rot_d100_g,
      rot_d100_angle;
};

PairSpectrum pair_spectrum(const model::GroundMotionPair& pair, const std::vector<double>& periods,
                           double damping_ratio) {
  PairSpectrum spectrum;
  spectrum.periods = periods;
  for (double period : periods) {
    const model::PairSpectralAcceleration sa =
        model::pair_spectral_acceleration(pair, period, damping_ratio);
    spectrum.first_g.push_back(sa.first / kStandardGravity);
    spectrum.second_g.push_back(sa.second / kStandardGravity);
    spectrum.geometric_mean_g.push_back(sa.geometric_mean / kStandardGravity);
    spectrum.rot_d50_g.push_back(sa.rot_d50 / kStandardGravity);
    spectrum.rot_d100_g.push_back(sa.rot_d100 / kStandardGravity);
    spectrum.rot_d100_angle.push_back(sa.rot_d100_angle);
  }
  return spectrum;
}

std::string format_pair_spectrum(const model::GroundMotionPair& pair, const PairSpectrum& spectrum,
                                 double damping_ratio, double factor, double rotation) {
  const model::GroundMotion& first = pair.first;
  std::string text = fmt::format(
      "record     {} and {}\npoints     {}\ndt         {:g} s\nduration   {:g} s\n"
      "scaled by  {:.6g}\nrotated by {:g} degrees\n"
      "PGA        {:.4f} g and {:.4f} g\ndamping    {:g} %\n\n"
      "{:>10}  {:>10}  {:>10}  {:>10}  {:>10}  {:>10}  {:>9}\n",
      first.name, pair.second.name, first.acceleration.size(), first.time_step, first.duration(),
      factor, rotation, first.peak() / kStandardGravity, pair.second.peak() / kStandardGravity,
      100.0 * damping_ratio, "period [s]", "Sa_1 [g]", "Sa_2 [g]", "GM [g]", "RotD50 [g]",
      "RotD100 [g]", "at [deg]");
  for (std::size_t k = 0; k < spectrum.periods.size(); ++k)
    text +=
        fmt::format("{:>10.4g}  {:>10.4f}  {:>10.4f}  {:>10.4f}  {:>10.4f}  {:>10.4f}  {:>9g}\n",
                    spectrum.periods[k], spectrum.first_g[k], spectrum.second_g[k],
                    spectrum.geometric_mean_g[k], spectrum.rot_d50_g[k], spectrum.rot_d100_g[k],
                    spectrum.rot_d100_angle[k]);
  return text;
}

io::Document pair_spectrum_document(const std::string& path, const std::string& pair_path,
                                    const model::GroundMotionPair& pair,
                                    const PairSpectrum& spectrum, double damping_ratio,
                                    double factor, double rotation) {
  io::Document document;
  document.set("record", pair.first.name)
      .set("path", path)
      .set("pair_record", pair.second.name)
      .set("pair_path", pair_path)
      .set("scale_factor", factor)
      .set("rotation_deg", rotation)
      .set("npts", static_cast<long>(pair.first.acceleration.size()))
      .set("dt", pair.first.time_step)
      .set("duration", pair.first.duration())
      .set("pga1_g", pair.first.peak() / kStandardGravity)
      .set("pga2_g", pair.second.peak() / kStandardGravity)
      .set("damping_ratio", damping_ratio)
      .set("periods", spectrum.periods)
      .set("sa1_g", spectrum.first_g)
      .set("sa2_g", spectrum.second_g)
      .set("geometric_mean_g", spectrum.geometric_mean_g)
      .set("rotd50_g", spectrum.rot_d50_g)
      .set("rotd100_g", spectrum.rot_d100_g)
      .set("rotd100_angle_deg", spectrum.rot_d100_angle);
  return document;
}

Spectrum response_spectrum(const model::GroundMotion& motion, const std::vector<double>& periods,
                           double damping_ratio) {
  Spectrum spectrum;
  spectrum.periods = periods;
  for (double period : periods) {
    const double sa = model::spectral_acceleration(motion, period, damping_ratio);
    const double omega = period > 0.0 ? 2.0 * std::numbers::pi / period : 0.0;
    spectrum.sa_g.push_back(sa / kStandardGravity);
    spectrum.sv.push_back(period > 0.0 ? sa / omega : 0.0);
    spectrum.sd.push_back(period > 0.0 ? sa / (omega * omega) : 0.0);
  }
  return spectrum;
}

std::string format_spectrum(const model::GroundMotion& motion, const Spectrum& spectrum,
                            double damping_ratio, double factor) {
  std::string text = fmt::format(
      "record     {}\npoints     {}\ndt         {:g} s\nduration   {:g} s\nscaled by  {:.6g}\n"
      "PGA        {:.4f} g ({:.4g} m/s^2)\ndamping    {:g} %\n\n"
      "{:>10}  {:>10}  {:>11}  {:>11}\n",
      motion.name, motion.acceleration.size(), motion.time_step, motion.duration(), factor,
      motion.peak() / kStandardGravity, motion.peak(), 100.0 * damping_ratio, "period [s]",
      "Sa [g]", "Sv [m/s]", "Sd [m]");
  for (std::size_t k = 0; k < spectrum.periods.size(); ++k)
    text += fmt::format("{:>10.4g}  {:>10.4f}  {:>11.4e}  {:>11.4e}\n", spectrum.periods[k],
                        spectrum.sa_g[k], spectrum.sv[k], spectrum.sd[k]);
  return text;
}

io::Document spectrum_document(const std::string& path, const model::GroundMotion& motion,
                               const Spectrum& spectrum, double damping_ratio, double factor) {
  io::Document document;
  document.set("record", motion.name)
      .set("path", path)
      .set("scale_factor", factor)
      .set("npts", static_cast<long>(motion.acceleration.size()))
      .set("dt", motion.time_step)
      .set("duration", motion.duration())
      .set("pga_g", motion.peak() / kStandardGravity)
      .set("pga_m_per_s2", motion.peak())
      .set("damping_ratio", damping_ratio)
      .set("periods", spectrum.periods)
      .set("sa_g", spectrum.sa_g)
      .set("sv_m_per_s", spectrum.sv)
      .set("sd_m", spectrum.sd);
  return document;
}

struct SpectrumRequest {
  std::string record;
  std::string format = "auto", units = "g", periods_text, csv;
  int column = 1;
  double damping_ratio = 0.05;
  std::optional<double> scale, pga;  // factor; target peak [g]
  std::string pair;                  // the second component's file
  std::optional<int> pair_column;    // or its column in the record's file
  std::optional<double> rotation;    // of the pair's axes [degrees]
  bool is_pair() const { return !pair.empty() || pair_column.has_value(); }
};

po::options_description spectrum_options(SpectrumRequest& r) {
  po::options_description options(kSpectrumUsage);
  options.add_options()("help,h", "show this help")(
      "format", po::value(&r.format)->default_value(r.format),
      "at2 | columns | auto (.AT2 or an NPTS header line: at2; else columns)")(
      "column", po::value(&r.column),
      "columns file: the column to read, counting from 1 (default 1, or 2 with --time-column)")(
      "dt", po::value<double>(), "time step [s] of a columns file that does not state it")(
      "time-column", "columns file: the first column is time (gives dt)")(
      "units", po::value(&r.units)->default_value(r.units),
      "of the values in the file: g | m/s2 | cm/s2 (AT2 files are in g)")(
      "scale", po::value<double>(), "multiply the record by this factor")(
      "pga", po::value<double>(), "scale the record to this peak acceleration [g]")(
      "damping", po::value(&r.damping_ratio)->default_value(r.damping_ratio, "0.05"),
      "damping ratio of the oscillators")(
      "periods", po::value(&r.periods_text),
      "comma-separated periods [s] from 0 to 1000, e.g. 0.1,0.2,0.5,1 (0 gives the PGA)")(
      "pair", po::value(&r.pair),
      "the second horizontal component, 90 degrees from the first (a file read as the first)")(
      "pair-column", po::value<int>(),
      "the second horizontal component is this column of the record's columns file")(
      "rotation", po::value<double>(),
      "with a pair: turn its axes by this angle [degrees] from the first towards the second")(
      "csv", po::value(&r.csv),
      "write period,sa_g,sv_m_per_s,sd_m (a pair: period,sa1_g,sa2_g,geometric_mean_g,rotd50_g,"
      "rotd100_g,rotd100_angle_deg) to this CSV file")(
      "json", "print the record's data and the spectrum as one JSON object");
  return options;
}

// What is wrong with the command line, or empty.
std::string request_error(const SpectrumRequest& r) {
  if (r.record.empty()) return "name the record file (see `pound spectrum --help`)";
  if (!(r.damping_ratio >= 0.0 && r.damping_ratio < 1.0)) return "--damping must be in [0, 1)";
  if (r.column < 1) return "--column must be 1 or more";
  if (r.format != "auto" && r.format != "at2" && r.format != "columns")
    return fmt::format("unknown --format '{}' (known: at2, columns, auto)", r.format);
  for (const auto& [value, option] : {std::pair{r.scale, "--scale"}, std::pair{r.pga, "--pga"}})
    if (value && (!(*value > 0.0) || !std::isfinite(*value)))
      return fmt::format("{} must be a positive number", option);
  if (r.scale && r.pga) return "give --scale or --pga, not both";
  if (!r.pair.empty() && r.pair_column) return "give --pair or --pair-column, not both";
  if (r.pair_column && (*r.pair_column < 1 || *r.pair_column == r.column))
    return "--pair-column must be 1 or more and not the record's --column";
  if (r.rotation && !r.is_pair()) return "--rotation turns a pair: give --pair or --pair-column";
  if (r.rotation && !std::isfinite(*r.rotation)) return "--rotation must be a finite angle";
  if (r.pga && r.is_pair())
    return "--pga scales one record; scale a pair by one factor with --scale, so that its "
           "components keep their ratio";
  return {};
}

// The factor --scale or --pga asks for (1 without them); the record must not be all zeros.
double scale_factor(const SpectrumRequest& r, const model::GroundMotion& motion) {
  if (r.scale) return *r.scale;
  if (!r.pga) return 1.0;
  if (!(motion.peak() > 0.0))
    throw InputError(r.record, "", "the record is all zeros: it cannot be scaled to --pga");
  return model::scale_to_peak(motion, *r.pga * kStandardGravity);
}

// How to read the record; throws std::invalid_argument on unknown units.
io::RecordFormat record_format(const SpectrumRequest& r, const po::variables_map& vm) {
  io::RecordFormat format;
  format.format = r.format;
  format.time_column = vm.count("time-column") > 0;
  format.column = vm.count("column") ? r.column : (format.time_column ? 2 : 1);
  if (vm.count("dt")) {
    format.time_step = vm["dt"].as<double>();
    if (!(*format.time_step > 0.0) || !std::isfinite(*format.time_step))
      throw std::invalid_argument("--dt must be a positive number of seconds");
  }
  try {
    format.units = io::parse_acceleration_unit(r.units);
  } catch (const std::invalid_argument& unknown) {
    throw std::invalid_argument(std::string("--units: ") + unknown.what());
  }
  return format;
}

// What `compute` gives for `scaled` (the record or a pair's components, scaled by `factor`), or
// nothing after a usage error naming the option the factor came from, where it made them or their
// spectral accelerations overflow (--scale 1e308; the readers refuse records that overflow by
// themselves). `what`: the record or the pair, for the message.
template <typename Compute>
auto spectrum_unless_overflow(const SpectrumRequest& request, double factor, const char* what,
                              std::initializer_list<const model::GroundMotion*> scaled,
                              Compute compute) -> std::optional<decltype(compute())> {
  std::string overflow;
  for (const model::GroundMotion* motion : scaled)
    if (!std::isfinite(factor) || !std::isfinite(motion->peak()))
      overflow = fmt::format("{} overflows the number range", what);
  if (overflow.empty()) try {
      return compute();
    } catch (const std::invalid_argument& error) {
      overflow = error.what();
    }
  std::cerr << fmt::format(
      "pound spectrum: {} scaled by {:.3g}: {} (the factor of {} is far beyond any ground "
      "motion's)\n",
      request.record, factor, overflow, request.pga ? "--pga" : "--scale");
  return std::nullopt;
}

// The pair's spectra: both components read alike (the second from its own file or column),
// checked to share one time grid, turned, scaled by one factor.
int pair_spectrum_command(const SpectrumRequest& request, io::RecordFormat format,
                          const std::vector<double>& periods, bool json) {
  const std::string pair_path = request.pair.empty() ? request.record : request.pair;
  if (!request.csv.empty())
    io::check_outputs_apart({{request.record, "the record"}, {pair_path, "--pair"}},
                            {{request.csv, "--csv"}});
  model::GroundMotion first = io::read_ground_motion(request.record, format, kStandardGravity);
  if (request.pair_column) format.column = *request.pair_column;
  model::GroundMotion second = io::read_ground_motion(pair_path, format, kStandardGravity);
  if (request.pair_column) {
    first.name += fmt::format(" (column {})", request.column);
    second.name += fmt::format(" (column {})", *request.pair_column);
  }
  model::GroundMotionPair pair;
  try {
    pair = model::make_component_pair(std::move(first), std::move(second));
  } catch (const std::invalid_argument& error) {
    throw InputError(pair_path, "", error.what());
  }
  const double rotation = request.rotation.value_or(0.0);
  if (rotation != 0.0) pair = model::rotated(pair, rotation * std::numbers::pi / 180.0);
  const double factor = request.scale.value_or(1.0);
  model::scale(pair.first, factor);
  model::scale(pair.second, factor);
  const std::optional<PairSpectrum> computed =
      spectrum_unless_overflow(request, factor, "the pair", {&pair.first, &pair.second},
                               [&] { return pair_spectrum(pair, periods, request.damping_ratio); });
  if (!computed) return 1;
  const PairSpectrum& spectrum = *computed;
  if (!request.csv.empty())
    io::write_csv_atomic(request.csv, Table{{"period", "sa1_g", "sa2_g", "geometric_mean_g",
                                             "rotd50_g", "rotd100_g", "rotd100_angle_deg"},
                                            {spectrum.periods, spectrum.first_g, spectrum.second_g,
                                             spectrum.geometric_mean_g, spectrum.rot_d50_g,
                                             spectrum.rot_d100_g, spectrum.rot_d100_angle}});
  if (json)
    std::cout << pair_spectrum_document(request.record, pair_path, pair, spectrum,
                                        request.damping_ratio, factor, rotation)
                     .dump()
              << "\n";
  else
    std::cout << format_pair_spectrum(pair, spectrum, request.damping_ratio, factor, rotation);
  return 0;
}

}  // namespace

int spectrum_command(const Arguments& arguments) {
  SpectrumRequest request;
  const po::options_description options = spectrum_options(request);
  const auto parsed = parse_command_line(arguments, options, "record", request.record);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  auto usage_error = [](const std::string& what) {
    std::cerr << "pound spectrum: " << what << "\n";
    return 1;
  };
  if (vm.count("scale")) request.scale = vm["scale"].as<double>();
  if (vm.count("pga")) request.pga = vm["pga"].as<double>();
  if (vm.count("pair-column")) request.pair_column = vm["pair-column"].as<int>();
  if (vm.count("rotation")) request.rotation = vm["rotation"].as<double>();
  if (vm.count("column") == 0 && vm.count("time-column")) request.column = 2;
  if (const std::string error = request_error(request); !error.empty()) return usage_error(error);
  io::RecordFormat format;
  std::vector<double> periods = model::default_spectrum_periods();
  try {
    format = record_format(request, vm);
    if (!request.periods_text.empty()) periods = parse_periods(request.periods_text);
  } catch (const std::invalid_argument& error) {
    return usage_error(error.what());
  }

  if (request.is_pair()) return pair_spectrum_command(request, format, periods, vm.count("json"));
  if (!request.csv.empty())
    io::check_outputs_apart({{request.record, "the record"}}, {{request.csv, "--csv"}});
  // Read in m/s^2 (the spectrum's SI units); Sa is printed in g.
  model::GroundMotion motion = io::read_ground_motion(request.record, format, kStandardGravity);
  const double factor = scale_factor(request, motion);
  model::scale(motion, factor);
  const std::optional<Spectrum> computed = spectrum_unless_overflow(
      request, factor, "the record", {&motion},
      [&] { return response_spectrum(motion, periods, request.damping_ratio); });
  if (!computed) return 1;
  const Spectrum& spectrum = *computed;
  if (!request.csv.empty())
    io::write_csv_atomic(request.csv,
                         Table{{"period", "sa_g", "sv_m_per_s", "sd_m"},
                               {spectrum.periods, spectrum.sa_g, spectrum.sv, spectrum.sd}});
  if (vm.count("json"))
    std::cout
        << spectrum_document(request.record, motion, spectrum, request.damping_ratio, factor).dump()
        << "\n";
  else
    std::cout << format_spectrum(motion, spectrum, request.damping_ratio, factor);
  return 0;
}

}  // namespace pound::app
