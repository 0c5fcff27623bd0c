// The thesis's own figures for the find-ball experiment (chapter 5),
// transcribed once here with their table numbers, for the report's
// "thesis" columns:
//   5.3 / 5.4   simulation, 3 robots, 2016 / 2017 component, positions 1-10 x 10
//   5.5 / 5.6   one real NAO V5, 2016 / 2017, positions 1-5 x 5
//   5.7 / 5.8   three real NAO V5s, 2016 / 2017, positions 1-5 x 5
//   5.9 - 5.12  the comparisons (found counts and average seconds per position)
// Seconds are the thesis's; "Avg." is Total / Found (0.00 when none was
// found) and the summary rows are the plain mean of the position rows.
#pragma once

#include <string>
#include <vector>

namespace simswift::experiment {

struct ThesisRow {
  int position = 0;
  int tests = 0, found = 0, not_found = 0;
  double total_s = 0, avg_s = 0, sd_s = 0;
};

// A summary row as printed: label and the six columns (sums for "Total"
// rows, means for "Average" rows; a Total row prints only the counts).
struct ThesisSummaryRow {
  std::string label;           // "Sub-Average (1-5)", "Grand Average", "Average", ...
  int first = 1, last = 10;    // positions it summarises
  double tests = 0, found = 0, not_found = 0, total_s = 0, avg_s = 0, sd_s = 0;
};

struct ThesisTable {
  std::string number;          // "5.3"
  std::string component;       // "2016" or "2017"
  int robots = 3;
  bool real = false;           // NAO V5s (true) or simulation
  std::vector<ThesisRow> rows;
  std::vector<ThesisSummaryRow> averages;  // the printed average rows
};

// A comparison table (5.9-5.12): per position, one value per source table.
struct ThesisComparison {
  std::string number;            // "5.9"
  std::string title;
  enum class What { Found, AvgSeconds } what = What::Found;
  std::vector<std::string> tables;          // source tables, column order
  std::vector<std::vector<double>> values;  // [position-1][column], as printed
  std::vector<double> bottom;               // "Total:" (found) or "Average:" (seconds) row
};

// Table 5.2: the ball positions (mm, field frame) and table 5.1: the start
// points of robots 2, 3 and 4 (mm). The shipped experiment files must agree
// (tests/experiment), and the report marks positions that do not.
struct ThesisPoint {
  int number = 0;
  double x_mm = 0, y_mm = 0;
};
const std::vector<ThesisPoint>& thesisBallPositions();  // table 5.2
const std::vector<ThesisPoint>& thesisStartPoints();    // table 5.1, by robot number

const std::vector<ThesisTable>& thesisTables();
const ThesisTable* thesisTable(const std::string& number);  // null if unknown
const std::vector<ThesisComparison>& thesisComparisons();

}  // namespace simswift::experiment
