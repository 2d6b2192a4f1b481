#include "compare/timing.h"

#include "scene/statistics.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <ctime>

extern char** environ;

namespace twr {

FrameTimes summariseFrameTimes(std::vector<double> frames) {
  FrameTimes t;
  t.frames = frames;
  if (frames.empty()) return t;
  std::sort(frames.begin(), frames.end());
  t.min = frames.front();
  t.max = frames.back();
  t.median = quantileOfSorted(frames, 0.5);
  t.q1 = quantileOfSorted(frames, 0.25);
  t.q3 = quantileOfSorted(frames, 0.75);
  return t;
}

double processCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

namespace {

// This process's environment less `unset` and the names `set` replaces, then `set`.
std::vector<std::string> childEnvironment(const ChildProcess& child) {
  auto dropped = [&](const std::string& entry) {
    const std::string name = entry.substr(0, entry.find('='));
    if (std::find(child.unsetVariables.begin(), child.unsetVariables.end(), name) != child.unsetVariables.end()) {
      return true;
    }
    return std::any_of(child.setVariables.begin(), child.setVariables.end(),
                       [&](const auto& variable) { return variable.first == name; });
  };
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) {
    if (!dropped(*e)) environment.emplace_back(*e);
  }
  for (const auto& [name, value] : child.setVariables) environment.push_back(name + "=" + value);
  return environment;
}

std::vector<char*> pointersOf(const std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  for (const std::string& s : strings) pointers.push_back(const_cast<char*>(s.c_str()));
  pointers.push_back(nullptr);
  return pointers;
}

std::string readAll(int fd) {
  std::string text;
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = read(fd, buffer.data(), buffer.size());
    if (n <= 0) break;
    text.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace

ChildResult runChildProcess(const ChildProcess& child) {
  ChildResult result;
  if (child.argv.empty()) return result;
  std::array<int, 2> pipeEnds{-1, -1};
  if (child.captureStdout && pipe(pipeEnds.data()) != 0) {
    result.spawnError = errno;
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (child.captureStdout) {
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[1]);
  }
  if (!child.captureStdout && !child.stdoutPath.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, child.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  }
  if (!child.stderrPath.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, child.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
  }
  const std::vector<std::string> environment = childEnvironment(child);
  std::vector<char*> argv = pointersOf(child.argv);
  std::vector<char*> envp = pointersOf(environment);
  pid_t pid = 0;
  const std::string& program = child.program.empty() ? child.argv.front() : child.program;
  result.spawnError = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (child.captureStdout) close(pipeEnds[1]);
  if (result.spawnError != 0) {
    if (child.captureStdout) close(pipeEnds[0]);
    return result;
  }
  if (child.captureStdout) {
    result.stdoutText = readAll(pipeEnds[0]);
    close(pipeEnds[0]);
  }
  if (waitpid(pid, &result.waitStatus, 0) != pid) return result;
  result.exitCode = WIFEXITED(result.waitStatus) ? WEXITSTATUS(result.waitStatus) : -1;
  return result;
}

}  // namespace twr
