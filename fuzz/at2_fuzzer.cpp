// libFuzzer target: the PEER .AT2 reader, forced ("at2") and by detection ("auto" on a file name
// without the .AT2 extension, which looks for an NPTS header).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_contract.hpp"
#include "io/ground_motion_reader.hpp"

namespace {
constexpr double kStandardGravity = 9.80665;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = pound::fuzz::as_text(data, size);
  pound::fuzz::expect_input_error_only("at2", [&text] {
    pound::io::RecordFormat format;
    format.format = "at2";
    (void)pound::io::parse_ground_motion(text, "fuzz.AT2", format, kStandardGravity);
  });
  pound::fuzz::expect_input_error_only("auto", [&text] {
    (void)pound::io::parse_ground_motion(text, "fuzz.txt", pound::io::RecordFormat{},
                                         kStandardGravity);
  });
  return 0;
}
