#include "scene/obj_loader.h"

#include "scene/errors.h"
#include "scene/read_file.h"
#include "scene/tangents.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <streambuf>
#include <tuple>

namespace twr {

namespace {

namespace fs = std::filesystem;

// Stands in for the spaces inside material names while tinyobjloader parses: its `usemtl`
// keeps only the first word of a name but its `newmtl` keeps the whole rest of the line, so
// "usemtl Hard Shiny Plastic" could never find its material. The unit separator never
// appears in text and is not whitespace to tinyobjloader.
constexpr char kNameSpace = '\x1f';
// The Unicode replacement character, for unpaired UTF-16 surrogates.
constexpr char32_t kReplacementCharacter = 0xFFFD;

// Counts of the OBJ vertex-data lines, which face indices refer to.
struct AttributeCounts {
  long long positions = 0;  // v
  long long uvs = 0;        // vt
  long long normals = 0;    // vn
};

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string trimmed(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  const std::size_t end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

// ---- text decoding ----

void appendUtf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// UTF-16 code units from `begin` (big- or little-endian) to UTF-8; a trailing odd byte is
// dropped and an unpaired surrogate becomes U+FFFD.
std::string utf8FromUtf16(const std::string& bytes, std::size_t begin, bool bigEndian) {
  const auto unitAt = [&](std::size_t i) {
    const auto first = static_cast<unsigned char>(bytes[i]);
    const auto second = static_cast<unsigned char>(bytes[i + 1]);
    return static_cast<char16_t>(bigEndian ? (first << 8) | second : (second << 8) | first);
  };
  std::string out;
  out.reserve(bytes.size() / 2);
  for (std::size_t i = begin; i + 1 < bytes.size(); i += 2) {
    const char16_t unit = unitAt(i);
    if (unit >= 0xD800 && unit <= 0xDBFF && i + 3 < bytes.size()) {
      const char16_t low = unitAt(i + 2);
      if (low >= 0xDC00 && low <= 0xDFFF) {
        appendUtf8(out, 0x10000 + ((static_cast<char32_t>(unit) - 0xD800) << 10) + (low - 0xDC00));
        i += 2;
        continue;
      }
    }
    appendUtf8(out, unit >= 0xD800 && unit <= 0xDFFF ? kReplacementCharacter : unit);
  }
  return out;
}

// The file's text as UTF-8 with '\n' line ends: a UTF-8 byte-order mark is dropped, UTF-16
// (with a byte-order mark, or recognised by a zero byte beside the first ASCII character) is
// transcoded, "\r\n" and a lone "\r" become "\n". UTF-32 is refused.
std::string decodeText(const std::string& bytes, const std::string& path) {
  const auto byteAt = [&](std::size_t i) { return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0x100u; };
  std::string text;
  if ((byteAt(0) == 0x00 && byteAt(1) == 0x00 && byteAt(2) == 0xFE && byteAt(3) == 0xFF) ||
      (byteAt(0) == 0xFF && byteAt(1) == 0xFE && byteAt(2) == 0x00 && byteAt(3) == 0x00)) {
    throw InputError(path + ": the file is UTF-32 encoded; expected UTF-8 or UTF-16 text");
  } else if (byteAt(0) == 0xEF && byteAt(1) == 0xBB && byteAt(2) == 0xBF) {
    text = bytes.substr(3);
  } else if (byteAt(0) == 0xFE && byteAt(1) == 0xFF) {
    text = utf8FromUtf16(bytes, 2, true);
  } else if (byteAt(0) == 0xFF && byteAt(1) == 0xFE) {
    text = utf8FromUtf16(bytes, 2, false);
  } else if (byteAt(0) == 0x00 && byteAt(1) > 0x00 && byteAt(1) < 0x80) {
    text = utf8FromUtf16(bytes, 0, true);
  } else if (byteAt(0) > 0x00 && byteAt(0) < 0x80 && byteAt(1) == 0x00) {
    text = utf8FromUtf16(bytes, 0, false);
  } else {
    text = bytes;
  }
  std::string normalised;
  normalised.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') {
      normalised += text[i];
    } else if (i + 1 >= text.size() || text[i + 1] != '\n') {
      normalised += '\n';
    }
  }
  return normalised;
}

// ---- material names with spaces ----

// A name's whitespace runs become single kNameSpace characters.
std::string encodeName(const std::string& name) {
  std::string encoded;
  bool inBlank = false;
  for (char c : trimmed(name)) {
    if (isBlank(c)) {
      inBlank = true;
      continue;
    }
    if (inBlank) encoded += kNameSpace;
    inBlank = false;
    encoded += c;
  }
  return encoded;
}

std::string decodeName(std::string name) {
  std::replace(name.begin(), name.end(), kNameSpace, ' ');
  return name;
}

struct NamedLine {
  long long line = 0;
  std::string name;  // decoded
};

// Rewrites every "<keyword> <name>" line so the name is one token (encodeName); returns the
// names in file order with their line numbers.
std::vector<NamedLine> encodeNamesAfter(std::string& text, const std::string& keyword) {
  std::vector<NamedLine> names;
  std::string out;
  out.reserve(text.size());
  long long lineNumber = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++lineNumber;
    const std::string line = text.substr(start, end - start);
    std::size_t at = 0;
    while (at < line.size() && isBlank(line[at])) ++at;
    const std::size_t nameAt = at + keyword.size();
    if (line.compare(at, keyword.size(), keyword) == 0 && nameAt < line.size() && isBlank(line[nameAt])) {
      const std::string encoded = encodeName(line.substr(nameAt));
      names.push_back({lineNumber, decodeName(encoded)});
      out += keyword + ' ' + encoded;
    } else {
      out += line;
    }
    if (end < text.size()) out += '\n';
    start = end + 1;
  }
  text = std::move(out);
  return names;
}

