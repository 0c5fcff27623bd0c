// The CSV dialect of the experiment's files (results.csv, cells.csv): RFC
// 4180 quoting, one record per line (no field holds a newline after
// csvField, which quotes it; readers split lines first).
#pragma once

#include <string>
#include <vector>

namespace simswift::experiment {

// A CSV field: quoted ("" for a quote) if it holds a comma, quote or newline.
std::string csvField(const std::string& s);
// Fields of one CSV line; a quoted field may hold commas and "" quotes; a
// trailing '\r' is dropped.
std::vector<std::string> splitCsv(const std::string& line);

}  // namespace simswift::experiment
