// JSON scene files; docs/scene-format.md is the contract. Every value is checked where it
// is read, so each message names the file, the JSON path of the value and what was expected.
#include "scene/scene_file.h"

#include "scene/horizon_map.h"
#include "scene/json_text.h"

#include "scene/errors.h"
#include "scene/environment_light.h"
#include "scene/obj_loader.h"
#include "scene/primitives.h"
#include "scene/read_file.h"
#include "scene/work_counters.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>

namespace twr {

namespace {

// Keeps keys in file order, so materials get indices in the order they are written.
using Json = nlohmann::ordered_json;

// Deepest node nesting accepted (inclusive); root nodes are at depth 1.
constexpr int kMaxNodeDepth = 64;
// Longest rendering of an offending value quoted in a message, in characters.
constexpr std::size_t kMaxQuotedChars = 60;
// Smallest segment counts (inclusive) that still give a closed, non-degenerate primitive.
constexpr int kMinSphereStacks = 2;
constexpr int kMinRoundSegments = 3;  // sphere slices, cylinder slices, torus rings and sides
// Largest relative difference (unitless) between a heightfield's world lengths per uv unit
// along x and z before the file is warned that parallax's square texels do not hold.
constexpr double kSquareTexelTolerance = 0.01;

constexpr std::array<std::pair<MeshType, std::string_view>, 8> kMeshTypeNames{{
    {MeshType::Cube, "cube"},
    {MeshType::Sphere, "sphere"},
    {MeshType::Plane, "plane"},
    {MeshType::Cylinder, "cylinder"},
    {MeshType::Torus, "torus"},
    {MeshType::Obj, "obj"},
    {MeshType::Triangles, "triangles"},
    {MeshType::Heightfield, "heightfield"},
}};

// "a.b" for identifier-like keys, a["odd key"] otherwise, so paths stay unambiguous.
std::string childPath(const std::string& path, const std::string& key) {
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
  if (!plain) return path + "[" + jsonText(Json(key)) + "]";
  return path.empty() ? key : path + "." + key;
}

std::string indexPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// Containers are summarised, never dumped whole: dump() recurses, and a file of 100000 nested
// '[' must give a message, not a stack overflow.
std::string quote(const Json& value) {
  std::string text;
  if (value.is_object()) {
    text = "an object {...} with " + std::to_string(value.size()) + " keys";
  } else if (value.is_array() && std::any_of(value.begin(), value.end(), [](const Json& e) { return e.is_structured(); })) {
    text = "an array of " + std::to_string(value.size()) + " arrays or objects";
  } else {
    text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
  if (text.size() > kMaxQuotedChars) text = text.substr(0, kMaxQuotedChars) + "...";
  return text;
}

// "none|back|front": every name toString() knows, in enum order (enums count from 0).
template <typename E>
std::string enumNames() {
  std::string names;
  for (int i = 0;; ++i) {
    const std::string_view name = toString(static_cast<E>(i));
    if (name == "?") break;
    if (!names.empty()) names += '|';
    names += name;
  }
  return names;
}

std::string joinNames(std::initializer_list<std::string_view> names) {
  std::string joined;
  for (std::string_view name : names) {
    if (!joined.empty()) joined += ", ";
    joined += name;
  }
  return joined;
}

// Constraints a number may carry; each has a description for the message.
enum class NumberRule { Finite, Positive, NonNegative, UnitInterval, NonZero, Colour };

std::string describe(NumberRule rule) {
  switch (rule) {
    case NumberRule::Finite: return "a finite number";
    case NumberRule::Positive: return "a number > 0";
    case NumberRule::NonNegative: return "a number >= 0";
    case NumberRule::UnitInterval: return "a number in [0, 1]";
    case NumberRule::NonZero: return "a non-zero number";
    case NumberRule::Colour: return "a number in [0, " + std::to_string(static_cast<int>(kMaxColourValue)) + "]";
  }
  return "a number";
}

bool satisfies(float v, NumberRule rule) {
  switch (rule) {
    case NumberRule::Finite: return true;
    case NumberRule::Positive: return v > 0.0f;
    case NumberRule::NonNegative: return v >= 0.0f;
    case NumberRule::UnitInterval: return v >= 0.0f && v <= 1.0f;
    case NumberRule::NonZero: return v != 0.0f;
    case NumberRule::Colour: return v >= 0.0f && v <= kMaxColourValue;
  }
  return false;
}

// Builds the document from nlohmann's SAX events, checking its structure on the way: nlohmann
// keeps the last of two equal keys silently, and a scene with "radius" twice is almost
// certainly a mistake, so the JSON path is tracked and duplicates refused, as is nesting deeper
// than kMaxJsonDepth. Built here rather than by Json::parse, in time linear in the file: its
// ordered objects search every key already read before adding one (quadratic in an object of
// a million materials), and its parse callback searches the enclosing container at the end of
// every object (quadratic in an array of a million nodes); over 120 s either way. Keys are
// known to be new here, so they are appended.
class JsonDocumentBuilder {
 public:
  JsonDocumentBuilder(std::string fileName, Json& root) : fileName_(std::move(fileName)), root_(root) {}

  bool null() { return put(Json(nullptr)); }
  bool boolean(bool v) { return put(Json(v)); }
  bool number_integer(Json::number_integer_t v) { return put(Json(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return put(Json(v)); }
  bool number_float(Json::number_float_t v, const Json::string_t&) { return put(Json(v)); }
  bool string(Json::string_t& v) { return put(Json(std::move(v))); }
  bool binary(Json::binary_t& v) { return put(Json::binary(std::move(v))); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(Json::string_t& key) {
    Frame& top = frames_.back();
    if (!top.keys.insert(key).second) {
      throw InputError(fileName_ + ": " + pathTo(key) + ": duplicate key; each key may appear once");
    }
    top.key = key;
    // ordered_map is a vector of pairs; its emplace would search it for the key first.
    auto& pairs = static_cast<std::vector<Json::object_t::value_type>&>(top.value->get_ref<Json::object_t&>());
    pairs.emplace_back(key, Json());
    pendingValue_ = &pairs.back().second;
    return true;
  }
  // Syntax errors: stop here; parseScene parses again with Json::parse, which reports them
  // with line and column.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

 private:
  struct Frame {
    bool isArray;
    std::size_t index;          // arrays: index of the element being read
    std::string key;            // objects: key of the value being read
    std::set<std::string> keys;  // objects: keys seen so far
    Json* value;                // the container being filled; only the innermost grows, so it stays put
  };

  // Stores a value where the document stands: the root, the next array element or the value
  // of the key just read. Returns true (go on).
  bool put(Json&& value) {
    place(std::move(value));
    return elementDone();
  }

  Json* place(Json&& value) {
    workCounters().jsonValuesBuilt.fetch_add(1, std::memory_order_relaxed);
    if (frames_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& top = frames_.back();
    if (top.isArray) {
      Json::array_t& array = top.value->get_ref<Json::array_t&>();
      array.push_back(std::move(value));
      return &array.back();
    }
    *pendingValue_ = std::move(value);
    return pendingValue_;
  }

  bool open(bool isArray) {
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      std::string path = pathThrough(frames_.size());
      if (path.size() > kMaxQuotedChars) path = path.substr(0, kMaxQuotedChars) + "...";
      throw InputError(fileName_ + ": " + path + ": JSON nests deeper than " + std::to_string(kMaxJsonDepth) +
                       " levels");
    }
    Json* container = place(isArray ? Json::array() : Json::object());
    frames_.push_back({isArray, 0, {}, {}, container});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return elementDone();
  }

  bool elementDone() {
    if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
    return true;
  }

  // The path through the first `frameCount` open containers.
  std::string pathThrough(std::size_t frameCount) const {
    std::string path;
    for (std::size_t i = 0; i < frameCount; ++i) {
      path = frames_[i].isArray ? indexPath(path, frames_[i].index) : childPath(path, frames_[i].key);
    }
    return path;
  }

  std::string pathTo(const std::string& key) const { return childPath(pathThrough(frames_.size() - 1), key); }

  std::string fileName_;
  Json& root_;
  std::vector<Frame> frames_;
  Json* pendingValue_ = nullptr;  // the value of the key just read
};

class SceneReader {
 public:
  SceneReader(std::string fileName, std::string baseDir) : fileName_(std::move(fileName)), baseDir_(std::move(baseDir)) {}

  Scene read(const Json& root) {
    requireObject(root, "");
    checkKeys(root, "", {"output", "camera", "ambient", "lights", "materials", "nodes", "settings", "environment"},
              "the top level");
    if (const Json* j = find(root, "output")) readOutput(*j, "output");
    if (const Json* j = find(root, "camera")) readCamera(*j, "camera");
    if (const Json* j = find(root, "ambient")) scene_.ambient = readColour(*j, "ambient", NumberRule::Colour);
    if (const Json* j = find(root, "lights")) readLights(*j, "lights");
    if (const Json* j = find(root, "materials")) readMaterials(*j, "materials");
    if (const Json* j = find(root, "settings")) readSettings(*j, "settings");
    if (const Json* j = find(root, "environment")) readEnvironment(*j, "environment");
    for (const Material& m : scene_.materials) {
      if (!scene_.environment && (m.environmentSpecular != EnvironmentSpecular::None || m.refractionIndex > 0.0f ||
                                  m.environmentDiffuse != EnvironmentDiffuse::None)) {
        scene_.warnings.push_back(fileName_ + ": " + childPath("materials", m.name) +
                                  ": its environment keys are ignored: the scene has no \"environment\"");
      } else if (scene_.environment && m.environmentSpecular != EnvironmentSpecular::None && m.reflectivity == 0.0f &&
                 m.fresnel == Fresnel::None && m.refractionIndex <= 0.0f) {
        // The reflection is read, then mixed in with a share of 0: say so rather than draw it unseen.
        scene_.warnings.push_back(fileName_ + ": " + childPath("materials", m.name) + ": environment_specular " +
                                  std::string(toString(m.environmentSpecular)) +
                                  " mixes nothing in: reflectivity is 0 and fresnel is none");
      }
    }
    if (scene_.settings.ssr.enabled && scene_.settings.ssr.indirectSamples == 0 &&
        std::none_of(scene_.materials.begin(), scene_.materials.end(), [](const Material& m) { return m.ssrReflect > 0.0f; })) {
      scene_.warnings.push_back(fileName_ + ": settings.ssr: on, but no material has ssr_reflect > 0: nothing reflects");
    }
    const Json* nodes = find(root, "nodes");
    if (!nodes) fail("nodes", "missing; expected an array of nodes (it may be empty)");
    requireArray(*nodes, "nodes");
    if (nodes->size() > kMaxSceneNodes) {
      fail("nodes", std::to_string(nodes->size()) + " nodes, at most " + std::to_string(kMaxSceneNodes) +
                        " are allowed (counting children)");
    }
    scene_.nodes.reserve(nodes->size());
    for (std::size_t i = 0; i < nodes->size(); ++i) {
      scene_.nodes.push_back(readNode((*nodes)[i], indexPath("nodes", i), 1));
    }
    if (scene_.environment && scene_.environment->capture) checkCaptureNode(scene_.environment->capture->node);
    // The environment's diffuse light, for the materials that ask for it (once, at load; a
    // captured environment's once it is captured).
    prefilterEnvironmentLight(scene_);
    return std::move(scene_);
  }

 private:
  // ---- messages and generic checks ----

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(fileName_ + ": " + (path.empty() ? "" : path + ": ") + what);
  }

  static const Json* find(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  void requireObject(const Json& j, const std::string& path) const {
    if (!j.is_object()) fail(path, "expected an object {...}, got " + quote(j));
  }

  void requireArray(const Json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, "expected an array [...], got " + quote(j));
  }

  void checkKeys(const Json& object, const std::string& path, std::initializer_list<std::string_view> allowed,
                 const std::string& where) const {
    for (auto it = object.begin(); it != object.end(); ++it) {
      if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
        fail(childPath(path, it.key()), "unknown key in " + where + "; expected one of: " + joinNames(allowed));
      }
    }
  }

  float readNumber(const Json& j, const std::string& path, NumberRule rule) const {
    if (!j.is_number()) fail(path, "expected " + describe(rule) + ", got " + quote(j));
    const float v = static_cast<float>(j.get<double>());
    // JSON has no NaN or Inf, but 1e999 parses to Inf and 1e300 overflows a float.
    if (!std::isfinite(v)) fail(path, "expected " + describe(rule) + ", got a number outside the float range");
    if (!satisfies(v, rule)) fail(path, "expected " + describe(rule) + ", got " + quote(j));
    return v;
  }

  int readInt(const Json& j, const std::string& path, int minInclusive, int maxInclusive) const {
    const std::string expected =
        "expected an integer in [" + std::to_string(minInclusive) + ", " + std::to_string(maxInclusive) + "]";
    if (!j.is_number_integer()) fail(path, expected + ", got " + quote(j));
    if (j.is_number_unsigned()) {
      const auto v = j.get<std::uint64_t>();
      if (v > static_cast<std::uint64_t>(maxInclusive) || static_cast<std::int64_t>(v) < minInclusive) {
        fail(path, expected + ", got " + quote(j));
      }
      return static_cast<int>(v);
    }
    const auto v = j.get<std::int64_t>();
    if (v < minInclusive || v > maxInclusive) fail(path, expected + ", got " + quote(j));
    return static_cast<int>(v);
  }

  // Two integers, each in [minInclusive, maxInclusive]; `what` names them for the message.
  ivec2 readIntPair(const Json& j, const std::string& path, const std::string& what, int minInclusive,
                    int maxInclusive) const {
    if (!j.is_array() || j.size() != 2) {
      fail(path, "expected " + what + " (integers in [" + std::to_string(minInclusive) + ", " +
                     std::to_string(maxInclusive) + "]), got " + quote(j));
    }
    return ivec2(readInt(j[0], indexPath(path, 0), minInclusive, maxInclusive),
                 readInt(j[1], indexPath(path, 1), minInclusive, maxInclusive));
  }

  // A relief depth in texture-space units (materials and heightfield meshes alike).
  float readHeightScale(const Json& j, const std::string& path) const {
    const float scale = readNumber(j, path, NumberRule::NonNegative);
    if (scale > kMaxHeightScale) {
      fail(path, "expected a depth in [0, 1] texture-space units (1 = one uv unit), got " + quote(j));
    }
    return scale;
  }

  bool readBool(const Json& j, const std::string& path) const {
    if (!j.is_boolean()) fail(path, "expected true or false, got " + quote(j));
    return j.get<bool>();
  }

  std::string readString(const Json& j, const std::string& path, const std::string& what) const {
    if (!j.is_string() || j.get_ref<const std::string&>().empty()) {
      fail(path, "expected " + what + " (a non-empty string), got " + quote(j));
    }
    // "\u0000" is valid JSON, but every file API would cut the name there and open another file.
    if (j.get_ref<const std::string&>().find('\0') != std::string::npos) {
      fail(path, "expected " + what + ", got a string containing a NUL character (\\u0000), which no file name or "
                 "name can hold");
    }
    return j.get<std::string>();
  }

  template <typename E>
  E readEnum(const Json& j, const std::string& path) const {
    E value{};
    if (!j.is_string() || !parse(j.get_ref<const std::string&>(), value)) {
      fail(path, "expected one of " + enumNames<E>() + ", got " + quote(j));
    }
    return value;
  }

  template <int N>
  glm::vec<N, float> readVector(const Json& j, const std::string& path, NumberRule rule) const {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(N)) {
      fail(path, "expected an array of " + std::to_string(N) + " numbers (each " + describe(rule) + "), got " +
                     quote(j));
    }
    glm::vec<N, float> v(0.0f);
    for (int i = 0; i < N; ++i) v[i] = readNumber(j[static_cast<std::size_t>(i)], indexPath(path, static_cast<std::size_t>(i)), rule);
    return v;
  }

  vec3 readColour(const Json& j, const std::string& path, NumberRule rule) const {
    return readVector<3>(j, path, rule);
  }

  std::string resolvePath(const std::string& relative) const {
    const std::filesystem::path p(relative);
    if (p.is_absolute() || baseDir_.empty()) return p.lexically_normal().string();
    return (std::filesystem::path(baseDir_) / p).lexically_normal().string();
  }

  // ---- sections ----

  void readOutput(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path, {"width", "height", "background", "expect_empty"}, "output");
    if (const Json* v = find(j, "width")) scene_.output.width = readInt(*v, childPath(path, "width"), 1, kMaxImageSide);
    if (const Json* v = find(j, "height")) scene_.output.height = readInt(*v, childPath(path, "height"), 1, kMaxImageSide);
    if (const Json* v = find(j, "background")) scene_.output.background = readBackground(*v, childPath(path, "background"));
    if (const Json* v = find(j, "expect_empty")) scene_.output.expectEmpty = readBool(*v, childPath(path, "expect_empty"));
    if (const std::string problem = renderSizeProblem(scene_.output.width, scene_.output.height); !problem.empty()) {
      fail(path, problem);
    }
  }

  // [r, g, b] (alpha 1: opaque images, as every scene written before alpha existed gets) or
  // [r, g, b, a]; each in [0, 1].
  vec4 readBackground(const Json& j, const std::string& path) const {
    if (!j.is_array() || (j.size() != 3 && j.size() != 4)) {
      fail(path, "expected an array of 3 or 4 numbers [r, g, b] or [r, g, b, a] (each " +
                     describe(NumberRule::UnitInterval) + "), got " + quote(j));
    }
    if (j.size() == 3) return vec4(readColour(j, path, NumberRule::UnitInterval), 1.0f);
    return readVector<4>(j, path, NumberRule::UnitInterval);
  }

  void readCamera(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path, {"position", "target", "up", "fov_deg", "near", "far"}, "camera");
    Camera& camera = scene_.camera;
    if (const Json* v = find(j, "position")) camera.position = readVector<3>(*v, childPath(path, "position"), NumberRule::Finite);
    if (const Json* v = find(j, "target")) camera.target = readVector<3>(*v, childPath(path, "target"), NumberRule::Finite);
    if (const Json* v = find(j, "up")) camera.up = readVector<3>(*v, childPath(path, "up"), NumberRule::Finite);
    if (const Json* v = find(j, "fov_deg")) camera.fovDeg = readNumber(*v, childPath(path, "fov_deg"), NumberRule::Finite);
    if (const Json* v = find(j, "near")) camera.near = readNumber(*v, childPath(path, "near"), NumberRule::Finite);
    if (const Json* v = find(j, "far")) camera.far = readNumber(*v, childPath(path, "far"), NumberRule::Finite);
    if (const std::string error = validateCamera(camera); !error.empty()) fail(path, error);
  }