// ---- our own pass over the text ----

// What our own pass over the text learns before tinyobjloader parses it.
struct ObjPrescan {
  fs::path mtlDirectory;  // of the first mtllib: texture paths are relative to the MTL
  bool hasMtllib = false;
  std::size_t triangles = 0;  // after fan triangulation of every 'f' line
  std::size_t largeFaceCorners = 0;  // corners of faces with more than kLargeFaceCorners
};

// tinyobjloader triangulates a polygon by ear clipping, in time quadratic in its corners (a
// face of 16,000 corners takes 0.7 s, one of 400,000 would take minutes). Each face may have
// at most kMaxFaceCorners, and the faces above kLargeFaceCorners at most
// kMaxLargeFaceCornersInFile corners in all, which bounds the whole file's triangulation to a
// few seconds (the sum of squares at most 65,536 x 16,384).
constexpr std::size_t kMaxFaceCorners = 16384;
constexpr std::size_t kLargeFaceCorners = 64;
constexpr std::size_t kMaxLargeFaceCornersInFile = 65536;

// Checks the vertex-data lines before tinyobjloader parses the file (tinyobjloader reads
// "nan", "inf" or "abc" as 0 without a word, and we want the line number), and counts the
// triangles so an oversized file is refused before anything is built.
ObjPrescan prescanObj(const std::string& path, const std::string& text, std::size_t maxTriangles) {
  ObjPrescan result;
  result.mtlDirectory = fs::path(path).parent_path();
  std::istringstream lines(text);
  std::string line;
  long long lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    std::size_t minimumValues = 0;
    if (keyword == "v" || keyword == "vn") {
      minimumValues = 3;
    } else if (keyword == "vt") {
      minimumValues = 1;
    } else if (keyword == "f") {
      std::size_t corners = 0;
      std::string corner;
      while (tokens >> corner) ++corners;
      if (corners > kMaxFaceCorners) {
        throw InputError(path + ":" + std::to_string(lineNumber) + ": a face of " + std::to_string(corners) +
                         " corners; at most " + std::to_string(kMaxFaceCorners) +
                         " are read (tinyobjloader's triangulation takes time quadratic in them)");
      }
      if (corners > kLargeFaceCorners) {
        result.largeFaceCorners += corners;
        if (result.largeFaceCorners > kMaxLargeFaceCornersInFile) {
          throw InputError(path + ":" + std::to_string(lineNumber) + ": faces of more than " +
                           std::to_string(kLargeFaceCorners) + " corners hold more than " +
                           std::to_string(kMaxLargeFaceCornersInFile) +
                           " corners in all up to here, the most read (tinyobjloader's triangulation takes time "
                           "quadratic in each face's corners)");
        }
      }
      if (corners >= 3) result.triangles += corners - 2;
      if (result.triangles > maxTriangles) {
        throw InputError(path + ":" + std::to_string(lineNumber) + ": the file has more than " +
                         std::to_string(maxTriangles) + " triangles, the most this scene can take");
      }
      continue;
    } else if (keyword == "mtllib" && !result.hasMtllib) {
      std::string firstName;  // "mtllib a.mtl b.mtl" may name several; the first decides
      tokens >> firstName;
      result.mtlDirectory = (fs::path(path).parent_path() / fs::path(firstName)).parent_path();
      result.hasMtllib = true;
      continue;
    } else {
      continue;
    }
    std::size_t values = 0;
    std::string token;
    while (tokens >> token) {
      errno = 0;
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      // tinyobjloader stores floats: a finite double beyond float's range would become inf.
      if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value) ||
          std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        throw InputError(path + ":" + std::to_string(lineNumber) + ": '" + keyword +
                         "' expects finite numbers, got '" + token + "' (each within float's range, |x| <= 3.4e38)");
      }
      ++values;
    }
    if (values < minimumValues) {
      throw InputError(path + ":" + std::to_string(lineNumber) + ": '" + keyword + "' expects at least " +
                       std::to_string(minimumValues) + " numbers, got " + std::to_string(values));
    }
  }
  return result;
}

