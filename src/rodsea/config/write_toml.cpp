#include "rodsea/config/detail/write_toml.hpp"

#include <sstream>

#include "rodsea/config/detail/resolve.hpp"
#include "rodsea/config/schema.hpp"

namespace rodsea::config {

namespace {

// Column count of UTF-8 text (the docs use Γ, Ω, ℓ, ...).
size_t columns(const std::string& s) {
    size_t n = 0;
    for (const char c : s)
        n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

std::string facts(const KeySpec& spec, const std::string& default_text) {
    std::string s = spec.type_text();
    if (!spec.unit.empty()) s += ", " + spec.unit;
    s += "; allowed " + spec.allowed_text();
    if (!default_text.empty()) s += "; default " + default_text;
    return s;
}

std::string kind_default_text(const KeySpec& spec, const TableValues& t) {
    if (spec.table != "species" || spec.default_value) return spec.default_doc();
    const BodyKind kind = parse_kind(t.text("kind"));
    const double length = kind == BodyKind::apolar_rod ? apolar_length(t) : 0.0;
    const auto v = species_default(spec.name, kind, length);
    return v ? doc_text(*v) : spec.default_doc();
}

void write_table(std::ostream& out, const TableSpec& table, const TableValues& t,
                 const ConfigValues& c) {
    const BodyKind kind =
        table.path == "species" ? parse_kind(t.text("kind")) : BodyKind::polar_rod;
    for (const KeySpec* spec : keys_of(table.path)) {
        if (table.path == "species" && !(spec->kinds & kind_bit(kind))) continue;
        out << '\n' << comment_lines(spec->doc);
        out << comment_lines(facts(*spec, kind_default_text(*spec, t)));
        if (!spec->choice.empty() && (table.path != "species" || spec->is_choice_for(kind)))
            out << comment_lines("CHOICE: " + spec->choice);
        if (t.has(spec->name)) {
            out << spec->name << " = " << toml_literal(t.at(spec->name)) << '\n';
            continue;
        }
        const auto equivalent = c.equivalents.find(t.key_path(spec->name));
        if (equivalent != c.equivalents.end())
            out << "# " << spec->name << " = " << toml_literal(equivalent->second) << '\n';
        else if (spec->example)
            out << "# " << spec->name << " = " << toml_literal(*spec->example) << "  # example\n";
    }
}

}  // namespace

std::string comment_lines(const std::string& text) {
    constexpr size_t kWidth = 100;
    std::string out;
    size_t width = 0;  // columns of the line being filled, 0 before its "#"
    std::istringstream words(text);
    std::string word;
    while (words >> word) {
        if (width > 1 && width + 1 + columns(word) > kWidth) {
            out += '\n';
            width = 0;
        }
        if (width == 0) {
            out += '#';
            width = 1;
        }
        out += ' ';
        out += word;
        width += 1 + columns(word);
    }
    if (width == 0) out += '#';
    out += '\n';
    return out;
}

std::string write_toml(const ConfigValues& c) {
    std::ostringstream out;
    out << "# rodsea config: every key with the value in force, defaults written out. An\n"
           "# alternative key that is not used shows, commented out, the value that says the\n"
           "# same. Reference: docs/config.md.\n";
    for (const TableSpec& table : config_tables()) {
        const std::vector<TableValues>& elements = c.all(table.path);
        if (table.array && elements.empty()) {
            // None given: an example, commented out, to start from.
            out << '\n' << comment_lines(table.doc) << "# [[" << table.path << "]]\n";
            for (const KeySpec* spec : keys_of(table.path)) {
                out << '\n' << comment_lines(spec->doc);
                out << comment_lines(facts(*spec, spec->default_doc()));
                if (spec->example)
                    out << "# " << spec->name << " = " << toml_literal(*spec->example) << '\n';
            }
            continue;
        }
        for (const TableValues& t : elements) {
            if (&t == &elements.front())
                out << '\n' << comment_lines(table.doc);
            else
                out << '\n';
            out << (table.array ? "[[" + table.path + "]]" : "[" + table.path + "]") << '\n';
            write_table(out, table, t, c);
        }
    }
    return out.str();
}

}  // namespace rodsea::config
