// Runs the built executables the way a user does, capturing exit code, stdout and stderr.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace twr::testcli {

inline const std::string kSource = TWINRASTER_SOURCE_DIR;

struct RunResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A folder under TWINRASTER_TEST_OUT for the running test, emptied first.
inline std::filesystem::path testDir(const std::string& group) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::path(TWINRASTER_TEST_OUT) / group / (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `<executable> <args>` with stdout and stderr captured in files under `dir`.
inline RunResult runProgram(const std::string& executable, const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      "\"" + executable + "\" " + args + " >\"" + out.string() + "\" 2>\"" + err.string() + "\"";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readFile(out);
  result.err = readFile(err);
  return result;
}

inline void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "missing \"" << part << "\" in:\n" << text;
}

}  // namespace twr::testcli
