// twinraster: one scene, two renderers. See `twinraster --help`.
#include "app/cli/commands.h"
#include "scene/errors.h"

#include <algorithm>
#include <iostream>

namespace twr::cli {

std::vector<CommandEntry>& commandRegistry() {
  static std::vector<CommandEntry> registry;
  return registry;
}

int& exitCode() {
  static int code = kExitOk;
  return code;
}

}  // namespace twr::cli

int main(int argc, char** argv) {
  using namespace twr;
  CLI::App app{
      "twinraster: renders one scene with a CPU software pipeline and with OpenGL 3.3 "
      "(OSMesa headless), and compares them.\nExit codes: 0 ok, 1 a comparison threshold "
      "was exceeded, 2 bad input or no usable GL."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every subcommand");

  auto& registry = cli::commandRegistry();
  std::sort(registry.begin(), registry.end(),
            [](const cli::CommandEntry& a, const cli::CommandEntry& b) { return a.order < b.order; });
  for (const cli::CommandEntry& entry : registry) entry.add(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    // CLI11 returns 0 for --help; any other parse error is bad input.
    return code == 0 ? kExitOk : kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "twinraster: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "twinraster: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  return cli::exitCode();
}
