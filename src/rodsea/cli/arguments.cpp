#include "rodsea/cli/arguments.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <ostream>
#include <sstream>

#include "rodsea/error.hpp"

namespace rodsea {

namespace {

constexpr std::size_t kHelpColumn = 22;  // where option descriptions start
constexpr std::size_t kHelpWidth = 100;  // the line length of the rest of rodsea's output

std::string long_name(const std::string& flags) {
    return flags.substr(flags.rfind(',') + 1);
}

// Words of `text` on lines of at most `width`, each line after the first indented by `indent`;
// a new line in the text starts a new line, and a line that starts with a space is laid out
// already (a table) and kept as it is.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width) {
    std::string out, line;
    const auto flush = [&] {
        if (!out.empty()) out += "\n" + std::string(indent, ' ');
        out += line;
        line.clear();
    };
    std::istringstream paragraphs(text);
    for (std::string paragraph; std::getline(paragraphs, paragraph);) {
        if (!paragraph.empty() && paragraph[0] == ' ') {
            line = paragraph;
            flush();
            continue;
        }
        std::istringstream words(paragraph);
        for (std::string word; words >> word;) {
            if (!line.empty() && indent + line.size() + 1 + word.size() > width) flush();
            line += (line.empty() ? "" : " ") + word;
        }
        flush();
    }
    return out;
}

// CLI11's layout with rodsea's synopsis first and descriptions wrapped to the line length.
class HelpLayout final : public CLI::Formatter {
  public:
    explicit HelpLayout(const CommandSpec& spec) : spec_(spec) { column_width(kHelpColumn); }
    std::string make_description(const CLI::App*) const override {
        std::string s = wrapped("rodsea " + spec_.name + " " + spec_.usage, 4, kHelpWidth) + "\n";
        if (!spec_.description.empty())
            s += "\n" + wrapped(spec_.description, 0, kHelpWidth) + "\n";
        return s;
    }
    std::string make_footer(const CLI::App*) const override {
        return spec_.footer.empty() ? "" : wrapped(spec_.footer, 0, kHelpWidth) + "\n";
    }
    std::string make_usage(const CLI::App*, std::string) const override { return ""; }
    std::string make_option_opts(const CLI::Option* o) const override {
        return o->get_type_name().empty() ? "" : " " + o->get_type_name();
    }
    std::string make_option_desc(const CLI::Option* o) const override {
        // CLI11 indents each further line of a description to the column itself.
        return wrapped(o->get_description(), 0, kHelpWidth - kHelpColumn);
    }

  private:
    const CommandSpec& spec_;
};

// The CLI11 parser of a command: option k fills values[k] or sets given[k].
std::unique_ptr<CLI::App> make_parser(const CommandSpec& spec,
                                      std::vector<std::vector<std::string>>& values,
                                      std::vector<bool>& given) {
    auto app = std::make_unique<CLI::App>(spec.description, "rodsea " + spec.name);
    app->set_help_flag("--help", "this help");
    app->allow_extras(true);  // positional words and unknown flags, checked below
    app->formatter(std::make_shared<HelpLayout>(spec));
    values.assign(spec.options.size(), {});
    given.assign(spec.options.size(), false);
    for (std::size_t k = 0; k < spec.options.size(); ++k) {
        const OptionSpec& o = spec.options[k];
        if (o.value.empty()) {
            app->add_flag_callback(
                o.flags, [&given, k] { given[k] = true; }, o.help);
            continue;
        }
        CLI::Option* option = app->add_option(o.flags, values[k], o.help);
        // Every value is kept; a flag that does not repeat is refused twice below.
        option->type_name(o.value)->allow_extra_args(false);
        option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    }
    return app;
}

std::string flag_list(const CommandSpec& spec) {
    std::string allowed;
    for (const OptionSpec& o : spec.options) {
        if (!allowed.empty()) allowed += ' ';
        allowed += long_name(o.flags);
    }
    return allowed + (allowed.empty() ? "" : " ") + "--help";
}

}  // namespace

