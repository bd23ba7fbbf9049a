#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace bezier::test {

/// The built bezier-service binary, started on a free port (--port 0) for one test
/// fixture. The port is read from the `listening on http://HOST:PORT` line, so no port
/// is ever fixed. The destructor kills the process if the test did not stop it.
class ServiceProcess {
 public:
  /// `extra_args` follow --host/--port; `extra_env` entries ("NAME=value") are added to
  /// this process's environment for the child only.
  explicit ServiceProcess(std::vector<std::string> extra_args = {},
                          std::vector<std::string> extra_env = {}) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    std::vector<std::string> args = {BEZIER_SERVICE_BINARY, "--host", "127.0.0.1", "--port", "0"};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    std::vector<char*> envp;
    for (char** e = environ; *e != nullptr; ++e) envp.push_back(*e);
    for (auto& e : extra_env) envp.push_back(e.data());
    envp.push_back(nullptr);
    const int rc = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    if (rc != 0) throw std::runtime_error("cannot start " + args[0]);
    stdout_fd_ = out[0];
    port_ = read_port();
    // Keep reading so the service never blocks on a full pipe while logging.
    reader_ = std::thread([this] {
      char buf[4096];
      for (;;) {
        const ssize_t n = read(stdout_fd_, buf, sizeof buf);
        if (n <= 0) return;
        const std::lock_guard lock(output_mutex_);
        output_.append(buf, static_cast<std::size_t>(n));
      }
    });
  }

  ServiceProcess(const ServiceProcess&) = delete;
  ServiceProcess& operator=(const ServiceProcess&) = delete;

  ~ServiceProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (reader_.joinable()) reader_.join();
    if (stdout_fd_ >= 0) close(stdout_fd_);
  }

  [[nodiscard]] int port() const noexcept { return port_; }
  [[nodiscard]] pid_t pid() const noexcept { return pid_; }

  void signal(int sig) const { kill(pid_, sig); }

  /// Waits for the process to exit (up to `limit`) and returns its exit status, or
  /// nullopt if it did not exit normally in time (then it is killed).
  std::optional<int> wait_exit(std::chrono::seconds limit = std::chrono::seconds(20)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        pid_ = -1;
        if (reader_.joinable()) reader_.join();  // all output is in output_ now
        if (WIFEXITED(status)) return WEXITSTATUS(status);
        return std::nullopt;
      }
      usleep(10000);
    }
    return std::nullopt;
  }

  /// Everything the service wrote to stdout after its listening line, so far.
  std::string output() {
    const std::lock_guard lock(output_mutex_);
    return output_;
  }

 private:
  int read_port() {
    std::string line;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    char c;
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd p{stdout_fd_, POLLIN, 100};
      if (poll(&p, 1, 100) <= 0) continue;
      if (read(stdout_fd_, &c, 1) != 1) break;
      if (c != '\n') {
        line += c;
        continue;
      }
      if (const auto port = port_in_listening_line(line)) return *port;
      line.clear();
    }
    throw std::runtime_error("service did not print its listening line");
  }

  // The port of "listening on http://HOST:PORT" anywhere in `line` (a text log line, or
  // a JSON one whose message holds it), or nullopt.
  static std::optional<int> port_in_listening_line(const std::string& line) {
    const std::string prefix = "listening on http://";
    const auto start = line.find(prefix);
    if (start == std::string::npos) return std::nullopt;
    const std::string url = line.substr(start, line.find_first_of(" \"", start + prefix.size()) - start);
    return std::stoi(url.substr(url.rfind(':') + 1));
  }

  pid_t pid_ = -1;
  int stdout_fd_ = -1;
  int port_ = 0;
  std::thread reader_;
  std::mutex output_mutex_;
  std::string output_;
};

}  // namespace bezier::test
