// A recorded CSV file as named columns of numbers: one header line of
// column names, then one row per sample. Separators: comma, semicolon or tab
// (the header's first one). Start-up only (allocates).
#pragma once

#include <string>
#include <vector>

namespace handover::perception::recording {

struct RecordedTable {
  std::string path;
  std::vector<std::string> names;            ///< header, in file order
  std::vector<std::vector<double>> columns;  ///< columns[c][row]

  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
  /// The column called `name`; throws InputError naming the file, the
  /// column and `context` (the mapping key that asked for it) if absent.
  const std::vector<double>& column(const std::string& name, const std::string& context) const;
};

/// Reads a table; throws InputError "file:line: ..." on a row with another
/// number of fields, a field that is not a finite number, or no rows.
RecordedTable readRecordedTable(const std::string& path);

}  // namespace handover::perception::recording
