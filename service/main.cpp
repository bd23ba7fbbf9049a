// bezier-service: wires configuration, logging, the HTTP server and signals.
#include <csignal>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <cstdlib>

#include <spdlog/spdlog.h>

#include "service/config.hpp"
#include "service/log.hpp"
#include "service/memory_release.hpp"
#include "service/server.hpp"
#include "service/version.hpp"

int main(int argc, char** argv) {
  using namespace bezier::service;
  const ParsedConfig parsed = parse_config(argc, argv);
  if (!parsed.config) {
    std::fputs(parsed.message.c_str(), parsed.exit_code == 0 ? stdout : stderr);
    return parsed.exit_code;
  }
  const Config& config = *parsed.config;
  configure_allocator();  // before any thread: see service/memory_release.hpp

  // SIGTERM and SIGINT are blocked in every thread and taken by sigwait in one, so
  // shutdown runs as ordinary code rather than inside a signal handler. The mask is
  // set before any thread starts, so they all inherit it. SIGPIPE is ignored: a
  // client that hangs up must not kill the process.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  Log log(make_logger(config), config.log_format);
  Server server(config, log);
  const BindResult bound = server.bind();
  if (bound.fd < 0) {
    log.always(spdlog::level::critical, bound.error, {});
    spdlog::shutdown();  // drains the asynchronous log queue
    return 1;
  }

  std::mutex exit_mutex;
  std::condition_variable exit_ready;
  bool served_returned = false;
  std::thread signal_waiter([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    log.info("received {}, draining for {} s, then stopping", signal == SIGTERM ? "SIGTERM" : "SIGINT",
                 config.drain_seconds);
    server.begin_draining();
    std::this_thread::sleep_for(std::chrono::duration<double>(config.drain_seconds));
    server.stop();
    std::unique_lock lock(exit_mutex);
    if (!exit_ready.wait_for(lock, std::chrono::duration<double>(config.shutdown_timeout_seconds),
                             [&] { return served_returned; })) {
      log.warn("in-flight requests did not finish within {} s; exiting anyway",
                   config.shutdown_timeout_seconds);
      spdlog::shutdown();
      std::_Exit(1);
    }
  });

  // Written once the socket accepts connections (it is bound and listening already:
  // connections made now wait in the backlog until serve() takes them).
  log.always(spdlog::level::info, fmt::format("listening on http://{}:{}", config.host, bound.port),
             {LogField::text("version", kServiceVersion), LogField::flag("auth_token_required", !config.auth_token.empty())});
  log.info("threads={} max_connections={} max_degree={} max_body_bytes={}", config.threads,
           config.max_connections, config.limits.max_degree, config.limits.max_body_bytes);
  const bool served = server.serve();
  {
    const std::lock_guard lock(exit_mutex);
    served_returned = true;
  }
  exit_ready.notify_all();
  if (!served) {
    // The listener failed on its own: wake the signal thread so it can be joined.
    pthread_kill(signal_waiter.native_handle(), SIGTERM);
  }
  signal_waiter.join();
  log.info("stopped");
  spdlog::shutdown();  // drains the asynchronous log queue
  return served ? 0 : 1;
}
