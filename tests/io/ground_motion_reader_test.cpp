// Reading ground-motion records as users download them. The real records live outside the
// repository, in ../shared/ground_motions (support/shared_records.hpp; the tests that read them
// skip without it); most bad inputs are those files edited in memory and written to a temporary
// folder. The `pound spectrum` command is tested here too, on the same files.
#include "io/ground_motion_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "support/process.hpp"
#include "support/shared_records.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

const std::string kShared = pound::testing::shared_record("");
const std::string kShipped = POUND_SOURCE_DIR "/ground_motions/";
const std::string kNgaWest2 = kShared + "ImperialValley1940_ElCentroArray9_180_NGAW2.AT2";
const std::string kKobeColumns = kShared + "Kobe1995_JMA_NS-EW_cms2_dt0.005.txt";

using pound::testing::read_text;

RecordFormat at2() {
  RecordFormat format;
  format.format = "at2";
  return format;
}

RecordFormat columns(int column, AccelerationUnit units = AccelerationUnit::cm_per_s2) {
  RecordFormat format;
  format.format = "columns";
  format.column = column;
  format.units = units;
  return format;
}

// Values in g: the model's g is 1.
model::GroundMotion read_in_g(const std::string& path, const RecordFormat& format) {
  return read_ground_motion(path, format, 1.0);
}

// `value` rounds to `expected` at 3 significant digits.
void expect_three_significant_digits(double value, double expected, const std::string& what) {
  const double half_unit = 0.5 * std::pow(10.0, std::floor(std::log10(expected)) - 2.0);
  EXPECT_LE(std::abs(value - expected), half_unit * (1.0 + 1e-9))
      << what << ": " << value << " is not " << expected << " to 3 significant digits";
}

// ---- the shared real records -----------------------------------------------------------------

struct SharedRecord {
  const char* file;
  int column;  // 0 for AT2
  std::size_t npts;
  double dt;
  double pga_g;  // PROVENANCE.md (check.py), 3 significant digits
};

std::ostream& operator<<(std::ostream& out, const SharedRecord& r) {
  return out << r.file << (r.column ? fmt::format(" column {}", r.column) : "");
}

const SharedRecord kSharedRecords[] = {
    {"ImperialValley1940_ElCentroArray9_180_NGAW2.AT2", 0, 5372, 0.01, 0.281},
    {"ImperialValley1940_ElCentroArray9_180_PEER2000.AT2", 0, 4000, 0.01, 0.313},
    {"ImperialValley1940_ElCentro_NS_Peknold.AT2", 0, 1559, 0.02, 0.319},
    {"SanFernando1971_PacoimaDam_164.AT2", 0, 4172, 0.01, 1.22},
    {"Northridge1994_Rinaldi_228.AT2", 0, 1991, 0.01, 0.874},
    {"Northridge1994_SylmarConverterSta_142.AT2", 0, 8773, 0.005, 0.923},
    {"LomaPrieta1989_Corralitos_000.AT2", 0, 7997, 0.005, 0.645},
    {"LomaPrieta1989_GilroyGavilanColl_067.AT2", 0, 7991, 0.005, 0.357},
    {"Kobe1995_NishiAkashi_090.AT2", 0, 4096, 0.01, 0.503},
    {"Landers1992_Lucerne_260.AT2", 0, 9625, 0.005, 0.725},
    {"ImperialValley1979_ElCentroArray6_230.AT2", 0, 7818, 0.005, 0.449},
    {"ChiChi1999_TCU078_E.AT2", 0, 18000, 0.005, 0.447},
    {"ChiChi1999_TCU052_N_PEER2000.AT2", 0, 18000, 0.005, 0.419},
    {"Kocaeli1999_Fatih_090.AT2", 0, 30598, 0.005, 0.162},
    {"Duzce1999_Lamont362_N.AT2", 0, 4316, 0.01, 0.0441},
    {"ChuetsuOki2007_MatsushiroTokamachi_NS.AT2", 0, 6000, 0.01, 0.185},
    {"Kobe1995_JMA_NS-EW_cms2_dt0.005.txt", 1, 6000, 0.005, 0.841},
    {"Kobe1995_JMA_NS-EW_cms2_dt0.005.txt", 2, 6000, 0.005, 0.631},
    {"Northridge1994_SylmarOliveView_360-090_cms2_dt0.005.txt", 1, 6000, 0.005, 0.875},
    {"Northridge1994_SylmarOliveView_360-090_cms2_dt0.005.txt", 2, 6000, 0.005, 0.605},
    {"Northridge1994_Newhall_FN-FP_cms2_dt0.005.txt", 1, 6000, 0.005, 0.736},
    {"Northridge1994_Newhall_FN-FP_cms2_dt0.005.txt", 2, 6000, 0.005, 0.656},
    {"Northridge1994_Rinaldi_228-318_cms2_dt0.005.txt", 1, 6000, 0.005, 0.840},
    {"Northridge1994_Rinaldi_228-318_cms2_dt0.005.txt", 2, 6000, 0.005, 0.476},
    {"ChiChi1999_TCU068_NS-EW_cms2_dt0.005.txt", 1, 18000, 0.005, 0.512},
    {"ChiChi1999_TCU068_NS-EW_cms2_dt0.005.txt", 2, 18000, 0.005, 0.369},
};

