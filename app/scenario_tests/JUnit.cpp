#include "app/scenario_tests/JUnit.hpp"

#include <cstdio>
#include <sstream>

#include "app/experiment/Trial.hpp"
#include "app/scenario_tests/TestReport.hpp"

namespace simswift::scenario_tests {

std::string xmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') o += '?';
        else o += c;
    }
  }
  return o;
}

namespace {

std::string seconds3(double s) { return experiment::fixed(s, 3); }

}  // namespace

std::string junitXml(const TestFile& f, const TestOptions& opt, const std::vector<TestSummary>& tests) {
  int failures = 0;
  double wall = 0;
  for (const TestSummary& s : tests) {
    failures += s.verdict != TestSummary::Verdict::Passes || s.regressed;
    wall += s.wall_s;
  }
  const std::string n = std::to_string(tests.size()), fl = std::to_string(failures);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << "<testsuites name=\"" << xmlEscape(f.name) << "\" tests=\"" << n << "\" failures=\"" << fl
    << "\" errors=\"0\" time=\"" << seconds3(wall) << "\">\n";
  x << "  <testsuite name=\"" << xmlEscape(f.name) << "\" tests=\"" << n << "\" failures=\"" << fl
    << "\" errors=\"0\" skipped=\"0\" time=\"" << seconds3(wall) << "\">\n";
  x << "    <properties>\n";
  x << "      <property name=\"file\" value=\"" << xmlEscape(f.source) << "\"/>\n";
  x << "      <property name=\"form\" value=\"" << (opt.short_form ? "short" : "full") << "\"/>\n";
  x << "      <property name=\"seed\" value=\"" << (opt.has_seed ? opt.seed : f.seed) << "\"/>\n";
  if (!opt.baseline.empty()) x << "      <property name=\"baseline\" value=\"" << xmlEscape(opt.baseline) << "\"/>\n";
  x << "    </properties>\n";
  for (const TestSummary& s : tests) {
    x << "    <testcase name=\"" << xmlEscape(s.name) << "\" classname=\"simswift." << xmlEscape(f.name)
      << "\" time=\"" << seconds3(s.wall_s) << "\"";
    const bool bad = s.verdict != TestSummary::Verdict::Passes || s.regressed;
    if (!bad) {
      x << "/>\n";
      continue;
    }
    // The verdict first; a passing test that regressed: "regression".
    const std::string type = s.verdict == TestSummary::Verdict::Fails       ? "fails"
                             : s.verdict == TestSummary::Verdict::Undecided ? "undecided"
                                                                             : "regression";
    x << ">\n      <failure type=\"" << type << "\" message=\"" << xmlEscape(verdictLine(s)) << "\">"
      << xmlEscape(failureText(f, opt, s)) << "</failure>\n";
    x << "    </testcase>\n";
  }
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

}  // namespace simswift::scenario_tests