  void readLights(const Json& j, const std::string& path) {
    requireArray(j, path);
    if (j.size() > static_cast<std::size_t>(kMaxLights)) {
      fail(path, "expected at most " + std::to_string(kMaxLights) + " lights, got " + std::to_string(j.size()));
    }
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string lightPath = indexPath(path, i);
      const Json& lj = j[i];
      requireObject(lj, lightPath);
      checkKeys(lj, lightPath,
                {"type", "position", "direction", "diffuse", "specular", "attenuation", "shadow", "spot"}, "a light");
      Light light;
      if (const Json* v = find(lj, "type")) {
        const std::string type = readString(*v, childPath(lightPath, "type"), "point or directional");
        if (type == "directional") {
          light.type = LightType::Directional;
        } else if (type != "point") {
          fail(childPath(lightPath, "type"), "expected one of point|directional, got " + quote(*v));
        }
      }
      const bool directional = light.type == LightType::Directional;
      // What the other type reads is read and reported as ignored.
      for (const char* key :
           {directional ? "position" : "direction", directional ? "attenuation" : "", directional ? "spot" : ""}) {
        if (*key != '\0' && find(lj, key)) {
          scene_.warnings.push_back(fileName_ + ": " + childPath(lightPath, key) + ": ignored: a " +
                                    (directional ? "directional" : "point") + " light has no " + key);
        }
      }
      if (const Json* v = find(lj, "direction"); v && directional) {
        const std::string directionPath = childPath(lightPath, "direction");
        const glm::dvec3 direction(readVector<3>(*v, directionPath, NumberRule::Finite));
        const double length = glm::length(direction);
        if (!(length > 0.0) || !std::isfinite(length)) {
          fail(directionPath, "expected a non-zero direction (the way the light travels), got " + quote(*v));
        }
        light.directionWorld = vec3(direction / length);  // normalised in double, rounded once
      }
      if (const Json* v = find(lj, "position"); v && !directional) {
        light.posWorld = readVector<3>(*v, childPath(lightPath, "position"), NumberRule::Finite);
      }
      if (const Json* v = find(lj, "diffuse")) light.diffuse = readColour(*v, childPath(lightPath, "diffuse"), NumberRule::Colour);
      if (const Json* v = find(lj, "specular")) light.specular = readColour(*v, childPath(lightPath, "specular"), NumberRule::Colour);
      if (const Json* v = find(lj, "attenuation"); v && !directional) {
        const std::string attenuationPath = childPath(lightPath, "attenuation");
        light.attenuation = readVector<3>(*v, attenuationPath, NumberRule::NonNegative);
        if (light.attenuation == vec3(0.0f)) {
          fail(attenuationPath, "expected [A_C, A_L, A_Q] not all zero (the light would be infinitely bright), got " + quote(*v));
        }
      }
      if (const Json* v = find(lj, "spot"); v && !directional) light.spot = readSpot(*v, childPath(lightPath, "spot"));
      if (const Json* v = find(lj, "shadow")) {
        light.shadow = readShadow(*v, childPath(lightPath, "shadow"), isSpotLight(light) ? ShadowKind::Perspective
                                                                      : directional ? ShadowKind::Orthographic
                                                                                    : ShadowKind::Cube);
      }
      scene_.lights.push_back(light);
    }
    const auto shadowed = std::count_if(scene_.lights.begin(), scene_.lights.end(),
                                        [](const Light& l) { return l.shadow.has_value(); });
    if (shadowed > kMaxShadowedLights) {
      fail(path, "expected at most " + std::to_string(kMaxShadowedLights) + " lights with a \"shadow\", got " +
                     std::to_string(shadowed));
    }
  }