// The NPTS an AT2 header states, found independently of the reader: the first whole number on
// the line that names NPTS.
std::size_t header_npts(const std::string& path) {
  std::istringstream lines(read_text(path));
  for (std::string line; std::getline(lines, line);) {
    if (line.find("NPTS") == std::string::npos) continue;
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      const std::size_t digits = word.find_first_of("0123456789");
      if (digits == std::string::npos || word.find('.') != std::string::npos) continue;
      return std::stoul(word.substr(digits));
    }
  }
  return 0;
}

class GroundMotionSharedRecord : public ::testing::TestWithParam<SharedRecord> {
 protected:
  void SetUp() override { POUND_SKIP_WITHOUT_SHARED_RECORDS(); }
};

TEST_P(GroundMotionSharedRecord, ReadsWithTheStatedSizeStepAndPeak) {
  const SharedRecord& r = GetParam();
  const std::string path = kShared + r.file;
  RecordFormat format = r.column ? columns(r.column) : at2();
  if (r.column) format.time_step = r.dt;  // Newhall states no dt; the others must agree
  const model::GroundMotion motion = read_in_g(path, format);
  EXPECT_EQ(motion.name, r.file);
  EXPECT_EQ(motion.acceleration.size(), r.npts);
  if (!r.column) {
    EXPECT_EQ(motion.acceleration.size(), header_npts(path));
  }
  EXPECT_NEAR(motion.time_step, r.dt, 1e-15);
  expect_three_significant_digits(motion.peak(), r.pga_g, "PGA [g]");
  std::cout << fmt::format("{:<58} {:>2} {:>6} {:>6} PGA {:.4f} g\n", r.file,
                           r.column ? std::to_string(r.column) : "-", motion.acceleration.size(),
                           motion.time_step, motion.peak());
}

INSTANTIATE_TEST_SUITE_P(GroundMotionReader, GroundMotionSharedRecord,
                         ::testing::ValuesIn(kSharedRecords));

TEST(GroundMotionReader, EveryFileInTheSharedFolderIsInTheTable) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(kShared)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".AT2" && entry.path().extension() != ".txt") continue;
    ++files;
    const bool listed = std::any_of(std::begin(kSharedRecords), std::end(kSharedRecords),
                                    [&](const SharedRecord& r) { return name == r.file; });
    EXPECT_TRUE(listed) << name;
  }
  EXPECT_EQ(files, 21u);
}

TEST(GroundMotionReader, AutoFormatAndUnitConversion) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const model::GroundMotion in_g = read_in_g(kNgaWest2, RecordFormat{});
  const model::GroundMotion in_si = read_ground_motion(kNgaWest2, RecordFormat{}, 9.80665);
  EXPECT_DOUBLE_EQ(in_si.peak(), 9.80665 * in_g.peak());
  const model::GroundMotion kobe_si = read_ground_motion(kKobeColumns, columns(1), 9.80665);
  EXPECT_NEAR(kobe_si.peak(), 0.841 * 9.80665, 0.0005 * 9.80665);
}

