// The options of `rodsea analyze`: their reference in docs/analysis.md is the one the code
// generates.
#include <gtest/gtest.h>

#include <filesystem>

#include "rodsea/analyze/analysis_options.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

// docs/analysis.md carries the parameter table generated from the code: they cannot drift.
TEST(AnalysisReference, DocsMatchTheCode) {
    const std::string doc =
        read_text(std::filesystem::path(RODSEA_SOURCE_DIR) / "docs/analysis.md");
    EXPECT_NE(doc.find(analysis_options_reference()), std::string::npos)
        << "regenerate the table in docs/analysis.md from analysis_options_reference()";
}

}  // namespace
}  // namespace rodsea
