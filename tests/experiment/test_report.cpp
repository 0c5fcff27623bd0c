// The report's arithmetic: checked against the thesis's own printed tables
// (our summary rows computed from its position rows must give its summary
// rows) and against hand-computed statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/experiment/Report.hpp"
#include "app/experiment/ThesisTables.hpp"

using namespace simswift::experiment;

namespace {
std::vector<PositionStats> asStats(const std::vector<ThesisRow>& rows, int first, int last) {
  std::vector<PositionStats> out;
  for (const ThesisRow& r : rows)
    if (r.position >= first && r.position <= last)
      out.push_back({r.position, r.tests, r.found, r.not_found, r.total_s, r.avg_s, r.sd_s});
  return out;
}
}  // namespace

// Hand-computed: finds at 10, 20, 30 s of 4 tests: total 60, mean 20,
// population SD sqrt((100 + 0 + 100) / 3) = 8.165.
TEST(Report, PositionStatistics) {
  const PositionStats p = positionStats(3, 4, {10, 20, 30});
  EXPECT_EQ(p.found, 3);
  EXPECT_EQ(p.not_found, 1);
  EXPECT_DOUBLE_EQ(p.total_s, 60);
  EXPECT_DOUBLE_EQ(p.avg_s, 20);
  EXPECT_NEAR(p.sd_s, std::sqrt(200.0 / 3), 1e-12);
  // A single find has SD 0 (the thesis prints 0.00); none found: avg 0.
  EXPECT_DOUBLE_EQ(positionStats(4, 10, {100}).sd_s, 0);
  EXPECT_DOUBLE_EQ(positionStats(4, 5, {}).avg_s, 0);
}

// Every printed thesis average row (tables 5.3-5.8) is the plain mean of its
// position rows: recomputing with meanRows gives the printed numbers within
// the thesis's rounding (0.01, position rows being rounded themselves).
TEST(Report, SummaryRowsReproduceTheThesis) {
  int checked = 0;
  for (const ThesisTable& t : thesisTables()) {
    for (const ThesisSummaryRow& printed : t.averages) {
      const SummaryRow ours = meanRows(asStats(t.rows, printed.first, printed.last));
      SCOPED_TRACE("table " + t.number + " " + printed.label);
      EXPECT_NEAR(ours.tests, printed.tests, 0.005);
      EXPECT_NEAR(ours.found, printed.found, 0.005);
      EXPECT_NEAR(ours.not_found, printed.not_found, 0.005);
      EXPECT_NEAR(ours.total_s, printed.total_s, 0.011);
      EXPECT_NEAR(ours.avg_s, printed.avg_s, 0.011);
      EXPECT_NEAR(ours.sd_s, printed.sd_s, 0.011);
      ++checked;
    }
    // Each position row: Avg = Total / Found, Found + Not Found = Tests.
    for (const ThesisRow& r : t.rows) {
      EXPECT_EQ(r.found + r.not_found, r.tests) << t.number << " pos " << r.position;
      EXPECT_NEAR(r.avg_s, r.found ? r.total_s / r.found : 0, 0.006) << t.number << " pos " << r.position;
    }
  }
  EXPECT_EQ(checked, 10);  // 3 + 3 + 1 + 1 + 1 + 1
}

// The comparisons 5.9-5.12 as printed agree with the tables they compare.
TEST(Report, ThesisComparisonsMatchTheirTables) {
  ASSERT_EQ(thesisComparisons().size(), 4u);
  for (const ThesisComparison& c : thesisComparisons()) {
    for (size_t k = 0; k < c.tables.size(); ++k) {
      const ThesisTable* t = thesisTable(c.tables[k]);
      ASSERT_NE(t, nullptr);
      ASSERT_EQ(c.values.size(), t->rows.size());
      double sum = 0;
      for (size_t p = 0; p < t->rows.size(); ++p) {
        const double v = c.what == ThesisComparison::What::Found ? t->rows[p].found : t->rows[p].avg_s;
        EXPECT_NEAR(c.values[p][k], v, 1e-9) << c.number << " column " << k << " pos " << p + 1;
        sum += v;
      }
      if (c.what == ThesisComparison::What::Found) EXPECT_NEAR(c.bottom[k], sum, 1e-9) << c.number;
      else EXPECT_NEAR(c.bottom[k], sum / t->rows.size(), 0.011) << c.number;
    }
  }
}

TEST(Report, SummaryGroupsOfFive) {
  EXPECT_EQ(summaryGroups(10).size(), 2u);
  EXPECT_EQ(summaryGroups(10)[1].first, 5);
  EXPECT_EQ(summaryGroups(5).size(), 1u);
  EXPECT_EQ(summaryGroups(2).size(), 1u);
}
