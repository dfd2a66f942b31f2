// The one command-line parser: what each command declares is what it accepts, and anything else
// is refused by name before the command does anything.
#include <gtest/gtest.h>

#include <limits>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/error.hpp"

namespace rodsea {
namespace {

const CommandSpec& spec() {
    static const CommandSpec s{"demo",
                               "INPUT [-o FILE] [--frame N] [--param K=V ...] [--quiet]",
                               "a command for the tests",
                               "What it does.",
                               {{"-o,--output", "FILE", "where to write"},
                                {"--frame", "N", "a frame"},
                                {"--param", "K=V", "a parameter", true},
                                {"--quiet", "", "say nothing"}},
                               "After the options."};
    return s;
}

std::string refusal(const std::vector<std::string>& words) {
    try {
        parse_arguments(words, spec());
    } catch (const InvalidParameter& e) {
        return e.name() + ": " + e.what();
    }
    return "accepted";
}

TEST(Arguments, SplitsWordsByTheFlagsTheCommandDeclares) {
    const Arguments a = parse_arguments({"in.h5", "-o", "x.png", "--frame", "-1", "--param", "a=1",
                                         "extra", "--param", "b=2", "--quiet"},
                                        spec());
    EXPECT_EQ(a.positional, (std::vector<std::string>{"in.h5", "extra"}));
    EXPECT_EQ(a.value("--output"), "x.png");  // known by its long name
    EXPECT_EQ(a.value("--frame"), "-1");      // a negative number is a value, not a flag
    EXPECT_EQ(a.values_of("--param"), (std::vector<std::string>{"a=1", "b=2"}));
    EXPECT_TRUE(a.has("--quiet"));
    EXPECT_TRUE(a.has("--output"));  // given with a value, as -o
    EXPECT_FALSE(parse_arguments({"in.h5"}, spec()).has("--output"));
    EXPECT_FALSE(a.help);
    EXPECT_EQ(parse_arguments({"--frame=7"}, spec()).value("--frame"), "7");
}

TEST(Arguments, RefusesWhatTheCommandDoesNotDeclareByName) {
    const std::string unknown = refusal({"in", "--frmae", "3"});
    EXPECT_EQ(unknown.rfind("--frmae: ", 0), 0u) << unknown;
    EXPECT_NE(unknown.find("an unknown option of 'demo'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("--output --frame --param --quiet --help"), std::string::npos);
    EXPECT_EQ(refusal({"in", "--frame"}).rfind("--frame: ", 0), 0u);  // no value after it
    const std::string twice = refusal({"in", "--frame", "1", "--frame", "2"});
    EXPECT_NE(twice.find("given twice ('1', '2')"), std::string::npos) << twice;
}

TEST(Arguments, HelpComesFromTheSameDeclaration) {
    EXPECT_TRUE(parse_arguments({"--frmae", "--help"}, spec()).help);  // nothing else checked
    const std::string help = help_text(spec());
    EXPECT_EQ(help.rfind("rodsea demo INPUT [-o FILE]", 0), 0u) << help;
    for (const char* part : {"What it does.", "-o,--output FILE", "where to write", "--param K=V",
                             "--quiet", "After the options."})
        EXPECT_NE(help.find(part), std::string::npos) << part << " in\n" << help;
}

TEST(Arguments, NumbersAreCheckedAgainstTheirRangeWithTheirUnit) {
    EXPECT_EQ(parse_number("--fps", "12.5", 0.001, 120, "frames/s"), 12.5);
    try {
        parse_number("--fps", "0", 0.001, 120, "frames/s");
        ADD_FAILURE() << "0 accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("[0.001, 120] frames/s"), std::string::npos);
    }
    EXPECT_THROW(parse_count("--every", "2.5", 1, 10), InvalidParameter);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(parse_number("--a", "inf", -inf, inf), InvalidParameter);  // any finite number
    EXPECT_EQ(parse_number("--a", "-3", -inf, inf), -3.0);
}

}  // namespace
}  // namespace rodsea
