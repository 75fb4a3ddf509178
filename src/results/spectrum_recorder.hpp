#pragma once
// Floor response spectra: the pseudo-spectral acceleration of linear oscillators standing on
// recorded nodes, driven by each node's absolute acceleration (what equipment and contents on a
// floor or deck feel), advanced with every step of the run.
#include <string>
#include <vector>

#include "model/ground_motion.hpp"
#include "results/ground_acceleration.hpp"
#include "results/recorders.hpp"

namespace pound::results {

// One node direction a spectrum is taken of: how it is read (no terms where fixed), its node and
// direction.
struct SpectrumPlace {
  std::string id;  // the node's
  DofReading reading;
  Index node = 0;
  int direction = 0;         // a translation (model::direction)
  std::string symbol = "x";  // its name in the columns
};

// Columns period and <id>.sa_<x|y|z>_<100 zeta>% per place and damping ratio, a row per period;
// Sa in the model's acceleration units. Exact for the acceleration linear between the steps
// (model::ResponseOscillator), so it equals the spectrum of the recorded a_abs history.
class SpectrumRecorder final : public Recorder {
 public:
  SpectrumRecorder(std::string file, std::vector<SpectrumPlace> places, std::vector<double> periods,
                   std::vector<double> damping_ratios, GroundAcceleration& ground,
                   const UnitNames& units = {});
  void record(const integrators::State& state) override;
  Table table() const override;
  const std::string& file() const override { return file_; }
  double held_values(double, double) const override { return 0.0; }

 private:
  std::string file_;
  std::vector<SpectrumPlace> places_;
  std::vector<double> periods_, damping_ratios_;
  GroundAcceleration& ground_;
  UnitNames units_;
  // oscillators_[(place * damping_ratios + damping) * periods + period]
  std::vector<model::ResponseOscillator> oscillators_;
  std::vector<double> previous_;  // each place's acceleration at the previous step
  double previous_time_ = 0.0;
  bool started_ = false;
};

}  // namespace pound::results
