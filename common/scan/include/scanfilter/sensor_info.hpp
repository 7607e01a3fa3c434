#pragma once
#include <string>

namespace scanfilter {

// The sense in which the beam angle grows with the beam index.
enum class BeamDirection { kCcw, kCw };

// The sensor's pose in the robot base frame.
struct SensorMount {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

// Everything the scan log header says about the sensor.
struct SensorInfo {
  SensorMount mount;
  BeamDirection direction = BeamDirection::kCcw;
  double range_min = 0.0;
  double range_max = 0.0;
  double angular_accuracy_deg = 1.0;  // Δθ of the paper's equation (5)
};

// Header of a recorded scan log.
struct ScanLogHeader {
  int version = 1;
  std::string source;
  SensorInfo sensor;
};

}  // namespace scanfilter
