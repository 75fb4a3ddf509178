#pragma once
// Every time integrator a model file or a command may name, each described once by its class
// (beside its code): its name, whether it is explicit, its parameters with their defaults and
// ranges, the presets that name it with fixed parameters, and how it is made. The reader, the
// writer, `check`, `verify` and the studies iterate this; integrator_catalog.cpp lists the
// entries, and nothing else keeps a list of integrator names.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "integrators/integrator.hpp"

namespace pound::integrators {

struct IntegratorParameter {
  std::string name;
  double fallback = 0.0;  // the default
  double minimum = 0.0;
  bool minimum_strict = false;  // value > minimum, else value >= minimum
  std::optional<double> maximum;
  std::string meaning;

  bool admits(double value) const;
};

// A name that stands for a method with some of its parameters fixed
// ("newmark_linear_acceleration": Newmark with beta = 1/6).
struct IntegratorPreset {
  std::string name;
  std::map<std::string, double> parameters;
};

struct IntegratorEntry {
  std::string name;  // the "type" of an integrator object in model files
  std::string description;
  bool is_explicit = false;
  std::vector<IntegratorParameter> parameters;
  std::vector<IntegratorPreset> presets;
  // What the error-against-run-time and stability studies run (the study presets of old: HHT at
  // its default alpha, generalised-alpha with rho_inf = 0.5).
  std::map<std::string, double> study_parameters;
  // Parameters complete (every one given or defaulted); their ranges checked.
  std::function<std::unique_ptr<Integrator>(const std::map<std::string, double>& parameters,
                                            const ConvergenceTest& test)>
      make;
  // c of the method's algorithmic energy c dt^2 a^T M a, with which the kinetic energy and the
  // trapezoidal work sums of results/energy_balance.hpp balance exactly whatever the forces:
  // Newmark with gamma = 1/2 has c = (beta - 1/4) / 2, central difference (beta = 0) -1/8.
  // None (0) for the methods that dissipate by design.
  std::function<double(const std::map<std::string, double>& parameters)> acceleration_energy;
  // Whether the method damps the highest modes numerically with these parameters, so that its
  // energy balance cannot close (none: it never does).
  std::function<bool(const std::map<std::string, double>& parameters)> dissipates;
  // The largest omega dt at which the undamped method stays stable, for a method stable only
  // below it (central difference 2; Newmark with beta < gamma / 2, 1 / sqrt(gamma / 2 - beta):
  // linear acceleration 2 sqrt(3)); none (or no function) where every step is stable.
  std::function<std::optional<double>(const std::map<std::string, double>& parameters)>
      stability_limit;

  const IntegratorParameter* parameter(std::string_view wanted) const;
};

// Every method, in the order of the docs and of error messages.
const std::vector<const IntegratorEntry*>& integrator_catalog();
const IntegratorEntry* find_integrator(std::string_view name);
std::vector<std::string> integrator_names();
// The preset names of every method, in catalog order.
std::vector<std::string> preset_names();

// A method with its parameters, as a model file, a command or a study chooses it.
class IntegratorChoice {
 public:
  IntegratorChoice();  // Newmark's average acceleration (the trapezoidal rule)
  explicit IntegratorChoice(const IntegratorEntry& method,
                            std::map<std::string, double> parameters = {});
  // By preset name; std::invalid_argument for a name no method has.
  static IntegratorChoice preset(std::string_view name);
  // Each method with its study parameters, in catalog order.
  static std::vector<IntegratorChoice> studied();

  const IntegratorEntry& method() const { return *method_; }
  bool is_explicit() const { return method_->is_explicit; }
  // The value given, or the method's default.
  double parameter(const std::string& name) const;
  void set(const std::string& name, double value) { parameters_[name] = value; }
  // Every parameter of the method with its value.
  std::map<std::string, double> values() const;
  // The name of the preset it equals, else the method's name.
  std::string label() const;
  std::unique_ptr<Integrator> make(const ConvergenceTest& test = {}) const;
  double acceleration_energy() const;  // IntegratorEntry::acceleration_energy, or 0
  bool dissipates() const;             // IntegratorEntry::dissipates, or false
  // IntegratorEntry::stability_limit, or none.
  std::optional<double> stability_limit() const;

 private:
  const IntegratorEntry* method_;
  std::map<std::string, double> parameters_;
};

}  // namespace pound::integrators