// FIPS 180 test vectors: a record's hash is what `sha1sum` prints for it.
TEST(RecordHash, Sha1OfTheStandardTestVectors) {
  EXPECT_EQ(sha1_hex(""), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
  EXPECT_EQ(sha1_hex("abc"), "a9993e364706816aba3e25717850c26c9cd0d89d");
  EXPECT_EQ(sha1_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
  EXPECT_EQ(sha1_hex(std::string(1000000, 'a')), "34aa973cd4c4daa4f61eeb2bdbad27316534016f");
}

TEST(RecordHash, ReadingARecordGivesItsFormatAndHash) {
  const std::string at2 =
      (std::filesystem::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_01.AT2")
          .string();
  RecordSource source;
  (void)read_ground_motion(at2, {}, 9.80665, &source);
  EXPECT_EQ(source.format, "at2");
  std::ifstream file(at2, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(source.sha1, sha1_hex(bytes));
}

TEST(GroundMotionReader, AccelerationUnitNames) {
  EXPECT_EQ(parse_acceleration_unit("cm/s2"), AccelerationUnit::cm_per_s2);
  EXPECT_EQ(parse_acceleration_unit("m/s2"), AccelerationUnit::m_per_s2);
  EXPECT_EQ(parse_acceleration_unit("g"), AccelerationUnit::g);
  EXPECT_EQ(parse_acceleration_unit("model"), AccelerationUnit::model);
  try {
    parse_acceleration_unit("furlongs");
    ADD_FAILURE() << "accepted 'furlongs'";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("g, m/s2, cm/s2 or gal, model"), std::string::npos);
  }
}

TEST(GroundMotionReader, ColumnsTimeStepFromTheHeader) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  RecordFormat format = columns(1);  // no dt given: "Acc. in cm/sec^2 and dt=0.005 sec."
  EXPECT_DOUBLE_EQ(read_in_g(kKobeColumns, format).time_step, 0.005);
}

// ---- the records this repository ships ---------------------------------------------------------

TEST(GroundMotionReader, ShippedSyntheticRecordsHitTheirPeakAndEndAtRest) {
  const std::vector<std::pair<std::string, double>> shipped = {{"synthetic_firm_01.AT2", 0.4},
                                                               {"synthetic_firm_02.AT2", 0.3},
                                                               {"synthetic_soft_01.AT2", 0.35},
                                                               {"synthetic_soft_02.AT2", 0.3}};
  for (const auto& [file, pga] : shipped) {
    const model::GroundMotion motion = read_ground_motion(kShipped + file, RecordFormat{}, 9.80665);
    EXPECT_NEAR(motion.peak() / 9.80665, pga, 1e-7) << file;
    double velocity = 0.0, displacement = 0.0;  // exact for the piecewise-linear record
    const double dt = motion.time_step;
    for (std::size_t k = 0; k + 1 < motion.acceleration.size(); ++k) {
      const double a0 = motion.acceleration[k], a1 = motion.acceleration[k + 1];
      displacement += dt * velocity + dt * dt / 6.0 * (2.0 * a0 + a1);
      velocity += 0.5 * dt * (a0 + a1);
    }
    std::cout << file << ": final velocity " << velocity << " m/s, displacement " << displacement
              << " m\n";
    EXPECT_LT(std::abs(velocity), 1e-6) << file;
    EXPECT_LT(std::abs(displacement), 1e-5) << file;
  }
}

// ---- record quirks that must read correctly --------------------------------------------------

class GroundMotionReaderFiles : public pound::testing::PoundProcess {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path file = folder_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }
};

std::vector<double> values_of(const model::GroundMotion& motion) { return motion.acceleration; }

TEST_F(GroundMotionReaderFiles, FortranQuirksReadCorrectly) {
  // A label list with '=', D exponents, glued fields, a short last line, lone CR line ends,
  // a byte-order mark and a DOS end-of-file mark.
  const std::string text =
      "\xEF\xBB\xBFSOME TITLE\rEVENT\rACCELERATION IN UNITS OF G\rNPTS, DT = 7, 0.02\r"
      " 1.0D-01-2.0E-01 3.0\r-.4E+01 5.0 +.6\r7\r\x1a";
  const model::GroundMotion motion = read_in_g(write("quirks.at2", text), RecordFormat{});
  EXPECT_EQ(values_of(motion), (std::vector<double>{0.1, -0.2, 3.0, -4.0, 5.0, 0.6, 7.0}));
  EXPECT_DOUBLE_EQ(motion.time_step, 0.02);
}

TEST_F(GroundMotionReaderFiles, SizeLineLayouts) {
  const std::vector<std::string> layouts = {
      "NPTS=      3, DT=   .0100 SEC,   0 POLE @    30.00000 HZ,  -5 POLE @      .05000",
      "3    0.0100    NPTS, DT",
      "NPTS, DT = 3, 0.01",
      "DT= .01 SEC NPTS= 3",
      "3 .01",
      "NPTS= 3 DT= 1.0D-02"};
  for (const std::string& layout : layouts) {
    const std::string path = write("layout.AT2", "T\nE\nU\n" + layout + "\n 1. 2. 3.\n");
    const model::GroundMotion motion = read_in_g(path, RecordFormat{});
    EXPECT_EQ(motion.acceleration.size(), 3u) << layout;
    EXPECT_DOUBLE_EQ(motion.time_step, 0.01) << layout;
  }
}

TEST_F(GroundMotionReaderFiles, ColumnsWithTimeColumnCommentsAndCsv) {
  const std::string text =
      "# station X, acceleration in g\ntime,acc\n0.5, 0.0\n0.52,0.1 # peak soon\n"
      "\n% a comment inside the data\n0.54, -0.25\n0.56,0.05\n";
  RecordFormat format = columns(2, AccelerationUnit::g);
  format.time_column = true;
  const model::GroundMotion motion = read_in_g(write("record.csv", text), format);
  EXPECT_EQ(values_of(motion), (std::vector<double>{0.0, 0.1, -0.25, 0.05}));
  EXPECT_NEAR(motion.time_step, 0.02, 1e-15);
}

TEST_F(GroundMotionReaderFiles, AutoDetectsAnAt2HeaderInATextFile) {
  const std::string path = write("record.txt", "title\nNPTS= 2, DT= 0.5\n0.1\n0.2\n");
  const model::GroundMotion motion = read_in_g(path, RecordFormat{});
  EXPECT_EQ(values_of(motion), (std::vector<double>{0.1, 0.2}));
  EXPECT_DOUBLE_EQ(motion.time_step, 0.5);
}

// ---- bad inputs ---------------------------------------------------------------------------------

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// The text of `file` with its line `number` (1-based) replaced by `line`.
std::string with_line(const std::string& file, std::size_t number, const std::string& line) {
  std::vector<std::string> lines = split_lines(read_text(file));
  lines.at(number - 1) = line;
  return join_lines(lines);
}

// The text of `file` without its last `count` lines.
std::string without_last_lines(const std::string& file, std::size_t count) {
  std::vector<std::string> lines = split_lines(read_text(file));
  lines.resize(lines.size() - count);
  return join_lines(lines);
}

// Whether a bad record is made here or edited from one of the real records.
enum class Source { made_here, real_record };

struct BadRecord {
  const char* name;
  std::function<std::string()> text;  // null: the file is not written (path given below)
  RecordFormat format;
  std::string where, phrase;
  Source source = Source::made_here;
};

std::ostream& operator<<(std::ostream& out, const BadRecord& r) { return out << r.name; }

RecordFormat with_time_step(RecordFormat format, double time_step) {
  format.time_step = time_step;
  return format;
}

RecordFormat with_time_column(RecordFormat format) {
  format.time_column = true;
  return format;
}

const std::vector<BadRecord>& bad_records() {
  static const std::vector<BadRecord> records = {
      {"empty", [] { return std::string(); }, at2(), "line 1", "the file is empty"},
      {"blank", [] { return std::string(" \r\n\t\n"); }, columns(1), "line 1", "the file is empty"},
      {"binary", [] { return std::string("\x00\x01PK\x03\x04 garbage\n", 15); }, RecordFormat{},
       "line 1", "binary data"},
      {"at2_npts_value_missing",
       [] { return with_line(kNgaWest2, 4, "NPTS=       , DT=   .0100 SEC,"); }, at2(), "line 4",
       "expected the number of points and the time step, as in 'NPTS=", Source::real_record},
      {"at2_size_line_missing",
       [] { return with_line(kNgaWest2, 4, "   .1000000E-02   .1000000E-02"); }, at2(), "line 4",
       "found '.1000000E-02   .1000000E-02'", Source::real_record},
      {"at2_npts_not_whole", [] { return with_line(kNgaWest2, 4, "NPTS= 5372.5, DT= .0100 SEC"); },
       at2(), "line 4", "NPTS must be a whole number of points; found '5372.5'",
       Source::real_record},
      {"at2_dt_zero", [] { return with_line(kNgaWest2, 4, "NPTS=   5372, DT=   .0000 SEC"); },
       at2(), "line 4", "DT must be a positive time step; found '.0000'", Source::real_record},
      {"at2_too_few_values", [] { return without_last_lines(kNgaWest2, 3); }, at2(), "line 1076",
       "the file ends after 5360 of the 5372 values NPTS gives (line 4)", Source::real_record},
      // Found by fuzz_at2: the reader reserved NPTS values before reading them.
      {"at2_npts_beyond_memory",
       [] {
         return std::string(
             "PEER\nEVENT\nACCELERATION IN G\nNPTS= 999999999999999999, DT= .01\n.1 .2 .3\n");
       },
       at2(), "line 5",
       "the file ends after 3 of the 999999999999999999 values NPTS gives (line 4)"},
      // One sample lasts no time: `pound run` completed with no step taken.
      {"at2_single_sample",
       [] { return std::string("PEER\nEVENT\nACCELERATION IN G\nNPTS= 1, DT= .01\n.1\n"); }, at2(),
       "line 4", "NPTS must be at least 2 (one sample lasts no time); found '1'"},
      {"columns_single_sample", [] { return std::string("% dt=0.01\n0.1\n"); },
       columns(1, AccelerationUnit::g), "line 2",
       "only 1 row of data: a record needs at least 2 samples"},
      {"at2_too_many_values",
       [] { return read_text(kNgaWest2) + "   .1000000E-02   .1000000E-02\n"; }, at2(), "line 1080",
       "more values than NPTS = 5372 (line 4): value 5373 is on this line", Source::real_record},
      {"at2_word_in_the_data",
       [] { return with_line(kNgaWest2, 100, "   .1000000E-02   .1O00000E-02   .1000000E-02"); },
       at2(), "line 100", "'.1O00000E-02' is not a number", Source::real_record},
      {"at2_nan", [] { return with_line(kNgaWest2, 200, "   .1000000E-02   NaN"); }, at2(),
       "line 200", "'NaN' is not a finite number", Source::real_record},
      {"at2_overflow", [] { return with_line(kNgaWest2, 201, "   .1000000E+999"); }, at2(),
       "line 201", "'.1000000E+999' is not a finite number", Source::real_record},
      {"at2_header_only", [] { return std::string("PEER NGA\nEVENT\n"); }, at2(), "line 2",
       "the file ends after 2 lines, before the NPTS and DT line"},
      {"at2_velocity_record",
       [] { return with_line(kNgaWest2, 3, "VELOCITY TIME SERIES IN UNITS OF CM/S"); }, at2(),
       "line 3", "this is a velocity record", Source::real_record},
      {"at2_dt_disagrees", [] { return read_text(kNgaWest2); }, with_time_step(at2(), 0.02),
       "line 4", "the file gives dt = 0.01 but the time step given is 0.02", Source::real_record},
      {"columns_three_of_two", [] { return read_text(kKobeColumns); }, columns(3), "line 4",
       "column 3 does not exist: this line has 2 values", Source::real_record},
      {"columns_garbage_in_the_data",
       [] { return with_line(kKobeColumns, 1000, "-1.05E-01\t\tn/a"); }, columns(1), "line 1000",
       "'n/a' is not a number", Source::real_record},
      {"columns_ragged_row", [] { return with_line(kKobeColumns, 500, "-1.05E-01"); }, columns(1),
       "line 500", "this line has 1 value where the first data line (line 4) has 2",
       Source::real_record},
      {"columns_units_disagree", [] { return read_text(kKobeColumns); },
       columns(1, AccelerationUnit::g), "line 3",
       "the header says the values are in cm/s2 ('%component (JMA Station - E-W). Acc. in "
       "cm/sec^2 and dt=0.005 sec.') but they are being read as g",
       Source::real_record},
      {"columns_dt_disagrees", [] { return read_text(kKobeColumns); },
       with_time_step(columns(1), 0.01), "line 3",
       "the file gives dt = 0.005 but the time step given is 0.01", Source::real_record},
      {"columns_no_time_step", [] { return std::string("0.1\n0.2\n0.3\n"); },
       columns(1, AccelerationUnit::g), "", "the file does not give its time step"},
      {"columns_time_step_zero", [] { return std::string("0.1\n0.2\n"); },
       with_time_step(columns(1, AccelerationUnit::g), 0.0), "",
       "the time step must be positive; got 0"},
      {"columns_no_data", [] { return std::string("time acc\n# nothing\n"); }, columns(1), "line 2",
       "no data: expected rows of numbers"},
      {"columns_time_not_uniform",
       [] { return std::string("0.00 0.1\n0.01 0.2\n0.02 0.3\n0.04 0.4\n0.05 0.5\n0.06 0.6\n"); },
       with_time_column(columns(2, AccelerationUnit::g)), "line 4",
       "the time column is not uniform: t = 0.04 after t = 0.02 (line 3)"},
      {"columns_time_column_is_column_one", [] { return std::string("0 0.1\n0.01 0.2\n"); },
       with_time_column(columns(1, AccelerationUnit::g)), "", "column 1 is the time column"},
  };
  return records;
}

class GroundMotionBadRecord : public GroundMotionReaderFiles,
                              public ::testing::WithParamInterface<BadRecord> {};

// Reading `path` fails with an InputError naming the file, `where` and `phrase`.
void expect_input_error(const std::string& path, const RecordFormat& format,
                        const std::string& where, const std::string& phrase) {
  try {
    read_in_g(path, format);
    ADD_FAILURE() << path << " was read without an error";
  } catch (const InputError& error) {
    std::cout << "message: " << error.what() << "\n";
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.where(), where);
    EXPECT_NE(error.reason().find(phrase), std::string::npos)
        << "'" << phrase << "' is not in '" << error.reason() << "'";
  }
}

