#pragma once
// A 3,000 t mass on an 8 m cantilever over a Takeda base hinge without hardening, under gravity
// with chord P-Delta, shaken by the bundled firm-ground record at 0.6 g: once the hinge yields
// (M_y = `yield_moment` N m) its post-yield stiffness is -W/h = -3.7 MN/m and it runs away. What
// the collapse tests of a run and of a batch share.
#include <fmt/format.h>

#include <string>

namespace pound::testing {

inline std::string collapsing_column(double yield_moment) {
  return fmt::format(R"({{
    "dimension": 2,
    "nodes": [{{"id": "base", "x": 0, "y": 0}}, {{"id": "hn", "x": 0, "y": 0}},
              {{"id": "top", "x": 0, "y": 8}}],
    "materials": [{{"id": "c", "youngs_modulus": 3e10, "density": 0}}],
    "elements": [{{"id": "e1", "type": "beam", "nodes": ["hn", "top"], "material": "c",
                   "area": 3, "inertia": 0.88}}],
    "masses": [{{"node": "top", "mass": 3e6}}],
    "supports": [{{"node": "base", "fix": ["x", "y", "rz"]}}, {{"node": "hn", "fix": ["x", "y"]}}],
    "links": [{{"id": "hinge", "nodes": ["hn", "base"], "dof": "rotation",
                "law": {{"type": "takeda", "stiffness": 9.9e10, "yield_force": {},
                        "hardening_ratio": 0}}}}],
    "monitors": {{"drifts": [{{"id": "pier", "kind": "pier", "bottom": "base", "top": "top",
                              "height": 8, "yield_displacement": 0.01, "base_element": "e1"}}]}},
    "gravity": {{"p_delta": "chord"}},
    "excitations": [{{"record": "{}/ground_motions/synthetic_firm_01.AT2", "units": "g",
                      "scale": {{"pga": 0.6}}}}],
    "analysis": {{"time_step": 0.005, "duration": 10}}}})",
                     yield_moment, POUND_SOURCE_DIR);
}

}  // namespace pound::testing
