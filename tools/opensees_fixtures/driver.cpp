// Writes the OpenSees fixtures of tests/links/opensees_fixtures_test.cpp: each material of OpenSees
// (Steel01, BoucWen, Hysteretic, compiled from source by generate.sh) stepped through one
// displacement history, its stress and tangent after each row committed, as CSV.
//
//   opensees_fixtures <output directory> <OpenSees commit>
//
// The history is piecewise linear between turning points (multiples of the yield displacement
// d_y = 5 mm, units kN and mm throughout), with rows every 0.1 d_y. OpenSees is stepped with
// `substeps` equal sub-steps per row, committing each: BoucWen integrates z by backward Euler
// (one Newton solve per step), first order in the step, so fine sub-steps make its step error
// small; pound's bouc_wen integrates exactly in delta and is driven through the rows only (the
// turning points are rows, so both follow the same straight segments). The same history run with
// twice the sub-steps measures that error (the "step study" line of each file's header).
// Hysteretic is piecewise linear but takes a step that crosses zero force whole at the unloading
// stiffness of the side it reloads toward (HystereticMaterial::positiveIncrement: Cstress + Eup kp
// dStrain), which differs from the other side's when beta > 0: a one-step error of up to
// (k_u' - k_u) |dStrain|, made small by the same sub-steps. Steel01 is exact for any step.
#include <BoucWenMaterial.h>
#include <HystereticMaterial.h>
#include <Steel01.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr double kYieldDisplacement = 5.0;  // mm
constexpr double kRowStep = 0.1;            // rows every 0.1 d_y

// Turning points in units of d_y. Elastic cycles, a first yield to one side only (the other
// side's reloading then aims at its yield point), reversals on reloading lines before their
// target and after crossing zero force, partial unloadings reloaded inside a large cycle (inner
// loops, with and without a zero-force crossing), growing amplitudes 0.5, 1, 2, 4, 5, 6 d_y and
// a last excursion past every previous peak. The reversal after 2 d_y is at -0.5 d_y, past zero
// force on the line toward the unyielded side's yield point, where pound's clough once unloaded
// along a secant to the origin (tests/links/opensees_fixtures_test.cpp).
const std::vector<double> kTurningPoints = {
    0.0,  0.5,  -0.5, 0.9,  -0.9, 2.0, -0.5, 1.0, -2.0, 4.0, 2.5,  3.5, 1.0,  3.0, 5.0,
    -4.0, -2.0, -3.0, -1.0, -5.0, 6.0, -6.0, 3.0, 0.5,  2.0, -1.0, 0.5, -6.5, 0.0};

std::vector<double> history() {
  std::vector<double> rows;
  for (std::size_t i = 1; i < kTurningPoints.size(); ++i) {
    const double from = kTurningPoints[i - 1] * kYieldDisplacement;
    const double to = kTurningPoints[i] * kYieldDisplacement;
    const int count = static_cast<int>(
        std::ceil(std::abs(kTurningPoints[i] - kTurningPoints[i - 1]) / kRowStep - 1e-9));
    for (int k = 1; k < count; ++k) rows.push_back(from + (to - from) * k / count);
    rows.push_back(to);  // the turning point itself, exactly
  }
  return rows;
}

struct Row {
  double strain, stress, tangent;
};

std::vector<Row> run(UniaxialMaterial& material, const std::vector<double>& rows, int substeps) {
  std::vector<Row> out;
  double previous = 0.0;
  for (const double strain : rows) {
    for (int j = 1; j <= substeps; ++j) {
      material.setTrialStrain(j == substeps ? strain
                                            : previous + (strain - previous) * j / substeps);
      material.commitState();
    }
    out.push_back({strain, material.getStress(), material.getTangent()});
    previous = strain;
  }
  return out;
}

// Hysteretic's tangent at zero force: E 1e-9 in place of the slope of either branch there.
bool placeholder(const Row& row, double stiffness) {
  return std::abs(row.tangent) < 1e-6 * stiffness;
}

