// libFuzzer target: a model file through the reader and, when it reads, through what `pound run`
// does before its first step: the acceleration units of each record, the builder (generators, id
// references, zero-length elements, self-links) with one small record per excitation, and the
// assembly of the structural system (DOF numbering, singular DOFs).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "fuzz/fuzz_contract.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/model_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = pound::fuzz::as_text(data, size);
  pound::fuzz::expect_input_error_only("model", [&text] {
    const pound::builder::ModelSpec spec = pound::io::parse_model(text, "fuzz.json");
    std::vector<pound::model::GroundMotion> motions;
    for (const pound::builder::ExcitationSpec& excitation : spec.excitations) {
      (void)pound::io::parse_acceleration_unit(excitation.units);
      // Short, so that a fuzzed model never integrates for long; non-zero so scaling to a PGA or
      // a spectral acceleration has something to scale.
      motions.push_back({"fuzz.AT2", 0.01, {0.0, 0.1, -0.2, 0.05, 0.0}});
    }
    pound::builder::BuiltModel built = pound::builder::build(spec, motions);
    pound::assembly::StructuralSystem system(built.model);
  });
  return 0;
}
