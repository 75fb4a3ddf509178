// libFuzzer target: a batch set file through its reader (models, records by file or by folder and
// pattern, scales, intensity measure, limits) and the case plan. Paths resolve against a folder
// that does not exist, so most references are refused as missing; absolute ones reach the real
// file system, which the reader only inspects and lists.
#include <cstddef>
#include <cstdint>

#include "builder/batch_spec.hpp"
#include "fuzz/fuzz_contract.hpp"
#include "io/set_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = pound::fuzz::as_text(data, size);
  pound::fuzz::expect_input_error_only("set", [&text] {
    const pound::builder::SetSpec set =
        pound::io::parse_set(text, "/nonexistent/pound_fuzz/set.json");
    (void)pound::builder::plan_cases(set);
  });
  return 0;
}
