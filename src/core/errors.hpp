#pragma once
// Errors the program reports to a user. Input errors name where the bad value is (file and
// JSON path, or file and line) and what was expected; solve errors name the time and reason.
#include <stdexcept>
#include <string>

namespace pound {

// Bad input: malformed or inconsistent model, record or option. Exit code 2.
class InputError : public std::runtime_error {
 public:
  // `where` is a JSON pointer ("/links/0/gap") or "line 12" or empty; `file` may be empty.
  InputError(std::string file, std::string where, std::string what);

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& reason() const { return reason_; }

  // The same error located in `file` (used when a reader learns the file name late).
  InputError in_file(const std::string& file) const;

 private:
  std::string file_;
  std::string where_;
  std::string reason_;
};

// The analysis could not go on: Newton did not converge after cutting the step to its floor,
// or the state became NaN/Inf. Exit code 3.
class SolveError : public std::runtime_error {
 public:
  SolveError(double time, std::string reason);
  double time() const { return time_; }
  const std::string& reason() const { return reason_; }

 private:
  double time_;
  std::string reason_;
};

}  // namespace pound
