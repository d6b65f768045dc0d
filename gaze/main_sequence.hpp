// SPDX-License-Identifier: Apache-2.0
// Main-sequence facts about saccades used to set and test the filters.
//  - Duration grows about linearly with amplitude: D ~= 2.2 ms/deg * A + 21 ms for A in
//    about 1..50 deg (Carpenter 1988, "Movements of the Eyes", 2nd ed.; Bahill, Clark & Stark
//    1975, "The main sequence, a tool for studying human eye movements", Math. Biosci. 24).
//  - Peak velocity grows with amplitude and saturates around 400-700 deg/s for large
//    saccades (Bahill et al. 1975; Baloh et al. 1975, Neurology 25, an exponential fit
//    Vp = Vmax (1 - exp(-A / C))). Even a 3 deg saccade peaks well above 100 deg/s.
//  - Fixational drift and tracker noise stay far below that, which is why a velocity
//    threshold of about 30 deg/s separates them (I-VT: Salvucci & Goldberg 2000, ETRA;
//    Olsen 2012, "The Tobii I-VT fixation filter", default 30 deg/s).
#pragma once

namespace gazelod::gaze::main_sequence {

// Typical saccade duration for an amplitude (Carpenter 1988), seconds.
constexpr double duration_s(double amplitude_deg) {
  return 0.021 + 0.0022 * amplitude_deg;
}

// I-VT threshold commonly used for 250 Hz-class trackers (Olsen 2012).
inline constexpr double kIvtThreshold_deg_s = 30.0;

}  // namespace gazelod::gaze::main_sequence
