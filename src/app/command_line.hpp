#pragma once
// Parsing a subcommand's command line: its named options plus one positional argument (a model,
// a record, a benchmark name). Every command shares this, with --help printing its options.
#include <boost/program_options.hpp>
#include <optional>
#include <string>

#include "app/commands.hpp"

namespace pound::app {

// The parsed options, or nothing when --help was asked for and printed (exit 0 then).
std::optional<boost::program_options::variables_map> parse_command_line(
    const Arguments& arguments, const boost::program_options::options_description& options,
    const char* positional_name, std::string& positional_value);

}  // namespace pound::app
