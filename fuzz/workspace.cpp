#include "fuzz/targets.h"

#include "scene/image.h"

#include <unistd.h>

#include <fstream>
#include <system_error>

namespace twr::fuzz {

namespace {

void writeText(const std::filesystem::path& path, const char* text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace

Workspace::Workspace(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
  std::filesystem::create_directories(dir_);
  Image texture = makeImage(2, 2, 0xff0000ffu);
  texture.pixel(1, 1)[1] = 255;  // one yellow texel, so orientation matters
  savePng((dir_ / "tex.png").string(), texture);
  writeText(dir_ / "model.mtl", "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 16\nmap_Kd tex.png\n");
  writeText(dir_ / "model.obj",
            "mtllib model.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
            "usemtl red\nf 1/1/1 2/2/1 3/3/1\n");
}

Workspace::~Workspace() {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);  // best effort: a leftover temp folder is harmless
}

std::filesystem::path processWorkspaceDir(const std::string& target) {
  return std::filesystem::temp_directory_path() /
         ("twinraster-fuzz-" + target + "-" + std::to_string(static_cast<long long>(getpid())));
}

}  // namespace twr::fuzz
