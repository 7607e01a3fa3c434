// The metrics' end of a service's life (common/dds ServiceMetrics): SIGTERM
// must end a service within a second, so destroying the metrics must not wait
// for civetweb to stop (its poll quantum is 2 s); its exposer is kept until
// the process exits instead, reachable, so LeakSanitizer (scripts/sanitize.sh
// asan) does not see a leak when this binary exits - it did when the exposer
// was released into nothing. And its start: an address the HTTP server
// cannot bind is refused before, or named when it fails (a port in use).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "scanfilter/dds/metrics_address.hpp"
#include "scanfilter/dds/service_metrics.hpp"

using scanfilter::dds_io::metricsAddressProblem;
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

TEST(MetricsAddress, TakesAnIpv4AddressOrAHostNameAndAPort) {
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:9471"), std::nullopt);
  EXPECT_EQ(metricsAddressProblem("localhost:9471"), std::nullopt);
  EXPECT_EQ(metricsAddressProblem("10.8.0.5:65535"), std::nullopt);
  EXPECT_EQ(metricsAddressProblem("robot-7.local:1"), std::nullopt);
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:0"), std::nullopt) << "any free port: the recorder's, scraped by nobody";
}

TEST(MetricsAddress, RefusesWhatTheServerCannotBindOrReadsAsEveryInterface) {
  const std::string expected =
      "expected host:port (an IPv4 address or host name, a port 0-65535, 0: any free one; e.g. 127.0.0.1:9471)";
  EXPECT_EQ(metricsAddressProblem("9471"), expected + ", got \"9471\"") << "civetweb: every interface";
  EXPECT_EQ(metricsAddressProblem("nonsense"), expected + ", got \"nonsense\"");
  EXPECT_EQ(metricsAddressProblem(":9471"), expected + ", got \":9471\"");
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:"), expected + ", got \"127.0.0.1:\"");
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:65536"), expected + ", got \"127.0.0.1:65536\"");
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:9471x"), expected + ", got \"127.0.0.1:9471x\"");
  EXPECT_EQ(metricsAddressProblem("127.0.0.1:1234567"), expected + ", got \"127.0.0.1:1234567\"");
  EXPECT_EQ(metricsAddressProblem("[::1]:9471"), expected + ", got \"[::1]:9471\"") << "this civetweb binds no IPv6";
  EXPECT_EQ(metricsAddressProblem("foo bar:9471"), expected + ", got \"foo bar:9471\"");
}

TEST(ServiceMetrics, APortInUseIsAnErrorNamingTheAddress) {
  // Hold a loopback port, as another service would.
  const int holder = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(holder, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(holder, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(listen(holder, 1), 0);
  socklen_t length = sizeof address;
  ASSERT_EQ(getsockname(holder, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const std::string taken = "127.0.0.1:" + std::to_string(ntohs(address.sin_port));
  try {
    ServiceMetrics metrics("test_service", taken, "0.0.0");
    ADD_FAILURE() << "served metrics on a port in use";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cannot serve metrics on " + taken + " (service.metrics_address, --metrics-address)"),
              std::string::npos)
        << message;
  }
  close(holder);
}
