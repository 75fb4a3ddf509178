#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "io/generated_docs.hpp"
#include "io/json_reader.hpp"
#include "io/model_schema.hpp"
#include "io/output.hpp"
#include "io/registry_docs.hpp"

namespace pound::app {
namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

constexpr const char* kDocsUsage = R"(usage: pound docs [FOLDER] [--check]

Rewrites the generated sections of the docs in the project FOLDER (default: the current one):
the field tables of docs/model_format.md, from the model schema the reader and writer use, and its
integrator table from the integrator catalog; the law tables of docs/laws.md, from the law
registry; the vocabulary of the model fuzzer's dictionary fuzz/model.dict. Each section stands
between "<!-- pound docs: NAME -->" and "<!-- end pound docs -->" (in the dictionary, as
comments); the text around them is left as it is. With --check nothing is written, and the
command exits with 1 naming every stale file and section.

options)";

// Every docs file with generated sections, and what generates them.
std::vector<io::GeneratedFile> generated_files() {
  std::vector<io::GeneratedSection> model_format = io::model_format_sections();
  model_format.push_back(io::integrator_section());
  return {{"docs/model_format.md", model_format},
          {"docs/laws.md", io::law_sections()},
          {"fuzz/model.dict", {io::vocabulary_section()}}};
}

}  // namespace

int docs_command(const Arguments& arguments) {
  po::options_description options(kDocsUsage);
  std::string folder = ".";
  bool check = false;
  options.add_options()("help,h", "show this help")("check", po::bool_switch(&check),
                                                    "only compare: exit 1 when a section is stale");
  if (!parse_command_line(arguments, options, "folder", folder)) return 0;
  int stale_count = 0;
  for (const io::GeneratedFile& file : generated_files()) {
    const std::string path = (fs::path(folder) / file.path).lexically_normal().string();
    const std::string text = io::read_text_file(path);
    const std::vector<std::string> stale = io::stale_sections(text, file);
    stale_count += static_cast<int>(stale.size());
    if (check) {
      for (const std::string& name : stale)
        std::cerr << fmt::format(
            "{}: section '{}' differs from what pound generates; run `pound "
            "docs` to rewrite it\n",
            path, name);
    } else if (!stale.empty()) {
      io::write_text_atomic(path, io::regenerate(text, file));
      std::cout << fmt::format("{}: rewrote {}\n", path, fmt::join(stale, ", "));
    }
  }
  return check && stale_count > 0 ? 1 : 0;
}

}  // namespace pound::app
