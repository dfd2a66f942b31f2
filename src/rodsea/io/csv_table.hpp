#pragma once
// A CSV table of named cells whose columns are the union of its rows' names, in order of first
// appearance: the summary tables of `analyze --table` and of `campaign collect`.
#include <map>
#include <string>
#include <vector>

namespace rodsea {

// RFC 4180: a field with a comma, quote or newline is quoted, quotes doubled.
std::string csv_quoted(const std::string& text);

class CsvTable {
  public:
    using Row = std::map<std::string, std::string>;
    explicit CsvTable(std::vector<std::string> first_columns = {})
        : columns_(std::move(first_columns)) {}
    // Sets a cell (already quoted where it may need it), adding its column if new.
    void set(Row& row, const std::string& column, const std::string& value);
    void add(Row row) { rows_.push_back(std::move(row)); }
    // "# <comment>", the header, then the rows; a missing cell is empty.
    std::string text(const std::string& comment) const;

  private:
    std::vector<std::string> columns_;
    std::vector<Row> rows_;
};

}  // namespace rodsea
