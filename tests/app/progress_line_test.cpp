// The progress line of long runs: when it shows, how it redraws and erases itself, and its text.
#include "app/progress_line.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace pound::app {
namespace {

// A clock the test sets.
struct FakeClock {
  double now = 100.0;
  ProgressLine::Clock function() {
    return [this] { return now; };
  }
};

TEST(ProgressLine, ShowsNothingBeforeItsDelayThenAtMostOncePerInterval) {
  std::ostringstream out;
  FakeClock clock;
  ProgressLine line(out, {false, 2.0, 0.5}, clock.function());
  int formed = 0;
  const auto text = [&](double elapsed) {
    ++formed;
    return "at " + std::to_string(static_cast<int>(10 * elapsed));
  };
  clock.now = 101.9;
  line.update(text);
  EXPECT_EQ(out.str(), "");
  EXPECT_EQ(formed, 0) << "the text is formed only when shown";
  clock.now = 102.0;
  line.update(text);
  clock.now = 102.4;  // within the interval: skipped
  line.update(text);
  clock.now = 102.5;
  line.update(text);
  EXPECT_EQ(out.str(), "at 20\nat 25\n");
  EXPECT_EQ(formed, 2);
  line.finish();  // lines for a log are not erased
  EXPECT_EQ(out.str(), "at 20\nat 25\n");
}

TEST(ProgressLine, InPlaceRedrawsOverALongerLineAndErasesItself) {
  std::ostringstream out;
  FakeClock clock;
  ProgressLine line(out, {true, 0.0, 0.0}, clock.function());
  line.update([](double) { return std::string("longer text"); });
  line.update([](double) { return std::string("short"); });
  EXPECT_EQ(out.str(), "\rlonger text\rshort      ");
  line.finish();
  EXPECT_EQ(out.str(), "\rlonger text\rshort      \r           \r");
  line.finish();  // nothing left to erase
  EXPECT_EQ(out.str(), "\rlonger text\rshort      \r           \r");
}

TEST(ProgressLine, InPlaceKeepsShortOfAnEightyColumnTerminal) {
  std::ostringstream out;
  FakeClock clock;
  {
    ProgressLine line(out, {true, 0.0, 0.0}, clock.function());
    line.update([](double) { return std::string(200, 'x'); });
  }  // erased when it goes (a run interrupted by Ctrl-C unwinds through it)
  EXPECT_EQ(out.str(), "\r" + std::string(79, 'x') + "\r" + std::string(79, ' ') + "\r");
}

TEST(ProgressLine, RestartCountsTheDelayFromThen) {
  std::ostringstream out;
  FakeClock clock;
  ProgressLine line(out, {false, 2.0, 0.5}, clock.function());
  clock.now = 150.0;
  line.restart();  // the solve starts after a long set-up
  EXPECT_DOUBLE_EQ(line.elapsed(), 0.0);
  clock.now = 151.0;
  line.update([](double) { return std::string("early"); });
  EXPECT_EQ(out.str(), "");
  clock.now = 152.0;
  line.update([](double elapsed) { return std::to_string(elapsed); });
  EXPECT_EQ(out.str(), std::to_string(2.0) + "\n");
}

TEST(ProgressLine, SettingsFollowTheTerminalTheOptionAndQuiet) {
  ProgressSettings settings;
  EXPECT_FALSE(progress_settings(false, 0.0, true, settings)) << "--quiet shows nothing";
  EXPECT_FALSE(progress_settings(false, 5.0, false, settings));
  EXPECT_FALSE(progress_settings(true, 0.0, false, settings)) << "a log without --progress";
  ASSERT_TRUE(progress_settings(true, 0.0, true, settings));
  EXPECT_TRUE(settings.in_place);
  EXPECT_EQ(settings.first_after, 2.0);
  EXPECT_EQ(settings.interval, 0.5);
  settings = {};
  ASSERT_TRUE(progress_settings(true, 60.0, false, settings));  // --progress 60 into a log
  EXPECT_FALSE(settings.in_place);
  EXPECT_EQ(settings.first_after, 60.0);
  EXPECT_EQ(settings.interval, 60.0);
}

TEST(ProgressText, SaysWhereTheAnalysisIsAndHowLongItTakesStill) {
  EXPECT_EQ(solve_progress_text(10.0, 0.0, 40.0, 3.0),
            "t = 10 of 40 s (25 %), 00:03 elapsed, about 00:09 left");
  // Whole percents rounded down: 100 % only at the end, which has nothing left.
  EXPECT_EQ(solve_progress_text(39.99, 0.0, 40.0, 100.0),
            "t = 39.99 of 40 s (99 %), 01:40 elapsed, about 00:00 left");
  EXPECT_EQ(solve_progress_text(40.0, 0.0, 40.0, 100.0), "t = 40 of 40 s (100 %), 01:40 elapsed");
  EXPECT_EQ(solve_progress_text(0.0, 0.0, 40.0, 0.0), "t = 0 of 40 s (0 %), 00:00 elapsed");
  // A run resumed from t = 5 s: its share is of the span it runs.
  EXPECT_EQ(solve_progress_text(7.5, 5.0, 10.0, 7200.0),
            "t = 7.5 of 10 s (50 %), 2:00:00 elapsed, about 2:00:00 left");
  EXPECT_EQ(copies_progress_text(0, 20, 1.0), "0 of 20 copies done, 00:01 elapsed");
  EXPECT_EQ(copies_progress_text(5, 20, 30.0),
            "5 of 20 copies done, 00:30 elapsed, about 01:30 left");
  EXPECT_EQ(copies_progress_text(20, 20, 120.0), "20 of 20 copies done, 02:00 elapsed");
}

// `pound batch`'s bar: the cases in flight count by their fractions done, in the bar and the
// ETA; no ETA before anything is done; within the 79 columns of a line redrawn in place.
TEST(ProgressText, ABatchsBarCountsTheCasesInFlight) {
  EXPECT_EQ(batch_progress_text({.done = 0, .total = 8, .running = 2}, 0.3),
            "[            ] 0/8 cases, 2 running, 00:00 elapsed");
  EXPECT_EQ(batch_progress_text(
                {.done = 3, .total = 8, .failed = 1, .running = 2, .running_done = 1.0}, 20.0),
            "[######      ] 3/8 cases, 1 failed, 2 running, 00:20 elapsed, ETA 00:20");
  EXPECT_EQ(batch_progress_text({.done = 8, .total = 8}, 40.0),
            "[############] 8/8 cases, 00:40 elapsed");
  // An IDA of hours on a workstation; longer lines are cut at 79 columns in place.
  const std::string wide = batch_progress_text(
      {.done = 99, .total = 200, .failed = 10, .running = 16, .running_done = 3.5}, 3600.0);
  std::cout << wide << "\n";
  EXPECT_LE(wide.size(), ProgressLine::kInPlaceWidth);
}

TEST(ProgressText, ClockTextRoundsToSecondsAndShowsHoursPastOne) {
  EXPECT_EQ(clock_text(0.4), "00:00");
  EXPECT_EQ(clock_text(59.6), "01:00");
  EXPECT_EQ(clock_text(3599.4), "59:59");
  EXPECT_EQ(clock_text(3725.0), "1:02:05");
  EXPECT_EQ(clock_text(-1.0), "00:00");
}

}  // namespace
}  // namespace pound::app