// tinyobjloader's own extension "vw <vertex> <joint> <weight> ..." (skin weights) converts
// each joint to int without a range check (undefined for 5e9, found by fuzzing), and this
// tool draws no skinning. Each such line is blanked, keeping the line numbers, before
// tinyobjloader sees the text; the returned warning names the first (empty if none).
// The test is tinyobjloader's: after spaces and tabs, "vw" and a space or tab.
std::string blankSkinWeightLines(const std::string& path, std::string& text) {
  long long lineNumber = 0, firstLine = 0, count = 0;
  for (std::size_t lineStart = 0; lineStart < text.size();) {
    const std::size_t lineEnd = std::min(text.find('\n', lineStart), text.size());
    ++lineNumber;
    const std::size_t at = std::min(text.find_first_not_of(" \t", lineStart), lineEnd);
    if (at + 2 < lineEnd && text[at] == 'v' && text[at + 1] == 'w' && (text[at + 2] == ' ' || text[at + 2] == '\t')) {
      std::fill(text.begin() + static_cast<std::ptrdiff_t>(lineStart), text.begin() + static_cast<std::ptrdiff_t>(lineEnd), ' ');
      if (count++ == 0) firstLine = lineNumber;
    }
    lineStart = lineEnd + 1;
  }
  if (count == 0) return {};
  return path + ":" + std::to_string(firstLine) + ": 'vw' (skin weights, " + std::to_string(count) +
         (count == 1 ? " line" : " lines") + ") is not drawn; the lines are ignored";
}

// An OBJ index (1-based, or negative = relative to the lines so far) is in range.
bool objIndexInRange(long long index, long long countSoFar, long long countTotal) {
  if (index > 0) return index <= countTotal;
  if (index < 0) return -index <= countSoFar;
  return false;
}

// Finds the first face line with an out-of-range index, for the error message (0 if none
// is found, e.g. when the bad index came from somewhere we do not re-parse).
long long findBadFaceLine(const std::string& text, const AttributeCounts& total) {
  std::istringstream lines(text);
  std::string line;
  long long lineNumber = 0;
  AttributeCounts soFar;
  while (std::getline(lines, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    if (keyword == "v") ++soFar.positions;
    if (keyword == "vt") ++soFar.uvs;
    if (keyword == "vn") ++soFar.normals;
    if (keyword != "f") continue;
    std::string corner;
    while (tokens >> corner) {
      // v, v/vt, v//vn or v/vt/vn
      std::array<std::string, 3> parts;
      std::size_t part = 0;
      for (char character : corner) {
        if (character == '/') {
          if (++part >= parts.size()) break;
        } else {
          parts[part] += character;
        }
      }
      const std::array<long long, 3> soFarCounts{soFar.positions, soFar.uvs, soFar.normals};
      const std::array<long long, 3> totalCounts{total.positions, total.uvs, total.normals};
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k].empty()) continue;
        const long long index = std::atoll(parts[k].c_str());
        if (!objIndexInRange(index, soFarCounts[k], totalCounts[k])) return lineNumber;
      }
    }
  }
  return 0;
}

// tinyobjloader ends its messages with newlines; keep them on one line.
std::string oneLine(const std::string& text) {
  std::string result = trimmed(text);
  for (char& character : result) {
    if (character == '\n') character = ' ';
  }
  return decodeName(result);
}

// ---- tinyobjloader plumbing ----

// A read-only stream over a string, without copying it (tinyobjloader reads a std::istream).
class StringBuffer : public std::streambuf {
 public:
  explicit StringBuffer(std::string& text) { setg(text.data(), text.data(), text.data() + text.size()); }
};

// ---- MTL keywords nobody draws ----

