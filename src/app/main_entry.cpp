#include <fmt/format.h>

#include <boost/program_options/errors.hpp>
#include <iostream>
#include <map>

#include "app/commands.hpp"
#include "core/errors.hpp"
#include "core/interrupt.hpp"
#include "io/output.hpp"

namespace pound::app {
namespace {

constexpr const char* kUsage =
    R"(pound: seismic pounding analysis (girders, abutments, adjacent buildings)

usage: pound <command> [options]

commands:
  run MODEL.json [--out DIR]   run a model file; writes summary.json and CSV time histories
  batch SET.json --out DIR     every model x record x scale of a set, on threads or MPI ranks,
                               resumable; summary rows, statistics, fragility fits
  study rod-impact [options]   error against run time over integrators, laws, meshes, steps
  verify rod-impact [options]  the rod-impact benchmark against the exact wave solution
  check MODEL.json             before a run: periods, stable steps, link stiffness and contact
                               resolution, and a warning for every meaningless setting
  modes MODEL.json [--count N]  natural periods and modal masses of a model
  pushover MODEL.json --node ID --to D  static pushover: capacity curve under constant gravity
  expand MODEL.json [--out FILE]  the model with its generators replaced by what they generate
  spectrum RECORD [options]    a ground motion's PGA and response spectrum (.AT2 or columns)
  docs [FOLDER] [--check]      rewrite the field tables of docs/model_format.md from the schema
  help [command]               this text, or a command's options

Run `pound <command> --help` for a command's options. Model format: docs/model_format.md.
Exit codes: 0 ok, 1 usage error or failed verification, 2 bad input, 3 analysis failed,
4 output could not be written, 130/143 interrupted by SIGINT/SIGTERM.
)";

}  // namespace

int report_failure(const std::string& command, const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const Interrupted& error) {
    // A batch keeps its complete cases, each put in place as it ended.
    std::cerr << fmt::format("pound {}: {}: {}\n", command, error.what(),
                             command == "batch"
                                 ? "the cases that ended are kept; add --resume to run the rest"
                                 : "no result of this run was put in place");
    return error.exit_code();
  } catch (const InputError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 2;
  } catch (const SolveError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 3;
  } catch (const io::OutputError& error) {
    // Under MPI, the ranks a signal did not stop first report the one it did as an output error.
    if (const int signal = interrupt_signal()) {
      std::cerr << fmt::format("pound {}: {}\n", command, Interrupted(signal).what());
      return Interrupted(signal).exit_code();
    }
    std::cerr << "error: " << error.what() << "\n";
    return 4;
  } catch (const boost::program_options::error& error) {
    std::cerr << fmt::format("pound {}: {}\n(see `pound {} --help`)\n", command, error.what(),
                             command);
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (the model, a record or an option asks for more than this "
                 "machine has)\n";
    return 3;
  } catch (const std::exception& error) {
    // Anything else escaped a check that should have caught it: still a clear answer, never an
    // abort.
    std::cerr << fmt::format(
        "error: pound {} stopped: {} (an unexpected failure: please report it with the input)\n",
        command, error.what());
    return 3;
  }
}

int main_entry(int argc, char** argv) {
  const Arguments all(argv + 1, argv + argc);
  if (all.empty()) {
    std::cerr << kUsage;
    return 1;
  }
  const std::string command = all.front();
  Arguments rest(all.begin() + 1, all.end());
  try {
    using Command = int (*)(const Arguments&);
    const std::map<std::string, Command> commands = {
        {"run", run_command},          {"batch", batch_command},       {"verify", verify_command},
        {"modes", modes_command},      {"check", check_command},       {"study", study_command},
        {"expand", expand_command},    {"spectrum", spectrum_command}, {"docs", docs_command},
        {"pushover", pushover_command}};
    if (auto found = commands.find(command); found != commands.end()) return found->second(rest);
    if (command == "help" || command == "--help" || command == "-h") {
      if (!rest.empty())
        if (auto found = commands.find(rest.front()); found != commands.end())
          return found->second({"--help"});
      std::cout << kUsage;
      return 0;
    }
    std::cerr << fmt::format("pound: unknown command '{}'\n\n{}", command, kUsage);
    return 1;
  } catch (...) {
    return report_failure(command, std::current_exception());
  }
}

}  // namespace pound::app