bool Arguments::has(std::string_view flag) const {
    return std::find(switches.begin(), switches.end(), flag) != switches.end() ||
           value(flag).has_value();
}

std::optional<std::string> Arguments::value(std::string_view flag) const {
    std::optional<std::string> found;
    for (const auto& [name, v] : values)
        if (name == flag) found = v;
    return found;
}

std::vector<std::string> Arguments::values_of(std::string_view flag) const {
    std::vector<std::string> found;
    for (const auto& [name, v] : values)
        if (name == flag) found.push_back(v);
    return found;
}

Arguments parse_arguments(const std::vector<std::string>& words, const CommandSpec& spec) {
    Arguments a;
    if (std::find(words.begin(), words.end(), "--help") != words.end()) {
        a.help = true;
        return a;
    }
    std::vector<std::vector<std::string>> values;
    std::vector<bool> given;
    const std::unique_ptr<CLI::App> app = make_parser(spec, values, given);
    std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes them so
    try {
        app->parse(reversed);
    } catch (const CLI::ArgumentMismatch& e) {
        const std::string what = e.what();
        throw InvalidParameter(what.substr(0, what.find(':')), "nothing", "a value after it");
    } catch (const CLI::ParseError& e) {
        throw InvalidParameter(spec.name, e.what(), "the options of rodsea " + spec.name);
    }
    for (const std::string& word : app->remaining()) {
        // Flags are --name or -x; "-" and negative numbers are values.
        const bool flag = word.size() > 1 && word[0] == '-' &&
                          !(std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
        if (flag) {
            std::string what = "an unknown option of '";
            what += spec.name;
            what += "'";
            throw InvalidParameter(word, what, flag_list(spec));
        }
        a.positional.push_back(word);
    }
    for (std::size_t k = 0; k < spec.options.size(); ++k) {
        const std::string name = long_name(spec.options[k].flags);
        if (values[k].size() > 1 && !spec.options[k].repeats) {
            std::string twice = "given twice (";
            twice += rodsea::quoted(values[k][0]);
            twice += ", ";
            twice += rodsea::quoted(values[k][1]);
            twice += ")";
            throw InvalidParameter(name, twice, "at most once");
        }
        if (given[k]) a.switches.push_back(name);
        for (const std::string& v : values[k])
            a.values.emplace_back(name, v);
    }
    return a;
}

std::string help_text(const CommandSpec& spec) {
    std::vector<std::vector<std::string>> values;
    std::vector<bool> given;
    return make_parser(spec, values, given)->help();
}

std::optional<Arguments> arguments_or_help(const std::vector<std::string>& words,
                                           const CommandSpec& spec, std::ostream& out) {
    Arguments a = parse_arguments(words, spec);
    if (!a.help) return a;
    out << help_text(spec);
    return std::nullopt;
}

// Built by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + std::string.
std::string quoted(const std::string& text) {
    std::string q(1, '\'');
    q += text;
    q += '\'';
    return q;
}

double parse_number(std::string_view flag, const std::string& text, double lo, double hi,
                    const std::string& unit) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v) || v < lo || v > hi) {
        if (std::isinf(lo) && std::isinf(hi))
            throw InvalidParameter(std::string(flag), quoted(text),
                                   unit.empty() ? "a finite number" : "a finite number in " + unit);
        std::string allowed("a number in [");
        allowed += format_number(lo);
        allowed += ", ";
        allowed += format_number(hi);
        allowed += ']';
        if (!unit.empty()) allowed.append(" ").append(unit);
        throw InvalidParameter(std::string(flag), quoted(text), allowed);
    }
    return v;
}

long long parse_count(std::string_view flag, const std::string& text, long long lo, long long hi) {
    long long v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || v < lo || v > hi)
        throw InvalidParameter(
            std::string(flag), quoted(text),
            "a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}

}  // namespace rodsea
