#pragma once
#include <prometheus/counter.h>
#include <prometheus/family.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>

#include "scanfilter/dds/service_metrics.hpp"
#include "scanfilter/occupancy_grid.hpp"

namespace scanfilter::map_service {

// The map publisher's own metrics, on the service's endpoint: the map's
// size and memory, scans integrated, occupied cells, and how long a publish
// takes and how long ago the last one was, and (when saving is configured)
// when the saved files last held everything the map in memory holds.
class MapMetrics {
 public:
  explicit MapMetrics(dds_io::ServiceMetrics& metrics);

  void scanIntegrated() { integrated_.Increment(); }
  // After a publish that took `seconds`: the map's figures now.
  void published(const OccupancyGrid& grid, double seconds);
  void lastPublishAge(double seconds) { publish_age_.Set(seconds); }
  // The map files were just written (the last rename succeeded).
  void mapSaved();
  // The files hold everything in memory as of now (just saved, or nothing to
  // save): the alert "map not saved for 10 min" watches this time.
  void savedMapCurrent();

 private:
  prometheus::Gauge& cells_;
  prometheus::Gauge& bytes_;
  prometheus::Counter& integrated_;
  prometheus::Gauge& occupied_;
  prometheus::Histogram& publish_time_;
  prometheus::Gauge& publish_age_;
  prometheus::Counter& saves_;
  // Created at the first savedMapCurrent(): absent when nothing is saved.
  prometheus::Family<prometheus::Gauge>& saved_time_family_;
};

}  // namespace scanfilter::map_service
