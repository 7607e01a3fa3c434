// The metrics' end of a service's life (common/dds ServiceMetrics): SIGTERM
// must end a service within a second, so destroying the metrics must not wait
// for civetweb to stop (its poll quantum is 2 s); its exposer is kept until
// the process exits instead, reachable, so LeakSanitizer (scripts/sanitize.sh
// asan) does not see a leak when this binary exits - it did when the exposer
// was released into nothing.
#include <chrono>
#include <memory>

#include <gtest/gtest.h>

#include "scanfilter/dds/service_metrics.hpp"

using scanfilter::dds_io::ServiceMetrics;

namespace {
// Port 0: the system picks a free one, so parallel tests never collide.
constexpr const char* kAnyLoopbackPort = "127.0.0.1:0";
// The services' promise on SIGTERM (tests/dds/pipeline_test.sh, metrics).
constexpr auto kStopWithin = std::chrono::seconds(1);
}  // namespace

TEST(ServiceMetrics, DestroyedWithinTheStopPromiseAndItsExposerKeptUntilExit) {
  for (int service = 0; service < 2; ++service) {  // a second one: the list of kept exposers grows
    auto metrics = std::make_unique<ServiceMetrics>("test_service", kAnyLoopbackPort, "0.0.0");
    metrics->updateProcessStats();
    const auto start = std::chrono::steady_clock::now();
    metrics.reset();
    EXPECT_LT(std::chrono::steady_clock::now() - start, kStopWithin);
  }
}
