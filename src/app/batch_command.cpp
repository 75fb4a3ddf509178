#include <fmt/format.h>
#include <unistd.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <exception>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/batch.hpp"
#include "app/cluster.hpp"
#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/progress_line.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kBatchUsage = R"(usage: pound batch SET.json --out DIR [--jobs N] [--resume]
       mpirun -np K pound batch SET.json --out DIR [--jobs N] [--resume]

Runs every (model, record, scale) case of a set file (docs/batch_format.md) on N worker threads
(default: every core; under mpirun, the cases are shared over the K ranks, one thread each unless
--jobs says otherwise). Writes into DIR:
  <model>/<record>/x<scale>/  per case, what `pound run` writes, and case.csv (its summary row);
                     moved into place only when complete, so a killed batch leaves whole cases
  batch_summary.csv  one row per case: status, reason, PGA and intensity measure, impacts, peak
                     pounding and restrainer forces, joint opening and seat movement, unseating,
                     drift ratio and ductility, energy balance error, run time
  batch_stats.json   per model and scale: median, 84th percentile and maximum of each response,
                     the fraction of records exceeding each limit, and lognormal fragility fits
  batch_plan.json    the cases and a content hash of every input, so --resume can check it
                     continues the same batch of the same files
A case is done once its case_complete.json (written last) and every file it lists are there;
--resume runs every other case. While it runs, a batch locks DIR (DIR/.lock): a second batch
there is refused. A case that fails (a broken record, an analysis that cannot go on) is reported
in its row and does not stop the others. Exit code 0 when every case completed, 3 when some
failed, 2 for a bad set or model (nothing written) or an input edited since the batch in DIR
began, 4 when results cannot be written or another batch is working in DIR.

options)";

// On a terminal a bar redrawn in place, also while cases run, left on screen at the end; one
// line per finished case otherwise (logs, CI).
class BatchDisplay {
 public:
  BatchDisplay(bool terminal, int rank, int ranks)
      : terminal_(terminal),
        who_(ranks > 1 ? fmt::format("rank {}/{}: ", rank, ranks) : std::string()),
        line_(std::cerr, {.in_place = true, .first_after = 0.0, .interval = 0.25}) {}

  void show(const BatchProgress& p) {
    const BatchCounts counts{p.done, p.total, p.failed, p.running, p.running_done};
    if (terminal_) {
      if (p.done == p.total) {  // the last case: the final bar stays
        line_.finish();
        std::cerr << batch_progress_text(counts, p.elapsed_s) << "\n";
        return;
      }
      line_.update([&](double) { return batch_progress_text(counts, p.elapsed_s); });
      return;
    }
    if (!p.last) return;
    const double eta =
        p.done ? p.elapsed_s / static_cast<double>(p.done) * static_cast<double>(p.total - p.done)
               : 0.0;
    std::cerr << fmt::format("{}[{}/{}] {} {}{} ({} elapsed, ETA {})\n", who_, p.done, p.total,
                             p.last->name, results::status_name(p.last->status),
                             p.last->reason.empty() ? "" : ": " + p.last->reason,
                             clock_text(p.elapsed_s), clock_text(eta));
  }

 private:
  bool terminal_;
  std::string who_;
  ProgressLine line_;
};

std::string fragility_line(const results::FragilityFit& f) {
  // Cases that gave no observation change what the rest say: the reader is told how many.
  const std::string left_out =
      f.left_out > 0
          ? fmt::format(
                " ({} of the model's {} cases left out: failed below the limit, refused, "
                "without a positive intensity, or reporting no value of the quantity)",
                f.left_out, f.left_out + f.observations)
          : std::string();
  if (!f.fitted)
    return fmt::format("  fragility {} {} > {:.4g}: not fitted: {}{}\n", f.model, f.quantity,
                       f.limit, f.reason, left_out);
  return fmt::format(
      "  fragility {} {} > {:.4g}: median {:.4g} g, dispersion {:.3f} ({} of {} cases exceed){}\n",
      f.model, f.quantity, f.limit, f.median, f.dispersion, f.exceeded, f.observations, left_out);
}

