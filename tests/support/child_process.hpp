#pragma once

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace bezier::test {

/// A program started with its stdout and stderr merged into one pipe that this object
/// reads, so a test sees every byte the program writes, in order. The destructor kills
/// the program if it is still running.
class ChildProcess {
 public:
  /// `args[0]` is the program's path; `extra_env` entries ("NAME=value") are added to
  /// this process's environment for the child only.
  explicit ChildProcess(std::vector<std::string> args, std::vector<std::string> extra_env = {}) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<char*> envp;
    for (char** e = environ; *e != nullptr; ++e) envp.push_back(*e);
    for (auto& e : extra_env) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    const int rc = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    if (rc != 0) {
      close(out[0]);
      throw std::runtime_error("cannot start " + args[0]);
    }
    output_fd_ = out[0];
  }

  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  ~ChildProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (output_fd_ >= 0) close(output_fd_);
  }

  void signal(int sig) const { kill(pid_, sig); }

  /// Reads output until `text` appears in it, the output ends or `limit` passes;
  /// whether it appeared.
  bool wait_for_output(const std::string& text, std::chrono::milliseconds limit = std::chrono::seconds(20)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (output_.find(text) == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      if (read_some(100) == Read::end) break;
    }
    return output_.find(text) != std::string::npos;
  }

  /// Reads the output to its end and waits for the program to exit (up to `limit`): its
  /// exit status, or nullopt if it did not exit normally in time (then it is killed).
  std::optional<int> wait_exit(std::chrono::seconds limit = std::chrono::seconds(20)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      read_some(10);
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        while (read_some(0) == Read::data) {
        }
        if (WIFEXITED(status)) return WEXITSTATUS(status);
        return std::nullopt;
      }
    }
    return std::nullopt;
  }

  /// Everything read from the program so far.
  [[nodiscard]] const std::string& output() const noexcept { return output_; }

 private:
  enum class Read { data, nothing, end };

  // Reads what is available within `timeout_ms`.
  Read read_some(int timeout_ms) {
    pollfd p{output_fd_, POLLIN, 0};
    if (poll(&p, 1, timeout_ms) <= 0) return Read::nothing;
    char buffer[4096];
    const ssize_t n = read(output_fd_, buffer, sizeof buffer);
    if (n <= 0) return Read::end;
    output_.append(buffer, static_cast<std::size_t>(n));
    return Read::data;
  }

  pid_t pid_ = -1;
  int output_fd_ = -1;
  std::string output_;
};

/// A program run to its end.
struct ProgramRun {
  std::optional<int> exit_code;  ///< nullopt: it did not exit normally within the limit
  std::string output;            ///< stdout and stderr, merged
};

/// Runs `args` (args[0] the program) until it exits, up to `limit` (then it is killed).
inline ProgramRun run_program(std::vector<std::string> args, std::vector<std::string> extra_env = {},
                              std::chrono::seconds limit = std::chrono::seconds(20)) {
  ChildProcess child(std::move(args), std::move(extra_env));
  const std::optional<int> code = child.wait_exit(limit);
  return {code, child.output()};
}

}  // namespace bezier::test
