#pragma once
// Error against run time on the rod benchmark (docs/design.md §3.1): a grid of integrator x
// contact law x mesh x time step on Kawashima's case, the fixed-end A2 = 3 A1 case, two rods of
// unequal lengths and a bar against a rigid wall across a gap (rod_impact_case_names()), every
// metric plus the run time of the solve alone (median of repeats), and the Pareto front per case:
// the runs no other run beats on both force error and run time.
#include <string>
#include <vector>

#include "integrators/integrator_catalog.hpp"
#include "io/document.hpp"
#include "io/output.hpp"
#include "verification/rod_impact.hpp"

namespace pound::verification {

struct StudyCase {
  std::string benchmark;   // a rod_impact_case_names() entry
  std::string integrator;  // "newmark_average_acceleration", "hht", "generalized_alpha",
                           // "central_difference"
  std::string law;         // "gap_spring" | "extended_penalty"
  int elements = 0;        // per rod
  double courant = 0.0;    // dt C0 / h
};

struct StudyResult {
  StudyCase input;
  bool refused = false;  // explicit step above its stable limit
  std::string refusal;
  RodImpactMetrics metrics;  // run_time_s: median of the repeats
  bool pareto = false;
};

struct ErrorStudyOptions {
  std::vector<std::string> benchmarks{"kawashima", "area-ratio-3", "unequal-lengths", "rigid-wall"};
  // Every method of the catalog with its study parameters.
  std::vector<integrators::IntegratorChoice> methods = integrators::IntegratorChoice::studied();
  std::vector<std::string> laws{"gap_spring", "extended_penalty", "hard_contact"};
  std::vector<int> elements{50, 200, 1000};
  std::vector<double> courants{1.0, 0.5, 0.25};
  int repeats = 3;
};

std::vector<StudyResult> error_study(const ErrorStudyOptions& options);
// Marks, per benchmark, the runs that no other run beats on both force_l2_error and run time.
void mark_pareto_front(std::vector<StudyResult>& results);

std::string format_error_study(const std::vector<StudyResult>& results);
io::TextTable error_study_table(const std::vector<StudyResult>& results);
io::Document to_document(const std::vector<StudyResult>& results);

}  // namespace pound::verification
