#pragma once
// Reading ground-acceleration records in the forms users download them:
//  * PEER .AT2 files of every header generation (NGA-West2 "NPTS=  5372, DT=   .0100 SEC",
//    NGA-West1 "4096    0.0100    NPTS, DT", PEER 2000, AT2-like free-text headers): values
//    free-format in Fortran E, F or D notation, glued fields, short last lines, CRLF;
//  * plain text columns: comment ('%', '#', '!', "//") and header lines before the data, tabs
//    and commas, CRLF, optionally a time column; dt from an option, the header ("dt=0.005") or
//    the time column.
// Values are converted to the model's units. A header that states units other than the ones
// given is an error, as is anything malformed: each InputError names the file, the line and
// what was expected.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "model/ground_motion.hpp"

namespace pound::io {

// A column (or a time column) asked of a PEER .AT2 file, which holds one component: a model
// names the field that asked for it.
class ColumnOfAt2Error : public InputError {
 public:
  using InputError::InputError;
};

// A record whose header states other units than it is read in: a model names the field that
// set them (its excitation's "units").
class StatedUnitsError : public InputError {
 public:
  using InputError::InputError;
};

enum class AccelerationUnit { g, m_per_s2, cm_per_s2, model };  // "g", "m/s2", "cm/s2", "model"

struct RecordFormat {
  // "at2", "columns", or "auto": at2 for a .AT2 extension (any case) or a header line with
  // NPTS in the first lines, else columns.
  std::string format = "auto";
  int column = 1;  // 1-based column to read in a columns file (counting the time column)
  // Required for columns files unless the header states dt or `time_column` is set; when the
  // file states it too, the two must agree.
  std::optional<double> time_step;
  bool time_column = false;  // the first column is time (uniform; dt is derived from it)
  AccelerationUnit units = AccelerationUnit::g;  // of the values in the file; AT2 files are in g
  // One second in the model's time unit (1000 for ms). The times a file states (an .AT2's DT, a
  // columns header's dt, a time column) are in seconds, as records are distributed; `time_step`,
  // given beside the file, and the record returned are in the model's unit.
  double second = 1.0;
};

// What a record was read from, for a run to be traced to it: the format read ("at2" or
// "columns", after "auto") and the SHA-1 of the file's bytes (as `sha1sum` prints it).
struct RecordSource {
  std::string format;
  std::string sha1;
};

// Reads a record and converts it to model units: `g_in_model_units` is the acceleration of
// gravity in the model's units (9.80665 for m and s). Throws pound::InputError(file, "line N",
// what) for anything wrong in the file. `source`, when given, is filled.
model::GroundMotion read_ground_motion(const std::string& path, const RecordFormat& format,
                                       double g_in_model_units, RecordSource* source = nullptr);

// The SHA-1 of `bytes` in lowercase hex.
std::string sha1_hex(std::string_view bytes);

// Same from the file's text; `path` names it in messages and in the motion, and its extension
// counts for "auto" as the file's would.
model::GroundMotion parse_ground_motion(const std::string& text, const std::string& path,
                                        const RecordFormat& format, double g_in_model_units);

// "g", "m/s2", "cm/s2" or "model"; throws std::invalid_argument listing the valid names.
AccelerationUnit parse_acceleration_unit(const std::string& text);

// What one `unit` is in the model's units of acceleration (1 for "model").
double to_model_units(AccelerationUnit unit, double g_in_model_units);

// A record given as values rather than a file (the Python module's arrays): `accelerations` in
// `unit`, sampled every `time_step`, or at `times` (uniform, as a time column must be; the
// record's origin moves to the first), converted to model units as a file's values would be.
// Fewer than 2 samples, a value that is not finite, a step that is not positive or times that
// are not uniform throw InputError(`name`, "accelerations[k]" or "times[k]", what).
model::GroundMotion ground_motion_from_samples(const std::string& name,
                                               const std::vector<double>& accelerations,
                                               std::optional<double> time_step,
                                               const std::vector<double>& times,
                                               AccelerationUnit unit, double g_in_model_units);

}  // namespace pound::io
