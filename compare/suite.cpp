#include "compare/suite.h"

#include "compare/timing.h"
#include "scene/errors.h"

#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

namespace twr {

namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The lines of `text` that start with `prefix`, the prefix dropped, joined by "; ".
std::string linesAfter(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) != 0) continue;
    if (!out.empty()) out += "; ";
    out += line.substr(prefix.size());
  }
  return out;
}

std::string lastLine(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && (trimmed.back() == '\n' || trimmed.back() == '\r')) trimmed.pop_back();
  const std::size_t at = trimmed.rfind('\n');
  return at == std::string::npos ? trimmed : trimmed.substr(at + 1);
}

SuiteCase runOne(const std::string& scene, const std::string& dir, const SuiteOptions& options) {
  SuiteCase c;
  c.scene = scene;
  c.dir = dir;
  const std::filesystem::path folder = std::filesystem::path(options.outDir) / dir;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  ChildProcess child;
  child.program = options.program;
  child.argv = {"twinraster", "compare", scene, "--out-dir", folder.string(), "--html"};
  child.argv.insert(child.argv.end(), options.compareArgs.begin(), options.compareArgs.end());
  child.stdoutPath = (folder / "stdout.txt").string();
  child.stderrPath = (folder / "stderr.txt").string();
  const auto start = std::chrono::steady_clock::now();
  const ChildResult result = runChildProcess(child);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.spawnError != 0) {
    c.outcome = SuiteOutcome::Error;
    c.message = "cannot start " + options.program + ": " + std::strerror(result.spawnError);
    return c;
  }
  classifySuiteCase(c, result.exitCode, result.waitStatus, readText(child.stderrPath));
  // A metrics.json from an earlier run would be taken for this one's: only a run that ended
  // with a verdict wrote one now.
  if (c.outcome != SuiteOutcome::Error && std::filesystem::exists(folder / "metrics.json")) {
    c.metrics = nlohmann::json::parse(readText(folder / "metrics.json"), nullptr, false);
    if (c.metrics.is_discarded()) c.metrics = nullptr;
  }
  return c;
}

}  // namespace

const char* toString(SuiteOutcome outcome) {
  switch (outcome) {
    case SuiteOutcome::Passed: return "passed";
    case SuiteOutcome::Failed: return "failed";
    case SuiteOutcome::Error: return "error";
  }
  return "error";
}

std::vector<std::string> suiteScenesFrom(const std::vector<std::string>& arguments, std::vector<std::string>& warnings) {
  std::vector<std::string> scenes;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    if (!std::filesystem::is_directory(argument, ec)) {
      scenes.push_back(argument);  // a missing file is that case's error, reported with the others
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(argument, ec)) {
      if (entry.is_regular_file(ec) && entry.path().extension() == ".json") found.push_back(entry.path().string());
    }
    std::sort(found.begin(), found.end());
    if (found.empty()) warnings.push_back(argument + ": a folder with no .json scene in it");
    scenes.insert(scenes.end(), found.begin(), found.end());
  }
  return scenes;
}

std::vector<std::string> suiteCaseDirs(const std::vector<std::string>& scenes) {
  std::vector<std::string> dirs;
  std::map<std::string, int> seen;
  for (const std::string& scene : scenes) {
    std::string name = std::filesystem::path(scene).stem().string();
    for (char& ch : name) {
      const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '-' ||
                        ch == '_' || ch == '.';
      if (!keep) ch = '_';
    }
    if (name.empty() || name == "." || name == "..") name = "scene";
    const int n = ++seen[name];
    dirs.push_back(n == 1 ? name : name + "-" + std::to_string(n));
  }
  return dirs;
}

void classifySuiteCase(SuiteCase& c, int exitCode, int waitStatus, const std::string& stderrText) {
  c.exitCode = exitCode;
  c.stderrText = stderrText;
  if (exitCode == 0) {
    c.outcome = SuiteOutcome::Passed;
  } else if (exitCode == 1) {
    c.outcome = SuiteOutcome::Failed;
    c.message = linesAfter(stderrText, "twinraster: threshold exceeded: ");
    if (c.message.empty()) c.message = lastLine(stderrText);
  } else {
    c.outcome = SuiteOutcome::Error;
    c.message = linesAfter(stderrText, "twinraster: error: ");
    if (c.message.empty()) {
      c.message = WIFSIGNALED(waitStatus) ? "compare ended by signal " + std::to_string(WTERMSIG(waitStatus))
                                          : "compare exited " + std::to_string(exitCode);
      const std::string last = lastLine(stderrText);
      if (!last.empty()) c.message += ": " + last;
    }
  }
}

std::vector<SuiteCase> runSuite(const std::vector<std::string>& scenes, const SuiteOptions& options,
                                const std::function<void(const SuiteCase&, int ended, int total)>& progress) {
  std::error_code ec;
  std::filesystem::create_directories(options.outDir, ec);
  if (!std::filesystem::is_directory(options.outDir)) throw InputError(options.outDir + ": cannot create the output folder");
  const std::vector<std::string> dirs = suiteCaseDirs(scenes);
  std::vector<SuiteCase> cases(scenes.size());
  std::atomic<std::size_t> next{0};
  std::mutex reporting;
  int ended = 0;
  const auto work = [&] {
    for (std::size_t i = next++; i < scenes.size(); i = next++) {
      cases[i] = runOne(scenes[i], dirs[i], options);
      const std::lock_guard<std::mutex> lock(reporting);
      ++ended;
      if (progress) progress(cases[i], ended, static_cast<int>(scenes.size()));
    }
  };
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(scenes.size())));
  std::vector<std::thread> workers;
  for (int j = 1; j < jobs; ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  return cases;
}

int suiteExitCode(const std::vector<SuiteCase>& cases) {
  int code = 0;
  for (const SuiteCase& c : cases) {
    if (c.outcome == SuiteOutcome::Error) return 2;
    if (c.outcome == SuiteOutcome::Failed) code = 1;
  }
  return code;
}

}  // namespace twr
