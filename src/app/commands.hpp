#pragma once
// Subcommands of the `pound` program. Each takes the arguments after its name and returns the
// process exit code: 0 success, 1 verification failed / usage error, 2 input error, 3 the
// analysis failed, 4 output could not be written.
#include <exception>
#include <string>
#include <vector>

namespace pound::app {

using Arguments = std::vector<std::string>;

int run_command(const Arguments& arguments);
int batch_command(const Arguments& arguments);
int verify_command(const Arguments& arguments);
int spectrum_command(const Arguments& arguments);
int modes_command(const Arguments& arguments);
int pushover_command(const Arguments& arguments);
int check_command(const Arguments& arguments);
int study_command(const Arguments& arguments);
int expand_command(const Arguments& arguments);
int docs_command(const Arguments& arguments);

// Prints the message for a command's failure and returns its exit code.
int report_failure(const std::string& command, const std::exception_ptr& failure);

// Dispatches argv to a subcommand, turning errors into messages and exit codes.
int main_entry(int argc, char** argv);

}  // namespace pound::app