TEST_P(GroundMotionBadRecord, IsAnInputErrorWithItsLine) {
  const BadRecord& r = GetParam();
  if (r.source == Source::real_record) {
    POUND_SKIP_WITHOUT_SHARED_RECORDS();
  }
  expect_input_error(write(std::string(r.name) + ".dat", r.text()), r.format, r.where, r.phrase);
}

INSTANTIATE_TEST_SUITE_P(GroundMotionReader, GroundMotionBadRecord,
                         ::testing::ValuesIn(bad_records()),
                         [](const ::testing::TestParamInfo<BadRecord>& test) {
                           return test.param.name;
                         });

// "model" units are the model's length over its time squared: a file whose header states another
// unit is refused as read in it, unless that unit is the model's own. An .AT2 file in g read as
// "model" by a model in metres and seconds was accepted and ran 9.81 times too weak (audit 71).
TEST(GroundMotionReader, ModelUnitsAreRefusedWhereTheHeaderStatesAnotherUnit) {
  const std::string at2 =
      "PEER NGA STRONG MOTION DATABASE RECORD\nTEST 1940, EL CENTRO, 180\n"
      "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    4, DT=   .0100 SEC\n"
      "  .1000000E-01  .2000000E-01 -.1000000E-01  .0000000E+00\n";
  RecordFormat model_units;
  model_units.units = AccelerationUnit::model;
  try {
    (void)parse_ground_motion(at2, "in_g.AT2", model_units, 9.80665);
    ADD_FAILURE() << "read without an error";
  } catch (const InputError& error) {
    std::cout << "message: " << error.what() << "\n";
    EXPECT_EQ(error.where(), "line 3");
    EXPECT_NE(error.reason().find("the header says the values are in g ("), std::string::npos);
    EXPECT_NE(error.reason().find("but they are being read as model units, of which 1 g is "
                                  "9.80665; set the units to g"),
              std::string::npos)
        << error.reason();
  }
  // A model whose own unit is the header's: read as it is.
  EXPECT_EQ(parse_ground_motion(at2, "in_g.AT2", model_units, 1.0).acceleration[1], 0.02);
  const std::string columns_in_cm = "# acc in cm/s2, dt=0.01\n1.0\n2.0\n3.0\n";
  RecordFormat columns_as_model = model_units;
  columns_as_model.format = "columns";
  EXPECT_EQ(parse_ground_motion(columns_in_cm, "cm.txt", columns_as_model, 980.665).acceleration[2],
            3.0);
  EXPECT_THROW((void)parse_ground_motion(columns_in_cm, "cm.txt", columns_as_model, 9.80665),
               InputError);
}

