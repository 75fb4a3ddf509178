#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "builder/generators.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "io/model_writer.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"

namespace pound::app {
namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

constexpr const char* kExpandUsage = R"(usage: pound expand MODEL.json [--out FILE]

Writes a model file with every generator (rod_pair, adjacent_buildings, girder_bridge) replaced
by the nodes, materials, elements, masses, supports, initial velocities, links and monitors it
generates, so that they can be seen and edited. The result is itself a model file
(docs/model_format.md): `pound run` on it gives the same results (only a rod_pair's comparison
with the exact solution, which needs the generator, is no longer made). Defaults are written
out where they matter to a reader (integrator, convergence).
Records of excitations are named relative to the model file; with --out they are renamed
relative to FILE's folder, on standard output they are left as they are.

options)";

// Keeps the records found when the expanded model is written to another folder.
void rebase_records(builder::ModelSpec& spec, const fs::path& model_path,
                    const fs::path& out_path) {
  const fs::path model_folder = fs::absolute(model_path).parent_path();
  const fs::path out_folder = fs::absolute(out_path).parent_path();
  const auto rebase = [&](std::string& file) {
    if (!fs::path(file).is_absolute())
      file = fs::proximate(model_folder / file, out_folder).generic_string();
  };
  for (builder::ExcitationSpec& excitation : spec.excitations) {
    rebase(excitation.record);
    if (excitation.pair && excitation.pair->record) rebase(*excitation.pair->record);
  }
}

}  // namespace

int expand_command(const Arguments& arguments) {
  po::options_description options(kExpandUsage);
  std::string model_path, out;
  options.add_options()("help,h", "show this help")(
      "out,o", po::value(&out), "write the expanded model to FILE (default: standard output)");
  if (!parse_command_line(arguments, options, "model", model_path)) return 0;
  if (model_path.empty()) {
    std::cerr << "pound expand: name a model file (see `pound expand --help`)\n";
    return 1;
  }
  builder::ModelSpec expanded;
  try {
    expanded = builder::expand(io::read_model_file(model_path));
  } catch (const InputError& error) {  // a generator's error names its path; the file is ours
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
  if (out.empty()) {
    std::cout << io::model_to_json(expanded);
    return 0;
  }
  // The expanded model may not replace the model or one of its records.
  std::vector<io::NamedPath> inputs{{model_path, "the model"}};
  for (std::size_t k = 0; k < expanded.excitations.size(); ++k) {
    const builder::ExcitationSpec& excitation = expanded.excitations[k];
    inputs.push_back({(fs::path(model_path).parent_path() / excitation.record).string(),
                      fmt::format("{}: /excitations/{}/record", model_path, k)});
    if (excitation.pair && excitation.pair->record)
      inputs.push_back({(fs::path(model_path).parent_path() / *excitation.pair->record).string(),
                        fmt::format("{}: /excitations/{}/pair/record", model_path, k)});
  }
  io::check_outputs_apart(inputs, {{out, "--out"}});
  rebase_records(expanded, model_path, out);
  io::write_text_atomic(out, io::model_to_json(expanded));
  return 0;
}

}  // namespace pound::app
