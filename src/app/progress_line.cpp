#include "app/progress_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pound::app {

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{:02}:{:02}", s / 60, s % 60);
}

bool progress_settings(bool enabled, double interval, bool terminal, ProgressSettings& settings) {
  if (!enabled || (interval <= 0.0 && !terminal)) return false;
  settings.in_place = terminal;
  if (interval > 0.0) {
    settings.first_after = interval;
    settings.interval = interval;
  }
  return true;
}

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ProgressLine::ProgressLine(std::ostream& out, ProgressSettings settings, Clock clock)
    : out_(out), settings_(settings), clock_(clock ? std::move(clock) : Clock(steady_seconds)) {
  origin_ = clock_();
}

double ProgressLine::elapsed() const { return clock_() - origin_; }

void ProgressLine::restart() {
  origin_ = clock_();
  last_shown_ = -1.0;
}

void ProgressLine::update(const std::function<std::string(double elapsed)>& text) {
  const double now = elapsed();
  if (now < settings_.first_after) return;
  if (last_shown_ >= 0.0 && now - last_shown_ < settings_.interval) return;
  last_shown_ = now;
  const std::string text_line = text(now);
  if (!settings_.in_place) {
    out_ << text_line << "\n" << std::flush;
    return;
  }
  // Short of an 80-column terminal's width: a line that wrapped could not be redrawn. Spaces
  // over what is left of a longer line before.
  const std::string line = text_line.substr(0, kInPlaceWidth);
  const std::size_t pad = shown_width_ > line.size() ? shown_width_ - line.size() : 0;
  out_ << "\r" << line << std::string(pad, ' ') << std::flush;
  shown_width_ = line.size() + pad;
}

void ProgressLine::finish() {
  if (shown_width_ == 0) return;
  out_ << "\r" << std::string(shown_width_, ' ') << "\r" << std::flush;
  shown_width_ = 0;
}

std::string solve_progress_text(double time, double start, double end, double elapsed) {
  const double span = end - start, done = time - start;
  const double fraction = span > 0.0 ? std::clamp(done / span, 0.0, 1.0) : 1.0;
  // Whole percents, rounded down: 100 % only at the end.
  std::string text = fmt::format("t = {:.4g} of {:.4g} s ({:.0f} %), {} elapsed", time, end,
                                 std::floor(100.0 * fraction), clock_text(elapsed));
  if (fraction > 0.0 && fraction < 1.0)
    text += fmt::format(", about {} left", clock_text(elapsed / fraction * (1.0 - fraction)));
  return text;
}

std::string copies_progress_text(std::size_t done, std::size_t total, double elapsed) {
  std::string text =
      fmt::format("{} of {} copies done, {} elapsed", done, total, clock_text(elapsed));
  if (done > 0 && done < total)
    text += fmt::format(", about {} left", clock_text(elapsed / static_cast<double>(done) *
                                                      static_cast<double>(total - done)));
  return text;
}

std::string batch_progress_text(const BatchCounts& counts, double elapsed) {
  constexpr double kBarWidth = 12.0;
  const double total = static_cast<double>(counts.total);
  const double fraction =
      total > 0.0
          ? std::clamp((static_cast<double>(counts.done) + counts.running_done) / total, 0.0, 1.0)
          : 1.0;
  const auto filled = static_cast<std::size_t>(std::floor(kBarWidth * fraction));
  std::string text = fmt::format("[{}{}] {}/{} cases", std::string(filled, '#'),
                                 std::string(static_cast<std::size_t>(kBarWidth) - filled, ' '),
                                 counts.done, counts.total);
  if (counts.failed > 0) text += fmt::format(", {} failed", counts.failed);
  if (counts.running > 0) text += fmt::format(", {} running", counts.running);
  text += fmt::format(", {} elapsed", clock_text(elapsed));
  if (fraction > 0.0 && fraction < 1.0)
    text += fmt::format(", ETA {}", clock_text(elapsed / fraction * (1.0 - fraction)));
  return text;
}

}  // namespace pound::app
