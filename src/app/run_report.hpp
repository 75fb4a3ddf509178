#pragma once
// What `pound run` prints of a run: a headline (DOFs, steps, Newton iterations, run time), then a
// line per contact and restrainer, one for all structural springs, a line per joint and per
// drift monitor, and the energy balance.
#include <string>

#include "core/units.hpp"
#include "results/run_summary.hpp"

namespace pound::app {

// A value with its unit in the model's units; alone where the model names none (forces, moments
// and energies without a mass unit).
std::string with_unit(double value, const std::string& unit, int digits = 4);

std::string run_headline(const std::string& model_path, const results::RunSummary& run);
// The lines of links, joints and drifts, each number with its unit in the model's `units` (forces,
// moments and energies only where the model names a mass unit).
std::string run_report(const results::RunSummary& run, const UnitNames& units);
// Why a step is automatic: "time_step": "auto", or none given to an explicit integrator.
std::string automatic_step_words(bool defaulted);
// How an automatic explicit step was chosen (the stable step and the fraction); empty otherwise.
std::string step_line(const results::RunSummary& run, const UnitNames& units);
std::string energy_line(const results::RunSummary& run, const UnitNames& units);

}  // namespace pound::app