  // A point light's "spot" (scene/scene.h's SpotCone): an object with direction, inner_deg
  // and outer_deg, each optional.
  SpotCone readSpot(const Json& j, const std::string& path) {
    if (!j.is_object()) fail(path, "expected an object {direction, inner_deg, outer_deg}, got " + quote(j));
    checkKeys(j, path, {"direction", "inner_deg", "outer_deg"}, "a spot");
    const auto num = [](float value) { return quote(Json(value)); };
    SpotCone spot;
    if (const Json* v = find(j, "direction")) {
      const std::string directionPath = childPath(path, "direction");
      const glm::dvec3 direction(readVector<3>(*v, directionPath, NumberRule::Finite));
      const double length = glm::length(direction);
      if (!(length > 0.0) || !std::isfinite(length)) {
        fail(directionPath, "expected a non-zero direction (the cone's axis, the way the light shines), got " +
                                quote(*v));
      }
      spot.directionWorld = vec3(direction / length);  // normalised in double, rounded once
    }
    const Json* inner = find(j, "inner_deg");
    const Json* outer = find(j, "outer_deg");
    if (outer) spot.outerDeg = readNumber(*outer, childPath(path, "outer_deg"), NumberRule::Finite);
    if (!(spot.outerDeg >= kMinSpotOuterDeg && spot.outerDeg < kMaxSpotOuterDeg)) {
      fail(childPath(path, "outer_deg"), "expected a half-angle from " + num(kMinSpotOuterDeg) + " to below " +
                                             num(kMaxSpotOuterDeg) + " degrees, got " +
                                             (outer ? quote(*outer) : num(spot.outerDeg)));
    }
    // Without inner_deg the cone's soft edge is the default's share of it.
    spot.innerDeg = inner ? readNumber(*inner, childPath(path, "inner_deg"), NumberRule::Finite)
                          : std::min(SpotCone{}.innerDeg, spot.outerDeg);
    if (!(spot.innerDeg >= 0.0f && spot.innerDeg <= spot.outerDeg)) {
      fail(childPath(path, "inner_deg"), "expected a half-angle from 0 to outer_deg (" + num(spot.outerDeg) +
                                             "), got " + (inner ? quote(*inner) : num(spot.innerDeg)));
    }
    return spot;
  }

  // A light's "shadow" (scene/shadow_map.h): true for the defaults, false for none, or an
  // object with size, bias [constant, slope], pcf and extent. `kind`: the map the light gets.
  std::optional<ShadowDesc> readShadow(const Json& j, const std::string& path, ShadowKind kind) {
    const bool cube = kind == ShadowKind::Cube;
    ShadowDesc shadow;
    if (cube) shadow.size = kDefaultCubeShadowMapSize;
    if (j.is_boolean()) return j.get<bool>() ? std::optional<ShadowDesc>(shadow) : std::nullopt;
    if (!j.is_object()) fail(path, "expected true, false or an object {size, bias, pcf, extent}, got " + quote(j));
    checkKeys(j, path, {"size", "bias", "pcf", "extent"}, "a shadow");
    if (const Json* v = find(j, "size")) {
      shadow.size = readInt(*v, childPath(path, "size"), kMinShadowMapSize, kMaxShadowMapSize);
      if (cube && shadow.size > kMaxCubeShadowMapSize) {
        fail(childPath(path, "size"), "expected at most " + std::to_string(kMaxCubeShadowMapSize) +
                                          " for a point light's cube map (six faces of that side), got " + quote(*v));
      }
    }
    if (const Json* v = find(j, "bias")) shadow.bias = readVector<2>(*v, childPath(path, "bias"), NumberRule::NonNegative);
    if (const Json* v = find(j, "pcf")) {
      shadow.pcf = readInt(*v, childPath(path, "pcf"), 1, kMaxShadowPcf);
      if (shadow.pcf % 2 == 0) fail(childPath(path, "pcf"), "expected 1, 3 or 5 (an odd kernel side), got " + quote(*v));
    }
    if (const Json* v = find(j, "extent")) shadow.extent = readNumber(*v, childPath(path, "extent"), NumberRule::NonNegative);
    return shadow;
  }