// What each MTL keyword this loader does not draw would have done; a keyword whose value is
// the no-op default (d 1, Tr 0, Ke 0 0 0, illum 1 or 2) changes nothing and is not reported.
struct UnusedKeyword {
  std::string_view keyword;
  std::string_view what;
};
constexpr UnusedKeyword kUnusedMtlKeywords[] = {
    {"map_Ka", "ambient map (ambient uses Ka times the diffuse map)"},
    {"map_d", "alpha map (no transparency is drawn)"},
    {"map_Ns", "shininess map"},
    {"map_Ke", "emission map"},
    {"map_Tr", "transparency map"},
    {"refl", "reflection map"},
    {"map_refl", "reflection map"},
    {"Ke", "emission"},
    {"d", "dissolve (no transparency is drawn)"},
    {"Tr", "transparency (no transparency is drawn)"},
    {"Tf", "transmission filter"},
    {"Ni", "index of refraction"},
    {"illum", "illumination model (Phong with specular is drawn)"},
    {"Pr", "PBR roughness"}, {"Pm", "PBR metallic"}, {"Ps", "PBR sheen"}, {"Pc", "PBR clearcoat"},
    {"Pcr", "PBR clearcoat roughness"}, {"aniso", "anisotropy"}, {"anisor", "anisotropy rotation"},
    {"map_Pr", "PBR roughness map"}, {"map_Pm", "PBR metallic map"}, {"map_Ps", "PBR sheen map"},
};
// Map keywords whose options are read (the others' options are covered by the keyword's own
// warning), and the options honoured.
constexpr std::string_view kDrawnMapKeywords[] = {"map_Kd", "map_Ks", "map_Bump", "map_bump", "bump", "norm", "disp"};
constexpr std::string_view kHonouredOptions[] = {"-s", "-o", "-clamp", "-bm"};
// Arguments each texture option takes (at most; -s, -o and -t take 1 to 3 numbers).
int optionArguments(std::string_view option) {
  if (option == "-s" || option == "-o" || option == "-t") return 3;
  if (option == "-mm") return 2;
  return 1;  // -blendu, -blendv, -boost, -cc, -clamp, -imfchan, -texres, -bm, -type, -colorspace
}

bool isNumber(const std::string& token) {
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

// A keyword line whose value is the default does nothing.
bool isNoOp(const std::string& keyword, const std::vector<std::string>& values) {
  const auto allNumbersEqual = [&](double v) {
    return !values.empty() && std::all_of(values.begin(), values.end(), [&](const std::string& t) {
      return isNumber(t) && std::strtod(t.c_str(), nullptr) == v;
    });
  };
  if (keyword == "d") return allNumbersEqual(1.0);
  if (keyword == "Tr" || keyword == "Ke") return allNumbersEqual(0.0);
  if (keyword == "Tf") return allNumbersEqual(1.0);
  if (keyword == "illum") return values.size() == 1 && (values[0] == "1" || values[0] == "2");
  if (keyword == "Ni") return true;  // refraction is never drawn; Ni alone changes nothing
  return false;
}

// One warning per unused keyword or option per file: the first line it is on, and how many
// more lines have it.
void warnUnusedMtlKeywords(const std::string& path, const std::string& text, std::vector<std::string>& warnings) {
  struct Seen {
    long long firstLine = 0;
    int more = 0;
    std::string what;
  };
  std::vector<std::pair<std::string, Seen>> seen;  // in order of first appearance
  const auto note = [&](const std::string& key, long long line, const std::string& what) {
    for (auto& [k, s] : seen) {
      if (k == key) {
        ++s.more;
        return;
      }
    }
    seen.push_back({key, Seen{line, 0, what}});
  };
  std::istringstream lines(text);
  std::string line;
  long long lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword) || keyword[0] == '#') continue;
    std::vector<std::string> values;
    for (std::string t; tokens >> t;) values.push_back(t);
    const auto unused = std::find_if(std::begin(kUnusedMtlKeywords), std::end(kUnusedMtlKeywords),
                                     [&](const UnusedKeyword& u) { return u.keyword == keyword; });
    if (unused != std::end(kUnusedMtlKeywords)) {
      if (!isNoOp(keyword, values)) {
        note(keyword, lineNumber, "'" + keyword + "' (" + std::string(unused->what) + ") is not drawn");
      }
      continue;
    }
    if (std::find(std::begin(kDrawnMapKeywords), std::end(kDrawnMapKeywords), keyword) == std::end(kDrawnMapKeywords)) {
      continue;
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::string& option = values[i];
      if (option.size() < 2 || option[0] != '-' || isNumber(option)) continue;
      const int arguments = optionArguments(option);
      std::size_t taken = 0;
      while (taken < static_cast<std::size_t>(arguments) && i + 1 + taken < values.size() - 1 &&
             (isNumber(values[i + 1 + taken]) || arguments == 1)) {
        ++taken;
      }
      if (std::find(std::begin(kHonouredOptions), std::end(kHonouredOptions), option) == std::end(kHonouredOptions)) {
        note(keyword + " " + option, lineNumber, "texture option '" + option + "' on '" + keyword + "' is not used");
      }
      i += taken;
    }
  }
  for (const auto& [key, s] : seen) {
    warnings.push_back(path + ":" + std::to_string(s.firstLine) + ": " + s.what +
                       (s.more > 0 ? " (and " + std::to_string(s.more) + " more line" + (s.more > 1 ? "s" : "") + ")" : ""));
  }
}