// The cases, where the workers' time went and the fragility fits.
void print_report(const BatchOptions& batch, const BatchReport& report) {
  const double rate = report.wall_s > 0.0 ? static_cast<double>(report.ran) / report.wall_s : 0.0;
  std::cout << fmt::format(
      "pound batch {}: {} cases ({} resumed, {} run on {} rank(s) x {} worker(s)), {} completed, "
      "{} failed -> {}/\n",
      batch.set_path, report.cases, report.resumed, report.ran, report.ranks, report.jobs,
      report.completed, report.failed, batch.out);
  if (report.ran > 0)
    std::cout << fmt::format(
        "  {:.2f} s, {:.3g} cases/s; of the workers' time: solving {:.1f} %, reading and "
        "building {:.1f} %, writing {:.1f} %, the rest {:.1f} %\n",
        report.wall_s, rate, 100.0 * report.solve_s / report.worker_s,
        100.0 * report.setup_s / report.worker_s, 100.0 * report.write_s / report.worker_s,
        100.0 * (report.worker_s - report.solve_s - report.setup_s - report.write_s) /
            report.worker_s);
  if (!report.warned.empty()) {
    // A completed case whose drifts went past 10 % (a collapse) is in the statistics as any
    // other: say which, so that they are read before the medians.
    constexpr std::size_t kNamed = 5;
    std::string names;
    for (std::size_t k = 0; k < std::min(kNamed, report.warned.size()); ++k)
      names += (k == 0 ? "" : ", ") + report.warned[k];
    if (report.warned.size() > kNamed)
      names += fmt::format(" and {} more", report.warned.size() - kNamed);
    std::cout << fmt::format(
        "  {} completed case(s) with warnings on their results (a drift past 10 % or a "
        "collapse, a girder off its seat, energy created by contacts, ensemble copies that "
        "failed...; column 'warnings', each case's summary.json and ensemble.json say which), in "
        "the statistics as the others: {}\n",
        report.warned.size(), names);
  }
  for (const results::FragilityFit& f : report.statistics.fragilities)
    std::cout << fragility_line(f);
}

// The ranks this process runs with, or nothing when MPI cannot start (said on stderr).
std::unique_ptr<Cluster> start_cluster() {
  try {
    return std::make_unique<Cluster>();
  } catch (const std::runtime_error& error) {
    std::cerr << "pound batch: " << error.what() << "\n";
    return nullptr;
  }
}

}  // namespace

int batch_command(const Arguments& arguments) {
  po::options_description options(kBatchUsage);
  BatchOptions batch;
  options.add_options()("help,h", "show this help")("out,o", po::value(&batch.out),
                                                    "output folder (required)")(
      "jobs,j", po::value(&batch.jobs), "worker threads per process (default, or 0: every core)")(
      "resume", "keep the complete cases of an earlier run into --out and run the rest")(
      "quiet,q", "print nothing but errors");
  const auto parsed = parse_command_line(arguments, options, "set", batch.set_path);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  if (batch.set_path.empty() || batch.out.empty()) {
    std::cerr << "pound batch: name a set file and --out DIR (see `pound batch --help`)\n";
    return 1;
  }
  if (vm.count("jobs") && batch.jobs < 0) {
    std::cerr << "pound batch: --jobs must be >= 0 (0: every core)\n";
    return 1;
  }
  batch.resume = vm.count("resume") > 0;
  const bool quiet = vm.count("quiet") > 0;
  std::unique_ptr<Cluster> started = start_cluster();
  if (!started) return 1;
  const Cluster& cluster = *started;
  const bool terminal = ::isatty(STDERR_FILENO) && cluster.size() == 1;
  // Under MPI only rank 0 reports, for its own share of the cases.
  BatchDisplay display(terminal, cluster.rank(), cluster.size());
  if (!quiet && cluster.is_root())
    batch.progress = [&](const BatchProgress& p) { display.show(p); };
  BatchReport report;
  try {
    report = run_batch(batch, cluster);
  } catch (...) {
    // Boost.MPI aborts every rank if an exception unwinds its environment, so MPI ends here. The
    // message comes first: MPI_Finalize waits for every rank, and mpirun kills the ranks still
    // running once one exits with an error, so rank 0 says why before any rank can exit.
    const int exit_code = report_failure("batch", std::current_exception());
    started.reset();
    return exit_code;
  }
  if (!cluster.is_root()) return 0;
  if (!quiet) print_report(batch, report);
  if (report.failed > 0) {
    std::cerr << fmt::format(
        "error: {} of {} cases failed (see the status and reason columns of "
        "{}/batch_summary.csv)\n",
        report.failed, report.cases, batch.out);
    return 3;
  }
  return 0;
}

}  // namespace pound::app