// The text entry point (used by the fuzz targets) reads exactly what the file reader reads, and
// takes "auto" from the name it is given.
TEST(GroundMotionReader, ParsesTextAsTheFileReaderReadsTheFile) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const model::GroundMotion from_file = read_in_g(kNgaWest2, RecordFormat{});
  const model::GroundMotion from_text =
      parse_ground_motion(read_text(kNgaWest2), kNgaWest2, RecordFormat{}, 1.0);
  EXPECT_EQ(from_text.name, from_file.name);
  EXPECT_EQ(from_text.time_step, from_file.time_step);
  EXPECT_EQ(from_text.acceleration, from_file.acceleration);
}

// A file's times are seconds (an .AT2's DT, a header's dt, a time column): in a model whose time
// unit is the millisecond they are 1000 times as many units; a time step given beside the file
// is in the model's unit already. (An .AT2's DT was read as 0.01 ms: a 25 s record in 25 ms.)
TEST(GroundMotionReader, AFilesSecondsBecomeTheModelsTimeUnit) {
  RecordFormat in_ms;
  in_ms.second = 1000.0;
  const std::string at2 =
      "PEER\nRECORD\nACCELERATION TIME SERIES IN UNITS OF G\n"
      "NPTS=    4, DT=   .0100 SEC\n  .1 .2 .3 .4\n";
  EXPECT_DOUBLE_EQ(parse_ground_motion(at2, "r.AT2", RecordFormat{}, 1.0).time_step, 0.01);
  EXPECT_DOUBLE_EQ(parse_ground_motion(at2, "r.AT2", in_ms, 1.0).time_step, 10.0);
  RecordFormat times = in_ms;
  times.time_column = true;
  times.column = 2;
  EXPECT_DOUBLE_EQ(
      parse_ground_motion("0 0.1\n0.005 0.2\n0.01 0.3\n", "t.txt", times, 1.0).time_step, 5.0);
  RecordFormat stated = in_ms;
  EXPECT_DOUBLE_EQ(
      parse_ground_motion("# dt = 0.02 sec\n0.1\n0.2\n", "h.txt", stated, 1.0).time_step, 20.0);
  stated.time_step = 20.0;  // given in ms: agrees with the header's 0.02 s
  EXPECT_DOUBLE_EQ(
      parse_ground_motion("# dt = 0.02 sec\n0.1\n0.2\n", "h.txt", stated, 1.0).time_step, 20.0);
  stated.time_step = 0.02;  // the header's number, but in ms: 1000 times too short
  try {
    parse_ground_motion("# dt = 0.02 sec\n0.1\n0.2\n", "h.txt", stated, 1.0);
    ADD_FAILURE() << "0.02 ms accepted against a header's 0.02 s";
  } catch (const InputError& error) {
    EXPECT_NE(error.reason().find("the file gives dt = 0.02 s, 20 in the model's time unit, but "
                                  "the time step given is 0.02"),
              std::string::npos)
        << error.what();
  }
}