// Reads each `mtllib` file relative to the OBJ, with the size limit, the same decoding as
// the OBJ and names with spaces made one token. Remembers the first file it cannot read.
class MtlReader : public tinyobj::MaterialReader {
 public:
  MtlReader(fs::path objDirectory, bool enabled) : objDirectory_(std::move(objDirectory)), enabled_(enabled) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* materialMap, std::string* warning, std::string* error) override {
    if (!enabled_) return false;
    const std::string path = (objDirectory_ / fs::path(name)).lexically_normal().string();
    std::string text;
    try {
      text = decodeText(readFileCapped(path, kMaxMtlFileBytes, "MTL file"), path);
    } catch (const InputError& e) {
      if (firstFailure_.empty()) firstFailure_ = e.what();
      return false;
    }
    warnUnusedMtlKeywords(path, text, warnings_);
    encodeNamesAfter(text, "newmtl");
    StringBuffer buffer(text);
    std::istream stream(&buffer);
    tinyobj::LoadMtl(materialMap, materials, &stream, warning, error);
    return true;
  }

  // "" when every mtllib file was read.
  const std::string& firstFailure() const { return firstFailure_; }
  std::vector<std::string>& warnings() { return warnings_; }

 private:
  fs::path objDirectory_;
  bool enabled_;
  std::string firstFailure_;
  std::vector<std::string> warnings_;
};

vec3 toVec3(const tinyobj::real_t* values) { return vec3(values[0], values[1], values[2]); }

// Loads each texture once per model; paths are relative to the MTL file.
class TextureCache {
 public:
  TextureCache(std::string objPath, fs::path mtlDirectory, std::uintmax_t budgetBytes, bool enabled)
      : objPath_(std::move(objPath)), mtlDirectory_(std::move(mtlDirectory)), budgetBytes_(budgetBytes), enabled_(enabled) {}

  std::shared_ptr<const Texture> get(const std::string& materialName, const char* key, const std::string& name,
                                     const tinyobj::texture_option_t& mtlOptions) {
    if (name.empty() || !enabled_) return nullptr;
    TextureOptions options;
    if (mtlOptions.clamp) options.wrap = TextureWrap::ClampToEdge;
    options.uvScale = vec2(mtlOptions.scale[0], mtlOptions.scale[1]);
    options.uvOffset = vec2(mtlOptions.origin_offset[0], mtlOptions.origin_offset[1]);
    if (!std::isfinite(options.uvScale.x) || !std::isfinite(options.uvScale.y) || !std::isfinite(options.uvOffset.x) ||
        !std::isfinite(options.uvOffset.y)) {
      throw InputError(objPath_ + ": material '" + materialName + "' " + key + " '" + name +
                       "': -s or -o is not a finite number");
    }
    std::string path = (mtlDirectory_ / fs::path(name)).lexically_normal().string();
    if (name.find('\\') != std::string::npos && !fs::exists(path)) {
      // Exported on Windows ("textures\\brick.png"): try the same path with '/'.
      std::string slashed = name;
      std::replace(slashed.begin(), slashed.end(), '\\', '/');
      path = (mtlDirectory_ / fs::path(slashed)).lexically_normal().string();
    }
    for (const auto& [k, texture] : cache_) {
      if (k.first == path && k.second == options) return texture;
    }
    std::shared_ptr<const Texture> texture;
    try {
      texture = std::make_shared<const Texture>(loadTexture(path, options, budgetBytes_));
    } catch (const InputError& error) {
      throw InputError(objPath_ + ": material '" + materialName + "' " + key + " '" + name +
                       "' cannot be loaded: " + error.what());
    }
    for (const std::string& w : texture->warnings) warnings_.push_back(w);
    cache_.push_back({{path, options}, texture});
    return texture;
  }

  std::vector<std::string>& warnings() { return warnings_; }

 private:
  std::string objPath_;
  fs::path mtlDirectory_;
  std::uintmax_t budgetBytes_;  // texel bytes still allowed
  bool enabled_;
  std::vector<std::pair<std::pair<std::string, TextureOptions>, std::shared_ptr<const Texture>>> cache_;
  std::vector<std::string> warnings_;
};

