// The JUnit XML with awkward text: a failure holding XML's special
// characters and control bytes (a launched program's message may) still
// passes the schema check (xmllint, a real consumer) and keeps the text.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/scenario_tests/JUnit.hpp"
#include "tests/support/Shell.hpp"

namespace {

using namespace simswift::scenario_tests;

TEST(JUnit, SpecialCharactersAreEscapedAndTheFileValidates) {
  EXPECT_EQ(xmlEscape("a<b>&\"c'\x01\td\n"), "a&lt;b&gt;&amp;&quot;c&apos;?\td\n");
  TestFile f;
  f.name = "t&t";
  f.source = "/x/<file>.yaml";
  TestSummary s;
  s.name = "a\"b";
  s.runs = 5;
  s.required = 0.5;
  s.hi = 0.43;
  s.verdict = TestSummary::Verdict::Fails;
  RunResult r;
  r.test = "a\"b";
  r.failure = "robot program failed: t19p2: <exit 3> & \"quoted\" \x02 'x'";
  s.failures.push_back(r);
  TestOptions opt;
  const std::string xml = junitXml(f, opt, {s});
  EXPECT_NE(xml.find("robot program failed: t19p2: &lt;exit 3&gt; &amp; &quot;quoted&quot; ? &apos;x&apos;"),
            std::string::npos)
      << xml;
  const std::string dir = std::string(SIMSWIFT_BINARY_DIR) + "/scenario_tests_tmp/junit_escape";
  std::filesystem::create_directories(dir);
  simswift::testing::writeText(dir + "/j.xml", xml);
  const auto lint = simswift::testing::shell("xmllint --noout --schema " + std::string(SIMSWIFT_SOURCE_DIR) +
                                             "/tests/scenario_tests/junit.xsd " + dir + "/j.xml");
  EXPECT_EQ(lint.code, 0) << lint.output << xml;
}

}  // namespace
