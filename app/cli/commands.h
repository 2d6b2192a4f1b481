// Subcommand registry: each app/cli/cmd_<name>.cpp registers itself, so adding a
// subcommand never edits main.cpp.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace twr::cli {

struct CommandEntry {
  int order = 0;  // position in --help
  // Adds the subcommand to `app` and sets its callback. The callback may throw InputError
  // (exit 2) or call std::exit-free paths that set exitCode().
  std::function<void(CLI::App& app)> add;
};

std::vector<CommandEntry>& commandRegistry();
inline bool registerCommand(int order, std::function<void(CLI::App&)> add) {
  commandRegistry().push_back({order, std::move(add)});
  return true;
}

// Exit code the running subcommand wants (0 unless it sets otherwise).
int& exitCode();

}  // namespace twr::cli