// Whether every texel is grey (r = g = b): a height map, not a tangent-space normal map
// (whose flat texel is (128, 128, 255)).
bool isGreyTexture(const Texture& texture) {
  for (std::size_t i = 0; i + 3 < texture.rgba.size(); i += 4) {
    if (texture.rgba[i] != texture.rgba[i + 1] || texture.rgba[i] != texture.rgba[i + 2]) return false;
  }
  return true;
}

Material toMaterial(const tinyobj::material_t& source, TextureCache& textures, const std::string& objPath) {
  Material material;
  material.name = decodeName(source.name);
  material.ka = toVec3(source.ambient);
  material.kd = toVec3(source.diffuse);
  material.ks = toVec3(source.specular);
  material.shininess = source.shininess;
  material.diffuseMap = textures.get(material.name, "map_Kd", source.diffuse_texname, source.diffuse_texopt);
  material.specularMap = textures.get(material.name, "map_Ks", source.specular_texname, source.specular_texopt);
  // `norm` is the explicit normal map; many exporters put the normal map in map_Bump/bump,
  // and others a height map there: grey texels say which.
  if (!source.normal_texname.empty()) {
    material.normalMap = textures.get(material.name, "norm", source.normal_texname, source.normal_texopt);
    material.normalStrength = source.normal_texopt.bump_multiplier;
  }
  if (!source.bump_texname.empty()) {
    std::shared_ptr<const Texture> bump = textures.get(material.name, "map_Bump", source.bump_texname, source.bump_texopt);
    if (bump && isGreyTexture(*bump)) {
      material.heightMap = bump;
      material.heightScale = kDefaultHeightScale * source.bump_texopt.bump_multiplier;
    } else if (bump && !material.normalMap) {
      material.normalMap = bump;
      material.normalStrength = source.bump_texopt.bump_multiplier;
    }
  }
  if (!source.displacement_texname.empty()) {
    material.heightMap = textures.get(material.name, "disp", source.displacement_texname, source.displacement_texopt);
    material.heightScale = kDefaultHeightScale * source.displacement_texopt.bump_multiplier;
  }
  // An MTL names no method: a height map beside a normal map is read but drawn only when a
  // scene material chooses a surface_detail; a height map alone draws Blinn bumps.
  if (material.heightMap && !material.normalMap) material.surfaceDetail = SurfaceDetail::BumpBlinn;
  if (material.heightMap && material.normalMap) {
    textures.warnings().push_back(objPath + ": material '" + material.name + "': height map '" +
                                  material.heightMap->path + "' is read but not drawn: the normal map beside it is "
                                  "(a scene material's \"surface_detail\" chooses a height-field method)");
  }
  if (material.heightMap && (material.heightScale < 0.0f || material.heightScale > kMaxHeightScale)) {
    textures.warnings().push_back(objPath + ": material '" + material.name + "': height map depth " +
                                  std::to_string(material.heightScale) + " (0.05 x -bm) clamped to [0, 1] uv units");
    material.heightScale = std::clamp(material.heightScale, 0.0f, kMaxHeightScale);
  }
  if (!std::isfinite(material.normalStrength) || !std::isfinite(material.heightScale)) {
    throw InputError(objPath + ": material '" + material.name + "': -bm is not a finite number");
  }
  return material;
}

// Ka, Kd and Ks in [0, kMaxColourValue] (as the scene file's colours), Ns finite and >= 0.
void requireValidMaterial(const std::string& path, const Material& material) {
  const std::pair<const char*, vec3> colours[] = {{"Ka", material.ka}, {"Kd", material.kd}, {"Ks", material.ks}};
  for (const auto& [key, colour] : colours) {
    for (int i = 0; i < 3; ++i) {
      if (!(colour[i] >= 0.0f && colour[i] <= kMaxColourValue)) {
        throw InputError(path + ": material '" + material.name + "' " + key + " must be in [0, " +
                         std::to_string(static_cast<int>(kMaxColourValue)) + "], got " + std::to_string(colour[i]));
      }
    }
  }
  if (!std::isfinite(material.shininess)) {
    throw InputError(path + ": material '" + material.name + "' has a non-finite Ns");
  }
  if (material.shininess < 0.0f) {
    throw InputError(path + ": material '" + material.name + "' Ns must be >= 0, got " +
                     std::to_string(material.shininess));
  }
}

// One mesh under construction, with its vertices welded by (v, vt, vn) index triple.
struct MeshBuilder {
  Mesh mesh;
  std::map<std::tuple<int, int, int>, std::uint32_t> vertexByIndices;
  std::vector<int> positionIndex;  // parallel to mesh.vertices: the OBJ 'v' it came from
  std::vector<bool> needsNormal;    // parallel to mesh.vertices: the OBJ gave no normal
};

}  // namespace

