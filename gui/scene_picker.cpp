#include "gui/scene_picker.h"

#include <algorithm>
#include <system_error>

namespace twr::gui {

std::vector<std::filesystem::path> sceneFilesIn(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code code;
  for (std::filesystem::directory_iterator it(folder, code), end; !code && it != end; it.increment(code)) {
    std::error_code typeCode;
    if (it->is_regular_file(typeCode) && it->path().extension() == ".json") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void rememberRecent(std::vector<std::string>& recent, const std::string& path, std::size_t limit) {
  recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
  recent.insert(recent.begin(), path);
  if (recent.size() > limit) recent.resize(limit);
}

}  // namespace twr::gui
