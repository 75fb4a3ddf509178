#include "app/rod_impact_request.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

#include "app/model_loading.hpp"
#include "builder/spec.hpp"
#include "integrators/integrator_catalog.hpp"
#include "verification/rod_impact.hpp"

namespace pound::app {

std::optional<std::string> rod_impact_request_error(const RodImpactRequest& request) {
  if (request.elements < 1) return "--n must be >= 1";
  if (const auto shortfall = memory_shortfall(2.0 * (request.elements + 1.0)))
    return fmt::format("--n {}: the rods would {}", request.elements, *shortfall);
  if (!(request.stiffness_ratio > 0.0)) return "--k-ratio must be > 0";
  // Past this the contact's stiffness is lost to round-off against the rods' elements: 1e200
  // let the rods pass through each other with no contact at all.
  if (!(request.stiffness_ratio <= 1e12))
    return "--k-ratio must be <= 1e12 (a stiffer link is lost to round-off beside the rods' "
           "elements)";
  if (!(request.dt_ratio > 0.0)) return "--dt-ratio must be > 0";
  if (request.courant && !(*request.courant > 0.0)) return "--courant must be > 0";
  if (!(request.duration_ratio >= 1.5)) return "--duration-ratio must be >= 1.5 (the error window)";
  if (!(request.tolerance > 0.0 && request.tolerance < 0.1))
    return "--tolerance must be in (0, 0.1): a looser test takes the contact force itself as "
           "round-off";
  if (!(request.eta >= 0.0)) return "--eta must be >= 0";
  return std::nullopt;
}

namespace {

// A step longer than the run computes nothing, and its metrics would read as a perfect result
// (the energy kept, the rods' velocities exact, since they never meet).
void check_step_fits_run(const verification::RodImpactOptions& run) {
  const verification::RodImpactTimes times = verification::rod_impact_times(run);
  constexpr double kMostSteps = 1e8;
  if (times.duration / times.time_step > kMostSteps)
    throw std::invalid_argument(fmt::format(
        "{} with --duration-ratio {:g}: the time step {:.4g} would take {:.3g} steps over the run "
        "({:.4g}), more than {:g}",
        run.courant ? "--courant" : "--dt-ratio", run.duration_ratio, times.time_step,
        times.duration / times.time_step, times.duration, kMostSteps));
  if (!(times.time_step < times.duration))
    throw std::invalid_argument(fmt::format(
        "{}: the time step {:.4g} is longer than the whole run ({:.4g}: the first contact at "
        "{:.4g}, then --duration-ratio {:g} contact durations of {:.4g}), so no step would be "
        "computed",
        run.courant ? "--courant" : "--dt-ratio", times.time_step, times.duration,
        times.first_contact, run.duration_ratio, times.contact_duration));
}

}  // namespace

verification::RodImpactOptions rod_impact_options(const RodImpactRequest& request) {
  if (const std::optional<std::string> error = rod_impact_request_error(request))
    throw std::invalid_argument(*error);
  verification::RodImpactOptions run;
  run.pair = verification::rod_impact_case(request.case_name, request.elements,
                                           request.stiffness_ratio, request.law, request.eta);
  run.dt_ratio = request.dt_ratio;
  run.courant = request.courant;
  run.duration_ratio = request.duration_ratio;
  run.relative_tolerance = request.tolerance;
  run.integrator = integrators::IntegratorChoice::preset(request.integrator);
  if (request.eta_given && request.law != "extended_penalty")
    throw std::invalid_argument(fmt::format(
        "--eta is the extended penalty's damping factor: the law {} has none (give --law "
        "extended_penalty)",
        request.law));
  // The options that set a method's parameters, where the method has them (`owner`: the one
  // that does, for the message).
  for (const auto& [option, name, owner, value, given] :
       {std::tuple{"--alpha", "alpha", "hht", request.hht_alpha, request.hht_alpha_given},
        std::tuple{"--rho-inf", "rho_infinity", "generalized_alpha", request.rho_infinity,
                   request.rho_infinity_given}}) {
    const integrators::IntegratorParameter* parameter = run.integrator.method().parameter(name);
    if (given && !parameter)
      throw std::invalid_argument(fmt::format("{} is not a parameter of {} (give --integrator {})",
                                              option, request.integrator, owner));
    if (parameter) {
      if (!parameter->admits(value))
        throw std::invalid_argument(fmt::format("{} must be in [{:g}, {:g}]", option,
                                                parameter->minimum,
                                                parameter->maximum.value_or(INFINITY)));
      run.integrator.set(name, value);
    }
  }
  // An explicit method without a step takes its stable one, as "time_step": "auto" does.
  if (run.integrator.is_explicit() && !request.courant && !request.dt_ratio_given)
    run.stable_fraction = builder::AnalysisSpec{}.safety_factor;
  else
    check_step_fits_run(run);
  if (request.profiles) run.profile_times = {0.0, 0.25, 0.5, 0.75};
  return run;
}

}  // namespace pound::app
