// libFuzzer target: the column reader under the option sets a model can give: dt from the header
// only, a time column, dt given (which a header dt must agree with), another column in cm/s2.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_contract.hpp"
#include "io/ground_motion_reader.hpp"

namespace {
constexpr double kStandardGravity = 9.80665;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = pound::fuzz::as_text(data, size);
  pound::io::RecordFormat header_dt;
  header_dt.format = "columns";
  pound::io::RecordFormat time_column = header_dt;
  time_column.time_column = true;
  time_column.column = 2;
  pound::io::RecordFormat given_dt = header_dt;
  given_dt.time_step = 0.01;
  pound::io::RecordFormat second_column = given_dt;
  second_column.column = 2;
  second_column.units = pound::io::AccelerationUnit::cm_per_s2;
  for (const pound::io::RecordFormat& format : {header_dt, time_column, given_dt, second_column})
    pound::fuzz::expect_input_error_only("columns", [&] {
      (void)pound::io::parse_ground_motion(text, "fuzz.txt", format, kStandardGravity);
    });
  return 0;
}
