// Timing for the commands that time renderers (bench, compare, report): a sample of frame
// times summarised by its order statistics (scene/statistics.h), the process's CPU time, and
// child processes of this executable for what one process cannot time twice (llvmpipe reads
// GALLIVM_PERF and LP_NUM_THREADS once, when its first context is made).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace twr {

// Frame times in milliseconds and their summary.
struct FrameTimes {
  std::vector<double> frames;  // in the order measured
  double median = 0.0, min = 0.0, max = 0.0;
  double q1 = 0.0, q3 = 0.0;  // quartiles: the spread is q3 - q1 (interquartile range)
};

// The summary of `frames` (ms); all zero for an empty sample.
FrameTimes summariseFrameTimes(std::vector<double> frames);

// CPU time all threads of this process have used so far, milliseconds (CLOCK_PROCESS_CPUTIME_ID):
// close to the wall time times the threads when they all work; unlike the wall time it stays
// put when other processes take the cores.
double processCpuMilliseconds();

// A child process to run and wait for.
struct ChildProcess {
  std::string program;            // the path run ("/proc/self/exe" for this one); empty: argv[0]
  std::vector<std::string> argv;  // argv[0] included
  std::vector<std::string> unsetVariables;                      // removed from this environment
  std::vector<std::pair<std::string, std::string>> setVariables;  // then set (replacing)
  bool captureStdout = false;  // else the child writes to this process's stdout
  std::string stderrPath;      // a file for the child's stderr (truncated); empty: this stderr
  std::string stdoutPath;      // without captureStdout: a file for its stdout (truncated); empty: this stdout
};

struct ChildResult {
  int exitCode = -1;   // -1: it did not start, or did not exit normally (a signal)
  int spawnError = 0;  // posix_spawn's error number when it did not start
  int waitStatus = 0;  // waitpid's status word
  std::string stdoutText;  // with captureStdout
};

// Starts `child`, waits for it and returns how it ended. Never throws for a child that fails.
ChildResult runChildProcess(const ChildProcess& child);

}  // namespace twr