TEST(GroundMotionReader, ParsedTextWithoutATimeStepIsAnInputErrorNamingItsSource) {
  try {
    parse_ground_motion("0.1\n0.2\n", "memory.txt", RecordFormat{}, 1.0);
    ADD_FAILURE() << "a columns text without dt was read";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "memory.txt");
    EXPECT_NE(error.reason().find("does not give its time step"), std::string::npos)
        << error.what();
  }
}

TEST_F(GroundMotionReaderFiles, MissingFileAndFolderAreInputErrors) {
  expect_input_error((folder_ / "no_such.AT2").string(), at2(), "", "no such file");
  expect_input_error(folder_.string(), at2(), "", "is a folder");
}

// ---- pound spectrum ----------------------------------------------------------------------------

using pound::testing::Outcome;

class SpectrumCommand : public GroundMotionReaderFiles {
 protected:
  // Runs `pound spectrum <arguments>`.
  Outcome spectrum(std::vector<std::string> arguments) const {
    arguments.insert(arguments.begin(), "spectrum");
    return pound(arguments);
  }
};

TEST_F(SpectrumCommand, JsonReportsTheRecordAndItsSpectrum) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const Outcome outcome = spectrum({kNgaWest2, "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json result = nlohmann::json::parse(outcome.out);
  EXPECT_EQ(result["npts"], 5372);
  EXPECT_DOUBLE_EQ(result["dt"].get<double>(), 0.01);
  expect_three_significant_digits(result["pga_g"].get<double>(), 0.281, "PGA [g]");
  ASSERT_EQ(result["periods"].size(), 40u);
  ASSERT_EQ(result["sa_g"].size(), 40u);
  EXPECT_DOUBLE_EQ(result["periods"][0].get<double>(), 0.02);
  EXPECT_NEAR(result["periods"][39].get<double>(), 10.0, 1e-12);
  // At 0.02 s the oscillator is rigid: Sa is about the PGA.
  EXPECT_NEAR(result["sa_g"][0].get<double>(), result["pga_g"].get<double>(), 0.01);
  std::cout << "PGA " << result["pga_g"] << " g, Sa(" << result["periods"][26] << " s) "
            << result["sa_g"][26] << " g\n";
}

TEST_F(SpectrumCommand, ColumnsFileAndCsv) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const fs::path csv = folder_ / "spectrum.csv";
  const Outcome outcome = spectrum({kKobeColumns, "--column", "2", "--units", "cm/s2", "--periods",
                                    "0,0.5,1", "--csv", csv.string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("PGA        0.631"), std::string::npos) << outcome.out;
  const std::vector<std::string> lines = split_lines(read_text(csv.string()));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "period,sa_g,sv_m_per_s,sd_m");
}

