// The suite (compare/suite.h, compare/suite_page.h): folder names, how a compare's end becomes
// a case, the exit code, the JUnit file and the index page, and runSuite itself over a stand-in
// program (a shell script that ends as compare would: within, over, bad input, a crash), so
// these tests need no renderer.
#include "compare/suite.h"
#include "compare/suite_page.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>

namespace twr {
namespace {

namespace fs = std::filesystem;

SuiteCase caseOf(const std::string& scene, SuiteOutcome outcome, const std::string& message = "") {
  SuiteCase c;
  c.scene = scene;
  c.dir = suiteCaseDirs({scene})[0];
  c.outcome = outcome;
  c.message = message;
  c.exitCode = outcome == SuiteOutcome::Passed ? 0 : outcome == SuiteOutcome::Failed ? 1 : 2;
  c.seconds = 1.25;
  if (outcome != SuiteOutcome::Error) {
    c.metrics = {{"max_abs_diff", 2}, {"over_1_pct", 0.05}, {"coverage_mismatch", 0}, {"cpu_ms", 3.5}, {"gl_ms", 4.0}};
  }
  return c;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Suite, CaseFoldersAreTheStemsSanitizedAndNumberedWhenRepeated) {
  const std::vector<std::string> dirs =
      suiteCaseDirs({"assets/scenes/default.json", "other/default.json", "a b&c.json", "/x/..", "shadow.v2.json",
                     "default.json"});
  ASSERT_EQ(dirs.size(), 6u);
  EXPECT_EQ(dirs[0], "default");
  EXPECT_EQ(dirs[1], "default-2");
  EXPECT_EQ(dirs[2], "a_b_c");
  EXPECT_EQ(dirs[3], "scene");  // never a folder that climbs out of the suite's
  EXPECT_EQ(dirs[4], "shadow.v2");
  EXPECT_EQ(dirs[5], "default-3");
}

TEST(Suite, AFolderStandsForTheJsonFilesInItSorted) {
  const fs::path dir = fs::path(testing::TempDir()) / "suite_scenes";
  fs::remove_all(dir);
  fs::create_directories(dir / "empty");
  for (const char* name : {"b.json", "a.json", "notes.txt"}) std::ofstream(dir / name) << "{}";
  std::vector<std::string> warnings;
  const std::vector<std::string> scenes =
      suiteScenesFrom({dir.string(), "missing.json", (dir / "empty").string()}, warnings);
  ASSERT_EQ(scenes.size(), 3u);
  EXPECT_EQ(scenes[0], (dir / "a.json").string());
  EXPECT_EQ(scenes[1], (dir / "b.json").string());
  EXPECT_EQ(scenes[2], "missing.json");  // kept: it becomes an error case with compare's message
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("no .json scene"), std::string::npos);
}

TEST(Suite, ExitCodesBecomeOutcomesWithCompareMessages) {
  SuiteCase passed, over, bad, crashed;
  classifySuiteCase(passed, 0, 0, "");
  EXPECT_EQ(passed.outcome, SuiteOutcome::Passed);
  classifySuiteCase(over, 1, 1 << 8,
                    "twinraster: note: x\ntwinraster: threshold exceeded: max_abs_diff 9 > 3\n"
                    "twinraster: threshold exceeded: over_1_pct 2 > 0.1\n");
  EXPECT_EQ(over.outcome, SuiteOutcome::Failed);
  EXPECT_EQ(over.message, "max_abs_diff 9 > 3; over_1_pct 2 > 0.1");
  classifySuiteCase(bad, 2, 2 << 8, "twinraster: error: bad.json:3: expected '}'\n");
  EXPECT_EQ(bad.outcome, SuiteOutcome::Error);
  EXPECT_EQ(bad.message, "bad.json:3: expected '}'");
  classifySuiteCase(crashed, -1, SIGSEGV, "rendering\n");
  EXPECT_EQ(crashed.outcome, SuiteOutcome::Error);
  EXPECT_EQ(crashed.message, "compare ended by signal 11: rendering");
}

TEST(Suite, ExitCodeIsTwoForAnyErrorElseOneForAnyFailure) {
  EXPECT_EQ(suiteExitCode({}), 0);
  EXPECT_EQ(suiteExitCode({caseOf("a", SuiteOutcome::Passed)}), 0);
  EXPECT_EQ(suiteExitCode({caseOf("a", SuiteOutcome::Passed), caseOf("b", SuiteOutcome::Failed)}), 1);
  EXPECT_EQ(suiteExitCode({caseOf("a", SuiteOutcome::Error), caseOf("b", SuiteOutcome::Failed)}), 2);
}

TEST(Suite, XmlEscapingReplacesWhatXmlForbids) {
  EXPECT_EQ(escapeXml("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
  EXPECT_EQ(escapeXml(std::string("x\x01y\tz\n")), "x\xEF\xBF\xBDy\tz\n");
}

TEST(Suite, JUnitHasATestcasePerSceneWithFailuresAndErrorsCounted) {
  std::vector<SuiteCase> cases = {caseOf("ok.json", SuiteOutcome::Passed),
                                  caseOf("over.json", SuiteOutcome::Failed, "max_abs_diff 9 > 3"),
                                  caseOf("bad<1>.json", SuiteOutcome::Error, "bad<1>.json:3: expected '}'")};
  cases[2].stderrText = "twinraster: error: bad<1>.json:3: expected '}'\n";
  const std::string xml = junitXml(cases, 12.5);
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0), 0u);
  EXPECT_NE(xml.find("tests=\"3\" failures=\"1\" errors=\"1\" time=\"12.500\""), std::string::npos);
  EXPECT_EQ(count(xml, "<testcase "), 3u);
  EXPECT_NE(xml.find("name=\"ok.json\" time=\"1.250\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<failure type=\"threshold\" message=\"max_abs_diff 9 &gt; 3\">"), std::string::npos);
  EXPECT_NE(xml.find("<error type=\"bad_input\" message=\"bad&lt;1&gt;.json:3: expected &apos;}&apos;\">"),
            std::string::npos);
  EXPECT_EQ(count(xml, "<failure "), 1u);
  EXPECT_EQ(count(xml, "<error "), 1u);
  EXPECT_EQ(count(xml, "</testcase>"), 2u);  // the passed case closes itself
}

TEST(Suite, IndexLinksEachRunSceneAndShowsNaWhereThereAreNoMetrics) {
  const std::vector<SuiteCase> cases = {caseOf("a/default.json", SuiteOutcome::Passed),
                                        caseOf("bad.json", SuiteOutcome::Error, "bad.json: no such file")};
  const std::string page = suiteIndexHtml(cases, 3.0);
  EXPECT_NE(page.find("<a href=\"default/index.html\">default</a><div class=\"small wrap\">a/default.json</div>"),
            std::string::npos);
  EXPECT_NE(page.find("src=\"default/cpu.png\""), std::string::npos);
  EXPECT_NE(page.find("src=\"default/page_heat.png\""), std::string::npos);
  EXPECT_EQ(page.find("bad/index.html"), std::string::npos);  // an error case has no page to open
  EXPECT_NE(page.find("bad.json: no such file"), std::string::npos);
  EXPECT_NE(page.find("<td data-value=\"\">n/a</td>"), std::string::npos);
  EXPECT_NE(page.find("1 within targets, 0 over them, 1 bad input"), std::string::npos);
  EXPECT_EQ(count(page, "th class=\"sort"), 7u);
}

TEST(Suite, JsonSummaryCountsTheCasesAndKeepsTheHeadlineMetrics) {
  const nlohmann::json j = suiteJson({caseOf("a.json", SuiteOutcome::Passed), caseOf("b.json", SuiteOutcome::Failed)}, 2.0);
  EXPECT_EQ(j["scenes"], 2);
  EXPECT_EQ(j["passed"], 1);
  EXPECT_EQ(j["failed"], 1);
  EXPECT_EQ(j["exit_code"], 1);
  EXPECT_EQ(j["cases"][1]["outcome"], "failed");
  EXPECT_EQ(j["cases"][0]["max_abs_diff"], 2);
}

// runSuite over a script that ends as compare would for the scene it is given.
TEST(Suite, RunsEveryCaseInItsOwnProcessAndKeepsTheirOrder) {
  const fs::path dir = fs::path(testing::TempDir()) / "suite_run";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path script = dir / "fake_compare.sh";
  std::ofstream(script) << "#!/bin/sh\n"
                           "# argv: compare SCENE --out-dir DIR --html ...\n"
                           "case \"$2\" in\n"
                           "  ok*) echo '{\"max_abs_diff\": 1}' > \"$4/metrics.json\"; exit 0 ;;\n"
                           "  over*) echo '{\"max_abs_diff\": 9}' > \"$4/metrics.json\";\n"
                           "         echo 'twinraster: threshold exceeded: max_abs_diff 9 > 3' >&2; exit 1 ;;\n"
                           "  bad*) echo \"twinraster: error: $2: no such file\" >&2; exit 2 ;;\n"
                           "  crash*) kill -SEGV $$ ;;\n"
                           "esac\n";
  fs::permissions(script, fs::perms::owner_all);
  SuiteOptions options;
  options.outDir = (dir / "out").string();
  options.jobs = 3;
  options.program = script.string();
  options.compareArgs = {"--targets"};
  int calls = 0, lastEnded = 0;
  const std::vector<std::string> scenes = {"ok1.json", "over.json", "bad.json", "crash.json", "ok2.json"};
  const std::vector<SuiteCase> cases = runSuite(scenes, options, [&](const SuiteCase&, int ended, int total) {
    ++calls;
    EXPECT_EQ(total, 5);
    EXPECT_EQ(ended, lastEnded + 1);
    lastEnded = ended;
  });
  EXPECT_EQ(calls, 5);
  ASSERT_EQ(cases.size(), 5u);
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(cases[i].scene, scenes[i]);
  EXPECT_EQ(cases[0].outcome, SuiteOutcome::Passed);
  EXPECT_EQ(cases[0].metrics["max_abs_diff"], 1);
  EXPECT_EQ(cases[1].outcome, SuiteOutcome::Failed);
  EXPECT_EQ(cases[1].message, "max_abs_diff 9 > 3");
  EXPECT_EQ(cases[2].outcome, SuiteOutcome::Error);
  EXPECT_EQ(cases[2].message, "bad.json: no such file");
  EXPECT_TRUE(cases[2].metrics.is_null());
  EXPECT_EQ(cases[3].outcome, SuiteOutcome::Error);
  EXPECT_EQ(cases[3].message, "compare ended by signal 11");
  EXPECT_EQ(cases[4].outcome, SuiteOutcome::Passed);
  EXPECT_TRUE(fs::exists(dir / "out" / "ok1" / "stderr.txt"));
  EXPECT_EQ(suiteExitCode(cases), 2);
}

TEST(Suite, AProgramThatCannotStartIsAnErrorCase) {
  const fs::path dir = fs::path(testing::TempDir()) / "suite_nostart";
  fs::remove_all(dir);
  SuiteOptions options;
  options.outDir = dir.string();
  options.program = (dir / "no_such_program").string();
  const std::vector<SuiteCase> cases = runSuite({"a.json"}, options, nullptr);
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].outcome, SuiteOutcome::Error);
  EXPECT_NE(cases[0].message.find("cannot start"), std::string::npos) << cases[0].message;
}

}  // namespace
}  // namespace twr