struct Case {
  std::string file;
  std::string command;  // the OpenSees command, for the header
  std::string pound;    // the pound law it is compared with
  double force_scale;   // the yield force (or k z_max) the step study is relative to
  double stiffness;     // the initial stiffness the tangent's step study is relative to
  int substeps;
  std::function<std::unique_ptr<UniaxialMaterial>()> make;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  all.push_back({"steel01.csv",
                 "uniaxialMaterial Steel01 1 100 20 0.05 (a1..a4 default: 0 55 0 55)",
                 "bilinear_spring {stiffness: 20, yield_force: 100, hardening_ratio: 0.05}", 100.0,
                 20.0, 1, [] { return std::make_unique<Steel01>(1, 100.0, 20.0, 0.05); }});
  // BoucWen: k = 20 kN/mm, alpha = 0.05, z_max = (Ao / (beta + gamma))^(1/n) = 5 mm;
  // deltaA = deltaNu = deltaEta = 0 (no degradation), tolerance 1e-8, 20 Newton iterations (the
  // command's defaults).
  struct Shape {
    const char* file;
    double n, gamma, beta, ao;
  };
  for (const Shape& s : {Shape{"bouc_wen_n1_gamma_beta.csv", 1.0, 0.1, 0.1, 1.0},
                         Shape{"bouc_wen_n1_gamma0.csv", 1.0, 0.0, 0.2, 1.0},
                         Shape{"bouc_wen_n2_gamma_beta.csv", 2.0, 0.02, 0.02, 1.0},
                         Shape{"bouc_wen_n2_gamma0_a1.5.csv", 2.0, 0.0, 0.06, 1.5}}) {
    char command[200], pound[200];
    std::snprintf(command, sizeof command,
                  "uniaxialMaterial BoucWen 1 0.05 20 %g %g %g %g 0 0 0 (tolerance 1e-8, 20 "
                  "iterations)",
                  s.n, s.gamma, s.beta, s.ao);
    std::snprintf(pound, sizeof pound,
                  "bouc_wen {stiffness: 20, hardening_ratio: 0.05, sharpness: %g, beta: %g, "
                  "gamma: %g, amplitude: %g}",
                  s.n, s.beta, s.gamma, s.ao);
    all.push_back({s.file, command, pound, 20.0 * 5.0, 20.0, 1000, [s] {
                     return std::make_unique<BoucWenMaterial>(1, 0.05, 20.0, s.n, s.gamma, s.beta,
                                                              s.ao, 0.0, 0.0, 0.0, 1e-8, 20);
                   }});
  }
  // Hysteretic, bilinear envelope (the two-point form: k = 100 / 5 = 20 kN/mm, post-yield 0.05 k
  // up to 50 mm and extrapolated beyond), no pinching (pinchX = pinchY = 1), no damage.
  for (const double beta : {0.0, 0.4}) {
    char file[64], command[200], pound[200];
    std::snprintf(file, sizeof file, "hysteretic_beta%g.csv", beta);
    std::snprintf(command, sizeof command,
                  "uniaxialMaterial Hysteretic 1 100 5 145 50 -100 -5 -145 -50 1 1 0 0 %g", beta);
    std::snprintf(pound, sizeof pound,
                  "clough {stiffness: 20, yield_force: 100, hardening_ratio: 0.05, "
                  "unloading_exponent: %g}",
                  beta);
    all.push_back({file, command, pound, 100.0, 20.0, 1000, [beta] {
                     return std::make_unique<HystereticMaterial>(1, 100.0, 5.0, 145.0, 50.0, -100.0,
                                                                 -5.0, -145.0, -50.0, 1.0, 1.0, 0.0,
                                                                 0.0, beta);
                   }});
  }
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <output directory> <OpenSees commit>\n", argv[0]);
    return 2;
  }
  const std::string directory = argv[1], commit = argv[2];
  const std::vector<double> rows = history();
  for (const Case& c : cases()) {
    const std::vector<Row> table = run(*c.make(), rows, c.substeps);
    const std::vector<Row> finer = run(*c.make(), rows, 2 * c.substeps);
    double force_change = 0.0, tangent_change = 0.0;
    for (std::size_t i = 0; i < table.size(); ++i) {
      force_change = std::max(force_change, std::abs(table[i].stress - finer[i].stress));
      // Hysteretic answers a step that ends at zero force (to rounding) with a placeholder
      // tangent E 1e-9 or the branch's, depending on the rounding: not a step error.
      if (placeholder(table[i], c.stiffness) || placeholder(finer[i], c.stiffness)) continue;
      tangent_change = std::max(tangent_change, std::abs(table[i].tangent - finer[i].tangent));
    }
    const std::string path = directory + "/" + c.file;
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (out == nullptr) {
      std::perror(path.c_str());
      return 1;
    }
    std::fprintf(out, "# OpenSees %s (github.com/OpenSees/OpenSees), %s\n", commit.c_str(),
                 c.command.c_str());
    std::fprintf(out, "# compared with pound %s\n", c.pound.c_str());
    std::fprintf(out, "# units kN, mm; turning points (x 5 mm):");
    for (const double point : kTurningPoints) std::fprintf(out, " %g", point);
    std::fprintf(out, "; rows every 0.5 mm\n");
    std::fprintf(
        out,
        "# OpenSees stepped with %d equal sub-steps per row; step study (%d sub-steps): "
        "max |force change| / %g = %.3g, max |tangent change| / %g = %.3g (where not at zero "
        "force)\n",
        c.substeps, 2 * c.substeps, c.force_scale, force_change / c.force_scale, c.stiffness,
        tangent_change / c.stiffness);
    std::fprintf(out, "# written by tools/opensees_fixtures/generate.sh\n");
    std::fprintf(out, "deformation,force,tangent\n");
    for (const Row& row : table)
      std::fprintf(out, "%.17g,%.17g,%.17g\n", row.strain, row.stress, row.tangent);
    std::fclose(out);
    std::printf("%s: %zu rows, step study force %.3g, tangent %.3g\n", path.c_str(), table.size(),
                force_change / c.force_scale, tangent_change / c.stiffness);
  }
  return 0;
}