  void readMaterials(const Json& j, const std::string& path) {
    requireObject(j, path);
    if (j.size() > kMaxSceneMaterials) {
      fail(path, std::to_string(j.size()) + " materials, at most " + std::to_string(kMaxSceneMaterials) + " are allowed");
    }
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string materialPath = childPath(path, it.key());
      if (it.key().empty()) fail(path, "a material name must not be empty");
      const Json& mj = it.value();
      requireObject(mj, materialPath);
      checkKeys(mj, materialPath,
                {"ka", "kd", "ks", "shininess", "diffuse_map", "normal_map", "specular_map", "height_map", "height_scale",
                 "surface_detail", "parallax_layers", "relief_refinement_steps", "self_shadow", "horizon_directions",
                 "reflectivity", "refraction_index", "fresnel", "environment_specular", "environment_diffuse", "ssr_reflect"},
                "a material");
      Material material;
      material.name = it.key();
      if (const Json* v = find(mj, "ka")) material.ka = readColour(*v, childPath(materialPath, "ka"), NumberRule::Colour);
      if (const Json* v = find(mj, "kd")) material.kd = readColour(*v, childPath(materialPath, "kd"), NumberRule::Colour);
      if (const Json* v = find(mj, "ks")) material.ks = readColour(*v, childPath(materialPath, "ks"), NumberRule::Colour);
      if (const Json* v = find(mj, "shininess")) material.shininess = readNumber(*v, childPath(materialPath, "shininess"), NumberRule::NonNegative);
      if (const Json* v = find(mj, "diffuse_map")) {
        material.diffuseMap = readTexture(*v, childPath(materialPath, "diffuse_map"), MapRole::Colour);
      }
      if (const Json* v = find(mj, "normal_map")) {
        material.normalMap = readTexture(*v, childPath(materialPath, "normal_map"), MapRole::Normal);
      }
      if (const Json* v = find(mj, "specular_map")) {
        material.specularMap = readTexture(*v, childPath(materialPath, "specular_map"), MapRole::Colour);
      }
      readSurfaceDetail(mj, materialPath, material);
      readEnvironmentKeys(mj, materialPath, material);
      materialIndex_[material.name] = static_cast<int>(scene_.materials.size());
      scene_.materials.push_back(std::move(material));
    }
  }

  // The height-field keys of a material (docs/parallax.md): the map, its depth, the method
  // that draws it and the method's knobs. A knob of a method the material does not use is
  // read and reported as ignored.
  void readSurfaceDetail(const Json& mj, const std::string& materialPath, Material& material) {
    const auto at = [&](const char* key) { return childPath(materialPath, key); };
    if (const Json* v = find(mj, "height_map")) material.heightMap = readTexture(*v, at("height_map"), MapRole::Height);
    if (const Json* v = find(mj, "height_scale")) material.heightScale = readHeightScale(*v, at("height_scale"));
    const bool hasSurfaceDetail = find(mj, "surface_detail") != nullptr;
    if (const Json* v = find(mj, "surface_detail")) {
      material.surfaceDetail = readEnum<SurfaceDetail>(*v, at("surface_detail"));
    } else if (material.heightMap && !material.normalMap) {
      material.surfaceDetail = SurfaceDetail::BumpBlinn;  // a height map alone draws bumps
    }
    if (const Json* v = find(mj, "parallax_layers")) {
      material.parallaxLayers = readIntPair(*v, at("parallax_layers"), "[min, max] layer counts", 1, kMaxParallaxLayers);
      if (material.parallaxLayers.x > material.parallaxLayers.y) {
        fail(at("parallax_layers"), "expected min <= max, got " + quote(*v));
      }
    }
    if (const Json* v = find(mj, "relief_refinement_steps")) {
      material.reliefRefinementSteps = readInt(*v, at("relief_refinement_steps"), 0, kMaxReliefRefinementSteps);
    }
    if (const Json* v = find(mj, "self_shadow")) material.selfShadow = readEnum<SelfShadow>(*v, at("self_shadow"));
    if (const Json* v = find(mj, "horizon_directions")) {
      material.horizonDirections = readInt(*v, at("horizon_directions"), kMinHorizonDirections, kMaxHorizonDirections);
    }

    // What cannot be drawn as asked: refused when the method has nothing to read, warned when
    // a knob is read and ignored.
    const SurfaceDetail d = material.surfaceDetail;
    if (d != SurfaceDetail::NormalMap && !material.heightMap) {
      fail(at("surface_detail"), "\"" + std::string(toString(d)) + "\" reads a height map; give \"height_map\"");
    }
    if (d == SurfaceDetail::NormalMap && hasSurfaceDetail && !material.normalMap) {
      scene_.warnings.push_back(fileName_ + ": " + at("surface_detail") +
                                ": \"normal_map\" without a \"normal_map\" texture draws the interpolated normal");
    }
    const auto ignored = [&](const char* key, const std::string& why) {
      if (find(mj, key)) scene_.warnings.push_back(fileName_ + ": " + at(key) + ": ignored: " + why);
    };
    if (material.heightMap && d == SurfaceDetail::NormalMap) {
      scene_.warnings.push_back(fileName_ + ": " + at("height_map") +
                                ": read but not drawn: surface_detail is \"normal_map\" (choose one of " +
                                enumNames<SurfaceDetail>() + ")");
    }
    // The height march towards the light reads the layer counts too.
    if (!marchesLayers(d) && material.selfShadow != SelfShadow::HeightMarch) {
      ignored("parallax_layers", "only steep_parallax, relief, parallax_occlusion and self_shadow height_march march layers");
    }
    if (d != SurfaceDetail::Relief) ignored("relief_refinement_steps", "only relief refines its hit");
    if (material.selfShadow != SelfShadow::None && !material.heightMap) {
      fail(at("self_shadow"), "self-shadowing reads a height map; give \"height_map\"");
    }
    if (material.selfShadow != SelfShadow::HorizonMap) ignored("horizon_directions", "self_shadow is not \"horizon_map\"");
    if (material.selfShadow != SelfShadow::None && d == SurfaceDetail::NormalMap) {
      scene_.warnings.push_back(fileName_ + ": " + at("self_shadow") +
                                ": ignored: self-shadowing needs a height-field surface_detail, not \"normal_map\"");
      material.selfShadow = SelfShadow::None;
    }
    if (material.selfShadow == SelfShadow::HorizonMap) {
      if (material.horizonDirections % 4 != 0) {
        fail(at("horizon_directions"), "expected a multiple of 4 (4 azimuths per RGBA texel), got " +
                                           std::to_string(material.horizonDirections));
      }
      const long long work = static_cast<long long>(material.heightMap->width) * material.heightMap->height *
                             material.horizonDirections;
      if (work > kMaxHorizonTexelDirections) {
        fail(at("self_shadow"), "a horizon map of " + std::to_string(material.heightMap->width) + "x" +
                                    std::to_string(material.heightMap->height) + " texels at " +
                                    std::to_string(material.horizonDirections) +
                                    " azimuths is too costly to build at load (at most 1024x1024 at 16); use "
                                    "\"height_march\" or a smaller height map");
      }
      material.horizonMap = std::make_shared<const HorizonMap>(
          makeHorizonMap(*material.heightMap, material.heightScale, material.horizonDirections));
    }
  }

  // The environment keys of a material (docs/environment.md). environment_specular defaults
  // to mirror when the material reflects or refracts, none otherwise.
  void readEnvironmentKeys(const Json& mj, const std::string& materialPath, Material& material) {
    const auto at = [&](const char* key) { return childPath(materialPath, key); };
    if (const Json* v = find(mj, "reflectivity")) material.reflectivity = readNumber(*v, at("reflectivity"), NumberRule::UnitInterval);
    if (const Json* v = find(mj, "ssr_reflect")) material.ssrReflect = readNumber(*v, at("ssr_reflect"), NumberRule::UnitInterval);
    if (const Json* v = find(mj, "refraction_index")) {
      material.refractionIndex = readNumber(*v, at("refraction_index"), NumberRule::Positive);
      if (material.refractionIndex > kMaxRefractionIndex) {
        fail(at("refraction_index"), "expected a ratio n1 / n2 in (0, 4], got " +
                                         quote(*v));
      }
    }
    if (const Json* v = find(mj, "fresnel")) material.fresnel = readEnum<Fresnel>(*v, at("fresnel"));
    const bool usesEnvironment = material.reflectivity > 0.0f || material.refractionIndex > 0.0f ||
                                 material.fresnel != Fresnel::None;
    material.environmentSpecular = usesEnvironment ? EnvironmentSpecular::Mirror : EnvironmentSpecular::None;
    if (const Json* v = find(mj, "environment_specular")) {
      material.environmentSpecular = readEnum<EnvironmentSpecular>(*v, at("environment_specular"));
    }
    if (const Json* v = find(mj, "environment_diffuse")) {
      material.environmentDiffuse = readEnum<EnvironmentDiffuse>(*v, at("environment_diffuse"));
    }
  }

  // The scene's environment (docs/environment.md): six faces or one equirectangular image,
  // made into the cube map both renderers sample.
  void readEnvironment(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path, {"cube", "equirect", "intensity", "background", "parameterization", "size", "capture"},
              "the environment");
    const auto at = [&](const char* key) { return childPath(path, key); };
    Environment env;
    if (const Json* v = find(j, "intensity")) env.intensity = readNumber(*v, at("intensity"), NumberRule::Colour);
    if (const Json* v = find(j, "background")) env.background = readBool(*v, at("background"));
    if (const Json* v = find(j, "parameterization")) {
      env.parameterization = readEnum<EnvironmentParameterization>(*v, at("parameterization"));
    }
    const bool builtMap = env.parameterization != EnvironmentParameterization::Cube;
    if (const Json* v = find(j, "size")) {
      env.size = readInt(*v, at("size"), kMinCubeFaceSize, kMaxCubeFaceSize);
      env.sizeGiven = true;
      if ((env.size & (env.size - 1)) != 0) {
        fail(at("size"), "expected a power of two in [1, " + std::to_string(kMaxCubeFaceSize) + "], got " + quote(*v));
      }
    }
    const Json* cube = find(j, "cube");
    const Json* equirect = find(j, "equirect");
    const Json* capture = find(j, "capture");
    if ((cube != nullptr) + (equirect != nullptr) + (capture != nullptr) != 1) {
      fail(path, cube || equirect || capture
                     ? "give one source: \"cube\", \"equirect\" or \"capture\", not two"
                     : "missing its source: \"cube\": [6 image paths, +X, -X, +Y, -Y, +Z, -Z], \"equirect\": "
                       "\"file.hdr|png|jpg\" or \"capture\": {\"node\": NAME, \"size\": N}");
    }
    std::uintmax_t bytes = 0;
    if (capture) {
      // Drawn later, by each renderer (scene/environment_capture.h); the node is looked up
      // once the nodes are read. The cube stays null until a renderer captures it.
      const std::string capturePath = at("capture");
      requireObject(*capture, capturePath);
      checkKeys(*capture, capturePath, {"node", "size"}, "the capture");
      const Json* node = find(*capture, "node");
      if (!node) fail(capturePath, "missing \"node\": the name of the node the cube map is captured from");
      EnvironmentCapture c;
      c.node = readString(*node, childPath(capturePath, "node"), "a node name");
      if (const Json* v = find(*capture, "size")) {
        c.size = readInt(*v, childPath(capturePath, "size"), kMinCubeFaceSize, kMaxCubeFaceSize);
        if ((c.size & (c.size - 1)) != 0) {
          fail(childPath(capturePath, "size"),
               "expected a power of two in [1, " + std::to_string(kMaxCubeFaceSize) + "], got " + quote(*v));
        }
      }
      if (env.sizeGiven && !builtMap) {
        scene_.warnings.push_back(fileName_ + ": " + at("size") +
                                  ": ignored: a captured \"cube\" environment has the capture's size (capture.size)");
      }
      if (builtMap && !env.sizeGiven) env.size = std::clamp(2 * c.size, kDefaultEnvironmentSize, kMaxCubeFaceSize);
      // The capture's cube and chain (and a built map's layers), counted now as a loaded one's.
      const std::uintmax_t faceTexels = 6u * static_cast<std::uintmax_t>(c.size) * static_cast<std::uintmax_t>(c.size);
      bytes += faceTexels * 4 / 3 * 3 * sizeof(float);
      if (builtMap) bytes += static_cast<std::uintmax_t>(layerCount(env.parameterization)) * env.size * env.size * 4 / 3 * 3 * sizeof(float);
      env.capture = c;
      capturePath_ = capturePath;
    } else if (cube) {
      requireArray(*cube, at("cube"));
      if (cube->size() != kCubeFaces) {
        fail(at("cube"), "expected 6 image paths in GL order (+X, -X, +Y, -Y, +Z, -Z), got " +
                             std::to_string(cube->size()));
      }
      for (std::size_t f = 0; f < kCubeFaces; ++f) {
        env.facePaths[f] = resolvePath(readString((*cube)[f], indexPath(at("cube"), f), "an image path relative to the scene file"));
      }
      // The six sizes from the headers first: a mismatched or oversized set is refused before
      // anything is decoded (a face decodes to 12 bytes per texel).
      std::array<std::pair<int, int>, kCubeFaces> sizes{};
      for (std::size_t f = 0; f < kCubeFaces; ++f) {
        try {
          if (!readEnvironmentImageSize(env.facePaths[f], sizes[f].first, sizes[f].second)) continue;
        } catch (const InputError& e) {
          fail(indexPath(at("cube"), f), e.what());
        }
        const auto [w, h] = sizes[f];
        if (w != h) {
          fail(indexPath(at("cube"), f), env.facePaths[f] + ": cube face " + kCubeFaceNames[f] + " is " + std::to_string(w) +
                                             "x" + std::to_string(h) + "; cube faces must be square");
        }
        if ((w & (w - 1)) != 0) {
          fail(indexPath(at("cube"), f), env.facePaths[f] + ": cube face " + kCubeFaceNames[f] + " is " + std::to_string(w) +
                                             "x" + std::to_string(h) +
                                             "; twinraster needs a power-of-two side for the faces' mip chain (resample "
                                             "them, or give an \"equirect\" image and a \"size\")");
        }
        if (f > 0 && sizes[0].first > 0 && w != sizes[0].first) {
          fail(indexPath(at("cube"), f), env.facePaths[f] + ": cube face " + kCubeFaceNames[f] + " is " + std::to_string(w) +
                                             "x" + std::to_string(h) + " but face +X is " + std::to_string(sizes[0].first) +
                                             "x" + std::to_string(sizes[0].second) + "; all six faces must have one size");
        }
      }
      if (env.sizeGiven && !builtMap) {
        scene_.warnings.push_back(fileName_ + ": " + at("size") + ": ignored: a \"cube\" environment keeps its faces' size");
      }
      std::array<FaceImage, kCubeFaces> faces;
      int readSide = 0;
      for (std::size_t f = 0; f < kCubeFaces; ++f) {
        try {
          FaceImage face = loadEnvironmentImage(env.facePaths[f]);
          readSide = face.width;
          // Reduced at once, so six large faces are never held at full size together; the
          // power-of-two check below still sees the file's size (a reduced odd side would not).
          faces[f] = face.width > kMaxCubeFaceSize && face.width == face.height && (face.width & (face.width - 1)) == 0
                         ? faceWithinCubeLimit(std::move(face))
                         : std::move(face);
        } catch (const InputError& e) {
          fail(indexPath(at("cube"), f), e.what());
        }
      }
      std::vector<std::string> warnings;
      try {
        env.cube = std::make_shared<const CubeMap>(cubeMapFromFaces(std::move(faces), env.facePaths, warnings));
      } catch (const InputError& e) {
        fail(at("cube"), e.what());
      }
      if (readSide > kMaxCubeFaceSize) {
        warnings.push_back(env.facePaths[0] + ": cube faces are " + std::to_string(readSide) + "x" + std::to_string(readSide) +
                           ", more than " + std::to_string(kMaxCubeFaceSize) + "; read at their mip level of " +
                           std::to_string(env.cube->size()) + "x" + std::to_string(env.cube->size()));
      }
      for (const std::string& w : warnings) scene_.warnings.push_back(fileName_ + ": " + at("cube") + ": " + w);
    } else {
      env.equirectPath = resolvePath(readString(*equirect, at("equirect"), "an image path relative to the scene file"));
      FaceImage image;
      try {
        image = loadEnvironmentImage(env.equirectPath);
      } catch (const InputError& e) {
        fail(at("equirect"), e.what());
      }
      if (image.width != 2 * image.height) {
        scene_.warnings.push_back(fileName_ + ": " + at("equirect") + ": " + env.equirectPath + " is " +
                                  std::to_string(image.width) + "x" + std::to_string(image.height) +
                                  ", not 2:1; read as 360 x 180 degrees all the same (stretched)");
      }
      // A sphere or paraboloid map is built at `size` from a cube at the equirect's own
      // resolution; a cube parameterization is the cube at `size`.
      const int cubeSize = env.sizeGiven && !builtMap ? env.size : defaultCubeSizeForEquirect(image.width);
      if (!env.sizeGiven) env.size = cubeSize;
      env.cube = std::make_shared<const CubeMap>(cubeMapFromEquirect(image, cubeSize, env.equirectPath));
    }
    if (builtMap && env.cube) {
      // Unless given, twice the cube's side s: a sphere map's disk then holds the whole sphere
      // in pi s^2 texels, about half the cube's 6 s^2.
      if (!env.sizeGiven) env.size = std::clamp(2 * env.cube->size(), kDefaultEnvironmentSize, kMaxCubeFaceSize);
      env.layers = std::make_shared<const ParameterizedMap>(
          parameterizedMapFromCube(*env.cube, env.parameterization, env.size));
      for (const CubeMapLevel& level : env.layers->levels) bytes += level.r.size() * 3 * sizeof(float);
    }
    if (env.cube) {
      for (const CubeMapLevel& level : env.cube->levels) bytes += level.r.size() * 3 * sizeof(float);
    }
    if (bytes > textureBudget_) {
      fail(path, "the cube map's " + describeBytes(bytes) + " of texels are more than the " + describeBytes(textureBudget_) +
                     " left of the scene's texture memory limit of " + describeBytes(kMaxSceneTextureBytes));
    }
    textureBudget_ -= bytes;
    scene_.environment = std::move(env);
  }

  // The capture's node must name a node (the first of that name, depth first, is used).
  void checkCaptureNode(const std::string& name) {
    std::vector<const Node*> matches;
    std::vector<std::string> names;
    const std::function<void(const Node&)> visit = [&](const Node& node) {
      if (node.name == name) matches.push_back(&node);
      names.push_back(node.name);
      for (const Node& child : node.children) visit(child);
    };
    for (const Node& node : scene_.nodes) visit(node);
    if (matches.empty()) {
      std::string list;
      for (std::size_t i = 0; i < names.size() && i < 8; ++i) list += (i ? ", " : "") + quote(Json(names[i]));
      if (names.size() > 8) list += ", ...";
      fail(childPath(capturePath_, "node"), "no node is named " + quote(Json(name)) +
                                                (names.empty() ? " (the scene has no nodes)" : " (the nodes: " + list + ")"));
    }
    if (matches.size() > 1) {
      scene_.warnings.push_back(fileName_ + ": " + childPath(capturePath_, "node") + ": " + std::to_string(matches.size()) +
                                " nodes are named " + quote(Json(name)) + "; the capture is taken from the first");
    }
  }

  enum class MapRole { Colour, Normal, Height };

  // A map is a path string or {"path", "flip_v", "wrap", "srgb"} (+ "green" on a normal map).
  // Materials naming the same file with the same options share one Texture.
  std::shared_ptr<const Texture> readTexture(const Json& j, const std::string& path, MapRole role) {
    const char* pathWhat = "an image file path relative to the scene file (PNG, JPEG, BMP, TGA or DDS)";
    TextureOptions options;
    std::string relative;
    std::string filePath = path;
    if (j.is_object()) {
      if (role == MapRole::Normal) {
        checkKeys(j, path, {"path", "flip_v", "wrap", "srgb", "green"}, "a normal map");
      } else {
        checkKeys(j, path, {"path", "flip_v", "wrap", "srgb"}, "a texture");
      }
      const Json* p = find(j, "path");
      filePath = childPath(path, "path");
      if (!p) fail(filePath, std::string("missing; expected ") + pathWhat);
      relative = readString(*p, filePath, pathWhat);
      if (const Json* v = find(j, "flip_v")) options.flipV = readBool(*v, childPath(path, "flip_v"));
      if (const Json* v = find(j, "wrap")) options.wrap = readEnum<TextureWrap>(*v, childPath(path, "wrap"));
      if (const Json* v = find(j, "srgb")) options.srgb = readBool(*v, childPath(path, "srgb"));
      if (const Json* v = find(j, "green")) options.green = readEnum<GreenAxis>(*v, childPath(path, "green"));
      if (role == MapRole::Height && options.srgb) {
        scene_.warnings.push_back(fileName_ + ": " + childPath(path, "srgb") +
                                  ": a height map holds heights, not colours; decoding it as sRGB bends every "
                                  "slope (done as asked)");
      }
      if (role == MapRole::Normal && options.srgb) {
        scene_.warnings.push_back(fileName_ + ": " + childPath(path, "srgb") +
                                  ": a normal map holds directions, not colours; decoding it as sRGB bends every "
                                  "normal (done as asked)");
      }
    } else if (j.is_string()) {
      relative = readString(j, path, pathWhat);
    } else {
      fail(path, std::string("expected ") + pathWhat + " or an object {\"path\": ..., \"flip_v\", \"wrap\", \"srgb\"" +
                     (role == MapRole::Normal ? ", \"green\"" : "") + "}, got " + quote(j));
    }
    const std::string file = resolvePath(relative);
    const auto key = std::make_pair(file, options);
    for (const auto& [k, texture] : textures_) {
      if (k.first == key.first && k.second == key.second) return texture;
    }
    std::shared_ptr<const Texture> texture;
    try {
      texture = std::make_shared<const Texture>(loadTexture(file, options, textureBudget_));
    } catch (const InputError& e) {
      fail(filePath, e.what());
    }
    for (const std::string& w : texture->warnings) scene_.warnings.push_back(fileName_ + ": " + path + ": " + w);
    textures_.emplace_back(key, texture);
    return texture;
  }

  void readSettings(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path,
              {"cull", "front_face", "clip", "user_clip_planes", "view", "lighting_space", "tangent_transform",
               "interpolation", "texture_filter", "anisotropy", "tbn_lines", "pipeline", "gbuffer_position", "ssr"},
              "settings");
    RenderSettings& s = scene_.settings;
    if (const Json* v = find(j, "cull")) s.cull = readEnum<CullMode>(*v, childPath(path, "cull"));
    if (const Json* v = find(j, "front_face")) s.frontFace = readEnum<FrontFace>(*v, childPath(path, "front_face"));
    if (const Json* v = find(j, "clip")) readClip(*v, childPath(path, "clip"));
    if (const Json* v = find(j, "user_clip_planes")) readClipPlanes(*v, childPath(path, "user_clip_planes"));
    if (const std::string problem = clipSlotProblem(s); !problem.empty()) {
      fail(childPath(path, "user_clip_planes"), problem);
    }
    if (const Json* v = find(j, "view")) s.view = readEnum<View>(*v, childPath(path, "view"));
    if (const Json* v = find(j, "lighting_space")) s.lightingSpace = readEnum<LightingSpace>(*v, childPath(path, "lighting_space"));
    if (const Json* v = find(j, "pipeline")) s.pipeline = readEnum<Pipeline>(*v, childPath(path, "pipeline"));
    if (const Json* v = find(j, "gbuffer_position")) {
      s.gbufferPosition = readEnum<GBufferPosition>(*v, childPath(path, "gbuffer_position"));
    }
    if (const Json* v = find(j, "tangent_transform")) {
      s.tangentTransform = readEnum<TangentTransform>(*v, childPath(path, "tangent_transform"));
    }
    if (const Json* v = find(j, "interpolation")) s.interpolation = readEnum<Interpolation>(*v, childPath(path, "interpolation"));
    if (const Json* v = find(j, "texture_filter")) s.textureFilter = readEnum<TextureFilter>(*v, childPath(path, "texture_filter"));
    if (const Json* v = find(j, "anisotropy")) {
      const std::string at = childPath(path, "anisotropy");
      s.anisotropy = readNumber(*v, at, NumberRule::Finite);
      if (!(s.anisotropy >= 1.0f && s.anisotropy <= kMaxTextureAnisotropy)) {
        fail(at, "expected a number in [1, 16] (1 = isotropic), got " + quote(*v));
      }
    }
    if (const Json* v = find(j, "tbn_lines")) readTbnLines(*v, childPath(path, "tbn_lines"));
    if (const Json* v = find(j, "ssr")) readSsr(*v, childPath(path, "ssr"));
  }

  void readClip(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path, {"left", "right", "bottom", "top", "near", "far"}, "settings.clip");
    ClipSwitches& clip = scene_.settings.clip;
    const std::pair<const char*, bool*> switches[] = {{"left", &clip.left},     {"right", &clip.right},
                                                      {"bottom", &clip.bottom}, {"top", &clip.top},
                                                      {"near", &clip.near},     {"far", &clip.far}};
    for (const auto& [key, target] : switches) {
      if (const Json* v = find(j, key)) *target = readBool(*v, childPath(path, key));
    }
  }

  void readClipPlanes(const Json& j, const std::string& path) {
    requireArray(j, path);
    if (j.size() > static_cast<std::size_t>(kMaxUserClipPlanes)) {
      fail(path, "expected at most " + std::to_string(kMaxUserClipPlanes) + " planes, got " + std::to_string(j.size()));
    }
    scene_.settings.userClipPlanes.clear();
    for (std::size_t i = 0; i < j.size(); ++i) {
      const vec4 plane = readVector<4>(j[i], indexPath(path, i), NumberRule::Finite);
      if (vec3(plane) == vec3(0.0f)) {
        fail(indexPath(path, i), "expected a plane [a, b, c, d] with (a, b, c) not all zero, got " + quote(j[i]));
      }
      scene_.settings.userClipPlanes.push_back(plane);
    }
  }

  void readTbnLines(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path, {"enabled", "length", "mode"}, "settings.tbn_lines");
    TbnLines& lines = scene_.settings.tbnLines;
    if (const Json* v = find(j, "enabled")) lines.enabled = readBool(*v, childPath(path, "enabled"));
    if (const Json* v = find(j, "length")) lines.length = readNumber(*v, childPath(path, "length"), NumberRule::Positive);
    if (const Json* v = find(j, "mode")) lines.mode = readEnum<LineMode>(*v, childPath(path, "mode"));
  }

  // settings.ssr (docs/ssr.md).
  void readSsr(const Json& j, const std::string& path) {
    requireObject(j, path);
    checkKeys(j, path,
              {"enabled", "march", "max_steps", "step", "thickness", "indirect_samples", "sample_distribution",
               "reflect_strength"},
              "settings.ssr");
    SsrSettings& ssr = scene_.settings.ssr;
    if (const Json* v = find(j, "enabled")) ssr.enabled = readBool(*v, childPath(path, "enabled"));
    if (const Json* v = find(j, "march")) {
      ssr.march = readEnum<SsrMarch>(*v, childPath(path, "march"));
    }
    if (const Json* v = find(j, "max_steps")) ssr.maxSteps = readInt(*v, childPath(path, "max_steps"), 1, kMaxSsrSteps);
    if (const Json* v = find(j, "step")) ssr.step = readNumber(*v, childPath(path, "step"), NumberRule::Positive);
    if (find(j, "step") && (ssr.march == SsrMarch::DdaScreen || ssr.march == SsrMarch::Hiz)) {
      scene_.warnings.push_back(fileName_ + ": " + childPath(path, "step") + ": read and ignored: " +
                                std::string(toString(ssr.march)) + " steps one pixel at a time (docs/ssr.md)");
    }
    if (const Json* v = find(j, "thickness")) {
      ssr.thickness = readNumber(*v, childPath(path, "thickness"), NumberRule::Positive);
    }
    if (const Json* v = find(j, "indirect_samples")) {
      ssr.indirectSamples = readInt(*v, childPath(path, "indirect_samples"), 0, kMaxSsrIndirectSamples);
    }
    if (const Json* v = find(j, "sample_distribution")) {
      ssr.sampleDistribution = readEnum<SampleDistribution>(*v, childPath(path, "sample_distribution"));
      if (ssr.indirectSamples == 0) {
        scene_.warnings.push_back(fileName_ + ": " + childPath(path, "sample_distribution") +
                                  ": read and ignored: indirect_samples is 0 (no indirect light)");
      }
    }
    if (const Json* v = find(j, "reflect_strength")) {
      const std::string at = childPath(path, "reflect_strength");
      ssr.reflectStrength = readNumber(*v, at, NumberRule::NonNegative);
      if (ssr.reflectStrength > kMaxSsrReflectStrength) {
        fail(at, "expected a number in [0, " + quote(Json(kMaxSsrReflectStrength)) + "], got " + quote(*v));
      }
    }
  }

  // ---- nodes and meshes ----

  Node readNode(const Json& j, const std::string& path, int depth) {
    if (++nodesSoFar_ > kMaxSceneNodes) {
      fail(path, "more than " + std::to_string(kMaxSceneNodes) + " nodes (counting children); at most " +
                     std::to_string(kMaxSceneNodes) + " are allowed");
    }
    requireObject(j, path);
    checkKeys(j, path, {"name", "material", "mesh", "translate", "rotate_deg", "scale", "children"}, "a node");
    Node node;
    node.name = path;
    if (const Json* v = find(j, "name")) node.name = readString(*v, childPath(path, "name"), "a node name");
    if (const Json* v = find(j, "translate")) node.translate = readVector<3>(*v, childPath(path, "translate"), NumberRule::Finite);
    if (const Json* v = find(j, "rotate_deg")) node.rotateDeg = readVector<3>(*v, childPath(path, "rotate_deg"), NumberRule::Finite);
    // A zero scale makes the normal matrix singular (1/det = 1/0); negative mirrors, which is fine.
    if (const Json* v = find(j, "scale")) node.scale = readVector<3>(*v, childPath(path, "scale"), NumberRule::NonZero);

    const Json* materialJson = find(j, "material");
    const Json* meshJson = find(j, "mesh");
    if (materialJson) {
      const std::string materialPath = childPath(path, "material");
      if (!meshJson) fail(materialPath, "a material needs a mesh on the same node (materials are not inherited)");
      const std::string name = readString(*materialJson, materialPath, "a material name");
      const auto it = materialIndex_.find(name);
      if (it == materialIndex_.end()) fail(materialPath, "unknown material " + quote(*materialJson) + "; " + definedMaterials());
      node.materialIndex = it->second;
    }
    if (meshJson) readNodeMesh(*meshJson, childPath(path, "mesh"), depth, node);

    if (const Json* v = find(j, "children")) {
      const std::string childrenPath = childPath(path, "children");
      requireArray(*v, childrenPath);
      if (!v->empty() && depth + 1 > kMaxNodeDepth) {
        fail(indexPath(childrenPath, 0), "nodes nest deeper than " + std::to_string(kMaxNodeDepth) + " levels");
      }
      node.children.reserve(v->size());
      for (std::size_t i = 0; i < v->size(); ++i) node.children.push_back(readNode((*v)[i], indexPath(childrenPath, i), depth + 1));
    }
    return node;
  }

  std::string definedMaterials() const {
    if (scene_.materials.empty()) return "no materials are defined in \"materials\"";
    std::string names;
    for (const Material& m : scene_.materials) names += (names.empty() ? "" : ", ") + jsonText(Json(m.name));
    return "defined: " + names;
  }

  void readNodeMesh(const Json& j, const std::string& path, int depth, Node& node) {
    // The node's material is read before its mesh: a heightfield takes its relief from it.
    const Material& material =
        node.materialIndex >= 0 ? scene_.materials[static_cast<std::size_t>(node.materialIndex)] : defaultMaterial();
    MeshDesc desc = readMeshDesc(j, path, material);
    if (desc.type == MeshType::Obj) {
      readObjParts(desc, path, depth, node);
      return;
    }
    checkTriangleBudget(plannedTriangleCount(desc), path);  // before building: a typo must not allocate gigabytes
    Mesh mesh;
    try {
      workCounters().meshesBuilt.fetch_add(1, std::memory_order_relaxed);
      mesh = buildMesh(desc);
    } catch (const InputError& e) {
      fail(path, e.what());
    }
    addTriangles(mesh.triangleCount(), path);
    node.meshIndex = static_cast<int>(scene_.meshes.size());
    scene_.meshes.push_back(std::move(mesh));
    scene_.meshDescs.push_back(std::move(desc));
  }

  // The OBJ's parts (one per material) become child nodes "<node>/<part>", placed before
  // the node's own children; the node's material, when given, overrides the MTL ones.
  void readObjParts(const MeshDesc& desc, const std::string& path, int depth, Node& node) {
    const std::string filePath = childPath(path, "path");
    ObjModel model;
    try {
      // The node's own material replaces the MTL's: their maps are not read (a missing one
      // must not stop the model); "mtl": false ignores the MTL files altogether.
      ObjReadOptions read;
      read.readMtl = desc.objMtl;
      read.loadMaps = node.materialIndex < 0;
      model = loadObj(desc.path, ObjLimits{kMaxSceneTriangles - trianglesSoFar_, textureBudget_}, read);
    } catch (const InputError& e) {
      fail(filePath, e.what());
    }
    if (model.meshes.empty()) fail(filePath, desc.path + ": the OBJ holds no faces");
    for (const std::string& w : model.warnings) scene_.warnings.push_back(w);
    if (depth + 1 > kMaxNodeDepth) {
      fail(path, "an obj mesh adds a level of child nodes, which would nest deeper than " +
                     std::to_string(kMaxNodeDepth) + " levels");
    }
    std::size_t objTriangles = 0;
    for (const Mesh& m : model.meshes) objTriangles += m.triangleCount();
    addTriangles(objTriangles, path);
    // The OBJ kept within what was left; its maps (each file once) now use up that much.
    std::set<const Texture*> objTextures;
    for (const Material& m : model.materials) {
      for (const Texture* map : {m.diffuseMap.get(), m.normalMap.get(), m.specularMap.get(), m.heightMap.get()}) {
        if (map && objTextures.insert(map).second) {
          textureBudget_ -= std::min<std::uintmax_t>(textureBudget_, textureTexelBytes(*map));
        }
      }
    }

    std::vector<Node> parts;
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
      const bool hasMaterial = i < model.hasMaterial.size() && model.hasMaterial[i] && i < model.materials.size();
      const std::string partName =
          hasMaterial && !model.materials[i].name.empty() ? model.materials[i].name : "part" + std::to_string(i);
      Node part;
      part.name = node.name + "/" + partName;
      part.meshIndex = static_cast<int>(scene_.meshes.size());
      scene_.meshes.push_back(std::move(model.meshes[i]));
      scene_.meshDescs.push_back(desc);
      scene_.meshDescs.back().objPart = static_cast<int>(i);  // so the GUI rebuilds just this part
      if (node.materialIndex >= 0) {
        part.materialIndex = node.materialIndex;
      } else if (hasMaterial) {
        Material material = std::move(model.materials[i]);
        material.name = part.name;
        part.materialIndex = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(material));
      }
      parts.push_back(std::move(part));
    }
    node.materialIndex = -1;  // the node itself draws nothing; its parts carry the material
    node.children.insert(node.children.begin(), std::make_move_iterator(parts.begin()),
                         std::make_move_iterator(parts.end()));
  }

  MeshDesc readMeshDesc(const Json& j, const std::string& path, const Material& material) {
    requireObject(j, path);
    const Json* typeJson = find(j, "type");
    std::string typeNames;
    for (const auto& [type, name] : kMeshTypeNames) typeNames += (typeNames.empty() ? "" : "|") + std::string(name);
    if (!typeJson) fail(childPath(path, "type"), "missing; expected one of " + typeNames);
    MeshDesc desc;
    const auto typeIt = std::find_if(kMeshTypeNames.begin(), kMeshTypeNames.end(), [&](const auto& entry) {
      return typeJson->is_string() && typeJson->get_ref<const std::string&>() == entry.second;
    });
    if (typeIt == kMeshTypeNames.end()) fail(childPath(path, "type"), "expected one of " + typeNames + ", got " + quote(*typeJson));
    desc.type = typeIt->first;
    const std::string where = "a " + std::string(typeIt->second) + " mesh";
    const auto at = [&](const char* key) { return childPath(path, key); };

    switch (desc.type) {
      case MeshType::Cube:
        checkKeys(j, path, {"type", "size"}, where);
        if (const Json* v = find(j, "size")) desc.size = readNumber(*v, at("size"), NumberRule::Positive);
        break;
      case MeshType::Sphere:
        checkKeys(j, path, {"type", "radius", "stacks", "slices"}, where);
        if (const Json* v = find(j, "radius")) desc.radius = readNumber(*v, at("radius"), NumberRule::Positive);
        if (const Json* v = find(j, "stacks")) desc.stacks = readInt(*v, at("stacks"), kMinSphereStacks, kMaxSegments);
        if (const Json* v = find(j, "slices")) desc.slices = readInt(*v, at("slices"), kMinRoundSegments, kMaxSegments);
        break;
      case MeshType::Plane:
        checkKeys(j, path, {"type", "size", "uv_scale"}, where);
        if (const Json* v = find(j, "size")) desc.planeSize = readVector<2>(*v, at("size"), NumberRule::Positive);
        if (const Json* v = find(j, "uv_scale")) desc.uvScale = readNumber(*v, at("uv_scale"), NumberRule::Positive);
        break;
      case MeshType::Cylinder:
        checkKeys(j, path, {"type", "radius", "height", "slices"}, where);
        if (const Json* v = find(j, "radius")) desc.radius = readNumber(*v, at("radius"), NumberRule::Positive);
        if (const Json* v = find(j, "height")) desc.height = readNumber(*v, at("height"), NumberRule::Positive);
        if (const Json* v = find(j, "slices")) desc.slices = readInt(*v, at("slices"), kMinRoundSegments, kMaxSegments);
        break;
      case MeshType::Torus:
        checkKeys(j, path, {"type", "major", "minor", "rings", "sides"}, where);
        if (const Json* v = find(j, "major")) desc.major = readNumber(*v, at("major"), NumberRule::Positive);
        if (const Json* v = find(j, "minor")) desc.minor = readNumber(*v, at("minor"), NumberRule::Positive);
        if (const Json* v = find(j, "rings")) desc.rings = readInt(*v, at("rings"), kMinRoundSegments, kMaxSegments);
        if (const Json* v = find(j, "sides")) desc.sides = readInt(*v, at("sides"), kMinRoundSegments, kMaxSegments);
        // minor >= major self-intersects: the surface has no well-defined outside.
        if (!(desc.minor < desc.major)) {
          fail(at("minor"), "expected minor < major, got minor " + Json(desc.minor).dump() + " and major " +
                                Json(desc.major).dump());
        }
        break;
      case MeshType::Obj: {
        checkKeys(j, path, {"type", "path", "mtl"}, where);
        const Json* v = find(j, "path");
        if (!v) fail(at("path"), "missing; expected the OBJ file path relative to the scene file");
        desc.path = resolvePath(readString(*v, at("path"), "an OBJ file path relative to the scene file"));
        if (const Json* m = find(j, "mtl")) desc.objMtl = readBool(*m, at("mtl"));
        break;
      }
      case MeshType::Triangles:
        checkKeys(j, path, {"type", "positions", "uvs", "normals"}, where);
        readTriangles(j, path, desc);
        break;
      case MeshType::Heightfield:
        checkKeys(j, path, {"type", "size", "uv_scale", "height_map", "height_scale", "resolution"}, where);
        if (const Json* v = find(j, "size")) desc.planeSize = readVector<2>(*v, at("size"), NumberRule::Positive);
        if (const Json* v = find(j, "uv_scale")) desc.uvScale = readNumber(*v, at("uv_scale"), NumberRule::Positive);
        readHeightfield(j, path, material, desc);
        break;
    }
    return desc;
  }

  // A heightfield's relief: its own height_map and height_scale, else the node's material's,
  // and its grid (docs/scene-format.md, "Heightfields").
  void readHeightfield(const Json& j, const std::string& path, const Material& material, MeshDesc& desc) {
    const auto at = [&](const char* key) { return childPath(path, key); };
    const auto warn = [&](const std::string& keyPath, const std::string& what) {
      scene_.warnings.push_back(fileName_ + ": " + keyPath + ": " + what);
    };
    desc.heightMap = material.heightMap;
    desc.heightScale = material.heightScale;
    if (const Json* v = find(j, "height_map")) desc.heightMap = readTexture(*v, at("height_map"), MapRole::Height);
    if (!desc.heightMap) {
      const std::string whose =
          &material != &defaultMaterial() ? jsonText(Json(material.name)) + " has none" : std::string("the node has none");
      fail(at("height_map"),
           "missing; a heightfield needs a height map: give \"height_map\" here or on the node's material (" + whose + ")");
    }
    if (const Json* v = find(j, "height_scale")) desc.heightScale = readHeightScale(*v, at("height_scale"));
    if (const Json* v = find(j, "resolution")) {
      desc.gridSegments = readIntPair(*v, at("resolution"), "[nx, nz] segment counts", 1, kMaxSegments);
    } else {
      bool capped = false;
      const ivec2 segments = defaultHeightfieldSegments(*desc.heightMap, desc.uvScale, &capped);
      if (capped) {
        warn(at("resolution"), "defaulted to " + std::to_string(segments.x) + " x " + std::to_string(segments.y) +
                                   " segments, coarser than one vertex per height-map texel (the limits are " +
                                   std::to_string(kMaxSegments) + " per axis and " + std::to_string(kMaxSceneTriangles) +
                                   " triangles)");
      }
    }
    // Parallax measures depth in uv units along the surface, assuming a uv unit is as long
    // along x as along z; otherwise the relief it draws is not this one.
    const double worldPerU = static_cast<double>(desc.planeSize.x) / desc.uvScale;
    const double worldPerV = static_cast<double>(desc.planeSize.y) / desc.uvScale;
    if (std::fabs(worldPerU - worldPerV) > kSquareTexelTolerance * std::max(worldPerU, worldPerV)) {
      const auto shortNumber = [](double v) {
        std::ostringstream text;
        text << v;  // six significant digits: 1, 0.5, 1.33333
        return text.str();
      };
      warn(at("size"), "one uv unit is " + shortNumber(worldPerU) + " world units along x but " +
                           shortNumber(worldPerV) + " along z; the depth follows x, and parallax mapping assumes "
                           "square texels, so it will not match this surface");
    }
    if (&material != &defaultMaterial() && material.surfaceDetail != SurfaceDetail::NormalMap) {
      warn(at("type"), "the material " + jsonText(Json(material.name)) + " draws \"" +
                           std::string(toString(material.surfaceDetail)) +
                           "\" on top of this already displaced surface; a reference usually wants surface_detail "
                           "\"normal_map\" (without a normal map: the surface's own normals)");
    }
  }

  void readTriangles(const Json& j, const std::string& path, MeshDesc& desc) {
    const std::string positionsPath = childPath(path, "positions");
    const Json* positions = find(j, "positions");
    if (!positions) fail(positionsPath, "missing; expected [[x, y, z], ...], three positions per triangle");
    requireArray(*positions, positionsPath);
    const std::size_t count = positions->size();
    if (count == 0 || count % 3 != 0) {
      fail(positionsPath, "expected a non-zero multiple of 3 positions (three per triangle), got " + std::to_string(count));
    }
    checkTriangleBudget(count / 3, positionsPath);  // refuse an oversized list before converting it
    desc.positions.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      desc.positions.push_back(readVector<3>((*positions)[i], indexPath(positionsPath, i), NumberRule::Finite));
    }
    if (const Json* uvs = find(j, "uvs")) {
      const std::string uvsPath = childPath(path, "uvs");
      requireArray(*uvs, uvsPath);
      if (uvs->size() != count) {
        fail(uvsPath, "expected " + std::to_string(count) + " uvs (one per position), got " + std::to_string(uvs->size()));
      }
      for (std::size_t i = 0; i < count; ++i) desc.uvs.push_back(readVector<2>((*uvs)[i], indexPath(uvsPath, i), NumberRule::Finite));
    }
    if (const Json* normals = find(j, "normals")) {
      const std::string normalsPath = childPath(path, "normals");
      requireArray(*normals, normalsPath);
      if (normals->size() != count) {
        fail(normalsPath,
             "expected " + std::to_string(count) + " normals (one per position), got " + std::to_string(normals->size()));
      }
      for (std::size_t i = 0; i < count; ++i) {
        const vec3 n = readVector<3>((*normals)[i], indexPath(normalsPath, i), NumberRule::Finite);
        if (!(glm::dot(n, n) > kMinLengthSquared)) fail(indexPath(normalsPath, i), "expected a non-zero normal, got " + quote((*normals)[i]));
        desc.normals.push_back(n);
      }
    }
  }

  // Triangles a primitive will have, known from its parameters (primitives.h).
  static std::size_t plannedTriangleCount(const MeshDesc& d) {
    const auto n = [](int v) { return static_cast<std::size_t>(v); };
    switch (d.type) {
      case MeshType::Cube: return 12;
      case MeshType::Sphere: return n(d.slices) * (2 * n(d.stacks) - 2);  // pole rows have one triangle per slice
      case MeshType::Plane: return 2;
      case MeshType::Cylinder: return 4 * n(d.slices);
      case MeshType::Torus: return 2 * n(d.rings) * n(d.sides);
      case MeshType::Triangles: return d.positions.size() / 3;
      case MeshType::Heightfield: {
        const bool byDefault = d.gridSegments == ivec2(0) && d.heightMap;
        const ivec2 segments = byDefault ? defaultHeightfieldSegments(*d.heightMap, d.uvScale) : d.gridSegments;
        return 2 * n(segments.x) * n(segments.y);
      }
      case MeshType::Obj: return 0;
    }
    return 0;
  }

  void checkTriangleBudget(std::size_t count, const std::string& path) const {
    if (count > kMaxSceneTriangles - trianglesSoFar_) {
      fail(path, "this mesh brings the scene to " + std::to_string(trianglesSoFar_ + count) +
                     " triangles; at most " + std::to_string(kMaxSceneTriangles) + " are allowed");
    }
  }

  void addTriangles(std::size_t count, const std::string& path) {
    checkTriangleBudget(count, path);
    trianglesSoFar_ += count;
  }

  std::string fileName_;
  std::string baseDir_;
  Scene scene_;
  std::map<std::string, int> materialIndex_;
  // Loaded maps by (file, options): a handful per scene, searched linearly.
  std::vector<std::pair<std::pair<std::string, TextureOptions>, std::shared_ptr<const Texture>>> textures_;
  std::size_t trianglesSoFar_ = 0;
  std::size_t nodesSoFar_ = 0;
  std::uintmax_t textureBudget_ = kMaxSceneTextureBytes;  // texel bytes still allowed
  std::string capturePath_;  // "environment.capture" when the environment is captured
};

