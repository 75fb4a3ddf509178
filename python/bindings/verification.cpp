#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>
#include <string>
#include <tuple>

#include "app/rod_impact_request.hpp"
#include "bindings/bindings.hpp"
#include "verification/restitution.hpp"
#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"
#include "verification/two_element.hpp"

namespace py = pybind11;

namespace pound::python {
namespace {

// The keyword arguments of pound.verify.rod_impact, each setting one number of the request.
using Setter = void (*)(app::RodImpactRequest&, const py::handle&);
const std::map<std::string, Setter>& rod_impact_setters() {
  static const std::map<std::string, Setter> setters{
      {"case", [](auto& r, const py::handle& v) { r.case_name = v.cast<std::string>(); }},
      {"n", [](auto& r, const py::handle& v) { r.elements = v.cast<int>(); }},
      {"k_ratio", [](auto& r, const py::handle& v) { r.stiffness_ratio = v.cast<double>(); }},
      {"dt_ratio",
       [](auto& r, const py::handle& v) {
         r.dt_ratio = v.cast<double>();
         r.dt_ratio_given = true;
       }},
      {"courant", [](auto& r, const py::handle& v) { r.courant = v.cast<double>(); }},
      {"duration_ratio", [](auto& r, const py::handle& v) { r.duration_ratio = v.cast<double>(); }},
      {"law", [](auto& r, const py::handle& v) { r.law = v.cast<std::string>(); }},
      {"eta",
       [](auto& r, const py::handle& v) {
         r.eta = v.cast<double>();
         r.eta_given = true;
       }},
      {"integrator", [](auto& r, const py::handle& v) { r.integrator = v.cast<std::string>(); }},
      {"alpha",
       [](auto& r, const py::handle& v) {
         r.hht_alpha = v.cast<double>();
         r.hht_alpha_given = true;
       }},
      {"rho_inf",
       [](auto& r, const py::handle& v) {
         r.rho_infinity = v.cast<double>();
         r.rho_infinity_given = true;
       }},
      {"tolerance", [](auto& r, const py::handle& v) { r.tolerance = v.cast<double>(); }}};
  return setters;
}

app::RodImpactRequest rod_impact_request(const py::dict& options) {
  app::RodImpactRequest request;
  for (const auto& [key, value] : options) {
    const std::string name = key.cast<std::string>();
    const auto setter = rod_impact_setters().find(name);
    if (setter == rod_impact_setters().end())
      throw py::type_error("rod_impact() got an unexpected keyword argument '" + name + "'");
    setter->second(request, value);
  }
  return request;
}

// The metrics (`pound verify rod-impact --json`) and the time step, time, force, exact force
// and penetration histories.
std::tuple<std::string, double, py::dict> rod_impact(const py::dict& options) {
  const verification::RodImpactOptions run = app::rod_impact_options(rod_impact_request(options));
  verification::RodImpactResult result;
  {
    const InterruptGuard guard;
    const py::gil_scoped_release unlocked;
    result = verification::run_rod_impact(run);
  }
  py::dict histories;
  histories["time"] = to_array(result.time);
  histories["force"] = to_array(result.force);
  histories["exact_force"] = to_array(result.exact_force);
  histories["penetration"] = to_array(result.penetration);
  return {verification::to_document(result.metrics).dump(), result.time_step, histories};
}

std::string restitution() {
  const py::gil_scoped_release unlocked;
  return verification::to_document(verification::restitution_study()).dump();
}

std::string two_element() {
  const py::gil_scoped_release unlocked;
  return verification::to_document(verification::two_element_sweep()).dump();
}

}  // namespace

void bind_verification(py::module_& module) {
  module.def("verify_rod_impact", &rod_impact, py::arg("options"),
             "`pound verify rod-impact`: the metrics as JSON text, dt and the histories.");
  module.def("verify_restitution", &restitution,
             "`pound verify restitution --json`: every impact law's achieved restitution.");
  module.def("verify_two_element", &two_element,
             "`pound verify two-element --json`: Suzuki & Toi's two-element eigenvalues.");
}

}  // namespace pound::python
