#pragma once
// A batch set (docs/batch_format.md): models run against a set of ground-motion records, each
// record at one or more scale factors (incremental dynamic analysis), and the limits whose
// exceedance the statistics count. Read and checked by io/set_reader; expanded here into the
// list of cases, in an order that does not depend on how the cases are later distributed.
#include <optional>
#include <string>
#include <vector>

#include "builder/spec.hpp"

namespace pound::builder {

struct BatchModel {
  std::string id;    // names the case folders and the summary rows
  std::string path;  // the model file, as the program can open it (relative paths resolved)
};

// One record (a component of a recording, or a pair of horizontal components for 3-D models):
// what replaces the model's first excitation. The model keeps its direction (not a pair's),
// supports and wave passage; the record brings its file, format, units and scale (none given:
// the record as recorded).
struct BatchRecord {
  std::string id;
  ExcitationSpec excitation;  // `record` is a path the program can open
  std::string path;           // its entry in the set, "/records/2" (a folder's matches share it)
};

// The intensity measure the fragility is fitted against, of the record as scaled for a case.
enum class IntensityKind { pga, sa };            // peak ground acceleration; S_a(period), both in g
const char* intensity_name(IntensityKind kind);  // "pga", "sa"

// Of a record pair (both horizontal components): the orientation-independent median RotD50, or
// the geometric mean of the two components' measures (model/record_pair.hpp).
enum class PairMeasure { rot_d50, geometric_mean };
const char* pair_measure_name(PairMeasure measure);  // "rotd50", "geometric_mean"

struct IntensityMeasure {
  IntensityKind type = IntensityKind::pga;
  double period = 0.0;
  double damping = 0.05;
  PairMeasure pair = PairMeasure::rot_d50;  // for records that are pairs
};

// A response quantity of the summary rows, and the value above which it counts as exceeded.
struct ResponseLimit {
  std::string quantity;  // a column of batch_summary.csv (results/batch_quantities.hpp)
  double value = 0.0;
};

// Each case run as an ensemble (app/ensemble.hpp): its copies' spread in ensemble.json, and its
// row the copies' medians (or the unperturbed run's numbers).
struct SetEnsemble {
  int copies = 0;  // >= 1
  double perturbation = 1e-4;
  double robust_spread = 0.05;
  bool medians = true;  // "rows": "median"; false: "unperturbed"
};

// The bounds of an ensemble's numbers, for `pound run --ensemble` and a set's "ensemble" alike:
// which number is wrong and why (each caller names it its own way), or none.
enum class EnsembleNumber { copies, perturbation, robust_spread };
struct EnsembleError {
  EnsembleNumber number;
  std::string why;
};
std::optional<EnsembleError> ensemble_error(int copies, double perturbation, double robust_spread);

struct SetSpec {
  std::string source;  // the set file, for messages
  std::string title;
  std::vector<BatchModel> models;
  std::vector<BatchRecord> records;
  std::vector<double> scales{1.0};  // IDA factors applied on top of each record's own scale
  IntensityMeasure intensity;
  std::vector<ResponseLimit> limits;
  // Whether each case writes the time histories its model's recorders ask for (false: only
  // summary.json and case.csv, for large IDA sets where the histories would fill the disk).
  bool histories = true;
  std::optional<SetEnsemble> ensemble;
};

// One analysis of a batch: a model under a record at a scale.
struct BatchCase {
  std::size_t index = 0;  // position in the plan: the row of batch_summary.csv
  std::size_t model = 0, record = 0;
  double scale = 1.0;
  std::string name;  // "<model id>/<record id>/x<scale>": the case's folder under --out
};

// The cases model by model, record by record, scale by scale.
std::vector<BatchCase> plan_cases(const SetSpec& set);

}  // namespace pound::builder