// nlohmann says "[json.exception.parse_error.101] parse error at line 3, column 5: syntax
// error ..."; keep "line 3, column 5: syntax error ...". The column is where the offending
// token ends.
std::string describeParseError(const std::string& what) {
  const std::size_t at = what.find("at line ");
  if (at != std::string::npos) return what.substr(at + 3);
  return what;
}

// nlohmann refuses a number beyond the double range (1e999) with "[...out_of_range.406]
// number overflow parsing '1e999'" and no position; find the first such token to give one.
std::string describeNumberOverflow(const std::string& what, const std::string& text) {
  const std::size_t open = what.find('\'');
  const std::size_t close = what.rfind('\'');
  if (open == std::string::npos || close <= open + 1) return "invalid JSON: " + what;
  const std::string token = what.substr(open + 1, close - open - 1);
  const auto isNumberChar = [](char c) { return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+'; };
  for (std::size_t pos = text.find(token); pos != std::string::npos; pos = text.find(token, pos + 1)) {
    const std::size_t end = pos + token.size();
    if ((pos > 0 && isNumberChar(text[pos - 1])) || (end < text.size() && isNumberChar(text[end]))) continue;
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    const std::size_t lineStart = text.rfind('\n', pos == 0 ? 0 : pos - 1);
    const std::size_t column = (lineStart == std::string::npos || pos == 0) ? pos + 1 : pos - lineStart;
    return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": number " + token +
           " is outside the range of a double, expected a finite number";
  }
  return "number " + token + " is outside the range of a double, expected a finite number";
}

}  // namespace

