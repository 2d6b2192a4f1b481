// The GLSL in shaders/ and its C++ twins, held to docs/shading.md's table of twins: every GLSL
// function has a row, every row names functions that exist on both sides, and no GLSL function
// grows past what a reader takes in at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr int kMaxGlslFunctionLines = 80;  // signature to closing brace
constexpr int kMaxCppFunctionLines = 80;   // template line (if any) to closing brace
constexpr int kMaxPhongMainLines = 60;

fs::path sourceDir() { return fs::path(TWINRASTER_SOURCE_DIR); }

std::vector<std::string> linesOf(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

struct GlslFunction {
  std::string file;  // relative to the source folder, "shaders/phong.frag"
  std::string name;
  int firstLine = 0;  // 1-based, the signature
  int lineCount = 0;  // the longest of its definitions (a function defined per #ifdef branch)
};

// A definition starts at column 0 with "type name(" and runs to the brace that closes it.
int definitionLength(const std::vector<std::string>& lines, std::size_t first) {
  int depth = 0;
  bool opened = false;
  for (std::size_t i = first; i < lines.size(); ++i) {
    for (char c : lines[i]) {
      if (c == '{') {
        ++depth;
        opened = true;
      } else if (c == '}') {
        --depth;
      }
    }
    if (opened && depth == 0) return static_cast<int>(i - first + 1);
  }
  return static_cast<int>(lines.size() - first);
}

std::vector<GlslFunction> glslFunctions() {
  static const std::regex signature(R"(^([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*\()");
  static const std::set<std::string> notTypes = {"return", "else", "uniform", "in", "out", "layout", "struct", "const"};
  std::vector<GlslFunction> functions;
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(sourceDir() / "shaders")) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& path : files) {
    const std::vector<std::string> lines = linesOf(path);
    std::map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::smatch m;
      if (!std::regex_search(lines[i], m, signature) || notTypes.count(m[1].str())) continue;
      const int length = definitionLength(lines, i);
      const std::string name = m[2].str();
      if (index.count(name)) {
        GlslFunction& existing = functions[index[name]];
        existing.lineCount = std::max(existing.lineCount, length);
        continue;
      }
      index[name] = functions.size();
      functions.push_back({"shaders/" + path.filename().string(), name, static_cast<int>(i + 1), length});
    }
  }
  return functions;
}

struct TwinRow {
  std::string glslFile, glslName, cppFile, cppName, note;
  int docLine = 0;
};

// docs/shading.md's rows: | `shaders/FILE:function` | `softrender/FILE:function` | note |
std::vector<TwinRow> twinRows() {
  static const std::regex row(R"(^\|\s*`([^`:]+):(\w+)`\s*\|\s*`([^`:]+)(?::(\w+))?`\s*\|\s*(.*?)\s*\|\s*$)");
  std::vector<TwinRow> rows;
  const std::vector<std::string> lines = linesOf(sourceDir() / "docs" / "shading.md");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!std::regex_match(lines[i], m, row)) continue;
    rows.push_back({m[1].str(), m[2].str(), m[3].str(), m[4].str(), m[5].str(), static_cast<int>(i + 1)});
  }
  return rows;
}

// A C++ definition: a line where the name follows a return type ("... Vec3L<L> nameLanes(") and
// nothing marks a call (an assignment, a return, a member access, an open call before it); a
// declaration ending in ';' does not count.
bool definesFunction(const fs::path& path, const std::string& name) {
  const std::regex definition("^[^=;(.\"]*[\\w>*&]\\s+" + name + "\\s*\\(");
  for (const std::string& line : linesOf(path)) {
    const std::size_t text = line.find_first_not_of(" \t");
    if (text == std::string::npos || line.compare(text, 2, "//") == 0 || line.compare(text, 7, "return ") == 0) continue;
    if (!std::regex_search(line, definition)) continue;
    const std::size_t end = line.find_last_not_of(" \t");
    if (line[end] != ';') return true;
  }
  return false;
}

struct CppFunction {
  std::string file;   // relative to the source folder
  std::string name;
  int firstLine = 0;  // 1-based: the template line, or the signature without one
  int lineCount = 0;
};

