// `twinraster suite`: the comparison of many scenes, each in a process of its own (a scene that
// crashes a renderer or exhausts memory ends its own run, not the others'; llvmpipe reads its
// environment once per process), N at once, with a page per scene, an index page and a JUnit
// file (compare/suite_page.h).
#pragma once

#include <nlohmann/json.hpp>  // SuiteCase holds its metrics by value

#include <functional>
#include <string>
#include <vector>

namespace twr {

enum class SuiteOutcome {
  Passed,  // compare exited 0: within the thresholds asked for (or none asked for)
  Failed,  // exited 1: over a threshold
  Error,   // exited 2 (bad input) or did not exit normally (a crash, a signal)
};
const char* toString(SuiteOutcome outcome);

struct SuiteCase {
  std::string scene;  // as given on the command line
  std::string dir;    // its folder under the suite's, relative ("default", "default-2")
  SuiteOutcome outcome = SuiteOutcome::Error;
  int exitCode = -1;       // compare's; -1 when it did not exit normally
  std::string message;     // Failed: the threshold lines; Error: compare's error message
  std::string stderrText;  // all compare printed on stderr
  nlohmann::json metrics;  // its metrics.json; null when it wrote none
  double seconds = 0.0;    // wall time of the compare process
};

struct SuiteOptions {
  std::string outDir;
  int jobs = 1;                          // compare processes at once (>= 1)
  std::vector<std::string> compareArgs;  // after SCENE --out-dir DIR --html: --targets, --gl-context egl, ...
  std::string program = "/proc/self/exe";  // the twinraster executable the children run
};

// The scenes the arguments name: a file as given, a folder as the .json files directly in it
// (sorted by name). `warnings` gets a line for a folder that holds none.
std::vector<std::string> suiteScenesFrom(const std::vector<std::string>& arguments, std::vector<std::string>& warnings);

// Folder names for `scenes`, one each: the file name without its extension, characters other
// than letters, digits, '-', '_' and '.' replaced by '_', a repeated name numbered "-2", "-3".
std::vector<std::string> suiteCaseDirs(const std::vector<std::string>& scenes);

// How a case ended, from compare's exit code and stderr (the message: the "threshold exceeded"
// lines for a failure, the "error" lines for bad input, how it ended for a crash).
void classifySuiteCase(SuiteCase& c, int exitCode, int waitStatus, const std::string& stderrText);

// Runs compare on every scene, `options.jobs` at once; `progress` (may be empty) is called
// after each case ends, from the thread that ran it but never from two at once, with the
// number ended so far. The cases come back in the order of `scenes`. Throws InputError when
// the output folder cannot be made; a bad scene is an Error case, never an exception.
std::vector<SuiteCase> runSuite(const std::vector<std::string>& scenes, const SuiteOptions& options,
                                const std::function<void(const SuiteCase&, int ended, int total)>& progress);

// The suite's exit code: 0 when every case passed, 1 when any failed, 2 when any is an error.
int suiteExitCode(const std::vector<SuiteCase>& cases);

}  // namespace twr
