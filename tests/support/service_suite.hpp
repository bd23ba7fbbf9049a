#pragma once

// A GoogleTest fixture whose tests share one bezier-service process.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/support/service_process.hpp"

namespace bezier::test {

/// The fixture of a suite whose tests talk to one service, started before the suite's
/// first test with the flags `Suite::service_args()` (after --host/--port) and killed after
/// its last. `Suite` is the fixture class itself (class T : public ServiceSuite<T>), so
/// that every suite has a process of its own.
template <class Suite>
class ServiceSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { service_ = std::make_unique<ServiceProcess>(Suite::service_args()); }
  static void TearDownTestSuite() { service_.reset(); }
  static ServiceProcess& service() { return *service_; }
  static int port() { return service_->port(); }

 private:
  static inline std::unique_ptr<ServiceProcess> service_;
};

}  // namespace bezier::test
