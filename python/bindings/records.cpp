#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "bindings/bindings.hpp"
#include "core/errors.hpp"
#include "io/ground_motion_reader.hpp"
#include "model/ground_motion.hpp"
#include "model/record_pair.hpp"

namespace py = pybind11;

namespace pound::python {
namespace {

io::AccelerationUnit unit_named(const std::string& record, const std::string& units) {
  try {
    return io::parse_acceleration_unit(units);
  } catch (const std::invalid_argument& unknown) {
    throw InputError(record, "units", unknown.what());
  }
}

// g in units in which the values in `unit` stay as they are: the records are kept as given.
double gravity_in(io::AccelerationUnit unit) { return 1.0 / io::to_model_units(unit, 1.0); }

// A record file read as `pound run --motion` reads it: its name, dt, values in `units`, the
// SHA-1 of the file and the format read ("at2" or "columns").
std::tuple<std::string, double, py::array_t<double>, std::string, std::string> read_record(
    const std::string& path, const std::string& format, const std::string& units, int column,
    std::optional<double> time_step, bool time_column) {
  io::RecordFormat record_format;
  record_format.format = format;
  record_format.column = column;
  record_format.time_step = time_step;
  record_format.time_column = time_column;
  record_format.units = unit_named(path, units);
  io::RecordSource source;
  model::GroundMotion motion;
  {
    const py::gil_scoped_release unlocked;
    motion = io::read_ground_motion(path, record_format, gravity_in(record_format.units), &source);
  }
  return {motion.name, motion.time_step, to_array(motion.acceleration), source.sha1, source.format};
}

// Checks samples given as arrays as a run would (io::ground_motion_from_samples); their dt.
double check_samples(const std::string& name, const std::vector<double>& accelerations,
                     std::optional<double> time_step, const std::vector<double>& times,
                     const std::string& units) {
  const io::AccelerationUnit unit = unit_named(name, units);
  return io::ground_motion_from_samples(name, accelerations, time_step, times, unit,
                                        gravity_in(unit))
      .time_step;
}

// `second`: one second in the record's unit of time (its periods'), 1000 for milliseconds.
void check_spectrum_request(const std::string& name, const std::vector<double>& periods,
                            double damping_ratio, double second) {
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0))
    throw InputError(name, "damping",
                     fmt::format("a damping ratio in [0, 1), got {:g}", damping_ratio));
  const double longest = model::kLongestSpectralPeriod * second;
  for (std::size_t k = 0; k < periods.size(); ++k)
    if (!(periods[k] >= 0.0 && periods[k] <= longest))
      throw InputError(name, fmt::format("periods[{}]", k),
                       fmt::format("a period in [0, {:g}] of the record's unit of time ({:g} s), "
                                   "got {:g}",
                                   longest, model::kLongestSpectralPeriod, periods[k]));
}

// Pseudo-spectral accelerations S_a = w^2 max|u| at each period (model::spectral_acceleration),
// in the record's units.
py::array_t<double> spectrum(const std::string& name, double time_step,
                             const std::vector<double>& accelerations,
                             const std::vector<double>& periods, double damping_ratio,
                             double second) {
  check_spectrum_request(name, periods, damping_ratio, second);
  const model::GroundMotion motion{name, time_step, accelerations};
  std::vector<double> values(periods.size());
  {
    const py::gil_scoped_release unlocked;
    for (std::size_t k = 0; k < periods.size(); ++k)
      values[k] = model::spectral_acceleration(motion, periods[k], damping_ratio);
  }
  return to_array(values);
}

// A pair's measures at each period (model::pair_spectral_acceleration), its axes turned by
// `rotation` [degrees] first: Sa of each component, geometric mean, RotD50, RotD100 (the
// records' units) and RotD100's direction [degrees].
py::dict pair_spectrum(const model::GroundMotion& first, const model::GroundMotion& second,
                       const std::vector<double>& periods, double damping_ratio, double rotation,
                       double unit_second) {
  check_spectrum_request(first.name, periods, damping_ratio, unit_second);
  if (!std::isfinite(rotation))
    throw InputError(second.name, "rotation", fmt::format("a finite angle, got {:g}", rotation));
  model::GroundMotionPair pair;
  try {
    pair = model::make_component_pair(first, second);
  } catch (const std::invalid_argument& error) {
    throw InputError(second.name, "", error.what());
  }
  std::vector<std::vector<double>> columns(6, std::vector<double>(periods.size()));
  {
    const py::gil_scoped_release unlocked;
    if (rotation != 0.0) pair = model::rotated(pair, rotation * std::numbers::pi / 180.0);
    for (std::size_t k = 0; k < periods.size(); ++k) {
      const model::PairSpectralAcceleration sa =
          model::pair_spectral_acceleration(pair, periods[k], damping_ratio);
      const double values[] = {sa.first,   sa.second,   sa.geometric_mean,
                               sa.rot_d50, sa.rot_d100, sa.rot_d100_angle};
      for (std::size_t c = 0; c < columns.size(); ++c) columns[c][k] = values[c];
    }
  }
  py::dict result;
  const char* names[] = {"sa1", "sa2", "geometric_mean", "rotd50", "rotd100", "rotd100_angle"};
  for (std::size_t c = 0; c < columns.size(); ++c) result[names[c]] = to_array(columns[c]);
  return result;
}

}  // namespace

void bind_records(py::module_& module) {
  module.def("read_record", &read_record, py::arg("path"), py::arg("format"), py::arg("units"),
             py::arg("column"), py::arg("time_step"), py::arg("time_column"),
             "Reads a record file: (name, dt, values in `units`, SHA-1, format read).");
  module.def("check_samples", &check_samples, py::arg("name"), py::arg("accelerations"),
             py::arg("time_step"), py::arg("times"), py::arg("units"),
             "Checks a record given as samples; returns its time step.");
  module.def("spectrum", &spectrum, py::arg("name"), py::arg("time_step"), py::arg("accelerations"),
             py::arg("periods"), py::arg("damping"), py::arg("second") = 1.0,
             "Pseudo-spectral accelerations at the periods, in the record's units.");
  module.def(
      "pair_spectrum",
      [](const std::string& first_name, double first_step, const std::vector<double>& first,
         const std::string& second_name, double second_step, const std::vector<double>& second,
         const std::vector<double>& periods, double damping, double rotation, double unit_second) {
        return pair_spectrum({first_name, first_step, first}, {second_name, second_step, second},
                             periods, damping, rotation, unit_second);
      },
      py::arg("first_name"), py::arg("first_step"), py::arg("first"), py::arg("second_name"),
      py::arg("second_step"), py::arg("second"), py::arg("periods"), py::arg("damping"),
      py::arg("rotation"), py::arg("unit_second") = 1.0,
      "A pair's Sa of each component, geometric mean, RotD50, RotD100 and its direction.");
  module.def("default_spectrum_periods", &model::default_spectrum_periods,
             "40 periods log-spaced from 0.02 s to 10 s.");
}

}  // namespace pound::python