std::string_view toString(MeshType type) {
  for (const auto& [t, name] : kMeshTypeNames)
    if (t == type) return name;
  return "?";
}

Scene parseScene(const std::string& json, const std::string& nameForMessages, const std::string& baseDir) {
  if (json.size() > kMaxSceneFileBytes) {
    throw InputError(nameForMessages + ": scene file is " + describeBytes(json.size()) + ", larger than the limit of " +
                     describeBytes(kMaxSceneFileBytes) + " for a scene file");
  }
  Json root;
  try {
    JsonDocumentBuilder builder(nameForMessages, root);
    if (!Json::sax_parse(json, &builder, nlohmann::detail::input_format_t::json, /*strict=*/true,
                         /*ignore_comments=*/true)) {
      root = Json::parse(json, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);  // throws the error
      throw InputError(nameForMessages + ": invalid JSON");  // not reached: the parse above throws
    }
  } catch (const Json::parse_error& e) {
    throw InputError(nameForMessages + ": " + describeParseError(e.what()) + " (invalid JSON)");
  } catch (const Json::out_of_range& e) {
    throw InputError(nameForMessages + ": " + describeNumberOverflow(e.what(), json));
  }
  return SceneReader(nameForMessages, baseDir).read(root);
}

Scene loadSceneFile(const std::string& path) {
  const std::string text = readFileCapped(path, kMaxSceneFileBytes, "scene file");
  const std::string baseDir = std::filesystem::path(path).parent_path().string();
  Scene scene = parseScene(text, path, baseDir.empty() ? "." : baseDir);
  scene.sourcePath = path;
  return scene;
}

}  // namespace twr
