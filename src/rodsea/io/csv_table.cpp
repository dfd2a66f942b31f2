#include "rodsea/io/csv_table.hpp"

#include <algorithm>
#include <sstream>

namespace rodsea {

std::string csv_quoted(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q(1, '"');
    for (char c : text) {
        q.push_back(c);
        if (c == '"') q.push_back('"');
    }
    q.push_back('"');
    return q;
}

void CsvTable::set(Row& row, const std::string& column, const std::string& value) {
    if (std::find(columns_.begin(), columns_.end(), column) == columns_.end())
        columns_.push_back(column);
    row[column] = value;
}

std::string CsvTable::text(const std::string& comment) const {
    std::ostringstream out;
    out << "# " << comment << "\n";
    for (std::size_t c = 0; c < columns_.size(); ++c)
        out << (c ? "," : "") << columns_[c];
    out << "\n";
    for (const Row& row : rows_) {
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            const auto it = row.find(columns_[c]);
            out << (c ? "," : "") << (it == row.end() ? "" : it->second);
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace rodsea
