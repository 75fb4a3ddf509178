#include "links/clough.hpp"

#include "links/law_registry.hpp"

namespace pound::links {

Clough::Clough(double stiffness, double yield_force, double hardening_ratio,
               double unloading_exponent)
    : law_({.stiffness = stiffness,
            .yield_force = yield_force,
            .hardening_ratio = hardening_ratio,
            .unloading_exponent = unloading_exponent,
            .reloading_factor = 0.0}) {}

const LawEntry& Clough::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "clough",
      .formula =
          "bilinear skeleton `k`, `F_y`, post-yield `b·k`; unloading `k·(δ_y/δ_p)^α` "
          "(α = 0: elastic `k`), δ_p the peak; past zero force reloading straight toward the "
          "largest previous excursion on the other side (the yield point if it has not "
          "yielded), then the skeleton; inner loops return along the unloading line",
      .source =
          "peak-oriented degrading stiffness: Clough & Johnston (1966), Proc. 2nd Japan "
          "Earthquake Engineering Symposium; inner loops as this program's takeda",
      .parameters = {{"stiffness", Range::positive, "F/L", "elastic stiffness k"},
                     {"yield_force", Range::positive, "F", "F_y (δ_y = F_y/k)"},
                     {"hardening_ratio", Range::fraction, "-",
                      "b, post-yield stiffness / k, 0 <= b < 1 (default 0)"},
                     {"unloading_exponent", Range::fraction, "-",
                      "α, 0 <= α < 1: unloading stiffness `k·(δ_y/δ_p)^α` (default 0: elastic "
                      "unloading)"}},
      .required = {"stiffness", "yield_force"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"stiffness", 4e7}, {"yield_force", 6e5}, {"hardening_ratio", 0.02}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double k = *law.number("stiffness"), yield = *law.number("yield_force");
        const double hardening = law.number("hardening_ratio").value_or(0.0);
        const double alpha = law.number("unloading_exponent").value_or(0.0);
        return [=](const LinkContext&) {
          return std::make_unique<Clough>(k, yield, hardening, alpha);
        };
      }};
  return entry;
}

}  // namespace pound::links
