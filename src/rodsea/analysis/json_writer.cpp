#include "rodsea/analysis/json_writer.hpp"

#include <cmath>
#include <cstdio>

namespace rodsea {

std::string JsonWriter::quote(std::string_view s) {
    std::string q = "\"";
    for (char c : s) {
        switch (c) {
            case '"':
                q += "\\\"";
                break;
            case '\\':
                q += "\\\\";
                break;
            case '\n':
                q += "\\n";
                break;
            case '\t':
                q += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    q += buf;
                } else {
                    q += c;  // UTF-8 passes through unchanged
                }
        }
    }
    return q + "\"";
}

std::string JsonWriter::number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

void JsonWriter::prefix(std::string_view key) {
    if (!first_.empty()) {
        if (!first_.back()) out_ << ",";
        first_.back() = false;
        out_ << "\n" << std::string(2 * first_.size(), ' ');
    }
    if (!key.empty()) out_ << quote(key) << ": ";
}

JsonWriter& JsonWriter::begin_object(std::string_view key) {
    prefix(key);
    out_ << "{";
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::end_object() {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty) out_ << "\n" << std::string(2 * first_.size(), ' ');
    out_ << "}";
    return *this;
}

JsonWriter& JsonWriter::begin_array(std::string_view key) {
    prefix(key);
    out_ << "[";
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::end_array() {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty) out_ << "\n" << std::string(2 * first_.size(), ' ');
    out_ << "]";
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, double v) {
    prefix(key);
    out_ << number(v);
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, long long v) {
    prefix(key);
    out_ << v;
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, bool v) {
    prefix(key);
    out_ << (v ? "true" : "false");
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, std::string_view v) {
    prefix(key);
    out_ << quote(v);
    return *this;
}

}  // namespace rodsea