// The functions defined at column 0 of one C++ file: a line that names a function after its
// return type and opens a body before any ';' (a declaration, a using, a call at namespace
// scope do not count). Members and lambdas, which are indented, belong to what holds them.
std::vector<CppFunction> cppFunctionsOf(const fs::path& path, const std::string& shownAs) {
  static const std::regex signature(R"(^(?:[A-Za-z_][\w:<>,]*[\s*&]+)+\(?([A-Za-z_]\w*)\)?\s*\()");
  static const std::set<std::string> notFunctions = {"if", "for", "while", "switch", "return", "sizeof"};
  std::vector<CppFunction> functions;
  const std::vector<std::string> lines = linesOf(path);
  const auto notASignature = [](const std::string& line) {
    if (line.empty() || line[0] == '#' || line[0] == '/' || line[0] == ' ' || line[0] == '}') return true;
    for (const char* word : {"template", "struct", "using", "namespace", "class", "enum"}) {
      if (line.rfind(word, 0) == 0) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (notASignature(lines[i]) || !std::regex_search(lines[i], m, signature) || notFunctions.count(m[1].str())) continue;
    std::size_t end = i;  // the declaration's last line: a ';' before any '{' is no definition
    while (end < lines.size() && lines[end].find('{') == std::string::npos && lines[end].find(';') == std::string::npos) {
      ++end;
    }
    if (end == lines.size() || lines[end].find('{') == std::string::npos) continue;
    const bool templated = i > 0 && lines[i - 1].rfind("template", 0) == 0;
    const int length = definitionLength(lines, i);
    functions.push_back({shownAs, m[1].str(), static_cast<int>(templated ? i : i + 1), length + (templated ? 1 : 0)});
    i += static_cast<std::size_t>(length) - 1;
  }
  return functions;
}

// The shading sources: every softrender/*-inl.h (the one C++ source of the shaders' steps),
// shade.h and shade.cpp.
std::vector<CppFunction> cppShadingFunctions() {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(sourceDir() / "softrender")) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 6 && name.compare(name.size() - 6, 6, "-inl.h") == 0) files.push_back(entry.path());
  }
  files.push_back(sourceDir() / "softrender" / "shade.h");
  files.push_back(sourceDir() / "softrender" / "shade.cpp");
  std::sort(files.begin(), files.end());
  std::vector<CppFunction> functions;
  for (const fs::path& path : files) {
    for (CppFunction& f : cppFunctionsOf(path, "softrender/" + path.filename().string())) functions.push_back(f);
  }
  return functions;
}

TEST(ShadingTwins, TheShadersAndTheTableAreRead) {
  // Guards the parsers: a table or a shader folder read as empty would pass every check below.
  EXPECT_GE(glslFunctions().size(), 60u);
  EXPECT_GE(twinRows().size(), 60u);
}

TEST(ShadingTwins, EveryGlslFunctionHasATwinListed) {
  std::set<std::string> listed;
  for (const TwinRow& row : twinRows()) listed.insert(row.glslFile + ":" + row.glslName);
  for (const GlslFunction& f : glslFunctions()) {
    EXPECT_TRUE(listed.count(f.file + ":" + f.name))
        << f.file << ":" << f.firstLine << ": " << f.name
        << " has no row in docs/shading.md's table of twins (GLSL file:function -> C++ file:function)";
  }
}

TEST(ShadingTwins, EveryListedTwinExistsOnBothSides) {
  std::set<std::string> glsl;
  for (const GlslFunction& f : glslFunctions()) glsl.insert(f.file + ":" + f.name);
  for (const TwinRow& row : twinRows()) {
    const std::string where = "docs/shading.md:" + std::to_string(row.docLine) + ": ";
    EXPECT_TRUE(glsl.count(row.glslFile + ":" + row.glslName))
        << where << row.glslFile << " defines no GLSL function " << row.glslName;
    const fs::path cpp = sourceDir() / row.cppFile;
    if (!fs::exists(cpp)) {
      ADD_FAILURE() << where << "no file " << row.cppFile;
      continue;
    }
    if (row.cppName.empty()) {
      // Only a GL-side probe has no C++ function; the row says so.
      EXPECT_EQ(row.note.rfind("GL only", 0), 0u) << where << row.glslName << " names no C++ function";
      continue;
    }
    EXPECT_TRUE(definesFunction(cpp, row.cppName))
        << where << row.cppFile << " defines no function " << row.cppName << " (the twin of " << row.glslName << ")";
  }
}

