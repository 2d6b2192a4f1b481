// A test that cannot run because something it needs is not on the machine (a package, a tool,
// a built executable). Locally it is skipped, with the reason; where every dependency is
// required it fails, naming what is missing, so a CI machine without the package cannot stay
// green with the test never run. Required when TWINRASTER_REQUIRE_DEPENDENCIES is set (to
// anything but 0; .ci/run sets it) or when CI is set (to anything but false or 0).
//
//   if (!haveCommand("xdotool")) TWR_MISSING_DEPENDENCY("xdotool") << "nothing can drive the window";
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace twr::test {

inline bool everyDependencyRequired() {
  const auto set = [](const char* name, bool ciStyle) {
    const char* value = std::getenv(name);
    if (!value || !*value) return false;
    const std::string v = value;
    return !(v == "0" || (ciStyle && v == "false"));
  };
  return set("TWINRASTER_REQUIRE_DEPENDENCIES", false) || set("CI", true);
}

inline std::string missingDependencyText(const std::string& dependency) {
  return everyDependencyRequired()
             ? "missing dependency " + dependency + " (every dependency is required here: CI or "
               "TWINRASTER_REQUIRE_DEPENDENCIES is set): "
             : "skipped: missing dependency " + dependency + ": ";
}

}  // namespace twr::test

// Returns from the test as GTEST_SKIP() does, or as FAIL() does where every dependency is
// required; stream the reason after it.
#define TWR_MISSING_DEPENDENCY(dependency)                                                              \
  return ::testing::internal::AssertHelper(::twr::test::everyDependencyRequired()                      \
                                               ? ::testing::TestPartResult::kFatalFailure              \
                                               : ::testing::TestPartResult::kSkip,                     \
                                           __FILE__, __LINE__, "") =                                   \
             ::testing::Message() << ::twr::test::missingDependencyText(dependency)
