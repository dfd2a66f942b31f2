#include "rodsea/config/config_values.hpp"

#include <cmath>

#include "rodsea/number_text.hpp"

namespace rodsea::config {

std::string TableValues::where(std::string_view key, const std::string& source) const {
    const auto it = entries.find(key);
    if (it == entries.end() || it->second.line <= 0) return "";
    return source + " line " + std::to_string(it->second.line);
}

std::string join_why(const std::string& why, const std::string& where) {
    if (why.empty()) return where;
    if (where.empty()) return why;
    return why + "; " + where;
}

const std::vector<TableValues>& ConfigValues::all(std::string_view table) const {
    static const std::vector<TableValues> none;
    const auto it = tables.find(table);
    return it == tables.end() ? none : it->second;
}

namespace {

std::string real_literal(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    // Shortest text that reads back as the same double: the resolved config must reload into
    // an identical plan.
    std::string s = exact_number(v);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string string_literal(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            static const char* hex = "0123456789abcdef";
            out += "\\u00";
            out += hex[(c >> 4) & 0xf];
            out += hex[c & 0xf];
        } else {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace

std::string toml_literal(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return real_literal(*d);
    if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
    if (const auto* s = std::get_if<std::string>(&v)) return string_literal(*s);
    std::string out = "[";
    for (const std::string& s : std::get<std::vector<std::string>>(v)) {
        if (out.size() > 1) out += ", ";
        out += string_literal(s);
    }
    return out + "]";
}

}  // namespace rodsea::config
