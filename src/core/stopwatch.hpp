#pragma once
// Wall-clock time of a piece of work, for the run times the reports show (the one output that
// varies from run to run).
#include <chrono>

namespace pound {

class Stopwatch {
 public:
  // Seconds since the stopwatch was made.
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  }

 private:
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace pound
