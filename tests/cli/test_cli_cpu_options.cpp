// --cpu-path and --cpu-isa on `render`, `compare`, `trace` and `bench`: the targets this
// machine runs work (scalar and auto), an unknown name and a target this CPU cannot run exit
// 2 naming it before anything is rendered, and the paths and targets draw the same PNG.
// The supported targets come from `twinraster info --json` (cpu_isas_supported), so the
// unsupported one is picked on whatever machine runs the tests.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace twr::testcli {
namespace {

const std::string kDefaultScene = kSource + "/assets/scenes/default.json";
const std::string kSmall = " --width 96 --height 72";
// Every target name --cpu-isa accepts besides auto, best first.
const std::array<std::string, 5> kTargets = {"avx512", "avx2", "sse4", "neon", "scalar"};

RunResult runCli(const std::string& args, const std::filesystem::path& dir) {
  return runProgram(TWINRASTER_CLI, args, dir);
}

std::vector<std::string> supportedTargets() {
  const RunResult r = runCli("info --json \"" + kDefaultScene + "\"", testDir("cli_cpu_options_info"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out).at("cpu_isas_supported").get<std::vector<std::string>>();
}

// A target this machine cannot run: avx512 where it lacks AVX-512 (as the CI machine does),
// else the first one not supported (neon on x86-64, the x86 ones on ARM).
std::string unsupportedTarget() {
  const std::vector<std::string> supported = supportedTargets();
  for (const std::string& target : kTargets) {
    if (std::find(supported.begin(), supported.end(), target) == supported.end()) return target;
  }
  return "";
}

// One invocation per subcommand, writing under `dir`, with `extra` appended.
struct Command {
  std::string name, args;
};
std::vector<Command> commands(const std::filesystem::path& dir) {
  return {
      {"render", "render \"" + kDefaultScene + "\"" + kSmall + " --out \"" + (dir / "cpu.png").string() + "\""},
      {"compare", "compare \"" + kDefaultScene + "\"" + kSmall + " --repeat 1 --out-dir \"" + (dir / "cmp").string() +
                      "\""},
      {"trace", "trace \"" + kDefaultScene + "\" 48 70" + kSmall},
      {"bench", "bench \"" + kDefaultScene + "\"" + kSmall + " --frames 1 --warmup 0 --threads 1"},
  };
}

TEST(CliCpuOptions, ScalarAndAutoWorkOnEveryCommand) {
  const auto dir = testDir("cli_cpu_options");
  // scalar: the last target this build has (a build without scalar kernels, CMake's
  // TWINRASTER_KERNEL_TARGETS, has another last one).
  for (const std::string& isa : {supportedTargets().back(), std::string("auto")}) {
    for (const Command& c : commands(dir)) {
      const RunResult r = runCli(c.args + " --cpu-isa " + isa, dir);
      EXPECT_EQ(r.exitCode, 0) << c.args << " --cpu-isa " << isa << "\n" << r.err;
      EXPECT_FALSE(r.out.empty()) << c.name;
    }
  }
}

// Each command says it ran the teaching path, and its picture is the fast path's to the bit.
TEST(CliCpuOptions, TeachingPathWorksOnEveryCommand) {
  const auto dir = testDir("cli_cpu_options");
  const std::map<std::string, std::string> says = {{"render", "cpu teaching)"},
                                                   {"compare", " ms (teaching)"},
                                                   {"trace", "rendered by the cpu path: teaching"},
                                                   {"bench", "  cpu teaching "}};
  for (const Command& c : commands(dir)) {
    const RunResult r = runCli(c.args + " --cpu-path teaching", dir);
    EXPECT_EQ(r.exitCode, 0) << c.args << " --cpu-path teaching\n" << r.err;
    EXPECT_NE(r.out.find(says.at(c.name)), std::string::npos) << c.name << " does not say '" << says.at(c.name)
                                                               << "':\n" << r.out;
    if (c.name != "render") continue;
    const std::string teaching = readFile(dir / "cpu.png");
    ASSERT_EQ(runCli(c.args, dir).exitCode, 0);
    EXPECT_FALSE(teaching.empty());
    EXPECT_EQ(readFile(dir / "cpu.png"), teaching) << "the teaching and fast paths drew different PNGs";
  }
}

TEST(CliCpuOptions, UnknownTargetExitsTwoNamingIt) {
  const auto dir = testDir("cli_cpu_options");
  for (const Command& c : commands(dir)) {
    const RunResult r = runCli(c.args + " --cpu-isa avx9000", dir);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    expectContains(r.err, "--cpu-isa");
    expectContains(r.err, "avx9000");
    expectContains(r.err, "auto|avx512|avx2|sse4|neon|scalar");
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "cpu.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "cmp"));
}

TEST(CliCpuOptions, TargetThisCpuCannotRunExitsTwoBeforeRendering) {
  const std::string target = unsupportedTarget();
  ASSERT_FALSE(target.empty()) << "this machine runs every target; nothing to refuse";
  const auto dir = testDir("cli_cpu_options");
  for (const Command& c : commands(dir)) {
    const RunResult r = runCli(c.args + " --cpu-isa " + target, dir);
    EXPECT_EQ(r.exitCode, 2) << c.args << " --cpu-isa " << target << "\n" << r.out;
    expectContains(r.err, "--cpu-isa: " + target + ": ");
    EXPECT_EQ(r.out, "") << c.name << " printed results for a target it cannot run";
  }
  // Refused before anything rendered or was written.
  EXPECT_FALSE(std::filesystem::exists(dir / "cpu.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "cmp"));
}

TEST(CliCpuOptions, ATargetWithTheTeachingPathExitsTwo) {
  const auto dir = testDir("cli_cpu_options");
  const RunResult r = runCli(commands(dir)[0].args + " --cpu-path teaching --cpu-isa " + supportedTargets().back(), dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "teaching path");
  EXPECT_FALSE(std::filesystem::exists(dir / "cpu.png"));
}

TEST(CliCpuOptions, EveryPathAndTargetWritesTheSamePng) {
  const auto dir = testDir("cli_cpu_options");
  const auto render = [&](const std::string& options, const std::string& file) {
    const std::string png = (dir / file).string();
    const RunResult r = runCli("render \"" + kDefaultScene + "\" --width 160 --height 120 --out \"" + png + "\" " +
                                   options,
                               dir);
    EXPECT_EQ(r.exitCode, 0) << options << "\n" << r.err;
    return readFile(png);
  };
  const std::string fast = render("", "fast.png");
  ASSERT_FALSE(fast.empty());
  EXPECT_TRUE(render("--cpu-path teaching", "teaching.png") == fast) << "teaching.png differs from fast.png";
  for (const std::string& target : supportedTargets()) {
    EXPECT_TRUE(render("--cpu-isa " + target, target + ".png") == fast) << target << ".png differs from fast.png";
  }
}

TEST(CliCpuOptions, RenderCompareAndTraceSayWhichPathRan) {
  const auto dir = testDir("cli_cpu_options");
  const std::string target = supportedTargets().front();
  RunResult r = runCli(commands(dir)[0].args + " --cpu-path teaching", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "cpu teaching)");
  r = runCli(commands(dir)[0].args, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "cpu fast (" + target + "))");

  const std::string last = supportedTargets().back();  // scalar, unless this build has no scalar kernels
  r = runCli(commands(dir)[1].args + " --json --cpu-isa " + last, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["cpu_path"], "fast (" + last + ")");
  EXPECT_EQ(json["cpu_isa"], last);
  r = runCli(commands(dir)[1].args + " --json --cpu-path teaching", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["cpu_path"], "teaching");
  EXPECT_TRUE(json["cpu_isa"].is_null());

  // trace: the final pixel from the teaching render equals the fast one's.
  r = runCli(commands(dir)[2].args + " --json --cpu-path teaching", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json teaching = nlohmann::json::parse(r.out);
  r = runCli(commands(dir)[2].args + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json fast = nlohmann::json::parse(r.out);
  EXPECT_EQ(teaching["cpu_path"], "teaching");
  EXPECT_EQ(fast["cpu_path"], "fast (" + target + ")");
  EXPECT_EQ(teaching["final"], fast["final"]);
  EXPECT_EQ(teaching["final"]["rgba"][3], 255) << "(48, 70) is on the floor";
  r = runCli(commands(dir)[2].args + " --cpu-path teaching", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "final pixel rendered by the cpu path: teaching");
}

TEST(CliCpuOptions, HelpNamesTheOptions) {
  const auto dir = testDir("cli_cpu_options");
  for (const std::string command : {"render", "compare", "trace", "bench"}) {
    const RunResult r = runCli(command + " --help", dir);
    EXPECT_EQ(r.exitCode, 0);
    expectContains(r.out, "--cpu-path");
    expectContains(r.out, "--cpu-isa");
    expectContains(r.out, "auto|avx512|avx2|sse4|neon|scalar");
  }
}

}  // namespace
}  // namespace twr::testcli
