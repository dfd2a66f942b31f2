#include "rodsea/config/detail/read_toml.hpp"

#include <toml++/toml.h>

#include <algorithm>

#include "rodsea/config/config_file.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/error.hpp"

namespace rodsea::config {

namespace {

long line_of(const toml::source_region& r) {
    return static_cast<long>(r.begin.line);
}

// The node as the user wrote it, for the VALUE slot of a message.
std::string node_text(const toml::node& node) {
    if (const auto* s = node.as_string()) return toml_literal(std::string(s->get()));
    if (const auto* i = node.as_integer()) return std::to_string(i->get());
    if (const auto* f = node.as_floating_point()) return format_number(f->get());
    if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
    if (node.is_table()) return "a table";
    if (node.is_array()) return "an array";
    return "a date or time";
}

std::string node_type_text(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a float";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        default:
            return "a date or time";
    }
}

// `expected` is the type alone ("an integer"), `allowed` the type with its range.
[[noreturn]] void wrong_type(const std::string& path, const toml::node& node,
                             const std::string& expected, const std::string& allowed,
                             const std::string& where) {
    const std::string given = node_type_text(node);
    const std::string value = node.is_table() || node.is_array() || node.is_date() ||
                                      node.is_time() || node.is_date_time()
                                  ? given
                                  : given + " (" + node_text(node) + ")";
    throw InvalidParameter(
        path, value, allowed,
        join_why("wrong type: " + given + " where " + expected + " is expected", where));
}

std::string expected_type(const KeySpec& spec) {
    switch (spec.type) {
        case ValueType::real:
            return "a number";
        case ValueType::integer:
            return "an integer";
        case ValueType::text:
        case ValueType::option:
            return "a string";
        case ValueType::name_pair:
            return "an array of two strings";
    }
    return "";
}

Value read_value(const KeySpec& spec, const toml::node& node, const std::string& path,
                 const std::string& where) {
    const auto out_of_range = [&](const std::string& value_text, const std::string& why) {
        throw InvalidParameter(path, value_text, spec.allowed_text(), join_why(why, where));
    };
    switch (spec.type) {
        case ValueType::real: {
            double v = 0.0;
            if (const auto* f = node.as_floating_point())
                v = f->get();
            else if (const auto* i = node.as_integer())
                v = static_cast<double>(i->get());  // integers are fine where reals are expected
            else
                wrong_type(path, node, expected_type(spec),
                           expected_type(spec) + " in " + spec.allowed_text(), where);
            if (!spec.range.contains(v))
                out_of_range(format_number(v) + (spec.unit.empty() ? "" : " " + spec.unit), "");
            return v;
        }
        case ValueType::integer: {
            const auto* i = node.as_integer();
            if (!i) wrong_type(path, node, expected_type(spec), spec.allowed_text(), where);
            const std::int64_t v = i->get();
            if (v < spec.min_integer || v > spec.max_integer)
                out_of_range(std::to_string(v) + (spec.unit.empty() ? "" : " " + spec.unit), "");
            return v;
        }
        case ValueType::text:
        case ValueType::option: {
            const auto* s = node.as_string();
            if (!s)
                wrong_type(path, node, expected_type(spec),
                           expected_type(spec) + ": " + spec.allowed_text(), where);
            std::string v(s->get());
            if (spec.type == ValueType::option &&
                std::find(spec.options.begin(), spec.options.end(), v) == spec.options.end()) {
                const auto guess = closest_match(v, spec.options);
                out_of_range(toml_literal(v), guess ? "did you mean \"" + *guess + "\"?" : "");
            }
            return v;
        }
        case ValueType::name_pair: {
            const auto* a = node.as_array();
            if (!a) wrong_type(path, node, expected_type(spec), expected_type(spec), where);
            std::vector<std::string> names;
            for (const toml::node& element : *a) {
                const auto* s = element.as_string();
                if (!s) wrong_type(path, element, expected_type(spec), expected_type(spec), where);
                names.emplace_back(s->get());
            }
            if (names.size() != 2) {
                throw InvalidParameter(path, std::to_string(names.size()) + " names",
                                       expected_type(spec), where);
            }
            return names;
        }
    }
    return 0.0;
}

// The schema tables nested directly in `table` ("" is the file's root).
std::vector<const TableSpec*> child_tables(std::string_view table) {
    std::vector<const TableSpec*> children;
    for (const TableSpec& t : config_tables()) {
        const size_t dot = t.path.rfind('.');
        const std::string_view parent =
            dot == std::string::npos ? std::string_view{} : std::string_view(t.path).substr(0, dot);
        if (parent == table) children.push_back(&t);
    }
    return children;
}

std::string table_header(const TableSpec& t) {
    return t.array ? "[[" + t.path + "]]" : "[" + t.path + "]";
}

[[noreturn]] void unknown_key(std::string_view table, const std::string& display_prefix,
                              const std::string& key, const toml::node& node,
                              const std::string& where) {
    const std::string path = display_prefix.empty() ? key : display_prefix + "." + key;
    std::vector<std::string> here;
    std::string allowed;
    for (const KeySpec* k : keys_of(table)) {
        here.push_back(k->name);
        allowed += (allowed.empty() ? "" : ", ") + k->name;
    }
    for (const TableSpec* t : child_tables(table)) {
        const std::string name = t->path.substr(table.empty() ? 0 : table.size() + 1);
        here.push_back(name);
        allowed += (allowed.empty() ? "" : ", ") + (table.empty() ? table_header(*t) : name);
    }
    allowed = table.empty()
                  ? "one of the tables " + allowed
                  : "one of the keys of " + table_header(*find_table(table)) + ": " + allowed;

    std::string hint;
    if (const auto guess = closest_match(key, here)) {
        hint =
            "did you mean " + (display_prefix.empty() ? "" : display_prefix + ".") + *guess + "?";
    } else {
        // A key written in the wrong table: suggest where it belongs.
        for (const KeySpec& k : config_keys()) {
            if (k.name == key && k.table != table) {
                hint = "did you mean " + k.path() + " (in " + table_header(*find_table(k.table)) +
                       ")?";
                break;
            }
        }
    }
    throw InvalidParameter(path, node_text(node), allowed,
                           join_why(hint.empty() ? "unknown key" : "unknown key; " + hint, where));
}

void read_table(const toml::table& source, std::string_view table, const std::string& prefix,
                TableValues& into, ConfigValues& out) {
    for (auto&& [k, node] : source) {
        const std::string key(k.str());
        const std::string path = prefix.empty() ? key : prefix + "." + key;
        const std::string where = out.source + " line " + std::to_string(line_of(k.source()));
        const std::string child = table.empty() ? key : std::string(table) + "." + key;
        if (const TableSpec* sub = find_table(child)) {
            std::vector<TableValues>& elements = out.all(child);
            if (sub->array) {
                const auto* array = node.as_array();
                bool all_tables = array != nullptr;
                if (array)
                    for (const toml::node& e : *array)
                        all_tables = all_tables && e.is_table();
                if (!all_tables)
                    wrong_type(path, node, "an array of tables",
                               "an array of tables (" + table_header(*sub) + ")", where);
                for (const toml::node& e : *array) {
                    TableValues element;
                    element.path = path + "[" + std::to_string(elements.size()) + "]";
                    element.line = line_of(e.source());
                    read_table(*e.as_table(), child, element.path, element, out);
                    elements.push_back(std::move(element));
                }
            } else {
                if (!node.is_table())
                    wrong_type(path, node, "a table", "a table (" + table_header(*sub) + ")",
                               where);
                TableValues element;
                element.path = path;
                element.line = line_of(node.source());
                read_table(*node.as_table(), child, element.path, element, out);
                elements.push_back(std::move(element));
            }
            continue;
        }
        const KeySpec* spec = find_key(table, key);
        if (!spec) unknown_key(table, prefix, key, node, where);
        into.entries[key] = {read_value(*spec, node, path, where), line_of(k.source())};
    }
}

}  // namespace

ConfigValues read_toml(std::string_view text, std::string_view source_name) {
    ConfigValues out;
    out.source = std::string(source_name);
    toml::table root;
    try {
        root = toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        throw ConfigSyntaxError(out.source, static_cast<long>(e.source().begin.line),
                                static_cast<long>(e.source().begin.column),
                                std::string(e.description()));
    }
    TableValues unused;
    read_table(root, "", "", unused, out);
    return out;
}

}  // namespace rodsea::config