// The twins carry the GLSL's names (the namespace, not a suffix, tells the lane types apart):
// a row whose names differ says why in its note (a shader's main(), a step the C++ shares).
TEST(ShadingTwins, TwinsShareTheGlslNameOrTheRowSaysWhy) {
  int sameName = 0;
  for (const TwinRow& row : twinRows()) {
    if (row.cppName.empty()) continue;  // GL only, checked above
    const std::string where = "docs/shading.md:" + std::to_string(row.docLine) + ": ";
    if (row.cppName == row.glslName) {
      ++sameName;
      continue;
    }
    EXPECT_FALSE(row.note.empty() || row.note.rfind("same name", 0) == 0)
        << where << row.glslName << " -> " << row.cppName << ": give the C++ twin the GLSL's name, or say why not";
    EXPECT_EQ(row.cppName.find("Lanes"), std::string::npos) << where << row.cppName << ": a suffix, not the GLSL's name";
  }
  EXPECT_GE(sameName, 60) << "most twins share their GLSL function's name";
}

TEST(ShadingTwins, NoGlslFunctionIsLongerThanAReaderTakesIn) {
  for (const GlslFunction& f : glslFunctions()) {
    EXPECT_LE(f.lineCount, kMaxGlslFunctionLines) << f.file << ":" << f.firstLine << ": " << f.name << " is "
                                                  << f.lineCount << " lines; split it into named steps";
  }
}

TEST(ShadingTwins, NoCppShadingFunctionIsLongerThanAReaderTakesIn) {
  const std::vector<CppFunction> functions = cppShadingFunctions();
  EXPECT_GE(functions.size(), 150u);  // the scanner found the sources' functions at all
  for (const CppFunction& f : functions) {
    EXPECT_LE(f.lineCount, kMaxCppFunctionLines) << f.file << ":" << f.firstLine << ": " << f.name << " is "
                                                 << f.lineCount << " lines; split it into named steps";
  }
}

TEST(ShadingTwins, PhongMainIsTheListOfNamedSteps) {
  bool found = false;
  for (const GlslFunction& f : glslFunctions()) {
    if (f.file != "shaders/phong.frag" || f.name != "main") continue;
    found = true;
    EXPECT_LE(f.lineCount, kMaxPhongMainLines) << "shaders/phong.frag:" << f.firstLine << ": main() is " << f.lineCount
                                               << " lines";
  }
  EXPECT_TRUE(found) << "shaders/phong.frag has no main()";
}

// The checks can fail: a renamed C++ twin is missed, and a function nobody listed is found.
TEST(ShadingTwins, TheDefinitionCheckTellsADefinitionFromACall) {
  const fs::path shade = sourceDir() / "softrender" / "shade-inl.h";
  EXPECT_TRUE(definesFunction(shade, "surfaceFrame"));
  EXPECT_FALSE(definesFunction(shade, "surfaceFrameRenamed"));
  // Called there, defined in environment-inl.h.
  EXPECT_FALSE(definesFunction(shade, "environmentDiffuse"));
}

// The length check counts a definition from its template line to its closing brace, skips
// declarations and members, and so finds a function grown too long.
TEST(ShadingTwins, TheCppLengthCheckFindsAFunctionGrownTooLong) {
  const fs::path path = fs::temp_directory_path() / "twinraster_twin_length_check-inl.h";
  {
    std::ofstream out(path);
    out << "template <typename L>\nTWR_LANE_INLINE Vec3L<L> declaredOnly(const L& x);\n";
    out << "struct Holder {\n  int member() {\n    return 1;\n  }\n};\n";
    out << "template <typename L>\nTWR_LANE_INLINE Vec3L<L> grownLanes(const L& x,\n                                  const L& y) {\n";
    for (int i = 0; i < 85; ++i) out << "  step(" << i << ");\n";
    out << "}\ninline int shortOne() { return 0; }\n";
  }
  const std::vector<CppFunction> functions = cppFunctionsOf(path, "test");
  fs::remove(path);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].name, "grownLanes");
  EXPECT_EQ(functions[0].firstLine, 8);
  EXPECT_EQ(functions[0].lineCount, 2 + 1 + 85 + 1);  // template, two signature lines, body, brace
  EXPECT_GT(functions[0].lineCount, kMaxCppFunctionLines);
  EXPECT_EQ(functions[1].name, "shortOne");
  EXPECT_EQ(functions[1].lineCount, 1);
}

}  // namespace
