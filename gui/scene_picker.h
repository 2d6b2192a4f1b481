// The scene picker's lists: the scene files shipped in assets/scenes/ and the files opened
// recently (kept in gui.json), so a student picks a scene instead of typing its path.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace twr::gui {

// Recent scene files remembered (entries).
inline constexpr std::size_t kMaxRecentScenes = 8;

// The *.json files directly in `folder`, sorted by name; empty when it cannot be read.
std::vector<std::filesystem::path> sceneFilesIn(const std::filesystem::path& folder);

// Puts `path` first in `recent`, removing an older copy of it, and keeps at most `limit`.
void rememberRecent(std::vector<std::string>& recent, const std::string& path, std::size_t limit = kMaxRecentScenes);

}  // namespace twr::gui
