// ros_scan_publisher: plays a scan log as a robot driver would publish it:
// sensor_msgs/LaserScan on rt/<ns>/scan and nav_msgs/Odometry on rt/<ns>/odom
// (best effort, ROS 2 sensor-data QoS). For trying the live ingest, and for
// feeding rviz2 or slam_toolbox from a recording.
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "namespace_check.hpp"
#include "scanfilter/cli/option_checks.hpp"
#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/default_paths.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;

namespace {

constexpr int kSensorQueueDepth = 10;

// One more odometry sample this long after the last scan, so it too can be posed.
constexpr std::int64_t kLastOdometryDelayNs = 1'000'000;

// The scan as a ROS LaserScan in the sensor's own frame: counter-clockwise
// about the sensor's z axis, which points down when it is mounted upside
// down; the ranges as recorded (REP 117: +inf no return, NaN an error).
void toLaserScan(const Scan& scan, const SensorInfo& sensor, bool upside_down, const std::string& frame,
                 LaserScanMsg& out) {
  const bool log_clockwise = sensor.direction == BeamDirection::kCw;
  const double sign = log_clockwise == upside_down ? 1.0 : -1.0;
  out.header().stamp(toTimeMsg(scan.stamp));
  out.header().frame_id(frame);
  setLaserScanGeometry(scan.angle_min, scan.angle_increment, scan.size(), sign, sensor.range_min, sensor.range_max,
                       out);
  const auto recorded = scan.rangesAsRecorded();
  out.ranges().resize(recorded.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) out.ranges()[i] = static_cast<float>(recorded[i]);
  out.intensities().assign(scan.intensities.begin(), scan.intensities.end());
}

// A number as the shortest text that reads back as the same double (the
// mount said for the live ingest's config: a yaw of π as π, exactly).
std::string shortest(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::to_string(value);
}

// A launcher waiting for more readers than this has a typo, not a fleet.
constexpr int kMaxWaitReaders = 1000;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ros_scan_publisher: publish a scan log as LaserScan (rt/<ns>/scan) and Odometry (rt/<ns>/odom)"};
  // Bad arguments: one line (what and which), no usage dump.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + " (see --help)\n"; });
  ParticipantSettings settings;
  settings.profiles_file = defaultProfilesFile();
  settings.name = "scanfilter_ros_scan_publisher";
  std::string input, ns, frame = "laser";
  double rate_hz = 0.0;
  int wait_readers = 1;
  bool reliable = false;
  bool upside_down = false;
  app.add_option("input", input, "scan log, CARMEN log or Mines URG-04LX log")->required()->check(CLI::ExistingFile);
  app.add_option("--domain", settings.domain_id, "DDS domain id")->check(CLI::Range(0, kMaxDomainId))->capture_default_str();
  app.add_option("--namespace", ns, "topic namespace (rt/<ns>/scan)")->check(kNamespaceCheck);
  app.add_option("--profiles-file", settings.profiles_file, "Fast DDS XML profiles")->capture_default_str();
  app.add_option("--enclave", settings.security.enclave,
                 "DDS Security enclave directory (scanfilter-make-keystore; default: security off)");
  app.add_option("--frame-id", frame, "LaserScan frame_id")->capture_default_str();
  app.add_option("--rate", rate_hz, "scans per second (0: the recorded pace)")
      ->check(scanfilter::cli::numberAtLeast(0.0, "scans per second"));
  app.add_option("--wait-readers", wait_readers, "wait for this many scan readers before publishing")
      ->check(CLI::Range(0, kMaxWaitReaders))
      ->capture_default_str();
  app.add_flag("--upside-down", upside_down,
               "publish as a sensor mounted upside down (roll pi) would: a clockwise log's angles as recorded");
  app.add_flag("--reliable", reliable, "reliable writers (default: best effort, as sensor drivers publish)");
  app.set_version_flag("--version", "ros_scan_publisher (scanfilter " SCANFILTER_VERSION ")");
  CLI11_PARSE(app, argc, argv);
  try {
    ShutdownSignal::install();
    checkLogToEnd(input);  // a log cut short fails before any of it is published
    auto source = openScanSource(input);
    const SensorInfo& sensor = source->header().sensor;
    DdsParticipant participant(settings);
    auto qos = sensorDataWriterQos(kSensorQueueDepth);
    if (reliable) qos.reliability().kind = eprosima::fastdds::dds::RELIABLE_RELIABILITY_QOS;
    TypedWriter<sensor_msgs::msg::dds_::LaserScan_PubSubType> scans(participant, rosTopic(ns, "scan"), qos);
    TypedWriter<nav_msgs::msg::dds_::Odometry_PubSubType> odometry(participant, rosTopic(ns, "odom"), qos);
    // A driver publishes no mount: the transform base -> laser is the live
    // ingest's to know (its `live` section), and a wrong one maps nonsense
    // without an error, so say what this log's is.
    const std::string mount =
        "[" + shortest(sensor.mount.x) + ", " + shortest(sensor.mount.y) + ", " + shortest(sensor.mount.yaw) + "]";
    std::cout << "the log's sensor is mounted at " << mount << " on the base: give the live ingest `live: {mount: "
              << mount << (upside_down ? ", upside_down: true" : "") << "}`" << std::endl;
    if (scans.matchedReaders() < wait_readers || odometry.matchedReaders() < wait_readers)
      std::cout << "waiting for " << wait_readers << " reader(s) of " << rosTopic(ns, "scan") << " and "
                << rosTopic(ns, "odom") << " (--wait-readers)" << std::endl;
    while (scans.matchedReaders() < wait_readers || odometry.matchedReaders() < wait_readers)
      if (ShutdownSignal::waitFor(std::chrono::milliseconds(50))) return 0;
    if (ShutdownSignal::waitFor(kDiscoverySettle)) return 0;
    // The sensor's mount becomes the odometry's base pose offset: publish the
    // base pose; the live ingest is told the mount in its config.
    ScanRecord record;
    LaserScanMsg scan_msg;
    OdometryMsg odom_msg;
    odom_msg.header().frame_id("odom");
    odom_msg.child_frame_id("base_link");
    std::size_t published = 0;
    Stamp first_stamp;
    const auto start = std::chrono::steady_clock::now();
    while (!ShutdownSignal::requested() && source->next(record)) {
      const Scan& s = record.scan;
      if (published == 0) first_stamp = s.stamp;
      const double due_s = rate_hz > 0 ? static_cast<double>(published) / rate_hz : s.stamp.secondsSince(first_stamp);
      if (ShutdownSignal::waitUntil(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                std::chrono::duration<double>(due_s))))
        break;  // stopped while waiting for the scan's time
      odom_msg.header().stamp(toTimeMsg(s.stamp));
      odom_msg.pose().pose().position().x(s.pose.x);
      odom_msg.pose().pose().position().y(s.pose.y);
      odom_msg.pose().pose().orientation(quaternionOfYaw(s.pose.theta));
      odometry.write(odom_msg);
      toLaserScan(s, sensor, upside_down, frame, scan_msg);
      scans.write(scan_msg);
      ++published;
    }
    // One more odometry sample after the last scan, so it too can be posed.
    odom_msg.header().stamp(toTimeMsg(Stamp::fromNanoseconds(record.scan.stamp.nanoseconds() + kLastOdometryDelayNs)));
    odometry.write(odom_msg);
    // Reliable streams: exiting deletes the writers, and with them whatever
    // the readers have not acknowledged yet.
    constexpr double kDrainSeconds = 5.0;
    scans.waitForAcknowledgments(kDrainSeconds);
    odometry.waitForAcknowledgments(kDrainSeconds);
    std::cout << "published " << published << " scans\n";
  } catch (const std::exception& e) {
    std::cerr << "ros_scan_publisher: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
