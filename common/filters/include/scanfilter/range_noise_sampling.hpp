#pragma once

namespace scanfilter {

// How the range-noise estimate (range_noise_estimate.hpp) samples the scans.
// Step 1's: jump_filter.noise_estimate_window_scans and
// noise_estimate_min_samples in config/filter.yaml. Step 2's
// (evidence_radius.hpp): its own window, penetration_filter.
// evidence_noise_window_scans, and step 1's minimum of samples.
struct RangeNoiseSampling {
  // 1 (step 1's default): each scan alone, no state: a restarted service labels as before.
  double window_scans = 1.0;  // scans: an older scan's weight decays by 1 - 1/this a scan
  double min_samples = 20.0;  // residuals (decayed) a 1 m range band needs to count
};

}  // namespace scanfilter