namespace {

// Line number (1-based) of the n-th (0-based) line starting with `keyword`, or 0.
long long lineOfNth(const std::string& text, const std::string& keyword, std::size_t n) {
  std::istringstream lines(text);
  std::string line;
  long long lineNumber = 0;
  std::size_t seen = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string first;
    if (tokens >> first && first == keyword && seen++ == n) return lineNumber;
  }
  return 0;
}

// The prescan checks every number with strtod, but tinyobjloader parses them itself and can
// still make inf or NaN of one strtod reads as finite: "0.0E39126" is 0 to strtod and
// 0 * 10^39126 = NaN to tinyobjloader (found by fuzzing). Whatever it produced is checked.
void checkFiniteAttributes(const std::string& path, const std::string& text, const tinyobj::attrib_t& attrib) {
  const struct {
    const std::vector<tinyobj::real_t>& values;
    std::size_t perLine;
    const char* keyword;
  } kinds[] = {{attrib.vertices, 3, "v"}, {attrib.texcoords, 2, "vt"}, {attrib.normals, 3, "vn"}};
  for (const auto& kind : kinds) {
    for (std::size_t i = 0; i < kind.values.size(); ++i) {
      if (std::isfinite(kind.values[i])) continue;
      const long long line = lineOfNth(text, kind.keyword, i / kind.perLine);
      throw InputError(path + ":" + std::to_string(line) + ": '" + kind.keyword +
                       "' has a number that reads as infinite or NaN (an exponent beyond float's range?)");
    }
  }
}

}  // namespace

