#include "app/gui/test_probe.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

namespace twr::gui {

TestProbe::TestProbe() {
  const char* path = std::getenv(kTestStateVariable);
  if (path && *path) path_ = path;
}

void TestProbe::beginFrame() {
  if (!enabled()) return;
  state_ = nlohmann::json::object();
  state_["items"] = nlohmann::json::object();
}

void TestProbe::item(const char* name) {
  if (!enabled()) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  state_["items"][name] = {min.x, min.y, max.x, max.y};
}

void TestProbe::endFrame() {
  if (!enabled()) return;
  const std::string text = state_.dump(1);
  if (text == lastWritten_) return;
  const std::string temporary = path_ + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << text << "\n";
    if (!out) return;
  }
  if (std::rename(temporary.c_str(), path_.c_str()) == 0) lastWritten_ = text;
}

}  // namespace twr::gui
