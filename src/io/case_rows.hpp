#pragma once
// A batch case's summary as a CSV row: written into the case's folder (case.csv) and gathered
// into batch_summary.csv. Numbers print in their shortest exact form, so a row read back (for
// --resume, or from another MPI rank) gives the same numbers and the same text, bit for bit.
#include <string>
#include <vector>

#include "results/case_summary.hpp"

namespace pound::io {

// The header of batch_summary.csv and case.csv (without the newline).
std::string case_row_header();

// One row (without the newline); absent quantities are empty cells, text is quoted when needed.
std::string case_row(const results::CaseSummary& summary);

// Reads a row back; throws InputError naming `source` when it is not a row of case_row_header().
results::CaseSummary parse_case_row(const std::string& row, const std::string& source);

// A case.csv file: the header and one row. Throws InputError if it is unreadable or not that.
results::CaseSummary read_case_file(const std::string& path, std::string& row);

}  // namespace pound::io
