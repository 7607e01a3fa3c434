// On each built-in scene, the map from filtered scans matches the floor plan
// better than the map from unfiltered scans: more of its occupied cells lie
// on a true surface (precision), and it covers as much of the surfaces
// (recall). Measured (docs/accuracy.md, "Maps"): recall better on every
// scene; the tolerance below is for a scene where the filter's few false
// deletions (mostly legs at their first sightings) cost what the removed
// ghosts gain, as the home's once did (0.8711 against 0.8708).
#include <gtest/gtest.h>

#include "scanfilter/sim/map_score.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter {
namespace {

TEST(MapAccuracy, FilteredMapBeatsUnfilteredOnEveryScene) {
  for (const auto& name : sim::builtinSceneNames()) {
    // True poses: the map is scored against the floor plan, and odometry
    // drift (on by default in the simulated logs) would bend the map however
    // well the filter does.
    sim::Scene scene = sim::findScene(name);
    scene.odometry = {};
    sim::ScanSimulator simulator(std::move(scene), 2);
    const SensorInfo& sensor = simulator.header().sensor;
    FilterConfig config;
    TwoStepFilter filter(config.resolve(sensor), Implementation::kFast);
    OccupancyGrid filtered{OccupancyGridParams{}}, unfiltered{OccupancyGridParams{}};
    ScanRecord record;
    std::vector<std::uint8_t> labels;
    while (simulator.next(record)) {
      labels.resize(record.scan.size());
      filter.apply(record.scan, sensor, labels);
      filtered.integrate(record.scan, sensor, labels);
      unfiltered.integrate(record.scan, sensor, {});
    }
    const sim::MapScore f = sim::scoreMap(filtered, simulator.scene());
    const sim::MapScore u = sim::scoreMap(unfiltered, simulator.scene());
    RecordProperty(name + "_precision", std::to_string(f.precision()) + " vs " + std::to_string(u.precision()));
    EXPECT_GT(f.precision(), u.precision()) << name;
    constexpr double kRecallTolerance = 0.001;
    EXPECT_GT(f.recall(), u.recall() - kRecallTolerance) << name;
    std::printf("%s: filtered precision %.4f recall %.4f (%zu occupied) | unfiltered precision %.4f recall %.4f (%zu occupied)\n",
                name.c_str(), f.precision(), f.recall(), f.occupied, u.precision(), u.recall(), u.occupied);
  }
}

}  // namespace
}  // namespace scanfilter