ObjModel loadObj(const std::string& path, const ObjLimits& limits, const ObjReadOptions& read) {
  const std::size_t maxTriangles = limits.maxTriangles;
  std::string text = decodeText(readFileCapped(path, kMaxObjFileBytes, "OBJ file"), path);
  const ObjPrescan prescan = prescanObj(path, text, maxTriangles);
  const std::string skinWeightWarning = blankSkinWeightLines(path, text);
  const std::vector<NamedLine> usedMaterials = encodeNamesAfter(text, "usemtl");

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> sourceMaterials;
  std::string warning, error;
  MtlReader mtlReader(fs::path(path).parent_path(), read.readMtl);
  {
    StringBuffer buffer(text);
    std::istream stream(&buffer);
    if (!tinyobj::LoadObj(&attrib, &shapes, &sourceMaterials, &warning, &error, &stream, &mtlReader,
                          /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
      throw InputError(path + ": " + (error.empty() ? std::string("cannot parse the OBJ file") : oneLine(error)));
    }
  }
  // A missing MTL file, or a usemtl naming a material the MTL lacks, is only a warning to
  // tinyobjloader; the model would silently render white, so both are errors here. (A
  // usemtl in a file without any mtllib is common in exports and just means no material.)
  std::vector<std::string> warnings = std::move(mtlReader.warnings());
  if (!skinWeightWarning.empty()) warnings.push_back(skinWeightWarning);
  if (!mtlReader.firstFailure().empty()) {
    if (read.loadMaps) throw InputError(path + ": mtllib: " + mtlReader.firstFailure());
    warnings.push_back(path + ": mtllib: " + mtlReader.firstFailure() + " (the scene gives the node its own material)");
  }
  if (prescan.hasMtllib && read.readMtl && mtlReader.firstFailure().empty()) {
    std::set<std::string> defined;
    for (const tinyobj::material_t& m : sourceMaterials) defined.insert(decodeName(m.name));
    for (const NamedLine& used : usedMaterials) {
      if (defined.count(used.name) == 0) {
        throw InputError(path + ":" + std::to_string(used.line) + ": usemtl: material '" + used.name +
                         "' is not in the MTL file(s)");
      }
    }
  }

  checkFiniteAttributes(path, text, attrib);

  const AttributeCounts counts{static_cast<long long>(attrib.vertices.size() / 3),
                               static_cast<long long>(attrib.texcoords.size() / 2),
                               static_cast<long long>(attrib.normals.size() / 3)};

  TextureCache textures(path, prescan.mtlDirectory, limits.maxTextureBytes, read.loadMaps);
  std::vector<Material> materials;
  materials.reserve(sourceMaterials.size());
  for (const tinyobj::material_t& source : sourceMaterials) {
    materials.push_back(toMaterial(source, textures, path));
    requireValidMaterial(path, materials.back());
  }
  for (std::string& w : textures.warnings()) warnings.push_back(std::move(w));

  // Material id (-1 = none) -> mesh, in order of first use.
  std::map<int, std::size_t> builderByMaterial;
  std::vector<int> materialOfBuilder;
  std::vector<MeshBuilder> builders;
  std::size_t triangleCount = 0;
  // Area-weighted face normals summed per OBJ position, for corners without a normal:
  // summing per position (not per welded vertex) keeps uv seams smooth.
  std::vector<vec3> normalSumByPosition(static_cast<std::size_t>(counts.positions), vec3(0.0f));

  auto badIndex = [&]() {
    const long long line = findBadFaceLine(text, counts);
    return InputError(path + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                      ": a face references a vertex, uv or normal index outside the file's " +
                      std::to_string(counts.positions) + " v, " + std::to_string(counts.uvs) + " vt and " +
                      std::to_string(counts.normals) + " vn lines");
  };

  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t indexOffset = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const std::size_t cornerCount = shape.mesh.num_face_vertices[face];
      const std::size_t first = indexOffset;
      indexOffset += cornerCount;
      // Triangulation is on, so anything else is a degenerate face (a point or a line).
      if (cornerCount != 3) continue;
      if (first + 3 > shape.mesh.indices.size()) throw badIndex();
      if (++triangleCount > maxTriangles) {
        throw InputError(path + ": more than " + std::to_string(maxTriangles) + " triangles");
      }
      int materialId = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
      if (materialId < 0 || materialId >= static_cast<int>(materials.size())) materialId = -1;
      auto [found, inserted] = builderByMaterial.try_emplace(materialId, builders.size());
      if (inserted) {
        builders.emplace_back();
        materialOfBuilder.push_back(materialId);
      }
      MeshBuilder& builder = builders[found->second];

      for (std::size_t corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = shape.mesh.indices[first + corner];
        if (index.vertex_index < 0 || index.vertex_index >= counts.positions ||
            index.texcoord_index >= counts.uvs || index.normal_index >= counts.normals) {
          throw badIndex();
        }
      }
      std::array<vec3, 3> cornerPositions;
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const std::size_t at = 3 * static_cast<std::size_t>(shape.mesh.indices[first + corner].vertex_index);
        cornerPositions[corner] = toVec3(&attrib.vertices[at]);
      }
      // |cross| is twice the area: the sum is area-weighted.
      const vec3 areaNormal =
          glm::cross(cornerPositions[1] - cornerPositions[0], cornerPositions[2] - cornerPositions[0]);
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = shape.mesh.indices[first + corner];
        normalSumByPosition[static_cast<std::size_t>(index.vertex_index)] += areaNormal;
        const auto key = std::make_tuple(index.vertex_index, std::max(index.texcoord_index, -1),
                                         std::max(index.normal_index, -1));
        auto [vertexEntry, newVertex] =
            builder.vertexByIndices.try_emplace(key, static_cast<std::uint32_t>(builder.mesh.vertices.size()));
        if (newVertex) {
          Vertex vertex;
          vertex.posModel = toVec3(&attrib.vertices[3 * static_cast<std::size_t>(index.vertex_index)]);
          if (index.texcoord_index >= 0) {
            const std::size_t uvAt = 2 * static_cast<std::size_t>(index.texcoord_index);
            vertex.uv = vec2(attrib.texcoords[uvAt], attrib.texcoords[uvAt + 1]);
          } else {
            vertex.uv = vec2(0.0f);
          }
          const bool hasNormal = index.normal_index >= 0;
          if (hasNormal) {
            vertex.nModel = toVec3(&attrib.normals[3 * static_cast<std::size_t>(index.normal_index)]);
          }
          builder.mesh.vertices.push_back(vertex);
          builder.positionIndex.push_back(index.vertex_index);
          builder.needsNormal.push_back(!hasNormal);
        }
        builder.mesh.indices.push_back(vertexEntry->second);
      }
    }
  }
  if (builders.empty()) throw InputError(path + ": the OBJ file has no triangles (no 'f' lines with 3+ corners)");

  ObjModel model;
  model.warnings = std::move(warnings);
  for (std::size_t b = 0; b < builders.size(); ++b) {
    MeshBuilder& builder = builders[b];
    Mesh& mesh = builder.mesh;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      vec3& nModel = mesh.vertices[i].nModel;
      if (builder.needsNormal[i]) nModel = normalSumByPosition[static_cast<std::size_t>(builder.positionIndex[i])];
      nModel = safeNormalize(nModel, vec3(0.0f, 1.0f, 0.0f));
    }
    computeTangents(mesh);

    const int materialId = materialOfBuilder[b];
    model.meshes.push_back(std::move(mesh));
    if (materialId >= 0) {
      model.materials.push_back(materials[static_cast<std::size_t>(materialId)]);
      model.hasMaterial.push_back(true);
    } else {
      Material none;
      none.name = "";
      model.materials.push_back(none);
      model.hasMaterial.push_back(false);
    }
  }
  return model;
}

}  // namespace twr
