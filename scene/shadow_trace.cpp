#include "scene/shadow_trace.h"

#include "scene/errors.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

namespace twr {

std::vector<ShadowTap> shadowTapsOf(const ShadowMap& map, glm::ivec3 centre, float reference) {
  const ShadowProjection& p = map.projection;
  const std::size_t texels = static_cast<std::size_t>(p.size) * static_cast<std::size_t>(p.size) *
                             static_cast<std::size_t>(std::max(p.layers, 0));
  if (texels == 0 || map.depth.size() != texels) {
    throw InputError("shadow taps: the map holds " + std::to_string(map.depth.size()) + " depths, expected " +
                     std::to_string(texels) + " (drawn without read-back?)");
  }
  if (centre.x < 0 || centre.x >= p.size || centre.y < 0 || centre.y >= p.size || centre.z < 0 || centre.z >= p.layers) {
    throw InputError("shadow taps: texel (" + std::to_string(centre.x) + ", " + std::to_string(centre.y) + ", " +
                     std::to_string(centre.z) + ") is outside the " + std::to_string(p.size) + "^2 x " +
                     std::to_string(p.layers) + " map");
  }
  const int radius = p.pcf / 2, last = p.size - 1;
  std::vector<ShadowTap> taps;
  for (int dy = -radius; dy <= radius; ++dy) {
    const int ty = std::clamp(centre.y + dy, 0, last);
    for (int dx = -radius; dx <= radius; ++dx) {
      ShadowTap tap;
      tap.dx = dx;
      tap.dy = dy;
      tap.texel = glm::ivec3(std::clamp(centre.x + dx, 0, last), ty, centre.z);
      tap.stored = map.at(centre.z, tap.texel.x, tap.texel.y);
      tap.lit = reference <= tap.stored;
      taps.push_back(tap);
    }
  }
  return taps;
}

bool tapsMatchTest(const ShadowTapTrace& t) {
  if (t.taps.empty()) return true;
  int lit = 0;
  float centre = 1.0f;
  for (const ShadowTap& tap : t.taps) {
    lit += tap.lit ? 1 : 0;
    if (tap.dx == 0 && tap.dy == 0) centre = tap.stored;
  }
  // The test's share: lit / taps in float, as both renderers divide.
  const float share = static_cast<float>(lit) / static_cast<float>(t.taps.size());
  return centre == t.stored && share == t.visibility;
}

std::string testsPartBeforeTaps(const std::string& nameA, const ShadowTapTrace& a, const std::string& nameB,
                                const ShadowTapTrace& b) {
  const auto state = [](const ShadowTapTrace& t) {
    return !t.tested ? "not tested" : (t.inside ? "inside the map" : "outside the map");
  };
  if (a.tested == b.tested && a.inside == b.inside) return "";
  return nameA + ": " + state(a) + ", " + nameB + ": " + state(b);
}

std::optional<std::size_t> firstDifferingTap(const ShadowTapTrace& a, const ShadowTapTrace& b) {
  const std::size_t common = std::min(a.taps.size(), b.taps.size());
  for (std::size_t k = 0; k < common; ++k) {
    const ShadowTap& x = a.taps[k];
    const ShadowTap& y = b.taps[k];
    if (x.texel != y.texel || x.stored != y.stored || x.lit != y.lit) return k;
  }
  if (a.taps.size() != b.taps.size()) return common;
  return std::nullopt;
}

nlohmann::json shadowTapTraceToJson(const ShadowTapTrace& t) {
  nlohmann::json taps = nlohmann::json::array();
  for (const ShadowTap& tap : t.taps) {
    taps.push_back({{"dx", tap.dx},
                    {"dy", tap.dy},
                    {"texel", {tap.texel.x, tap.texel.y, tap.texel.z}},
                    {"stored", tap.stored},
                    {"lit", tap.lit}});
  }
  return {{"light", t.light},         {"tested", t.tested},
          {"inside", t.inside},       {"pcf", t.pcf},
          {"texel", {t.texel.x, t.texel.y, t.texel.z}},
          {"depth", t.depth},         {"bias", t.bias},
          {"reference", t.reference}, {"visibility", t.visibility},
          {"stored", t.stored},       {"taps_match_test", tapsMatchTest(t)},
          {"taps", taps}};
}

namespace {

std::string tapText(const ShadowTap* tap) {
  if (!tap) return "-";
  char buffer[120];
  std::snprintf(buffer, sizeof buffer, "(%4d, %4d, %d) %.9f %s", tap->texel.x, tap->texel.y, tap->texel.z,
                static_cast<double>(tap->stored), tap->lit ? "lit" : "shadow");
  return buffer;
}

std::string fragmentText(const ShadowTapTrace& t) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "depth %.9f - bias %.9f = %.9f, texel (%d, %d, %d), visibility %.5f",
                static_cast<double>(t.depth), static_cast<double>(t.bias), static_cast<double>(t.reference),
                t.texel.x, t.texel.y, t.texel.z, static_cast<double>(t.visibility));
  return buffer;
}

}  // namespace

std::string formatShadowTapTraces(const std::string& nameA, const ShadowTapTrace& a, const std::string& nameB,
                                  const ShadowTapTrace* b) {
  std::ostringstream out;
  for (const auto& [name, t] : {std::pair{&nameA, &a}, std::pair{&nameB, b}}) {
    if (!t) continue;
    if (!t->tested) {
      out << "  " << *name << ": not tested (nothing drawn at this pixel, or the light has no map)\n";
      continue;
    }
    out << "  " << *name << ": " << fragmentText(*t) << (t->inside ? "" : "; outside the map: lit, no tap read") << "\n";
    if (!tapsMatchTest(*t)) {
      out << "  " << *name << ": its taps read from the map disagree with its test's own stored depth or visibility\n";
    }
  }
  if (b) {
    const std::string parted = testsPartBeforeTaps(nameA, a, nameB, *b);
    if (!parted.empty()) {
      out << "  the tests part before any tap: " << parted << "\n";
      return out.str();
    }
  }
  if (!a.tested || !a.inside) return out.str();
  char line[400];
  std::snprintf(line, sizeof line, "    tap   dx  dy  %-44s  %s\n", (nameA + ": texel (x, y, layer), stored, outcome").c_str(),
                b ? nameB.c_str() : "");
  out << line;
  const std::size_t rows = std::max(a.taps.size(), b ? b->taps.size() : std::size_t{0});
  std::size_t parted = rows;  // a plain index (rows = none), as formatSsrMarchTraces does
  if (b) {
    const std::optional<std::size_t> first = firstDifferingTap(a, *b);
    if (first) parted = *first;
  }
  for (std::size_t k = 0; k < rows; ++k) {
    const ShadowTap* left = k < a.taps.size() ? &a.taps[k] : nullptr;
    const ShadowTap* right = b && k < b->taps.size() ? &b->taps[k] : nullptr;
    const ShadowTap* any = left ? left : right;
    std::snprintf(line, sizeof line, "  %c %3zu  %3d %3d  %-44s  %s\n", k == parted ? '*' : ' ', k + 1, any->dx, any->dy,
                  tapText(left).c_str(), b ? tapText(right).c_str() : "");
    out << line;
  }
  if (b) {
    if (parted < rows) {
      out << "  first tap where they part: " << parted + 1 << "\n";
    } else if (a.reference != b->reference) {
      out << "  every tap decided alike (the compared depths differ in their last bits)\n";
    } else {
      out << "  every tap alike on both\n";
    }
  }
  return out.str();
}

}  // namespace twr
