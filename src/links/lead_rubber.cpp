#include "links/lead_rubber.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "links/bilinear_spring.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

namespace {

// The default k_u / k_d: the elastic stiffness of a lead-rubber bearing is commonly estimated as
// 10 times its post-yield one when no test gives it (Naeim & Kelly 1999).
constexpr double kElasticToPostYield = 10.0;

}  // namespace

const LawEntry& LeadRubber::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "lead_rubber",
      .formula =
          "bilinear, yield lines `F = k_d·δ ± Q_d`, elastic slope k_u: "
          "`F_y = Q_d·k_u/(k_u − k_d)`, `b = k_d/k_u`; per cycle to ±D "
          "`EDC = 4·Q_d·(D − δ_y)`, `k_eff = k_d + Q_d/D`",
      .source =
          "lead-rubber isolator, bilinear model (AASHTO Guide Specifications for Seismic "
          "Isolation Design 2010; Naeim & Kelly 1999)",
      .parameters = {{"characteristic_strength", Range::positive, "F",
                      "Q_d, force of the post-yield branch at zero displacement"},
                     {"post_yield_stiffness", Range::positive, "F/L", "k_d"},
                     {"elastic_stiffness", Range::positive, "F/L", "k_u, > k_d (default 10·k_d)"}},
      .required = {"characteristic_strength", "post_yield_stiffness"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"characteristic_strength", 1e5},
                  {"post_yield_stiffness", 1e6},
                  {"elastic_stiffness", 1e7}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double strength = *law.number("characteristic_strength");
        const double post_yield = *law.number("post_yield_stiffness");
        const double elastic =
            law.number("elastic_stiffness").value_or(kElasticToPostYield * post_yield);
        if (!(elastic > post_yield))
          throw InputError(where.file, where.path + "/elastic_stiffness",
                           fmt::format("lead_rubber: elastic_stiffness k_u = {} must be above "
                                       "post_yield_stiffness k_d = {} (no yield point otherwise)",
                                       elastic, post_yield));
        const double yield_force = strength * elastic / (elastic - post_yield);
        const double hardening = post_yield / elastic;
        return [=](const LinkContext&) {
          return std::make_unique<BilinearSpring>(elastic, yield_force, hardening, "lead_rubber");
        };
      }};
  return entry;
}

}  // namespace pound::links