TEST_F(SpectrumCommand, MissingFileIsExitCode2) {
  const std::string missing = (folder_ / "missing.AT2").string();
  const Outcome outcome = spectrum({missing});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find(missing), std::string::npos) << outcome.err;
}

TEST_F(SpectrumCommand, BadRecordIsExitCode2WithItsLine) {
  const std::string path =
      write("bad.AT2", with_line(kShipped + "synthetic_firm_01.AT2", 4, "NPTS= , DT= .01"));
  const Outcome outcome = spectrum({path});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find(path + ": line 4: expected"), std::string::npos) << outcome.err;
}

TEST_F(SpectrumCommand, BadOptionsAreUsageErrors) {
  const std::string record = kShipped + "synthetic_firm_01.AT2";
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{record, "--units", "furlongs"},
        std::vector<std::string>{record, "--periods", "0.1,x"},
        std::vector<std::string>{record, "--damping", "1.5"}, std::vector<std::string>{}}) {
    const Outcome outcome = spectrum(arguments);
    EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
    std::cout << "stderr: " << outcome.err;
  }
}

// Samples given as values (the Python module's records) convert as a file of the same values.
TEST(GroundMotionFromSamples, ConvertsAsAFileOfTheSameValues) {
  const std::vector<double> values{0.0, 0.125, -0.3, 0.2, 0.05};
  for (const char* unit : {"g", "m/s2", "cm/s2"}) {
    RecordFormat format;
    format.format = "columns";
    format.time_step = 0.01;
    format.units = parse_acceleration_unit(unit);
    const model::GroundMotion from_file =
        parse_ground_motion("0.0\n0.125\n-0.3\n0.2\n0.05\n", "given.txt", format, 9.80665);
    const model::GroundMotion given =
        ground_motion_from_samples("given", values, 0.01, {}, format.units, 9.80665);
    EXPECT_EQ(given.acceleration, from_file.acceleration) << unit;
    EXPECT_EQ(given.time_step, 0.01);
  }
  const model::GroundMotion timed = ground_motion_from_samples(
      "timed", values, std::nullopt, {2.0, 2.02, 2.04, 2.06, 2.08}, AccelerationUnit::g, 1.0);
  EXPECT_NEAR(timed.time_step, 0.02, 1e-15);
}

