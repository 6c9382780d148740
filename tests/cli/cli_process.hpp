#pragma once
// Runs the `antumbra` program from GoogleTest (tests/cli): in a working directory of the
// test's choosing, with extra environment variables, its stdout and stderr in files; or
// started in the background, to be killed midway (an interrupted run's files).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace antumbra::test {

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A fresh folder per test (ctest runs tests side by side), removed first if left over.
inline std::filesystem::path test_folder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::temp_directory_path() / "antumbra_cli_tests" /
             (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct ProgramRun {
  int exit_code = -1;  // -1 when killed by a signal
  std::string out;
  std::string err;
};

// `antumbra ARGS...` started in `cwd` with `env` ("NAME=value") added to this process's
// environment; stdout and stderr go to `logs`/stdout and `logs`/stderr.
class Program {
 public:
  Program(const std::vector<std::string>& args, const std::filesystem::path& cwd,
          const std::filesystem::path& logs, const std::vector<std::string>& env = {})
      : logs_(logs) {
    std::vector<std::string> argv{ANTUMBRA_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<std::string> envp(env);
    for (char** e = environ; *e != nullptr; ++e) envp.emplace_back(*e);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, (logs / "stdout").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, (logs / "stderr").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    const auto argv_c = pointers(argv);
    const auto envp_c = pointers(envp);
    const int failed =
        posix_spawn(&pid_, ANTUMBRA_EXE, &actions, nullptr, argv_c.data(), envp_c.data());
    posix_spawn_file_actions_destroy(&actions);
    if (failed != 0) throw std::runtime_error("cannot start " + std::string(ANTUMBRA_EXE));
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program() {
    if (pid_ > 0) kill_and_wait();
  }

  // Waits for the exit (at most `limit`, then kills it and fails the test).
  ProgramRun wait(std::chrono::seconds limit = std::chrono::seconds(300)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (pid_ > 0 && std::chrono::steady_clock::now() < end) {
      if (reap(WNOHANG)) return result();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ADD_FAILURE() << "antumbra ran past " << limit.count() << " s; killed";
    return kill_and_wait();
  }

  [[nodiscard]] bool running() { return pid_ > 0 && !reap(WNOHANG); }

  // SIGKILL: no handler, no clean-up, as when a machine's job is cut off.
  ProgramRun kill_and_wait() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      reap(0);
    }
    return result();
  }

 private:
  static std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> out;
    out.reserve(strings.size() + 1);
    for (auto& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
  }

  bool reap(int options) {
    int status = 0;
    if (waitpid(pid_, &status, options) != pid_) return false;
    pid_ = -1;
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return true;
  }

  ProgramRun result() const {
    return {exit_code_, read_text(logs_ / "stdout"), read_text(logs_ / "stderr")};
  }

  std::filesystem::path logs_;
  pid_t pid_ = -1;
  int exit_code_ = -1;
};

// Runs `antumbra ARGS...` from the source tree to its end; logs under `logs`.
inline ProgramRun run_antumbra(const std::vector<std::string>& args,
                               const std::filesystem::path& logs) {
  Program program(args, ANTUMBRA_TEST_SOURCE_DIR, logs);
  return program.wait();
}

}  // namespace antumbra::test
