#pragma once
// The config between the TOML text and the RunPlan: every key that was given (or, after
// resolution, every key in force) with its value, keyed as in the file. Parsing, resolution and
// writing the resolved TOML all work on this, so that none of them needs toml++ but the reader.
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace rodsea::config {

// real, integer, string, array of strings (the names of a collision pair).
using Value = std::variant<double, std::int64_t, std::string, std::vector<std::string>>;

struct Entry {
    Value value;
    long line = 0;  // where it was given in the source; 0 when it is a default
};

// One table of the file ([drive]) or one element of an array of tables ([[species]]).
struct TableValues {
    std::string path;  // as error messages name it: "drive", "species[1]"
    long line = 0;
    std::map<std::string, Entry, std::less<>> entries;

    bool has(std::string_view key) const { return entries.find(key) != entries.end(); }
    const Value& at(std::string_view key) const { return entries.find(key)->second.value; }
    double real(std::string_view key) const { return std::get<double>(at(key)); }
    std::int64_t integer(std::string_view key) const { return std::get<std::int64_t>(at(key)); }
    const std::string& text(std::string_view key) const { return std::get<std::string>(at(key)); }
    std::string key_path(std::string_view key) const { return path + "." + std::string(key); }
    // " (demo.toml line 3)" when the key was given in a file, else "".
    std::string where(std::string_view key, const std::string& source) const;
};

struct ConfigValues {
    std::string source;  // the file or string's name, for messages
    // By table path as in the schema ("drive", "species", "collisions.pair"); a plain table has
    // one element, an array of tables one per element.
    std::map<std::string, std::vector<TableValues>, std::less<>> tables;
    // After resolution: the value each unused alternative key would have for the same plan
    // ("box.side_in_polar_lengths" -> 56), shown as comments in the resolved TOML.
    std::map<std::string, Value, std::less<>> equivalents;

    std::vector<TableValues>& all(std::string_view table) { return tables[std::string(table)]; }
    const std::vector<TableValues>& all(std::string_view table) const;
    TableValues& one(std::string_view table) { return all(table).front(); }
    const TableValues& one(std::string_view table) const { return all(table).front(); }
};

// "why; where", leaving out whichever is empty.
std::string join_why(const std::string& why, const std::string& where);

// A value as TOML writes it: reals always with a '.' or an exponent, and with as many digits as
// it takes to read back the same double.
std::string toml_literal(const Value& v);

}  // namespace rodsea::config