TEST(GroundMotionFromSamples, BadSamplesNameTheirIndex) {
  auto where = [](const std::vector<double>& values, std::optional<double> dt,
                  const std::vector<double>& times) {
    try {
      (void)ground_motion_from_samples("given", values, dt, times, AccelerationUnit::g, 9.8);
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), "given");
      return error.where();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(where({0.0, NAN, 0.1}, 0.01, {}), "accelerations[1]");
  EXPECT_EQ(where({0.0, 1e308, 0.1}, 0.01, {}), "accelerations[1]");  // overflows in m/s2
  EXPECT_EQ(where({0.0}, 0.01, {}), "accelerations");
  EXPECT_EQ(where({0.0, 0.1}, 0.0, {}), "time_step");
  EXPECT_EQ(where({0.0, 0.1}, INFINITY, {}), "time_step");
  EXPECT_EQ(where({0.0, 0.1, 0.2}, std::nullopt, {0.0, 0.1}), "times");
  EXPECT_EQ(where({0.0, 0.1, 0.2, 0.3}, std::nullopt, {0.0, 0.1, 0.2, 0.5}), "times[3]");
  EXPECT_EQ(where({0.0, 0.1, 0.2}, std::nullopt, {0.0, NAN, 0.2}), "times[1]");
  EXPECT_EQ(where({0.0, 0.1, 0.2}, std::nullopt, {0.2, 0.1, 0.0}), "times");
}

}  // namespace
}  // namespace pound::io
