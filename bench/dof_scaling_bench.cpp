// How the cost of a time step grows with the number of DOFs (issue 5: linearly from 10^3 to
// 10^6). The rod pair of the rod-impact benchmark meshed with 500 ... 500,000 elements per rod
// (1,002 ... 1,000,002 DOFs), in contact from the start (gap 0), 400 steps at its Courant number;
// the solve's CPU time (one factorisation included) is divided by the steps. The exponent p of
// time per step ~ DOFs^p is fitted by least squares on the logarithms; p = 1 is linear.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <iostream>
#include <vector>

#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"

namespace {

constexpr int kSteps = 400;

// CPU time of this thread: on a shared machine, wall time would count the other processes.
double thread_cpu_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// range(0): 0 Newmark average acceleration (Courant 1), 1 central difference (Courant 0.5).
void dof_scaling(benchmark::State& state) {
  const bool explicit_method = state.range(0) == 1;
  const std::vector<int> elements = {500, 5000, 50000, 500000};
  std::vector<double> dofs, seconds_per_step;
  for (auto _ : state) {
    dofs.clear();
    seconds_per_step.clear();
    for (const int n : elements) {
      pound::verification::RodImpactOptions options;
      options.pair = pound::verification::rod_impact_case("kawashima", n, 1.0, "extended_penalty");
      options.courant = explicit_method ? 0.5 : 1.0;
      if (explicit_method)
        options.integrator = pound::integrators::IntegratorChoice::preset("central_difference");
      // Steps in 3 T are 6 n / courant: ask for kSteps of them.
      options.duration_ratio = 3.0 * kSteps / (6.0 * n / *options.courant);
      pound::verification::RodPairSimulation simulation(options);
      pound::verification::RodImpactResult result;
      double best = INFINITY;
      for (int repeat = 0; repeat < (n < 50000 ? 5 : 2); ++repeat) {
        const double start = thread_cpu_seconds();
        const long steps = simulation.solve(result).steps;
        best = std::min(best, (thread_cpu_seconds() - start) / static_cast<double>(steps));
      }
      dofs.push_back(static_cast<double>(simulation.dofs()));
      seconds_per_step.push_back(best);
    }
  }
  // Least squares on log(time per step) = p log(DOFs) + c.
  double mx = 0, my = 0;
  const double count = static_cast<double>(dofs.size());
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    mx += std::log(dofs[k]) / count;
    my += std::log(seconds_per_step[k]) / count;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    sxy += (std::log(dofs[k]) - mx) * (std::log(seconds_per_step[k]) - my);
    sxx += (std::log(dofs[k]) - mx) * (std::log(dofs[k]) - mx);
  }
  const double exponent = sxy / sxx;
  state.counters["exponent"] = exponent;
  // Between neighbouring sizes: where the vectors leave the caches the cost per DOF steps up.
  for (std::size_t k = 1; k < dofs.size(); ++k)
    state.counters[fmt::format("exponent_{:.0e}_{:.0e}", dofs[k - 1], dofs[k])] =
        std::log(seconds_per_step[k] / seconds_per_step[k - 1]) / std::log(dofs[k] / dofs[k - 1]);
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    state.counters[fmt::format("us_per_step_{:.0e}", dofs[k])] = 1e6 * seconds_per_step[k];
    state.counters[fmt::format("ns_per_step_dof_{:.0e}", dofs[k])] =
        1e9 * seconds_per_step[k] / dofs[k];
  }
}
BENCHMARK(dof_scaling)
    ->ArgName("explicit")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
