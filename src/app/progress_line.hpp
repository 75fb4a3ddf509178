#pragma once
// A long command's progress on the console (stderr): on a terminal one line redrawn in place,
// shown only once the work has taken a while, so short runs print nothing new; for logs (a
// pipe, a cluster job's output) a line every so many seconds when asked for (--progress).
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace pound::app {

// "mm:ss", or "h:mm:ss" from an hour.
std::string clock_text(double seconds);

struct ProgressSettings {
  bool in_place = false;     // redraw one line (a terminal), else one line each time
  double first_after = 2.0;  // [s] of work before anything is shown
  double interval = 0.5;     // [s] between updates
};

// The settings of `pound run`: `interval` > 0 (--progress S)
// prints a line every S seconds, in place on a terminal; 0 keeps a line up to date on a
// terminal after 2 s and prints nothing elsewhere; `enabled` false (--quiet) nothing at all.
// Returns false when nothing is to be shown.
bool progress_settings(bool enabled, double interval, bool terminal, ProgressSettings& settings);

class ProgressLine {
 public:
  static constexpr std::size_t kInPlaceWidth = 79;  // characters of a line redrawn in place
  using Clock = std::function<double()>;            // seconds, from any origin
  ProgressLine(std::ostream& out, ProgressSettings settings, Clock clock = {});
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Seconds since construction (or the last restart()).
  double elapsed() const;
  // Counts the elapsed time from now again (a new phase: the ensemble's copies after its run).
  void restart();
  // Shows `text()` if an update is due: reads the clock once, forms the text only then.
  void update(const std::function<std::string(double elapsed)>& text);
  // In place: erases the line, so the next output starts at its beginning. Again: nothing.
  void finish();

 private:
  std::ostream& out_;
  ProgressSettings settings_;
  Clock clock_;
  double origin_ = 0.0;
  double last_shown_ = -1.0;     // elapsed() when last shown, < 0: not yet
  std::size_t shown_width_ = 0;  // characters on the line in place, 0: none
};

// "t = 12.4 of 40 s (31 %), 00:03 elapsed, about 00:07 left": the analysis' time `time` between
// `start` and `end` [s of the record], after `elapsed` seconds of solving.
std::string solve_progress_text(double time, double start, double end, double elapsed);
// "3 of 20 copies done, 00:12 elapsed, about 01:08 left".
std::string copies_progress_text(std::size_t done, std::size_t total, double elapsed);

// A batch's cases: finished (of them failed) and in flight, with the fractions of those done.
struct BatchCounts {
  std::size_t done = 0, total = 0, failed = 0, running = 0;
  double running_done = 0.0;
};
// "[####        ] 7/20 cases, 1 failed, 2 running, 00:40 elapsed, ETA 01:10": the bar and the
// ETA count the cases in flight by their fractions done; no failures, no "failed".
std::string batch_progress_text(const BatchCounts& counts, double elapsed);

}  // namespace pound::app
